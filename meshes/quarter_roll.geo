// Quarter (or any sector up to 180 deg) of the rubber roll cover: the
// annulus R1 <= r <= R0, 0 <= theta <= Sector, meshed with quadrilaterals
// only (structured/transfinite, recombined).
//
// Boundary ids = Physical Curve tags (the convention of
// include/rollnip/boundary_ids.h and doc/physics.md, section 1):
//   0  inner arc r = R1        (bond surface)
//   1  outer arc r = R0        (cover surface)
//   2  symmetry edge X2 = 0    (theta = 0, the line of centres)
//   3  far edge                (theta = Sector)
// The cover itself is Physical Surface 0 (the material id).
//
// Make a mesh that rollnip reads (Mesh/Source = gmsh):
//   gmsh -2 -format msh2 meshes/quarter_roll.geo -o quarter_roll.msh
// Any parameter below can be overridden on the command line, e.g.
//   gmsh -2 -format msh2 -setnumber NTheta 32 meshes/quarter_roll.geo -o q.msh
// R1, R0 and Sector must match Geometry/Inner radius, Outer radius and
// Sector angle of the .prm file.

// ---- parameters -----------------------------------------------------------
DefineConstant[
  R1      = {47.2, Name "Parameters/R1 inner radius [mm]"},
  R0      = {60.7, Name "Parameters/R0 outer radius [mm]"},
  Sector  = {90,   Name "Parameters/Sector angle [deg], 0 < Sector <= 180"},
  NR      = {4,    Name "Parameters/Cells through the thickness"},
  NTheta  = {16,   Name "Parameters/Cells along the sector"},
  // Widest over narrowest cell along theta; the narrow cells are at
  // theta = 0 (the nip). 1 = uniform. Same meaning as rollnip's
  // Mesh/Circumferential grading.
  GradeTheta = {8, Name "Parameters/Circumferential grading (>= 1)"},
  // Outermost over innermost cell thickness; < 1 refines towards r = R0.
  // Same meaning as rollnip's Mesh/Radial grading.
  GradeR  = {1,    Name "Parameters/Radial grading"}
];
// ---------------------------------------------------------------------------

If (R1 <= 0 || R0 <= R1)
  Error("quarter_roll.geo: need 0 < R1 < R0");
  Abort;
EndIf
If (Sector <= 0 || Sector > 180)
  Error("quarter_roll.geo: need 0 < Sector <= 180");
  Abort;
EndIf
If (NR < 1 || NTheta < 2)
  Error("quarter_roll.geo: need NR >= 1 and NTheta >= 2");
  Abort;
EndIf

alpha = Sector * Pi / 180;

// Geometric cell widths along theta: w_k = w_0 g^k, g^(NTheta-1) = GradeTheta.
g = GradeTheta^(1 / (NTheta - 1));
// A gmsh circle arc must span less than 180 deg, so the sector is built from
// two arcs. They meet at a cell boundary of the graded division (so the
// grading is one geometric sequence across the joint), the one closest to
// the middle of the sector.
nSplit = 1;
For k In {1 : NTheta - 1}
  If (g == 1)
    fk = k / NTheta;
  Else
    fk = (g^k - 1) / (g^NTheta - 1);
  EndIf
  If (g == 1)
    fs = nSplit / NTheta;
  Else
    fs = (g^nSplit - 1) / (g^NTheta - 1);
  EndIf
  If (Fabs(fk - 0.5) < Fabs(fs - 0.5))
    nSplit = k;
  EndIf
EndFor
If (g == 1)
  beta = alpha * nSplit / NTheta;
Else
  beta = alpha * (g^nSplit - 1) / (g^NTheta - 1);
EndIf

// Points: the centre, then inner/outer at theta = 0, beta (joint), alpha.
Point(1) = {0, 0, 0};
Point(2) = {R1, 0, 0};
Point(3) = {R0, 0, 0};
Point(4) = {R1 * Cos(beta), R1 * Sin(beta), 0};
Point(5) = {R0 * Cos(beta), R0 * Sin(beta), 0};
Point(6) = {R1 * Cos(alpha), R1 * Sin(alpha), 0};
Point(7) = {R0 * Cos(alpha), R0 * Sin(alpha), 0};

// Radial lines, all from r = R1 to r = R0.
Line(1) = {2, 3}; // theta = 0: symmetry edge
Line(2) = {4, 5}; // the joint (interior)
Line(3) = {6, 7}; // theta = Sector: far edge
// Arcs, all in the direction of increasing theta.
Circle(4) = {2, 1, 4}; // inner, first part
Circle(5) = {4, 1, 6}; // inner, second part
Circle(6) = {3, 1, 5}; // outer, first part
Circle(7) = {5, 1, 7}; // outer, second part

Curve Loop(1) = {1, 6, -2, -4};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 7, -3, -5};
Plane Surface(2) = {2};

// Structured quadrilateral mesh.
Transfinite Curve {1, 2, 3} = NR + 1 Using Progression GradeR^(1 / Max(NR - 1, 1));
Transfinite Curve {4, 6} = nSplit + 1 Using Progression g;
Transfinite Curve {5, 7} = NTheta - nSplit + 1 Using Progression g;
Transfinite Surface {1} = {2, 3, 5, 4};
Transfinite Surface {2} = {4, 5, 7, 6};
Recombine Surface {1, 2};

// Tags = rollnip boundary ids (see the header).
Physical Curve(0) = {4, 5}; // inner arc r = R1
Physical Curve(1) = {6, 7}; // outer arc r = R0
Physical Curve(2) = {1};    // symmetry edge theta = 0
Physical Curve(3) = {3};    // far edge theta = Sector
Physical Surface(0) = {1, 2};
