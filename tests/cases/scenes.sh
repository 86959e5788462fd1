# The scenes of config/scenes that no other test runs, each against what its header promises.
# column_1d: surface velocity 2 v_in(t - H/vs), L2 <= 1.5 %, late motion <= 1e-3 (as the SV
#   column test). foundation_3d: runs to the end with the budget closed (1e-9); the block's
#   starting base traction, area-weighted (lumped weights 1/4, 1/2, 1 for the corner, edge
#   and centre pairs of its 2 x 2-cell base), equals its weight per area rho g h =
#   2400*9.81*6 = 141264 Pa within 1 %; it slides (> 1 cm) and rocks (some pair opens).
#   The run's answers in 3D read the vertical as z: the rocking angle, the tilt after shaking
#   and the rocking left (their mean and half range over the last 2 s) from
#   the base-corner stations equal scripts/scene_metrics.py's (stations every step, their
#   span from stations.h5) to 1e-9 of the peak; the settlement under gravity (-u_z of
#   block_top; the outputs count displacements from the geostatic state, so only the answer
#   holds it) lies within a factor 3 of a rigid square footing's on an elastic half-space of
#   the soft layer, s = q B (1 - nu^2) I / E with I = 0.82 (Poulos & Davis 1974, rigid
#   square), q = 141264 Pa, B = 4 m, E and nu from vp 450, vs 200, rho 1900: 1.9 mm (the
#   stiffer soil 6 m down makes it less, the contact springs' compression more). Reading u_y,
#   the horizontal component that the symmetric load leaves at zero, gave 1e-15 m.
# (default.yaml: tests/cases/default_scene.sh; site_response_2d: mpi_ranks.sh, output_files.sh;
# sliding_block, two_bar_impact and free_field_site: their interface_ and free_field_ tests;
# saturated_site: saturated_site_scene.sh; foundation_saturated: foundation_saturated.sh.)
set -eu
. tests/tools/lib.sh
$SW -options_file config/scenes/column_1d.yaml -output_dir "$WORK/column" > "$WORK/column.log"
$CHECK column "$WORK/column/stations/top.csv" --component x --height 100 --speed 200 --amplitude 0.1 --f0 5 --t0 0.24 --l2-max 0.015 --late-max 1e-3
$SW -options_file config/scenes/foundation_3d.yaml -output_dir "$WORK/f3d" > "$WORK/f3d.log"
$CHECK energy "$WORK/f3d/energy.csv" --max-error 1e-9
$PY scripts/check_output.py "$WORK/f3d"
$PY scripts/check_output.py "$WORK/f3d" --grid interface_base
$PY - "$WORK/f3d" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
f = Frames(sys.argv[1], "interface_base")
xyz = f.geometry
sn = f.field("sigma_N", 0)[:, 0]
slip = max(s.max() for s in f.series("accumulated_slip"))
opened = sum(int(np.any(s == 2)) for s in f.series("status"))
edge_x = np.isclose(np.abs(xyz[:, 0]), 2.0)
edge_y = np.isclose(np.abs(xyz[:, 1]), 2.0)
w = np.where(edge_x & edge_y, 0.25, np.where(edge_x | edge_y, 0.5, 1.0))
mean = np.sum(w * sn) / np.sum(w)
rel = abs(mean / -141264.0 - 1)
print(f"foundation_3d: weighted base traction {mean:.0f} Pa (weight/area -141264), error {rel:.2e}; slip {slip:.4f} m; {opened} frames with an open pair")
sys.exit(0 if rel <= 0.01 and slip > 0.01 and opened > 0 else 1)
PY
$PY scripts/scene_metrics.py "$WORK/f3d" --json "$WORK/f3d_metrics.json" > /dev/null
$PY - "$WORK/f3d" "$WORK/f3d_metrics.json" <<'PY'
import json, sys
run = json.load(open(f"{sys.argv[1]}/run_info.json"))["answers"]
ref = json.load(open(sys.argv[2]))
peak = ref["peak_rocking_angle"]
ok = peak > 0
for k in ("peak_rocking_angle", "tilt_after_shaking", "rocking_at_end"):
    a, b = run[k]["value"], ref[k]
    ok &= abs(a - b) <= 1e-9 * peak
    print(f"foundation_3d {k}: run {a:.10g}, scene_metrics {b:.10g} (bound 1e-9 of {peak:.4g})")
rho, vp, vs = 1900.0, 450.0, 200.0
G = rho * vs**2
nu = (vp**2 - 2 * vs**2) / (2 * (vp**2 - vs**2))
s_half = 141264.0 * 4.0 * (1 - nu**2) * 0.82 / (2 * G * (1 + nu))
settle = run["settlement_gravity"]["value"]
ok &= s_half / 3 <= settle <= 3 * s_half
print(f"foundation_3d settlement under gravity: run {settle * 1e3:.3f} mm, rigid square footing on the half-space {s_half * 1e3:.3f} mm (bound: within a factor 3)")
sys.exit(0 if ok else 1)
PY
