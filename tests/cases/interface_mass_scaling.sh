#!/usr/bin/env bash
# Mass scaling of interface nodes (-time_step_mass_scaling interface,
# problem/interface_mass_scaling.hpp) on the Newmark sliding block of
# interface_newmark_block.sh (config/scenes/sliding_block.yaml: 1 m x 1 m block, rho 2400,
# phi = atan 0.2, base pulse A = 0.4 g for t_p = 0.2 s, E = G = 1e10 Pa/m), on rows of 0.25 m
# (-mesh_box_faces 1,6) and 0.125 m (2,12), each with and without the scaling.
# Expected:
# - the penalty no longer lowers the step: the report's limit with scaling is the bulk's own
#   (no "interface penalty lowers" warning) and above the limit without it;
# - the added mass is inertia without weight, so the block slides as Newmark's block of
#   inertia M + a and weight M g, i.e. with N' = N M / (M + a): slip V^2/(2 g N')(1 - N'/A)
#   (Newmark 1965). M = 2400 kg/m; a = half the added mass the report prints (both sides
#   are the same material on the same rows, so their pair nodes take the same mass). The
#   ratio of the scaled run's slip to the unscaled one's must be Newmark's ratio
#   slip(N')/slip(N) within 0.2 % (measured: 0.03 %; the penalty's stick error and the
#   block's flexibility, 0.55 % of the slip, cancel in the ratio);
# - the added mass falls as h^2 (dt^2 k / 4 per node: dt ~ h, the springs' total fixed):
#   0.125 m rows carry a quarter of the 0.25 m rows' (within 1 %), and the slip's change
#   with it (observed order 2 +- 0.2);
# - the energy balance closes with the scaled mass as without it: here no worse than the
#   unscaled run (whose prescribed-velocity base leaves 2e-11 .. 3e-10 stuck or sliding;
#   bound 3 x its error), and to round-off (bound 1e-12) on the default scene
#   (config/scenes/default.yaml: rigid block on yielding clay, absorbing base, free-field
#   sides, its first 0.5 s), whose scaled limit must be the bulk's own; 2 ranks give the
#   1-rank slip (sliding block) and rocking (default scene) to 1e-9; run_info.json says the
#   mass added (its "mass_scaling": the report's number, the lightest region: the base); a
#   restart halfway (the scaled mass is set up again, not stored) gives the straight run's
#   energy.csv and station files byte for byte.
set -eu
. tests/tools/lib.sh
newmark_pulse "$WORK/pulse.csv"
for m in "1,6" "2,12"; do
  for s in none interface; do
    run="$WORK/m${m/,/x}_$s"
    $SW -options_file config/scenes/sliding_block.yaml -mesh_box_faces $m -time_step_mass_scaling $s -bc_bottom_record "$WORK/pulse.csv" -output_dir "$run" > "$run.log"
  done
  grep "mass scaling" "$WORK/m${m/,/x}_interface.log"
  if grep -q "interface penalty lowers" "$WORK/m${m/,/x}_interface.log"; then echo "FAIL the penalty still lowers the step with mass scaling ($m)"; exit 1; fi
done
for np in 1 2; do
  $MPIEXEC -n $np $SW -options_file config/scenes/default.yaml -time_step_mass_scaling interface -ts_max_time 0.5 -output_fields 0 -output_dir "$WORK/scene$np" > "$WORK/scene$np.log"
done
grep "mass scaling" "$WORK/scene1.log"
if grep -q "interface penalty lowers" "$WORK/scene1.log"; then echo "FAIL the penalty still lowers the default scene's step with mass scaling"; exit 1; fi
scaled="-options_file config/scenes/sliding_block.yaml -mesh_box_faces 2,12 -time_step_mass_scaling interface -bc_bottom_record $WORK/pulse.csv"
half=$(( $(tail -1 "$WORK/m2x12_interface/energy.csv" | cut -d, -f1) / 2 ))
$SW $scaled -ts_max_steps $half -checkpoint_interval $half -output_dir "$WORK/A" > "$WORK/A.log"
cp -r "$WORK/A" "$WORK/B"
$SW $scaled -restart "$WORK/B/checkpoint.bin" -output_dir "$WORK/B" | grep -E "^restart|^done"
cmp "$WORK/B/energy.csv" "$WORK/m2x12_interface/energy.csv"
for s in base mid top; do cmp "$WORK/B/stations/$s.csv" "$WORK/m2x12_interface/stations/$s.csv"; done
echo "ok restart halfway with the scaled mass: energy.csv and the stations byte for byte"
$MPIEXEC -n 2 $SW -options_file config/scenes/sliding_block.yaml -mesh_box_faces 2,12 -time_step_mass_scaling interface -bc_bottom_record "$WORK/pulse.csv" \
  -output_dir "$WORK/np2" > "$WORK/np2.log"
