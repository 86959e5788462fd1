# Closed undamped system: a two-material 2D box and a 3D box, bottom fixed, released with a
# uniform initial velocity, 10,000 steps. Central difference at constant step conserves the
# shadow energy W = ½ v_{n+1/2}ᵀ M v_{n+1/2} + ½ u_nᵀ K u_{n+1} exactly in exact arithmetic
# (the identity is derived in include/slipwave/problem/energy_ledger.hpp); the ledger's balance
# error must stay at round-off: bound 1e-9 relative (issue 2).
# SEM_DEGREE=p runs it with ceil(N / p) elements of degree p per direction for N cells
# (tests/cases/sem_energy_closed.sh: the block region still spans whole elements).
set -eu
. tests/tools/lib.sh
# -energy_interval 1: this test reads the ledger at every step (row count, per-step rows).
common="-bc_bottom_type fixed -ts_max_steps 10000 -ts_max_time 1e9 -output_fields 0 -progress_interval 100 -energy_interval 1"
$SW -mesh_box_faces $(elements 12),$(elements 8) -element_degree $DEGREE -mesh_box_upper 30,20 -regions soil,block -region_block_box 10,20,10,20 \
  -material_soil_rho 1800 -material_soil_vp 600 -material_soil_vs 250 -material_block_rho 2500 -material_block_E 3e10 -material_block_nu 0.2 \
  -initial_velocity 0.1,0.05 $common -output_dir "$WORK/2d"
$CHECK energy "$WORK/2d/energy.csv" --max-error 1e-9 --min-rows 10001
$SW -mesh_dim 3 -mesh_box_faces $(elements 4),$(elements 4),$(elements 4) -element_degree $DEGREE -mesh_box_upper 10,10,10 -regions soil -material_soil_rho 1800 -material_soil_vp 600 -material_soil_vs 250 \
  -initial_velocity 0.1,0.05,0.02 $common -output_dir "$WORK/3d"
$CHECK energy "$WORK/3d/energy.csv" --max-error 1e-9 --min-rows 10001
