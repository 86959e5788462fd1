// The default scene's mesh (config/scenes/default.yaml; docs/default-scene.md, "The default since
// 2026-11-29"):
// 2D, x = -62..62 m, y = -20..30 m of ground (rock -20..0, the clay's sublayers 0..10, 10..20,
// 20..30) and the rigid block x = -3..3, y = 30..40 on it. Quadrilaterals of 1 m everywhere but
// in a window of the top sublayer around the block (x = -9..9, y = 24..30), where structured
// cells are graded geometrically from 1 m to FINE m (default 0.125) toward the block's edges
// (x = +-3) and base (y = 30): the edges' yielding under a rocking block converges only with
// cells a fraction of a metre wide there (docs/convergence-study.md, "Which limit"), and the
// window keeps the fine cells out of the rock, whose 1600 m/s would set the step.
// The sizes follow Gmsh's size factor (gmsh -clscale f, Mesh.MeshSizeFactor): f = 2 is the
// companion scripts/convergence_check.py --geo runs beside it (2 m, graded to 2 FINE m).
// Made at twice the size and split in four (Mesh.SubdivisionAlgorithm 1), so that the
// unstructured part holds no triangle. Physical groups: surfaces rock, soil_low, soil_mid,
// soil (the window), soil_far (the rest of the top sublayer), block;
// curves bottom, left, right. config/scenes/default.msh is this file's output (gmsh -2
// default.geo -format msh41 -o default.msh; tests/cases/default_mesh.sh checks it); another
// finest size: gmsh ... -setnumber fine 0.1.
DefineConstant[ fine = 0.125 ];
f = Mesh.MeshSizeFactor;
lc = 2;
big = 2 * f;
small = 2 * fine * f;
// Cells of a geometric progression from big toward small over L m: n6 over 6 m, n3 over 3 m
// (bench/study/graded_mesh.py's cells_for, in closed form); then the growth ratio r6, r3 of
// each that makes its first cell exactly small and its cells sum to L (bisection of
// small (r^n - 1) / (r - 1) = L), so that the finest cells are FINE f m at every factor.
n6 = 2;
If (6 > big)
  n6 = Max(2, Round(1 + Log(small / big) / Log((6 - big) / (6 - small))));
EndIf
n3 = 2;
If (3 > big)
  n3 = Max(2, Round(1 + Log(small / big) / Log((3 - big) / (3 - small))));
EndIf
lo6 = 1 + 1e-12; hi6 = 1e3; lo3 = lo6; hi3 = hi6;
For k In {1 : 200}
  r = (lo6 + hi6) / 2;
  If (small * (r ^ n6 - 1) / (r - 1) > 6)
    hi6 = r;
  Else
    lo6 = r;
  EndIf
  r = (lo3 + hi3) / 2;
  If (small * (r ^ n3 - 1) / (r - 1) > 3)
    hi3 = r;
  Else
    lo3 = r;
  EndIf
EndFor
q6 = 2 / (lo6 + hi6); // ratios along a line run from its coarse end to its fine end
q3 = 2 / (lo3 + hi3);
nb = Max(1, Round(5 / f)); // the block's height, 10 m (rigid: its cells carry its mass only)
// Outside the top sublayer's middle, structured cells of 2 f m (1 f m once split): nf across
// x = -62..-16 and 16..62, nr across -16..16, n20 and n10 over the rock's and the sublayers'
// depths, n8 along the surface from x = +-16 to the window. Only the ring x = -16..16 around
// the window is unstructured (its boundary counts sum to an even
// number at every factor, so that it can be all quadrilaterals): 16 % fewer cells than an
// unstructured far field, and the structured cells share one element matrix.
nf = Max(1, Round(46 / (2 * f)));
nr = Max(1, Round(32 / (2 * f)));
n20 = Max(1, Round(20 / (2 * f)));
n10 = Max(1, Round(10 / (2 * f)));
n8 = Max(1, Round(7 / (2 * f)));
Point(1) = {-62, -20, 0, lc}; Point(2) = {62, -20, 0, lc};
Point(3) = {-62, 0, 0, lc}; Point(4) = {62, 0, 0, lc};
Point(5) = {-62, 10, 0, lc}; Point(6) = {62, 10, 0, lc};
Point(7) = {-62, 20, 0, lc}; Point(8) = {-16, 20, 0, lc}; Point(9) = {16, 20, 0, lc}; Point(10) = {62, 20, 0, lc};
Point(11) = {-62, 30, 0, lc}; Point(12) = {-16, 30, 0, lc}; Point(13) = {16, 30, 0, lc}; Point(14) = {62, 30, 0, lc};
Point(15) = {-3, 40, 0, lc}; Point(16) = {0, 40, 0, lc}; Point(17) = {3, 40, 0, lc};
xs[] = {-9, -3, 0, 3, 9};
For i In {0 : 4}
  Point(20 + i) = {xs[i], 24, 0, lc}; // the window's bottom
  Point(30 + i) = {xs[i], 30, 0, lc}; // its top, the surface
