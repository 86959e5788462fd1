# The default scene's mesh (config/scenes/default.msh) is what its .geo makes, and the .geo
# makes what the scene's header and docs/convergence-study.md ("Which limit") say, at the size
# factor of the main run (1) and of make run's companion (2):
#  1. gmsh -2 config/scenes/default.geo gives config/scenes/default.msh byte for byte (the
#     committed mesh is the file's output, not edited by hand).
#  2. Every cell is a quadrilateral (the unstructured part is made at twice the size and split
#     in four: no triangle left).
#  3. The finest cells sit at the block's base corners (+-3, 30): the shortest edge of the cells
#     that touch a corner is FINE f = 0.125 f m (the window's progressions end there), to 1e-6 m
#     (Gmsh places the transfinite nodes to about 3e-8 m here).
#  4. Away from the window (cell centres outside x = -9..9, y = 24..30) the median edge is 1 m
#     within 10 % at f = 1 (the far field's resolution, 23-25 Hz), and twice it, within 10 %,
#     at f = 2 (the structured far field's counts are rounded: 1.94 m at f = 2, where the
#     46 m on each side take 12 cells of 4 m before the split).
#  5. Its physical groups are the scene's regions (regions: in default.yaml) and the sides
#     bottom, left, right of its boundary conditions.
set -eu
. tests/tools/lib.sh
gmsh -2 config/scenes/default.geo -format msh41 -o "$WORK/f1.msh" > "$WORK/f1.log"
cmp "$WORK/f1.msh" config/scenes/default.msh && echo "ok: config/scenes/default.msh is config/scenes/default.geo's output, byte for byte"
default_companion "$WORK/f2.msh"
$PY - "$WORK" <<'PY'
import re, sys
import numpy as np
sys.path.insert(0, "tests/tools"); sys.path.insert(0, "scripts")
from quad_field_error import read_quads
from convergence_check import msh_cell_count
work = sys.argv[1]
ok = True
def check(good, text):
    global ok
    ok &= bool(good)
    print(("ok " if good else "FAIL ") + text)
for f, path in ((1, f"{work}/f1.msh"), (2, f"{work}/f2.msh")):
    xy, quads = read_quads(path)
    cells = msh_cell_count(path, 2)
    check(len(quads) == cells, f"f = {f}: {len(quads)} quadrilaterals of {cells} cells")
    edges = np.linalg.norm(xy[quads] - xy[np.roll(quads, -1, axis=1)], axis=2)
    for cx in (-3.0, 3.0):
        at = np.any(np.linalg.norm(xy[quads] - [cx, 30.0], axis=2) < 1e-9, axis=1)
        shortest = edges[at].min()
        check(at.any() and abs(shortest - 0.125 * f) <= 1e-6, f"f = {f}: shortest edge at the corner ({cx:g}, 30): {shortest:.12g} m (FINE f = {0.125 * f:g})")
    c = xy[quads].mean(axis=1)
    far = ~((np.abs(c[:, 0]) < 9) & (c[:, 1] > 24) & (c[:, 1] < 30))
    median = np.median(edges[far])
    if f == 1:
        median_f1 = median
        check(abs(median - 1) <= 0.10, f"f = 1: median edge away from the window {median:.3f} m (allowed 1 m within 10 %)")
    else:
        check(abs(median / median_f1 / f - 1) <= 0.10, f"f = {f}: median edge away from the window {median:.3f} m, {median / median_f1:.3f} x f = 1's (allowed {f} x within 10 %)")
text = open("config/scenes/default.msh").read()
groups = set(re.findall(r'^\d+ \d+ "(\w+)"$', text[text.index("$PhysicalNames"):text.index("$EndPhysicalNames")], re.M))
regions = next(l.split(":", 1)[1].strip() for l in open("config/scenes/default.yaml") if l.startswith("regions:")).split(",")
check(groups == set(regions) | {"bottom", "left", "right"}, f"physical groups {sorted(groups)}: the regions {regions} and bottom, left, right")
sys.exit(0 if ok else 1)
PY
