#!/bin/bash
# slipwave batch job for PBS (PBS Pro / OpenPBS; Torque: see the commented line). Submit from
# the slipwave directory:
#     qsub scripts/pbs_job.sh
#     qsub -v SCENE=my_scene.yaml,EXTRA="-ts_max_time 10" scripts/pbs_job.sh
# Outside PBS (no PBS_JOBID) it runs locally with mpiexec:
#     NP=2 bash scripts/pbs_job.sh
# Steps: copy the scene into OUT, record provenance, dry run (OUT/dry_run.txt), the run
# (-output_dir OUT, log in OUT/run.log), plots (OUT/plots/) if /usr/bin/python3 has matplotlib.
# The exit status is that of the run.
#
# Edit the #PBS lines for your site: they must stay before the first command.
# select=<nodes>:ncpus=<cores per node>:mpiprocs=<ranks per node>
#PBS -N slipwave
#PBS -l select=1:ncpus=4:mpiprocs=4
#PBS -l walltime=01:00:00
#PBS -j oe
#PBS -o slipwave.out
##PBS -l nodes=1:ppn=4
##PBS -q workq
##PBS -A my_project

# ---------------------------------------------------------------------------------------
# Variables to edit. Each can also be set in the environment when submitting; the
# environment wins (qsub -v SCENE=...,NP=... scripts/pbs_job.sh).
#   SCENE  options file of the scene (YAML or PETSc format), relative to the submit
#          directory or to the slipwave directory
#   NP     MPI ranks (default: the lines of $PBS_NODEFILE, i.e. the mpiprocs; locally 2)
#   OUT    output directory (default: $SCRATCH/run-<jobid>, or ./run-<jobid> without SCRATCH)
#   EXTRA  more options, they override the scene: "-ts_max_time 2 -output_interval 0.02"
#   SLIPWAVE_HOME  the slipwave directory (default: found from this script or the submit dir)
#   SLIPWAVE_BIN   the executable (default: $SLIPWAVE_HOME/build/slipwave)
#   MPIEXEC        the launcher, replaces "mpiexec -machinefile $PBS_NODEFILE" (e.g. "mpirun")
SCENE=${SCENE:-config/scenes/default.yaml}
if [ -z "${NP:-}" ] && [ -n "${PBS_NODEFILE:-}" ] && [ -f "$PBS_NODEFILE" ]; then NP=$(wc -l <"$PBS_NODEFILE"); fi
NP=${NP:-2}
OUT=${OUT:-}
EXTRA=${EXTRA:-}
SLIPWAVE_HOME=${SLIPWAVE_HOME:-}
SLIPWAVE_BIN=${SLIPWAVE_BIN:-}
MPIEXEC=${MPIEXEC:-}
# Site modules, if slipwave was built with them:
# module load openmpi petsc hdf5
# ---------------------------------------------------------------------------------------

set -eu
die() { echo "pbs_job.sh: error: $*" >&2; exit 1; }

if [ -n "${PBS_JOBID:-}" ]; then
  MODE=pbs; JOBID=${PBS_JOBID%%.*}; START_DIR=${PBS_O_WORKDIR:-$PWD}
else
  MODE=local; JOBID=local-$(date +%Y%m%d-%H%M%S)-$$; START_DIR=$PWD
fi
cd "$START_DIR"

# The slipwave directory: SLIPWAVE_HOME, else where this script lives (PBS runs a copy in
# its spool, so also the submit directory).
for d in "$SLIPWAVE_HOME" "$(dirname "$0")/.." "$START_DIR"; do
  if [ -n "$d" ] && [ -f "$d/scripts/plot_results.py" ]; then SLIPWAVE_HOME=$(cd "$d" && pwd); break; fi
done
[ -n "$SLIPWAVE_HOME" ] || die "cannot find the slipwave directory; set SLIPWAVE_HOME"
SCHEDULER_LAUNCH=()
if [ "$MODE" = pbs ]; then
  SCHEDULER_LAUNCH=(mpiexec -n "$NP")
  [ -n "${PBS_NODEFILE:-}" ] && SCHEDULER_LAUNCH+=(-machinefile "$PBS_NODEFILE")
fi

SELF=pbs_job.sh
NODES=$(if [ -n "${PBS_NODEFILE:-}" ] && [ -f "$PBS_NODEFILE" ]; then sort -u "$PBS_NODEFILE" | tr '\n' ' '; else hostname; fi)
# shellcheck source=scripts/job_run.sh
. "$SLIPWAVE_HOME/scripts/job_run.sh"
