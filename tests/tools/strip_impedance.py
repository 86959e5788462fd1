#!/usr/bin/env python3
"""Dynamic impedance of a rigid, massless strip footing (half-width B, plane strain) on the
surface of a homogeneous elastic half-space: the reference for slipwave's forced-vibration
impedance (tests/cases/foundation_impedance_strip.sh, bench/cases/foundation_impedance_strip.sh).

Method (the subdivision method of Gazetas & Roesset; Gazetas 1975, MIT thesis "Dynamic
stiffness functions of strip and rectangular footings on layered media"): the contact width
is cut into N sub-strips (cosine spacing, finer at the edges where the traction is singular)
carrying uniform tractions; the surface displacement at each sub-strip's centre follows from
the half-space's surface Green's functions for harmonic line loads (tests/tools/
lamb_line_load.py, surface_kernels), integrated over the sub-strip in the wavenumber domain:
    even kernels (U_z, U_x):  1/pi int_0^inf U(k) cos(k d) 2 sin(k b)/k dk
    odd kernel (V_x):         1/pi int_0^inf V(k) sin(k d) 2 sin(k b)/k dk
(d: collocation point minus sub-strip centre, b: the sub-strip's half-width). The integrand
has the branch points w/vp, w/vs and the Rayleigh pole w/c_R on the real axis; the path from
0 to 2 w/vs is lifted into Im k > 0 (k = t + i h sin(pi t / K1)), which for time dependence
e^{i w t} passes the pole on the side the radiation condition asks for (a small material
damping would move it below the axis) and keeps numpy's principal roots on the outgoing,
decaying branches. From K1 on, the integrand minus its static (Flamant) asymptote, which
decays as k^-4, is integrated numerically; the asymptote's share is done in closed form
(sine and cosine integrals), which also carries the sub-strips' logarithmic self-influence.
The flexibility matrix is inverted, the rigid-body motion imposed, and the resultant force
and moment give K (3 x 3: horizontal, vertical, rocking about the base's centre).

Contact: "welded" (both traction components under the footing, as in slipwave, where the
footing is one with the soil; Gazetas 1975 takes the strip "perfectly bonded", and so, by
its title, does Luco & Westmann 1972, "Dynamic response of a rigid footing bonded to an
elastic half space") or "relaxed" (no shear for vertical and rocking, no normal traction for
horizontal motion: the assumption of Luco 1974, Nucl. Eng. Des. 31, for the disc). Welded
contact couples horizontal motion and rocking (K_xr); at nu = 1/3 it stiffens rocking by
3.5 % and the translations by about 1 % over relaxed contact (printed by the self-check).

Conventions: z down (a vertical force and displacement are positive down), rocking theta
with u_z = theta x (the edge at +B goes down), moment M = int q_z x dx. Dimensionless
coefficients (Gazetas 1991): K = K_ref (k + i a0 c), a0 = w B / vs.

As a script it checks itself against what is published and against its own convergence
(see self_check).
"""
import sys

import numpy as np
from scipy.special import sici

from lamb_line_load import poisson_ratio, surface_kernels


def _gauss_panels(edges, order=8):
    """Gauss-Legendre nodes and weights on consecutive panels [edges[i], edges[i + 1]]."""
    x, w = np.polynomial.legendre.leggauss(order)
    a, b = edges[:-1, None], edges[1:, None]
    return (0.5 * (b - a) * x + 0.5 * (a + b)).ravel(), (0.5 * (b - a) * w).ravel()


def wavenumber_path(omega, vs, B, per_unit=1.0):
    """Nodes k and weights dk of the integration path: lifted over the poles and branch points
    up to K1 = 2 w/vs, then real up to K2 = K1 + max(60 w/vs, 150/B) (beyond, the integrand
    minus its static asymptote is below 1e-4 of what it was at K1). per_unit scales the node
    density and K2 - K1 (convergence checks)."""
    kb = omega / vs
    K1 = 2.0 * kb
    h = 0.25 * kb  # the lift; at most e^{0.75 a0} growth of cos(k d), |d| + b <= 3B
    t, wt = _gauss_panels(np.linspace(0.0, K1, int(np.ceil(24 * per_unit)) + 1))
    k_path = t + 1j * h * np.sin(np.pi * t / K1)
    dk_path = wt * (1 + 1j * h * np.pi / K1 * np.cos(np.pi * t / K1))
    K2 = K1 + per_unit * max(60.0 * kb, 150.0 / B)
    # Panels no wider than 0.5/B (cos(k d) sin(k b) oscillates with periods >= 2 pi/(3B)) and
    # geometric near K1 (the difference to the static asymptote falls as k^-4 from there).
    geometric = K1 * 1.25 ** np.arange(0, 200)
    geometric = geometric[geometric < K1 + 0.5 / B]
    edges = np.unique(np.concatenate([geometric, np.arange(K1 + 0.5 / B, K2, 0.5 / (B * per_unit)), [K2]]))
    k_real, dk_real = _gauss_panels(edges)
    return k_path, dk_path, K1, k_real, dk_real


