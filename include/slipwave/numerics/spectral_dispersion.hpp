// The numerical dispersion of spectral elements: how much slower than c a wave travels on a
// chain of 1D GLL elements of degree p (lumped, diagonal mass), from the Bloch analysis of
// one element (Ainsworth & Wajid 2009, SIAM J. Numer. Anal. 47, 3910-3937, treat the same
// problem). At angular frequency Omega the element's dynamic stiffness K - Omega^2 M,
// condensed onto its two end nodes, is [[a, b], [b, a]] (the element is symmetric); a chain of
// such elements carries u_j = exp(i j theta) when 2 a + 2 b cos(theta) = 0, so the discrete
// phase per element is theta_h = acos(-a / b), unfolded onto the branch nearest the exact
// theta = Omega h_e / c. The relative phase-speed error is theta / theta_h - 1 (negative:
// spectral elements with lumped mass are slow). Frequencies in a band gap (|a / b| > 1, at
// theta = m pi) get the band edge's phase. Plain doubles, no PETSc.
#pragma once

namespace slipwave::numerics {

// Relative phase-speed error at theta = k h_e (exact phase per element, > 0), degree 1..8.
double spectralPhaseSpeedError(int p, double theta);

// The largest |spectralPhaseSpeedError| over every wavelength at least as long as that of
// n GLL nodes per wavelength (theta = 2 pi p / n and below, 256 phases): what a signal whose
// shortest wavelength carries n nodes suffers at worst. The error falls like n^(-2p) apart
// from the band gaps at theta = m pi, which a single n could miss or hit.
double spectralDispersionBound(int p, double nodes_per_wavelength);

} // namespace slipwave::numerics
