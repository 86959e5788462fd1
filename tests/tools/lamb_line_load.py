#!/usr/bin/env python3
"""Lamb's problem in 2D (Lamb 1904): surface motion of an elastic half-space under a vertical
line load F s(t) [N/m] on its surface, by a frequency-wavenumber integral.

Plane strain, depth z down, load pushing down at x = 0. With k_a = w/vp, k_b = w/vs,
nu_a = sqrt(k^2 - k_a^2), nu_b = sqrt(k^2 - k_b^2) (Re >= 0: decaying with depth) and the
Rayleigh function R(k) = (2k^2 - k_b^2)^2 - 4 k^2 nu_a nu_b, the surface displacement per unit
force is (the standard solution of the surface-traction problem, e.g. Aki & Richards,
Quantitative Seismology, ch. 6; Ewing, Jardetzky & Press 1957)
    vertical (down):  u_z(x) = 1/pi int_0^inf U_z(k) cos(kx) dk,  U_z = -k_b^2 nu_a / (mu R)
    horizontal:       u_x(x) = 1/pi int_0^inf V_x(k) sin(kx) dk,  V_x = k (2k^2 - k_b^2 - 2 nu_a nu_b) / (mu R)
Its static limit w -> 0 (where R -> -2 k^2 (k_b^2 - k_a^2)) is Flamant's: U_z -> (1 - nu)/(mu k)
and V_x -> -(1 - 2 nu)/(2 mu k), i.e. u_z = -(1 - nu)/(pi mu) ln x + const and
u_x = -(1 - 2 nu)/(4 mu) for x > 0 (toward the load). The Rayleigh pole at k = w/c_R lies on
the real axis: the frequency is taken complex, w - i eps (Bouchon 1979; the time series is
multiplied back by e^{eps t}), which moves it off the axis. Beyond k_max the integrand is its
static asymptote, integrated in closed form (cosine and sine integrals).

As a script it checks itself: (1) at a low frequency the integral gives Flamant's
u_z(x1) - u_z(x2) = (1 - nu)/(pi mu) ln(x2/x1) and |u_x| = (1 - 2 nu)/(4 mu) within 1 %;
(2) the envelope of the vertical velocity of a Ricker load at 200 m peaks at the Rayleigh
arrival t0 + x/c_R (c_R the root of the Rayleigh equation, 0.9194 vs at nu = 0.25) within
2 % of the travel time.
"""
import sys

import numpy as np
from scipy.special import sici


def surface_kernels(k, omega, vp, vs, mu):
    """The surface flexibility in the wavenumber domain (module docstring), broadcast over k
    and w (complex k allowed: numpy's principal square roots are the decaying, outgoing
    branches for Re k, Im k >= 0): U_z (vertical load -> u_z, cosine transform), U_x
    (horizontal load -> u_x, cosine transform; U_z with the P and S roots swapped,
    by the symmetry of the traction problem) and V_x (vertical load -> u_x, sine transform; by
    reciprocity a horizontal load gives u_z with -V_x)."""
    ka2, kb2 = (omega / vp) ** 2, (omega / vs) ** 2
    nua, nub = np.sqrt(k * k - ka2 + 0j), np.sqrt(k * k - kb2 + 0j)
    R = (2 * k * k - kb2) ** 2 - 4 * k * k * nua * nub
    Uz = -kb2 * nua / (mu * R)
    Ux = -kb2 * nub / (mu * R)
    Vx = k * (2 * k * k - kb2 - 2 * nua * nub) / (mu * R)
    return Uz, Ux, Vx


def poisson_ratio(vp, vs):
    return 1 - 0.5 / (1 - (vs / vp) ** 2)


def _integrals(x, omega, vp, vs, mu, k_max, nk):
    """u_z(x, w), u_x(x, w) per unit force for complex w (arrays over w), x > 0."""
    nu = poisson_ratio(vp, vs)
    k = np.linspace(0.0, k_max, nk)[None, :]
    Uz, _, Vx = surface_kernels(k, omega[:, None], vp, vs, mu)
    wk = np.full(nk, k_max / (nk - 1))
    wk[0] = wk[-1] = 0.5 * k_max / (nk - 1)
    uz = (wk * Uz * np.cos(k * x)).sum(axis=1) / np.pi
    ux = (wk * Vx * np.sin(k * x)).sum(axis=1) / np.pi
    si, ci = sici(k_max * x)
    # The static asymptotes beyond k_max: int_K^inf cos(kx)/k dk = -Ci(Kx),
    # int_K^inf sin(kx)/k dk = pi/2 - Si(Kx).
    uz += (1 - nu) / mu * (-ci) / np.pi
    ux -= (1 - 2 * nu) / (2 * mu) * (np.pi / 2 - si) / np.pi
    return uz, ux


