// 1D SV column on unstructured linear tetrahedra: 2 m x 2 m x 100 m (z up), target size
// 1 m. Sides named like the built-in 3D box: left/right (x), front/back (y), bottom/top (z).
SetFactory("OpenCASCADE");
W = 2; H = 100; e = 1e-6;
Box(1) = {0, 0, 0, W, W, H};
Physical Volume("soil") = {1};
Physical Surface("left") = Surface In BoundingBox{-e, -e, -e, e, W + e, H + e};
Physical Surface("right") = Surface In BoundingBox{W - e, -e, -e, W + e, W + e, H + e};
Physical Surface("front") = Surface In BoundingBox{-e, -e, -e, W + e, e, H + e};
Physical Surface("back") = Surface In BoundingBox{-e, W - e, -e, W + e, W + e, H + e};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -e, W + e, W + e, e};
Physical Surface("top") = Surface In BoundingBox{-e, -e, H - e, W + e, W + e, H + e};
Mesh.MeshSizeMin = 1;
Mesh.MeshSizeMax = 1;
