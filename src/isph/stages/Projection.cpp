#include "isph/stages/Projection.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"

namespace isph {

std::unique_ptr<Projection> Projection::New(const StageSetup& setup, const DeviatoricTerm& deviatoric) {
  const Dictionary& d = setup.schemes;
  const std::string scope = d.getChoiceOrDefault("incrementalPressure", {"none", "granular", "all"}, "none");
  const auto conflict = [&](const char* key, const std::string& why) {
    fatalIOError(d.findEntry(key)->location(), fmt::format("keyword '{}' in {}: {}", key, d.name(), why));
  };
  if (scope != "none" && d.found("viscousTerm") && d.get<std::string>("viscousTerm") == "explicit") {
    conflict("incrementalPressure",
             "the incremental projection needs the semi-implicit deviatoric term (viscousTerm implicit); with "
             "viscousTerm explicit it is not used: remove one of the two");
  }
  if (scope == "none" && d.found("laggedPressure")) {
    conflict("laggedPressure",
             "the lagged pressure is the incremental projection's (incrementalPressure granular or all); with "
             "incrementalPressure none it is not used: remove it");
  }
  const bool incremental =
      deviatoric.isImplicit() && (scope == "all" || (scope == "granular" && setup.materials.anyGranular()));
  if (scope != "none" && !incremental) d.markRead("laggedPressure");  // asked for scenes this one is not
  const Entry* e = d.findEntry("incrementalPressure");
  return ProjectionRegistry::create(incremental ? "incremental" : "plain", "projection",
                                    e ? e->location() : d.location(), setup);
}

void Projection::beforePredictor(StepContext&, double, bool, std::vector<Vec3>&) { lagged_.clear(); }

}  // namespace isph
