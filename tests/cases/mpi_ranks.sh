# Rank independence: the default scene (two regions, damping, absorbing input, rollers),
# shortened to 2 s, on 1 and 2 ranks (METIS partition). Each node's force is the same sum in
# a different order, so station records must agree to round-off: 1e-10 of the peak of each quantity (u, v, a)
# (issue 2). The energy ledgers must agree to the same 1e-10 of the largest energy.
# SEM_DEGREE=p runs it with ceil(N / p) elements of degree p per direction for the scene's
# 134 x 54 cells (tests/cases/sem_ranks.sh).
set -eu
. tests/tools/lib.sh
opts="-options_file config/scenes/site_response_2d.yaml -ts_max_time 2 -output_fields 0 -progress_interval 100
 -element_degree $DEGREE -mesh_box_faces $(elements 134),$(elements 54)"
$SW $opts -output_dir "$WORK/np1"
$MPIEXEC -n 2 $SW $opts -output_dir "$WORK/np2"
$CHECK stations-equal "$WORK/np1" "$WORK/np2" --names surface,layer_base,bedrock_base --tol 1e-10
$CHECK energy-equal "$WORK/np1/energy.csv" "$WORK/np2/energy.csv" --tol 1e-10
