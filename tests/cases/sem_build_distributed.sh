# Spectral elements built distributed (issue 11 item 3, issue 25 part 5): a box without
# interfaces is built by every rank for its own part at any degree (meshing/box_lattice.hpp), a
# box with interfaces is refined on the distributed mesh, log2(p) times more for the GLL
# sub-cells at p = 2, 4, 8 (meshing/box_refinement.hpp); -mesh_build serial subdivides the whole
# box on rank 0. The meshes are the same (sub-cells, positions in their elements, regions,
# boundary faces, node pairs and pair ids: checked label by label in
# build/tests/unit/test_box_refinement, run here on 2 ranks), so every result may differ by
# the order of the floating-point sums only: stations (t, u, v scaled by their peak) to 1e-10
# (the issue's bound), accelerations to 1e-9 (at p = 4 the stiffness divided by the lumped GLL
# mass reaches ~1.4e4 rad/s, so the acceleration's round-off is that much larger than the
# displacement's: tests/cases/sem_constant_q_free_field.sh), the interface fields per pair id
# at every frame to 1e-10 of their peak.
#  1. 2D footing at p = 4: a block (16 m wide, 16 m tall) embedded 8 m in the soil, the air
#     beside it a void region, an interface "base" along its base and buried sides (33 pairs;
#     where it bends, the serial subdivision's vertex order that numbers the pairs is not the
#     lattice order: pair ids in lattice order fail interface-equal at 1.0 of the peak), with
#     cohesion 1e12 Pa against sliding (without gravity it opens under tension, 30 of 33 pairs
#     at the end, so the contact law switches too; gravity without the geostatic stage drops
#     the block, and its stick-slip switching lifts the accelerations' round-off above 1e-9
#     already between 1 and 2 ranks of the serial build: 7.5e-9 with the block on the
#     surface), absorbing sides and base with an SV Ricker input;
#     16 x 8 elements (refined once from 8 x 4, then twice into the sub-cells). Serial on 1
#     rank against distributed on 1 and 2 ranks (on 2, the partition cuts pairs).
#  2. 3D two layers at p = 2 (4 x 4 x 6 hexahedra, partitioned as 2 x 2 x 3 coarse cells),
#     absorbing base, SV input: serial against distributed on 1 and 2 ranks.
#  3. 2D two layers at p = 8 (4 x 2 elements, partitioned by element): 2 ranks.
#  4. Every degree that is no power of 2 (issue 25 part 5): 2D two layers at p = 3, 5, 6, 7 (8 x 4
#     elements partitioned as 4 x 2 coarse cells, the layers' bound on the coarse grid), and
#     3D two layers at p = 3 (4 x 4 x 6, as 2.): serial on 1 rank against distributed on 1 and 2,
#     and distributed on 1 against 2 ranks.
# The reports must say which build ran.
set -eu -o pipefail
. tests/tools/lib.sh
IC="$PY tests/tools/contact_checks.py"
sv="-bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf ricker -input_amplitude 0.1 -output_fields 0 -progress_interval 1000"
footing="-element_degree 4 -mesh_box_faces 16,8 -mesh_box_lower -32,0 -mesh_box_upper 32,32 -regions soil,air,block -region_air_box -32,32,24,32
 -region_block_box -8,8,16,32 -void_regions air -interfaces base -interface_base_regions soil,block -interface_base_c 1e12 -interface_base_phi 0
 -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_block_rho 2400 -material_block_vp 1500 -material_block_vs 800
 -bc_left_type absorbing -bc_right_type absorbing $sv -input_f0 4 -input_t0 0.3 -ts_max_time 0.8 -output_interval 0.05
 -station_coordinates 0,32,20,24,0,8 -station_names block_top,surface,deep"
layers3d="-mesh_dim 3 -element_degree 2 -mesh_box_faces 4,4,6 -mesh_box_upper 16,16,24 -regions rock,soil -region_soil_box 0,16,0,16,8,24
 -material_rock_rho 2200 -material_rock_vp 1500 -material_rock_vs 800 -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200
 $sv -input_f0 5 -input_t0 0.25 -ts_max_time 0.3 -station_coordinates 8,8,24,3,5,16,8,8,4 -station_names top,soil,rock"
