# The answers the run states at its end (app/run_answers.hpp) against scripts/scene_metrics.py
# on the same run's output: config/scenes/default.yaml on its 2 m companion mesh (the scene's
# config/scenes/default.geo at the size factor 2, the level make run's band runs), shortened to 2 s (the block's first slip and
# uplift at 1.6-2 s), on 2 ranks, stations every step (-station_interval 0), interface frames
# every 5 ms.
#  - From the stations (every step here, as the run's own accumulation): the 5 %-damped PSA
#    of block_top and free_field at the 7 periods, free_field_pga, peak_structure_acceleration:
#    the same Nigam-Jennings recursion on the same samples, equal to 1e-9; the peaks of
#    block_top and free_field low-passed at the resolved frequency (12.3 Hz here): the same
#    zero-padded frequency-domain filter on the same samples, equal to 1e-9.
#  - peak_rocking_angle: the rigid block's rotation against scene_metrics' |u_y(right) -
#    u_y(left)| / 5.5 m of the stations 0.25 m inside its base corners: a rigid body's points
#    move as U + theta x r exactly, so equal to 1e-9. tilt_after_shaking (the same angle,
#    signed, its mean over the last 2 s) and rocking_at_end (its half range there): the same
#    trapezoids on the same samples, equal to 1e-9 of the peak (their round-off is that of
#    the rotation, and they can be far smaller than the peak).
#  - net_slip and accumulated_slip: the state at the last step, which is also the last frame:
#    equal to 1e-9.
#  - peak_uplift, mean_slip_range, largest_slip_excursion: the run takes every step, the
#    script the frames (every 5 ms, ~25 steps), a subset: so by construction the run's peak
#    and range are >= the script's (to round-off), and exceed them by at most what the
#    quantity moves between two frames, bounded by the largest change of it between
#    consecutive frames (the opening of any pair, the mean slip; twice that for the
#    excursion, whose two ends may each fall between frames).
# run_info.json holds them as {"value", "unit"}; the table is printed. Then the default
# sampling (-station_interval 0.005 s) on 1 rank: the answers do not depend on it nor on the
# ranks (the bounds of default_scene_ranks.sh: 1e-9 of u, 1e-8 of a and of what comes
# from it), the station rows are uniform, every round(0.005 / dt) steps, rigid_block.csv has
# a row per station row, and 15 s of stations (the default scene) stay under 1 MB a file.
# A restart with the default sampling (0.4 s, from a checkpoint at step 1000, which is not a
# sample step) writes station and rigid-body files identical to the straight run's, and
# counts the steps it ran.
set -eu -o pipefail
. tests/tools/lib.sh
. tests/tools/together.sh
default_companion "$WORK/coarse.msh"
opts="-options_file config/scenes/default.yaml -mesh_file $WORK/coarse.msh -ts_max_time 2 -progress_interval 100000 -output_fields 0"
$MPIEXEC -n 2 $SW $opts -station_interval 0 -output_interval 0.005 -output_dir "$WORK/np2" > "$WORK/np2.log"
sed -n '/^answers/,$p' "$WORK/np2.log"
grep -q "^  peak rocking angle (rigid body block)" "$WORK/np2.log"
$PY scripts/scene_metrics.py "$WORK/np2" --json "$WORK/metrics.json" > /dev/null
# The 1-rank runs (np1 here, the straight run and the checkpointed first half below) are
# independent: two at a time (tests/tools/together.sh); the restart after its first half.
short="$opts -ts_max_time 0.4 -output_interval 1"
together "$SLIPWAVE_BINARY" $opts -output_interval 1 -output_dir "$WORK/np1" > "$WORK/np1.log"
together "$SLIPWAVE_BINARY" $short -output_dir "$WORK/straight" > "$WORK/straight.log"
together "$SLIPWAVE_BINARY" $short -checkpoint_interval 500 -ts_max_steps 1000 -output_dir "$WORK/first" > /dev/null
together_wait
$PY - "$WORK" <<'PY'
import json, sys
import numpy as np
sys.path.insert(0, "tests/tools"); sys.path.insert(0, "python")
from slipwave import RunFolder
work = sys.argv[1]
run = json.load(open(f"{work}/np2/run_info.json"))["answers"]
ref = json.load(open(f"{work}/metrics.json"))
ok = True
def report(name, good, text):
    global ok
    ok &= bool(good)
    print(f"{'ok' if good else 'FAIL'}: {name}: {text}")
