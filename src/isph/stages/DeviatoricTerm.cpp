#include "isph/stages/DeviatoricTerm.hpp"

namespace isph {

std::unique_ptr<DeviatoricTerm> DeviatoricTerm::New(const StageSetup& setup) {
  const std::string name = setup.schemes.getChoiceOrDefault("viscousTerm", {"implicit", "explicit"}, "implicit");
  const Entry* e = setup.schemes.findEntry("viscousTerm");
  // With no deviatoric stress in the scene the predictor is gravity alone: the explicit sum.
  return DeviatoricTermRegistry::create(setup.materials.anyDeviatoricStress() ? name : std::string("explicit"),
                                        "viscousTerm", e ? e->location() : setup.schemes.location(), setup);
}

}  // namespace isph
