// sampleSurface: the free-surface height of the material over bins along the bed, for the
// selected times, as system/sampleSurfaceDict says:
//
//   binWidth   0.01;       // [m]
//   xMin       0;          // the bins cover [xMin, xMax) along the bed from the origin [m]
//   xMax       0.6;
//   origin     (0 0 0);    // optional: the bed line's origin (default (0 0 0))
//   direction  (1 0 0);    // optional: along the bed (default x); heights are along it turned by +90 deg
//   reference  "validation/profile.csv";  // optional: x,height of a measured profile, relative
//                                          // to the case; its RMS distance is reported
//
// The height of a bin is its highest material particle centre plus dx/2, 0 where it holds no
// material (src/postProcessing/sampling/SurfaceProfile.hpp). Writes
// postProcessing/sampleSurface/<time>/surface.dat for each time: x [m] (bin centre), height [m].
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "core/Log.hpp"
#include "core/app/Application.hpp"
#include "core/app/SkippedTimes.hpp"
#include "core/app/TimeOptions.hpp"
#include "parallel/DecomposedCase.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "core/io/AtomicFile.hpp"
#include "particles/CloudIO.hpp"
#include "postProcessing/sampling/SurfaceProfile.hpp"

namespace {

namespace fs = std::filesystem;

const isph::ApplicationSpec spec{
    .name = "sampleSurface",
    .description = "Free-surface height profile of the material along the bed, from system/sampleSurfaceDict.",
    .options = {{"cloud", "name", "the cloud (default: particles)"}, isph::SkippedTimes::option()},
    .arguments = {},
    .timeOptions = true,
    .parallel = true,
};

void run(const isph::ArgList& args) {
  const isph::Dictionary dict = isph::Dictionary::readFile(args.casePath() / "system" / "sampleSurfaceDict");
  isph::SurfaceSpec s;
  s.binWidth = dict.get<double>("binWidth");
  if (!(s.binWidth > 0)) isph::fatalIOError(dict.findEntry("binWidth")->location(), "binWidth: expected a positive length");
  s.xMin = dict.get<double>("xMin");
  s.xMax = dict.get<double>("xMax");
  if (!(s.xMax > s.xMin)) isph::fatalIOError(dict.findEntry("xMax")->location(), "xMax: expected more than xMin");
  s.origin = dict.getOrDefault("origin", s.origin);
  s.direction = dict.getOrDefault("direction", s.direction);
  if (!(isph::Vec3(s.direction.x(), s.direction.y(), 0).norm() > 0)) {
    isph::fatalIOError(dict.findEntry("direction")->location(), "direction: expected a non-zero vector in the x-y plane");
  }
  const auto referenceName = dict.getOptional<std::string>("reference");
  dict.checkKeywords();
  std::vector<isph::ProfilePoint> reference;
  if (referenceName) reference = isph::readProfileCsv(args.casePath() / *referenceName);

  const std::string cloudName = args.option("cloud").value_or("particles");
  const auto times = isph::selectedTimes(args);
  isph::SkippedTimes skipped(args);  // a time that cannot be read: an error, or skipped (-skipDamaged)
  for (const auto& time : times) {
    const auto cloud = skipped.read(time, [&] {
      return isph::readCloud(isph::DecomposedTime(args.casePath(), time.name, args.found("parallel")).path(), cloudName);
    });
    if (!cloud) continue;
    const isph::SurfaceProfile profile = isph::surfaceProfile(*cloud, s);
    std::string text = fmt::format("# free surface at time {}: highest material particle centre + dx/2 per bin\n", time.name);
    text += fmt::format("# bins of {} m along ({} {} {}) from ({} {} {}); height 0 where a bin has no material\n",
                        s.binWidth, s.direction.x(), s.direction.y(), s.direction.z(), s.origin.x(), s.origin.y(),
                        s.origin.z());
    std::string message = fmt::format("Time = {}  height at the first bin {:.6g} m", time.name, profile.height.front());
    if (referenceName) {
      const double rms = isph::rmsDistance(profile, reference);
      text += fmt::format("# RMS distance to {} ({} points): {:.6g} m\n", *referenceName, reference.size(), rms);
      message += fmt::format("  surfaceRms {:.6g} m", rms);
    }
    text += "# x[m] height[m]\n";
    for (std::size_t k = 0; k < profile.x.size(); ++k) text += fmt::format("{:.8g} {:.8g}\n", profile.x[k], profile.height[k]);
    isph::info("{}", message);
    const fs::path out = args.casePath() / "postProcessing" / "sampleSurface" / time.name / "surface.dat";
    fs::create_directories(out.parent_path());
    isph::writeFileAtomic(out, text);
    isph::info("Written {}", out.string());
  }
  skipped.finish(times.size());
}

}  // namespace

int main(int argc, char* argv[]) { return isph::runApplication(spec, argc, argv, run); }
