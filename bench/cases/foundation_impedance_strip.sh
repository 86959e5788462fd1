# Dynamic impedance of a rigid strip footing (B = 2 m half-width) on an elastic half-space
# (vs 100 m/s, nu = 1/3) by forced vibration, all three modes, against the reference
# tests/tools/strip_impedance.py (welded contact, as here) over a0 = w B / vs = 0.2 .. 2.
# The model (tests/tools/strip_footing.sh, chosen and justified in the header of
# tests/cases/foundation_impedance_strip.sh, which checks the vertical and rocking modes
# within 10 %): 80 x 40 m of soil behind sponge layers 6 m thick, meshes h = B/4 and B/8;
# a Ricker vertical force, horizontal force (at the footing's centroid, 1 m above the base)
# and couple. tests/tools/footing_runs.py takes the footing's inertia out exactly (rigid block
# 4 m x 2 m, m = 16000 kg/m, I_c = 26667 kg m^2/m about its centre of mass, 1 m above the
# base): K_yy from the vertical run;
# the sway-rocking block (K_xx, K_xr, K_rr at the base's centre) from the horizontal and
# couple runs together. Each is Richardson-extrapolated, 2 K(B/8) - K(B/4) (the punch's edge
# singularity makes the stiffness converge as O(h)). Rows: the dimensionless k = Re K / K_ref,
# c = Im K / (a0 K_ref) (Gazetas 1991), K_ref = G for the translations (a strip has no finite
# static translational stiffness) and pi G B^2 / (2 (1 - nu)) for rocking, of slipwave
# (extrapolated) and of the reference, and the complex relative error, at a0 = 0.25, 0.5, 1,
# 1.5, 2; the maximum error over a0 = 0.2-2 (step 0.1) per mode and mesh. Exits non-zero if
# an extrapolated error exceeds 10 % (issue 12's bound). About 8 minutes on one core.
set -u
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SW="$BUILD/slipwave"
PY=/usr/bin/python3
WORK="$BUILD/bench/work/foundation_impedance_strip"
rm -rf "$WORK"; mkdir -p "$WORK"
. tests/tools/strip_footing.sh
for h in 0.5 0.25; do
  strip_footing_run vertical_$h 80 40 $h 6 "-structure_load_force 0,1e5"
  strip_footing_run horizontal_$h 80 40 $h 6 "-structure_load_force 1e5,0"
  strip_footing_run rocking_$h 80 40 $h 6 "-structure_load_moment 1e5"
done
$PY - "$WORK" "${BENCH_CSV:-/dev/null}" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "tests/tools")
import footing_runs as fr
work, csv = sys.argv[1], sys.argv[2]
B, rho, vp, vs = 2.0, 2000.0, 200.0, 100.0
G, nu = rho * vs * vs, 1 / 3
K_ref = {"vertical": G, "horizontal": G, "rocking": np.pi * G * B * B / (2 * (1 - nu))}
m, I_c, e = fr.rigid_block(2000.0, 2 * B, 2.0)
a0s = np.round(np.arange(0.2, 2.0001, 0.1), 10)
ref = fr.reference(a0s, B, rho, vp, vs)
reference = {"vertical": np.array([K[1, 1] for K in ref]), "horizontal": np.array([K[0, 0] for K in ref]),
             "rocking": np.array([K[2, 2] for K in ref])}


def measured(h):
    w, P, _, Uy, _ = fr.load_run(f"{work}/vertical_{h}", 40.0, B)
    _, H, Ux_h, _, Th_h = fr.load_run(f"{work}/horizontal_{h}", 40.0, B)
    _, M, Ux_r, _, Th_r = fr.load_run(f"{work}/rocking_{h}", 40.0, B)
    a0 = w * B / vs
    S = fr.sway_rocking_block(w, H, Ux_h, Th_h, M, Ux_r, Th_r, m, I_c, e)
    return {"vertical": fr.at(a0s, a0, fr.vertical_impedance(w, P, Uy, m)),
            "horizontal": fr.at(a0s, a0, S[:, 0, 0]), "rocking": fr.at(a0s, a0, S[:, 1, 1])}


coarse, fine = measured("0.5"), measured("0.25")
ok = True
with open(csv, "a") as out:
    for mode in ("vertical", "horizontal", "rocking"):
        R = reference[mode]
        X = 2 * fine[mode] - coarse[mode]
        err = lambda K: np.abs(K / R - 1)
        for a0 in (0.25, 0.5, 1.0, 1.5, 2.0):
            x = lambda K: np.interp(a0, a0s, K.real) + 1j * np.interp(a0, a0s, K.imag)
            k, c = x(X).real / K_ref[mode], x(X).imag / (a0 * K_ref[mode])
            kr, cr = x(R).real / K_ref[mode], x(R).imag / (a0 * K_ref[mode])
            rel = abs(x(X) / x(R) - 1)
            print(f"{mode}: a0 = {a0}: k = {k:.3f} (reference {kr:.3f}), c = {c:.3f} (reference {cr:.3f}), |K/K_ref - 1| = {rel:.3f}")
            out.write(f"foundation_impedance_strip,{mode},k_a0_{a0},{k:.4g},-\nfoundation_impedance_strip,{mode},c_a0_{a0},{c:.4g},-\n"
                      f"foundation_impedance_strip,{mode},k_ref_a0_{a0},{kr:.4g},-\nfoundation_impedance_strip,{mode},c_ref_a0_{a0},{cr:.4g},-\n")
        e1, e2, ex = err(coarse[mode]).max(), err(fine[mode]).max(), err(X).max()
        print(f"{mode}: max complex relative error over a0 = 0.2-2: B/4 {e1:.3f}, B/8 {e2:.3f}, extrapolated {ex:.3f} (bound 0.10)")
        out.write(f"foundation_impedance_strip,{mode},max_rel_error_B/4,{e1:.4g},-\nfoundation_impedance_strip,{mode},max_rel_error_B/8,{e2:.4g},-\n"
                  f"foundation_impedance_strip,{mode},max_rel_error_extrapolated,{ex:.4g},-\n")
        ok &= ex <= 0.10
sys.exit(0 if ok else 1)
PY
