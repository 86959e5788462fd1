# Mesh convergence of what an engineer reads from the default scene (config/scenes/default.yaml,
# El Centro 1940 N-S at 0.3 g, 15 s): the scene at h = 1 m (its own mesh), h/2 and h/4, by
# overriding -mesh_box_faces (122,60 times 1, 2, 4: every region boundary stays on cell edges).
# Each level reports, from scripts/scene_metrics.py:
#   net slip (net tangential offset at the end), slip path (accumulated slip), peak uplift,
#   peak rocking angle, peak structure acceleration (block top), free-field PGA and the
#   free-field surface 5 %-damped PSA at T = 0.1, 0.3 and 1 s;
# and, from three successive levels f1 (h), f2 (h/2), f3 (h/4), the observed convergence
# rate p = log2(|f1 - f2| / |f2 - f3|), the Richardson estimate f* = f3 + (f3 - f2)/(2^p - 1),
# and each level's distance to it |f - f*|/|f*| (the mesh that gets a quantity within 5 %).
# When the differences change sign the convergence is not monotone: no rate is claimed.
# The levels run in order while the next one's projected wall time (the last one's x 8: 4x
# the cells, 2x the steps) fits in STUDY_BUDGET_S (default 900 s = 15 min); a skipped level
# is reported. Settings: STUDY_LEVELS (default "1 2 4"), STUDY_NP ranks (default 2),
# STUDY_EXTRA (options appended to every run, e.g. "-ts_max_time 3" for a quick look).
# Rows go to $BENCH_CSV (benchmark,case,metric,value,unit); the table to stdout and to
# build/bench/work/default_scene_convergence/table.txt.
set -eu
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
PY=/usr/bin/python3
CSV=${BENCH_CSV:-}
LEVELS=${STUDY_LEVELS:-1 2 4}
NP=${STUDY_NP:-2}
BUDGET=${STUDY_BUDGET_S:-900}
EXTRA=${STUDY_EXTRA:-}
MPIEXEC="mpiexec --oversubscribe"
[ "$(id -u)" = 0 ] && MPIEXEC="$MPIEXEC --allow-run-as-root"
WORK="$BUILD/bench/work/default_scene_convergence"
rm -rf "$WORK"; mkdir -p "$WORK"

start=$(date +%s)
last_wall=0
rows=()
for r in $LEVELS; do
  used=$(( $(date +%s) - start ))
  if [ "$last_wall" -gt 0 ] && [ $(( used + 8 * last_wall )) -gt "$BUDGET" ]; then
    echo "level h/$r skipped: projected $(( 8 * last_wall )) s after $used s exceeds the budget STUDY_BUDGET_S = $BUDGET s"
    rows+=("$r skipped")
    continue
  fi
  out="$WORK/h$r"
  t0=$(date +%s)
  $MPIEXEC -n "$NP" "$SW" -options_file config/scenes/default.yaml -mesh_box_faces $((122 * r)),$((60 * r)) -progress_interval 60 \
    $EXTRA -output_dir "$out" > "$out.log"
  last_wall=$(( $(date +%s) - t0 ))
  $PY scripts/scene_metrics.py "$out" --json "$out/metrics.json" > /dev/null
  echo "level h/$r: $last_wall s wall on $NP ranks"
  rows+=("$r $last_wall $out/metrics.json")
done

$PY - "$CSV" "$WORK/table.txt" "$EXTRA" "${rows[@]}" <<'PY'
import json, math, sys
csv, table_path, extra = sys.argv[1:4]
levels = []
for row in sys.argv[4:]:
    parts = row.split()
    if parts[1] == "skipped":
        continue
    levels.append((int(parts[0]), int(parts[1]), json.load(open(parts[2]))))
names = [("net_slip", "m"), ("accumulated_slip", "m"), ("peak_uplift", "m"), ("peak_rocking_angle", "rad"),
         ("peak_structure_acceleration", "m/s^2"), ("free_field_pga", "m/s^2"), ("free_field_psa_0.1s", "m/s^2"),
         ("free_field_psa_0.3s", "m/s^2"), ("free_field_psa_1s", "m/s^2")]
lines = [f"default scene (El Centro 1940 N-S, 0.3 g outcrop, 15 s){' with ' + extra if extra else ''} at h = 1 m / r; wall time per level: " +
         ", ".join(f"h/{r}: {w} s" for r, w, _ in levels)]
head = f"{'quantity':30s} {'unit':6s}" + "".join(f" {'h/' + str(r):>11s}" for r, _, _ in levels)
if len(levels) >= 3:
    head += f" {'rate p':>7s} {'Richardson':>11s}" + "".join(f" {'err h/' + str(r):>9s}" for r, _, _ in levels) + f" {'5 % at':>8s}"
lines.append(head)
out = open(csv, "a") if csv else None
for name, unit in names:
    values = [m[name] for _, _, m in levels]
    line = f"{name:30s} {unit:6s}" + "".join(f" {v:11.4g}" for v in values)
    if len(levels) >= 3:
        f1, f2, f3 = values[-3:]
        d12, d23 = f1 - f2, f2 - f3
        if d12 * d23 > 0 and abs(d23) > 0:
            p = math.log(abs(d12) / abs(d23)) / math.log(2)
            star = f3 + (f3 - f2) / (2 ** p - 1) if abs(2 ** p - 1) > 1e-12 else float("nan")
            errs = [abs(v - star) / abs(star) if star else float("nan") for v in values]
            within = next((f"h/{r}" for k, (r, _, _) in enumerate(levels) if all(e <= 0.05 for e in errs[k:])), "none")
            line += f" {p:7.2f} {star:11.4g}" + "".join(f" {e:9.1%}" for e in errs) + f" {within:>8s}"
            if out:
                out.write(f"default_scene_convergence,{name},observed_rate,{p:.3f},1\n")
                out.write(f"default_scene_convergence,{name},richardson,{star:.6g},{unit}\n")
        else:
            # No rate: the distance to the finest level instead, marked with *.
            errs = [abs(v - f3) / abs(f3) if f3 else float("nan") for v in values]
            line += f" {'n/m':>7s} {'not monot.':>11s}" + "".join(f" {e:8.1%}*" for e in errs)
    lines.append(line)
    if out:
        for (r, _, _), v in zip(levels, values):
            out.write(f"default_scene_convergence,{name}_h{r},value,{v:.6g},{unit}\n")
if out:
    for r, w, _ in levels:
        out.write(f"default_scene_convergence,h{r},wall_time,{w},s\n")
if len(levels) >= 3:
    lines.append("err: |f - f*| / |f*| with f* the Richardson estimate; 5 % at: the coarsest mesh within 5 % from there on; "
                 "* (not monotone): |f - f(finest)| / |f(finest)|, no rate claimed")
text = "\n".join(lines)
print(text)
open(table_path, "w").write(text + "\n")
PY
