# The forced-vibration model of a rigid strip footing on a half-space, shared by
# tests/cases/foundation_impedance_strip.sh and bench/cases/foundation_impedance_strip.sh
# (see the test's header for the choices): footing 4 m x 2 m (rho 2000, vp 2000, vs 1000
# m/s: 100 x the soil's G) welded on soil rho 2000, vp 200, vs 100 m/s, Lysmer sides and
# base behind four sponge layers (constant Q, xi 0.25, 0.15, 0.08, 0.03 inward), a Ricker
# load (f0 6 Hz, t0 0.25 s: tests/tools/footing_runs.py's defaults), stations L, C, R at the
# base's corners and centre, 4 s. Needs $SW, $PY and $WORK (tests/tools/lib.sh).
# strip_footing_run NAME WIDTH DEPTH H SPONGE_LAYER LOAD: the footing centred on the surface
# of a WIDTH x DEPTH soil box (inside the sponge layers, each SPONGE_LAYER thick), faces of H.
strip_footing_run() {
  W=$2; D=$3; s=$5
  opts="-regions sp0,sp1,sp2,sp3,soil,air,footing -region_soil_box $((4 * s)),$((W - 4 * s)),$((4 * s)),$D"
  i=0
  for xi in 0.25 0.15 0.08 0.03; do
    opts="$opts -material_sp${i}_rho 2000 -material_sp${i}_vp 200 -material_sp${i}_vs 100 -material_sp${i}_damping_ratio $xi"
    [ $i = 0 ] || opts="$opts -region_sp${i}_box $((i * s)),$((W - i * s)),$((i * s)),$D"
    i=$((i + 1))
  done
  $SW $opts -mesh_box_faces "$($PY -c "print(f'{round($W / $4)},{round(($D + 2) / $4)}')")" -mesh_box_upper $W,$((D + 2)) \
    -region_air_box 0,$W,$D,$((D + 2)) -region_footing_box $((W / 2 - 2)),$((W / 2 + 2)),$D,$((D + 2)) -void_regions air \
    -material_soil_rho 2000 -material_soil_vp 200 -material_soil_vs 100 -material_footing_rho 2000 -material_footing_vp 2000 \
    -material_footing_vs 1000 -bc_left_type absorbing -bc_right_type absorbing -bc_bottom_type absorbing \
    -structure_load_region footing -structure_load_stf ricker -structure_load_f0 6 -structure_load_t0 0.25 $6 \
    -ts_max_time 4 -output_fields 0 -progress_interval 1000000 \
    -station_coordinates $((W / 2 - 2)),$D,$((W / 2)),$D,$((W / 2 + 2)),$D -station_names L,C,R -output_dir "$WORK/$1" > /dev/null
}
