#pragma once
// particleMesh's last check before it writes: every material particle on the walls' material
// side (MaterialSideOfWalls.hpp). A region drawn across the walls, with a wall's materialSide
// set to quieten auto's tie, kept the particles beside a tank's corners, below its bed, and
// the solver ran them there (issue 54, item 5). FatalIOError at the entry of the first region
// with particles outside, naming the region, the count per wall patch (behind it, or past its
// open end: outside the domain the walls enclose) and one position.
#include "particleGeneration/ParticleGenerator.hpp"
#include "particleGeneration/Scene.hpp"

namespace isph {

void checkMaterialInsideWalls(const Scene& scene, const GenerationResult& result);

}  // namespace isph
