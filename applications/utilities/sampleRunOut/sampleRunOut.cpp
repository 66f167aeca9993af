// sampleRunOut: the run-out (front position) of the material along a direction, for the
// selected times, as system/sampleRunOutDict says:
//
//   origin        (0 0 0);   // where the run-out is measured from (the back wall, the gate)
//   direction     (1 0 0);   // along the bed
//   maxHeight     0.03;      // only material within this distance of the bed line [m]
//   minNeighbours 2;         // a front particle needs this many material particles within 1.5 dx
//
// Writes postProcessing/sampleRunOut/<firstTime>/runOut.dat: Time [s], runOut [m].
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
#include "postProcessing/sampling/RunOut.hpp"

namespace {

namespace fs = std::filesystem;

const isph::ApplicationSpec spec{
    .name = "sampleRunOut",
    .description = "Run-out (front position) of the material along a direction, from system/sampleRunOutDict.",
    .options = {{"cloud", "name", "the cloud (default: particles)"}, isph::SkippedTimes::option()},
    .arguments = {},
    .timeOptions = true,
    .parallel = true,
};

void run(const isph::ArgList& args) {
  const isph::Dictionary dict = isph::Dictionary::readFile(args.casePath() / "system" / "sampleRunOutDict");
  isph::RunOutSpec s;
  s.origin = dict.getOrDefault("origin", s.origin);
  s.direction = dict.get<isph::Vec3>("direction");
  if (!(s.direction.norm() > 0)) {
    isph::fatalIOError(dict.findEntry("direction")->location(), "direction: expected a non-zero vector");
  }
  s.maxHeight = dict.getOrDefault("maxHeight", s.maxHeight);
  s.minNeighbours = dict.getOrDefault("minNeighbours", 2);
  dict.checkKeywords();
  const std::string cloudName = args.option("cloud").value_or("particles");
  const auto times = isph::selectedTimes(args);

  std::string text = "# run-out along (" + fmt::format("{} {} {}", s.direction.x(), s.direction.y(), s.direction.z()) +
                     ") from (" + fmt::format("{} {} {}", s.origin.x(), s.origin.y(), s.origin.z()) + ")\n" +
                     "# Time[s] runOut[m]\n";
  isph::SkippedTimes skipped(args);  // a time that cannot be read: an error, or skipped (-skipDamaged)
  for (const auto& time : times) {
    const auto cloud = skipped.read(time, [&] {
      return isph::readCloud(isph::DecomposedTime(args.casePath(), time.name, args.found("parallel")).path(), cloudName);
    });
    if (!cloud) continue;
    const auto front = isph::runOut(*cloud, s);
    if (!front) {
      isph::warning(fmt::format("time {}: no material particle within maxHeight of the bed line", time.name));
      continue;
    }
    isph::info("Time = {}  runOut {:.6g} m", time.name, *front);
    text += fmt::format("{} {:.8g}\n", time.value, *front);
  }
  skipped.finish(times.size());
  const fs::path out = args.casePath() / "postProcessing" / "sampleRunOut" / times.front().name / "runOut.dat";
  fs::create_directories(out.parent_path());
  isph::writeFileAtomic(out, text);
  isph::info("\nWritten {}", out.string());
}

}  // namespace

int main(int argc, char* argv[]) { return isph::runApplication(spec, argc, argv, run); }
