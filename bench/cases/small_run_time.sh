# Whole-process time of a small run, split by phase (issue 25 part 7: a ~70 k-DOF run should
# start, set up and write its output in under 0.2 s). The run: Lamb's line load of
# bench/cases/sem_speed_error.sh at degree 4, 60 x 40 elements (77 602 DOFs, 5 GLL nodes per
# lambda_min, 3.6 % error, 1531 steps; SMALL_RUN_DEGREE, SMALL_RUN_FACES), one rank, launched
# as a user would launch it (no mpiexec, no environment of our own). Per run: the whole process
# timed from outside (start to exit), and from -log_view its stages: Setup (options to the
# first step: mesh, operators, boundaries, outputs opened), Solve (TSSolve: the time loop),
# Output (the series flushed, the closing report). start+exit is the rest: exec, the dynamic
# loader, MPI and PETSc initialisation, option checks, clean-up, PetscFinalize.
# SMALL_RUN_REPEATS runs (default 7); the minimum of each column is printed (the machine may be
# shared: minima are the figures least disturbed by other work). Rows to $BENCH_CSV.
set -eu
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
PY=/usr/bin/python3
P=${SMALL_RUN_DEGREE:-4}
FACES=${SMALL_RUN_FACES:-60,40}
REPEATS=${SMALL_RUN_REPEATS:-7}
WORK="$BUILD/bench/work/small_run_time"
mkdir -p "$WORK"
eval "$($PY bench/sem_speed_error.py geometry)" # LAMB: sem_speed_error.sh's run but mesh and degree
LAMB="$LAMB -element_degree $P -time_step_safety 0.45 -mesh_box_faces $FACES -output_dir $WORK/run -output_overwrite"
$PY - "$SW" "$WORK" "$REPEATS" "${BENCH_CSV:-}" "p${P}_${FACES/,/x}" $LAMB <<'PY'
import re, subprocess, sys, time
sw, work, repeats, csv, case, args = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4], sys.argv[5], sys.argv[6:]
rows = []
for k in range(repeats):
    log = f"{work}/log_view_{k}.txt"
    start = time.perf_counter()
    out = subprocess.run([sw, *args, "-log_view", f":{log}"], capture_output=True, text=True)
    whole = time.perf_counter() - start
    if out.returncode:
        sys.exit(f"small_run_time: the run failed:\n{out.stdout}{out.stderr}")
    stages = dict(re.findall(r"^\s*\d+:\s+(\w[\w ]*?):\s+([0-9.e+-]+)", open(log).read(), re.M))
    setup, loop, output = (float(stages.get(name, 0)) for name in ("Setup", "Solve", "Output"))
    rows.append((whole, whole - setup - loop - output, setup, loop, output))
names = ("whole", "start+exit", "setup", "loop", "output")
best = [min(r[i] for r in rows) for i in range(len(names))]
print(f"{case}, {repeats} runs, minimum of each column [s]: " + ", ".join(f"{n} {b:.3f}" for n, b in zip(names, best)))
print(f"  start + set-up + output (the fixed time): {best[1] + best[2] + best[4]:.3f} s")
if csv:
    with open(csv, "a") as f:
        for n, b in zip(names, best):
            f.write(f"small_run_time,{case},{n.replace('+', '_')}_wall,{b:.6g},s\n")
PY
