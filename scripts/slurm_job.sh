#!/bin/bash
# slipwave batch job for SLURM. Submit from the slipwave directory:
#     sbatch scripts/slurm_job.sh
#     SCENE=my_scene.yaml EXTRA="-ts_max_time 10" sbatch --ntasks=16 scripts/slurm_job.sh
# Outside SLURM (no SLURM_JOB_ID) it runs locally with mpiexec:
#     NP=2 bash scripts/slurm_job.sh
# Steps: copy the scene into OUT, record provenance, dry run (OUT/dry_run.txt), the run
# (-output_dir OUT, log in OUT/run.log), plots (OUT/plots/) if /usr/bin/python3 has matplotlib.
# The exit status is that of the run.
#
# Edit the #SBATCH lines for your site: they must stay before the first command.
#SBATCH --job-name=slipwave
#SBATCH --nodes=1
#SBATCH --ntasks=4
#SBATCH --time=01:00:00
#SBATCH --output=slipwave-%j.out
##SBATCH --partition=compute
##SBATCH --account=my_project
##SBATCH --mem-per-cpu=2G

# ---------------------------------------------------------------------------------------
# Variables to edit. Each can also be set in the environment when submitting; the
# environment wins (SCENE=... sbatch scripts/slurm_job.sh).
#   SCENE  options file of the scene (YAML or PETSc format), relative to the submit
#          directory or to the slipwave directory
#   NP     MPI ranks (default: the tasks SLURM gave the job; locally 2)
#   OUT    output directory (default: $SCRATCH/run-<jobid>, or ./run-<jobid> without SCRATCH)
#   EXTRA  more options, they override the scene: "-ts_max_time 2 -output_interval 0.02"
#   SLIPWAVE_HOME  the slipwave directory (default: found from this script or the submit dir)
#   SLIPWAVE_BIN   the executable (default: $SLIPWAVE_HOME/build/slipwave)
#   MPIEXEC        the launcher, replaces srun / mpiexec (e.g. "srun --mpi=pmix")
SCENE=${SCENE:-config/scenes/default.yaml}
NP=${NP:-${SLURM_NTASKS:-2}}
OUT=${OUT:-}
EXTRA=${EXTRA:-}
SLIPWAVE_HOME=${SLIPWAVE_HOME:-}
SLIPWAVE_BIN=${SLIPWAVE_BIN:-}
MPIEXEC=${MPIEXEC:-}
# Site modules, if slipwave was built with them:
# module load openmpi petsc hdf5
# ---------------------------------------------------------------------------------------

set -eu
die() { echo "slurm_job.sh: error: $*" >&2; exit 1; }

if [ -n "${SLURM_JOB_ID:-}" ]; then
  MODE=slurm; JOBID=$SLURM_JOB_ID; START_DIR=${SLURM_SUBMIT_DIR:-$PWD}
else
  MODE=local; JOBID=local-$(date +%Y%m%d-%H%M%S)-$$; START_DIR=$PWD
fi
cd "$START_DIR"

# The slipwave directory: SLIPWAVE_HOME, else where this script lives (sbatch runs a copy in
# its spool, so also the submit directory).
for d in "$SLIPWAVE_HOME" "$(dirname "$0")/.." "$START_DIR"; do
  if [ -n "$d" ] && [ -f "$d/scripts/plot_results.py" ]; then SLIPWAVE_HOME=$(cd "$d" && pwd); break; fi
done
[ -n "$SLIPWAVE_HOME" ] || die "cannot find the slipwave directory; set SLIPWAVE_HOME"
SCHEDULER_LAUNCH=()
[ "$MODE" = slurm ] && SCHEDULER_LAUNCH=(srun --ntasks="$NP")

SELF=slurm_job.sh
NODES=${SLURM_JOB_NODELIST:-$(hostname)}
# shellcheck source=scripts/job_run.sh
. "$SLIPWAVE_HOME/scripts/job_run.sh"
