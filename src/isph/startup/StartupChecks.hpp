#pragma once
// What the solver refuses at start, each with the file and line to fix, instead of running
// zero steps without a word, writing a time directory every step, or letting a particle that
// was moved out of the scene fall for ever:
//  - endTime not after the start time (system/controlDict, endTime);
//  - with writeControl runTime or adjustableRunTime, a writeInterval shorter than the time
//    step: every step would write a time directory (and adjustableRunTime would shrink the
//    step to the interval: writeInterval 1e-12 ran at deltaT 1e-12);
//  - a material particle outside the scene's domain: the bounding box of the case's first
//    particles (those particleMesh made) enlarged each way by its largest side and 10 dx, the
//    margin within which the solver keeps the particles during the run (checkStillInDomain).
//  - a material particle behind a wall (on its solid side: MaterialSideOfWalls.hpp), a field
//    edited by hand or particles that particleMesh made before it refused them (issue 54,
//    item 5: the run went on with them, and the wall safeguard put one back still outside). A
//    particle past the open end of a wall is left to the domain check: it may have flowed off it;
//  - a material particle faster than speedBoundFactor times the free-fall speed over the
//    domain's height, sqrt(2 |g| H) (no landslide or dam break comes near it): a field edited by
//    hand or written by a run that blew up (U = 1e200 stopped with "the time step must be
//    positive, found 0", naming nothing).
// Fields that are not finite numbers are refused by the field readers (FieldIO.hpp).
#include <filesystem>
#include <optional>
#include <string>

#include "core/Types.hpp"
#include "core/time/Time.hpp"
#include "isph/ParticleSystem.hpp"

namespace isph {

// FatalError at controlDict's endTime entry.
void checkEndTime(const Time& time);
// FatalError at controlDict's writeInterval entry. `firstDeltaT` is the step the run starts
// with (the controlDict's deltaT, or the solver's first adjusted step).
void checkWriteInterval(const Time& time, double firstDeltaT);

struct SceneDomain {
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();
};

// The domain of the particles at `positions` (the case's first particles): their bounding box
// enlarged each way by its largest side and 10 dx.
SceneDomain sceneDomain(const std::vector<Vec3>& positions, double dx);
// The same over the positions of every rank of a parallel run (collective; serial: the above).
SceneDomain sceneDomainOverRanks(const std::vector<Vec3>& positions, double dx);

// The domain of a run starting at `time`: `kept` (a restart's, from its StepState), else that
// of the particles of the case's first time directory, else of `ps`'s (over the ranks); the
// particles of `ps` (this rank's own) are checked to lie in it (checkInsideDomain) unless it is
// theirs. Collective in a parallel run.
SceneDomain startDomain(const Time& time, const std::string& cloudName, const ParticleSystem& ps,
                        const std::optional<SceneDomain>& kept);

// FatalError naming the positions file of `cloudDir`, the line (ascii) or value of the first
// material particle outside `domain`, its origId and position, and the domain.
void checkInsideDomain(const ParticleSystem& ps, const SceneDomain& domain,
                       const std::filesystem::path& cloudDir, const std::string& domainSource);

// FatalError naming the positions file of `cloudDir`, the line (ascii) or value of the first
// material particle (this rank's own) behind a wall, its origId, position, depth and the wall
// particle's patch, and how many there are over all ranks. The wall particles of every rank are
// gathered (collective in a parallel run).
void checkMaterialSideOfWalls(const ParticleSystem& ps, const std::filesystem::path& cloudDir);

constexpr double speedBoundFactor = 10;
// speedBoundFactor sqrt(2 |g| H), H the extent of `domain` along g (no bound without gravity).
double speedBound(const SceneDomain& domain, const Vec3& g);
// FatalError naming the U file of `cloudDir`, the line (ascii) or value, the particle's origId
// and its velocity when a material particle (this rank's own) is faster than speedBound.
void checkSpeeds(const ParticleSystem& ps, const SceneDomain& domain, const Vec3& g,
                 const std::filesystem::path& cloudDir);

// The check after every step: FatalError when a material particle (this rank's own) has a
// non-finite position, velocity or pressure, or left `domain`, naming it, the time and that the
// last written time directory is intact.
void checkStillInDomain(const ParticleSystem& ps, const SceneDomain& domain, const Time& time);

}  // namespace isph
