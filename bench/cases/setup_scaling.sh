# Set-up cost of a 3D box (BENCH_SETUP_3D^3 hexahedra, default 64; BENCH_SETUP_DEGREE p,
# default 1: that many elements of degree p, p^3 GLL sub-cells each) through the executable
# (-dry_run: everything up to the first step), serial build (-mesh_build serial: the whole mesh
# built, labelled and partitioned on rank 0) against the distributed build (-mesh_build
# auto: every rank builds its part, partitioned as a coarse box, meshing/box_lattice.hpp), on 1
# and 2 ranks (BENCH_SETUP_RANKS, default "1 2"): set-up wall time, of it the mesh, and the peak
# resident memory per rank (ru_maxrss: rank 0's, the average and the largest) from the run
# report's "set-up:" line (-report_verbose). Issue 11's target: 128^3 in <= 10 s on 16 ranks with rank 0's peak
# <= 2x the average. The same for a Gmsh file of (N/4)^3 hexahedra refined twice (-mesh_refine 2,
# below). Rows go to $BENCH_CSV.
set -u
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
PY=/usr/bin/python3
N=${BENCH_SETUP_3D:-64}
P=${BENCH_SETUP_DEGREE:-1}
RANKS=${BENCH_SETUP_RANKS:-"1 2"}
MPIEXEC="mpiexec --oversubscribe"
[ "$(id -u)" = 0 ] && MPIEXEC="$MPIEXEC --allow-run-as-root"
WORK="$BUILD/bench/work/setup_scaling${BENCH_SETUP_DEGREE:+_p$P}"
mkdir -p "$WORK"
BOX="-mesh_dim 3 -element_degree $P -mesh_box_faces $N,$N,$N -mesh_box_upper 100,100,100 -regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200
 -bc_bottom_type absorbing -input_wave sv -input_boundary bottom -input_stf ricker -input_f0 5 -input_t0 0.24 -input_amplitude 0.1 -output_fields 0 -dry_run -report_verbose"
# The Gmsh case (-mesh_refine, meshing/mesh_refinement.hpp): the same cube as a coarse file of
# (N/4)^3 hexahedra (transfinite, so N must be a multiple of 4) refined twice to N^3, read
# and refined on rank 0 (serial) or refined on the distributed mesh (auto).
command -v gmsh > /dev/null || { echo "gmsh is not installed"; exit 1; }
cat > "$WORK/cube.geo" <<GEO
n = $N / 4;
Point(1) = {0, 0, 0}; Point(2) = {100, 0, 0}; Point(3) = {100, 100, 0}; Point(4) = {0, 100, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};
Extrude {0, 0, 100} { Surface{1}; Layers{n}; Recombine; }
Physical Surface("bottom") = {1};
Physical Volume("soil") = {1};
GEO
gmsh -3 "$WORK/cube.geo" -format msh41 -o "$WORK/cube.msh" > "$WORK/cube.gmsh.log" 2>&1 || { cat "$WORK/cube.gmsh.log"; exit 1; }
GMSH="${BOX/-mesh_box_faces $N,$N,$N -mesh_box_upper 100,100,100/-mesh_file $WORK/cube.msh -mesh_refine 2}"
logs=()
for n in $RANKS; do
  for build in serial auto; do
    $MPIEXEC -n "$n" "$SW" $BOX -mesh_build $build -output_dir "$WORK/${build}_np$n" > "$WORK/${build}_np$n.log" 2>&1 || echo "run $build np$n failed"
    logs+=("box $build np$n $WORK/${build}_np$n.log")
    $MPIEXEC -n "$n" "$SW" $GMSH -mesh_build $build -output_dir "$WORK/gmsh_${build}_np$n" > "$WORK/gmsh_${build}_np$n.log" 2>&1 || echo "run gmsh $build np$n failed"
    logs+=("gmsh $build np$n $WORK/gmsh_${build}_np$n.log")
  done
done
$PY - "${BENCH_CSV:-}" "$N" "$P" "${logs[@]}" <<'PY'
import re, sys
csv, n, p = sys.argv[1], sys.argv[2], sys.argv[3]
rows = []
for entry in sys.argv[4:]:
    kind, build, ranks, log = entry.split()
    text = open(log).read()
    m = re.search(r"set-up: ([0-9.]+) s wall \(mesh ([0-9.]+) s\); peak memory per rank ([0-9.]+) / ([0-9.]+) / ([0-9.]+) MB .*rank 0 ([0-9.]+) MB", text)
    if not m:
        print(f"{build} {ranks}: no set-up line in {log}")
        continue
    setup, mesh, low, avg, high, root = map(float, m.groups())
    how = "distributed" if "built distributed" in text else "serial"
    case = f"3d_{n}^3{'_p' + p if p != '1' else ''}_{'gmsh_' if kind == 'gmsh' else ''}{how}_{ranks}"
    print(f"{case:36s} set-up {setup:7.2f} s (mesh {mesh:6.2f} s), peak memory rank 0 {root:7.1f} MB, avg {avg:7.1f} MB, max {high:7.1f} MB, rank 0 / avg {root / avg:.2f}")
    rows += [(case, "setup_wall", setup, "s"), (case, "mesh_wall", mesh, "s"), (case, "rank0_peak_rss", root, "MB"), (case, "avg_peak_rss", avg, "MB"),
             (case, "max_peak_rss", high, "MB")]
if csv:
    with open(csv, "a") as f:
        for case, metric, value, unit in rows:
            f.write(f"setup_scaling,{case},{metric},{value:.6g},{unit}\n")
PY
