#!/usr/bin/python3
"""Closed-form free field of a plane P or SV wave in a homogeneous elastic half-space with a
free surface (incident + reflected P and S), for the DRM tests.

Geometry of slipwave's DRM (docs/drm.md): x horizontal (the direction of travel), y up, the
free surface at y = 0, depth z = -y. The incident up-going wave's particle velocity along its
polarisation is v(t) at the reference point (x_r, z_r); with horizontal slowness p and
vertical slownesses q_P, q_S, the incident wave's argument is t - p (x - x_r) + q (z - z_r) and
a reflected wave's is t - p (x - x_r) - q_k z - q z_r (equal at the surface).
Polarisations (x, up): incident P (sin i, cos i); incident SV (cos j, -sin j); reflected P
(sin i_P, -cos i_P), reflected S (-cos j_S, -sin j_S). The reflection coefficients come from
zero traction at the surface (2 x 2 solve) and are checked against the closed forms of Aki &
Richards (2nd ed., eqs. 5.27 and 5.30): their magnitudes must agree to 1e-12.
Below the critical angle only (all waves propagate, real coefficients).
"""
import numpy as np


def ricker_velocity(t, a, f0, t0):
    x = (np.pi * f0 * (t - t0)) ** 2
    return a * (1 - 2 * x) * np.exp(-x)


class HalfspacePlaneWave:
    def __init__(self, rho, vp, vs, wave, angle_deg):
        self.rho, self.vp, self.vs, self.wave = rho, vp, vs, wave
        c = vp if wave == "p" else vs
        p = np.sin(np.radians(angle_deg)) / c
        qp, qs = np.sqrt(1 / vp**2 - p**2), np.sqrt(1 / vs**2 - p**2)
        mu, lam = rho * vs**2, rho * vp**2 - 2 * rho * vs**2
        self.p, self.qp, self.qs = p, qp, qs

        def traction(d, s):  # (tau_xz, tau_zz) / (-i w) on z = const, z down
            return np.array([mu * (d[0] * s[1] + d[1] * s[0]), lam * (d[0] * s[0] + d[1] * s[1]) + 2 * mu * d[1] * s[1]])

        # (x, z down) polarisations and slownesses
        inc = (np.array([vp * p, -vp * qp]), np.array([p, -qp])) if wave == "p" else (np.array([vs * qs, vs * p]), np.array([p, -qs]))
        rp = (np.array([vp * p, vp * qp]), np.array([p, qp]))
        rs = (np.array([-vs * qs, vs * p]), np.array([p, qs]))
        A = np.column_stack([traction(*rp), traction(*rs)])
        self.R = np.linalg.solve(A, -traction(*inc))
        self.waves = [(1.0, inc), (self.R[0], rp), (self.R[1], rs)]
        # Aki & Richards closed forms (magnitudes)
        ci, cj = vp * qp, vs * qs
        g = 1 / vs**2 - 2 * p**2
        D = g**2 + 4 * p**2 * (ci / vp) * (cj / vs)
        PP = (-g**2 + 4 * p**2 * (ci / vp) * (cj / vs)) / D
        PS = 4 * (vp / vs) * p * (ci / vp) * g / D
        SP = 4 * (vs / vp) * p * (cj / vs) * g / D
        want = (abs(PP), abs(PS)) if wave == "p" else (abs(SP), abs(PP))
        assert np.allclose(np.abs(self.R), want, rtol=1e-12, atol=1e-14), (self.R, want)

    def velocity(self, v, t, x, y, xr, zr):
        """(v_x, v_y) at the point (x, y) for the incident velocity history v(t)."""
        z = -y
        out = np.zeros((2, np.size(t)))
        q_in = self.qp if self.wave == "p" else self.qs
        for k, (amp, (d, s)) in enumerate(self.waves):
            arg = t - self.p * (x - xr) + (q_in * (z - zr) if k == 0 else -s[1] * z - q_in * zr)
            out += amp * np.outer([d[0], -d[1]], v(arg))
        return out

    def undrained_pressure(self, alpha_M, v, t, x, y, xr, zr):
        """Excess pore pressure of the undrained wave (no change of fluid content), -alpha M div u,
        with vp the undrained speed: only the P waves change volume, each by -(d . s) times its
        velocity history (d . s = 1/vp for both), so p = alpha M / vp times their velocity."""
        z = -y
        out = np.zeros(np.size(t))
        q_in = self.qp if self.wave == "p" else self.qs
        for k, (amp, (d, s)) in enumerate(self.waves):
            if k == 2 or (k == 0 and self.wave != "p"):
                continue  # S waves
            arg = t - self.p * (x - xr) + (q_in * (z - zr) if k == 0 else -s[1] * z - q_in * zr)
            out += amp * (d @ s) * alpha_M * v(arg)
        return out


