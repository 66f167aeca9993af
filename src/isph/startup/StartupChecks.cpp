#include "isph/startup/StartupChecks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "core/fields/FieldIO.hpp"
#include "core/time/TimeName.hpp"
#include "parallel/Reduce.hpp"
#include "particles/MaterialSideOfWalls.hpp"

namespace isph {

namespace {

SourceLocation entryLocation(const Time& time, const char* key) {
  const Entry* e = time.controlDict().findEntry(key);
  return e ? e->location() : time.controlDict().location();
}

}  // namespace

void checkEndTime(const Time& time) {
  const ControlSettings& s = time.settings();
  if (s.stopAt == StopAt::endTime && !(s.endTime > time.startTime())) {
    fatalIOError(entryLocation(time, "endTime"),
                 fmt::format("endTime {} is not after the start time {} (startFrom {}): the run "
                             "would make no step.\n"
                             "    To run on from time {}, raise endTime.",
                             s.endTime, time.timeName(), toString(s.startFrom), time.timeName()));
  }
}

void checkWriteInterval(const Time& time, double firstDeltaT) {
  const ControlSettings& s = time.settings();
  if (s.writeControl != WriteControl::timeStep && s.writeInterval < firstDeltaT) {
    fatalIOError(
        entryLocation(time, "writeInterval"),
        fmt::format(
            "writeInterval {} s is shorter than the time step {:.4g} s: with writeControl {} every "
            "step would write a time directory{}.\n    To write every step use writeControl "
            "timeStep; "
            "writeInterval 1; otherwise a writeInterval of at least {:.4g} s.",
            s.writeInterval, firstDeltaT, toString(s.writeControl),
            s.writeControl == WriteControl::adjustableRunTime
                ? fmt::format(" and the step would shrink to {} s", s.writeInterval)
                : "",
            firstDeltaT));
  }
}

namespace {

// The box from `lo` to `hi` enlarged each way by its largest side and 10 dx.
SceneDomain enlarged(const Vec3& lo, const Vec3& hi, double dx) {
  const Vec3 margin = Vec3::Constant((hi - lo).maxCoeff() + 10 * dx);
  return {lo - margin, hi + margin};
}

}  // namespace

SceneDomain sceneDomain(const std::vector<Vec3>& positions, double dx) {
  if (positions.empty()) return {};
  Vec3 lo = positions.front(), hi = positions.front();
  for (const auto& x : positions) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return enlarged(lo, hi, dx);
}

SceneDomain sceneDomainOverRanks(const std::vector<Vec3>& positions, double dx) {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const auto& x : positions) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  lo = minOverRanks(lo), hi = maxOverRanks(hi);  // parallel: all ranks
  return hi.x() < lo.x() ? SceneDomain{} : enlarged(lo, hi, dx);
}

SceneDomain startDomain(const Time& time, const std::string& cloudName, const ParticleSystem& ps,
                        const std::optional<SceneDomain>& kept) {
  // (parallel: the start time's folder is processor<rank>/<time>, or the case's own <time> for
  // an undecomposed start; time.timePath() is where the run writes)
  const auto cloudDir = time.startPath() / "lagrangian" / cloudName;
  if (kept) {
    checkInsideDomain(ps, *kept, cloudDir,
                      "that of the case's first particles (uniform/isphState)");
    return *kept;
  }
  // A time written without the state (or the first one): the domain of the first time's
  // particles (the case's own first time, read whole by every rank of a parallel run).
  const auto times = listTimes(time.path());
  const auto first =
      times.empty() ? cloudDir : time.path() / times.front().name / "lagrangian" / cloudName;
  if (first == cloudDir || !std::filesystem::exists(first / "positions"))
    return sceneDomainOverRanks(ps.cloud.positions, ps.dx);
  const SceneDomain domain = sceneDomain(readField<Vec3>(first / "positions"), ps.dx);
  checkInsideDomain(ps, domain, cloudDir,
                    fmt::format("the bounding box of the particles of {}", first.string()));
  return domain;
}

