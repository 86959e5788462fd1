# The run-folder reader python/slipwave (docs/python.md) on a run made here: a 20 x 6 box of
# 1 m cells with a stiff block tied to the soil by interface 'base', an SV Ricker from the
# absorbing bottom, a fixed step, two stations on mesh nodes (one in the soil, one in the
# block), on 2 ranks. python/tests/test_run_folder.py then checks every reader against what
# the options and the writers fix: column names and units, station times at every step,
# frame count and times, the energy balance against its terms, run_info.json's fields, the
# stations against the volume frames at their nodes, the interface's pairs and fields.
set -eu
. tests/tools/lib.sh
export SLIPWAVE_RUN="$WORK/run" SLIPWAVE_TS_DT=1e-4 SLIPWAVE_OUTPUT_INTERVAL=0.02 SLIPWAVE_MAX_TIME=0.1 SLIPWAVE_ENERGY_INTERVAL=7
# name:x:y of each station, given to slipwave as -station_names and -station_coordinates.
export SLIPWAVE_STATIONS="soil_node:3:2,block_node:10:5"
names=$(tr ',' '\n' <<<"$SLIPWAVE_STATIONS" | cut -d: -f1 | paste -sd,)
coordinates=$(tr ',' '\n' <<<"$SLIPWAVE_STATIONS" | cut -d: -f2,3 | tr ':' ',' | paste -sd,)
$MPIEXEC -n 2 $SW -regions soil,block -material_soil_rho 2000 -material_soil_vp 600 -material_soil_vs 300 \
  -material_block_rho 2400 -material_block_vp 3000 -material_block_vs 1800 -interfaces base -interface_base_regions soil,block \
  -mesh_box_faces 20,6 -mesh_box_upper 20,6 -region_block_box 8,12,4,6 \
  -bc_bottom_type absorbing -input_wave sv -input_stf ricker -input_f0 10 -input_t0 0.03 -input_amplitude 1 \
  -ts_dt $SLIPWAVE_TS_DT -ts_max_time $SLIPWAVE_MAX_TIME -output_interval $SLIPWAVE_OUTPUT_INTERVAL -energy_interval $SLIPWAVE_ENERGY_INTERVAL \
  -station_coordinates "$coordinates" -station_names "$names" -progress_interval 1000 -output_dir "$SLIPWAVE_RUN" > "$WORK/run.log"
$PY python/tests/test_run_folder.py