def _static_tail_even(d, b, K):
    """int_K^inf cos(k d) 2 sin(k b) / k^2 dk = I(b + d) + I(b - d),
    I(a) = int_K^inf sin(a k)/k^2 dk = sin(a K)/K - a Ci(|a| K) (by parts)."""
    def I(a):
        ci = sici(np.maximum(np.abs(a), 1e-300) * K)[1]
        return np.sin(a * K) / K - np.where(a == 0, 0.0, a * ci)
    return I(b + d) + I(b - d)


def _static_tail_odd(d, b, K):
    """int_K^inf sin(k d) 2 sin(k b) / k^2 dk = J(d - b) - J(d + b),
    J(a) = int_K^inf cos(a k)/k^2 dk = cos(a K)/K - |a| (pi/2 - Si(|a| K))."""
    def J(a):
        return np.cos(a * K) / K - np.abs(a) * (np.pi / 2 - sici(np.abs(a) * K)[0])
    return J(d - b) - J(d + b)


def sub_strips(B, n):
    """Edges at -B cos(pi j / n): centres and half-widths of the n sub-strips."""
    edges = -B * np.cos(np.pi * np.arange(n + 1) / n)
    return 0.5 * (edges[1:] + edges[:-1]), 0.5 * (edges[1:] - edges[:-1])


