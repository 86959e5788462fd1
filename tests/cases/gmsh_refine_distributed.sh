#!/usr/bin/env bash
# Gmsh files refined uniformly (-mesh_refine k, src/meshing/mesh_refinement.hpp): the coarse file
# read, labelled, split and partitioned on rank 0, then refined on the distributed mesh
# (-mesh_build auto/distributed), against the same coarse split refined on rank 0
# (-mesh_build serial). The two are the same mesh up to point numbers (same cells, regions,
# boundary faces, pairs and pair ids), so results may differ by the order of floating-point
# sums only: stations (scaled by their peak) and interface fields per pair id to 1e-10 of the
# peak (the bound of tests/cases/mesh_build_distributed.sh).
#  (a) 2D: soil 40 m x 20 m (coarse triangles, 4 m) under an 8 m x 6 m block on its surface,
#      tied interface "base" (c = 1e12 Pa, phi = 0: linear springs, so no status switch can
#      amplify round-off), absorbing sides and base, SV Ricker input; k = 2; serial and
#      distributed route on 1 and 2 ranks, all against the serial route on 1 rank.
#  (b) counts: k = 2 has 4^2 = 16 times the coarse cells (report), and the interface (the
#      block's base, e coarse edges, e + 1 pairs) 4 e + 1 pairs.
#  (c) physics: a coarse Gmsh column of 1 x 25 quadrilaterals (2 m x 100 m) refined twice is
#      the grid of -mesh_box_faces 4,100 (node positions exact in binary): the SV column
#      record at the top must equal the box's to 1e-9 of its peak (round-off; a lost or
#      spread absorbing-base label, a wrong child geometry would show at > 1e-3). At
#      -element_degree 2 the column is refined once on rank 0 before the subdivision: 2 x 50
#      elements, the grid of -mesh_box_faces 2,50 at degree 2, also to 1e-9 (2 ranks).
#  (d) 3D: soil 8 x 8 x 4 m under a 4 x 4 x 2 m block, coarse tetrahedra, k = 1, distributed
#      on 1 and 2 ranks against serial on 1 rank.
set -eu -o pipefail
. tests/tools/lib.sh
. tests/tools/together.sh
IC="$PY tests/tools/contact_checks.py"
command -v gmsh >/dev/null || { echo "FAIL: gmsh is not installed"; exit 1; }
mesh() { # name dim, geo on stdin
  cat > "$WORK/$1.geo"
  gmsh -"$2" "$WORK/$1.geo" -format msh41 -o "$WORK/$1.msh" > "$WORK/$1.gmsh.log" 2>&1 || { cat "$WORK/$1.gmsh.log"; echo "FAIL: gmsh $1"; exit 1; }
}
mesh footing 2 <<'GEO'
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 40, 20};
Rectangle(2) = {16, 20, 0, 8, 6};
BooleanFragments{ Surface{1}; Delete; }{ Surface{2}; Delete; }
e = 1e-6;
Physical Surface("soil") = Surface In BoundingBox{-e, -e, -e, 40 + e, 20 + e, e};
Physical Surface("block") = Surface In BoundingBox{16 - e, 20 - e, -e, 24 + e, 26 + e, e};
Physical Curve("bottom") = Curve In BoundingBox{-e, -e, -e, 40 + e, e, e};
Physical Curve("left") = Curve In BoundingBox{-e, -e, -e, e, 20 + e, e};
Physical Curve("right") = Curve In BoundingBox{40 - e, -e, -e, 40 + e, 20 + e, e};
Mesh.MeshSizeMax = 4;
GEO
mesh column 2 <<'GEO'
Point(1) = {0, 0, 0}; Point(2) = {2, 0, 0}; Point(3) = {2, 100, 0}; Point(4) = {0, 100, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 2;
Transfinite Curve{2, 4} = 26;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("bottom") = {1};
Physical Surface("soil") = {1};
GEO
mesh footing3d 3 <<'GEO'
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 8, 8, 4};
Box(2) = {2, 2, 4, 4, 4, 2};
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
e = 1e-6;
Physical Volume("soil") = Volume In BoundingBox{-e, -e, -e, 8 + e, 8 + e, 4 + e};
Physical Volume("block") = Volume In BoundingBox{2 - e, 2 - e, 4 - e, 6 + e, 6 + e, 6 + e};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, 8 + e, 8 + e, e};
Mesh.MeshSizeMax = 2;
GEO
scene="-regions soil,block -material_soil_rho 1900 -material_soil_vp 400 -material_soil_vs 200 -material_block_rho 2400 -material_block_vp 800 -material_block_vs 400
 -interfaces base -interface_base_regions soil,block -interface_base_c 1e12 -interface_base_phi 0
 -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf ricker -input_amplitude 0.1 -output_fields 0 -progress_interval 100"
