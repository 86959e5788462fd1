# Mandel's problem (plane strain; Cheng & Detournay 1988; series in tests/tools/poroelastic.py):
# a quarter of a 2 m x 2 m saturated specimen (20 x 20 cells; symmetry: x held on the left,
# y held at the bottom, both impervious), drained free right side, pressed by 100 kPa through
# a stiff plate (0.25 m, vp 8000 m/s) on a frictionless interface (phi = 0, penalty factor
# 100), which stands for Mandel's rigid frictionless plate. Water in a soft soil (nu 1/3,
# nu_u 0.493, B 0.963): the centre pressure rises to 1.062 p0 (the Mandel-Cryer effect) before
# it drains. Checked within 2 % (issue 10): the centre peak, the time the centre pressure is
# back at p0 (0.0848 s; the peak itself is too flat to time), and p at the centre and at
# x = 0.5 m over [0.03, 0.3] s against p0. Measured when written: 0.7 %, 1.5 %, 1.1 % and
# 0.85 % of p0; the plate's finite stiffness is most of it (a 0.05 m plate at vp 4000: 4.8 %).
# Explicit dynamics for consolidation as in saturated_terzaghi.sh: k = 5e-5 m/s puts a^2/c =
# 0.65 s a thousand times above the undrained transit; mass-proportional damping (alpha ~ 300
# 1/s) removes the load's ringing by t = 0.03 s (its drag ~ alpha rho a^2/(E a^2/c) = 0.3 %).
set -eu
. tests/tools/lib.sh
SAT="-material_soil_rho 2000 -material_soil_vp 400 -material_soil_vs 200 -material_soil_saturated -material_soil_porosity 0.4 -material_soil_hydraulic_conductivity 5e-5"
$SW -mesh_box_faces 20,25 -mesh_box_upper 1,1.25 -regions soil,plate -region_plate_box 0,1,1,1.25 $SAT -material_plate_rho 2400 -material_plate_vp 8000 \
  -material_plate_vs 4000 -interfaces top -interface_top_regions soil,plate -interface_top_phi 0 -interface_top_penalty_rule mesh -interface_top_penalty_factor 100 -bc_left_type fixed \
  -bc_left_components x -bc_bottom_type fixed -bc_bottom_components y -bc_top_type traction -bc_top_traction 0,-1e5 -bc_right_fluid drained \
  -damping_ratio 0.24 -damping_frequencies 100,1e6 -ts_max_time 0.3 -station_coordinates 0,0.5,0.5,0.5 -station_names centre,mid -output_fields 0 \
  -progress_interval 100 -output_dir "$WORK" | grep -E "done"
$PY tests/tools/poroelastic.py mandel "$WORK" --half-width 1 --load 1e5 --stations centre:0,mid:0.5 --t1 0.03 --t-end 0.3 --rho 2000 --vp 400 --vs 200 \
  --porosity 0.4 --hydraulic-conductivity 5e-5
