"""The displacement FIELD of a 1D column run (one element across, the wave vertical) against
the closed form, in the L2 norm of the element basis (issue 14's convergence tests).

The column (base y = 0 absorbing with the incident wave, top y = H free) carries, until the
surface reflection comes back to the base, u(y, t) = U(t - y/c) + U(t - (2H - y)/c): the
incident wave and its reflection at the traction-free top (reflection coefficient +1, e.g.
Kramer, Geotechnical Earthquake Engineering, sec. 5.2). U is the displacement of the input
Ricker velocity A (1 - 2a) exp(-a), a = (pi f0 (t - t0))^2, whose antiderivative vanishing
at t -> -inf is U(t) = A (t - t0) exp(-a).

The numerical field is the element's own: the Lagrange interpolant of degree p through the
p + 1 nodes of each element along y (the GLL nodes the run wrote), integrated with a
Gauss-Legendre rule of p + 6 points per element, finer than the GLL rule, so that the nodes'
superconvergence does not flatter the rate."""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from slipwave import Frames  # noqa: E402


def ricker_displacement(t, amplitude, f0, t0):
    return amplitude * (t - t0) * np.exp(-((math.pi * f0 * (t - t0)) ** 2))


def column_exact(y, t, height, speed, amplitude, f0, t0):
    return ricker_displacement(t - y / speed, amplitude, f0, t0) + ricker_displacement(t - (2 * height - y) / speed, amplitude, f0, t0)


def column_strain_exact(y, t, height, speed, amplitude, f0, t0):
    """du/dy of column_exact: U' is the Ricker velocity, so du/dy = (-U'(t - y/c) + U'(t - (2H - y)/c)) / c."""
    def velocity(tau):
        a = (math.pi * f0 * (tau - t0)) ** 2
        return amplitude * (1 - 2 * a) * np.exp(-a)
    return (-velocity(t - y / speed) + velocity(t - (2 * height - y) / speed)) / speed


def shear_stress_error(out_dir, shear_modulus, exact_strain, frame=-1, vertical=1):
    """Relative RMS difference over the output cells between the shear stress sigma_x,vertical
    slipwave writes per cell (at its centre, by the element basis at p > 1) and mu du/dy of
    the closed form at the cell centres: the derivative, order p at degree p."""
    f = Frames(out_dir)
    stress = f.field("stress", frame)[:, vertical]   # 3 x 3 tensor rows: x row, column `vertical`
    centres = f.geometry[f.topology, vertical].mean(axis=1)
    exact = shear_modulus * exact_strain(centres)
    return float(np.linalg.norm(stress - exact) / np.linalg.norm(exact))


def profile(out_dir, component="x", frame=-1, vertical=1):
    """(time, node heights, displacement component along the column's edge at the smallest
    other coordinates, largest difference between nodes at the same height: the field must be
    1D) of one output frame; `vertical` is the index of the height coordinate (1 in 2D, 2 in 3D)."""
    f = Frames(out_dir)
    u = f.field("displacement", frame)[:, "xyz".index(component)]
    y = f.geometry[:, vertical]
    spread = max(np.ptp(u[np.isclose(y, h, atol=1e-9, rtol=0)]) for h in np.unique(np.round(y, 9)))
    edge = np.ones(len(y), dtype=bool)
    for d in range(vertical):
        edge &= np.isclose(f.geometry[:, d], f.geometry[:, d].min())
    order = np.argsort(y[edge])
    return f.times[frame], y[edge][order], u[edge][order], spread


def lagrange(nodes, x):
    """Values at x of the Lagrange basis through `nodes`: shape (len(x), len(nodes))."""
    out = np.ones((len(x), len(nodes)))
    for j, xj in enumerate(nodes):
        for m, xm in enumerate(nodes):
            if m != j:
                out[:, j] *= (x - xm) / (xj - xm)
    return out


def l2_distance(ys, values, degree, func):
    """sqrt of the integral over the column of (u_h - func)^2, u_h the degree-p interpolant of
    `values` at the nodes `ys` (elements of p + 1 consecutive nodes sharing their ends)."""
    if (len(ys) - 1) % degree:
        raise ValueError(f"{len(ys)} nodes along y is not a multiple of degree {degree} plus 1")
    gx, gw = np.polynomial.legendre.leggauss(degree + 6)
    total = 0.0
    for e in range(0, len(ys) - 1, degree):
        yn = ys[e:e + degree + 1]
        yq = 0.5 * (yn[0] + yn[-1]) + 0.5 * (yn[-1] - yn[0]) * gx
        total += np.sum(0.5 * (yn[-1] - yn[0]) * gw * (lagrange(yn, yq) @ values[e:e + degree + 1] - func(yq)) ** 2)
    return math.sqrt(total)
