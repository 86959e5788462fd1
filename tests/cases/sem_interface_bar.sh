# The two-bar impact of interface_bar_impact.sh (same expected numbers, same bounds: 1D wave
# theory, Graff sec. 2.4) at element degree 4 with 4x fewer elements along the bars (100
# elements of 0.2 m, one element 0.2 m high: contact area 0.2 m^2, 5 GLL node pairs with the
# GLL face weights). The auto penalty at degree p is (lambda + 2 mu)(p^2 + p + 1)/(3 h_e)
# = 1e9 x 7/0.2 = 3.5e10 Pa/m (the end-node stiffness of a GLL element, numerics/gll_basis.hpp),
# so its stable-step cost matches degree 1's (-30.4 % here, -27.3 % at p = 1). Case A also on
# 2 ranks: the stations must agree with 1 rank to 1e-10 of the peak velocity.
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
IC="$PY tests/tools/contact_checks.py"
c=$($PY -c "import math; print(math.sqrt(1e9/2000))")
Z=$($PY -c "print(2000*$c)")
# No volume fields (-output_fields 0): the checks read energy.csv, the stations and the
# interface frames.
scene="-options_file config/scenes/two_bar_impact.yaml -mesh_box_faces 100,1 -mesh_box_upper 20,0.2 -element_degree 4 -output_fields 0 -energy_interval 1"
# The 1-rank runs of A and B are independent: side by side (tests/tools/together.sh).
together $SW $scene -region_right_bar_box 10,20,0,0.2 -output_dir "$WORK/a" > "$WORK/a.log"
together $SW $scene -region_right_bar_box 5,20,0,0.2 -initial_velocity_left_bar 2,0 -initial_velocity_right_bar 0,0 -station_coordinates 2.5,0,12.5,0 -output_dir "$WORK/b" > /dev/null
together_wait

echo "== A: identical bars, +1 and -1 m/s"
grep "interface gap: E = 3.5e+10 Pa/m (auto)" "$WORK/a.log"
$IC bar-contact "$WORK/a" --name gap --E 3.5e10 --area 0.2 --duration "$($PY -c "print(2*10/$c)")" --duration-tol 0.018 --stress "$($PY -c "print($Z*2/2)")" --stress-tol 0.01
$IC station-window "$WORK/a" --station left_mid --column v_x --t0 0.035 --t1 0.06 --expected -1 --tol 0.02
$IC station-window "$WORK/a" --station right_mid --column v_x --t0 0.035 --t1 0.06 --expected 1 --tol 0.02
$IC open-traction "$WORK/a" --name gap --min-open 2
$IC energy-growth "$WORK/a" --max-growth 0.01 --max-balance 1e-9
# (Its stations only are compared: no interface frames, -output_interval = the run's length.)
$MPIEXEC -n 2 $SW $scene -region_right_bar_box 10,20,0,0.2 -output_fields 0 -output_interval 0.06 -output_dir "$WORK/a2" > /dev/null
$PY - "$WORK" <<'PY'
import sys
import numpy as np
w = sys.argv[1]
worst = 0.0
for s in ("left_mid", "right_mid"):
    one = np.genfromtxt(f"{w}/a/stations/{s}.csv", delimiter=",", names=True)
    two = np.genfromtxt(f"{w}/a2/stations/{s}.csv", delimiter=",", names=True)
    for col in one.dtype.names:
        worst = max(worst, float(np.abs(one[col] - two[col]).max()))
print(f"1 vs 2 ranks: largest station difference {worst:.2e} (bound 1e-10 of the 1 m/s peak)")
sys.exit(0 if worst <= 1e-10 else 1)
PY

echo "== B: L1 = 5 m at 2 m/s onto L2 = 15 m at rest"
t_sep=$($PY -c "print(2*5/$c)")
$IC bar-contact "$WORK/b" --name gap --E 3.5e10 --area 0.2 --duration "$t_sep" --duration-tol 0.029 --stress "$($PY -c "print($Z*2/2)")" --stress-tol 0.01
$IC station-window "$WORK/b" --station left_mid --column v_x --t0 0.02 --t1 0.06 --expected 0 --tol 0.06
$IC station-window "$WORK/b" --station right_mid --column v_x --t0 "$($PY -c "print(7.5/$c + 0.0015)")" --t1 "$($PY -c "print(7.5/$c + $t_sep - 0.0015)")" --expected 1 --tol 0.02
$IC station-window "$WORK/b" --station right_mid --column u_x --t0 "$($PY -c "print(7.5/$c + $t_sep + 0.0015)")" --t1 "$($PY -c "print(22.5/$c - 0.0015)")" --expected "$($PY -c "print(2*5/$c)")" --tol "$($PY -c "print(0.03*2*5/$c)")"
$IC energy-growth "$WORK/b" --max-growth 0.01 --max-balance 1e-9
