// 1D SV column on non-affine quadrilaterals: a 10 m x 100 m rectangle cut into four macro
// quadrilaterals that meet at the off-centre point (6, 56) (joined to the side midpoints),
// each meshed transfinitely with nx x ny cells (-setnumber nx, ny). Every cell is the image
// of a square under a bilinear map that is no parallelogram, and refinement (nx, ny doubled)
// subdivides the macro quadrilaterals uniformly in their parameters: the usual setting in
// which isoparametric elements of degree p keep their order p + 1 (tests/cases/sem_convergence_warped.sh).
DefineConstant[ nx = 1, ny = 7 ];
W = 10; H = 100;
Point(1) = {0, 0, 0}; Point(2) = {W / 2, 0, 0}; Point(3) = {W, 0, 0};
Point(4) = {0, H / 2, 0}; Point(5) = {6, 56, 0}; Point(6) = {W, H / 2, 0};
Point(7) = {0, H, 0}; Point(8) = {W / 2, H, 0}; Point(9) = {W, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {4, 5}; Line(4) = {5, 6}; Line(5) = {7, 8}; Line(6) = {8, 9};
Line(7) = {1, 4}; Line(8) = {2, 5}; Line(9) = {3, 6}; Line(10) = {4, 7}; Line(11) = {5, 8}; Line(12) = {6, 9};
Curve Loop(1) = {1, 8, -3, -7}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 9, -4, -8}; Plane Surface(2) = {2};
Curve Loop(3) = {3, 11, -5, -10}; Plane Surface(3) = {3};
Curve Loop(4) = {4, 12, -6, -11}; Plane Surface(4) = {4};
Transfinite Curve{1, 2, 3, 4, 5, 6} = nx + 1;
Transfinite Curve{7, 8, 9, 10, 11, 12} = ny + 1;
Transfinite Surface{1, 2, 3, 4};
Recombine Surface{1, 2, 3, 4};
Physical Curve("bottom") = {1, 2};
Physical Curve("right") = {9, 12};
Physical Curve("top") = {5, 6};
Physical Curve("left") = {7, 10};
Physical Surface("soil") = {1, 2, 3, 4};
