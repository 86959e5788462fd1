# What hysteretic soil costs per step, through the real executable (issue 22: "2D 512^2, p = 1
# and p = 4, with every soil cell hysteretic"): the 2D N^2 box of constant_q_cost.sh (one
# region, SV wave of 0.5 m/s through an absorbing base so that the soil yields where the wave
# is, 200 steps, 1 rank), linear and hysteretic (MKZ, gamma_r 1e-3, N = 24 surfaces) at p = 1
# with the stress at the Gauss points and once per cell (-material_soil_stress_points mean),
# and at p = 4 (N/4 elements per side, the same nodes) linear and hysteretic; with BENCH_3D=M
# (default 0: none) also the 3D M^3 box at p = 1 (linear, Gauss points, once per cell). Best of
# BENCH_REPEATS (3) runs each; appends rows to $BENCH_CSV. BENCH_2D=128 for a quick look.
# In 200 steps the S wave front travels about 73 m (vs 200 m/s, dt 1.84 ms): it covers a 64^2
# box, and 29 % of a 256^2 one, 14 % of 512^2; the rest of the soil is still at rest, where a
# point costs a few loads (docs/hysteretic-soil.md, "Cost per step"), so the ratio depends on N.
set -u
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
PY=/usr/bin/python3
N=${BENCH_2D:-512}
M=${BENCH_3D:-0}
REPEATS=${BENCH_REPEATS:-3}
WORK="$BUILD/bench/work/hysteretic_cost"
mkdir -p "$WORK"
SOIL="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -bc_bottom_type absorbing -input_wave sv -input_boundary bottom
 -input_stf ricker -input_f0 5 -input_t0 0.24 -input_amplitude 0.5"
H="-material_soil_model hysteretic -material_soil_backbone mkz -material_soil_reference_strain 1e-3"
CASES="p1_linear p1_gauss p1_mean p4_linear p4_gauss"
[ "$M" -gt 0 ] && CASES="$CASES 3d_linear 3d_gauss 3d_mean"
logs=()
for k in $(seq 1 "$REPEATS"); do
  for case in $CASES; do
    log="$WORK/${case}_$k.log"
    mesh="-mesh_box_faces $N,$N -mesh_box_upper $N,$N"
    [ "${case%%_*}" = p4 ] && mesh="-mesh_box_faces $((N / 4)),$((N / 4)) -mesh_box_upper $N,$N -element_degree 4"
    [ "${case%%_*}" = 3d ] && mesh="-mesh_dim 3 -mesh_box_faces $M,$M,$M -mesh_box_upper $M,$M,$M"
    soil=""
    case $case in *_gauss) soil="$H" ;; *_mean) soil="$H -material_soil_stress_points mean" ;; esac
    "$SW" $mesh $SOIL $soil -output_fields 0 -ts_max_steps 200 -ts_max_time 10 -progress_interval 1000 -output_dir "$WORK/$case" -output_overwrite > "$log"
    logs+=("$case $log")
  done
done
$PY - "${BENCH_CSV:-}" "$N" "$M" "${logs[@]}" <<'PY'
import re, sys
csv, n, m = sys.argv[1], sys.argv[2], sys.argv[3]
best = {}
for r in sys.argv[4:]:
    case, log = r.split()
    per = float(re.search(r"\(([0-9.eE+-]+) s per step\)", open(log).read()).group(1))
    best[case] = min(best.get(case, 1e300), per)
p1, p4 = best["p1_linear"], best["p4_linear"]
print(f"2D {n}^2 nodes, 1 rank, whole step: p = 1 linear {1e3 * p1:.2f} ms, hysteretic at the Gauss points {1e3 * best['p1_gauss']:.2f} ms "
      f"(x {best['p1_gauss'] / p1:.2f}), once per cell {1e3 * best['p1_mean']:.2f} ms (x {best['p1_mean'] / p1:.2f}); "
      f"p = 4 linear {1e3 * p4:.2f} ms, hysteretic {1e3 * best['p4_gauss']:.2f} ms (x {best['p4_gauss'] / p4:.2f})")
if "3d_linear" in best:
    l3 = best["3d_linear"]
    print(f"3D {m}^3 cells, 1 rank, whole step: linear {1e3 * l3:.2f} ms, hysteretic at the Gauss points {1e3 * best['3d_gauss']:.2f} ms "
          f"(x {best['3d_gauss'] / l3:.2f}), once per cell {1e3 * best['3d_mean']:.2f} ms (x {best['3d_mean'] / l3:.2f})")
if csv:
    with open(csv, "a") as out:
        for case in sorted(best):
            name = f"3d_{m}_{case[3:]}" if case.startswith("3d_") else f"2d_{n}_{case}"
            out.write(f"hysteretic_cost,{name},step_wall_time,{best[case]:.4g},s\n")
PY
