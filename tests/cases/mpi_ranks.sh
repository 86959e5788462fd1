# Rank independence: the default scene (two regions, damping, absorbing input, rollers),
# shortened to 2 s, on 1 and 2 ranks (METIS partition). Each node's force is the same sum in
# a different order, so station records must agree to round-off: 1e-10 of the peak of each quantity (u, v, a)
# (issue 2). The energy ledgers must agree to the same 1e-10 of the largest energy.
# SEM_DEGREE=p runs it with ceil(N / p) elements of degree p per direction for 134 x 64 cells
# (tests/cases/sem_ranks.sh; 64 rows of 1.25 m, 16 elements of 5 m at p = 4: the soil box's
# face y = 0 on a grid line at both, src/meshing/region_box_fit.hpp).
set -eu
. tests/tools/lib.sh
opts="-options_file config/scenes/site_response_2d.yaml -ts_max_time 2 -output_fields 0 -progress_interval 100
 -element_degree $DEGREE -mesh_box_faces $(elements 134),$(elements 64)"
$SW $opts -output_dir "$WORK/np1"
$MPIEXEC -n 2 $SW $opts -output_dir "$WORK/np2"
$CHECK stations-equal "$WORK/np1" "$WORK/np2" --names surface,layer_base,bedrock_base --tol 1e-10
$CHECK energy-equal "$WORK/np1/energy.csv" "$WORK/np2/energy.csv" --tol 1e-10
