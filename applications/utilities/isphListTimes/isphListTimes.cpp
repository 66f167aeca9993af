// isphListTimes: list a case's time directories (OpenFOAM's foamListTimes), honouring
// -time, -latestTime and -noZero; -rm removes the selected ones (never 0 unless selected
// explicitly with -time).
#include <filesystem>
#include <iostream>

#include "core/app/Application.hpp"
#include "core/app/TimeOptions.hpp"
#include "core/io/AtomicFile.hpp"

namespace {

const isph::ApplicationSpec spec{
    .name = "isphListTimes",
    .description = "List the time directories of a case (one per line, in time order).",
    .options = {{"rm", "", "remove the selected time directories"}},
    .arguments = {},
    .timeOptions = true,
    .banner = false,
};

void run(const isph::ArgList& args) {
  for (const auto& t : isph::selectedTimes(args, isph::EmptySelection::warn)) {
    if (args.found("rm")) {
      if (t.value == 0 && !args.option("time")) continue;
      isph::removeDirectoryAtomically(args.casePath() / t.name);  // out of view first
    } else {
      std::cout << t.name << '\n';
    }
  }
}

}  // namespace

int main(int argc, char* argv[]) { return isph::runApplication(spec, argc, argv, run); }
