// The cover annulus R1 <= r <= R0, 0 <= theta <= Sector (default 90 deg)
// meshed with unstructured quadrilaterals (a free triangulation recombined
// and split once more, so every cell is a quadrilateral), the cells sized
// by their distance from the nip at (R0, 0): H near the nip growing to
// HFar beyond Reach. A cross-section drawn the way a user draws one for a
// roll whose cover gmsh cannot mesh with a structured grid; for 2D
// (Mesh/Source = gmsh) or the 3D body (Three d/Enabled, extruded along
// the face).
//
// Boundary ids = Physical Curve tags as in quarter_roll.geo:
//   0 inner arc r = R1, 1 outer arc r = R0, 2 symmetry edge theta = 0,
//   3 far edge theta = Sector; the cover is Physical Surface 0.
//
//   gmsh -2 -format msh2 meshes/quarter_roll_free.geo -o free.msh
// (the final split halves H and HFar: the cells are about H/2 at the nip).

DefineConstant[
  R1     = {47.2, Name "Parameters/R1 inner radius [mm]"},
  R0     = {60.7, Name "Parameters/R0 outer radius [mm]"},
  Sector = {90,   Name "Parameters/Sector angle [deg], 0 < Sector <= 180"},
  H      = {3,    Name "Parameters/Cell size at the nip [mm] (before the split)"},
  HFar   = {12,   Name "Parameters/Cell size far from the nip [mm] (before the split)"},
  Reach  = {40,   Name "Parameters/Distance from the nip over which the size grows [mm]"}
];

If (R1 <= 0 || R0 <= R1 || Sector <= 0 || Sector > 180)
  Error("quarter_roll_free.geo: need 0 < R1 < R0 and 0 < Sector <= 180");
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

// Size: H at the nip point (R0, 0), growing linearly to HFar at Reach.
Field[1] = Distance;
Field[1].PointsList = {3};
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

Recombine Surface {1};
Mesh.SubdivisionAlgorithm = 1; // all quadrilaterals

Physical Curve(0) = {3, 4}; // inner arc r = R1
Physical Curve(1) = {5, 6}; // outer arc r = R0
Physical Curve(2) = {1};    // symmetry edge theta = 0
Physical Curve(3) = {2};    // far edge theta = Sector
Physical Surface(0) = {1};
