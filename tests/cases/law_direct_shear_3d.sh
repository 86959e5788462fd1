# slipwave-law on tests/data/law/direct_shear_3d.csv: 3D shear along T1 at constant normal
# jump under p = 100 kPa, psi = 0 (no dilatancy, so sigma_N stays -p and the plateau is flat),
# then an opening of 3 mm beyond e_ini = 1 mm. Expected on paper: sigma_T1 =
# min(G w_T1, p tan(phi) + c), sigma_T2 = 0, sigma_N = -p; last row open and traction free.
set -eu
BUILD=${BUILD:-build}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
"$BUILD/slipwave-law" -path tests/data/law/direct_shear_3d.csv -output "$tmp/out.csv" -interface_E 1e8 -interface_G 5e7 \
  -interface_phi 30 -interface_psi 0 -interface_c 2e3 -interface_e_ini 1e-3 -interface_sigma_N0 -1e5
/usr/bin/python3 - "$tmp/out.csv" <<'PY'
import csv, math, sys
G, c, p = 5e7, 2e3, 1e5
strength = p * math.tan(math.radians(30)) + c
rows = list(csv.DictReader(open(sys.argv[1])))
assert list(rows[0].keys()) == ["t", "w_T1", "w_T2", "w_N", "sigma_T1", "sigma_T2", "sigma_N", "wp_T1", "wp_T2", "wp_N",
                                "status", "dissipation"], rows[0].keys()
assert len(rows) == 6
for r in rows[:5]:
    sT = min(G * float(r["w_T1"]), strength)
    assert abs(float(r["sigma_T1"]) - sT) <= 1e-9 * strength, r
    assert float(r["sigma_T2"]) == 0.0 and abs(float(r["sigma_N"]) + p) <= 1e-9 * p, r
    assert abs(float(r["wp_T1"]) - (float(r["w_T1"]) - sT / G)) <= 1e-12, r
last = rows[5]
assert last["status"] == "open", last
assert float(last["sigma_T1"]) == 0.0 and float(last["sigma_T2"]) == 0.0 and float(last["sigma_N"]) == 0.0, last
print("direct shear 3D and opening as derived")
PY
