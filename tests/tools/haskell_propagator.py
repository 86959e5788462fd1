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


def surface_velocity_ricker(t, f0, t0, amplitude, layers, halfspace, wave, angle_deg, rock_depth, x_from_reference):
    """The surface velocity [v_x, v_y] at the times t (uniform) of a Ricker incident wave
    (peak velocity `amplitude` at t0, centre frequency f0) given at a reference point in the
    halfspace: rock_depth below the top of the halfspace and x_from_reference along x from it
    (the DRM's reference point, drm_layered_oblique.sh), through surface_transfer; numpy's FFT
    zero padded eight times. The Ricker's spectrum is below 1e-30 of its peak above 12.5 f0:
    the transfer is left zero there."""
    dt, m = t[1] - t[0], 8 * len(t)
    tt = np.arange(m) * dt
    arg = (np.pi * f0 * (tt - t0)) ** 2
    v_in = amplitude * (1 - 2 * arg) * np.exp(-arg)
    om = 2 * np.pi * np.fft.rfftfreq(m, dt)
    band = om < 2 * np.pi * 12.5 * f0
    tf = np.zeros((2, len(om)), complex)
    tf[:, band] = surface_transfer(layers, halfspace, wave, angle_deg, om[band])
    c_rock = halfspace[2] if wave == "sv" else halfspace[1]
    p = np.sin(np.radians(angle_deg)) / c_rock
    q_rock = np.sqrt(1 / c_rock**2 - p**2)
    shift = np.exp(-1j * om * (rock_depth * q_rock + p * x_from_reference))
    return [np.fft.irfft(np.fft.rfft(v_in) * tf[k] * shift, m)[: len(t)] for k in (0, 1)]