def surface_response(x, t, force, rho, vp, vs, f_max, eps=None, k_factor=8.0, dk_per_eps=0.05):
    """Displacement (down, and horizontal: + away from the load) at x > 0 on the surface for
    the load force(t) [N/m] sampled on the uniform grid t (starting at 0, long enough that the
    motion has died out: the series is periodic). Frequencies above f_max are dropped."""
    n = len(t)
    dt = t[1] - t[0]
    T = n * dt
    eps = eps if eps is not None else 6.0 / T  # wrap-around damped by e^{-6}
    mu = rho * vs * vs
    f = np.fft.rfftfreq(n, dt)
    keep = (f <= f_max) & (f > 0)
    omega = 2 * np.pi * f[keep] - 1j * eps
    S = np.fft.rfft(force * np.exp(-eps * t))[keep] * dt
    c_min = 0.87 * vs  # below the Rayleigh speed for any Poisson's ratio
    k_max = k_factor * 2 * np.pi * f_max / c_min
    dk = dk_per_eps * eps / vs
    nk = int(k_max / dk) + 1
    Uz, Ux = np.zeros(len(f), complex), np.zeros(len(f), complex)
    for chunk in np.array_split(np.arange(len(omega)), max(1, len(omega) * nk // 4_000_000)):
        uz, ux = _integrals(x, omega[chunk], vp, vs, mu, k_max, nk)
        Uz[np.flatnonzero(keep)[chunk]] = uz * S[chunk]
        Ux[np.flatnonzero(keep)[chunk]] = ux * S[chunk]
    uz_t = np.fft.irfft(Uz, n) / dt * np.exp(eps * t)
    ux_t = np.fft.irfft(Ux, n) / dt * np.exp(eps * t)
    return uz_t, ux_t


def rayleigh_speed(vp, vs):
    """Root of (2 - c^2/vs^2)^2 = 4 sqrt(1 - c^2/vp^2) sqrt(1 - c^2/vs^2) in (0, vs)."""
    lo, hi = 0.5 * vs, vs * (1 - 1e-12)
    g = lambda c: (2 - (c / vs) ** 2) ** 2 - 4 * np.sqrt(1 - (c / vp) ** 2) * np.sqrt(1 - (c / vs) ** 2)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if g(lo) * g(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)


def ricker(t, f0, t0):
    a = (np.pi * f0 * (t - t0)) ** 2
    return (1 - 2 * a) * np.exp(-a)


def self_check():
    rho, vs = 2000.0, 400.0
    vp = vs * np.sqrt(3.0)  # nu = 0.25
    mu, nu = rho * vs * vs, 0.25
    ok = True
    # (1) static limit: a frequency whose wavelengths are 100x the distances.
    omega = np.array([2 * np.pi * 0.02 - 1e-4j])
    x1, x2 = 10.0, 20.0
    uz1, ux1 = _integrals(x1, omega, vp, vs, mu, 50.0, 2_000_001)
    uz2, _ = _integrals(x2, omega, vp, vs, mu, 50.0, 2_000_001)
    dz, dz_exact = (uz1 - uz2).real[0], (1 - nu) / (np.pi * mu) * np.log(x2 / x1)
    ux_exact = -(1 - 2 * nu) / (4 * mu)
    e1, e2 = abs(dz / dz_exact - 1), abs(ux1.real[0] / ux_exact - 1)
    print(f"static limit: u_z(10) - u_z(20) = {dz:.6e}, Flamant {dz_exact:.6e} (rel {e1:.2e}); u_x(10) = {ux1.real[0]:.6e}, Flamant {ux_exact:.6e} (rel {e2:.2e})")
    ok &= e1 < 0.01 and e2 < 0.01
    # (2) Rayleigh arrival of a Ricker pulse at 200 m.
    f0, t0, x = 10.0, 0.12, 200.0
    t = np.arange(0, 4.0, 5e-4)
    uz, _ = surface_response(x, t, ricker(t, f0, t0), rho, vp, vs, f_max=4 * f0)
    vz = np.gradient(uz, t)
    c_r = rayleigh_speed(vp, vs)
    # The Rayleigh pulse of a line load is the Hilbert-shifted Ricker; its velocity envelope
    # peaks at the arrival: compare the envelope's peak time.
    from scipy.signal import hilbert
    env = np.abs(hilbert(vz))
    w = (t > 0.3) & (t < 1.5)
    t_peak = t[w][np.argmax(env[w])]
    t_r = t0 + x / c_r
    e3 = abs(t_peak - t_r) / (t_r - t0)
    print(f"Rayleigh arrival at {x:.0f} m: envelope peak {t_peak:.4f} s, t0 + x/c_R = {t_r:.4f} s (c_R = {c_r:.2f} m/s = {c_r / vs:.4f} vs): rel {e3:.2e}")
    ok &= e3 < 0.02
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(self_check())
