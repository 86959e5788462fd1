# What a saturated region costs, through the real executable (1 rank, best of BENCH_REPEATS
# runs, 200 steps): time per step of the 2D N^2 Q1 box (BENCH_2D, default 512) and of the 3D
# M^3 Q1 box (BENCH_3D, default 48), dry and saturated (k = 0, so the undrained wave sets the
# step and the per-step work is compared at the same mesh), per DOF-update of the mixture
# (target of issue 10: at most 1.6x the dry); and the stable step the explicit pore-pressure
# diffusion allows on the 2D box (h = 100/N m) for hydraulic conductivities 1e-3 .. 1e-7 m/s
# against the undrained wave's, from the setup report (-dry_run). Rows go to $BENCH_CSV.
set -u
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
PY=/usr/bin/python3
N=${BENCH_2D:-512}
N3=${BENCH_3D:-48}
REPEATS=${BENCH_REPEATS:-3}
WORK="$BUILD/bench/work/saturated_cost"
mkdir -p "$WORK"
SOIL="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -bc_bottom_type absorbing -input_wave p -input_boundary bottom
 -input_stf ricker -input_f0 5 -input_t0 0.24 -input_amplitude 0.1 -output_fields 0 -ts_max_steps 200 -ts_max_time 10 -progress_interval 1000"
WET="-material_soil_saturated -material_soil_porosity 0.4 -material_soil_hydraulic_conductivity"
logs=()
for k in $(seq 1 "$REPEATS"); do
  for case in dry wet; do
    sat=""; [ $case = wet ] && sat="$WET 0"
    "$SW" -mesh_box_faces "$N,$N" -mesh_box_upper 100,100 $SOIL $sat -output_dir "$WORK/2d_$case" > "$WORK/2d_${case}_$k.log"
    "$SW" -mesh_dim 3 -mesh_box_faces "$N3,$N3,$N3" -mesh_box_upper 100,100,100 $SOIL $sat -output_dir "$WORK/3d_$case" > "$WORK/3d_${case}_$k.log"
    logs+=("2d_$case $WORK/2d_${case}_$k.log" "3d_$case $WORK/3d_${case}_$k.log")
  done
done
for kh in 1e-3 1e-4 1e-5 1e-6 1e-7; do
  "$SW" -mesh_box_faces "$N,$N" -mesh_box_upper 100,100 $SOIL $WET $kh -dry_run -output_dir "$WORK/k$kh" > "$WORK/k_$kh.log"
  logs+=("k$kh $WORK/k_$kh.log")
done
$PY - "${BENCH_CSV:-}" "$N" "$N3" "${logs[@]}" <<'PY'
import math, re, sys
csv, n, n3 = sys.argv[1], sys.argv[2], sys.argv[3]
best, rows = {}, []
for r in sys.argv[4:]:
    case, log = r.split()
    text = open(log).read()
    if case.startswith("k"):
        m = re.search(r"undrained wave ([0-9.eE+-]+) s .*diffusion ([0-9.eE+-]+) s", text)
        wave, diff = float(m.group(1)), float(m.group(2))
        ratio = wave / diff
        print(f"k = {case[1:]} m/s on the 2D {n}^2 box: diffusion limit {diff:.3e} s, undrained wave {wave:.3e} s: "
              + (f"{math.ceil(ratio / 0.9)} diffusion sub-steps per step (or a {ratio:.3g}x smaller step with -pore_pressure_subcycle false)" if ratio > 0.9 else "free"))
        rows.append((f"2d_{n}_k{case[1:]}", "diffusion_step", diff, "s"))
        rows.append((f"2d_{n}_k{case[1:]}", "wave_step", wave, "s"))
        continue
    per = float(re.search(r"\(([0-9.eE+-]+) s per step\)", text).group(1))
    best[case] = min(best.get(case, 1e300), per)
for d, size in (("2d", f"{n}^2"), ("3d", f"{n3}^3")):
    # DOF-updates: dim per node dry; dim + 1 per node saturated (the mixture's u and p).
    dim = 2 if d == "2d" else 3
    ratio = best[f"{d}_wet"] / best[f"{d}_dry"]
    print(f"{d} {size}, 1 rank, whole step: dry {1e3 * best[d + '_dry']:.2f} ms, saturated {1e3 * best[d + '_wet']:.2f} ms (x {ratio:.2f}; per DOF-update x {ratio * dim / (dim + 1):.2f}, target <= 1.6)")
    for case in ("dry", "wet"):
        rows.append((f"{d}_{case}", "step_wall_time", best[f"{d}_{case}"], "s"))
if csv:
    with open(csv, "a") as out:
        for case, metric, value, unit in rows:
            out.write(f"saturated_cost,{case},{metric},{value:.4g},{unit}\n")
PY
