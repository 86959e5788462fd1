# 1D SV column, 100 m, absorbing base, Ricker incident wave, 20 points per S wavelength at
# the Ricker top frequency (2.7638 f0 = 13.8 Hz, where the spectrum falls below 1% of its peak):
# h = 200/13.8/20 = 0.72 m -> 139 cells. The vertical displacement is held everywhere, which
# makes the column exactly 1D. Bounds from issue 2: L2 error <= 1.5 %, late reflection <= 1e-3.
# SEM_DEGREE=p runs it with ceil(139 / p) elements of degree p (tests/cases/sem_columns.sh).
set -eu
. tests/tools/lib.sh
$SW $COLUMN -mesh_box_faces 1,$(elements 139) -element_degree $DEGREE -mesh_box_upper 1,100 -input_wave sv -constrain_components y \
  -station_coordinates 0.5,100 -station_names top -output_dir "$WORK"
$CHECK column "$WORK/stations/top.csv" --component x --height 100 --speed 200 --amplitude 0.1 --f0 5 --t0 0.24 --l2-max 0.015 --late-max 1e-3
