#!/usr/bin/env bash
# Spectral elements as GLL sub-cells (-element_degree): tests/unit/test_spectral_subdivision
# on 1 and 2 ranks (node counts and GLL coordinates, labels, the layout whole on one rank,
# GLL face weights and interface pair areas against closed forms: see its header), then on an
# unstructured Gmsh quadrilateral mesh and an extruded hexahedral one at p = 3 (1 and 2 ranks), whose node count V + 2E + 4C follows from
# the mesh's V vertices and C quads (E = V + C - 1 edges: Euler's formula for a disk), and
# the solver's dry run at p = 4 (mesh built, report printed) and its refusal of triangles.
set -euo pipefail
BUILD=${BUILD:-build}
bin="$BUILD/tests/unit/test_spectral_subdivision"
[ -x "$bin" ] || { echo "missing $bin: run make build-only"; exit 1; }
root_flag=""; [ "$(id -u)" = 0 ] && root_flag="--allow-run-as-root"
for n in 1 2; do
  out=$(mpiexec --oversubscribe $root_flag -n $n "$bin" 2>&1) || { echo "$out"; echo "FAIL: $n rank(s) exited non-zero"; exit 1; }
  echo "$out"
  if grep -q '^not ok' <<<"$out"; then echo "FAIL: a check failed on $n rank(s)"; exit 1; fi
  grep -q "^ok - interface: areas sum to its length 4" <<<"$out" || { echo "FAIL: no interface check on $n rank(s)"; exit 1; }
done

command -v gmsh >/dev/null || { echo "FAIL: gmsh is not installed"; exit 1; }
dir="$BUILD/tests/spectral_mesh"; rm -rf "$dir"; mkdir -p "$dir"
cat > "$dir/quad.geo" <<'GEO'
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 3, 2};
Mesh.CharacteristicLengthMax = 0.6;
Mesh.RecombineAll = 1;
Mesh.SubdivisionAlgorithm = 1;
Physical Surface("soil") = {1};
Physical Curve("bottom") = {1};
GEO
gmsh -2 "$dir/quad.geo" -format msh41 -o "$dir/quad.msh" > "$dir/gmsh.log" 2>&1 || { cat "$dir/gmsh.log"; echo "FAIL: gmsh"; exit 1; }
counts=$(/usr/bin/python3 - "$dir/quad.msh" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
i = lines.index("$Nodes"); V = int(lines[i + 1].split()[1])
i = lines.index("$Elements"); nblocks = int(lines[i + 1].split()[0]); k = i + 2; C = 0
for _ in range(nblocks):
    dim, tag, etype, n = map(int, lines[k].split()); k += 1 + n
    if etype == 3: C += n   # 4-node quadrangle
print(f"{V},{V + C - 1},{C}")
PY
)
echo "Gmsh quad mesh: V,E,C = $counts"
for n in 1 2; do
  out=$(mpiexec --oversubscribe $root_flag -n $n "$bin" -gmsh_file "$dir/quad.msh" -gmsh_cells "$counts" 2>&1) || { echo "$out"; echo "FAIL: Gmsh case on $n rank(s)"; exit 1; }
  echo "$out"
  if grep -q '^not ok' <<<"$out"; then echo "FAIL: a Gmsh check failed on $n rank(s)"; exit 1; fi
  grep -q "^ok - Gmsh quads, p = 3: V + 2E" <<<"$out" || { echo "FAIL: no Gmsh node count check"; exit 1; }
done
# Gmsh hexahedra (the quad mesh extruded in 2 layers): Gmsh's hexahedron node order is not the
# box's, so the element frames come from another closure order.
cat > "$dir/hex.geo" <<'GEO'
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 2, 1};
Mesh.CharacteristicLengthMax = 0.6;
Mesh.RecombineAll = 1;
Extrude {0, 0, 1} { Surface{1}; Layers{2}; Recombine; }
Physical Volume("soil") = {1};
GEO
gmsh -3 "$dir/hex.geo" -format msh41 -o "$dir/hex.msh" > "$dir/gmsh_hex.log" 2>&1 || { cat "$dir/gmsh_hex.log"; echo "FAIL: gmsh hex"; exit 1; }
for n in 1 2; do
  out=$(mpiexec --oversubscribe $root_flag -n $n "$bin" -gmsh_file "$dir/hex.msh" 2>&1) || { echo "$out"; echo "FAIL: Gmsh hex case on $n rank(s)"; exit 1; }
  echo "$out"
  if grep -q '^not ok' <<<"$out"; then echo "FAIL: a Gmsh hex check failed on $n rank(s)"; exit 1; fi
  grep -q "^ok - Gmsh hexes, p = 3: V + 2E" <<<"$out" || { echo "FAIL: no Gmsh hex node count check"; exit 1; }
done

# The solver builds the p = 4 mesh: 4x2 elements -> (4*4+1)(2*4+1) = 153 nodes, 8*16 = 128 sub-cells.
out=$("$BUILD/slipwave" -mesh_box_faces 4,2 -mesh_box_upper 4,2 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 \
  -ts_max_time 0.01 -output_fields false -dry_run -output_dir "$dir/run" -element_degree 4 2>&1) || { echo "$out"; echo "FAIL: dry run at p = 4"; exit 1; }
echo "$out"
grep -q "8 elements in 128 linear sub-cells, 153 nodes" <<<"$out" || { echo "FAIL: the p = 4 mesh has not 128 sub-cells and 153 nodes"; exit 1; }
# The cell check judges elements, not GLL sub-cells: a 20:1 element at p = 8 (aspect 20 < 50)
# passes although its sub-cells reach 20 x 3.62 = 72 (the largest over the smallest GLL gap
# at p = 8: 0.3631 / 0.1002, from the GLL points).
out=$("$BUILD/slipwave" -mesh_box_faces 1,1 -mesh_box_upper 20,1 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 \
  -ts_max_time 0.01 -output_fields false -dry_run -output_dir "$dir/run8" -element_degree 8 2>&1) || { echo "$out"; echo "FAIL: a 20:1 element at p = 8 is refused"; exit 1; }
grep -q "1 element in 64 linear sub-cells, 81 nodes" <<<"$out" || { echo "$out"; echo "FAIL: p = 8 element not 64 sub-cells, 81 nodes"; exit 1; }
echo "PASS"
