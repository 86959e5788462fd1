# Drained limit: the same kind of P pulse (5 Hz) in a very permeable saturated column
# (k = 7.8 m/s, a compressible pore fluid K_f = 1.28e8 Pa so that alpha^2 M = E and the
# undrained speed 565.7 m/s is well apart from the drained 400 m/s) travels at the drained
# speed within 1 %. Expected from the 1D u-p dispersion relation rho w^2 = k^2 (E + alpha^2 M
# i w/(i w + M kappa k^2)) (docs/saturated-soil.md): at 5 Hz M kappa k^2 / w = 50, which moves
# the phase speed by alpha^2 M / E / (2 (50^2 + 1)) = 0.02 % from the drained one. The top is
# 120 m above the upper station so its reflection (the absorbing boundary matches the
# undrained wave) arrives after the pulse has passed. The explicit diffusion limit (~6e-6 s)
# is 450x below the wave's step: sub-cycled (the default), 375 steps of ~400 sub-steps.
set -eu
. tests/tools/lib.sh
MAT="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4 -material_soil_fluid_bulk_modulus 1.28e8
 -material_soil_hydraulic_conductivity 7.8"
$SW -regions soil $MAT -mesh_box_faces 1,120 -mesh_box_upper 2,240 -constrain_components x -bc_bottom_type absorbing -bc_top_type absorbing -input_wave p \
  -input_boundary bottom -input_stf ricker -input_f0 5 -input_t0 0.24 -input_amplitude 0.1 -ts_max_time 0.9 -station_coordinates 1,40,1,120 \
  -station_names lower,upper -output_dir "$WORK" -output_fields 0 -progress_interval 100 | tee "$WORK/log" | grep -E "pore pressure step|sub-cycled|done"
$PY tests/tools/poroelastic.py pulse "$WORK" --lower lower --upper upper --distance 80 --limit drained --rho 2000 --vp 400 --porosity 0.4 \
  --fluid-bulk-modulus 1.28e8 --hydraulic-conductivity 7.8
