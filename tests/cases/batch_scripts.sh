# Batch templates: scripts/slurm_job.sh and scripts/pbs_job.sh.
# (1) Headers: every #SBATCH / #PBS line comes before the first command (the schedulers stop
#     reading there), with job name, nodes/tasks, time and output file; bash -n passes.
# (2) Local mode (no SLURM_JOB_ID / PBS_JOBID): each runs a tiny scene written here (a stiff
#     block on soil with interface 'base', two stations) with NP=2 and
#     EXTRA="-ts_max_time 0.05 ..." into OUT; checked: the scene copy (identical), provenance.txt,
#     dry_run.txt with the "stable step:" line, energy.csv with rows up to t = 0.05,
#     volume.xmf, interface_base.xmf, run.log, and the four plots.
# (3) Batch mode, simulated: SLURM_JOB_ID set and a fake srun on PATH (it logs its arguments
#     and runs mpiexec); PBS_JOBID/PBS_NODEFILE set and a fake mpiexec. Checked: the launcher
#     got the rank count (and the node file under PBS), and the default OUT is
#     $SCRATCH/run-<jobid>.
set -eu
. tests/tools/lib.sh
ROOT=$PWD
WORK="$ROOT/$WORK"  # absolute: the fake launchers log there
EXTRA="-ts_max_time 0.05 -output_interval 0.01 -progress_interval 100"
export SLIPWAVE_BIN="$ROOT/$SLIPWAVE_BINARY"
cat >"$WORK/tiny.yaml" <<'EOF'
# tiny scene of tests/cases/batch_scripts.sh: a stiff block on soil, 20 m x 6 m
mesh_box_faces: 20,6
mesh_box_upper: 20,6
regions: soil,block
region_block_box: 8,12,4,6
material_soil_rho: 2000
material_soil_vp: 600
material_soil_vs: 300
material_block_rho: 2400
material_block_vp: 3000
material_block_vs: 1800
interfaces: base
interface_base_regions: soil,block
bc_bottom_type: absorbing
input_wave: sv
input_stf: ricker
input_f0: 5
input_amplitude: 1
gravity: 9.81
ts_max_time: 1
station_coordinates: 10,6,10,0
station_names: top,base
EOF
export SCENE="$WORK/tiny.yaml"

$PY - scripts/slurm_job.sh scripts/pbs_job.sh <<'PY'
import re, sys
need = {"slurm_job.sh": ["--job-name", "--nodes", "--ntasks", "--time", "--output"],
        "pbs_job.sh": ["-N ", "-l select", "-l walltime", "-o "]}
for path in sys.argv[1:]:
    prefix = "#SBATCH" if "slurm" in path else "#PBS"
    lines = open(path).read().splitlines()
    first_cmd = next(i for i, l in enumerate(lines) if l.strip() and not l.lstrip().startswith("#"))
    headers = [i for i, l in enumerate(lines) if l.startswith(prefix + " ")]
    assert headers and max(headers) < first_cmd, f"{path}: a {prefix} line after the first command (line {first_cmd + 1})"
    text = "\n".join(lines[i] for i in headers)
    for key in need[path.split("/")[-1]]:
        assert key in text, f"{path}: no {prefix} {key}"
    print(f"{path}: {len(headers)} {prefix} lines before the first command")
PY
bash -n scripts/slurm_job.sh
bash -n scripts/pbs_job.sh

check_out() {  # DIR: what every run of a template must leave
  local d=$1
  for f in tiny.yaml provenance.txt dry_run.txt run.log energy.csv volume.xmf interface_base.xmf \
           plots/energy.png plots/stations_acceleration.png plots/interface_base_history.png plots/interface_base_profile.png; do
    [ -s "$d/$f" ] || { echo "$d/$f missing or empty"; exit 1; }
  done
  cmp -s "$d/tiny.yaml" "$SCENE" || { echo "$d/tiny.yaml differs from the scene"; exit 1; }
  grep -q "^  stable step: " "$d/dry_run.txt" || { echo "$d/dry_run.txt has no stable step line"; cat "$d/dry_run.txt"; exit 1; }
  grep -q "^dry run: stopping before the first step" "$d/dry_run.txt"
  grep -q "^slipwave: " "$d/provenance.txt"
  $PY - "$d" <<'PY'
import sys, numpy as np
e = np.genfromtxt(f"{sys.argv[1]}/energy.csv", delimiter=",", names=True)
assert e.shape[0] > 10 and abs(e["time"][-1] - 0.05) < 1e-9, (e.shape, e["time"][-1])
print(sys.argv[1], ": energy.csv", e.shape[0], "rows to t =", e["time"][-1])
PY
}

