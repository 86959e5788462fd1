"""L2 error of a 2D displacement FIELD in the basis of degree-p elements on quadrilaterals
read from a Gmsh file (issue 14's convergence tests on non-affine meshes).

Each quadrilateral of the Gmsh mesh (4-node, type 3) is an element; its GLL nodes are the
images of the tensor GLL points under the element's bilinear map (the geometry slipwave uses:
docs/spectral-kernels.md), found among the output nodes by their coordinates, so nothing of
slipwave's own node order is assumed. The error integral runs over the reference square with
a tensor Gauss-Legendre rule of p + 6 points per direction (finer than GLL, so that nodal
superconvergence does not flatter the rate), weighted by |det J| of the bilinear map."""
import math
import sys

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from column_field_error import lagrange  # noqa: E402


def gll_points(p):
    """The p + 1 Gauss-Lobatto-Legendre points on [-1, 1]: the ends and the roots of P_p'."""
    inner = np.polynomial.legendre.Legendre.basis(p).deriv().roots()
    return np.concatenate(([-1.0], np.sort(inner.real), [1.0]))


def read_quads(msh):
    """(node coordinates (n, 2), quads as rows of 4 node indices) of a Gmsh 4.1 ASCII file."""
    lines = open(msh).read().split("\n")
    i = lines.index("$Nodes")
    nblocks = int(lines[i + 1].split()[0])
    k, coords = i + 2, {}
    for _ in range(nblocks):
        n = int(lines[k].split()[3])
        tags = [int(lines[k + 1 + j]) for j in range(n)]
        for j, tag in enumerate(tags):
            coords[tag] = [float(v) for v in lines[k + 1 + n + j].split()[:2]]
        k += 1 + 2 * n
    i = lines.index("$Elements")
    nblocks = int(lines[i + 1].split()[0])
    k, quads = i + 2, []
    for _ in range(nblocks):
        _, _, etype, n = map(int, lines[k].split())
        if etype == 3:
            quads += [[int(v) for v in lines[k + 1 + j].split()[1:5]] for j in range(n)]
        k += 1 + n
    tags = sorted(coords)
    index = {t: j for j, t in enumerate(tags)}
    return np.array([coords[t] for t in tags]), np.array([[index[t] for t in q] for q in quads])


def bilinear(corners, xi, eta):
    """Points and |det J| of the bilinear map of `corners` (counter-clockwise or clockwise)."""
    n = np.array([(1 - xi) * (1 - eta), (1 + xi) * (1 - eta), (1 + xi) * (1 + eta), (1 - xi) * (1 + eta)]) / 4
    dxi = np.array([-(1 - eta), 1 - eta, 1 + eta, -(1 + eta)]) / 4
    deta = np.array([-(1 - xi), -(1 + xi), 1 + xi, 1 - xi]) / 4
    x = n.T @ corners
    jx, jy = dxi.T @ corners, deta.T @ corners
    return x, np.abs(jx[:, 0] * jy[:, 1] - jx[:, 1] * jy[:, 0])


def l2_distance(msh, degree, geometry, values, func):
    """sqrt of the integral of (u_h - func(x, y))^2, u_h the degree-p element interpolant of
    `values` given at the output nodes `geometry`."""
    verts, quads = read_quads(msh)
    tree = cKDTree(geometry[:, :2])
    g = gll_points(degree)
    gi, gj = np.meshgrid(g, g, indexing="ij")
    gx, gw = np.polynomial.legendre.leggauss(degree + 6)
    qi, qj = np.meshgrid(gx, gx, indexing="ij")
    basis = (lagrange(g, qi.ravel())[:, :, None] * lagrange(g, qj.ravel())[:, None, :]).reshape(len(qi.ravel()), -1)
    weights = np.outer(gw, gw).ravel()
    total, scale = 0.0, np.max(np.abs(geometry))
    for q in quads:
        nodes_x, _ = bilinear(verts[q], gi.ravel(), gj.ravel())
        dist, idx = tree.query(nodes_x)
        if np.max(dist) > 1e-9 * scale:
            raise ValueError(f"element {q}: a GLL node is {np.max(dist):.2e} m from every output node")
        xq, det = bilinear(verts[q], qi.ravel(), qj.ravel())
        total += np.sum(weights * det * (basis @ values[idx] - func(xq[:, 0], xq[:, 1])) ** 2)
    return math.sqrt(total)
