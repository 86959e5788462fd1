# Stable step with constant-Q damping (issue 8): the memory update is unconditionally stable,
# so the step is set by the unrelaxed moduli alone; with the default reference frequency the
# step must stay within 2 % of the elastic model with the same vp, vs. Measured on a 2D
# two-material box (the Gershgorin bound of the whole mesh, through the executable) for
# xi = 0.05 and xi = 0.2 in the rock (which sets the step), and both regions damped with
# another band and 5 mechanisms.
# Soil damped alone (the rock's cells set the step): the automatic reference frequency is the
# band's geometric centre sqrt(0.5 x 20) = 3.1623 Hz (the given speeds hold mid-band), and the
# whole mesh's step still within 2 % of the elastic one.
# And the run report's stable-step cost of Rayleigh damping: the undamped step it prints must
# be the elastic run's, and the damped one the closed form of central difference with
# stiffness-proportional damping, dt = (2/w)(sqrt(1 + z^2) - z), z = beta w / 2, w = 2/dt_0,
# beta = 2 xi / (w1 + w2) (Rayleigh damping xi at f1 and f2).
set -eu
. tests/tools/lib.sh
box="-mesh_box_faces 20,10 -mesh_box_upper 40,20 -regions soil,rock -region_rock_box 0,40,0,6 -material_soil_rho 1900 -material_soil_vp 500
 -material_soil_vs 200 -material_rock_rho 2400 -material_rock_vp 1600 -material_rock_vs 800 -bc_bottom_type absorbing -ts_max_time 1 -dry_run"
$SW $box > "$WORK/elastic.log"
$SW $box -material_rock_damping_ratio 0.05 > "$WORK/q10.log"
$SW $box -material_rock_damping_ratio 0.2 > "$WORK/q2.log"
$SW $box -material_soil_damping_ratio 0.05 -material_rock_damping_ratio 0.2 -attenuation_band 0.1,30 -attenuation_mechanisms 5 > "$WORK/both.log"
$SW $box -material_soil_damping_ratio 0.05 > "$WORK/soil.log"
$SW $box -damping_ratio 0.05 -damping_frequencies 1,10 > "$WORK/rayleigh.log"
$PY - "$WORK" <<'PY'
import re
import sys
import numpy as np
work = sys.argv[1]
def stable(name):
    return float(re.search(r"stable step: ([0-9.e+-]+) s", open(f"{work}/{name}.log").read()).group(1))
dt0 = stable("elastic")
ok = True
for name in ("q10", "q2", "both", "soil"):
    drop = 1 - stable(name) / dt0
    print(f"stable step, {name}: {stable(name):.4e} s, {drop:.2%} below the elastic {dt0:.4e} s (bound 2 %)")
    ok = ok and 0 <= drop <= 0.02
ref = float(re.search(r"; reference ([0-9.e+-]+) Hz", open(f"{work}/soil.log").read()).group(1))
print(f"soil damped alone: reference {ref:.5g} Hz (band centre {np.sqrt(0.5 * 20):.5g} Hz, bound 1e-9 relative)")
ok = ok and abs(ref / np.sqrt(10) - 1) <= 1e-9
text = open(f"{work}/rayleigh.log").read()
m = re.search(r"lowers the stable step from ([0-9.e+-]+) s \(undamped\) to ([0-9.e+-]+) s", text)
beta = 2 * 0.05 / (2 * np.pi * (1 + 10))
undamped, damped = float(m.group(1)), float(m.group(2))
w = 2 / undamped
z = beta * w / 2
expect = (2 / w) * (np.sqrt(1 + z * z) - z)
print(f"Rayleigh: report says {undamped:.4e} s undamped (elastic run {dt0:.4e} s), {damped:.4e} s damped (closed form {expect:.4e} s), "
      f"-{1 - damped / undamped:.1%}; bounds 1e-4 relative (5 printed digits)")
ok = ok and abs(undamped / dt0 - 1) <= 1e-4 and abs(damped / expect - 1) <= 1e-4 and stable("rayleigh") == damped
sys.exit(0 if ok else 1)
PY
