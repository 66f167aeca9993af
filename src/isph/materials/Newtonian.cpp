// Newtonian fluid: constant dynamic viscosity mu = rho * nu (`nu` or `mu` in the material).
#include <fmt/format.h>

#include "isph/materials/MaterialModel.hpp"

namespace isph {

namespace {

class Newtonian final : public MaterialModel {
 public:
  Newtonian(const std::string& name, const Dictionary& dict) : MaterialModel(name, dict) {
    if (dict.found("mu") == dict.found("nu")) {
      fatalIOError(dict.location(), fmt::format("material '{}' (model newtonian) needs exactly one of nu "
                                                "(kinematic viscosity, m^2/s) or mu (dynamic, Pa s)",
                                                name));
    }
    mu_ = dict.found("mu") ? dict.get<double>("mu") : rho_ * dict.get<double>("nu");
    if (!(mu_ >= 0)) fatalIOError(dict.location(), fmt::format("material '{}': viscosity must be >= 0", name));
    dict.checkKeywords({"model"});
  }
  std::string type() const override { return "newtonian"; }
  bool hasDeviatoricStress() const override { return mu_ > 0; }
  double viscosity(double, double) const override { return mu_; }
  double maxViscosity() const override { return mu_; }
  std::string describe() const override {
    return fmt::format("{}: newtonian, rho {} kg/m^3, mu {} Pa s", name_, rho_, mu_);
  }

 private:
  double mu_ = 0;
};

class Inviscid final : public MaterialModel {
 public:
  Inviscid(const std::string& name, const Dictionary& dict) : MaterialModel(name, dict) {
    dict.checkKeywords({"model"});
  }
  std::string type() const override { return "inviscid"; }
  bool hasDeviatoricStress() const override { return false; }
  double viscosity(double, double) const override { return 0.0; }
  double maxViscosity() const override { return 0.0; }
  std::string describe() const override { return fmt::format("{}: inviscid, rho {} kg/m^3", name_, rho_); }
};

const bool registeredNewtonian = MaterialRegistry::add(
    "newtonian", [](const std::string& n, const Dictionary& d) { return std::make_unique<Newtonian>(n, d); });
const bool registeredInviscid = MaterialRegistry::add(
    "inviscid", [](const std::string& n, const Dictionary& d) { return std::make_unique<Inviscid>(n, d); });

}  // namespace

}  // namespace isph
