# Hysteretic soil through the whole program (issue 22): one cell in strain-controlled cyclic
# simple shear, a Quad4 and a Hex8 (bottom fixed, top driven in x by a harmonic velocity,
# the other components held: the strain is uniform). Hyperbolic backbone (MKZ, s = beta = 1),
# gamma_r = 1e-3, Gmax = 2000 x 200^2 = 8e7 Pa; strain to gamma_m = A/(pi f H) = 4e-3
# (G/Gmax 0.2) and back to 0 and up again. tests/tools/hysteretic.py reads the shear stress
# from the supports' work in energy.csv and checks it against Masing's rules on the continuous
# hyperbola (closed forms there), and the work and loop area against their integrals; the
# bounds are the error of N = 200 surfaces (docs/hysteretic-soil.md). The ledger's balance
# stays at round-off (bound 1e-9 relative, as tests/cases/energy_closed.sh). The 2D run's
# volume output (stress, max_shear_strain, secant_modulus_ratio) is checked at every T/4.
set -eu
. tests/tools/lib.sh
A=0.012566370614359173 # pi f gamma_m H = pi x 1 x 4e-3 x 1 [m/s]
soil="-regions soil -material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_model hysteretic -material_soil_backbone mkz
  -material_soil_reference_strain 1e-3 -material_soil_surfaces 200"
# Every node is prescribed, so no stable step bounds dt: 1 ms, 1000 steps per cycle.
drive="-bc_bottom_type fixed -bc_top_type velocity -bc_top_components x -bc_top_stf harmonic -bc_top_f0 1 -bc_top_amplitude $A
  -ts_max_time 1.5 -ts_dt 1e-3 -output_fields 0 -energy_interval 1 -progress_interval 1000"
$SW -mesh_box_faces 1,1 -mesh_box_upper 1,1 $soil $drive -constrain_components y -output_fields 1 -output_interval 0.25 -output_dir "$WORK/2d" > "$WORK/2d.log"
grep -q "region soil: hysteretic soil (Masing, parallel Iwan), backbone mkz, gamma_r 0.001" "$WORK/2d.log"
$CHECK energy "$WORK/2d/energy.csv" --max-error 1e-9 --min-rows 1501
$PY tests/tools/hysteretic.py loop "$WORK/2d/energy.csv" --gmax 8e7 --reference-strain 1e-3 --amplitude $A --f0 1 --height 1 --volume 1 --area 1 --rho 2000 --surfaces 200
# The volume output every T/4: the cell's stress, largest shear strain and secant G/Gmax.
$PY tests/tools/hysteretic.py frames "$WORK/2d" --gmax 8e7 --reference-strain 1e-3 --amplitude $A --f0 1 --height 1 --surfaces 200
$SW -mesh_dim 3 -mesh_box_faces 1,1,1 -mesh_box_upper 1,1,1 $soil $drive -constrain_components y,z -output_dir "$WORK/3d" > /dev/null
$CHECK energy "$WORK/3d/energy.csv" --max-error 1e-9 --min-rows 1501
$PY tests/tools/hysteretic.py loop "$WORK/3d/energy.csv" --gmax 8e7 --reference-strain 1e-3 --amplitude $A --f0 1 --height 1 --volume 1 --area 1 --rho 2000 --surfaces 200
