# The README's tutorial scene, exactly as the README prints it (the YAML block after the
# "tutorial-scene" marker), run as the README tells a newcomer to (the program itself, its
# defaults: no test options): a dry run, then 2 ranks.
# It must run to its end with no warning a newcomer would have to understand beyond the
# penalty's step note (no side holding back the wave, no under-resolved region), the energy
# budget must close to 1e-9 of the largest energy (the scheme's discrete identity makes it
# round-off; the bound of the other scene tests), the output must parse, and the footing
# must answer what the tutorial asks: scene_metrics.py finds a slip path and a free-field
# PGA (numbers, finite).
set -eu
. tests/tools/lib.sh
mkdir -p "$WORK/scene"
$PY - README.md "$WORK/scene/my_footing.yaml" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
start = next(i for i, l in enumerate(lines) if "tutorial-scene" in l)
assert lines[start + 1].strip() == "```yaml", lines[start + 1]
end = next(i for i in range(start + 2, len(lines)) if lines[i].strip() == "```")
open(sys.argv[2], "w").write("\n".join(lines[start + 2:end]) + "\n")
PY
"$SLIPWAVE_BINARY" -options_file "$WORK/scene/my_footing.yaml" -dry_run -output_dir "$WORK/dry" > "$WORK/dry.txt"
grep -q "stable step" "$WORK/dry.txt"
$MPIEXEC -n 2 "$SLIPWAVE_BINARY" -options_file "$WORK/scene/my_footing.yaml" -output_dir "$WORK/out" > "$WORK/report.txt"
if grep "warning" "$WORK/report.txt" | grep -v "the interface penalty lowers the stable step"; then
  echo "FAIL: the tutorial scene warns"; exit 1
fi
$CHECK energy "$WORK/out/energy.csv" --max-error 1e-9
$PY scripts/check_output.py "$WORK/out"
$PY scripts/scene_metrics.py "$WORK/out" --json "$WORK/metrics.json" 2>/dev/null
$PY - "$WORK/metrics.json" "$WORK/out/run_info.json" <<'PY'
import json, math, sys
m = json.load(open(sys.argv[1]))
for k in ("accumulated_slip", "net_slip", "peak_uplift", "free_field_pga"):
    assert k in m and math.isfinite(m[k]), k
# The program states the same answers at the end of the run (run_info.json "answers").
stated = json.load(open(sys.argv[2]))["answers"]
assert abs(stated["accumulated_slip"]["value"] - m["accumulated_slip"]) <= 1e-9 * max(m["accumulated_slip"], 1e-12) + 1e-12, (stated["accumulated_slip"], m["accumulated_slip"])
print("tutorial: slip path %.3g m, free-field PGA %.3g m/s^2" % (m["accumulated_slip"], m["free_field_pga"]))
PY
echo "readme_tutorial: ok"
