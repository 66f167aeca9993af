#pragma once
// Reads the scene of a case from system/particleMeshDict (particleMesh's input). Shapes are
// drawn in the x-y plane of the scene frame ((x y 0)); a 3D scene extrudes them along z over
// its width; `transform` maps the scene frame to the case.
//
//   spacing         0.0036;      // dx [m]; required, > 0
//   maxParticles    1e7;         // a scene estimated to make more is refused before any is
//                                // made (ParticleEstimate.hpp); raise it for a larger one
//   cloud           particles;   // the cloud's name: 0/lagrangian/<cloud>
//   dimension       2;           // 2: plane strain in x-y | 3: the x-y scene extruded along z
//   width           0.2;         // 3D only: z from 0 to width (round(width/dx) layers); regions
//                                // and walls are x-y shapes that span it (Extrusion.hpp);
//                                // a region may fill part of it (zRange below)
//   sideWalls                    // 3D only, optional: walls at z = 0 and z = width
//   {
//       frictionAngle 25;        // required
//       patch       sideWalls;   // both walls' patch (default sideWalls), or one each:
//       patches     (front back); //   the wall at z = 0, then at z = width
//       rho         1379;        // default: first region's rho
//       min (0 0 0); max (3 0.6 0); // optional: the part of the x-y section they cover
//                                //   (default: the section's bounding box, walls included)
//   }
//   lattice         square;      // square (dx²) | hexagonal ((√3/2) dx² per site; 2D only)
//   latticeOrigin   (0 0 0);     // a corner of a lattice cell: sites at origin + (i+½, j+½) cells
//   wallLayers      3;           // wall + dummy layers; default ceil(kernel support / dx) from
//                                // system/isphSchemes (kernel WendlandC2, hOverDx 1.3 -> 3)
//   wallClearance   0.5;         // material sites closer than this × dx to a wall surface go
//   initialPressure zero;        // zero | lithostatic (p = ∫ρ|g|dz along g; needs constant/g)
//   initialVelocity (0 0 0);     // of the material particles, scene frame
//   transform                    // optional: x' = R(rotate) (x - origin) + origin + translate
//   {
//       rotate      -45;         // degrees, counter-clockwise about z
//       origin      (0 0 0);
//       translate   (0 0 0);
//   }
//   regions                      // material; the first listed wins where they overlap; each on
//                                // the walls' material side (MaterialInsideWalls.hpp)
//   {
//       <name>
//       {
//           type        box;     // box | polygon | profile | cylinder (3D) (RegionTypes.cpp)
//           min (0 0 0); max (0.5 0.242 0);       // box
//           points ((0 0 0) (1 0 0) (0 1 0));      // polygon (or pointsFile "constant/a.csv")
//           upper (...); lower (...);             // profile: material between them; or
//           upperFile "constant/ground.csv";      //   from CSV files (x,y columns); an
//           thickness 0.59;                       //   optional thickness caps it at lower + t
//           base (0.1 0 0.1); radius 0.05; height 0.1;  // cylinder: vertical axis (y)
//           material    sand;    // a material of constant/materialProperties (its rho)
//           initialVelocity (0 0 0);              // optional, overrides the global one
//           zRange      (0 0.1); // 3D only, optional: present in the layers with z in [z0, z1]
//                                // (default: the whole width; ZSlabs.hpp)
//       }
//   }
//   walls                        // solid boundaries, each a patch
//   {
//       <name>
//       {
//           type        polyline;  // polyline | box | polygon (WallTypes.cpp)
//           points ((0 0.4 0) (0 0 0) (2.4 0 0)); // polyline or polygon (or pointsFile)
//           min (2.3 0 0); max (2.32 0.3 0);      // box
//           frictionAngle 25;    // Coulomb wall friction [deg]; required
//           patch       <name>;  // patch name (default: the wall's name; walls may share one)
//           materialSide auto;   // polyline only: left | right | auto (walking first -> last)
//           rho         1379;    // wall and dummy mass = rho dx² (default: first region's rho)
//       }
//   }
//
// Also reads constant/materialProperties (rho of the materials used), system/isphSchemes
// (optional) and constant/g (for lithostatic pressure). Every default used is echoed in the
// log; every bad input is a FatalIOError naming the file, line and keyword.
#include <filesystem>
#include <optional>

#include "particleGeneration/Scene.hpp"

namespace isph {

// The scene of system/particleMeshDict; `spacing`, if given, in place of the file's (the same
// scene at another resolution: particleMesh -spacing, the tutorials' -test runs).
Scene readScene(const std::filesystem::path& caseDir, std::optional<double> spacing = std::nullopt);

// ceil(support radius / dx): the wall + dummy layers that fill the kernel support.
int kernelWallLayers(double supportRadius, double dx);

}  // namespace isph
