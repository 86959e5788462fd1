// A half-space on unstructured linear triangles for the Domain Reduction Method: 200 m x
// 100 m (x from -100 to 100, y from -100 to 0), target size 1.25 m (Frontal-Delaunay). The
// DRM interior is the region "inner" (x in [-95, 95], y >= -95); "outer" is the band around
// it, whose cells along the inner boundary form the DRM layer. Physical names of the sides
// follow the built-in box.
lc = 1.25;
Point(1) = {-100, -100, 0, lc}; Point(2) = {100, -100, 0, lc}; Point(3) = {100, 0, 0, lc}; Point(4) = {95, 0, 0, lc};
Point(5) = {-95, 0, 0, lc}; Point(6) = {-100, 0, 0, lc}; Point(7) = {-95, -95, 0, lc}; Point(8) = {95, -95, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6}; Line(6) = {6, 1};
Line(7) = {5, 7}; Line(8) = {7, 8}; Line(9) = {8, 4};
Curve Loop(1) = {7, 8, 9, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {1, 2, 3, -9, -8, -7, 5, 6};
Plane Surface(2) = {2};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3, 4, 5};
Physical Curve("left") = {6};
Physical Surface("inner") = {1};
Physical Surface("outer") = {2};
Mesh.Algorithm = 6;
