# Energy budget with an absorbing base: the SV column. For an incident pulse v_in through a
# base of area A with the Lysmer dashpot, the input traction 2 rho c v_in does the work
#   W_in = A * 2 rho c ∫ v_in (v_in + v_out) dt = 2 rho c A ∫ v_in^2 dt
# (v_out, the surface reflection, does not overlap v_in in time at the base for H = 100 m and
# a 5 Hz Ricker: they are 2H/c = 1 s apart), and ∫ v_in^2 dt of a Ricker with peak amplitude a
# is a^2 * 3 / (4 sqrt(2 pi) f0) (closed form of ∫ (1-2x)^2 e^{-2x}, x = (pi f0 t)^2).
# With rho = 2000, c = 200, A = 1 m^2 (width 1 m, unit thickness), a = 0.1, f0 = 5:
#   W_in = 2*2000*200*0.01*3/(4*sqrt(2 pi)*5) = 478.7307 J.
# Bounds: the booked input within 1 % of it (issue 2: budget closes to 1 %), the balance
# at round-off (1e-9), and after the wave has left (t = 2 s) at most 1e-3 of the peak
# energy remains (no trapped reflection).
set -eu
. tests/tools/lib.sh
$SW $COLUMN -mesh_box_faces 1,139 -mesh_box_upper 1,100 -input_wave sv -constrain_components y -output_dir "$WORK"
w_in=$($PY -c "import math; print(2*2000*200*0.01*3/(4*math.sqrt(2*math.pi)*5))")
$CHECK energy "$WORK/energy.csv" --max-error 1e-9 --input-work "$w_in" --input-tol 0.01 --final-fraction 1e-3
