# Where a step's time goes, through the real executable with -log_view: the 2D 1024^2 and 3D
# 64^3 Q1 boxes (edge 100 m, one soil region) with absorbing base and sides, an SV Ricker
# input through the base, the energy ledger at its default interval, no field output; 1 and 2
# ranks. Per case, best of BENCH_REPEATS (5) runs, the 1- and 2-rank runs of a box interleaved
# (other jobs and the VM's neighbours share the machine; the slower rank changes from run to
# run, so single runs measure the noise, not the code): the whole
# step ("s per step" of the run report), the bulk force (SW:Bulk:Force), the boundary terms
# (SW:Boundary:Apply), the acceleration pass over every dof (SW:Accel:Assemble), the ledger (SW:Energy:Ledger) per step (max over ranks), the ratio
# whole step / bulk force of the same run, DOF-updates per second per core and the 2-rank
# efficiency (1-rank step / (2 x 2-rank step)). Appends rows to $BENCH_CSV.
# BENCH_STEP_2D=256 BENCH_STEP_3D=24 for a quick look. BENCH_STEP_DEGREES (default "1 4"): the
# same boxes (same nodes) as spectral elements of degree p, n/p elements per direction (issue
# 14's throughput targets at p = 4: 80 M DOF-updates/s/core in 2D, 40 M in 3D).
set -u
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
PY=/usr/bin/python3
MPIEXEC="mpiexec --oversubscribe"
[ "$(id -u)" = 0 ] && MPIEXEC="$MPIEXEC --allow-run-as-root"
N2=${BENCH_STEP_2D:-1024}
N3=${BENCH_STEP_3D:-64}
DEGREES=${BENCH_STEP_DEGREES:-1 4}
REPEATS=${BENCH_REPEATS:-5}
WORK="$BUILD/bench/work/step_cost"
mkdir -p "$WORK"
SOIL="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -input_wave sv -input_boundary bottom -input_stf ricker -input_f0 5
 -input_t0 0.24 -input_amplitude 0.1 -output_fields 0 -progress_interval 1000 -log_view"
logs=()
run_box() { # dim n steps ranks degree repeat
  local dim=$1 n=$2 steps=$3 ranks=$4 p=$5 k=$6 faces upper sides
  local e=$((n / p))
  if [ "$dim" = 2 ]; then faces="$e,$e"; upper="100,100"; sides="bottom left right"
  else faces="$e,$e,$e"; upper="100,100,100"; sides="bottom left right front back"; fi
  local bc=""
  for s in $sides; do bc="$bc -bc_${s}_type absorbing"; done
  local launch="$SW"
  [ "$ranks" -gt 1 ] && launch="$MPIEXEC -n $ranks $SW"
  local log="$WORK/box${dim}d_${n}_p${p}_np${ranks}_$k.log"
  $launch -mesh_dim "$dim" -mesh_box_faces "$faces" -mesh_box_upper "$upper" -element_degree "$p" $SOIL $bc -ts_max_steps "$steps" -ts_max_time 100 \
    -output_dir "$WORK/box${dim}d_${n}_p${p}_np${ranks}" -output_overwrite > "$log"
  logs+=("$dim $n $ranks $p $log")
}
for p in $DEGREES; do
  for k in $(seq 1 "$REPEATS"); do
    run_box 2 "$N2" 100 1 "$p" "$k"
    run_box 2 "$N2" 100 2 "$p" "$k"
  done
  for k in $(seq 1 "$REPEATS"); do
    run_box 3 "$N3" 40 1 "$p" "$k"
    run_box 3 "$N3" 40 2 "$p" "$k"
  done
done
$PY - "${BENCH_CSV:-}" "${logs[@]}" <<'PY'
import re, sys
csv = sys.argv[1]
best = {}
def event(text, name):
    # The Solve stage's line: name, count, ratio, max time over ranks [s].
    solve = text[text.index("--- Event Stage 3: Solve"):]
    m = re.search(r"^" + re.escape(name) + r"\s+(\d+)\s+[0-9.]+\s+([0-9.eE+-]+)", solve, re.M)
    return int(m.group(1)), float(m.group(2))
for r in sys.argv[2:]:
    dim, n, ranks, p, log = r.split()
    text = open(log).read()
    m = re.search(r"done: (\d+) steps in [0-9.]+ s wall \(([0-9.eE+-]+) s per step\)", text)
    steps, per = int(m.group(1)), float(m.group(2))
    row = {"step": per}
    for key, name in (("bulk", "SW:Bulk:Force"), ("boundary", "SW:Boundary:Apply"), ("accel", "SW:Accel:Assemble"), ("ledger", "SW:Energy:Ledger"), ("tsstep", "TSStep")):
        count, t = event(text, name)
        row[key] = t / steps
    key = (int(dim), int(n), int(p), int(ranks))
    if key not in best or per < best[key]["step"]:
        best[key] = row
rows = []
def name(dim, n, p):  # degree 1 keeps the names of the earlier rows
    return f"box{dim}d_{n}" + (f"_p{p}" if p > 1 else "")
for (dim, n, p, ranks), b in sorted(best.items()):
    dofs = dim * (n + 1) ** dim
    case = f"{name(dim, n, p)}_np{ranks}"
    mdof = dofs / b["step"] / ranks / 1e6
    print(f"{case}: {dofs} dofs, step {1e3 * b['step']:.2f} ms (bulk {1e3 * b['bulk']:.2f}, boundary {1e3 * b['boundary']:.2f}, acceleration {1e3 * b['accel']:.2f}, "
          f"ledger {1e3 * b['ledger']:.2f}), "
          f"step/bulk {b['step'] / b['bulk']:.2f}, {mdof:.1f} M DOF-updates/s/core")
    rows += [(case, "step_wall_time", b["step"], "s"), (case, "bulk_force_time", b["bulk"], "s"), (case, "boundary_time", b["boundary"], "s"),
             (case, "acceleration_time", b["accel"], "s"), (case, "ledger_time", b["ledger"], "s"), (case, "step_over_bulk", b["step"] / b["bulk"], "-"), (case, "dof_updates_per_core", mdof * 1e6, "1/s")]
for dim, n, p in sorted({(d, n, p) for d, n, p, _ in best}):
    if (dim, n, p, 1) in best and (dim, n, p, 2) in best:
        eff = best[(dim, n, p, 1)]["step"] / (2 * best[(dim, n, p, 2)]["step"])
        # Per event too (1-rank time / (2 x 2-rank time), the slower rank's): which part does
        # not halve. The ledger's reduction waits for the slower rank, so it holds the imbalance.
        parts = ", ".join(f"{k} {100 * best[(dim, n, p, 1)][k] / (2 * best[(dim, n, p, 2)][k]):.0f} %" for k in ("bulk", "boundary", "accel", "ledger")
                          if best[(dim, n, p, 2)][k] > 0)
        print(f"{name(dim, n, p)}: 2-rank efficiency {100 * eff:.0f} % ({parts})")
        rows.append((name(dim, n, p), "efficiency_2_ranks", eff, "-"))
if csv:
    with open(csv, "a") as out:
        for case, metric, value, unit in rows:
            out.write(f"step_cost,{case},{metric},{value:.4g},{unit}\n")
PY
