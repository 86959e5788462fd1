# Terzaghi consolidation of a 10 m saturated column (20 cells), loaded by 100 kPa on its
# drained top, impervious fixed base, lateral strain held (-constrain_components x):
# pore pressure at depths 2.5 m and 7.5 m at T_v = 0.1, 0.3, 0.6 within 1 % of the load and
# the settlement within 1 % of the closed-form series (Terzaghi 1923; Wang 2000 sec. 6.2),
# recomputed in tests/tools/poroelastic.py from the inputs.
# Explicit dynamics for a quasi-static problem: the sand-like k = 3.8e-4 m/s puts the
# consolidation time H^2/c_v = 8.5 s 1450 times above the undrained wave's transit 5.9 ms, so
# inertia is negligible, and it balances the diffusion limit with the undrained wave step
# (about 2e-4 s each), so T_v = 0.6 takes ~27,000 steps. The sudden load rings the column at
# its undrained modes; mass-proportional Rayleigh damping (alpha = 2 xi w1 ~ 20 1/s; beta
# ~ 5e-8 s is negligible) kills the ringing (e^{-alpha t/2} ~ 2e-4 at T_v = 0.1) while its
# drag on the consolidation flow is ~ alpha rho v H / load ~ 1e-3 (docs/saturated-soil.md).
set -eu
. tests/tools/lib.sh
MAT="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4 -material_soil_hydraulic_conductivity 3.8e-4"
$SW -regions soil $MAT -mesh_box_faces 1,20 -mesh_box_upper 0.5,10 -constrain_components x -bc_bottom_type fixed -bc_top_type traction -bc_top_traction 0,-1e5 \
  -bc_top_fluid drained -damping_ratio 0.16 -damping_frequencies 10,1e6 -ts_max_time 5.2 -station_coordinates 0,7.5,0,2.5,0,10 -station_names d2_5,d7_5,top \
  -output_dir "$WORK" -output_fields 0 -progress_interval 100 | tee "$WORK/log" | grep -E "saturated|pore|stable step|done"
$PY tests/tools/poroelastic.py terzaghi "$WORK" --height 10 --load 1e5 --stations d2_5:2.5,d7_5:7.5 --top top --rho 2000 --vp 400 --porosity 0.4 \
  --hydraulic-conductivity 3.8e-4
