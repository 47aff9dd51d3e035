// Two blocks r in [0.5, 1] x z in [0, 0.5] (material 1) and z in [0.5, 1]
// (material 2) joined by a zero-thickness interface along z = 0.5, boundary
// id 5. The interface curve exists twice (curves 3 and 7), on distinct but
// coincident points, so the two blocks do not share nodes there (double
// nodes); both copies carry the Physical Curve 5. Do not run Coherence.
// Generate: gmsh -2 -order 1 two_blocks.geo   (writes two_blocks.msh)
// Then: Mesh/Type = gmsh, Mesh/Mesh file = two_blocks.msh,
//       Interfaces/Interfaces = 5: rough
n = 3; // cells per block side

// bottom block
Point(1) = {0.5, 0.0, 0};
Point(2) = {1.0, 0.0, 0};
Point(3) = {1.0, 0.5, 0};
Point(4) = {0.5, 0.5, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4}; // interface, bottom side
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// top block, with its own copies of the interface points
Point(5) = {0.5, 0.5, 0};
Point(6) = {1.0, 0.5, 0};
Point(7) = {1.0, 1.0, 0};
Point(8) = {0.5, 1.0, 0};
Line(5) = {6, 7};
Line(6) = {7, 8};
Line(7) = {5, 6}; // interface, top side
Line(8) = {8, 5};
Curve Loop(2) = {7, 5, 6, 8};
Plane Surface(2) = {2};

// structured first-order quadrilaterals
Transfinite Curve{1, 2, 3, 4, 5, 6, 7, 8} = n + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};

Physical Curve(0) = {4, 8};    // inner side r = 0.5
Physical Curve(1) = {2, 5};    // outer side r = 1
Physical Curve(2) = {1};       // bottom
Physical Curve(3) = {6};       // top
Physical Curve(5) = {3, 7};    // interface: both copies
Physical Surface(1) = {1};     // material 1
Physical Surface(2) = {2};     // material 2