def beyond_critical_velocity(rho, vp, vs, angle_deg, v_in, dt, x, y, xr, zr):
    """(v_x, v_y) of an SV wave beyond the critical angle (sin i > vs/vp), where the reflected P
    is evanescent: q_P = -i sqrt(p^2 - 1/vp^2) for w > 0 (decaying with depth), the free-surface
    coefficients complex (the same 2 x 2 zero-traction solve as above, in complex numbers). The
    incident velocity samples v_in (every dt from t = 0, zero padded 8x) are synthesised with
    numpy's FFT; time dependence e^{i w t}."""
    medium = lambda f: (np.full(np.shape(f), complex(rho)), np.full(np.shape(f), complex(vp)), np.full(np.shape(f), complex(vs)))
    return complex_medium_velocity(medium, np.sin(np.radians(angle_deg)) / vs, "sv", v_in, dt, x, y, xr, zr)


def complex_medium_velocity(medium, p, wave, v_in, dt, x, y, xr, zr):
    """(v_x, v_y) of a plane P or SV wave of real horizontal slowness p in a half-space whose
    density and speeds at frequency f are medium(f) = (rho*, vp*, vs*) (complex for a damped
    medium: Rayleigh rho* = rho (1 - i alpha/w), moduli (1 + i w beta) M; constant Q moduli
    M_U M(w)/M_U), synthesised per frequency as above: vertical slownesses q = sqrt(1/c*^2 - p^2)
    with Im q <= 0 (decaying downward), polarisations c* (p, +-q) (complex "unit" vectors, as in
    slipwave's plane_wave_layered.hpp), the reflection coefficients from zero traction with the
    moduli mu* = rho* vs*^2, lambda* = rho* vp*^2 - 2 mu*. x, y may be arrays of points: the
    result is then (2, points, samples). Any history works in place of the velocity (the
    displacement gives the displacement)."""
    n = 8 * len(v_in)
    f = np.fft.rfftfreq(n, dt)
    om = 2 * np.pi * f
    media = [tuple(complex(c) for c in medium(fj)) for fj in f]
    rho, vp, vs = (np.array([m[k] for m in media]) for k in range(3))
    mu, lam = rho * vs**2, rho * vp**2 - 2 * rho * vs**2

    def vertical(c):
        q = np.sqrt(1 / c**2 - p**2 + 0j)
        return np.where(q.imag > 0, -q, q)

    qp, qs = vertical(vp), vertical(vs)
    one = np.ones_like(qp)

    def traction(d, s):  # per frequency; d, s: (x, z) pairs of arrays
        return np.stack([mu * (d[0] * s[1] + d[1] * s[0]), lam * (d[0] * s[0] + d[1] * s[1]) + 2 * mu * d[1] * s[1]], axis=-1)

    inc = ((vp * p, -vp * qp), (p * one, -qp)) if wave == "p" else ((vs * qs, vs * p), (p * one, -qs))
    q_in = qp if wave == "p" else qs
    rp = ((vp * p, vp * qp), (p * one, qp))
    rs = ((-vs * qs, vs * p), (p * one, qs))
    R = np.linalg.solve(np.stack([traction(*rp), traction(*rs)], axis=-1), -traction(*inc)[..., None])[..., 0]
    V = np.fft.rfft(v_in, n)
    xs, zs = np.atleast_1d(np.asarray(x, float))[:, None], -np.atleast_1d(np.asarray(y, float))[:, None]
    out = np.zeros((2, len(xs), len(f)), complex)
    for k, (amp, (d, s)) in enumerate(((one, inc), (R[:, 0], rp), (R[:, 1], rs))):
        delay = p * (xs - xr) + (-q_in * (zs - zr) if k == 0 else s[1] * zs + q_in * zr)
        phase = amp * np.exp(-1j * om * delay)
        out[0] += d[0] * phase
        out[1] -= d[1] * phase
    result = np.fft.irfft(V * out, n)[..., : len(v_in)]
    return result if np.ndim(x) else result[:, 0]
