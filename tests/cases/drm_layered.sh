# Domain Reduction Method on a layered site at vertical incidence (issue 12 item 1): 30 m of
# soil (rho 1900, vp 500, vs 200) on rock (rho 2400, vp 1600, vs 800), 2D, 120 m x 60 m,
# absorbing sides and base, h = 1.25 m (29 points per soil S wavelength at the Ricker's top
# frequency 5.5 Hz), the DRM layer 2 cells in, SV (and P) Ricker f0 = 2 Hz.
# Reference: the 1D Thomson-Haskell transfer function of one layer on elastic rock (Kramer
# 1996, eq. 7.32): surface / incident at the top of the rock = 2 / (cos kH + i a sin kH),
# k = w / c_soil, a = rho_s c_s / (rho_r c_r), c = vs for SV and vp for P; the incident wave
# is given at the reference point, the deepest DRM nodes (depth 60 - e = 58.75 m, e = h the
# element size), so at the top of the rock it is delayed by (30 - e) / c_rock. Synthesised
# with numpy's FFT (zero padded).
# Bound (issue): surface velocity within 2 % relative L2 at the centre and off-centre.
# A third run drives the SV wave by a ground-motion record (-drm_stf record, -drm_record_motion
# incident): v(t) = V0 sin^2(pi t/T) sin(4 pi t/T) on [0, T], T = 0.6 s, V0 = 0.1 m/s (the pulse
# of tests/cases/record_input.sh), its exact derivative sampled every 1 ms as CSV; the
# reference convolves the closed-form v(t) with the same transfer function.
# SEM_DEGREE=p runs it with ceil(96 / p) x ceil(48 / p) elements of degree p (the same GLL
# nodes, tests/cases/sem_drm.sh); the reference point is then 1 element of e = 1.25 p m in.
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
e=$($PY -c "print(120 / $(elements 96))") # element size [m]
model="-regions rock,soil -material_soil_rho 1900 -material_soil_vp 500 -material_soil_vs 200 -material_rock_rho 2400 -material_rock_vp 1600
 -material_rock_vs 800 -region_soil_box -60,60,-30,0 -mesh_box_faces $(elements 96),$(elements 48) -element_degree $DEGREE -mesh_box_lower -60,-60 -mesh_box_upper 60,0
 -bc_left_type absorbing -bc_right_type absorbing -bc_bottom_type absorbing -input_method drm -ts_max_time 4 -output_fields 0
 -progress_interval 100000 -station_coordinates 0,0,-40,0,30,-15 -station_names centre,left,mid"
ricker="-drm_stf ricker -drm_f0 2 -drm_t0 0.6 -drm_amplitude 0.1"
# The three runs are independent (one rank each): two at a time (tests/tools/together.sh),
# the record's run once its record is written.
together $SW $model $ricker -drm_wave sv -output_dir "$WORK/sv" > "$WORK/sv.log"
together $SW $model $ricker -drm_wave p -output_dir "$WORK/p" > "$WORK/p.log"
$PY - "$WORK/record.csv" <<'PY'
import sys
import numpy as np
T, V0 = 0.6, 0.1
t = np.arange(0, 1.2 + 1e-9, 1e-3)
a = V0 * np.pi / T * (np.sin(2 * np.pi * t / T) * np.sin(4 * np.pi * t / T) + 4 * np.sin(np.pi * t / T) ** 2 * np.cos(4 * np.pi * t / T))
a[t > T] = 0
np.savetxt(sys.argv[1], np.column_stack([t, a]), delimiter=",", header="time,acceleration", comments="")
PY
together $SW $model -drm_stf record -drm_record_motion incident -drm_record "$WORK/record.csv" -drm_wave sv -output_dir "$WORK/record" > "$WORK/record.log"
together_wait
cat "$WORK/sv.log" "$WORK/p.log" "$WORK/record.log"
$PY - "$WORK" "$e" <<'PY'
import sys
import numpy as np
w, e = sys.argv[1], float(sys.argv[2])
ok = True
def ricker(tt):
    x = (np.pi * 2.0 * (tt - 0.6)) ** 2
    return 0.1 * (1 - 2 * x) * np.exp(-x)
def record(tt):
    return np.where(tt <= 0.6, 0.1 * np.sin(np.pi * tt / 0.6) ** 2 * np.sin(4 * np.pi * tt / 0.6), 0.0)
for run, wave, comp, cs, cr, v in (("sv", "sv", "v_x", 200.0, 800.0, ricker), ("p", "p", "v_y", 500.0, 1600.0, ricker), ("record", "sv", "v_x", 200.0, 800.0, record)):
    for n in ("centre", "left"):
        d = np.genfromtxt(f"{w}/{run}/stations/{n}.csv", delimiter=",", names=True)
        t = d["t"]
        dt = t[1] - t[0]
        m = 8 * len(t)
        v_in = v(np.arange(m) * dt)
        om = 2 * np.pi * np.fft.rfftfreq(m, dt)
        H, a = 30.0, 1900 * cs / (2400 * cr)
        tf = 2 / (np.cos(om * H / cs) + 1j * a * np.sin(om * H / cs)) * np.exp(-1j * om * (30 - e) / cr)
        ref = np.fft.irfft(np.fft.rfft(v_in) * tf, m)[: len(t)]
        err = np.sqrt(np.sum((d[comp] - ref) ** 2) / np.sum(ref**2))
        print(f"{run}: surface {n}: relative L2 error against Thomson-Haskell {err:.2e} (bound 2e-2)")
        ok &= err <= 2e-2
sys.exit(0 if ok else 1)
PY
