# 1D P column, as the SV column but with the horizontal displacement held and the wave
# polarised vertically, travelling at vp = 400 m/s: 20 points per P wavelength at 13.8 Hz
# gives h = 400/13.8/20 = 1.45 m -> 69 cells. Bounds from issue 2: L2 <= 1.5 %, late <= 1e-3.
# SEM_DEGREE=p runs it with ceil(69 / p) elements of degree p (tests/cases/sem_columns.sh).
set -eu
. tests/tools/lib.sh
$SW $COLUMN -mesh_box_faces 1,$(elements 69) -element_degree $DEGREE -mesh_box_upper 1,100 -input_wave p -constrain_components x -ts_max_time 1.2 \
  -station_coordinates 0.5,100 -station_names top -output_dir "$WORK"
$CHECK column "$WORK/stations/top.csv" --component y --height 100 --speed 400 --amplitude 0.1 --f0 5 --t0 0.24 --l2-max 0.015 --late-max 1e-3