foot="-mesh_file $WORK/footing.msh $scene -bc_left_type absorbing -bc_right_type absorbing -input_f0 4 -input_t0 0.3 -ts_max_time 0.6 -output_interval 0.05
 -station_coordinates 20,26,6,20,30,8 -station_names block_top,surface,deep"
foot3="-mesh_file $WORK/footing3d.msh $scene -input_f0 10 -input_t0 0.12 -ts_max_time 0.25 -output_interval 0.05
 -station_coordinates 4,4,6,1,1,4 -station_names block_top,surface"
run() { # name ranks options...
  local name=$1 n=$2
  shift 2
  $MPIEXEC -n "$n" $SW "$@" -output_dir "$WORK/$name" > "$WORK/$name.log"
  grep -E "mesh:|node pairs" "$WORK/$name.log"
}
cells() { sed -n 's/.*mesh: .*, \([0-9]*\) cells,.*/\1/p' "$WORK/$1.log"; }
pairs() { sed -n 's/.*: \([0-9]*\) node pairs;.*/\1/p' "$WORK/$1.log"; }
column="$COLUMN -constrain_components y -input_wave sv -ts_max_time 1.2 -station_coordinates 1,100 -station_names top"
# The runs of (a), (c) and (d): on 1 rank, then on 2.
run coarse 1 $foot -mesh_refine 0
run serial_np1 1 $foot -mesh_refine 2 -mesh_build serial
run dist_np1 1 $foot -mesh_refine 2
run box 1 -mesh_box_faces 4,100 -mesh_box_upper 2,100 $column
run box_p2 1 -mesh_box_faces 2,50 -mesh_box_upper 2,100 -element_degree 2 $column
run t_serial 1 $foot3 -mesh_refine 1 -mesh_build serial
run t_np1 1 $foot3 -mesh_refine 1 -mesh_build distributed
run serial_np2 2 $foot -mesh_refine 2 -mesh_build serial
run dist_np2 2 $foot -mesh_refine 2
run column 2 -mesh_file "$WORK/column.msh" -mesh_refine 2 $column
run column_p2 2 -mesh_file "$WORK/column.msh" -mesh_refine 1 -element_degree 2 $column
run t_np2 2 $foot3 -mesh_refine 1 -mesh_build distributed
together_wait
for name in "${runs[@]}"; do echo "$name:"; grep -E "mesh:|node pairs" "$WORK/$name.log"; done
# (a)
for n in 1 2; do
  grep -q "footing.msh, refined 2 times on rank 0" "$WORK/serial_np$n.log"
  grep -q "footing.msh, built distributed: refined 2 times" "$WORK/dist_np$n.log"
done
for r in serial_np2 dist_np1 dist_np2; do
  $CHECK stations-equal "$WORK/serial_np1" "$WORK/$r" --names block_top,surface,deep --tol 1e-10
  $IC interface-equal "$WORK/serial_np1" "$WORK/$r" --name base --fields sigma_N,sigma_T --tol 1e-10
  [ "$(pairs $r)" = "$(pairs serial_np1)" ] || { echo "FAIL: $r has $(pairs $r) pairs, serial $(pairs serial_np1)"; exit 1; }
done
# (b)
c0=$(cells coarse); p0=$(pairs coarse)
for r in serial_np1 dist_np2; do
  [ "$(cells $r)" = $((16 * c0)) ] || { echo "FAIL: $r has $(cells $r) cells, want 16 x $c0"; exit 1; }
  [ "$(pairs $r)" = $((4 * (p0 - 1) + 1)) ] || { echo "FAIL: $r has $(pairs $r) pairs, want 4 x ($p0 - 1) + 1"; exit 1; }
done
echo "coarse $c0 cells, $p0 pairs; refined twice $(cells dist_np2) cells, $(pairs dist_np2) pairs"
# (c)
grep -q "built distributed: refined 2 times" "$WORK/column.log"
$CHECK stations-equal "$WORK/box" "$WORK/column" --names top --tol 1e-9
grep -q "column.msh, refined 1 times on rank 0, spectral elements of degree 2" "$WORK/column_p2.log"
$CHECK stations-equal "$WORK/box_p2" "$WORK/column_p2" --names top --tol 1e-9
# (d)
for n in 1 2; do
  $CHECK stations-equal "$WORK/t_serial" "$WORK/t_np$n" --names block_top,surface --tol 1e-10
  $IC interface-equal "$WORK/t_serial" "$WORK/t_np$n" --name base --fields sigma_N,sigma_T --tol 1e-10
done
echo PASS