namespace {

// Where particle `id` of the cloud read from `cloudDir` is in its file `field`: the file and line
// (ascii), and the words for the message ("line 12", "value 3 of 617", or "read by another rank":
// the cloud was reordered material | wall | dummy on reading, and parallel runs read per rank).
std::pair<SourceLocation, std::string> particleInFile(const std::filesystem::path& cloudDir, const std::string& field,
                                                      label id) {
  const auto file = cloudDir / field;
  const auto ids = readField<label>(cloudDir / "origId");
  const auto at = std::find(ids.begin(), ids.end(), id);
  const std::size_t index = static_cast<std::size_t>(at - ids.begin());
  const int line = at == ids.end() ? 0 : fieldValueLine<Vec3>(file, index);
  const std::string where = at == ids.end() ? std::string("read by another rank")
                            : line > 0      ? fmt::format("line {}", line)
                                            : fmt::format("value {} of {}", index + 1, ids.size());
  return {SourceLocation{std::make_shared<const std::string>(file.string()), line, 0}, where};
}

}  // namespace

void checkInsideDomain(const ParticleSystem& ps, const SceneDomain& domain,
                       const std::filesystem::path& cloudDir, const std::string& domainSource) {
  const auto& c = ps.cloud;
  for (std::size_t a = 0; a < ps.ownMaterial(); ++a) {  // (parallel: this rank's own)
    const Vec3& x = c.positions[a];
    if ((x.array() >= domain.min.array()).all() && (x.array() <= domain.max.array()).all())
      continue;
    const auto [location, where] = particleInFile(cloudDir, "positions", c.origId[a]);
    fatalIOError(
        location,
        fmt::format(
            "material particle origId {} ({}) is at ({:.6g} {:.6g} {:.6g}), outside the scene's "
            "domain ({:.6g} {:.6g} {:.6g}) to ({:.6g} {:.6g} {:.6g}): {}, enlarged each way by its "
            "largest side and 10 dx.\n    A field edited by hand? Restart from an earlier time.",
            c.origId[a], where, x.x(), x.y(), x.z(), domain.min.x(), domain.min.y(), domain.min.z(),
            domain.max.x(), domain.max.y(), domain.max.z(), domainSource));
  }
}

void checkMaterialSideOfWalls(const ParticleSystem& ps, const std::filesystem::path& cloudDir) {
  const auto& c = ps.cloud;
  std::vector<double> own;  // this rank's wall particles: position, normal, patch
  own.reserve(7 * ps.ownWall());
  for (std::size_t w = ps.wallBegin(); w < ps.wallBegin() + ps.ownWall(); ++w) {
    own.insert(own.end(), {c.positions[w].x(), c.positions[w].y(), c.positions[w].z(), c.normal[w].x(),
                           c.normal[w].y(), c.normal[w].z(), static_cast<double>(c.patch[w])});
  }
  const std::vector<double> all = gatherOverRanks(own);  // parallel: every rank's walls
  std::vector<MaterialSideOfWalls::WallPoint> walls;
  walls.reserve(all.size() / 7);
  for (std::size_t i = 0; i + 7 <= all.size(); i += 7) {
    walls.push_back({Vec3(all[i], all[i + 1], all[i + 2]), Vec3(all[i + 3], all[i + 4], all[i + 5]),
                     static_cast<label>(all[i + 6])});
  }
  if (walls.empty()) return;
  const MaterialSideOfWalls sides(std::move(walls), ps.dx);
  long behind = 0;
  std::size_t first = 0;
  MaterialSideOfWalls::Verdict example;
  for (std::size_t a = 0; a < ps.ownMaterial(); ++a) {  // (parallel: this rank's own)
    const auto v = sides.classify(c.positions[a]);
    if (v.side != MaterialSideOfWalls::Side::behindWall) continue;
    if (behind++ == 0) first = a, example = v;
  }
  const std::vector<long> perRank = gatherOverRanks(behind);  // parallel: the lowest rank with one says it
  long total = 0;
  int reporter = -1;
  for (std::size_t r = 0; r < perRank.size(); ++r) {
    total += perRank[r];
    if (perRank[r] > 0 && reporter < 0) reporter = static_cast<int>(r);
  }
  if (total == 0 || thisRank() != reporter) return;  // (the others end with the reporter's error)
  const Vec3& x = c.positions[first];
  const auto& wall = sides.walls()[static_cast<std::size_t>(example.wall)];
  const auto patch = static_cast<std::size_t>(wall.patch);
  const std::string patchName =
      patch < c.properties.patches.size() ? c.properties.patches[patch].name : fmt::format("{}", wall.patch);
  const auto [location, where] = particleInFile(cloudDir, "positions", c.origId[first]);
  fatalIOError(location,
               fmt::format("material particle origId {} ({}) is at ({:.6g} {:.6g} {:.6g}), {:.4g} m behind wall patch "
                           "'{}' (its wall particle at ({:.6g} {:.6g} {:.6g})): outside the walls{}.\n    A field "
                           "edited by hand, or particles from a particleMesh that did not check the walls' side? Run "
                           "particleMesh again, or restart from an earlier time.",
                           c.origId[first], where, x.x(), x.y(), x.z(), -example.depth, patchName, wall.position.x(),
                           wall.position.y(), wall.position.z(),
                           total > 1 ? fmt::format(" ({} material particles are behind a wall in all)", total)
                                     : std::string()));
}

