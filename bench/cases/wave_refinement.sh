# Speed against error, through the real executable (build/slipwave):
#  1. The 1D SV column (100 m, vs 200 m/s, Ricker f0 5 Hz through an absorbing base) at 10,
#     20, 40, 80 points per S wavelength at the Ricker top frequency 2.7638 f0: relative L2
#     error of the surface velocity against the closed form 2 v_in(t - H/vs), the observed
#     convergence rate between successive meshes, and the wall time of the run.
#  2. Whole-step timing of a 2D box (512^2 Q1, 200 steps) and a 3D box (64^3 Q1, 40 steps)
#     with the same wave coming in through an absorbing base and no field output, on 1 and
#     2 ranks: "s per step" of the run report, best of 3 runs (other jobs share the machine),
#     and DOF-updates per second per core = dofs / (s per step) / ranks.
# Rows go to $BENCH_CSV (benchmark,case,metric,value,unit) when it is set; a table to stdout.
# Sizes can be overridden for a quick look: BENCH_2D=128 BENCH_3D=16 BENCH_REPEATS=1.
set -eu
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
PY=/usr/bin/python3
CSV=${BENCH_CSV:-}
N2=${BENCH_2D:-512}
N3=${BENCH_3D:-64}
REPEATS=${BENCH_REPEATS:-3}
MPIEXEC="mpiexec --oversubscribe"
[ "$(id -u)" = 0 ] && MPIEXEC="$MPIEXEC --allow-run-as-root"
WORK="$BUILD/bench/work/wave_refinement"
rm -rf "$WORK"; mkdir -p "$WORK"

SOIL="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200"
WAVE="-bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf ricker -input_f0 5 -input_amplitude 0.1"
H=100; VS=200; F0=5; T0=0.24; A=0.1

# ---- 1. refinement series of the 1D column ----
column_rows=()
for ppw in 10 20 40 80; do
  # cells over the height for ppw points per wavelength lambda = vs / (2.7638 f0); square cells
  read -r ny w <<<"$($PY -c "n=round($ppw*$H*2.7638*$F0/$VS); print(n, $H/n)")"
  out="$WORK/column_ppw$ppw"
  log="$out.log"
  t0=$(date +%s%N)
  "$SW" $SOIL $WAVE -mesh_box_faces 1,"$ny" -mesh_box_upper "$w",$H -constrain_components y -ts_max_time 1.2 \
    -station_coordinates "$($PY -c "print($w/2)")",$H -station_names top -station_interval 0 -output_fields 0 -progress_interval 100 -output_dir "$out" > "$log"
  column_rows+=("$ppw $ny $log $out/stations/top.csv $(( ($(date +%s%N) - t0) / 1000 ))")
done
$PY - "$CSV" "$H" "$VS" "$F0" "$T0" "$A" "${column_rows[@]}" <<'PY'
import math, re, sys
import numpy as np
sys.path.insert(0, "python")
from slipwave import read_csv
csv, H, vs, f0, t0, A = sys.argv[1], *map(float, sys.argv[2:7])
rows = [r.split() for r in sys.argv[7:]]
def v_in(t):
    a = (math.pi * f0 * (t - t0)) ** 2
    return A * (1 - 2 * a) * np.exp(-a)
res = []
for ppw, ny, log, station, us in rows:
    text = open(log).read()
    m = re.search(r"done: (\d+) steps in ([0-9.]+) s wall \(([0-9.eE+-]+) s per step\)", text)
    steps, wall, per = int(m.group(1)), float(m.group(2)), float(m.group(3))
    d = read_csv(station)
    ref = 2 * v_in(d["t"] - H / vs)
    err = math.sqrt(np.sum((d["v_x"] - ref) ** 2) / np.sum(ref ** 2))
    res.append((int(ppw), int(ny), steps, steps * per, int(us) * 1e-6, err))
