# Hysteretic soil with constant-Q damping in the same region (issue 22: the small-strain
# damping D_min stays with constant Q, docs/hysteretic-soil.md): the model takes the region's
# unrelaxed moduli, and the memory is driven by the force of the soil's stress (K_U u less
# the relaxation force; medium/attenuation.hpp). The 1D column of $COLUMN with xi = 2 %:
# - small motion (1e-4 m/s, strains < 5e-7, below the elastic limit 1e-6): the hysteretic
#   column equals the damped linear one to 1e-6 of each quantity's peak (the issue's bound),
#   with the top 30 m hysteretic (the drive from the region's own K_U u) and with the whole
#   column hysteretic (the drive from the whole mesh's);
# - strong motion (0.1 m/s): the ledger closed (1e-9, as tests/cases/constant_q_energy.sh),
#   and both the mechanisms and the hysteresis took energy.
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
C="$COLUMN -material_soil_damping_ratio 0.02 -mesh_box_faces 1,400 -mesh_box_upper 1,100 -input_wave sv -constrain_components y
  -station_coordinates 0.5,100,0.5,85 -station_names top,layer"
H="-material_soil_model hysteretic -material_soil_backbone mkz -material_soil_reference_strain 1e-3"
L="-regions rock,soil -region_soil_box 0,1,70,100 -material_rock_rho 2000 -material_rock_vp 400 -material_rock_vs 200 -material_rock_damping_ratio 0.02"
# The five runs are independent (one rank each): two at a time (tests/tools/together.sh).
together $SW $C $L $H -energy_interval 1 -output_dir "$WORK/strong" > /dev/null
together $SW $C $L -input_amplitude 1e-4 -output_dir "$WORK/layer_linear" > /dev/null
together $SW $C $L $H -input_amplitude 1e-4 -output_dir "$WORK/layer_hysteretic" > /dev/null
together $SW $C -input_amplitude 1e-4 -output_dir "$WORK/whole_linear" > /dev/null
together $SW $C $H -input_amplitude 1e-4 -output_dir "$WORK/whole_hysteretic" > /dev/null
together_wait
$CHECK stations-equal "$WORK/layer_linear" "$WORK/layer_hysteretic" --names top,layer --tol 1e-6
$CHECK stations-equal "$WORK/whole_linear" "$WORK/whole_hysteretic" --names top,layer --tol 1e-6
$CHECK energy "$WORK/strong/energy.csv" --max-error 1e-9 --min-rows 2001
$PY - "$WORK/strong/energy.csv" <<'PY'
import sys
sys.path.insert(0, "python")
from slipwave.run_folder import read_csv
d = read_csv(sys.argv[1])
a, h, w = d["anelastic"][-1], d["hysteretic_dissipated"][-1], d["input_work"][-1]
print(f"strong: of the {w:.4e} J put in, the mechanisms took {a:.4e} J and the hysteresis {h:.4e} J")
sys.exit(0 if a > 0.01 * w and h > 0.01 * w else 1)
PY
