# Rank independence with hysteretic soil (issue 22): the 2D two-material box of
# tests/cases/hysteretic_energy.sh (hysteretic MKZ soil around an elastic block, yielding),
# with stations, on 1 and 2 ranks (METIS partition). Each node's force, the relaxation force
# included, is the same sum in a different order and the Iwan update of a point does not
# depend on the rank, so records agree to round-off: 1e-10 of each quantity's peak, the
# energy ledgers to 1e-10 of the largest energy (as tests/cases/mpi_ranks.sh). Accelerations:
# 1e-9 (measured 8e-11): a yielding surface switches the force by a kink, so a round-off
# difference in the strain becomes a larger one in the force than in a linear run. The
# stations record their cell's stress and strain too (-station_stress; two of them on cell
# corners, where the cell is chosen by its centroid, not by the partition): 1e-10 as u.
set -eu
. tests/tools/lib.sh
opts="-mesh_box_faces 12,8 -mesh_box_upper 30,20 -regions soil,block -region_block_box 10,20,10,20 -material_soil_rho 1800 -material_soil_vp 600
  -material_soil_vs 250 -material_soil_model hysteretic -material_soil_backbone mkz -material_soil_reference_strain 3e-4 -material_soil_curvature 0.9
  -material_soil_strength 6e4 -material_block_rho 2500 -material_block_E 3e10 -material_block_nu 0.2 -initial_velocity 0.1,0.05
  -bc_bottom_type fixed -ts_max_steps 2000 -ts_max_time 1e9 -output_fields 0 -progress_interval 1000
  -station_coordinates 5,20,15,20,25,10 -station_names a,b,c -station_stress true"
$SW $opts -output_dir "$WORK/np1" > /dev/null
$MPIEXEC -n 2 $SW $opts -output_dir "$WORK/np2" > /dev/null
$CHECK stations-equal "$WORK/np1" "$WORK/np2" --names a,b,c --tol 1e-10 --tol-a 1e-9
$CHECK energy-equal "$WORK/np1/energy.csv" "$WORK/np2/energy.csv" --tol 1e-10
# The same at element degree 3 (6 x 4 elements, the stress at the GLL nodes), a GQ/H soil
# (tau_max 50 kPa; theta as published forms go, here -7,-1,1,1,0.8: G/Gmax 0.49 at 1e-4):
# rank independence with the same bounds, and the ledger closed (1e-9, as above).
opts3="-mesh_box_faces 6,4 -element_degree 3 -mesh_box_upper 30,20 -regions soil -material_soil_rho 1800 -material_soil_vp 600 -material_soil_vs 250
  -material_soil_model hysteretic -material_soil_backbone gqh -material_soil_strength 5e4 -material_soil_gqh_theta -7,-1,1,1,0.8 -initial_velocity 0.1,0.05
  -bc_bottom_type fixed -ts_max_steps 2000 -ts_max_time 1e9 -output_fields 0 -progress_interval 1000 -energy_interval 1
  -station_coordinates 5,20,15,20,25,10 -station_names a,b,c -station_stress true"
$SW $opts3 -output_dir "$WORK/p3_np1" > /dev/null
$MPIEXEC -n 2 $SW $opts3 -output_dir "$WORK/p3_np2" > /dev/null
$CHECK energy "$WORK/p3_np1/energy.csv" --max-error 1e-9 --min-rows 2001
$CHECK stations-equal "$WORK/p3_np1" "$WORK/p3_np2" --names a,b,c --tol 1e-10 --tol-a 1e-9
$CHECK energy-equal "$WORK/p3_np1/energy.csv" "$WORK/p3_np2/energy.csv" --tol 1e-10
