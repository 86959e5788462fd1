#!/usr/bin/python3
"""A Gmsh .geo of the default scene's geometry whose cells are graded toward the block as in
graded_mesh.py (structured quadrilaterals, geometric progressions from 1 m to FINE m at the
block's edges and base) but only in a window of the top sublayer, x = -9..9 m, y = 24..30 m;
everywhere else unstructured quadrilaterals of 1 m that meet the window's nodes
(docs/convergence-study.md, "Which limit"). It separates what the structured study's cells
refine inside that window from what their fine columns and rows refine elsewhere (down
through the rock, along the whole surface). Physical groups: surfaces rock, soil_low,
soil_mid, soil (the top sublayer), block; curves bottom, left, right.

usage: /usr/bin/python3 bench/study/graded_patch.py [FINE] > patch.geo
       gmsh -2 patch.geo -format msh41 -o patch.msh
then as graded_mesh.py's meshes (bench/cases/default_scene_graded.sh).
"""
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from graded_mesh import cells_for  # noqa: E402

fine = float(sys.argv[1]) if len(sys.argv) > 1 else 0.25
# Gmsh's blossom recombination leaves a few triangles in the unstructured part; the mesh is
# made of cells twice as large and then split into four quadrilaterals each
# (Mesh.SubdivisionAlgorithm 1), so the progressions run from 2 m to 2 FINE.
n6, q6 = cells_for(6.0, 2.0, 2 * fine)
n3, q3 = cells_for(3.0, 2.0, 2 * fine)
# the window's columns: (x0, x1, cells, progression along +x), fine toward x = -3 and 3
X = [(-9, -3, n6, q6), (-3, 0, n3, 1 / q3), (0, 3, n3, q3), (3, 9, n6, 1 / q6)]
xs = [-9, -3, 0, 3, 9]
out = [f"// generated: cells graded to {fine} m at the block's edges and base in x = -9..9, y = 24..30 (bench/study/graded_patch.py)", "lc = 2;"]
P = {}
def point(name, x, y):
    P[name] = len(P) + 1
    out.append(f"Point({P[name]}) = {{{x}, {y}, 0, lc}};")
for name, x, y in (("b0", -61, -20), ("b1", 61, -20), ("r0", -61, 0), ("r1", 61, 0), ("m0", -61, 10), ("m1", 61, 10), ("t0", -61, 20),
                   ("t1", 61, 20), ("s0", -61, 30), ("s1", 61, 30), ("k0", -3, 40), ("k1", 3, 40), ("k2", 0, 40)):
    point(name, x, y)
for i, x in enumerate(xs):
    point(f"w{i}", x, 24)
    point(f"v{i}", x, 30)
L = {}
def line(name, a, b, transfinite=None):
    L[name] = len(L) + 1
    out.append(f"Line({L[name]}) = {{{P[a]}, {P[b]}}};")
    if transfinite:
        out.append(f"Transfinite Curve{{{L[name]}}} = {transfinite[0] + 1} Using Progression {transfinite[1]};")
for name, a, b in (("bottom", "b0", "b1"), ("rock_top", "r0", "r1"), ("low_top", "m0", "m1"), ("mid_top", "t0", "t1"),
                   ("left0", "b0", "r0"), ("left1", "r0", "m0"), ("left2", "m0", "t0"), ("left3", "t0", "s0"),
                   ("right0", "b1", "r1"), ("right1", "r1", "m1"), ("right2", "m1", "t1"), ("right3", "t1", "s1"),
                   ("surf_left", "s0", "v0"), ("surf_right", "v4", "s1")):
    line(name, a, b)
# the block (rigid: its cells only carry its mass), two structured halves on the window's top
for name, a, b, n in (("block_left", "v1", "k0", 5), ("block_middle", "v2", "k2", 5), ("block_right", "v3", "k1", 5)):
    line(name, a, b, (n, 1.0))
line("block_top_left", "k0", "k2", (n3, 1 / q3))
line("block_top_right", "k2", "k1", (n3, q3))
for i, (x0, x1, n, q) in enumerate(X):
    line(f"wb{i}", f"w{i}", f"w{i + 1}", (n, q))  # the window's bottom, y = 24
    line(f"wt{i}", f"v{i}", f"v{i + 1}", (n, q))  # its top, y = 30
for i in range(len(xs)):
    line(f"wv{i}", f"w{i}", f"v{i}", (n6, q6))    # graded toward y = 30
S = {}
def surface(name, loop, structured=False):
    S[name] = len(S) + 1
    out.append(f"Curve Loop({S[name]}) = {{{', '.join(str(c) for c in loop)}}};")
    out.append(f"Plane Surface({S[name]}) = {{{S[name]}}};")
    if structured:
        out.append(f"Transfinite Surface{{{S[name]}}};")
    out.append(f"Recombine Surface{{{S[name]}}};")
surface("rock", [L["bottom"], L["right0"], -L["rock_top"], -L["left0"]])
surface("soil_low", [L["rock_top"], L["right1"], -L["low_top"], -L["left1"]])
surface("soil_mid", [L["low_top"], L["right2"], -L["mid_top"], -L["left2"]])
# the top sublayer around the window: up the right side, along the surface to the window,
# around the window's bottom, on to the left side
around = [L["mid_top"], L["right3"], -L["surf_right"], -L["wv4"]] + [-L[f"wb{i}"] for i in (3, 2, 1, 0)] + [L["wv0"], -L["surf_left"], -L["left3"]]
surface("soil_around", around)
for i in range(4):
    surface(f"window{i}", [L[f"wb{i}"], L[f"wv{i + 1}"], -L[f"wt{i}"], -L[f"wv{i}"]], structured=True)
surface("block_left", [L["wt1"], L["block_middle"], -L["block_top_left"], -L["block_left"]], structured=True)
surface("block_right", [L["wt2"], L["block_right"], -L["block_top_right"], -L["block_middle"]], structured=True)
out.append(f'Physical Surface("rock") = {{{S["rock"]}}};')
out.append(f'Physical Surface("soil_low") = {{{S["soil_low"]}}};')
out.append(f'Physical Surface("soil_mid") = {{{S["soil_mid"]}}};')
out.append(f'Physical Surface("soil") = {{{", ".join(str(S[n]) for n in ["soil_around"] + [f"window{i}" for i in range(4)])}}};')
out.append(f'Physical Surface("block") = {{{S["block_left"]}, {S["block_right"]}}};')
out.append(f'Physical Curve("bottom") = {{{L["bottom"]}}};')
out.append(f'Physical Curve("left") = {{{", ".join(str(L[f"left{i}"]) for i in range(4))}}};')
out.append(f'Physical Curve("right") = {{{", ".join(str(L[f"right{i}"]) for i in range(4))}}};')
out += ["Mesh.Algorithm = 6;", "Mesh.RecombinationAlgorithm = 1;", "Mesh.SubdivisionAlgorithm = 1;"]
print("\n".join(out))
