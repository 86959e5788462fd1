# -energy_interval N books the work of every step and evaluates the stored energies and the
# balance every N steps and at the last. The discrete identity (energy_ledger.hpp) holds at
# each step, so an evaluation every 7th step must show exactly what an evaluation at every
# step shows at that step: every energy column equal to round-off (1e-12 of the largest
# energy; the sums are the same sums, only the FMA contraction of the two loops may differ),
# and the balance at round-off (1e-9, as energy_closed), on 1 and 2 ranks. If a skipped step's
# work were lost (the ledger sampled instead of booked) the input and absorbed work would lack
# 6/7 of their terms and the balance would fail by O(1). Scenes: the ledger's two paths, the
# listed one (absorbing sides and an SV input: work summed on the boundary dofs only) and the
# sweep of every dof (constant-Q damping and Rayleigh damping add work over the whole mesh).
# Output times are evaluated too; -output_interval 10 (beyond the run) leaves only the first
# and the last step as such.
set -eu
. tests/tools/lib.sh
base="-mesh_box_faces 40,20 -mesh_box_upper 100,50 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200
 -bc_bottom_type absorbing -bc_left_type absorbing -bc_right_type absorbing -input_wave sv -input_boundary bottom -input_stf ricker -input_f0 5
 -input_t0 0.24 -input_amplitude 0.1 -ts_max_time 0.8 -output_fields 0 -output_interval 10 -progress_interval 100"
damped="$base -material_soil_damping_ratio 0.05 -damping_ratio 0.02"
for scene in base damped; do
  opts=${!scene}
  $SW $opts -energy_interval 1 -output_dir "$WORK/${scene}_1" > /dev/null
  $SW $opts -energy_interval 7 -output_dir "$WORK/${scene}_7" > /dev/null
  $MPIEXEC -n 2 $SW $opts -energy_interval 7 -output_dir "$WORK/${scene}_7np2" > /dev/null
  for run in 1 7 7np2; do $CHECK energy "$WORK/${scene}_$run/energy.csv" --max-error 1e-9; done
done
$PY - "$WORK" <<'PY'
import sys
import numpy as np
work = sys.argv[1]
for scene in ("base", "damped"):
    every = np.genfromtxt(f"{work}/{scene}_1/energy.csv", delimiter=",", names=True)
    names = [n for n in every.dtype.names if n not in ("step", "time", "balance_error", "relative_balance_error")]
    scale = max(np.abs(every[n]).max() for n in names)
    last = int(every["step"][-1])
    for run in ("7", "7np2"):
        sampled = np.genfromtxt(f"{work}/{scene}_{run}/energy.csv", delimiter=",", names=True)
        steps = sampled["step"].astype(int)
        expected = sorted(set(range(0, last + 1, 7)) | {last})
        assert list(steps) == expected, f"{scene}_{run}: rows at steps {list(steps)[:5]}..., expected every 7th and the last"
        worst = max(np.abs(sampled[n] - every[n][steps]).max() for n in names) / scale
        assert worst < 1e-12, f"{scene}_{run}: energy columns differ from the every-step ledger by {worst:.2e} of the largest energy"
        print(f"{scene}, -energy_interval 7 ({run}): {len(steps)} rows of {last + 1}, columns equal to the every-step ledger within {worst:.1e} of the largest energy")
PY