equal = ["net_slip", "accumulated_slip", "peak_rocking_angle", "peak_structure_acceleration", "free_field_pga"]
equal += [k for k in ref if "_psa_" in k]
equal += [k for k in ref if k.endswith("_peak_acceleration_lowpassed")]
for k in equal:
    a, b = run[k]["value"], ref[k]
    report(k, abs(a - b) <= 1e-9 * abs(b), f"run {a:.10g}, scene_metrics {b:.10g} (bound 1e-9 relative)")
frames = RunFolder(f"{work}/np2").interface("base")
st = frames.stacked(["slip", "opening"])
s = st["slip"][:, :, 0].mean(axis=1)
w = st["opening"][:, :, 0]
moves = {"peak_uplift": np.max(np.abs(np.diff(w, axis=0))), "mean_slip_range": np.max(np.abs(np.diff(s))), "largest_slip_excursion": 2 * np.max(np.abs(np.diff(s)))}
for k, bound in moves.items():
    a, b = run[k]["value"], ref[k]
    report(k, b - 1e-12 <= a <= b + bound, f"run {a:.6g} (every step) vs scene_metrics {b:.6g} (frames every 5 ms): {b:.6g} <= run <= {b + bound:.6g}")
for k in ("tilt_after_shaking", "rocking_at_end"):
    a, b = run[k]["value"], ref[k]
    report(k, abs(a - b) <= 1e-9 * ref["peak_rocking_angle"] and abs(b) > 0, f"run {a:.10g}, scene_metrics {b:.10g} (bound 1e-9 of the peak {ref['peak_rocking_angle']:.4g})")
units = {"tilt_after_shaking": "rad", "rocking_at_end": "rad", "net_slip": "m", "peak_rocking_angle": "rad", "free_field_pga": "m/s^2", "settlement_gravity": "m", "settlement_after_shaking": "m"}
for k, u in units.items():
    report(f"unit of {k}", run[k]["unit"] == u, run[k]["unit"])
one = json.load(open(f"{work}/np1/run_info.json"))["answers"]
for k in run:
    a, b = one[k]["value"], run[k]["value"]
    tol = 1e-9 if run[k]["unit"] in ("m", "rad") else 1e-8
    # A settlement after shaking can be ~0 (a block that stays put): its round-off is that of
    # the displacements it is the difference of, so it is judged against the gravity settlement.
    # The tilt and the rocking left likewise against the peak rocking angle.
    scale = max(abs(b), abs(run["settlement_gravity"]["value"]) if k.startswith("settlement") else 0.0,
                run["peak_rocking_angle"]["value"] if k in ("tilt_after_shaking", "rocking_at_end") else 0.0, 1e-30)
    report(f"1 vs 2 ranks {k}", abs(a - b) <= tol * scale, f"{a:.12g} vs {b:.12g} (bound {tol:g} of {scale:.4g})")
dt = json.load(open(f"{work}/np1/run_info.json"))["time_step_s"]
every = max(1, round(0.005 / dt))
t = np.loadtxt(f"{work}/np1/stations/block_top.csv", delimiter=",", skiprows=1)[:, 0]
report("uniform default sampling", np.allclose(np.diff(t), every * dt, rtol=1e-9), f"rows every {every} steps = {every * dt:.6g} s, {len(t)} rows")
rigid = np.loadtxt(f"{work}/np1/rigid_block.csv", delimiter=",", skiprows=1)
report("rigid_block.csv", open(f"{work}/np1/rigid_block.csv").readline().strip() == "t,u_x,u_y,theta_z" and np.array_equal(rigid[:, 0], t), f"{len(rigid)} rows at the station times")
import os
size = os.path.getsize(f"{work}/np1/stations/block_top.csv") * 15 / 2
report("station CSV size over 15 s", size < 1e6, f"{size / 1e6:.2f} MB projected from 2 s (bound 1 MB)")
sys.exit(0 if ok else 1)
PY
"$SLIPWAVE_BINARY" $short -restart "$WORK/first/checkpoint.bin" -output_dir "$WORK/resumed" > "$WORK/resumed.log"
grep -E "^restart|^done|^answers" "$WORK/resumed.log"
grep -q "^restart: continuing from step 1000," "$WORK/resumed.log"
all=$(sed -n 's/^done: \([0-9]*\) steps.*/\1/p' "$WORK/straight.log")
ran=$(sed -n 's/^done: \([0-9]*\) steps.*/\1/p' "$WORK/resumed.log")
echo "restart: ran $ran steps of the straight run's $all (want $all - 1000)"
[ "$ran" -eq $((all - 1000)) ]
for f in rigid_block.csv stations/block_top.csv stations/free_field.csv; do
  cmp "$WORK/straight/$f" "$WORK/resumed/$f"
  echo "restart: $f identical to the straight run's ($(grep -c '' "$WORK/resumed/$f") lines)"
done
