// sampleWallFilm: the material at rest in a thin film on walls steeper than their friction
// angle, for the selected times (src/postProcessing/sampling/WallFilm.hpp has the definition):
// a film there has no material below to carry it, so at rest it is held by the method, not
// by Coulomb friction. Gravity from constant/g, the walls' friction angles from the cloud's
// patches; system/sampleWallFilmDict is optional:
//
//   restSpeed     0.01;   // [m/s] below this a particle is at rest (default 0.01)
//   maxThickness  2.5;    // [spacings] a film is at most this thick normal to its wall (default 2.5)
//
// Writes postProcessing/sampleWallFilm/<firstTime>/wallFilm.dat: Time [s], the particles
// counted, their mass [kg] (per metre of width in 2D), their lowest and highest elevation
// along up [m], and the material particles at rest; and beside it wallFilmParticles.dat: the
// counted particles of the last time selected (Time, origId, x y z, |u|), to find them in the
// VTK output.
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Log.hpp"
#include "core/app/Application.hpp"
#include "core/app/SkippedTimes.hpp"
#include "core/app/TimeOptions.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/io/AtomicFile.hpp"
#include "isph/Gravity.hpp"
#include "parallel/DecomposedCase.hpp"
#include "particles/CloudIO.hpp"
#include "postProcessing/sampling/WallFilm.hpp"

namespace {

namespace fs = std::filesystem;

const isph::ApplicationSpec spec{
    .name = "sampleWallFilm",
    .description = "The material at rest in a thin film on walls steeper than their friction angle (mass, particles, "
                   "elevations), with system/sampleWallFilmDict if present.",
    .options = {{"cloud", "name", "the cloud (default: particles)"}, isph::SkippedTimes::option()},
    .arguments = {},
    .timeOptions = true,
    .parallel = true,
};

isph::WallFilmSpec readSpec(const fs::path& casePath) {
  isph::WallFilmSpec s;
  const fs::path file = casePath / "system" / "sampleWallFilmDict";
  if (fs::exists(file)) {
    const isph::Dictionary dict = isph::Dictionary::readFile(file);
    s.restSpeed = dict.getOrDefault("restSpeed", s.restSpeed);
    if (!(s.restSpeed > 0)) {
      isph::fatalIOError(dict.findEntry("restSpeed")->location(), "restSpeed: expected a positive speed [m/s]");
    }
    s.maxThickness = dict.getOrDefault("maxThickness", s.maxThickness);
    if (!(s.maxThickness > 0)) {
      isph::fatalIOError(dict.findEntry("maxThickness")->location(),
                         "maxThickness: expected a positive number of spacings");
    }
    dict.checkKeywords();
  } else {
    isph::info("    no {}: restSpeed {} m/s, maxThickness {} spacings", file.string(), s.restSpeed, s.maxThickness);
  }
  s.g = isph::readGravity(casePath);
  return s;
}

void run(const isph::ArgList& args) {
  const isph::WallFilmSpec s = readSpec(args.casePath());
  const std::string cloudName = args.option("cloud").value_or("particles");
  const auto times = isph::selectedTimes(args);

  std::string text = fmt::format(
      "# material at rest (|u| < {} m/s) in a film at most {} spacings thick on walls steeper than their friction angle, "
      "g ({} {} {})\n# Time[s] particles mass[kg] lowest[m] highest[m] resting\n",
      s.restSpeed, s.maxThickness, s.g.x(), s.g.y(), s.g.z());
  std::string members = "# the particles counted at the last time read\n# Time[s] origId x[m] y[m] z[m] |u|[m/s]\n";
  isph::SkippedTimes skipped(args);  // a time that cannot be read: an error, or skipped (-skipDamaged)
  for (const auto& time : times) {
    const auto cloud = skipped.read(time, [&] {
      return isph::readCloud(isph::DecomposedTime(args.casePath(), time.name, args.found("parallel")).path(), cloudName);
    });
    if (!cloud) continue;
    const isph::WallFilm f = isph::restingWallFilm(*cloud, s);
    isph::info("Time = {}  film at rest on steep walls: {} particles, {:.6g} kg, elevation {:.6g} to {:.6g} m ({} at rest)",
               time.name, f.particles, f.mass, f.lowest, f.highest, f.resting);
    text += fmt::format("{} {} {:.8g} {:.8g} {:.8g} {}\n", time.value, f.particles, f.mass, f.lowest, f.highest,
                        f.resting);
    members.resize(members.find('\n', members.find('\n') + 1) + 1);  // the header: the last time's only
    for (const int i : f.members) {
      const auto a = static_cast<std::size_t>(i);
      const isph::Vec3& x = cloud->positions[a];
      members += fmt::format("{} {} {:.8g} {:.8g} {:.8g} {:.4g}\n", time.value, cloud->origId[a], x.x(), x.y(), x.z(),
                             cloud->U[a].norm());
    }
  }
  skipped.finish(times.size());
  const fs::path out = args.casePath() / "postProcessing" / "sampleWallFilm" / times.front().name / "wallFilm.dat";
  fs::create_directories(out.parent_path());
  isph::writeFileAtomic(out, text);
  isph::writeFileAtomic(out.parent_path() / "wallFilmParticles.dat", members);
  isph::info("\nWritten {} and wallFilmParticles.dat beside it", out.string());
}

}  // namespace

int main(int argc, char* argv[]) { return isph::runApplication(spec, argc, argv, run); }
