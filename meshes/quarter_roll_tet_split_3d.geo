// The cover of quarter_roll_free.geo drawn in 3D with cells that are not in
// layers along the roll axis: the sector R1 <= r <= R0, 0 <= theta <=
// Sector, 0 <= z <= SliceThickness meshed with tetrahedra, each split by
// gmsh into 4 hexahedra (Mesh.SubdivisionAlgorithm = 2). No cell lies
// between two planes z = const; rollnip reads it as drawn (doc/three_d.md,
// "A gmsh mesh drawn in 3D") and gives the line load along the axis at
// stations (see there).
//
// Boundary ids = Physical Surface tags, as in quarter_roll_free_3d.geo:
//   0 inner arc r = R1 (bond), 1 outer arc r = R0, 2 symmetry plane
//   theta = 0 (through the nip), 3 far edge theta = Sector,
//   4 symmetry plane z = 0 (the middle of the face), 5 far face
//   z = SliceThickness; the cover is Physical Volume 0.
//
//   gmsh -3 -format msh2 meshes/quarter_roll_tet_split_3d.geo -o split.msh
//
// The cells are sized by their distance from the nip line (R0, 0, z): H
// there, growing to HFar over Reach (the split halves them). SliceThickness
// must match Three d/Slice thickness.
DefineConstant[
  R1     = {47.2, Name "Parameters/R1 inner radius [mm]"},
  R0     = {60.7, Name "Parameters/R0 outer radius [mm]"},
  Sector = {90,   Name "Parameters/Sector angle [deg], 0 < Sector <= 180"},
  H      = {3,    Name "Parameters/Cell size at the nip [mm] (before the split)"},
  HFar   = {12,   Name "Parameters/Cell size far from the nip [mm] (before the split)"},
  Reach  = {40,   Name "Parameters/Distance from the nip over which the size grows [mm]"},
  SliceThickness = {20, Name "Parameters/Length along the roll axis [mm]"}
];
If (R1 <= 0 || R0 <= R1 || Sector <= 0 || Sector > 180 || SliceThickness <= 0)
  Error("quarter_roll_tet_split_3d.geo: need 0 < R1 < R0, 0 < Sector <= 180, SliceThickness > 0");
  Abort;
EndIf

alpha = Sector * Pi / 180;
beta = alpha / 2; // a gmsh circle arc spans less than 180 deg: two arcs

Point(1) = {0, 0, 0};
Point(2) = {R1, 0, 0};
Point(3) = {R0, 0, 0};
Point(4) = {R1 * Cos(beta), R1 * Sin(beta), 0};
Point(5) = {R0 * Cos(beta), R0 * Sin(beta), 0};
Point(6) = {R1 * Cos(alpha), R1 * Sin(alpha), 0};
Point(7) = {R0 * Cos(alpha), R0 * Sin(alpha), 0};

Line(1) = {2, 3};      // theta = 0: symmetry edge
Line(2) = {6, 7};      // theta = Sector: far edge
Circle(3) = {2, 1, 4}; // inner arc
Circle(4) = {4, 1, 6};
Circle(5) = {3, 1, 5}; // outer arc
Circle(6) = {5, 1, 7};
Curve Loop(1) = {1, 5, 6, -2, -4, -3};
Plane Surface(1) = {1};

// out[0]: the face z = SliceThickness, out[1]: the volume, out[2..7]: the
// sides swept by the curves of Curve Loop(1) = {1, 5, 6, -2, -4, -3}.
out[] = Extrude {0, 0, SliceThickness} { Surface{1}; };

// Size: H on the nip line (R0, 0, z), growing linearly to HFar at Reach.
Field[1] = MathEval;
Field[1].F = Sprintf("Sqrt((x - %g)^2 + y^2)", R0);
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = H;
Field[2].SizeMax = HFar;
Field[2].DistMin = 0;
Field[2].DistMax = Reach;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.SubdivisionAlgorithm = 2; // every tetrahedron into 4 hexahedra

Physical Surface(0) = {out[6], out[7]}; // inner arc r = R1
Physical Surface(1) = {out[3], out[4]}; // outer arc r = R0
Physical Surface(2) = {out[2]};         // symmetry plane theta = 0
Physical Surface(3) = {out[5]};         // far edge theta = Sector
Physical Surface(4) = {1};              // symmetry plane z = 0
Physical Surface(5) = {out[0]};         // far face z = SliceThickness
Physical Volume(0) = {out[1]};
