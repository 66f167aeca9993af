// toVTK: the selected time directories as VTK XML PolyData for ParaView (OpenFOAM's
// foamToVTK for particle clouds): VTK/<case>_<time>.vtp per time and the collection
// VTK/<case>.pvd listing every converted time, so that ParaView opens the animation at once.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <vtkPointData.h>

#include "core/Log.hpp"
#include "core/app/Application.hpp"
#include "core/app/OutOfMemory.hpp"
#include "core/app/SkippedTimes.hpp"
#include "core/app/TimeOptions.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "parallel/DecomposedCase.hpp"
#include "postProcessing/vtk/CloudPolyData.hpp"
#include "postProcessing/vtk/PvdCollection.hpp"
#include "postProcessing/vtk/VtpFile.hpp"

namespace {

namespace fs = std::filesystem;

const isph::ApplicationSpec spec{
    .name = "toVTK",
    .description = "Convert the particle clouds of the selected times to VTK/<case>_<time>.vtp and VTK/<case>.pvd.",
    .options = {{"fields", "(U p)", "convert only these fields (positions always)"},
                {"noWalls", "", "leave out wall and dummy particles"},
                {"ascii", "", "write ascii instead of compressed binary"},
                {"cloud", "name", "the cloud to convert (default particles)"}, isph::SkippedTimes::option()},
    .arguments = {},
    .timeOptions = true,
    .parallel = true,
};

// `-fields '(U p)'` (or a single word) as a list of names; errors name the option.
std::optional<std::vector<std::string>> fieldList(const isph::ArgList& args) {
  const auto text = args.option("fields");
  if (!text) return std::nullopt;
  const std::string list = text->find('(') == std::string::npos ? "(" + *text + ")" : *text;
  return isph::Dictionary::parse("fields " + list + ";", "option -fields").get<std::vector<std::string>>("fields");
}

void run(const isph::ArgList& args) {
  const auto fields = fieldList(args);
  const std::string cloudName = args.option("cloud").value_or("particles");
  const auto format = args.found("ascii") ? isph::VtkFormat::ascii : isph::VtkFormat::binary;
  const fs::path vtkDir = args.casePath() / "VTK";
  const auto times = isph::selectedTimes(args);
  fs::create_directories(vtkDir);

  std::vector<isph::PvdEntry> converted;
  isph::SkippedTimes skipped(args);  // a time that cannot be read: an error, or skipped (-skipDamaged)
  for (const auto& time : times) {
    const auto cloud = skipped.read(time, [&] {
      const isph::DecomposedTime timeDir(args.casePath(), time.name, args.found("parallel"));
      return isph::readCloudFields(timeDir.path(), cloudName, fields);
    });
    if (!cloud) continue;
    const isph::Building building(fmt::format("the VTK file of time {} ({} particles)", time.name, cloud->cloud.size()));
    const auto poly = isph::cloudPolyData(*cloud, time.value, {.noWalls = args.found("noWalls")});
    const std::string file = args.caseName() + "_" + time.name + ".vtp";
    isph::writeVtp(poly, vtkDir / file, format);
    isph::info("Time = {}: {} particles, {} point fields -> VTK/{}", time.name, poly->GetNumberOfPoints(),
               poly->GetPointData()->GetNumberOfArrays(), file);
    converted.push_back({time.name, file});
  }
  const fs::path pvd = vtkDir / (args.caseName() + ".pvd");
  if (!converted.empty()) {
    const auto all = isph::updatePvd(pvd, converted);
    isph::info("\nWritten {} ({} times)", pvd.string(), all.size());
  }
  skipped.finish(times.size());
}

}  // namespace

int main(int argc, char* argv[]) { return isph::runApplication(spec, argc, argv, run); }
