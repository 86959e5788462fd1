# Opening and re-contact: a 1 m block resting on a 1 m base (fixed at its bottom) through a
# Mohr-Coulomb interface (phi 30), under gravity g = 9.81, launched upward at v0 = 0.5 m/s.
# 1D column (x held), one cell of h = 0.125 m across (contact area A = 0.125 m^2 per metre of
# thickness), rho = 2000, E = 1e8, nu = 0 (c = 223.6 m/s); auto penalty E_pen = E/h = 8e8 Pa/m;
# default step (0.5 of the limit). Expected:
# - Flight: the block is a free body under uniform gravity, so it moves rigidly (no strain)
#   on the ballistic path y = v0 t - g t^2/2 and lands after 2 v0/g = 0.10194 s. Central
#   differences integrate a constant acceleration exactly, so the only errors are the step at
#   which the contact is detected (one step, 1.77e-4 s) and the base's own sag: it starts
#   unstressed and its top oscillates between 0 and -rho g Hs^2/E = -1.96e-4 m, which can
#   delay the meeting by up to 1.96e-4/v0 = 3.9e-4 s. Bound: dt + rho g Hs^2/(E v0) = 5.7e-4 s.
# - While open: status open and traction exactly 0 at every output frame; at every step the
#   interface stores nothing and its work does not change.
# - Landing: a mass m = rho Hb A = 250 kg arriving at v0 (the flight is symmetric) on a spring
#   k = E_pen A = 1e8 N/m compresses it at most v0 sqrt(m/k) + m g/k = 7.91e-4 + 2.45e-5
#   = 8.15e-4 m (rigid mass: energy 1/2 m v0^2 into the spring, plus the static weight). An
#   elastic block is softer than a rigid one (the contact stress is limited to about
#   Z v0 = rho c v0, i.e. a penetration Z v0/E_pen + m g/k = 3.0e-4 m), so the rigid estimate is
#   an upper bound. The penetration is read every step from the ledger: interface_stored =
#   1/2 E_pen A u^2 for a uniform penetration u.
# - Energy: kinetic + strain + interface stored + dissipated minus the work of gravity never
#   above 1.01 x the initial kinetic energy 31.25 J (issue bound), and the ledger's balance
#   at round-off (1e-9).
set -eu -o pipefail
. tests/tools/lib.sh
IC="$PY tests/tools/contact_checks.py"
# -energy_interval 1: the contact phase is read from energy.csv at every step.
$SW -mesh_box_faces 1,16 -mesh_box_upper 0.125,2 -regions base,block -region_block_box 0,0.125,1,2 \
  -material_base_rho 2000 -material_base_E 1e8 -material_base_nu 0 -material_block_rho 2000 -material_block_E 1e8 -material_block_nu 0 \
  -interfaces contact -interface_contact_regions base,block -interface_contact_phi 30 -interface_contact_penalty_rule mesh \
  -constrain_components x -bc_bottom_type fixed -gravity 9.81 -initial_velocity_block 0,0.5 \
  -ts_max_time 0.3 -output_interval 0.002 -progress_interval 100 -energy_interval 1 -output_dir "$WORK" | tee "$WORK/log"
dt=$(sed -n 's/^  time step \([0-9.e+-]*\) s = .*/\1/p' "$WORK/log")
read -r flight tol pen <<<"$($PY -c "
import math
v0, g, rho, E, h, A, Hb, Hs = 0.5, 9.81, 2000, 1e8, 0.125, 0.125, 1.0, 1.0
m, k = rho * Hb * A, E / h * A
print(2 * v0 / g, $dt + rho * g * Hs**2 / (E * v0), v0 * math.sqrt(m / k) + m * g / k)")"
$IC lift-drop "$WORK" --flight "$flight" --flight-tol "$tol" --E 8e8 --area 0.125 --penetration-max "$pen"
$IC open-traction "$WORK" --name contact --min-open 40
$IC energy-growth "$WORK" --max-growth 0.01 --max-balance 1e-9
