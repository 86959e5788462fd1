#!/usr/bin/env bash
# Free-field lateral sides on saturated soil under a vertically incident P wave: the free-field
# column carries the main mesh's u-p pore pressure (physics/column_pore_pressure.hpp), so a
# scatterer-free site with free-field sides must move as the exact 1D column (sides tied to
# each other in 2D, rollers in 3D): vertical velocity and excess pore pressure at every
# station equal to 1e-10 of their peaks, horizontal velocity zero to 1e-12 m/s (against peaks
# of 0.07-1 m/s: the bounds of saturated_free_field.sh, the SV case). Measured 1e-14 to 1e-12.
#  1. A 50 m saturated column on an absorbing base (rho 2000, vp 400, n 0.4, drained top), 4 m
#     wide, under a 10 Hz Ricker P pulse (0.1 m/s): k = 0.04 m/s, where Biot flow matters most
#     at 10 Hz (as saturated_up_column.sh: the diffusion is sub-cycled, 25 sub-steps), and
#     k = 0 (undrained), and k = 0.04 m/s with constant Q (5 %) and Rayleigh damping (2 % at
#     2 and 20 Hz: the column's stiffness damping and memory act on the skeleton, as the
#     cells' do), and k = 0.04 m/s with a Darcy inflow of 1e-6 m/s through the base (it
#     moves the stations by 1e-5 of their peaks: the column takes it as its base node's
#     inflow over storage); the free-field run on 2 ranks as on 1 to 1e-10; the energy balance
#     closes (1e-12); and the surface displacement and p at 25 m and 40 m depth agree with the
#     semi-analytic u-p solution with the same absorbing base (tests/tools/up_column.py --base
#     absorbing) within saturated_up_column.sh's 3 % (measured 0.6-1.4 %: the sub-cycled
#     split's error), and within 3e-3 with the step at the diffusion limit
#     (-pore_pressure_subcycle false; measured 2-5e-4, saturated_up_column.sh's unsplit errors
#     are 3-6e-4), which checks the solution's absorbing base itself.
#  2. The same column on hexahedra with free-field sides on all four sides against rollers
#     (-constrain_components x,y).
#  3. The saturated site of config/scenes/saturated_site.yaml (rock below 30 m of saturated
#     sand, k = 1e-4 m/s) under its P wave: without gravity, where the default cavitation limit
#     holds p at -100 kPa at up to 132 nodes at once; and with gravity, the water table at the
#     surface and the geostatic stage (free-field sides: static solve; tied sides: relaxation to
#     an unbalanced-force ratio of 1e-13, so its residual drift stays at round-off) under a
#     0.5 m/s pulse, where cavities open at up to 143 nodes against the limit less p_h.
#  4. The free-field column run of 1 stopped halfway with a checkpoint and restarted: energy.csv
#     and the station files byte for byte those of the uninterrupted run (the columns' pore
#     pressure state is in the checkpoint, format version 14).
set -eu
. tests/tools/lib.sh
TIED="-bc_left_type tied -bc_left_tie_with right -bc_right_type tied -bc_right_tie_with left"
FREE="-bc_left_type freefield -bc_right_type freefield"
# The linear u-p model that the closed form solves: no cavitation limit (its tension phases
# reach beyond -100 kPa).
COL="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4
 -material_soil_hydraulic_conductivity 0.04 -fluid_cavitation_pressure none -bc_top_fluid drained -bc_bottom_type absorbing -input_wave p -input_boundary bottom
 -input_stf ricker -input_f0 10 -input_t0 0.12 -input_amplitude 0.1 -ts_max_time 0.4 -output_fields 0 -progress_interval 100000"