# (2) local mode
for s in slurm pbs; do
  env -u SLURM_JOB_ID -u PBS_JOBID -u SCRATCH -u MPIEXEC NP=2 OUT="$WORK/local_$s" EXTRA="$EXTRA" \
    bash scripts/${s}_job.sh >"$WORK/local_$s.log" 2>&1 || { cat "$WORK/local_$s.log"; exit 1; }
  check_out "$WORK/local_$s"
  grep -q "mode:      local" "$WORK/local_$s/provenance.txt"
  grep -q "^command:   mpiexec -n 2 " "$WORK/local_$s/provenance.txt"
done

# (3) batch mode, simulated with fake launchers that log their arguments
REAL_MPIEXEC=$(command -v mpiexec)
FAKE="$WORK/fakebin"; mkdir -p "$FAKE"
cat >"$FAKE/srun" <<EOF
#!/bin/bash
echo "srun \$*" >>"$WORK/launcher.log"
n=\${1#--ntasks=}; shift
exec $REAL_MPIEXEC $(echo "$MPIEXEC" | cut -d' ' -f2-) -n "\$n" "\$@"
EOF
cat >"$FAKE/mpiexec" <<EOF
#!/bin/bash
echo "mpiexec \$*" >>"$WORK/launcher.log"
case "\$1" in --version) exec $REAL_MPIEXEC --version ;; esac
exec $REAL_MPIEXEC $(echo "$MPIEXEC" | cut -d' ' -f2-) "\$@"
EOF
chmod +x "$FAKE/srun" "$FAKE/mpiexec"
mkdir -p "$WORK/scratch"
printf 'localhost\nlocalhost\n' >"$WORK/nodefile"

env -u PBS_JOBID -u NP -u OUT -u MPIEXEC PATH="$FAKE:$PATH" SLURM_JOB_ID=4242 SLURM_NTASKS=2 SLURM_SUBMIT_DIR="$ROOT" \
  SCRATCH="$WORK/scratch" EXTRA="$EXTRA" bash scripts/slurm_job.sh >"$WORK/batch_slurm.log" 2>&1 || { cat "$WORK/batch_slurm.log"; exit 1; }
check_out "$WORK/scratch/run-4242"
grep -q "mode:      slurm (job 4242)" "$WORK/scratch/run-4242/provenance.txt"
[ "$(grep -c '^srun --ntasks=2 .*build/slipwave -options_file' "$WORK/launcher.log")" = 2 ] || { cat "$WORK/launcher.log"; exit 1; }

env -u SLURM_JOB_ID -u NP -u OUT -u MPIEXEC PATH="$FAKE:$PATH" PBS_JOBID=77.server PBS_NODEFILE="$WORK/nodefile" PBS_O_WORKDIR="$ROOT" \
  SCRATCH="$WORK/scratch" EXTRA="$EXTRA" bash scripts/pbs_job.sh >"$WORK/batch_pbs.log" 2>&1 || { cat "$WORK/batch_pbs.log"; exit 1; }
check_out "$WORK/scratch/run-77"
grep -q "mode:      pbs (job 77)" "$WORK/scratch/run-77/provenance.txt"
[ "$(grep -c "^mpiexec -n 2 -machinefile $WORK/nodefile .*build/slipwave -options_file" "$WORK/launcher.log")" = 2 ] || { cat "$WORK/launcher.log"; exit 1; }
echo "batch scripts: OK"
