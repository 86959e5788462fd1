"""Elastic response spectra of an acceleration history (numpy only).

The pseudo-acceleration PSA(T) = omega^2 max|u| of the damped oscillator
    u'' + 2 zeta omega u' + omega^2 u = -a_g(t),   omega = 2 pi / T,
starting at rest, with a_g linear between the samples. The step from sample i to i+1 is the
exact solution for that linear excitation (Nigam & Jennings, BSSA 59 (1969) 909-922), so the
result has no time-step error for the piecewise-linear record: only the maximum between
samples is missed (below 1 % when dt <= T/10, see response_spectrum.sh).
"""
import numpy as np


def oscillator_step(omega, zeta, dt):
    """Matrices A, B of the exact step  [u, v]_{i+1} = A [u, v]_i + B [a_i, a_{i+1}]  for
    u'' + 2 zeta omega u' + omega^2 u = -a, a linear on [t_i, t_i + dt], 0 <= zeta < 1."""
    root = np.sqrt(1.0 - zeta * zeta)
    wd = omega * root
    e = np.exp(-zeta * omega * dt)
    s, c = np.sin(wd * dt), np.cos(wd * dt)
    A = e * np.array([[c + zeta / root * s, s / wd],
                      [-omega / root * s, c - zeta / root * s]])
    # For a = a0 + da tau the particular solution is the quasi-static u_p = p + q tau with
    # q = -da / omega^2, p = -(a0 - 2 zeta da / omega) / omega^2; the free vibration carries
    # the rest of the initial state: x(dt) = x_p(dt) + A (x(0) - x_p(0)). B holds x_p(dt) -
    # A x_p(0) for a unit a_i (column 0) and a unit a_{i+1} (column 1).
    k = 1.0 / (omega * omega)
    B = np.empty((2, 2))
    for col, (a0, a1) in enumerate(((1.0, 0.0), (0.0, 1.0))):
        da = (a1 - a0) / dt
        vp = -k * da
        start = np.array([-k * (a0 - 2 * zeta / omega * da), vp])
        end = np.array([-k * (a1 - 2 * zeta / omega * da), vp])
        B[:, col] = end - A @ start
    return A, B


def oscillator_response(acc, dt, period, zeta=0.05):
    """Relative displacement u [m] at the samples of acc [m/s^2] (uniform step dt [s])."""
    acc = np.asarray(acc, float)
    A, B = oscillator_step(2 * np.pi / period, zeta, dt)
    x = np.zeros(2)
    u = np.empty(len(acc))
    u[0] = 0.0
    for i in range(len(acc) - 1):
        x = A @ x + B @ acc[i:i + 2]
        u[i + 1] = x[0]
    return u


def pseudo_acceleration_spectrum(acc, dt, periods, zeta=0.05):
    """PSA(T) = (2 pi / T)^2 max|u| [m/s^2] for each period T [s], all oscillators at once."""
    acc = np.asarray(acc, float)
    periods = np.asarray(periods, float)
    steps = [oscillator_step(2 * np.pi / T, zeta, dt) for T in periods]
    A = np.stack([s[0] for s in steps])  # [nT, 2, 2]
    B = np.stack([s[1] for s in steps])
    x = np.zeros((len(periods), 2))
    peak = np.zeros(len(periods))
    for i in range(len(acc) - 1):
        x = np.einsum("kij,kj->ki", A, x) + B @ acc[i:i + 2]
        np.maximum(peak, np.abs(x[:, 0]), out=peak)
    return (2 * np.pi / periods) ** 2 * peak


def resample_uniform(t, acc):
    """(dt, acc) on a uniform grid: the records of slipwave have a constant step already; a
    slightly varying one (round-off in t) is interpolated onto its mean step."""
    t = np.asarray(t, float)
    dt = (t[-1] - t[0]) / (len(t) - 1)
    if np.allclose(np.diff(t), dt, rtol=1e-6, atol=0):
        return dt, np.asarray(acc, float)
    grid = t[0] + dt * np.arange(len(t))
    return dt, np.interp(grid, t, acc)


def default_periods(n=60):
    """Log-spaced periods from 0.02 to 5 s."""
    return np.logspace(np.log10(0.02), np.log10(5.0), n)