$PY - "$WORK" <<'PY'
import json, math, re, sys
sys.path.insert(0, "python")
import numpy as np
from slipwave import RunFolder
work = sys.argv[1]
A, N, g, tp, M = 0.4, 0.2, 9.81, 0.2, 2400.0
V = A * g * tp
newmark = lambda n: V**2 / (2 * g * n) * (1 - n / A)  # Newmark (1965), rigid block
slip = lambda run: float(np.max(RunFolder(f"{work}/{run}").interface("slide").field("accumulated_slip", -1)))
failed = 0
def check(ok, text):
    global failed
    print(("ok " if ok else "FAIL ") + text)
    failed += not ok
added, change = {}, {}
for tag in ("m1x6", "m2x12"):
    log = open(f"{work}/{tag}_interface.log").read()
    ms = re.search(r"carry \+(\S+) kg/m .* the limit (\S+) s instead of (\S+) s", log)
    added[tag] = float(ms.group(1))
    info = json.load(open(f"{work}/{tag}_interface/run_info.json"))["mass_scaling"]
    check(abs(info["added_kg"] / added[tag] - 1) < 5e-4 and info["lightest_region"] == "base", f"{tag}: run_info.json mass_scaling {info}")
    check(float(ms.group(2)) > float(ms.group(3)), f"{tag}: the limit with scaling {ms.group(2)} s above the own-mass limit {ms.group(3)} s")
    balance, own = (abs(float(re.search(r"energy balance error (\S+) of the largest energy", text).group(1))) for text in (log, open(f"{work}/{tag}_none.log").read()))
    check(balance <= 3 * own, f"{tag}: energy balance error {balance:.2e} with the scaled mass, {own:.2e} without (bound 3 x)")
    s0, s1 = slip(f"{tag}_none"), slip(f"{tag}_interface")
    n_scaled = N * M / (M + added[tag] / 2)
    expected, measured = newmark(n_scaled) / newmark(N), s1 / s0
    check(abs(measured / expected - 1) <= 2e-3,
          f"{tag}: slip {s1 * 1e3:.3f} mm scaled / {s0 * 1e3:.3f} mm own = {measured:.5f}; Newmark with inertia M + {added[tag] / 2:.4g} kg/m: {expected:.5f} (bound 0.2 %)")
    change[tag] = s1 - s0
for np_ in (1, 2):
    balance = abs(float(re.search(r"energy balance error (\S+) of the largest energy", open(f"{work}/scene{np_}.log").read()).group(1)))
    check(balance <= 1e-12, f"default scene, scaled, {np_} rank(s): energy balance error {balance:.2e} (bound 1e-12)")
theta = [np.genfromtxt(f"{work}/scene{np_}/rigid_block.csv", delimiter=",", names=True)["theta_z"] for np_ in (1, 2)]
d = float(np.max(np.abs(theta[1] - theta[0]))) / float(np.max(np.abs(theta[0])))
check(d <= 1e-9, f"default scene, scaled: rocking angle on 2 ranks within {d:.1e} of 1 rank's peak (bound 1e-9)")
ratio = added["m1x6"] / added["m2x12"]
check(abs(ratio / 4 - 1) <= 0.01, f"added mass {added['m1x6']:.4g} / {added['m2x12']:.4g} kg/m = {ratio:.3f} for rows halved (expected 4: h^2)")
order = math.log2(change["m1x6"] / change["m2x12"])
check(abs(order - 2) <= 0.2, f"the slip's change by the scaling {change['m1x6'] * 1e3:.3f} -> {change['m2x12'] * 1e3:.3f} mm: observed order {order:.2f} (expected 2 +- 0.2)")
s1, s2 = slip("m2x12_interface"), slip("np2")
check(abs(s2 - s1) <= 1e-9 * s1, f"2 ranks: slip {s2 * 1e3:.9f} mm against 1 rank {s1 * 1e3:.9f} mm (bound 1e-9 relative)")
sys.exit(1 if failed else 0)
PY
