# Dynamic u-p column between the drained and undrained regimes: 50 m of saturated soil
# (k = 0.04 m/s: at 10 Hz M kappa k^2 / w = 0.5, where Biot flow matters most) on a base
# moving with a 10 Hz Ricker velocity, drained free top, impervious base. Over the first
# 0.4 s the top displacement and p at 25 m and 40 m depth agree with the semi-analytic
# solution of the 1D u-p equations (Laplace domain, Durbin inversion; tests/tools/up_column.py)
# within 3 % relative L2. The script is first checked against Terzaghi's series in its
# quasi-static limit (step load, rho -> 0.2 kg/m^3) to 1e-3 of the load. With k ten times
# smaller or larger the same run differs from the solution by 67 % and 230 %.
# Run twice: with the diffusion sub-cycled within the undrained wave's step (the default:
# 1,065 steps of 25 sub-steps; the split costs ~1 % of L2) and with the step lowered to the
# diffusion limit (-pore_pressure_subcycle false: 26,589 steps, 0.05 %).
set -eu
. tests/tools/lib.sh
$PY tests/tools/up_column.py selfcheck --rho 0.2 | tail -1
for MODE in "" "-pore_pressure_subcycle false"; do
# The linear u-p model that the closed form solves: no cavitation limit (its tension
# phases reach beyond -100 kPa, where the default limit would hold the pressure).
MAT="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4 -material_soil_hydraulic_conductivity 0.04 -fluid_cavitation_pressure none"
$SW -regions soil $MAT -mesh_box_faces 1,50 -mesh_box_upper 1,50 -constrain_components x -bc_bottom_type velocity -bc_bottom_components y -bc_bottom_stf ricker \
  -bc_bottom_f0 10 -bc_bottom_t0 0.12 -bc_bottom_amplitude 0.1 -bc_top_fluid drained -ts_max_time 0.4 -station_coordinates 0,50,0,25,0,10 \
  -station_names top,d25,d40 -output_dir "$WORK" -output_overwrite -output_fields 0 -progress_interval 100 $MODE | grep -E "pore pressure step|sub-cycled|done"
$PY tests/tools/up_column.py compare "$WORK" --stations top,d25,d40 --depths 0,25,40 --height 50 --rho 2000 --vp 400 --porosity 0.4 \
  --hydraulic-conductivity 0.04 --f0 10 --t0 0.12 --amplitude 0.1 --t-end 0.4
done
