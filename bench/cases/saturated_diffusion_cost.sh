# What the explicit pore-pressure diffusion costs across permeabilities (issue 10's benchmark):
# a saturated strip of the 2D box (16 columns of the N^2 box of 100 m, so h = 100/N m; the
# stable steps depend on h only, the strip keeps the runs short) under a P Ricker pulse, run to
# BENCH_T (default 0.2 s) simulated seconds, for hydraulic conductivities 1e-3 .. 1e-7 m/s
# and k = 0 (undrained: no diffusion), with -pore_pressure_subcycle true (the default: the
# step stays the undrained wave's, the diffusion takes m sub-steps) and false (the step drops
# to the diffusion limit). Mesh sizes N in BENCH_DIFFUSION_N (default "128 512": h = 0.78 m,
# a seismic mesh, and 0.20 m). Per run: the step, the sub-steps per step, the steps taken and
# the wall time per simulated second, against k = 0. 1 rank, one run each (a shared machine:
# +-30 %). Rows go to $BENCH_CSV.
set -u
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
PY=/usr/bin/python3
T=${BENCH_T:-0.2}
WORK="$BUILD/bench/work/saturated_diffusion_cost"
mkdir -p "$WORK"
SOIL="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -bc_bottom_type absorbing -input_wave p -input_boundary bottom
 -input_stf ricker -input_f0 5 -input_t0 0.24 -input_amplitude 0.1 -output_fields 0 -ts_max_time $T -progress_interval 100000
 -material_soil_saturated -material_soil_porosity 0.4"
logs=()
for n in ${BENCH_DIFFUSION_N:-128 512}; do
  width=$($PY -c "print(100 * 16 / $n)")
  for kh in 0 1e-3 1e-4 1e-5 1e-6 1e-7; do
    for sub in true false; do
      [ "$kh" = 0 ] && [ $sub = false ] && continue
      log="$WORK/n${n}_k${kh}_$sub.log"
      "$SW" -mesh_box_faces "16,$n" -mesh_box_upper "$width,100" $SOIL -material_soil_hydraulic_conductivity "$kh" -pore_pressure_subcycle $sub \
        -output_dir "$WORK/run" -output_overwrite > "$log"
      logs+=("$n $kh $sub $log")
    done
  done
done
$PY - "${BENCH_CSV:-}" "$T" "${logs[@]}" <<'PY'
import re, sys
csv, T = sys.argv[1], float(sys.argv[2])
runs, rows = [], []
for r in sys.argv[3:]:
    n, kh, sub, log = r.split()
    text = open(log).read()
    dt = float(re.search(r"time step ([0-9.eE+-]+) s", text).group(1))
    m = re.search(r"diffusion sub-cycled: (\d+) sub-steps", text)
    sub_steps = int(m.group(1)) if m else 1
    # The per-step wall time has three digits where the total has two decimals.
    steps, per = re.search(r"done: (\d+) steps in [0-9.eE+-]+ s wall \(([0-9.eE+-]+) s per step\)", text).groups()
    wall = float(per) * int(steps)
    diff = re.search(r"diffusion ([0-9.eE+-]+) s", text).group(1)
    runs.append((int(n), kh, sub, dt, sub_steps, int(steps), float(wall) / T, float(diff)))
base = {n: w for n, kh, sub, dt, m, s, w, d in runs if kh == "0"}
print(f"{'N':>4} {'h [m]':>6} {'k [m/s]':>8} {'subcycle':>8} {'diffusion limit [s]':>20} {'step [s]':>10} {'sub-steps':>9} {'steps':>6} {'wall/sim s':>10} {'x k=0':>6}")
for n, kh, sub, dt, m, steps, w, d in runs:
    print(f"{n:>4} {100 / n:>6.3f} {kh:>8} {sub:>8} {d:>20.3e} {dt:>10.3e} {m:>9} {steps:>6} {w:>10.2f} {w / base[n]:>6.2f}")
    rows.append((f"2d_h{100 / n:.3g}_k{kh}_sub{sub}", "wall_per_simulated_second", w, "s/s"))
    rows.append((f"2d_h{100 / n:.3g}_k{kh}_sub{sub}", "time_step", dt, "s"))
if csv:
    with open(csv, "a") as out:
        for case, metric, value, unit in rows:
            out.write(f"saturated_diffusion_cost,{case},{metric},{value:.4g},{unit}\n")
PY