print("1D SV column, 100 m, surface velocity vs 2 v_in(t - H/vs), t in [0, 1.2] s, 1 rank")
print("  (steps s: stepping only = steps x 's per step'; run s: the whole process incl. set-up and station output)")
print(f"{'ppw':>5} {'cells':>6} {'steps':>6} {'steps s':>9} {'run s':>7} {'L2 error':>10} {'rate':>6}")
out = open(csv, "a") if csv else None
for i, (ppw, ny, steps, wall, run, err) in enumerate(res):
    rate = math.log(res[i - 1][5] / err) / math.log(ppw / res[i - 1][0]) if i else float("nan")
    print(f"{ppw:5d} {ny:6d} {steps:6d} {wall:9.4f} {run:7.2f} {err:10.3e} " + (f"{rate:6.2f}" if i else ""))
    if out:
        case = f"column_1d_ppw{ppw}"
        out.write(f"wave_refinement,{case},cells,{ny},1\n")
        out.write(f"wave_refinement,{case},steps,{steps},1\n")
        out.write(f"wave_refinement,{case},step_wall_time,{wall:.4g},s\n")
        out.write(f"wave_refinement,{case},run_wall_time,{run:.3f},s\n")
        out.write(f"wave_refinement,{case},l2_error_surface_velocity,{err:.4e},1\n")
        if i: out.write(f"wave_refinement,{case},observed_rate,{rate:.3f},1\n")
PY

# ---- 2. whole-step timing, 2D and 3D boxes, 1 and 2 ranks ----
timing_rows=()
run_box() { # dim n steps ranks
  local dim=$1 n=$2 steps=$3 ranks=$4 faces upper k
  if [ "$dim" = 2 ]; then faces="$n,$n"; upper="100,100"; else faces="$n,$n,$n"; upper="100,100,100"; fi
  for k in $(seq 1 "$REPEATS"); do
    local log="$WORK/box${dim}d_${n}_np${ranks}_$k.log"
    local launch="$SW"
    [ "$ranks" -gt 1 ] && launch="$MPIEXEC -n $ranks $SW"
    $launch -mesh_dim "$dim" -mesh_box_faces "$faces" -mesh_box_upper "$upper" $SOIL $WAVE -output_fields 0 -ts_max_steps "$steps" \
      -progress_interval 1000 -output_dir "$WORK/box${dim}d_${n}_np${ranks}" > "$log"
    timing_rows+=("$dim $n $ranks $log")
  done
}
run_box 2 "$N2" 200 1
run_box 2 "$N2" 200 2
run_box 3 "$N3" 40 1
run_box 3 "$N3" 40 2
$PY - "$CSV" "${timing_rows[@]}" <<'PY'
import re, sys
csv = sys.argv[1]
best = {}
for r in sys.argv[2:]:
    dim, n, ranks, log = r.split()
    text = open(log).read()
    nodes = int(re.search(r"cells, (\d+) nodes", text).group(1))
    per = float(re.search(r"\(([0-9.eE+-]+) s per step\)", text).group(1))
    key = (int(dim), int(n), int(ranks))
    b = best.setdefault(key, {"dofs": nodes * int(dim), "per": [], "steps": int(re.search(r"done: (\d+) steps", text).group(1))})
    b["per"].append(per)
print("whole step through build/slipwave (SV wave through an absorbing base, no field output; best of the runs)")
print(f"{'case':>10} {'ranks':>5} {'dofs':>9} {'steps':>5} {'s/step':>10} {'runs':>24} {'Mdof/s':>8} {'Mdof/s/core':>11}")
out = open(csv, "a") if csv else None
for (dim, n, ranks), b in sorted(best.items()):
    per = min(b["per"])
    rate = b["dofs"] / per
    case = f"box{dim}d_{n}_np{ranks}"
    runs = " ".join(f"{p:.3g}" for p in b["per"])
    print(f"{f'{dim}D {n}':>10} {ranks:5d} {b['dofs']:9d} {b['steps']:5d} {per:10.4g} {runs:>24} {rate / 1e6:8.1f} {rate / ranks / 1e6:11.1f}")
    if out:
        out.write(f"wave_refinement,{case},dofs,{b['dofs']},1\n")
        out.write(f"wave_refinement,{case},step_time,{per:.4g},s\n")
        out.write(f"wave_refinement,{case},dof_updates_per_second_per_core,{rate / ranks:.4g},1/s\n")
PY