def influence_matrices(omega, B, n, rho, vp, vs, per_unit=1.0):
    """A_zz, A_xx (even kernels) and A_xz (odd, vertical load -> u_x) between the n sub-strips
    [m/Pa: displacement at centre i per unit traction on sub-strip j]."""
    mu = rho * vs * vs
    nu = poisson_ratio(vp, vs)
    x, b = sub_strips(B, n)
    d = (x[:, None] - x[None, :]).ravel()
    bj = np.broadcast_to(b[None, :], (n, n)).ravel()
    k_path, dk_path, K1, k_real, dk_real = wavenumber_path(omega, vs, B, per_unit)
    s_even, s_odd = (1 - nu) / mu, -(1 - 2 * nu) / (2 * mu)  # the static asymptotes times k
    out = np.zeros((3, n * n), complex)
    for k, dk, static in ((k_path, dk_path, False), (k_real, dk_real, True)):
        for chunk in np.array_split(np.arange(len(k)), max(1, len(k) * n * n // 2_000_000)):
            kc = k[chunk]
            Uz, Ux, Vx = surface_kernels(kc, omega, vp, vs, mu)
            if static:
                Uz, Ux, Vx = Uz - s_even / kc, Ux - s_even / kc, Vx - s_odd / kc
            strip = 2 * np.sin(np.outer(bj, kc)) / kc * dk[chunk]
            cos, sin = np.cos(np.outer(d, kc)) * strip, np.sin(np.outer(d, kc)) * strip
            out[0] += cos @ Uz
            out[1] += cos @ Ux
            out[2] += sin @ Vx
    out[0] += s_even * _static_tail_even(d, bj, K1)
    out[1] += s_even * _static_tail_even(d, bj, K1)
    out[2] += s_odd * _static_tail_odd(d, bj, K1)
    return [a.reshape(n, n) / np.pi for a in out], x, b


def impedance_matrix(a0, B=1.0, rho=1.0, vp=2.0, vs=1.0, n=48, contact="welded", per_unit=1.0):
    """K (3 x 3, rows/columns: horizontal u_x, vertical u_z, rocking theta about the base's
    centre) per unit length of strip at a0 = w B / vs."""
    omega = a0 * vs / B
    (Azz, Axx, Axz), x, b = influence_matrices(omega, B, n, rho, vp, vs, per_unit)
    if contact == "welded":
        # u_x = A_xx q_x + A_xz q_z; u_z = A_zx q_x + A_zz q_z with A_zx = -A_xz (reciprocity)
        F = np.block([[Axx, Axz], [-Axz, Azz]])
    elif contact == "relaxed":
        Z = np.zeros_like(Azz)
        F = np.block([[Axx, Z], [Z, Azz]])
    else:
        raise ValueError(contact)
    one, zero = np.ones(n), np.zeros(n)
    modes = np.column_stack([np.r_[one, zero], np.r_[zero, one], np.r_[zero, x]])
    q = np.linalg.solve(F, modes)
    area = 2 * b
    resultants = np.vstack([area @ q[:n], area @ q[n:], (area * x) @ q[n:]])
    return resultants


def rocking_static(G, nu, B):
    """The tilted rigid punch (Muskhelishvili; Gazetas 1991, table for strips)."""
    return np.pi * G * B * B / (2 * (1 - nu))


def self_check():
    """Checks against published values and closed forms, and the convergence in N and in the
    wavenumber integration; exits non-zero if one fails."""
    rho, vs, vp, B = 1.0, 1.0, 2.0, 1.0  # nu = 1/3 as in slipwave's tests
    G, nu = rho * vs * vs, poisson_ratio(vp, vs)
    Kr = rocking_static(G, nu, B)
    ok = True

    def report(name, value, expected, tol):
        nonlocal ok
        err = abs(value / expected - 1)
        ok &= err <= tol
        print(f"{name}: {value:.5g} vs {expected:.5g}: rel {err:.2e} (bound {tol:g}) {'ok' if err <= tol else 'FAILED'}")

    # (1) Static limit of rocking, relaxed contact: K_r = pi G B^2 / (2 (1 - nu)) (exact).
    K = impedance_matrix(0.01, n=48, contact="relaxed")
    report("rocking, relaxed, a0 = 0.01: Re K_rr / K_r", K[2, 2].real / Kr, 1.0, 0.01)
    Kw = impedance_matrix(0.01, n=48)
    print(f"welded / relaxed contact at a0 = 0.01: rocking {Kw[2, 2].real / K[2, 2].real:.4f}, vertical {abs(Kw[1, 1] / K[1, 1]):.4f}, "
          f"horizontal {abs(Kw[0, 0] / K[0, 0]):.4f}; coupling K_xr / (B sqrt(|K_xx| K_rr)) = {abs(Kw[0, 2]) / (B * np.sqrt(abs(Kw[0, 0]) * Kw[2, 2].real)):.3f}")
    # (2) Convergence in N and in the wavenumber integration at a0 = 1 and 2 (welded).
    for a0 in (1.0, 2.0):
        K48 = impedance_matrix(a0, n=48)
        K96 = impedance_matrix(a0, n=96)
        Kfine = impedance_matrix(a0, n=48, per_unit=2.0)
        for i, name in ((0, "horizontal"), (1, "vertical"), (2, "rocking")):
            report(f"a0 = {a0}, {name}: K(N = 48) against N = 96", abs(K48[i, i]), abs(K96[i, i]), 0.01)
            report(f"a0 = {a0}, {name}: K against twice the wavenumber nodes and range", abs(K48[i, i]), abs(Kfine[i, i]), 1e-4)
    # (3) High frequency: the tractions under the footing tend to those of plane waves, rho vp
    # u' (vertical) and rho vs u' (horizontal) (edge effects fall as 1/a0): C_z -> rho vp 2B,
    # C_x -> rho vs 2B (the latter Gazetas 1991's strip formula); at a0 = 8 within 10 %.
    a0 = 8.0
    K = impedance_matrix(a0, n=96)
    w = a0 * vs / B
    report(f"a0 = {a0}: C_x / (rho vs 2B)", K[0, 0].imag / w / (rho * vs * 2 * B), 1.0, 0.10)
    report(f"a0 = {a0}: C_z / (rho vp 2B)", K[1, 1].imag / w / (rho * vp * 2 * B), 1.0, 0.10)
    # Gazetas 1991's Lysmer-analogue dashpot rho V_La 2B, V_La = 3.4 vs/(pi (1 - nu)), is an
    # approximation for the engineering range a0 ~ 0.5-2 (printed, not checked).
    V_La = 3.4 * vs / (np.pi * (1 - nu))
    for a0 in (0.5, 1.0, 2.0):
        K = impedance_matrix(a0)
        w = a0 * vs / B
        print(f"a0 = {a0}: C_z / (rho V_La 2B) = {K[1, 1].imag / w / (rho * V_La * 2 * B):.3f}, "
              f"C_x / (rho vs 2B) = {K[0, 0].imag / w / (rho * vs * 2 * B):.3f}, "
              f"k_r = {K[2, 2].real / Kr:.3f} (Gazetas 1991: about 1 - 0.2 a0 = {1 - 0.2 * a0:.2f})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(self_check())
