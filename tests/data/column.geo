// The 1D column of tests/cases/convergence_check_column.sh as a Gmsh file: 1 m x 100 m, one
// cell across, 200 cells along it at the size factor 1 (gmsh -clscale f: 200 / f cells, the
// structured counts following the factor as Gmsh's sizes do), the same cells as
// -mesh_box_faces 1,200 -mesh_box_upper 1,100. Physical groups: surface soil, curves bottom, top.
N = Round(200 / Mesh.MeshSizeFactor);
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 100, 0}; Point(4) = {0, 100, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{2, 4} = N + 1;
Transfinite Curve{1, 3} = 2;
Transfinite Surface{1};
Recombine Surface{1};
Physical Surface("soil") = {1};
Physical Curve("bottom") = {1};
Physical Curve("top") = {3};
