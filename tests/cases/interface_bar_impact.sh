# Two elastic bars meeting through a frictionless contact interface (1D: x motion only,
# plane strain with nu = 0, so the P speed is the bar speed c = sqrt(E/rho)).
# rho = 2000, E = 1e9: c = 707.107 m/s, Z = rho c = 1.41421e6 Pa s/m; 400 cells of h = 0.05 m
# over 20 m, one cell high (contact area A = 0.05 m^2, 2 pairs); auto penalty E/h = 2e10 Pa/m;
# default step (0.5 of the limit). Expected numbers, 1D wave theory (Graff, Wave Motion in
# Elastic Solids, sec. 2.4; impedance matching at the contact):
# A. Identical bars, L = 10 m, velocities +1 and -1 m/s (config/scenes/two_bar_impact.yaml).
#    The contact point has velocity v_c with Z (v1 - v_c) = Z (v_c - v2) (equal stresses on
#    both sides), so v_c = (v1 + v2)/2 = 0 and the stress is Z (v1 - v2)/2 = Z v_rel/2
#    = 1.41421e6 Pa. The compression waves reflect at the free ends as unloading waves and
#    return after 2L/c = 28.284 ms; the bars separate with swapped velocities (-1, +1 m/s).
# B. Unequal bars: L1 = 5 m at v0 = 2 m/s hits L2 = 15 m at rest. Same stress Z v0/2 =
#    1.41421e6 Pa (v_c = v0/2). The unloading wave returns to the contact after 2 L1/c =
#    14.142 ms, leaving bar 1 at rest and stress-free; bar 2's loaded end is then relieved
#    and moves at v0, away from bar 1: separation at 2 L1/c. Bar 1 stays at rest (its mid
#    station: v = 0); bar 2 carries all the momentum as a pulse 2 L1 long of particle velocity
#    v0/2 (its mid station at x = 12.5 m: v = v0/2 from 7.5/c + front spread to 7.5/c + 2L1/c,
#    then at rest with u = (v0/2)(2 L1/c) = v0 L1/c = 14.142 mm until the reflection from its
#    free end returns at 22.5/c = 31.8 ms).
# Tolerances. Contact duration: central differences spread a step front over a width of about
# (h^2 D)^(1/3) after a path D (the Airy front of the discrete wave equation): D = 2L gives
# 0.37 m, i.e. 1.8 % of the 20 m path in A; D = 2 L1 gives 0.29 m, 2.9 % of 10 m in B
# (measured 1.5 %, converging as h shrinks: 2.1, 1.5, 1.1, 0.4 % for h = 0.1 ... 0.0125).
# The same spread bounds the extra impulse of B, so bar 1's residual velocity and bar 2's
# displacement are held to 3 % of v0 and of v0 L1/c. Contact stress: the mean over the middle
# half of the contact of |sigma_N| at every step, within 1 % (the ringing behind the front
# averages out; the ledger's interface_stored, A sigma_N^2 / 2E, gives sigma_N at every step and
# is checked against the interface output's sigma_N at each output frame). Exit velocities of A:
# mean over 35-60 ms at the mid stations, 2 % (ringing of the unloading front). Energy: kinetic +
# strain + interface stored + dissipated never above 1.01 x the initial kinetic energy (issue
# bound), and the ledger's balance at round-off (1e-9), with the contact dashpots' work booked.
# The runs use the default contact damping (0.1 of each pair's critical damping). Measured
# against no damping: A's duration 0.61 % from 2L/c (0.02 % without) and exit velocities 0.66 %
# (0.55 %); the stress ripple 2.3e-4 (0.48) and no re-contact (one); B's contact ends at 14.50 ms
# with no re-contact, where without damping it ends at 14.35 ms and re-contacts until 14.51 ms
# (the ringing of the unloading front is merged into the contact, hence 2.5 % against 1.5 %).
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
IC="$PY tests/tools/contact_checks.py"
c=$($PY -c "import math; print(math.sqrt(1e9/2000))")
Z=$($PY -c "print(2000*$c)")
# -energy_interval 1: the contact phase is read from energy.csv at every step. No volume
# fields (-output_fields 0): the checks read energy.csv, the stations and the interface frames.
scene="-options_file config/scenes/two_bar_impact.yaml -output_fields 0 -energy_interval 1"
# The two runs are independent (one rank each): side by side (tests/tools/together.sh).
together $SW $scene -output_dir "$WORK/a" > "$WORK/a.log"
together $SW $scene -region_right_bar_box 5,20,0,0.05 -initial_velocity_left_bar 2,0 -initial_velocity_right_bar 0,0 -station_coordinates 2.5,0,12.5,0 -output_dir "$WORK/b" > "$WORK/b.log"
together_wait