EndFor
// the outline and the layers
Line(1) = {1, 2};                                        // bottom
Line(2) = {3, 4}; Line(3) = {5, 6};                      // rock / soil_low, soil_low / soil_mid
Line(4) = {7, 8}; Line(5) = {8, 9}; Line(6) = {9, 10};   // soil_mid / top sublayer
Line(7) = {1, 3}; Line(8) = {3, 5}; Line(9) = {5, 7}; Line(10) = {7, 11};    // left
Line(11) = {2, 4}; Line(12) = {4, 6}; Line(13) = {6, 10}; Line(14) = {10, 14}; // right
Line(15) = {8, 12}; Line(16) = {9, 13};                  // soil / soil_far
Line(17) = {11, 12}; Line(18) = {12, 30}; Line(19) = {34, 13}; Line(20) = {13, 14}; // free surface
// the window: its bottom (40..43) and top (50..53) graded toward x = -3 and 3, its columns'
// sides (60..64) toward the base, y = 30
nx[] = {n6, n3, n3, n6};
qx[] = {q6, 1 / q3, q3, 1 / q6};
For i In {0 : 3}
  Line(40 + i) = {20 + i, 21 + i}; Transfinite Curve{40 + i} = nx[i] + 1 Using Progression qx[i];
  Line(50 + i) = {30 + i, 31 + i}; Transfinite Curve{50 + i} = nx[i] + 1 Using Progression qx[i];
EndFor
For i In {0 : 4}
  Line(60 + i) = {20 + i, 30 + i}; Transfinite Curve{60 + i} = n6 + 1 Using Progression q6;
EndFor
// the block, two structured halves on the window's top
Line(70) = {31, 15}; Line(71) = {32, 16}; Line(72) = {33, 17};
Transfinite Curve{70, 71, 72} = nb + 1;
Line(73) = {15, 16}; Transfinite Curve{73} = n3 + 1 Using Progression 1 / q3;
Line(74) = {16, 17}; Transfinite Curve{74} = n3 + 1 Using Progression q3;
Transfinite Curve{1, 2, 3} = 2 * nf + nr + 1;
Transfinite Curve{4, 6, 17, 20} = nf + 1;
Transfinite Curve{5} = nr + 1;
Transfinite Curve{7, 11} = n20 + 1;
Transfinite Curve{8, 9, 10, 12, 13, 14, 15, 16} = n10 + 1;
Transfinite Curve{18, 19} = n8 + 1;
Curve Loop(1) = {1, 11, -2, -7}; Plane Surface(1) = {1};             // rock
Curve Loop(2) = {2, 12, -3, -8}; Plane Surface(2) = {2};             // soil_low
Curve Loop(3) = {3, 13, -6, -5, -4, -9}; Plane Surface(3) = {3};     // soil_mid
Curve Loop(4) = {4, 15, -17, -10}; Plane Surface(4) = {4};           // soil_far, left
Curve Loop(5) = {6, 14, -20, -16}; Plane Surface(5) = {5};           // soil_far, right
Curve Loop(6) = {5, 16, -19, -64, -43, -42, -41, -40, 60, -18, -15}; Plane Surface(6) = {6}; // soil around the window
For i In {0 : 3}
  Curve Loop(7 + i) = {40 + i, 61 + i, -(50 + i), -(60 + i)}; Plane Surface(7 + i) = {7 + i};
  Transfinite Surface{7 + i};
EndFor
Curve Loop(11) = {51, 71, -73, -70}; Plane Surface(11) = {11}; Transfinite Surface{11};
Curve Loop(12) = {52, 72, -74, -71}; Plane Surface(12) = {12}; Transfinite Surface{12};
Transfinite Surface{1}; Transfinite Surface{2};
Transfinite Surface{3} = {5, 6, 10, 7}; // soil_mid: its top is three lines
Transfinite Surface{4}; Transfinite Surface{5};
Recombine Surface{1 : 12};
Physical Surface("rock") = {1};
Physical Surface("soil_low") = {2};
Physical Surface("soil_mid") = {3};
Physical Surface("soil_far") = {4, 5, 6}; // the far field and the ring around the window
Physical Surface("soil") = {7, 8, 9, 10}; // the window
Physical Surface("block") = {11, 12};
Physical Curve("bottom") = {1};
Physical Curve("left") = {7, 8, 9, 10};
Physical Curve("right") = {11, 12, 13, 14};
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
