// 1D SV column on quadrilaterals recombined from a transfinite triangulation: 2 x 100 cells
// of 1 m on a 2 m x 100 m rectangle, i.e. the same grid as -mesh_box_faces 2,100, read
// through Gmsh (physical groups, face labels, Gmsh's vertex order).
W = 2; H = 100;
Point(1) = {0, 0, 0}; Point(2) = {W, 0, 0}; Point(3) = {W, H, 0}; Point(4) = {0, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 3;
Transfinite Curve{2, 4} = 101;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Surface("soil") = {1};
