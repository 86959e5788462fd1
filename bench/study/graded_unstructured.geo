// The default scene's geometry (config/scenes/default.yaml) meshed with quadrilaterals whose
// size grows from `fine` m at the block's base (both edges and between them) by `grow` m per
// metre of distance, up to 1 m (docs/convergence-study.md, "Cells graded toward the block
// without the rock's columns"). Unlike graded_mesh.py's structured cells, whose fine columns
// run down through the rock (vp 1600 m/s: they set the step), the fine cells stay in the clay.
// Physical groups: surfaces rock, soil_low, soil_mid, soil_far and soil (the top sublayer,
// soil within 14 m of the block as in the scene), block; curves bottom, left, right.
//   gmsh -2 bench/study/graded_unstructured.geo -setnumber fine 0.125 -format msh41 -o g.msh
// then config/scenes/default.yaml less its mesh_box_*, region_*, regions, void_regions and
// mesh_dim lines, with -mesh_file g.msh -regions rock,soil_low,soil_mid,soil_far,soil,block
// (bench/cases/default_scene_mass_scaling.sh).
If (!Exists(fine)) fine = 0.125; EndIf
If (!Exists(grow)) grow = 0.2; EndIf
Point(1) = {-61, -20, 0}; Point(2) = {61, -20, 0};
Point(3) = {-61, 0, 0};   Point(4) = {61, 0, 0};
Point(5) = {-61, 10, 0};  Point(6) = {61, 10, 0};
Point(7) = {-61, 20, 0};  Point(8) = {61, 20, 0};
Point(9) = {-61, 30, 0};  Point(10) = {61, 30, 0};
Point(11) = {-3, 30, 0};  Point(12) = {3, 30, 0};
Point(13) = {-3, 40, 0};  Point(14) = {3, 40, 0};
Point(15) = {-17, 20, 0}; Point(16) = {17, 20, 0};
Point(17) = {-17, 30, 0}; Point(18) = {17, 30, 0};
Line(1) = {1, 2}; Line(2) = {3, 4}; Line(3) = {5, 6};
Line(4) = {7, 15}; Line(19) = {15, 16}; Line(20) = {16, 8};
Line(5) = {9, 17}; Line(21) = {17, 11}; Line(6) = {11, 12}; Line(22) = {12, 18}; Line(7) = {18, 10};
Line(8) = {1, 3}; Line(9) = {3, 5}; Line(10) = {5, 7}; Line(11) = {7, 9};
Line(12) = {2, 4}; Line(13) = {4, 6}; Line(14) = {6, 8}; Line(15) = {8, 10};
Line(16) = {11, 13}; Line(17) = {13, 14}; Line(18) = {14, 12};
Line(23) = {15, 17}; Line(24) = {16, 18};
Curve Loop(1) = {1, 12, -2, -8};                 Plane Surface(1) = {1};
Curve Loop(2) = {2, 13, -3, -9};                 Plane Surface(2) = {2};
Curve Loop(3) = {3, 14, -20, -19, -4, -10};      Plane Surface(3) = {3};
Curve Loop(4) = {19, 24, -22, -6, -21, -23};     Plane Surface(4) = {4};
Curve Loop(5) = {6, -18, -17, -16};              Plane Surface(5) = {5};
Curve Loop(6) = {4, 23, -5, -11};                Plane Surface(6) = {6};
Curve Loop(7) = {20, 15, -7, -24};               Plane Surface(7) = {7};
Physical Surface("rock") = {1};
Physical Surface("soil_low") = {2};
Physical Surface("soil_mid") = {3};
Physical Surface("soil_far") = {6, 7};
Physical Surface("soil") = {4};
Physical Surface("block") = {5};
Physical Curve("bottom") = {1};
Physical Curve("left") = {8, 9, 10, 11};
Physical Curve("right") = {12, 13, 14, 15};
// Size: fine at the block's base, growing linearly with the distance to it, at most 1 m.
Field[1] = Distance;
Field[1].CurvesList = {6};
Field[2] = MathEval;
Field[2].F = Sprintf("Min(1, %g + %g * F1)", fine, grow);
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 1;
Mesh.RecombineAll = 1;
