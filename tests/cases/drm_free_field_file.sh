# Domain Reduction Method driven by a free field read from an HDF5 file (issue 12 item 1:
# "an interface to read a free field from an HDF5 file"). The file holds the closed-form
# half-space SV free field at 20 deg (tests/tools/plane_wave_halfspace.py, the reference of
# tests/cases/drm_halfspace.sh) at the DRM layer's nodes, sampled every 1 ms; the run must
# give the records of the built-in plane wave. Expected difference: the file's displacement is
# linear in time between samples, an error of (2 pi f dt)^2 / 8 relative: 4.4e-5 at the
# Ricker's f0 = 3 Hz, 3.4e-4 at its top frequency 8.3 Hz; bound 1e-3 relative L2 on the
# velocity records (the built-in field's own error is below 1e-7, tests/unit/test_plane_wave_layered).
# Also: a missing file, and a file lacking a layer node (the last point written, (98.75, 0)) stops the run with one
# line naming the node. (Sampled every 2 ms, close to the time step, the kinks of the linear
# interpolation give 1.2e-3: a file should sample the field well below the time step.)
set -eu
. tests/tools/lib.sh
model="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -mesh_box_faces 160,80 -mesh_box_lower -100,-100
 -mesh_box_upper 100,0 -bc_left_type absorbing -bc_right_type absorbing -bc_bottom_type absorbing -input_method drm -ts_max_time 1.3
 -output_fields 0 -progress_interval 100000 -station_coordinates -60,0,0,0,0,-50,-96,-50,0,-96 -station_names s1,s2,mid,left_in,base_in"
$PY - "$WORK" <<'PY'
import sys
import h5py
import numpy as np
sys.path.insert(0, "tests/tools")
from plane_wave_halfspace import HalfspacePlaneWave
w = sys.argv[1]
f = HalfspacePlaneWave(2000, 400, 200, "sv", 20)
ricker_u = lambda t: 0.1 * (t - 0.4) * np.exp(-((np.pi * 3.0 * (t - 0.4)) ** 2))  # the Ricker velocity's antiderivative
grid = -100 + 1.25 * np.arange(161)
band = [-98.75, -97.5, 97.5, 98.75]
pts = [(x, y) for x in grid for y in grid[grid <= 0] if (x in band or y in (-98.75, -97.5)) and abs(x) <= 98.75 and y >= -98.75]
t = np.arange(0, 1.3 + 1e-9, 1e-3)
u = np.array([f.velocity(ricker_u, t, x, y, -98.75, 98.75).T for x, y in pts])  # (points, samples, 2)
for name, keep in (("field.h5", len(pts)), ("short.h5", len(pts) - 1)):
    with h5py.File(f"{w}/{name}", "w") as h:
        h["coordinates"] = np.array(pts[:keep])
        h["time"] = t
        h["displacement"] = u[:keep]
PY
$SW $model -drm_wave sv -drm_incidence_angle 20 -drm_stf ricker -drm_f0 3 -drm_t0 0.4 -drm_amplitude 0.1 -output_dir "$WORK/plane"
$SW $model -drm_free_field_file "$WORK/field.h5" -output_dir "$WORK/file"
# Each rank reads its own nodes' rows: 2 ranks give the 1-rank records to round-off (the bound
# of tests/cases/mpi_ranks.sh).
$MPIEXEC -n 2 $SW $model -drm_free_field_file "$WORK/field.h5" -output_dir "$WORK/file2"
$CHECK stations-equal "$WORK/file" "$WORK/file2" --names s1,s2,mid,left_in,base_in --tol 1e-10
if $SW $model -drm_free_field_file "$WORK/short.h5" -output_dir "$WORK/short" 2>"$WORK/short.err"; then echo "FAIL: a file without a layer node was accepted"; exit 1; fi
grep -q "^slipwave: error: -drm_free_field_file = .*short.h5 has no point at the DRM node (98.75, 0) (within" "$WORK/short.err" || { cat "$WORK/short.err"; exit 1; }
if $SW $model -drm_free_field_file "$WORK/missing.h5" -output_dir "$WORK/missing" 2>"$WORK/missing.err"; then echo "FAIL: a missing file was accepted"; exit 1; fi
grep -q "^slipwave: error: -drm_free_field_file = .*missing.h5 cannot be opened as an HDF5 file$" "$WORK/missing.err" || { cat "$WORK/missing.err"; exit 1; }
[ "$(wc -l <"$WORK/missing.err")" -eq 1 ] || { echo "FAIL: more than one error line"; cat "$WORK/missing.err"; exit 1; }
$PY - "$WORK" <<'PY'
import sys
import numpy as np
w = sys.argv[1]
ok = True
for n in ("s1", "s2", "mid", "left_in", "base_in"):
    a = np.genfromtxt(f"{w}/plane/stations/{n}.csv", delimiter=",", names=True)
    b = np.genfromtxt(f"{w}/file/stations/{n}.csv", delimiter=",", names=True)
    err = np.sqrt(np.sum((a["v_x"] - b["v_x"]) ** 2 + (a["v_y"] - b["v_y"]) ** 2) / np.sum(a["v_x"] ** 2 + a["v_y"] ** 2))
    print(f"file vs built-in plane wave: {n}: relative L2 difference {err:.2e} (bound 1e-3)")
    ok &= err <= 1e-3
sys.exit(0 if ok else 1)
PY
