#!/usr/bin/env bash
# Gmsh meshes (tests/data/meshes/*.geo, physical groups named like the box sides and a
# region "soil") through slipwave: the 1D SV column (H = 100 m, vs = 200 m/s, vp = 400 m/s,
# absorbing base with a Ricker incident wave, f0 = 5 Hz, 0.1 m/s) on
#   column_quad.geo  2 x 100 quads recombined from a transfinite grid (= -mesh_box_faces 2,100)
#   column_tri.geo   unstructured triangles, 4 m x 100 m, target size 1 m, -constrain_components y
#   column_tet.geo   unstructured tetrahedra, 2 x 2 x 100 m, target size 1 m, -constrain_components y,z
# Expected: top velocity v_x = 2 v_in(t - H/vs) (closed form; vertical incidence, free surface).
# Tolerances:
#  - quads: the same grid as the built-in box, so the run must equal the box run to 1e-9 of
#    the peak (round-off from a different node numbering), and the closed form within
#    e_disp + 0.5 %, e_disp computed from the discrete dispersion relation of the lumped-mass
#    chain with central differences, sin(w dt/2) = (vs dt/h) sin(k h/2) (3.0 % here).
#  - triangles, tetrahedra: no closed-form dispersion for an irregular mesh; allowed is what a
#    regular chain of the target size h = 1 m reaches with the run's dt (e_disp, 3.0-3.4 %)
#    plus 1 % for the irregular sizes (0.7-1.3 m). Measured when written: 0.2 % (triangles,
#    whose stiffer shear partly cancels the lumped-mass lag) and 2.2 % (tetrahedra).
#  - the triangle run on 2 ranks equals the 1-rank run to 1e-9 of the peak.
# Every output is checked with scripts/check_output.py; the y (and z) velocities stay 0.
set -euo pipefail
BUILD=${BUILD:-build}
export SLIPWAVE_BINARY="$BUILD/slipwave"
SW=tests/tools/slipwave_for_tests.sh # stations every step, the verbose report
out="$BUILD/tests/gmsh_meshes"
rm -rf "$out"; mkdir -p "$out"
command -v gmsh >/dev/null || { echo "FAIL: gmsh is not installed"; exit 1; }
root_flag=""; [ "$(id -u)" = 0 ] && root_flag="--allow-run-as-root"
for g in column_quad:2 column_tri:2 column_tet:3; do
  name=${g%:*}; dim=${g#*:}
  gmsh -"$dim" "tests/data/meshes/$name.geo" -format msh41 -o "$out/$name.msh" > "$out/$name.gmsh.log" 2>&1 || { cat "$out/$name.gmsh.log"; echo "FAIL: gmsh $name"; exit 1; }
done
common="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -bc_bottom_type absorbing -input_wave sv -input_boundary bottom
 -input_stf ricker -input_f0 5 -input_amplitude 0.1 -ts_max_time 1.2 -output_interval 0.1 -station_names top"
run() { # name, args...
  local name=$1; shift
  "$@" $common -output_dir "$out/$name" > "$out/$name.log" 2>&1 || { cat "$out/$name.log"; echo "FAIL: run $name"; exit 1; }
  grep -E "mesh:|boundaries:" "$out/$name.log"
}
run box   "$SW" -mesh_box_faces 2,100 -mesh_box_upper 2,100 -constrain_components y -station_coordinates 1,100
run quad  "$SW" -mesh_file "$out/column_quad.msh" -constrain_components y -station_coordinates 1,100
run tri   "$SW" -mesh_file "$out/column_tri.msh" -constrain_components y -station_coordinates 2,100
run tri_np2 mpiexec --oversubscribe $root_flag -n 2 "$SW" -mesh_file "$out/column_tri.msh" -constrain_components y -station_coordinates 2,100
run tet   "$SW" -mesh_file "$out/column_tet.msh" -constrain_components y,z -station_coordinates 1,1,100
grep -q "boundaries: left=free right=free front=free back=free bottom=absorbing top=free" "$out/tet.log" || { echo "FAIL: tet boundaries"; exit 1; }
for r in box quad tri tri_np2 tet; do
  /usr/bin/python3 scripts/check_output.py "$out/$r" --expect-fields displacement,velocity
done
/usr/bin/python3 - "$out" <<'PY'
import sys, numpy as np
out = sys.argv[1]
A, f0, t0, H, vs, h = 0.1, 5.0, 0.24, 100.0, 200.0, 1.0
def v_in(t):
    a = (np.pi * f0 * (t - t0)) ** 2
    return A * (1 - 2 * a) * np.exp(-a)
def top(run):
    return np.genfromtxt(f"{out}/{run}/stations/top.csv", delimiter=",", names=True)
def e_disp(t):
    """Error of the regular lumped-mass chain (spacing h, the run's dt) against the closed form."""
    dt = t[1] - t[0]; N = 16 * len(t); om = 2 * np.pi * np.fft.rfftfreq(N, dt)
    k_h = 2 / h * np.arcsin(np.clip(np.sin(om * dt / 2) / (vs * dt / h), -1, 1))
    dispersed = np.fft.irfft(2 * np.fft.rfft(v_in(np.arange(N) * dt)) * np.exp(-1j * k_h * H), N)[:len(t)]
    exact = 2 * v_in(t - H / vs)
    return np.abs(dispersed - exact).max() / np.abs(exact).max()
fail = False
def check(label, value, limit):
    global fail
    ok = value <= limit
    fail |= not ok
    print(f"{label}: {value:.3e} (allowed {limit:.3e}) {'ok' if ok else 'FAIL'}")
d = {r: top(r) for r in ("box", "quad", "tri", "tri_np2", "tet")}
peak = 2 * A
check("quad Gmsh vs box, max |dv|/peak", np.abs(d["quad"]["v_x"] - d["box"]["v_x"]).max() / peak, 1e-9)
check("triangles 2 ranks vs 1, max |dv|/peak", np.abs(d["tri_np2"]["v_x"] - d["tri"]["v_x"]).max() / peak, 1e-9)
for r, margin in (("quad", 0.005), ("tri", 0.01), ("tet", 0.01)):
    t, v = d[r]["t"], d[r]["v_x"]
    exact = 2 * v_in(t - H / vs)
    e = np.abs(v - exact).max() / np.abs(exact).max(); ed = e_disp(t)
    check(f"{r}: |v_x - 2 v_in(t - H/vs)|/peak (chain dispersion {ed:.2%} + {margin:.1%})", e, ed + margin)
    for c in ("v_y", "v_z"):
        if c in d[r].dtype.names:
            check(f"{r}: max |{c}|", np.abs(d[r][c]).max(), 0.0)
sys.exit(1 if fail else 0)
PY
echo PASS
