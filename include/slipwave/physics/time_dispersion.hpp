// The numerical dispersion of the explicit integrators (time/central_difference.hpp): a mode
// of angular frequency omega stepped with h oscillates at omega~, from the scheme's
// characteristic equation u_{n+1} - 2 cos(omega~ h) u_n + u_{n-1} = 0:
//   order 2 (central difference): cos(omega~ h) = 1 - W^2/2, omega~ > omega (it runs fast),
//     omega~/omega - 1 = (2/W) asin(W/2) - 1 ~ W^2/24;
//   order 4 (modified equation):  cos(omega~ h) = 1 - W^2/2 + W^4/24, omega~ < omega,
//     omega~/omega - 1 ~ -W^4/720 (the first neglected term of cos, W^6/720, over W sin W ~ W^2),
// with W = omega h. The relative error of omega is that of the phase speed, which adds to the
// elements' (numerics/spectral_dispersion.hpp). Plain doubles.
#pragma once

namespace slipwave::physics {

// omega~/omega - 1 for order 2 or 4 at W = omega h inside the stable range (W <= 2, W < sqrt 12).
double integratorPhaseSpeedError(int order, double omega_dt);

// The largest h whose |integratorPhaseSpeedError| at omega is at most `error` (> 0), within
// the stable range (|error| grows with W there).
double integratorStepForError(int order, double omega, double error);

} // namespace slipwave::physics
