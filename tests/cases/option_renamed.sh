# An option renamed for the prefix scheme (-stations_file is now -station_file) still works
# under its old name for one release, and the run says so once.
#  1. On 2 ranks, the same 1D column (lib.sh) with its stations given by -stations_file and by
#     -station_file writes byte-identical station records: the old name reads the same file.
#  2. The old-name run prints "-stations_file is renamed -station_file; ..." exactly once
#     (not once per rank); the new-name run never prints it.
#  3. Both names together stop the run (tests/errors/cases.txt, both_station_file_names).
set -eu -o pipefail
. tests/tools/lib.sh
printf 'name,x,y\nsurface,0.5,100\nmiddle,0.5,50\n' > "$WORK/stations.csv"
opts="$COLUMN -mesh_box_faces 1,100 -mesh_box_upper 1,100 -constrain_components y -input_wave sv -ts_max_time 0.3"
$MPIEXEC -n 2 $SW $opts -stations_file "$WORK/stations.csv" -output_dir "$WORK/old" > "$WORK/old.log"
$MPIEXEC -n 2 $SW $opts -station_file "$WORK/stations.csv" -output_dir "$WORK/new" > "$WORK/new.log"
for s in surface middle; do cmp "$WORK/old/stations/$s.csv" "$WORK/new/stations/$s.csv"; done
n_old=$(grep -c "^-stations_file is renamed -station_file; the old name is accepted until the next release$" "$WORK/old.log" || true)
n_new=$(grep -c "is renamed" "$WORK/new.log" || true)
echo "rename notices: old name $n_old, new name $n_new"
[ "$n_old" = 1 ] && [ "$n_new" = 0 ]
