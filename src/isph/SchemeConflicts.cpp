#include "isph/SchemeConflicts.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"

namespace isph {

void checkSchemeConflicts(const Dictionary& d, const IsphSchemes& s) {
  const auto conflict = [&](const Dictionary& where, const char* key, const std::string& why) {
    fatalIOError(where.findEntry(key)->location(), fmt::format("keyword '{}' in {}: {}", key, where.name(), why));
  };
  if (s.method == Method::wcsph) return;  // (it reads none of the projection's entries: IsphSchemes::read)
  const bool incremental = s.incrementalPressure != MaterialScope::none;
  if (incremental && s.viscousTerm == ViscousTerm::explicit_) {
    conflict(d, "incrementalPressure",
             "the incremental projection needs the semi-implicit deviatoric term (viscousTerm implicit); with "
             "viscousTerm explicit it is not used: remove one of the two");
  }
  if (!incremental && d.found("laggedPressure")) {
    conflict(d, "laggedPressure",
             "the lagged pressure is the incremental projection's (incrementalPressure granular or all); with "
             "incrementalPressure none it is not used: remove it");
  }
  if (s.incrementalPressure == MaterialScope::all && s.pressureGradient == PressureGradientForm::symmetric) {
    conflict(d, "pressureGradient",
             "the incremental projection (incrementalPressure all) corrects with the renormalised gradient of the "
             "increment; the symmetric form is not used: remove one of the two");
  }
  const Dictionary wf = d.subDictOrEmpty("wallFriction");
  if (incremental && s.laggedForm == LaggedPressureForm::pairs && s.frictionNormal == FrictionNormal::hydrostatic) {
    conflict(wf, "normalForce",
             "with the incremental projection's pair form (laggedPressure { form pairs; }) the Coulomb capacity is "
             "the wall pairs' normal reaction; normalForce hydrostatic is not used: remove it or use "
             "laggedPressure { form gradient; }");
  }
}

void checkSchemesForScene(const IsphSchemes& s, bool incrementalActs) {
  if (incrementalActs && s.pressureGradient == PressureGradientForm::symmetric) {
    fatalIOError(s.pressureGradientAt,
                 "keyword 'pressureGradient' in system/isphSchemes: the incremental projection (incrementalPressure "
                 "granular, acting in this scene of granular material) corrects with the renormalised gradient of "
                 "the increment; the symmetric form would not be used: remove one of the two");
  }
}

}  // namespace isph