double speedBound(const SceneDomain& domain, const Vec3& g) {
  const double gravity = g.norm();
  if (gravity == 0) return 1e300;
  const double height = std::abs((domain.max - domain.min).dot(g / gravity));
  return speedBoundFactor * std::sqrt(2 * gravity * height);
}

void checkSpeeds(const ParticleSystem& ps, const SceneDomain& domain, const Vec3& g,
                 const std::filesystem::path& cloudDir) {
  const double bound = speedBound(domain, g);
  const auto& c = ps.cloud;
  for (std::size_t a = 0; a < ps.ownMaterial(); ++a) {  // (parallel: this rank's own)
    const Vec3& u = c.U[a];
    if (u.stableNorm() <= bound) continue;
    const auto [location, where] = particleInFile(cloudDir, "U", c.origId[a]);
    const double height = std::abs((domain.max - domain.min).dot(g.normalized()));
    fatalIOError(location,
                 fmt::format("field U of material particle origId {} ({}) is ({:.6g} {:.6g} {:.6g}), |U| = {:.4g} m/s: "
                             "above {} times the free-fall speed over the domain's height, {} sqrt(2 |g| H) = {:.4g} "
                             "m/s (H = {:.4g} m, the scene's domain along g).\n    A field edited by hand, or a run "
                             "that blew up? Restart from an earlier time.",
                             c.origId[a], where, u.x(), u.y(), u.z(), u.stableNorm(), speedBoundFactor,
                             speedBoundFactor, bound, height));
  }
}

void checkStillInDomain(const ParticleSystem& ps, const SceneDomain& domain, const Time& time) {
  for (std::size_t a = 0; a < ps.ownMaterial(); ++a) {  // (parallel: the own; an error ends every rank)
    const Vec3& x = ps.cloud.positions[a];
    const Vec3& u = ps.cloud.U[a];
    if (!x.allFinite() || !u.allFinite() || !std::isfinite(ps.cloud.p[a])) {
      fatalError(fmt::format("the solution diverged at time {}: particle {} (origId {}) has a non-finite position, "
                             "velocity or pressure.\n    The last written time directory is intact; try a smaller "
                             "maxCo or maxDeltaT.",
                             time.timeName(), a, ps.cloud.origId[a]));
    }
    if ((x.array() < domain.min.array()).any() || (x.array() > domain.max.array()).any()) {
      fatalError(fmt::format("particle {} (origId {}) left the domain at time {}: position ({:.4g} {:.4g} {:.4g}), "
                             "velocity ({:.3g} {:.3g} {:.3g}); the domain is the initial bounding box enlarged each "
                             "way by its largest side and 10 dx, ({:.4g} {:.4g} {:.4g}) to ({:.4g} {:.4g} {:.4g}).\n    "
                             "The last written time directory is intact.",
                             a, ps.cloud.origId[a], time.timeName(), x.x(), x.y(), x.z(), u.x(), u.y(), u.z(),
                             domain.min.x(), domain.min.y(), domain.min.z(), domain.max.x(), domain.max.y(),
                             domain.max.z()));
    }
  }
}

}  // namespace isph
