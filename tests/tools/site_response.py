#!/usr/bin/python3
"""Closed-form 1D site response of the default scene's site, for the scene tests.

A soil layer of thickness H on elastic rock, vertically incident SV wave (Kramer,
Geotechnical Earthquake Engineering, 1996, eq. 7.32 with complex moduli; time dependence
e^{i w t}, the convention of numpy's forward FFT kernel e^{-i w t}):
    surface / outcrop = 1 / (cos k* H + i alpha* sin k* H),
    k* = w / vs*(w),  alpha* = rho_s vs*(w) / (rho_r vs_r),
where the outcrop motion is twice the incident wave at the top of the rock. The soil's
complex speed vs*(w) = sqrt(G*(w) / rho_s) comes from the generalized Maxwell body that
slipwave fitted (its run report prints the mechanisms and the reference frequency):
    G*(w) / G_U = 1 - sum_l Y_l w_l / (w_l + i w),
with G_U set so that the phase speed 1 / Re(1 / vs*) equals the given vs at f_r.
"""
import re

import numpy as np

G = 9.80665  # standard gravity [m/s^2], the record's unit


def outcrop_velocity(path, pga_g):
    """(dt, velocity) of a record in g as slipwave applies it: baseline-corrected by removing the
    line c0 + c1 t that makes the integrated velocity and displacement end at zero, scaled to a
    peak acceleration of pga_g, integrated by the trapezoid rule (docs/features.md, "How a record is
    applied")."""
    d = np.loadtxt(path, delimiter=",", skiprows=1)
    t, a = d[:, 0], d[:, 1] * G
    dt = t[1] - t[0]

    def trapezoid(y):
        return np.concatenate([[0.0], np.cumsum(0.5 * (y[1:] + y[:-1]) * dt)])

    def ends(y):
        v = trapezoid(y)
        return v[-1], trapezoid(v)[-1]

    ramp = t - t[0]
    (v0, d0), (v1, d1), (v, dd) = ends(np.ones_like(t)), ends(ramp), ends(a)
    det = v0 * d1 - v1 * d0
    a = a - (v * d1 - v1 * dd) / det - (v0 * dd - v * d0) / det * ramp
    return dt, trapezoid(a * pga_g * G / np.max(np.abs(a)))


def fitted_body(report, region):
    """(frequencies [Hz], weights Y_l, reference frequency [Hz]) of a damped region, from the
    'mechanisms' line that follows 'region <name>: constant-Q damping' in the run report."""
    block = re.search(rf"region {region}: constant-Q damping.*?\n.*?\n\s*mechanisms \(relaxation frequency \[Hz\]: weight Y_l\):(.*); reference ([0-9.e+-]+) Hz", report)
    pairs = re.findall(r"([0-9.e+-]+): ([0-9.e+-]+)", block.group(1))
    return np.array([float(f) for f, _ in pairs]), np.array([float(y) for _, y in pairs]), float(block.group(2))


def complex_speed(f, speed, body=None):
    """vs*(f) of a material whose phase speed is `speed` at the body's reference frequency;
    the real `speed` itself when body is None (elastic)."""
    if body is None:
        return np.full(np.shape(f), complex(speed))
    freqs, weights, f_ref = body

    def ratio(x):
        w, wl = 2j * np.pi * np.asarray(x, float)[..., None], 2 * np.pi * freqs
        return 1 - np.sum(weights * wl / (wl + w), axis=-1)

    phase_ref = 1 / np.real(1 / np.sqrt(ratio(f_ref)))
    return speed / phase_ref * np.sqrt(ratio(f))


def surface_velocity(outcrop, dt, H, rho_s, vs, rho_r, vr, body=None, rock_path=0.0, n=2**17):
    """Free-surface velocity of the layer for an outcrop velocity history sampled at dt; the
    incident wave enters rock_path metres below the layer (travel delay rock_path / vr)."""
    f = np.fft.rfftfreq(n, dt)
    vstar = complex_speed(f, vs, body)
    k = 2 * np.pi * f / vstar
    alpha = rho_s * vstar / (rho_r * vr)
    transfer = np.exp(-2j * np.pi * f * rock_path / vr) / (np.cos(k * H) + 1j * alpha * np.sin(k * H))
    return np.fft.irfft(np.fft.rfft(outcrop, n) * transfer, n)
