#pragma once
// The log of particleMesh: the scene, then per region and per wall what was generated,
// against what the geometry says (area and mass against the geometric area and area × ρ),
// lost and removed sites, bounding boxes, and a summary of the cloud.
#include "particleGeneration/ParticleGenerator.hpp"
#include "particleGeneration/Scene.hpp"

namespace isph {

void logScene(const Scene& scene);
void logGeneration(const Scene& scene, const GenerationResult& result);

}  // namespace isph
