// 1D SV column on unstructured quadrilaterals (Frontal-Delaunay triangles recombined): W = 8 m
// wide, H = 100 m high, target size 2.9 m (4x the 0.72 m of tests/cases/column_1d_sv.sh, for
// degree-4 elements). Irregular, non-affine elements: the spectral geometry is exercised
// where the box meshes' rectangles are not. Physical names follow the built-in box sides.
W = 8; H = 100; lc = 2.9;
Point(1) = {0, 0, 0, lc}; Point(2) = {W, 0, 0, lc}; Point(3) = {W, H, 0, lc}; Point(4) = {0, H, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Surface("soil") = {1};
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
