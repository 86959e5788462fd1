# The run report at -element_degree p (issue 14, part 5), dry runs of a two-region box:
# soil (vs 200 m/s) over rock (vs 800 m/s), 48 x 32 elements, Ricker input f0 = 5 Hz whose
# top frequency is 2.7638 f0 = 13.82 Hz (physics/source_time_function.hpp: its spectrum is 1 % of its peak there), so
# lambda_S = 14.47 m in the soil and 57.89 m in the rock.
#  1. Mesh line: 48 x 32 = 1536 elements, 1536 x 4^2 = 24576 linear sub-cells, (48*4+1)(32*4+1)
#     = 24897 nodes at p = 4; the same on 2 ranks (elements summed over the ranks).
#  2. GLL nodes per S wavelength = p lambda / h (h = 15 m, the element edge): soil
#     4 x 14.47 / 15 = 3.9, rock 15.4; the warning names the soil alone (below 5 GLL nodes per
#     wavelength at p = 4, Komatitsch & Tromp 1999, src/app/run_report.cpp), the rock passes.
#  3. p = 1 on the same mesh: the present numbers (points per wavelength lambda / h, h the
#     region's largest cell, here every cell's 15 m: soil
#     1.0, rock 3.9), both below 10 (Kuhlemeyer & Lysmer 1973): two warnings.
#  4. p = 2 with h = 5 m: soil 2 x 14.47 / 5 = 5.8, below the 8.33 that degree 2 needs,
#     although above the 5 of p = 4: the threshold depends on the degree.
#  5. p = 4 with h = 1.5 m: soil 38.6 GLL nodes per wavelength, no warning.
#  6. -help says triangles and tetrahedra stay linear.
#  7. Every time history enters the resolution: case 5's mesh (no warning from the input) with a
#     point force whose Ricker f0 = 50 Hz tops at 2.7638 x 50 = 138.19 Hz, lambda_S = 1.447 m in
#     the soil: 4 x 1.447 / 1.5 = 3.9 GLL nodes per wavelength, a warning that names the force.
set -eu -o pipefail
. tests/tools/lib.sh
box() { # width height: the two regions on a 48 x 32 box of that size
  echo "-mesh_box_faces 48,32 -mesh_box_upper $1,$2 -regions soil,rock -region_soil_box 0,$1,$(($2 / 2)),$2 -region_rock_box 0,$1,0,$(($2 / 2))"
}
opts="$COLUMN -material_rock_rho 2500 -material_rock_vp 1600 -material_rock_vs 800 -input_wave sv -dry_run"
fail() { echo "FAIL: $1"; exit 1; }
$SW $opts $(box 720 480) -element_degree 4 -output_dir "$WORK/p4" > "$WORK/p4.log"
$MPIEXEC -n 2 $SW $opts $(box 720 480) -element_degree 4 -output_dir "$WORK/p4_np2" > "$WORK/p4_np2.log"
$SW $opts $(box 720 480) -output_dir "$WORK/p1" > "$WORK/p1.log"
$SW $opts $(box 240 160) -element_degree 2 -output_dir "$WORK/p2" > "$WORK/p2.log"
$SW $opts $(box 72 48) -element_degree 4 -output_dir "$WORK/fine" > "$WORK/fine.log"
$SW $opts $(box 72 48) -element_degree 4 -point_forces src -point_force_src_location 36,40 -point_force_src_force 0,-1e3 -point_force_src_stf ricker \
  -point_force_src_f0 50 -point_force_src_t0 0.05 -output_dir "$WORK/force" > "$WORK/force.log"
grep -h "mesh:\|region\|warning\|resolution" "$WORK"/p4.log "$WORK"/p1.log "$WORK"/p2.log "$WORK"/fine.log
# auto builds the box distributed, every rank its part of the sub-cells, partitioned by element
# (1536 elements: too few for a coarser partition, docs/running.md).
mesh_line="mesh: box 48 x 32 quadrilaterals, built distributed: every rank builds its part (partitioned as 48 x 32 coarse cells), spectral elements of degree 4 (GLL): 1536 elements in 24576 linear sub-cells, 24897 nodes,"
grep -qF "$mesh_line" "$WORK/p4.log" || fail "p = 4 mesh line"
grep -qF "$mesh_line" "$WORK/p4_np2.log" || fail "p = 4 mesh line on 2 ranks"
grep -qE "region soil .* 3\.9 GLL nodes per S wavelength at 13\.82 Hz \(degree 4, element size 15 m\)" "$WORK/p4.log" || fail "p = 4 soil nodes per wavelength"
grep -qE "region rock .* 15\.4 GLL nodes per S wavelength at 13\.82 Hz" "$WORK/p4.log" || fail "p = 4 rock nodes per wavelength"
grep -qF "warning: region soil is under-resolved for the top frequency 13.82 Hz of the input wave: 3.9 GLL nodes per S wavelength, below the 5 that elements of degree 4 need (Komatitsch & Tromp 1999)" \
  "$WORK/p4.log" || fail "p = 4 soil warning"
[ "$(grep -c "under-resolved" "$WORK/p4.log")" = 1 ] || fail "p = 4: the rock (15.4 >= 5) is warned about"
grep -qE "region soil .* 1\.0 points per S wavelength at 13\.82 Hz \(cell size 15 m\)" "$WORK/p1.log" || fail "p = 1 soil points per wavelength"
grep -qE "region rock .* 3\.9 points per S wavelength" "$WORK/p1.log" || fail "p = 1 rock points per wavelength"
grep -qF "warning: region rock is under-resolved for the top frequency 13.82 Hz of the input wave: 3.9 points per S wavelength, below the 10 that elements of degree 1 need (Kuhlemeyer & Lysmer 1973)" \
  "$WORK/p1.log" || fail "p = 1 rock warning"
[ "$(grep -c "under-resolved" "$WORK/p1.log")" = 2 ] || fail "p = 1: not both regions warned about"
grep -qF "warning: region soil is under-resolved for the top frequency 13.82 Hz of the input wave: 5.8 GLL nodes per S wavelength, below the 8.33 that elements of degree 2 need" \
  "$WORK/p2.log" || fail "p = 2 soil warning"
grep -qE "region soil .* 38\.6 GLL nodes per S wavelength" "$WORK/fine.log" || fail "p = 4 fine soil nodes per wavelength"
! grep -q "under-resolved" "$WORK/fine.log" || fail "p = 4 fine mesh warned about"
$SW -help > "$WORK/help.txt" 2>&1 || true
grep -- "-element_degree <" "$WORK/help.txt" | grep -q "triangles and tetrahedra are linear only" || fail "-help on triangles and tetrahedra"
grep -qF "warning: region soil is under-resolved for the top frequency 138.19 Hz of point force src: 3.9 GLL nodes per S wavelength" "$WORK/force.log" || fail "point force frequency"
echo "PASS"
