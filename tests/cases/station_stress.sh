# Stations that record stress and strain (-station_stress, issue 22 part 5): one cell in
# strain-controlled shear (all nodes prescribed, so the strain is uniform; the setup of
# tests/cases/hysteretic_cyclic_shear.sh: bottom fixed, top moving with v = A sin(2 pi f t)).
# 1. Hysteretic MKZ soil (s = beta = 1, gamma_r 1e-3, Gmax 8e7 Pa, 200 surfaces), top moving
#    in x: the station (off the cell's centre) records 2 e_xy = gamma(t) and s_xy = Masing's
#    closed forms, and at every volume frame the frame's cell stress
#    (tests/tools/hysteretic.py station, bounds and their sources there).
# 2. Elastic, the top moving in every direction (u(t) = A (1 - cos 2 pi f t) / (2 pi f), H = 1):
#    2D e_yy = u, e_xy = u / 2, e_xx = 0; 3D e_zz = u, e_xz = e_yz = u / 2, others 0; the
#    stress sigma = lambda tr(eps) I + 2 mu eps with mu = rho vs^2 = 8e7 Pa, lambda = rho vp^2
#    - 2 mu = 1.6e8 Pa (2D: plane strain, s_zz = lambda tr(eps)). Strain within 1e-5 of its peak
#    (the time step's error, as in hysteretic.py), stress = C eps of the recorded strain to
#    1e-12 of its peak (round-off), the CSV and stations.h5 the same through python/slipwave.
set -eu
. tests/tools/lib.sh
A=0.012566370614359173 # pi f gamma_m H = pi x 1 x 4e-3 x 1 [m/s]
soil="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200"
drive="-bc_bottom_type fixed -bc_top_type velocity -bc_top_stf harmonic -bc_top_f0 1 -bc_top_amplitude $A -ts_max_time 1.5 -ts_dt 1e-3 -progress_interval 1000
  -station_stress true"
hyst="-material_soil_model hysteretic -material_soil_backbone mkz -material_soil_reference_strain 1e-3 -material_soil_surfaces 200"
$SW -mesh_box_faces 1,1 -mesh_box_upper 1,1 $soil $hyst $drive -bc_top_components x -constrain_components y -station_coordinates 0.3,0.6 \
  -output_interval 0.25 -output_dir "$WORK/hysteretic" > /dev/null
$PY tests/tools/hysteretic.py station "$WORK/hysteretic" S1 --gmax 8e7 --reference-strain 1e-3 --amplitude $A --f0 1 --height 1 --surfaces 200
$SW -mesh_box_faces 1,1 -mesh_box_upper 1,1 $soil $drive -output_fields 0 -station_coordinates 0.7,0.2 -output_dir "$WORK/elastic2d" > /dev/null
$SW -mesh_dim 3 -mesh_box_faces 1,1,1 -mesh_box_upper 1,1,1 $soil $drive -output_fields 0 -station_coordinates 0.7,0.2,0.4 -output_dir "$WORK/elastic3d" > /dev/null
$PY - "$WORK" "$A" <<'PY'
import sys
import numpy as np
sys.path.insert(0, "python")
from slipwave import RunFolder
work, A = sys.argv[1], float(sys.argv[2])
mu, lam = 2000 * 200.0**2, 2000 * 400.0**2 - 2 * 2000 * 200.0**2
ok = True
for case, dim in (("elastic2d", 2), ("elastic3d", 3)):
    run = RunFolder(f"{work}/{case}")
    d, h5 = run.station("S1"), run.station("S1", "h5")
    u = A * (1 - np.cos(2 * np.pi * d["t"])) / (2 * np.pi)
    up = "y" if dim == 2 else "z"
    expect = {f"e_{up}{up}": u}
    expect.update({f"e_x{up}" if dim == 2 else f"e_{c}{up}": u / 2 for c in ("x", "y")})
    strains = [c for c in d.names if c.startswith("e_")]
    err_e = max(np.max(np.abs(d[c] - expect.get(c, 0 * u))) for c in strains) / np.max(u)
    e = {c[2:]: d[c] for c in strains}
    zero = 0 * u
    tr = e["xx"] + e["yy"] + e.get("zz", zero)
    sigma = {"xx": lam * tr + 2 * mu * e["xx"], "yy": lam * tr + 2 * mu * e["yy"], "zz": lam * tr + 2 * mu * e.get("zz", zero),
             "xy": 2 * mu * e["xy"], "yz": 2 * mu * e.get("yz", zero), "xz": 2 * mu * e.get("xz", zero)}
    stresses = [c for c in d.names if c.startswith("s_")]
    peak = max(np.max(np.abs(d[c])) for c in stresses)
    err_s = max(np.max(np.abs(d[c] - sigma[c[2:]])) for c in stresses) / peak
    same = d.names == h5.names and all(np.array_equal(d[c], h5[c]) for c in d.names)
    want = ["s_xx", "s_yy", "s_zz", "s_xy"] + (["s_yz", "s_xz"] if dim == 3 else []) + (["e_xx", "e_yy", "e_xy"] if dim == 2 else
                                                                                        ["e_xx", "e_yy", "e_zz", "e_xy", "e_yz", "e_xz"])
    print(f"{case}: columns {','.join(d.names[1 + 3 * dim:])}; strain within {err_e:.2e} of its peak (bound 1e-5); stress - C eps {err_s:.1e} "
          f"of its peak {peak:.4g} Pa (bound 1e-12); CSV = stations.h5: {same}")
    ok = ok and list(d.names[1 + 3 * dim:]) == want and err_e <= 1e-5 and err_s <= 1e-12 and same
sys.exit(0 if ok else 1)
PY
