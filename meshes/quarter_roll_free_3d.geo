// The cover of quarter_roll_free.geo drawn in 3D: its unstructured
// quadrilateral cross-section (the same points, curves, sizes) extruded
// along the roll axis z from 0 to SliceThickness in NLayers layers and
// recombined, so that every cell is a hexahedron. For the 3D body
// (Three d/Enabled = true, Mesh/Source = gmsh), which reads a 3D mesh as
// drawn (doc/three_d.md, "A gmsh mesh drawn in 3D").
//
// Boundary ids = Physical Surface tags (include/rollnip/boundary_ids.h and
// include/rollnip/three_d/slice_mesh.h):
//   0 inner arc r = R1 (bond), 1 outer arc r = R0, 2 symmetry plane
//   theta = 0 (through the nip), 3 far edge theta = Sector,
//   4 symmetry plane z = 0 (the middle of the face), 5 far face
//   z = SliceThickness; the cover is Physical Volume 0.
//
//   gmsh -3 -format msh2 meshes/quarter_roll_free_3d.geo -o free_3d.msh
//
// The final split (Mesh.SubdivisionAlgorithm = 2) cuts every hexahedron
// into 8, as quarter_roll_free.geo cuts every quadrilateral into 4: the
// mesh has 2 NLayers layers, and its cross-section is the 2D mesh of
// quarter_roll_free.geo with the same R1, R0, Sector, H, HFar and Reach.
// SliceThickness must match Three d/Slice thickness.

DefineConstant[
  SliceThickness = {1, Name "Parameters/Length along the roll axis [mm]"},
  NLayers        = {1, Name "Parameters/Layers along the axis (before the split)"}
];
If (SliceThickness <= 0 || NLayers < 1)
  Error("quarter_roll_free_3d.geo: need SliceThickness > 0 and NLayers >= 1");
  Abort;
EndIf

Include "quarter_roll_free.geo";
Delete Physicals;

// out[0]: the face z = SliceThickness, out[1]: the volume, out[2..7]: the
// sides swept by the curves of Curve Loop(1) = {1, 5, 6, -2, -4, -3}.
out[] = Extrude {0, 0, SliceThickness} {
  Surface{1}; Layers{NLayers}; Recombine;
};
Mesh.SubdivisionAlgorithm = 2; // all hexahedra

Physical Surface(0) = {out[6], out[7]}; // inner arc r = R1
Physical Surface(1) = {out[3], out[4]}; // outer arc r = R0
Physical Surface(2) = {out[2]};         // symmetry plane theta = 0
Physical Surface(3) = {out[5]};         // far edge theta = Sector
Physical Surface(4) = {1};              // symmetry plane z = 0
Physical Surface(5) = {out[0]};         // far face z = SliceThickness
Physical Volume(0) = {out[1]};
