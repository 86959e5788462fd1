# Plots: scripts/plot_results.py on (1) a short 2D run with an interface (a stiff block on
# soil, interface 'base') and two stations, the transfer ratio taken over the station 'base'
# (--reference base), (2) a short 3D run with the same kind of interface and no station, (3) a
# directory with no output. Checks that every expected PNG is written (and listed on stdout),
# is a valid PNG (signature, IHDR chunk, a size of at least 400 x 300 pixels) and is not blank
# (the pixel values vary), that --out DIR is honoured, that the 3D run (no station) plots its
# input motion and spectrum, and that an empty directory exits 1. spectra.csv: a period
# column from 0.02 to 5 s and one PSA column per station (a_x), finite and > 0; the
# acceleration plot's title gives the resolved frequency vs/(10 h) = 300/(10*1) = 30 Hz of
# run_info.json; without the reference station the transfer ratio is skipped with a note.
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
BLOCK="-regions soil,block -material_soil_rho 2000 -material_soil_vp 600 -material_soil_vs 300
 -material_block_rho 2400 -material_block_vp 3000 -material_block_vs 1800 -interfaces base -interface_base_regions soil,block
 -bc_bottom_type absorbing -input_wave sv -input_stf ricker -input_f0 5 -input_amplitude 1 -gravity 9.81 -ts_max_time 0.3 -progress_interval 100
 -output_fields 0"
# The two runs, then the three plotting runs, are independent: two at a time
# (tests/tools/together.sh; each plot's stdout into its file, printed after). The runs write
# no volume fields (-output_fields 0): plot_results.py reads the stations, the interface
# frames, energy.csv and run_info.json.
together $SW $BLOCK -mesh_box_faces 20,6 -mesh_box_upper 20,6 -region_block_box 8,12,4,6 \
  -station_coordinates 10,6,10,0 -station_names top,base -output_dir "$WORK/run2d" > "$WORK/run2d.log"
together $SW $BLOCK -mesh_dim 3 -mesh_box_faces 8,8,4 -mesh_box_upper 8,8,4 -region_block_box 3,5,3,5,3,4 -output_dir "$WORK/run3d" > "$WORK/run3d.log"
together_wait
cat "$WORK/run2d.log" "$WORK/run3d.log"

together $PY scripts/plot_results.py "$WORK/run2d" --reference base > "$WORK/plot2d.txt"
together $PY scripts/plot_results.py "$WORK/run3d" --out "$WORK/plots3d" > "$WORK/plot3d.txt"
together $PY scripts/plot_results.py "$WORK/run2d" --out "$WORK/plots_noref" > "$WORK/plot_noref.txt"
together_wait
cat "$WORK/plot2d.txt" "$WORK/plot3d.txt" "$WORK/plot_noref.txt"
grep -q '"resolved_frequency_hz": 30,' "$WORK/run2d/run_info.json"
grep -q "no station 'free_field' (the free-field reference, --reference): transfer ratio skipped" "$WORK/plot_noref.txt"
mkdir -p "$WORK/empty"
if $PY scripts/plot_results.py "$WORK/empty" >"$WORK/plot_empty.txt" 2>&1; then
  echo "plot_results.py exited 0 on a directory without output"; exit 1
fi
grep -q "nothing to plot" "$WORK/plot_empty.txt"

$PY - "$WORK" <<'PY'
import os, struct, sys, zlib
import numpy as np
import matplotlib.image as mpimg
w = sys.argv[1]
expected = {
    "plot2d.txt": [f"{w}/run2d/plots/{n}" for n in
                   ("stations_acceleration.png", "spectra.png", "amplification.png", "transfer_ratio.png", "interface_base_history.png",
                    "interface_base_profile.png", "energy.png")],
    "plot3d.txt": [f"{w}/plots3d/{n}" for n in
                   ("stations_acceleration.png", "spectra.png", "interface_base_history.png", "interface_base_profile.png", "energy.png")],
}
for log, files in expected.items():
    listed = open(os.path.join(w, log)).read()
    for path in files:
        assert path in listed, f"{path} not in the list printed by plot_results.py ({log})"
        with open(path, "rb") as f:
            data = f.read()
        assert len(data) > 5000, f"{path}: only {len(data)} bytes"
        assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: no PNG signature"
        length, kind = struct.unpack(">I4s", data[8:16])
        assert kind == b"IHDR" and length == 13, f"{path}: first chunk is {kind!r}, not IHDR"
        width, height = struct.unpack(">II", data[16:24])
        crc = struct.unpack(">I", data[29:33])[0]
        assert crc == zlib.crc32(data[12:29]), f"{path}: IHDR checksum wrong"
        assert width >= 400 and height >= 300, f"{path}: {width} x {height} pixels"
        assert data[-12:] == b"\x00\x00\x00\x00IEND\xaeB`\x82", f"{path}: does not end with the IEND chunk"
        img = mpimg.imread(path)
        assert img.shape[:2] == (height, width), (path, img.shape)
        assert float(np.var(img[..., :3])) > 1e-4, f"{path}: blank image"
        print(f"ok {path}: {width} x {height}, {len(data)} bytes, pixel variance {np.var(img[..., :3]):.3g}")
assert not os.path.exists(f"{w}/run3d/plots"), "--out ignored: run3d/plots was created"
csv = f"{w}/run2d/plots/spectra.csv"
assert csv in open(os.path.join(w, "plot2d.txt")).read(), "spectra.csv not listed"
with open(csv) as f:
    header = f.readline().strip().split(",")
assert header == ["period_s", "input_outcrop_psa_g", "top_a_x_psa_g", "base_a_x_psa_g"], header  # input first, then top (y 6) to base (y 0)
table = np.loadtxt(csv, delimiter=",", skiprows=1)
assert abs(table[0, 0] - 0.02) < 1e-9 and abs(table[-1, 0] - 5) < 1e-9, table[[0, -1], 0]
assert np.all(np.isfinite(table)) and np.all(table[:, 1:] > 0), "spectra.csv: a PSA is not finite and > 0"
print(f"ok {csv}: {table.shape[0]} periods, columns {header}")
print("plots: OK")
PY
