# Free-field sides beside hysteretic soil: the side columns carry the region's Iwan model at
# their GLL points (physics/free_field_column.hpp), fed the full strain of the height-only
# motion, so the side's traction (sigma_xz and the lateral sigma_xx) is the stress the
# interior's cells carry. A laterally uniform site has nothing to scatter: a narrow model with
# free-field sides must then move exactly like the 1D column of the same layers (the set-up of
# tests/cases/constant_q_free_field.sh: 30 m of soil, vs 200, 5 % constant-Q, over rock,
# xi 2 %), here with the soil hysteretic (MKZ hyperbola, gamma_r = 5e-4: strength 3.8e4 Pa)
# under a Ricker pulse of 0.3 m/s, whose stress rho vs v = 1.1e5 Pa is 3x the strength:
# the surface peak is 0.17 m/s against 1.02 m/s linear (SV). SV (shear) and P (the deviator
# of eps_zz: the column's sigma_xx departs from lambda/(lambda+2mu) sigma_zz once a surface
# yields; peak 0.957 against 0.929 m/s linear) waves; SV on 1 and 2 ranks.
# Bound: the two models compute the same stresses by different sums (the main mesh's K u less
# its relaxation force at its Gauss points, the column the Iwan stress against the basis), so
# they differ by round-off, 1e-10 of each quantity's peak as in constant_q_free_field
# (measured 5.5e-13 SV, 2.2e-13 P, 1.0e-12 SV on 2 ranks; p = 2: 1.8e-12). The accelerations
# carry the round-off of the force over the mass, times (omega_max/omega_0)^2: omega_max =
# 2/dt_limit = 4.0e3 rad/s (p = 1; 8.8e3 at p = 2), omega_0 = 2 pi 2 Hz, so 1e5 (4.9e5) x 1.1e-16
# = 1.1e-11 (5.4e-11) per evaluation, accumulated over the run: bound 1e-9 as in
# sem_constant_q_free_field (measured 5.2e-11 SV, 5.9e-12 P, 4.1e-11 on 2 ranks; p = 2: 4.3e-10).
# With the columns linear (the refusal this replaces) the difference is 5.9 (SV) and 0.18 (P)
# of the peaks. Energy: the balance closes to round-off, bound 1e-12 (measured 4e-15 to 1e-14).
# SEM_DEGREE=p: elements of degree p, SV on 1 rank (tests/cases/sem_hysteretic_free_field.sh:
# p = 2; P waves and ranks at p > 1: hysteretic_ranks, sem_constant_q_free_field).
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
# 2.1 s is a whole number of steps (a shorter last step books O(h) terms: balance 2e-10).
dt=3e-4; [ "$DEGREE" -gt 1 ] && dt=2e-4 # (the 1-element column's limit at p = 2: 2.28e-4 s)
site="-regions rock,soil -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_soil_damping_ratio 0.05
 -material_soil_model hysteretic -material_soil_backbone mkz -material_soil_reference_strain 5e-4
 -material_rock_rho 2400 -material_rock_vp 1600 -material_rock_vs 800 -material_rock_damping_ratio 0.02 -bc_bottom_type absorbing
 -input_boundary bottom -input_stf ricker -input_f0 2 -input_t0 0.6 -input_amplitude 0.3 -ts_max_time 2.1 -ts_dt $dt -output_fields 0
 -progress_interval 100000 -element_degree $DEGREE"
narrow="-mesh_box_faces $(elements 20),$(elements 40) -mesh_box_lower -10,-10 -mesh_box_upper 10,30 -region_soil_box -10,10,0,30
 -bc_left_type freefield -bc_right_type freefield -station_coordinates -10,30,-9,30,0,30,10,30,0,10 -station_names left,edge,centre,right,centre_10"
column="-mesh_box_faces 1,$(elements 40) -mesh_box_lower -2,-10 -mesh_box_upper -1,30 -region_soil_box -10,10,0,30
 -station_coordinates -2,30,-2,30,-2,30,-2,30,-2,10 -station_names left,edge,centre,right,centre_10"
names=left,edge,centre,right,centre_10
waves="sv p"; [ "$DEGREE" -gt 1 ] && waves=sv # (P and ranks at p > 1: hysteretic_ranks)
# The 1-rank runs are independent: two at a time (tests/tools/together.sh); then the checks.
for wave in $waves; do
  held=y; [ $wave = p ] && held=x
  together $SW $site $narrow -input_wave $wave -output_dir "$WORK/free_$wave" > "$WORK/free_$wave.log"
  together $SW $site $column -input_wave $wave -constrain_components $held -output_dir "$WORK/column_$wave" > "$WORK/column_$wave.log"
done
together_wait
for wave in $waves; do
  $CHECK stations-equal "$WORK/column_$wave" "$WORK/free_$wave" --names $names --tol 1e-10 --tol-a 1e-9
  $CHECK energy "$WORK/free_$wave/energy.csv" --max-error 1e-12 --min-rows 2
done
[ "$DEGREE" -gt 1 ] && exit 0
$MPIEXEC -n 2 $SW $site $narrow -input_wave sv -output_dir "$WORK/free_sv_2" > "$WORK/free_sv_2.log"
$CHECK stations-equal "$WORK/column_sv" "$WORK/free_sv_2" --names $names --tol 1e-10 --tol-a 1e-9
$CHECK energy "$WORK/free_sv_2/energy.csv" --max-error 1e-12 --min-rows 2
