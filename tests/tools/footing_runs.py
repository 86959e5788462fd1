#!/usr/bin/env python3
"""The soil's impedance under a rigid footing from slipwave forced-vibration runs, with the
footing's own inertia taken out exactly (rigid body with its centre of mass above the base),
and the same quantities predicted from a reference impedance matrix (tests/tools/
strip_impedance.py), so that both sides of a comparison are computed alike.

Frame: slipwave's (x right, y up; rocking theta counter-clockwise, = (u_y(R) - u_y(L)) /
(x_R - x_L)); motions of the base's centre O. The footing (mass m, moment of inertia I_c about
its centre of mass, which lies e above O) moves as a rigid body, so its centre of mass moves
u_x - e theta: mass matrix about O, in (u_x, theta): [[m, -m e], [-m e, I_c + m e^2]]. The
soil's reactions are K_s (u_x, u_y, theta) and, harmonically, K_s u = F + w^2 M_f u.
- vertical run (force P up): K_yy = P/u_y + m w^2 (no coupling, by symmetry);
- rocking run (couple M): K_xr u_x + K_rr theta = M + w^2 (-m e u_x + (I_c + m e^2) theta);
  the "apparent" rocking impedance K_rr + K_xr u_x/theta is what one run measures;
- horizontal run (force H at the centroid, moment -e H about O): with the rocking run, the
  2 x 2 (u_x, theta) block of K_s follows from both runs' equations.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from slipwave import RunFolder  # noqa: E402


def ricker(t, f0, t0):
    a = (np.pi * f0 * (t - t0)) ** 2
    return (1 - 2 * a) * np.exp(-a)


def spectra(run, amplitude, f0, t0, x_left, x_right, pad=4):
    """Frequencies [Hz], the Ricker load's spectrum and those of u_x, u_y at station C and of
    theta from stations L and R."""
    folder = RunFolder(run)
    L, C, R = folder.station("L"), folder.station("C"), folder.station("R")
    t = C["t"]
    n = pad * len(t)
    fft = lambda s: np.fft.rfft(s, n)
    theta = (R["u_y"] - L["u_y"]) / (x_right - x_left)
    f = np.fft.rfftfreq(n, t[1] - t[0])
    return f, fft(amplitude * ricker(t, f0, t0)), fft(C["u_x"]), fft(C["u_y"]), fft(theta)


def load_run(run, x0, B, amplitude=1e5, f0=6.0, t0=0.25):
    """w [rad/s] and the spectra of spectra() (without w = 0) of a run of
    tests/tools/strip_footing.sh, footing centred at x0."""
    f, P, Ux, Uy, Th = spectra(run, amplitude, f0, t0, x0 - B, x0 + B)
    return 2 * np.pi * f[1:], P[1:], Ux[1:], Uy[1:], Th[1:]


def rigid_block(rho, width, height):
    """Mass, moment of inertia about the centre of mass and its height above the base, per
    unit length, of a rectangular footing."""
    m = rho * width * height
    return m, m * (width ** 2 + height ** 2) / 12, height / 2


def mass_matrix(m, I_c, e):
    return np.array([[m, -m * e], [-m * e, I_c + m * e * e]])


def vertical_impedance(w, P, Uy, m):
    return P / Uy + m * w * w


def apparent_rocking(w, M, Ux, Th, m, I_c, e):
    """K_rr + K_xr u_x / theta from a run loaded by the couple M."""
    return (M + w * w * (-m * e * Ux + (I_c + m * e * e) * Th)) / Th


def sway_rocking_block(w, H, Ux_h, Th_h, M, Ux_r, Th_r, m, I_c, e):
    """The (u_x, theta) block of K_s at each frequency from a horizontal-force run (h) and a
    couple run (r): K_s [u_h u_r] = [[H, 0], [-e H, M]] + w^2 M_f [u_h u_r]."""
    Mf = mass_matrix(m, I_c, e)
    out = np.empty((len(w), 2, 2), complex)
    for i in range(len(w)):
        U = np.array([[Ux_h[i], Ux_r[i]], [Th_h[i], Th_r[i]]])
        F = np.array([[H[i], 0], [-e * H[i], M[i]]]) + w[i] ** 2 * Mf @ U
        out[i] = F @ np.linalg.inv(U)
    return out


def to_slipwave_frame(K):
    """strip_impedance's K (z down, theta with u_z = theta x) in slipwave's frame (y up,
    counter-clockwise theta): u_y = -u_z, theta' = -theta, F_y = -F_z, M' = -M."""
    T = np.diag([1.0, -1.0, -1.0])
    return T @ K @ T


def predicted_apparent_rocking(K, w, m, I_c, e):
    """What apparent_rocking gives for a footing on a soil of impedance K (slipwave frame):
    solve (K_s - w^2 M_f) u = (0, 1) for the couple run."""
    S = K[np.ix_([0, 2], [0, 2])] - w * w * mass_matrix(m, I_c, e)
    ux, th = np.linalg.solve(S, [0.0, 1.0])
    return K[2, 2] + K[0, 2] * ux / th


def reference(a0s, B, rho, vp, vs):
    """strip_impedance's welded-contact K (3 x 3) at each a0, in slipwave's frame."""
    from strip_impedance import impedance_matrix
    return [to_slipwave_frame(impedance_matrix(a0, B=B, rho=rho, vp=vp, vs=vs)) for a0 in a0s]


def at(a0s, a0, K):
    """K (complex, sampled at a0 increasing) interpolated at a0s."""
    return np.interp(a0s, a0, K.real) + 1j * np.interp(a0s, a0, K.imag)
