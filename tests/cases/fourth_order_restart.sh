# Checkpoint/restart with the fourth-order integrator (issue 25): tests/cases/sem_restart.sh
# (the default scene at degree 2: geostatic stage, sliding interface, constant Q, free-field
# sides; run C to the end, A to a checkpoint halfway, B from it) with -ts_cd_order 4. The
# integrator keeps the two accelerations before the current one (for the reported velocity)
# and the ledger its correction work: both in the checkpoint (version 11), so B must equal C
# byte for byte (energy.csv, every station file).
set -eu
CD_ORDER=4 bash tests/cases/sem_restart.sh
