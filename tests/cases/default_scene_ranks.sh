# Rank independence of the default scene with its geostatic stage (issue 8, parts 5 and 6):
# config/scenes/default.yaml as it is, shortened to 3 s (the record's peak at 2.1 s and the
# yielding soil's largest strains; the block sticks on that soil, so the slip and status
# comparisons below guard against a spurious slip or opening, and the rocking block's stations
# and contact stresses carry the check), on 1 and 2 ranks (METIS partitions); the geostatic
# stage also on 3.
#  - The geostatic stage is one linear solve with the interface in stick, to a relative
#    residual of 1e-12: every rank count must report it (no fallback to relaxation, whose end
#    point depends on the rounding), and the geostatic state must agree to 1e-10 of its peak:
#    the cell stresses of the first frame (matched by cell centroid) and the pairs' sigma_N.
#    Its unbalanced-force ratio max|M a| / max|f| must be at round-off, below 1e-9: the
#    solver's 1e-12 of |f|_2 is at most 1e-12 sqrt(dofs) = 1.2e-10 of max|f| here, and the
#    element loop's K u adds the rounding of terms E u ~ 1e4 times the nodal load (the stiff
#    block moves 1 cm as a body), ~1e-12 each.
#  - The dynamic stage then sums each force in a different order only, so every station's
#    u and v agree to 1e-9 of their peak and a to 1e-8 (the issue's bounds; accelerations
#    carry the stiffness times the round-off of u, hence the wider one), and so do the
#    interface fields per pair id at every frame: its kinematic ones (slip, accumulated
#    slip, opening, status) to 1e-9, its stresses to 1e-8 like the accelerations (they are
#    the penalty times the round-off of the jumps; and the rigid block's motion comes from
#    its resultant, the small difference of the interface's and gravity's 1.4 MN/m, whose
#    round-off is some 1e3 times that of one node's force: 2.6e-9 measured on 2 ranks).
#  - The station block_base at (0, 30) lies on the interface: it must record the structure
#    side (the default of -station_side) on every rank count, and the report must say so.
#    On 2 and 3 ranks pairs must be cut by the partition (else the test proves less): METIS'
#    default 2-way partition of the graded mesh leaves the interface on one rank, so every run
#    takes -petscpartitioner_metis_seed 1, whose 2-way partition cuts 10 of the 13 pairs (the
#    3-way one all 13).
# The 3-rank run stops after 0.05 s of shaking: on the 2-core machine of make test its three
# ranks share two cores (3 s of the 1 m box scene took 83 s there, against 45 s on 1 rank and
# 30 s on 2; the graded mesh since 2026-11-29 takes about twice that), and the
# dynamic stage's rank independence (a force summed in another order) is the 2-rank run's
# check; the 3-way partition's geostatic solve, its cut pairs, report lines and geostatic
# stresses are checked as before.
set -eu -o pipefail
. tests/tools/lib.sh
IC="$PY tests/tools/contact_checks.py"
opts="-options_file config/scenes/default.yaml -petscpartitioner_metis_seed 1 -ts_max_time 3 -progress_interval 100000"
for n in 1 2 3; do
  time=""; [ $n = 3 ] && time="-ts_max_time 0.05"
  $MPIEXEC -n $n $SW $opts $time -output_dir "$WORK/np$n" > "$WORK/np$n.log"
  grep -E "geostatic stage|station block_base|pairs have" "$WORK/np$n.log"
  grep -q "geostatic stage: static solve .*every interface pair in stick" "$WORK/np$n.log"
  ratio=$(sed -n 's/.*unbalanced-force ratio \([0-9.e+-]*\);.*/\1/p' "$WORK/np$n.log")
  $PY -c "import sys; r = float('$ratio'); print(f'$n ranks: unbalanced-force ratio {r:.2e} after the static solve (bound 1e-9)'); sys.exit(0 if r <= 1e-9 else 1)"
  grep -q "station block_base at (0, 30) lies on interface base (split nodes): records the structure side (block)" "$WORK/np$n.log"
done
for n in 2 3; do
  cut=$(sed -n 's/.* \([0-9][0-9]*\) pairs have their two nodes on different ranks.*/\1/p' "$WORK/np$n.log")
  echo "$n ranks: $cut pairs cut by the partition (need > 0)"
  [ "$cut" -gt 0 ]
  [ $n = 3 ] && continue  # the geostatic stage only (above)
  $CHECK stations-equal "$WORK/np1" "$WORK/np$n" --names block_top,block_base,free_field,bedrock --tol 1e-9 --tol-a 1e-8
  $IC interface-equal "$WORK/np1" "$WORK/np$n" --name base --fields accumulated_slip,opening,slip,status --tol 1e-9
  $IC interface-equal "$WORK/np1" "$WORK/np$n" --name base --fields sigma_N,sigma_T --tol 1e-8
done
$PY - "$WORK" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
from frames import Frames
work = sys.argv[1]
def geostatic_state(d):
    f = Frames(f"{work}/{d}")
    xyz, cells, stress = f.geometry, f.topology, f.field("stress", 0)
    centroid = xyz[cells].mean(axis=1)
    order = np.lexsort((centroid[:, 1], centroid[:, 0]))
    return centroid[order], stress[order]
from contact_checks import interface_frames
c1, s1 = geostatic_state("np1")
n1 = interface_frames(f"{work}/np1", "base", "sigma_N")[1][0]
ok = True
for d in ("np2", "np3"):
    c, s = geostatic_state(d)
    assert np.allclose(c, c1, atol=1e-9), "cells differ"
    diff = np.max(np.abs(s - s1)) / np.max(np.abs(s1))
    print(f"geostatic stress, 1 vs {d[2]} ranks: largest difference {diff:.2e} of the peak (bound 1e-10)")
    ok &= diff <= 1e-10
    # The pairs' sigma_N of the first frame (per pair id), to 1e-10 of its peak.
    n = interface_frames(f"{work}/{d}", "base", "sigma_N")[1][0]
    diff = np.max(np.abs(n - n1)) / np.max(np.abs(n1))
    print(f"geostatic sigma_N of the pairs, 1 vs {d[2]} ranks: largest difference {diff:.2e} of the peak (bound 1e-10)")
    ok &= n.shape == n1.shape and diff <= 1e-10
sys.exit(0 if ok else 1)
PY
