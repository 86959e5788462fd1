#!/usr/bin/env bash
# Free-field lateral sides on a saturated site under SV. A vertically incident SV wave is pure
# shear (u = u_x(z)), with no volume change and so no excess pore pressure: the column's
# vertical chain and its pore pressure (physics/column_pore_pressure.hpp) stay exactly at
# rest, its shear chains are the dry ones, and the side dashpots take the undrained P speed
# (input/free_field.cpp).
#  1. The saturated site of config/scenes/saturated_site.yaml without gravity (so no geostatic
#     relaxation residual separates the runs), 20 m wide, under the 2 Hz SV Ricker: with
#     free-field sides it must move as with sides tied to each other (the exact 1D column):
#     horizontal velocity at the four stations equal to 1e-10 of its peak, vertical velocity
#     and excess pore pressure zero to round-off (1e-12 m/s, 1e-6 Pa against peaks of the
#     order of the surface velocity's 0.74 m/s and rho c v ~ 3e5 Pa).
#  2. The same with gravity, a water table at the surface and the geostatic stage (static
#     solve with free-field sides): the geostatic state is an exact equilibrium and the
#     problem is linear, so the motion is that of the run without gravity (v_x to 1e-10 of
#     its peak, v_y to 1e-12 m/s, excess p to 1e-6 Pa), and the energy balance closes (1e-12).
# (-input_wave p with free-field sides on a saturated site: saturated_free_field_p.sh.)
set -eu
. tests/tools/lib.sh
grep -v -E "^(gravity|water_table|geostatic_stage):" config/scenes/saturated_site.yaml > "$WORK/site_nogravity.yaml"
grep -v -E "tie_with|_type: tied" "$WORK/site_nogravity.yaml" > "$WORK/site_nogravity_ff.yaml"
grep -v -E "tie_with|_type: tied" config/scenes/saturated_site.yaml > "$WORK/site_ff.yaml"
# SEM_DEGREE=p (tests/cases/sem_saturated.sh): elements of degree p, 5 m tall so that the soil's
# base (y = 0, 50 m above the model's) stays on element faces.
O="-element_degree $DEGREE -mesh_box_faces $(elements 10),$([ "$DEGREE" = 1 ] && echo 40 || echo 16) -ts_max_time 2 -output_fields 0 -progress_interval 100000"
$SW -options_file "$WORK/site_nogravity.yaml" $O -output_dir "$WORK/tied" > "$WORK/tied.log"
$SW -options_file "$WORK/site_nogravity_ff.yaml" $O -bc_left_type freefield -bc_right_type freefield -output_dir "$WORK/ff" > "$WORK/ff.log"
$SW -options_file "$WORK/site_ff.yaml" $O -bc_left_type freefield -bc_right_type freefield -output_dir "$WORK/ffg" > "$WORK/ffg.log"
grep -E "^geostatic|^done" "$WORK/ffg.log"
$CHECK energy "$WORK/ff/energy.csv" --max-error 1e-12
$CHECK energy "$WORK/ffg/energy.csv" --max-error 1e-12
$PY - "$WORK" <<'PY'
import sys
import numpy as np
work = sys.argv[1]
ok = True
for s in ("surface", "layer_mid", "layer_base", "bedrock_base"):
    a = np.genfromtxt(f"{work}/tied/stations/{s}.csv", delimiter=",", names=True)
    b = np.genfromtxt(f"{work}/ff/stations/{s}.csv", delimiter=",", names=True)
    peak = np.abs(a["v_x"]).max()
    dx = np.abs(a["v_x"] - b["v_x"]).max() / peak
    vy = np.abs(b["v_y"]).max()
    pex = np.abs(b["p_excess"]).max()
    good = dx <= 1e-10 and vy <= 1e-12 and pex <= 1e-6
    ok &= good
    print(f"{s}: free-field vs tied v_x {dx:.2e} of the peak {peak:.3f} m/s; v_y {vy:.1e} m/s, excess p {pex:.1e} Pa" + ("" if good else "  FAILED"))
for s in ("surface", "layer_mid", "layer_base", "bedrock_base"):
    a = np.genfromtxt(f"{work}/ff/stations/{s}.csv", delimiter=",", names=True)
    b = np.genfromtxt(f"{work}/ffg/stations/{s}.csv", delimiter=",", names=True)
    dx = np.abs(a["v_x"] - b["v_x"]).max() / np.abs(a["v_x"]).max()
    dy = np.abs(a["v_y"] - b["v_y"]).max()
    dp = np.abs(a["p_excess"] - b["p_excess"]).max()
    good = dx <= 1e-10 and dy <= 1e-12 and dp <= 1e-6
    ok &= good
    print(f"{s}: with gravity and the water table vs without: v_x {dx:.1e} of the peak, v_y {dy:.1e} m/s, excess p {dp:.1e} Pa" + ("" if good else "  FAILED"))
sys.exit(0 if ok else 1)
PY
