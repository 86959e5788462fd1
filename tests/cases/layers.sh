#!/usr/bin/env bash
# Includes point down the floors: a file may include headers of its own folder and of the
# floors below it, never of a floor above. Every folder has a floor of its own, so two folders
# that include each other (a cycle) always hold one upward include and fail the check. The
# order, lowest first (docs/architecture.md draws it):
#    0 core       log events and stages, user-input errors, option files and checks
#    1 numerics   pure numerics: GLL points and Lagrange basis, reference cells and their
#                 Gauss rules, dense solve, FFT (no PETSc)
#    2 physics    pure kernels: materials, interface law, damping, wave solutions, stable step
#    3 mesh       what a distributed mesh holds and tells: labels, coordinates, centroids,
#                 spectral layout and face weights, cell quality, the METIS partitioner
#    4 meshing    how the mesh is made: options, box and Gmsh builders, refinement, spectral
#                 subdivision, the interface split, the memory check
#    5 fem        element kernels, the bulk operator (Q1 and spectral), node-field layouts
#    6 time       the central-difference TS
#    7 interface  the split-node interface: options and assembler
#    8 medium     what the regions are made of: materials, constant-Q attenuation
#    9 input      how the earthquake and the loads come in: boundary conditions and faces,
#                 free-field columns, DRM, records and time functions, forces, lateral ties
#   10 porous     the water: pore pressure, its boundary conditions, the fluid
#   11 problem    the assembled problem and its stages: elastodynamics, nodal acceleration,
#                 stable step, energy ledger, geostatic stage, static equilibrium
#   12 io         writers and readers: fields, stations, interface output, jump histories
#   13 app        the driver: SimulationRun, checkpoint, report
#   14 bin        the programs (src/bin)
# Every directory of include/slipwave/ and src/ must be in the table, so a new one gets a
# place before it is used. Fails naming each upward include (file:line, both floors).
set -u
cd "$(dirname "$0")/../.."

layer_rank() {
  case "$1" in
    core) echo 0 ;;
    numerics) echo 1 ;;
    physics) echo 2 ;;
    mesh) echo 3 ;;
    meshing) echo 4 ;;
    fem) echo 5 ;;
    time) echo 6 ;;
    interface) echo 7 ;;
    medium) echo 8 ;;
    input) echo 9 ;;
    porous) echo 10 ;;
    problem) echo 11 ;;
    io) echo 12 ;;
    app) echo 13 ;;
    bin) echo 14 ;;
    *) echo -1 ;;
  esac
}

# check_tree ROOT: prints one line per upward include or unplaced directory; exit 1 if any.
check_tree() {
  local root=$1 bad=0 f dir rank line target tdir trank
  while IFS= read -r f; do
    dir=${f#"$root"/}; dir=${dir#include/slipwave/}; dir=${dir#src/}; dir=${dir%%/*}
    rank=$(layer_rank "$dir")
    if [ "$rank" -lt 0 ]; then echo "${f#"$root"/}: directory '$dir' has no layer (add it to tests/cases/layers.sh)"; bad=1; continue; fi
    while IFS= read -r line; do
      target=${line#*:}; target=${target#*\"slipwave/}; tdir=${target%%/*}
      trank=$(layer_rank "$tdir")
      if [ "$trank" -lt 0 ]; then
        echo "${f#"$root"/}:${line%%:*}: includes slipwave/$tdir/, which has no layer"; bad=1
      elif [ "$trank" -gt "$rank" ]; then
        echo "${f#"$root"/}:${line%%:*}: $dir (floor $rank) includes slipwave/${target%%\"*} ($tdir, floor $trank)"; bad=1
      fi
    done < <(grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*"slipwave/' "$f")
  done < <(find "$root/include/slipwave" "$root/src" -type f \( -name '*.hpp' -o -name '*.cpp' \) | sort)
  return "$bad"
}

# The check must be able to fail. plant DIR FILE INCLUDE...: a fake tree whose FILE includes
# the given headers; the check must give exactly the expected number of violations.
fake=$(mktemp -d); trap 'rm -rf "$fake"' EXIT
plant() {
  local want=$1 what=$2 out; shift 2
  rm -rf "${fake:?}"/*; mkdir -p "$fake/include/slipwave" "$fake/src"
  while [ $# -gt 0 ]; do
    mkdir -p "$fake/$(dirname "$1")"; printf '#include "slipwave/%s"\n' "$2" >>"$fake/$1"; shift 2
  done
  out=$(check_tree "$fake")
  if [ "$(grep -c . <<<"$out")" -ne "$want" ]; then echo "self-test ($what): expected $want violation(s), got:"; echo "$out"; exit 1; fi
}
plant 1 "upward include physics -> problem" include/slipwave/physics/up.hpp problem/elastodynamics.hpp
plant 1 "cycle fem <-> mesh" src/fem/a.cpp mesh/labels.hpp src/mesh/b.cpp fem/bulk_operator.hpp
plant 1 "cycle input <-> problem" src/input/drm.cpp problem/elastodynamics.hpp src/problem/elastodynamics.cpp input/drm.hpp
plant 1 "unplaced folder" src/model/x.cpp core/errors.hpp
plant 0 "includes that point down" src/problem/x.cpp input/drm.hpp src/input/y.cpp numerics/fft.hpp include/slipwave/numerics/z.hpp numerics/fft.hpp

if ! out=$(check_tree .); then
  echo "includes pointing up the floors:"; echo "$out"; exit 1
fi
echo "all $(find include/slipwave src -type f \( -name '*.hpp' -o -name '*.cpp' \) | wc -l) files include only their own folder or the floors below"
