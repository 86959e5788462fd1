#!/usr/bin/python3
"""Thomson-Haskell propagator for a plane P or SV wave in elastic layers over a half-space, an
independent reference for slipwave's DRM free field (src/physics/plane_wave_layered.cpp solves
the same problem as one global linear system; this one propagates the state vector).

Time dependence e^{i w t} (numpy's inverse FFT), depth z down from the free surface, every
field has the factor e^{-i w p x}. In a medium the state b = (u_x, u_z, tau_xz, tau_zz)/(-i w
for the tractions) is E c(z), E's columns the four plane waves' states (P down, S down, P up,
S up), c_k(z) = c_k(z0) e^{-i w s_zk (z - z0)}. Across a layer of thickness h the state at its
top is E diag(e^{i w s_zk h}) E^-1 times the state at its bottom (the propagator), continuous
at the interfaces. In the half-space the state at its top is the incident up-going wave
(amplitude 1) plus reflected P and S; zero traction at the surface fixes the two reflected
amplitudes. Polarisations: P along its slowness (p, s_z) times vp, S vs (-s_z, p); the
incident up-going SV moves +x, P up and +x. Propagating waves only (p < 1/c everywhere).
"""
import numpy as np


def _waves(rho, vp, vs, p):
    mu, lam = rho * vs**2, rho * vp**2 - 2 * rho * vs**2
    qp, qs = np.sqrt(1 / vp**2 - p**2), np.sqrt(1 / vs**2 - p**2)
    cols, sz = [], []
    for s_wave, down in ((False, True), (True, True), (False, False), (True, False)):
        q = (qs if s_wave else qp) * (1 if down else -1)
        d = np.array([-vs * q, vs * p]) if s_wave else np.array([vp * p, vp * q])
        tau = [mu * (d[0] * q + d[1] * p), lam * (d[0] * p + d[1] * q) + 2 * mu * d[1] * q]
        cols.append([d[0], d[1], tau[0], tau[1]])
        sz.append(q)
    return np.array(cols).T.astype(complex), np.array(sz)


def surface_transfer(layers, halfspace, wave, angle_deg, omega):
    """(u_x, u_up) at the surface per unit incident amplitude at the half-space top, for each
    omega. layers: [(h, rho, vp, vs)], halfspace: (rho, vp, vs)."""
    rho, vp, vs = halfspace
    p = np.sin(np.radians(angle_deg)) / (vp if wave == "p" else vs)
    Eh, _ = _waves(rho, vp, vs, p)
    out = np.zeros((2, len(omega)), complex)
    for k, w in enumerate(omega):
        P = np.eye(4, dtype=complex)  # surface state = P (half-space top state)
        for h, r, a, b in layers:
            E, sz = _waves(r, a, b, p)
            P = P @ (E @ np.diag(np.exp(1j * w * sz * h)) @ np.linalg.inv(E))
        inc = Eh[:, 2] if wave == "p" else Eh[:, 3]
        # surface tractions (rows 2, 3) vanish: P[2:] (inc + R_P Eh[:,0] + R_S Eh[:,1]) = 0
        A = P[2:] @ Eh[:, :2]
        R = np.linalg.solve(A, -P[2:] @ inc)
        s = P @ (inc + Eh[:, :2] @ R)
        out[:, k] = (s[0], -s[1])
    return out
