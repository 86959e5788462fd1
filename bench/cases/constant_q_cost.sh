# What constant-Q damping costs per step, through the real executable: the 2D 512^2 Q1 box of
# wave_refinement.sh (one region, SV wave through an absorbing base, 200 steps, 1 rank), elastic
# with -material_soil_damping_ratio 0.05 (one damped region covering the mesh, 3 mechanisms:
# the memory is driven by K_U u itself), and with the lower half an elastic region "rock" (the
# damped half needs its own pass of the element loop and an assembly). Best of BENCH_REPEATS
# (3) runs each; appends rows to $BENCH_CSV. BENCH_2D=128 for a quick look.
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
  for case in elastic all half; do
    log="$WORK/${case}_$k.log"
    xi=0.05; [ $case = elastic ] && xi=0
    half=""; [ $case = half ] && half="-regions soil,rock -region_rock_box 0,100,0,50 -material_rock_rho 2000 -material_rock_vp 400 -material_rock_vs 200"
    "$SW" -mesh_box_faces "$N,$N" -mesh_box_upper 100,100 $SOIL $half -material_soil_damping_ratio $xi -output_fields 0 -ts_max_steps 200 -ts_max_time 10 \
      -progress_interval 1000 -output_dir "$WORK/$case" > "$log"
    logs+=("$case $log")
  done
done
$PY - "${BENCH_CSV:-}" "$N" "${logs[@]}" <<'PY'
import re, sys
csv, n = sys.argv[1], sys.argv[2]
best = {}
for r in sys.argv[3:]:
    case, log = r.split()
    per = float(re.search(r"\(([0-9.eE+-]+) s per step\)", open(log).read()).group(1))
    best[case] = min(best.get(case, 1e300), per)
e = best["elastic"]
print(f"2D {n}^2, 1 rank, whole step: elastic {1e3 * e:.2f} ms; constant-Q (xi 0.05, 3 mechanisms) everywhere {1e3 * best['all']:.2f} ms (x {best['all'] / e:.2f}), "
      f"in the upper half {1e3 * best['half']:.2f} ms (x {best['half'] / e:.2f})")
if csv:
    with open(csv, "a") as out:
        for case in ("elastic", "all", "half"):
            out.write(f"constant_q_cost,2d_{n}_{case},step_wall_time,{best[case]:.4g},s\n")
PY