layers2d="-regions rock,soil -region_soil_box 0,32,8,16 -mesh_box_upper 32,16
 -material_rock_rho 2200 -material_rock_vp 1500 -material_rock_vs 800 -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200
 $sv -input_f0 6 -input_t0 0.2 -ts_max_time 0.25 -station_coordinates 16,16,5,12,20,3 -station_names top,soil,rock"
layers8="-element_degree 8 -mesh_box_faces 4,2 $layers2d"
run() { # name ranks build options...
  local name=$1 n=$2 build=$3 start=$SECONDS
  shift 3
  $MPIEXEC -n "$n" $SW "$@" -mesh_build "$build" -output_dir "$WORK/$name" > "$WORK/$name.log"
  echo "$name: $(grep -E "^ *mesh:" "$WORK/$name.log" | sed 's/^ *//') ($((SECONDS - start)) s)"
}
distributed() { grep -q "built distributed: refined $2 times ($3 into the GLL sub-cells)" "$WORK/$1.log" || { echo "FAIL: $1 was not built distributed ($2 refinements)"; exit 1; }; }
parts() { grep -q "built distributed: every rank builds its part (partitioned as $2 coarse cells)" "$WORK/$1.log" || { echo "FAIL: $1 was not built distributed by parts of $2"; exit 1; }; }
run footing_serial 1 serial $footing
if grep -q "built distributed" "$WORK/footing_serial.log"; then echo "FAIL: -mesh_build serial built distributed"; exit 1; fi
for n in 1 2; do
  run footing_np$n $n distributed $footing
  distributed footing_np$n 3 2
  $CHECK stations-equal "$WORK/footing_serial" "$WORK/footing_np$n" --names block_top,surface,deep --tol 1e-10 --tol-a 1e-9
  $IC interface-equal "$WORK/footing_serial" "$WORK/footing_np$n" --name base --fields sigma_N,sigma_T,slip,opening,status --tol 1e-10
done
run layers3d_serial 1 serial $layers3d
for n in 1 2; do
  run layers3d_np$n $n distributed $layers3d
  parts layers3d_np$n "2 x 2 x 3"
  $CHECK stations-equal "$WORK/layers3d_serial" "$WORK/layers3d_np$n" --names top,soil,rock --tol 1e-10 --tol-a 1e-9
done
run layers8_serial 2 serial $layers8
run layers8_np2 2 distributed $layers8
parts layers8_np2 "4 x 2"
$CHECK stations-equal "$WORK/layers8_serial" "$WORK/layers8_np2" --names top,soil,rock --tol 1e-10 --tol-a 1e-9
for p in 3 5 6 7; do
  run layers_p${p}_serial 1 serial -element_degree $p -mesh_box_faces 8,4 $layers2d
  for n in 1 2; do
    run layers_p${p}_np$n $n distributed -element_degree $p -mesh_box_faces 8,4 $layers2d
    parts layers_p${p}_np$n "4 x 2"
    $CHECK stations-equal "$WORK/layers_p${p}_serial" "$WORK/layers_p${p}_np$n" --names top,soil,rock --tol 1e-10 --tol-a 1e-9
  done
  $CHECK stations-equal "$WORK/layers_p${p}_np1" "$WORK/layers_p${p}_np2" --names top,soil,rock --tol 1e-10 --tol-a 1e-9
done
run layers3d_p3_serial 1 serial ${layers3d/-element_degree 2/-element_degree 3}
for n in 1 2; do
  run layers3d_p3_np$n $n distributed ${layers3d/-element_degree 2/-element_degree 3}
  parts layers3d_p3_np$n "2 x 2 x 3"
  $CHECK stations-equal "$WORK/layers3d_p3_serial" "$WORK/layers3d_p3_np$n" --names top,soil,rock --tol 1e-10 --tol-a 1e-9
done
$CHECK stations-equal "$WORK/layers3d_p3_np1" "$WORK/layers3d_p3_np2" --names top,soil,rock --tol 1e-10 --tol-a 1e-9
out=$($MPIEXEC -n 2 "$BUILD/tests/unit/test_box_refinement")
grep -E "p = [0-9]: same|PETSc" <<<"$out"
if grep -q "^not ok" <<<"$out"; then echo "FAIL: the meshes differ on 2 ranks"; exit 1; fi
