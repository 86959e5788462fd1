# slipwave-law on a 2D direct shear at constant normal LOAD p = 100 kPa with dilatancy.
# sigma_N stays -p only if the elastic normal jump is constant: w_N = tan(psi) (w_T - w_y)
# once slipping (w_y = (p tan(phi) + c) / G, put on a row boundary). Expected on paper:
# sigma_T = min(G w_T, p tan(phi) + c), sigma_N = -p, wp_T = w_T - sigma_T / G,
# wp_N = tan(psi) wp_T, dissipation = (c + p (tan(phi) - tan(psi))) wp_T (spec section 4).
# Also: -output writes the same CSV as standard output.
set -eu
BUILD=${BUILD:-build}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 - "$tmp/in.csv" <<'PY'
import math, sys
G, c, p, phi, psi = 5e7, 2e3, 1e5, math.radians(30), math.radians(10)
wy = (p * math.tan(phi) + c) / G
with open(sys.argv[1], "w") as f:
    f.write("t,w_T,w_N\n")
    for k in range(1, 21):
        wT = k * wy / 4
        f.write(f"{0.01 * k!r},{wT!r},{math.tan(psi) * max(0.0, wT - wy)!r}\n")
PY
opts="-interface_E 1e8 -interface_G 5e7 -interface_phi 30 -interface_psi 10 -interface_c 2e3 -interface_sigma_N0 -1e5"
"$BUILD/slipwave-law" -path "$tmp/in.csv" -output "$tmp/out.csv" $opts
"$BUILD/slipwave-law" -path "$tmp/in.csv" $opts > "$tmp/stdout.csv"
cmp "$tmp/out.csv" "$tmp/stdout.csv"
/usr/bin/python3 - "$tmp/out.csv" <<'PY'
import csv, math, sys
G, c, p, phi, psi = 5e7, 2e3, 1e5, math.radians(30), math.radians(10)
strength = p * math.tan(phi) + c
rows = list(csv.DictReader(open(sys.argv[1])))
assert list(rows[0].keys()) == ["t", "w_T", "w_N", "sigma_T", "sigma_N", "wp_T", "wp_N", "status", "dissipation"], rows[0].keys()
assert len(rows) == 20, len(rows)
def close(got, want, scale, what):
    assert abs(float(got) - want) <= 1e-9 * scale, f"{what}: got {got}, want {want}"
for r in rows:
    wT = float(r["w_T"])
    sT = min(G * wT, strength)
    wpT = wT - sT / G
    close(r["sigma_T"], sT, strength, "sigma_T")
    close(r["sigma_N"], -p, p, "sigma_N")
    close(r["wp_T"], wpT, 1e-3, "wp_T")
    close(r["wp_N"], math.tan(psi) * wpT, 1e-3, "wp_N")
    close(r["dissipation"], (c + p * (math.tan(phi) - math.tan(psi))) * wpT, 100.0, "dissipation")
    assert r["status"] == ("slip" if G * wT > strength * (1 + 1e-12) else "stick"), r
print("direct shear 2D: 20 rows as derived")
PY
