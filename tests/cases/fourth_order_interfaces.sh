# The interface scenes at degree 4 with the fourth-order integrator (issue 25), with the bounds
# they have with central differences: the Newmark sliding block (tests/cases/
# sem_interface_newmark.sh: slip within 2 % of Newmark's, 1 vs 2 ranks), the two-bar impact
# (sem_interface_bar.sh: contact duration and stress, velocities after, energy growth 1 %,
# balance 1e-9, 1 vs 2 ranks) and the tied SV column (sem_interface_tied.sh: the tied
# interface never slips, the response within its penalty bounds of the column without it,
# 1 vs 2 ranks). The interface forces (penalty springs, Mohr-Coulomb return, contact
# dashpots) enter as in central differences; the correction is the bulk's; the stable step is
# central differences' (problem/stable_step.hpp), at the interfaces' safety 0.5.
set -eu
for t in sem_interface_newmark sem_interface_bar sem_interface_tied; do
  echo "== $t with -ts_cd_order 4"
  CD_ORDER=4 bash tests/cases/$t.sh
done
