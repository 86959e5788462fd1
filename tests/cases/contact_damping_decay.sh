# Contact damping (issue 8, part 4): a closed pair's normal dashpot gives the decay its ratio
# says. A rigid block on a rigid base through a pressed interface oscillates on the penalty
# springs and decays freely. 1D column (x held): base and block one cell each (h = w = 1 m,
# rho = 2000, E = 1e11, nu = 0), base fixed at its bottom, gravity 9.81; the interface starts
# under the block's weight (sigma_N0 = -rho g H = -19620 Pa), so the block starts at
# equilibrium, and is launched down at v0 = 0.1 m/s. Penalty factor 1e-5: E_pen = 1e6 Pa/m,
# 1e5 times softer than a cell, so block and base are rigid to 1e-5.
# Expected (closed form): the block (mass M = rho w H = 2000 kg) on the two pairs' springs
# k = E_pen w = 1e6 N/m: wn = sqrt(k/M) = 22.36 rad/s, amplitude v0/wn = 4.5 mm (below the
# static compression 19.6 mm, so the pairs never open). Each pair is a spring E_pen w/2 between
# two nodes of lumped mass rho w h/4 = 500 kg (m_eff 250 kg) with the dashpot
# c = 2 zeta sqrt(E_pen (w/2) m_eff); the two dashpots on the block's mode give the ratio
# zeta_b = 2 c / (2 sqrt(k M)) = zeta / 2 (h = H). The free decay u(t) = A e^{-zeta_b wn t}
# sin(wd t), wd = wn sqrt(1 - zeta_b^2): log decrement per cycle 2 pi zeta_b / sqrt(1 - zeta_b^2).
# Tolerances: the dashpot acts on the half-step velocity, a lag of dt/2, which changes the
# ratio by about zeta_b wn dt / 2 (6.5e-5 at zeta_b = 0.1, wn dt = 1.3e-3); bound wn dt zeta_b.
# Period: peak times are sampled at the step (dt = 2e-4 T) over 5 cycles; bound 5e-4.
# Energy: the ledger, with the dashpots' work booked as contact_damped, closes to 1e-9, and
# what the dashpots took is the oscillation's energy 1/2 M v0^2 = 10 J less what is left,
# 10 (1 - e^{-2 zeta_b wn t_end}) J, within 1 % (the envelope formula averages over a cycle).
# The default ratio (0.1, no option given) and 0.2 are tested, and the default on 2 ranks
# against 1 rank (round-off: 1e-10 of each station quantity's peak).
set -eu -o pipefail
. tests/tools/lib.sh
IC="$PY tests/tools/contact_checks.py"
opts="-mesh_box_faces 1,2 -mesh_box_upper 1,2 -regions base,block -region_block_box 0,1,1,2
 -material_base_rho 2000 -material_base_E 1e11 -material_base_nu 0 -material_block_rho 2000 -material_block_E 1e11 -material_block_nu 0
 -interfaces contact -interface_contact_regions base,block -interface_contact_phi 30 -interface_contact_penalty_rule mesh -interface_contact_penalty_factor 1e-5
 -interface_contact_sigma_N0 -19620 -constrain_components x -bc_bottom_type fixed -gravity 9.81 -initial_velocity_block 0,-0.1
 -ts_max_time 1.5 -output_fields 0 -progress_interval 1000 -station_coordinates 0.5,2 -station_names top"
for zeta in default 0.2; do
  extra=""; z=0.1
  [ "$zeta" != default ] && extra="-interface_contact_contact_damping $zeta" && z=$zeta
  $SW $opts $extra -output_dir "$WORK/$zeta" > "$WORK/$zeta.log"
  grep "contact damping $z of critical" "$WORK/$zeta.log"
  dt=$(sed -n 's/^  time step \([0-9.e+-]*\) s = .*/\1/p' "$WORK/$zeta.log")
  read -r zb period ztol left <<<"$($PY -c "
import math
wn, zb = math.sqrt(1e6 / 2000), $z / 2
print(zb, 2 * math.pi / (wn * math.sqrt(1 - zb * zb)), wn * $dt * zb, 10 * (1 - math.exp(-2 * zb * wn * 1.5)))")"
  echo "== contact damping $z: block mode zeta_b = $zb"
  $IC decay "$WORK/$zeta" --station top --column u_y --zeta "$zb" --zeta-tol "$ztol" --period "$period" --period-tol 5e-4
  $IC energy-growth "$WORK/$zeta" --max-growth 0.01 --max-balance 1e-9
  $PY - "$WORK/$zeta/energy.csv" "$left" <<'PY'
import sys
import numpy as np
d = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
got, want = d["contact_damped"][-1], float(sys.argv[2])
print(f"contact dashpots took {got:.6e} J, expected 10 (1 - exp(-2 zeta_b wn t)) = {want:.6e} J, relative difference {abs(got - want) / want:.2e} (bound 1e-2)")
sys.exit(0 if abs(got - want) <= 1e-2 * want else 1)
PY
done
$MPIEXEC -n 2 $SW $opts -output_dir "$WORK/np2" > "$WORK/np2.log"
$CHECK stations-equal "$WORK/default" "$WORK/np2" --names top --tol 1e-10
