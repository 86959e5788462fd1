# A user's table backbone (-material_<r>_backbone table, -material_<r>_backbone_file): the
# hyperbola G/Gmax = 1/(1 + gamma/gamma_r), gamma_r = 1e-3, written as a table in percent at
# 40 rows per decade, must give the model of -material_<r>_backbone mkz with the same
# gamma_r. The table is interpolated linearly in (ln gamma, ln G/Gmax); the hyperbola's
# |d^2 ln(G/Gmax) / d(ln gamma)^2| = x/(1+x)^2 <= 1/4, so at a spacing d = ln(10)/40 the table
# is within d^2/8 * 1/4 = 1.04e-4 of the curve (relative), and so are the Iwan model's knot
# stresses. The strong-motion column of hysteretic_column.sh (top 30 m hysteretic, strains
# ~1e-3) run both ways: the surface velocities must agree to 1e-3 relative L2 (10 x that knot
# error: the response moves with the moduli by about as much; measured in the log), and the
# run_info.json of the table run must carry its rows and source for scripts/soil_loops.py.
set -eu
. tests/tools/lib.sh
. tests/tools/together.sh
$PY - "$WORK/hyperbola.csv" <<'PY'
import sys
import numpy as np
g = np.logspace(-7, 0, 7 * 40 + 1)
with open(sys.argv[1], "w") as f:
    f.write("# source: Hardin & Drnevich (1972) hyperbola, gamma_r = 1e-3, 40 rows per decade\nstrain_percent,G/Gmax\n")
    for x in g:
        f.write(f"{100 * x:.17g},{1 / (1 + x / 1e-3):.17g}\n")
PY
column="$COLUMN -regions rock,soil -region_soil_box 0,1,70,100 -material_rock_rho 2000 -material_rock_vp 400 -material_rock_vs 200
  -material_soil_model hysteretic -mesh_box_faces 1,400 -mesh_box_upper 1,100 -input_wave sv -constrain_components y -station_coordinates 0.5,100,0.5,85 -station_names top,layer -station_stress true"
# The two runs are independent (one rank each): side by side (tests/tools/together.sh).
together $SW $column -material_soil_backbone mkz -material_soil_reference_strain 1e-3 -output_dir "$WORK/mkz" > "$WORK/mkz.log"
together $SW $column -material_soil_backbone table -material_soil_backbone_file "$WORK/hyperbola.csv" -output_dir "$WORK/table" > "$WORK/table.log"
together_wait
grep -q "backbone table .*hyperbola.csv (281 rows; source: Hardin & Drnevich (1972) hyperbola" "$WORK/table.log"
$CHECK energy "$WORK/table/energy.csv" --max-error 1e-9 --min-rows 2
$PY - "$WORK/mkz/stations/top.csv" "$WORK/table/stations/top.csv" "$WORK/table/run_info.json" <<'PY'
import json, sys
import numpy as np
a = np.genfromtxt(sys.argv[1], delimiter=",", names=True)["v_x"]
b = np.genfromtxt(sys.argv[2], delimiter=",", names=True)["v_x"]
l2 = np.linalg.norm(a - b) / np.linalg.norm(a)
print(f"surface velocity, table against mkz: relative L2 {l2:.3e} (bound 1e-3); peaks {abs(a).max():.4f}, {abs(b).max():.4f} m/s")
assert l2 < 1e-3, l2
assert abs(a).max() < 0.16, "the layer must yield (linear peak 0.200 m/s)"
region = json.load(open(sys.argv[3]))["hysteretic_regions"][0]
assert region["backbone"] == "table" and len(region["table"]) == 281 and region["table_source"].startswith("Hardin"), region.keys()
assert abs(region["table"][0][0] - 1e-7) < 1e-20, region["table"][0]
PY
# The plotting script draws the table's curves (soil_loops.py reads the rows from run_info.json).
$PY scripts/soil_loops.py "$WORK/table" --out "$WORK/plots" > "$WORK/loops.log"
[ -s "$WORK/plots/soil_curves_soil.png" ]