# SEM_DEGREE=p (tests/cases/sem_saturated.sh): elements of degree p (the column's pore pressure
# at the GLL nodes, as the main mesh's), about the same node spacing; the site's elements 5 m
# tall as in saturated_free_field.sh.
COL="$COL -element_degree $DEGREE"
COL2="$COL -mesh_box_faces $(elements 4),$(elements 50) -mesh_box_upper 4,50 -station_coordinates 2,50,2,25,2,10,0,25 -station_names top,d25,d40,side25"
COL3="$COL -mesh_dim 3 -mesh_box_faces $(elements 2),$(elements 2),$(elements 50) -mesh_box_upper 2,2,50 -station_coordinates 1,1,50,1,1,25,1,1,10,0,0,25 -station_names top,d25,d40,side25"
$SW $COL2 $TIED -output_dir "$WORK/tied" > "$WORK/tied.log"
$SW $COL2 $FREE -output_dir "$WORK/free" > "$WORK/free.log"
$MPIEXEC -n 2 $SW $COL2 $FREE -output_dir "$WORK/free2" > "$WORK/free2.log"
$SW $COL2 $FREE -pore_pressure_subcycle false -output_dir "$WORK/unsplit" > "$WORK/unsplit.log"
$SW $COL2 $TIED -material_soil_hydraulic_conductivity 0 -output_dir "$WORK/tied_k0" > "$WORK/tied_k0.log"
$SW $COL2 $FREE -material_soil_hydraulic_conductivity 0 -output_dir "$WORK/free_k0" > "$WORK/free_k0.log"
DAMPED="-material_soil_damping_ratio 0.05 -damping_ratio 0.02 -damping_frequencies 2,20"
$SW $COL2 $TIED $DAMPED -output_dir "$WORK/tied_q" > "$WORK/tied_q.log"
$SW $COL2 $FREE $DAMPED -output_dir "$WORK/free_q" > "$WORK/free_q.log"
INFLOW="-bc_bottom_fluid flux -bc_bottom_fluid_flux 1e-6"
$SW $COL2 $TIED $INFLOW -output_dir "$WORK/tied_in" > "$WORK/tied_in.log"
$SW $COL2 $FREE $INFLOW -output_dir "$WORK/free_in" > "$WORK/free_in.log"
$SW $COL3 -constrain_components x,y -output_dir "$WORK/rollers3" > "$WORK/rollers3.log"
$SW $COL3 $FREE -bc_front_type freefield -bc_back_type freefield -output_dir "$WORK/free3" > "$WORK/free3.log"
grep -E "sub-cycled" "$WORK/free.log"
half=$(( $(tail -1 "$WORK/free/energy.csv" | cut -d, -f1) / 2 ))
$SW $COL2 $FREE -energy_interval 1 -output_dir "$WORK/whole" > "$WORK/whole.log"
$SW $COL2 $FREE -energy_interval 1 -ts_max_steps $half -checkpoint_interval $half -output_dir "$WORK/first" > "$WORK/first.log"
cp -r "$WORK/first" "$WORK/resumed"
$SW $COL2 $FREE -energy_interval 1 -restart "$WORK/resumed/checkpoint.bin" -output_dir "$WORK/resumed" | grep -E "^restart"
cmp "$WORK/resumed/energy.csv" "$WORK/whole/energy.csv"
for f in "$WORK"/whole/stations/*.csv; do cmp "$f" "$WORK/resumed/stations/$(basename "$f")"; done
echo "restart at step $half: energy.csv and the station files identical"
grep -v -E "^(gravity|water_table|geostatic_stage):" config/scenes/saturated_site.yaml > "$WORK/site_nogravity.yaml"
grep -v -E "tie_with|_type: tied" "$WORK/site_nogravity.yaml" > "$WORK/site_nogravity_ff.yaml"
grep -v -E "tie_with|_type: tied" config/scenes/saturated_site.yaml > "$WORK/site_ff.yaml"
SITE="-element_degree $DEGREE -mesh_box_faces $(elements 10),$([ "$DEGREE" = 1 ] && echo 40 || echo 16) -input_wave p -ts_max_time 2 -output_fields 0 -progress_interval 100000"
$SW -options_file "$WORK/site_nogravity.yaml" $SITE -output_dir "$WORK/site_tied" > "$WORK/site_tied.log"
$SW -options_file "$WORK/site_nogravity_ff.yaml" $SITE $FREE -output_dir "$WORK/site_free" > "$WORK/site_free.log"
$SW -options_file config/scenes/saturated_site.yaml $SITE -input_amplitude 0.5 -geostatic_tolerance 1e-13 -geostatic_max_steps 100000 -output_dir "$WORK/wet_tied" \
  > "$WORK/wet_tied.log"
$SW -options_file "$WORK/site_ff.yaml" $SITE -input_amplitude 0.5 $FREE -output_dir "$WORK/wet_free" > "$WORK/wet_free.log"
grep -E "^geostatic|^cavitation" "$WORK/site_free.log" "$WORK/wet_tied.log" "$WORK/wet_free.log" | sed 's/; largest cavity.*//'
for run in free free2 free_k0 free_q free_in free3 site_free wet_free; do $CHECK energy "$WORK/$run/energy.csv" --max-error 1e-12; done
$CHECK stations-equal "$WORK/free" "$WORK/free2" --names top,d25,d40,side25 --tol 1e-10
UP="--stations top,d25,d40 --depths 0,25,40 --height 50 --rho 2000 --vp 400 --porosity 0.4 --hydraulic-conductivity 0.04 --f0 10 --t0 0.12 --amplitude 0.1 --t-end 0.4 --base absorbing"
$PY tests/tools/up_column.py compare "$WORK/free" $UP
$PY tests/tools/up_column.py compare "$WORK/unsplit" $UP --tol 3e-3
$PY - "$WORK" <<'PY'
import sys
import numpy as np
work = sys.argv[1]
ok = True
for ref, run, names in (("tied", "free", "top,d25,d40,side25"), ("tied_k0", "free_k0", "top,d25,d40,side25"), ("tied_q", "free_q", "top,d25,d40,side25"),
                        ("tied_in", "free_in", "top,d25,d40,side25"),                        ("rollers3", "free3", "top,d25,d40,side25"),
                        ("site_tied", "site_free", "surface,layer_mid,layer_base,bedrock_base"), ("wet_tied", "wet_free", "surface,layer_mid,layer_base,bedrock_base")):
    worst_v = worst_p = horizontal = 0.0
    for s in names.split(","):
        a = np.genfromtxt(f"{work}/{ref}/stations/{s}.csv", delimiter=",", names=True)
        b = np.genfromtxt(f"{work}/{run}/stations/{s}.csv", delimiter=",", names=True)
        vz = "v_z" if "v_z" in a.dtype.names else "v_y"
        worst_v = max(worst_v, np.abs(a[vz] - b[vz]).max() / np.abs(a[vz]).max())
        if np.abs(a["p_excess"]).max() > 0:  # the drained surface and the dry rock hold none
            worst_p = max(worst_p, np.abs(a["p_excess"] - b["p_excess"]).max() / np.abs(a["p_excess"]).max())
        horizontal = max(horizontal, max(np.abs(b[c]).max() for c in ("v_x", "v_y") if c != vz))
    good = worst_v <= 1e-10 and worst_p <= 1e-10 and horizontal <= 1e-12
    ok &= good
    print(f"{run} vs {ref}: vertical velocity {worst_v:.1e} of its peak, excess p {worst_p:.1e} of its peak (bound 1e-10); horizontal velocity {horizontal:.1e} m/s "
          f"(bound 1e-12)" + ("" if good else "  FAILED"))
sys.exit(0 if ok else 1)
PY
