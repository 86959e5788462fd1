#!/usr/bin/env bash
# The physics and numerics headers, the element kernels and the cell-quality measures are
# plain C++ (no PETSc), so they can be reused and unit-tested without MPI (the
# hysteretic-soil kernel's sources too: it runs at every quadrature point). Fails listing
# every file that includes a PETSc header, directly or through another slipwave header.
set -u
cd "$(dirname "$0")/../.."
files=(include/slipwave/physics/*.hpp include/slipwave/numerics/*.hpp src/numerics/*.cpp include/slipwave/fem/element_kernels.hpp src/fem/element_kernels.cpp
       include/slipwave/fem/spectral_kernels.hpp include/slipwave/fem/spectral_force_kernel.hpp src/fem/spectral_kernels.cpp
       include/slipwave/mesh/cell_quality.hpp src/mesh/cell_quality.cpp src/physics/hysteretic_soil.cpp src/physics/soil_backbone.cpp)
[ -e "${files[0]}" ] || { echo "no physics headers found"; exit 1; }
bad=0
for f in "${files[@]}"; do
  # The full include chain, to catch a PETSc header pulled in through another header.
  if ! deps=$(g++ -std=c++17 -Iinclude -I/usr/lib/petscdir/petsc3.18/x86_64-linux-gnu-real/include -M -x c++ "$f" 2>&1); then
    echo "$f does not preprocess:"; echo "$deps" | head -5; bad=1
  elif grep -qi 'petsc' <<<"$deps"; then
    echo "$f pulls in PETSc through:"; tr ' ' '\n' <<<"$deps" | grep -i petsc | head -5; bad=1
  fi
done
[ "$bad" -eq 0 ] && echo "all ${#files[@]} files free of PETSc"
exit "$bad"
