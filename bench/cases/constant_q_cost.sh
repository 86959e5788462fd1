# What constant-Q damping costs per step, through the real executable: the 2D 512^2 Q1 box of
# wave_refinement.sh (one region, SV wave through an absorbing base, 200 steps, 1 rank), elastic
# and with -material_soil_damping_ratio 0.05 (every cell damped, 3 mechanisms: 32 memory
# values per cell, committed and trial). Best of BENCH_REPEATS (3) runs each; appends rows to
# $BENCH_CSV. BENCH_2D=128 for a quick look.
set -u
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
PY=/usr/bin/python3
N=${BENCH_2D:-512}
REPEATS=${BENCH_REPEATS:-3}
WORK="$BUILD/bench/work/constant_q_cost"
mkdir -p "$WORK"
SOIL="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -bc_bottom_type absorbing -input_wave sv -input_boundary bottom
 -input_stf ricker -input_f0 5 -input_t0 0.24 -input_amplitude 0.1"
logs=()
for k in $(seq 1 "$REPEATS"); do
  for xi in 0 0.05; do
    log="$WORK/xi${xi}_$k.log"
    "$SW" -mesh_box_faces "$N,$N" -mesh_box_upper 100,100 $SOIL -material_soil_damping_ratio $xi -output_fields 0 -ts_max_steps 200 -ts_max_time 10 \
      -progress_interval 1000 -output_dir "$WORK/xi$xi" > "$log"
    logs+=("$xi $log")
  done
done
$PY - "${BENCH_CSV:-}" "$N" "${logs[@]}" <<'PY'
import re, sys
csv, n = sys.argv[1], sys.argv[2]
best = {}
for r in sys.argv[3:]:
    xi, log = r.split()
    per = float(re.search(r"\(([0-9.eE+-]+) s per step\)", open(log).read()).group(1))
    best[xi] = min(best.get(xi, 1e300), per)
ratio = best["0.05"] / best["0"]
print(f"2D {n}^2, 1 rank, whole step: elastic {1e3 * best['0']:.2f} ms, constant-Q (xi 0.05, 3 mechanisms) {1e3 * best['0.05']:.2f} ms: x {ratio:.2f}")
if csv:
    with open(csv, "a") as out:
        out.write(f"constant_q_cost,2d_{n},step_elastic,{best['0']:.4g},s\n")
        out.write(f"constant_q_cost,2d_{n},step_constant_q,{best['0.05']:.4g},s\n")
        out.write(f"constant_q_cost,2d_{n},ratio,{ratio:.3f},1\n")
PY