echo "== A: identical bars, +1 and -1 m/s"
cat "$WORK/a.log"
$IC bar-contact "$WORK/a" --name gap --E 2e10 --area 0.05 --duration "$($PY -c "print(2*10/$c)")" --duration-tol 0.018 --stress "$($PY -c "print($Z*2/2)")" --stress-tol 0.01
$IC station-window "$WORK/a" --station left_mid --column v_x --t0 0.035 --t1 0.06 --expected -1 --tol 0.02
$IC station-window "$WORK/a" --station right_mid --column v_x --t0 0.035 --t1 0.06 --expected 1 --tol 0.02
$IC open-traction "$WORK/a" --name gap --min-open 2
$IC energy-growth "$WORK/a" --max-growth 0.01 --max-balance 1e-9
# At the interfaces' default step (0.5 of the limit) the report says nothing of the switching.
if grep -q "open/closed switches" "$WORK/a.log"; then echo "FAIL: a switching warning at the default step"; exit 1; fi

echo "== B: L1 = 5 m at 2 m/s onto L2 = 15 m at rest"
cat "$WORK/b.log"
t_sep=$($PY -c "print(2*5/$c)")
$IC bar-contact "$WORK/b" --name gap --E 2e10 --area 0.05 --duration "$t_sep" --duration-tol 0.029 --stress "$($PY -c "print($Z*2/2)")" --stress-tol 0.01
$IC station-window "$WORK/b" --station left_mid --column v_x --t0 0.02 --t1 0.06 --expected 0 --tol 0.06
# bar 2's pulse at its mid station: inside it (front spread 0.29 m = 0.4 ms cut from each end)
$IC station-window "$WORK/b" --station right_mid --column v_x --t0 "$($PY -c "print(7.5/$c + 0.0015)")" --t1 "$($PY -c "print(7.5/$c + $t_sep - 0.0015)")" --expected 1 --tol 0.02
# after it, before the reflection returns: at rest, displaced by v0 L1 / c
$IC station-window "$WORK/b" --station right_mid --column u_x --t0 "$($PY -c "print(7.5/$c + $t_sep + 0.0015)")" --t1 "$($PY -c "print(22.5/$c - 0.0015)")" --expected "$($PY -c "print(2*5/$c)")" --tol "$($PY -c "print(0.03*2*5/$c)")"
$IC energy-growth "$WORK/b" --max-growth 0.01 --max-balance 1e-9

echo "== C: A at 0.9 of the stable limit: the report counts the open/closed switches and warns"
# A's two pairs start closed and open once each at the separation (no re-contact): 2 switches.
# The count is checkpointed: a run stopped after the separation (step 1000 of 1588, t = 37.8 ms
# against 2L/c = 28.3 ms) and restarted from there reports the same 2 at its end.
line="warning: 2 open/closed switches of pairs on interface gap with the step at 0.90 of the stable limit"
$SW $scene -time_step_safety 0.9 -output_dir "$WORK/c" > "$WORK/c.log"
grep "open/closed switches" "$WORK/c.log"
grep -q "$line" "$WORK/c.log"
$SW $scene -time_step_safety 0.9 -ts_max_steps 1000 -checkpoint_interval 1000 -output_dir "$WORK/d" > "$WORK/d.log"
$SW $scene -time_step_safety 0.9 -restart "$WORK/d/checkpoint.bin" -output_dir "$WORK/d" > "$WORK/d2.log"
grep -q "$line" "$WORK/d2.log"
echo "restarted after the separation: the same 2 switches"
