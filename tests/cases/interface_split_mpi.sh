#!/usr/bin/env bash
# The split 8x8 mesh (soil y < 4 | block y > 4, 9 pairs) distributed over 2 ranks, twice:
# with -petscpartitioner_type metis (METIS tends to give the soil and the block one rank each,
# since the split mesh is two bodies; then every pair's structure node lives on the other rank)
# and with a forced partition x < 4 | x > 4 that cuts the interface. InterfacePairsBuild must
# give each pair exactly one owner, dofs that point at the right vertex copy, and the serial
# areas/normals (checks inside test_interface_split -distribute, printed by rank 0).
# Then, serially, unstructured Gmsh triangles and tetrahedra of two bodies meshed conformingly
# along y = 1 / z = 1 (written here, meshed with gmsh): the split keeps every cell's vertex
# coordinates and closure order, DMPlexCheck passes, one pair per mesh vertex on the plane,
# total area = the plane's extent (3 m in 2D, 2 x 1.5 m^2 in 3D), normals straight up.
set -euo pipefail
BUILD=${BUILD:-build}
bin="$BUILD/tests/unit/test_interface_split"
[ -x "$bin" ] || { echo "missing $bin: run make build-only"; exit 1; }
root_flag=""; [ "$(id -u)" = 0 ] && root_flag="--allow-run-as-root"
out=$(mpiexec --oversubscribe $root_flag -n 2 "$bin" -distribute -petscpartitioner_type metis 2>&1) || { echo "$out"; echo "FAIL: mpiexec exited non-zero"; exit 1; }
echo "$out"
if grep -q '^not ok' <<<"$out"; then echo "FAIL: a check failed"; exit 1; fi
for how in options cut; do
  grep -q "^ok - distributed ($how): every pair owned by exactly one rank" <<<"$out" || { echo "FAIL: no passing ownership check for '$how'"; exit 1; }
  grep -q "^ok - distributed ($how): areas, normals, coordinates equal the serial values" <<<"$out" || { echo "FAIL: no passing geometry check for '$how'"; exit 1; }
done
grep -q "^ok - distributed (cut): the interface is cut by the partition" <<<"$out" || { echo "FAIL: the forced partition did not cut the interface"; exit 1; }
grep -q "^ok - no PETSc error" <<<"$out" || { echo "FAIL: PETSc error"; exit 1; }

command -v gmsh >/dev/null || { echo "FAIL: gmsh is not installed"; exit 1; }
dir="$BUILD/tests/interface_split"; rm -rf "$dir"; mkdir -p "$dir"
cat > "$dir/tri.geo" <<'GEO'
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 3, 1};
Rectangle(2) = {0, 1, 0, 3, 1};
BooleanFragments{ Surface{1}; Delete; }{ Surface{2}; Delete; }
Mesh.MeshSizeMax = 0.3;
GEO
cat > "$dir/tet.geo" <<'GEO'
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 1.5, 1};
Box(2) = {0, 0, 1, 2, 1.5, 1};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
Mesh.MeshSizeMax = 0.4;
GEO
for m in tri:2 tet:3; do
  name=${m%:*}; dim=${m#*:}
  gmsh -"$dim" "$dir/$name.geo" -format msh41 -o "$dir/$name.msh" > "$dir/$name.gmsh.log" 2>&1 || { cat "$dir/$name.gmsh.log"; echo "FAIL: gmsh $name"; exit 1; }
  out=$("$bin" -gmsh_file "$dir/$name.msh" -gmsh_plane 1 2>&1) || { echo "$out"; echo "FAIL: $name exited non-zero"; exit 1; }
  echo "$out"
  if grep -q '^not ok' <<<"$out"; then echo "FAIL: a check failed ($name)"; exit 1; fi
  grep -q "closure order" <<<"$out" || { echo "FAIL: no closure-order check ($name)"; exit 1; }
done
echo "PASS"
