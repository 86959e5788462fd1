#!/usr/bin/python3
"""A Gmsh .geo of the default scene's geometry with cells graded toward the block's edges and
base, for the convergence study (docs/convergence-study.md): 1 m cells far away, FINE m at the
block's corners (geometric progressions over 6 m on each side of an edge and 6 m below the
base), structured quadrilaterals. Physical groups: surfaces rock, soil, block; curves bottom,
left, right (the rest is free).

usage: /usr/bin/python3 bench/study/graded_mesh.py [FINE] > graded.geo
       gmsh -2 graded.geo -format msh41 -o graded.msh
then run config/scenes/default.yaml less its mesh_box_*, region_*, regions, void_regions,
material_soil_far_* and mesh_dim lines, with -mesh_file graded.msh
-regions rock,soil_low,soil_mid,soil,block (its whole top sublayer is region soil).
"""
import sys


def cells_for(length, big, small):
    # cells of a geometric progression from big to small whose sum is closest to length
    best = None
    for n in range(2, 60):
        q = (small / big) ** (1 / (n - 1))
        s = big * (1 - q**n) / (1 - q)
        if best is None or abs(s - length) < abs(best[1] - length):
            best = (n, s, q)
    return best[0], best[2]


def main():
    fine = float(sys.argv[1]) if len(sys.argv) > 1 else 0.25
    n6, q6 = cells_for(6.0, 1.0, fine)
    n3, q3 = cells_for(3.0, 1.0, fine)
    # x intervals: (x0, x1, cells, progression along +x)
    X = [(-61, -9, 52, 1.0), (-9, -3, n6, q6), (-3, 0, n3, 1 / q3), (0, 3, n3, q3), (3, 9, n6, 1 / q6), (9, 61, 52, 1.0)]
    # the soil's three sublayers (0-10, 10-20, 20-30 m) each its own region
    Y = [(-20, 0, 20, 1.0), (0, 10, 10, 1.0), (10, 20, 10, 1.0), (20, 24, 4, 1.0), (24, 30, n6, q6), (30, 40, 10, 1.0)]
    LAYER = ["rock", "soil_low", "soil_mid", "soil", "soil", "block"]
    xs = [X[0][0]] + [x[1] for x in X]
    ys = [Y[0][0]] + [y[1] for y in Y]
    out = [f"// generated: cells graded to {fine} m at the block's edges and base"]
    pid = {}
    k = 0
    for j, y in enumerate(ys):
        for i, x in enumerate(xs):
            k += 1; pid[i, j] = k; out.append(f"Point({k}) = {{{x}, {y}, 0}};")
    def patch_ok(i, j):
        return j < 5 or i in (2, 3)
    H, V, lid = {}, {}, 0
    for j in range(len(ys)):
        for i in range(len(xs) - 1):
            if (j < len(ys) - 1 and patch_ok(i, j)) or (j > 0 and patch_ok(i, j - 1)):
                lid += 1; H[i, j] = lid; out.append(f"Line({lid}) = {{{pid[i, j]}, {pid[i + 1, j]}}};")
                n, r = X[i][2], X[i][3]
                out.append(f"Transfinite Curve{{{lid}}} = {n + 1} Using Progression {r};")
    for j in range(len(ys) - 1):
        for i in range(len(xs)):
            if (i < len(xs) - 1 and patch_ok(i, j)) or (i > 0 and patch_ok(i - 1, j)):
                lid += 1; V[i, j] = lid; out.append(f"Line({lid}) = {{{pid[i, j]}, {pid[i, j + 1]}}};")
                n, r = Y[j][2], Y[j][3]
                out.append(f"Transfinite Curve{{{lid}}} = {n + 1} Using Progression {r};")
    sid = 0
    groups = {name: [] for name in dict.fromkeys(LAYER)}
    for j in range(len(ys) - 1):
        for i in range(len(xs) - 1):
            if not patch_ok(i, j): continue
            sid += 1
            out.append(f"Curve Loop({sid}) = {{{H[i, j]}, {V[i + 1, j]}, {-H[i, j + 1]}, {-V[i, j]}}};")
            out.append(f"Plane Surface({sid}) = {{{sid}}};")
            out.append(f"Transfinite Surface{{{sid}}};")
            out.append(f"Recombine Surface{{{sid}}};")
            groups[LAYER[j]].append(sid)
    for g, s in groups.items():
        out.append(f'Physical Surface("{g}") = {{{", ".join(map(str, s))}}};')
    out.append(f'Physical Curve("bottom") = {{{", ".join(str(H[i, 0]) for i in range(len(xs) - 1))}}};')
    out.append(f'Physical Curve("left") = {{{", ".join(str(V[0, j]) for j in range(5))}}};')
    out.append(f'Physical Curve("right") = {{{", ".join(str(V[len(xs) - 1, j]) for j in range(5))}}};')
    print("\n".join(out))
    print(f"// x cells: {[x[2] for x in X]}, y cells: {[y[2] for y in Y]}", file=sys.stderr)


if __name__ == "__main__":
    main()
