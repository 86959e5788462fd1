# Per-component boundary conditions on one named boundary (issue 12): "x driven, y held" on
# the base of a box mesh, -bc_bottom_type_x velocity -bc_bottom_type_y fixed, with tied
# (periodic) sides and no -constrain_components. A column with periodic sides under uniform
# horizontal base motion is in pure shear (no normal strain), so it is the 1D SV column of
# boundary_velocity.sh: rigid base moving with a Ricker v_b(t), top v_x(t) = 2 v_b(t - H/vs)
# until the first reflection from the base returns (t0 + 3H/vs - 1.5/f0 = 1.44 s); relative
# L2 <= 1.5 %, the column tests' bound. With y free the P wave sets the time step, the shear
# Courant number falls from 0.48 to 0.39 and lumped-mass dispersion grows (1.58 % on the
# column tests' 139 cells): 170 cells (24 points per shortest wavelength) instead. The held component stays at
# rest: |v_y| at the top below 1e-12 m/s (the base holds it and nothing drives it), and the
# base's v_x follows v_b to the accuracy of the central-difference integration of the
# prescribed acceleration, (h 2 pi f_top)^2/24 x 0.1 m/s = 6e-5 m/s (h = 1.39e-3 s,
# f_top = 2.76 f0).
set -eu
. tests/tools/lib.sh
$SW -mesh_box_faces 1,170 -mesh_box_upper 1,100 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 \
  -bc_bottom_type_x velocity -bc_bottom_type_y fixed -bc_bottom_stf ricker -bc_bottom_f0 5 -bc_bottom_t0 0.24 -bc_bottom_amplitude 0.1 \
  -bc_left_type tied -bc_left_tie_with right -bc_right_type tied -bc_right_tie_with left -ts_max_time 1.44 -output_fields 0 -progress_interval 1000 \
  -station_coordinates 0.5,100,0,0 -station_names top,base -output_dir "$WORK" | grep "load: boundary 'bottom' per component: y fixed x velocity"
$CHECK column "$WORK/stations/top.csv" --component x --height 100 --speed 200 --amplitude 0.1 --f0 5 --t0 0.24 --l2-max 0.015 --late-max 0
$PY - "$WORK" <<'PY'
import sys
import numpy as np
top = np.genfromtxt(sys.argv[1] + "/stations/top.csv", delimiter=",", names=True)
base = np.genfromtxt(sys.argv[1] + "/stations/base.csv", delimiter=",", names=True)
a = (np.pi * 5 * (base["t"] - 0.24)) ** 2
vb = 0.1 * (1 - 2 * a) * np.exp(-a)
vy = max(np.max(np.abs(top["v_y"])), np.max(np.abs(base["v_y"])))
dx = np.max(np.abs(base["v_x"] - vb))
print(f"held y: max |v_y| {vy:.2e} m/s (bound 1e-12); driven x: base v_x - v_b max {dx:.2e} m/s (bound 6e-5)")
sys.exit(0 if vy <= 1e-12 and dx <= 6e-5 else 1)
PY
