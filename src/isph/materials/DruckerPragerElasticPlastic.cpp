#include "isph/materials/DruckerPragerElasticPlastic.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Plausibility.hpp"

namespace isph {

namespace {

constexpr double deg = std::numbers::pi / 180.0;

double checked(const Dictionary& dict, const std::string& key, bool ok, const std::string& material,
               const std::string& expected) {
  const double v = dict.get<double>(key);
  if (!ok) {
    fatalIOError(dict.findEntry(key)->location(),
                 fmt::format("material '{}': {} must be {}, got {}", material, key, expected, v));
  }
  return v;
}

double rootJ2(const SymmTensor& s) { return std::sqrt(0.5 * doubleDotSymm(s)); }

}  // namespace

DruckerPragerElasticPlastic::DruckerPragerElasticPlastic(const std::string& name, const Dictionary& dict)
    : MaterialModel(name, dict) {
  phi_ = dict.get<double>("phi");
  checked(dict, "phi", phi_ > 0 && phi_ < 90, name, "an angle in degrees between 0 and 90");
  warnIfImplausibleFrictionAngle(phi_, fmt::format("material '{}': phi", name), dict.findEntry("phi")->location());
  cohesion_ = dict.getOrDefault("cohesion", 0.0);
  if (dict.found("cohesion")) checked(dict, "cohesion", cohesion_ >= 0, name, "a cohesion >= 0 (Pa)");
  E_ = dict.get<double>("E");
  checked(dict, "E", E_ > 0, name, "a positive Young's modulus (Pa)");
  nu_ = dict.get<double>("nu");
  checked(dict, "nu", nu_ >= 0 && nu_ < 0.5, name, "a Poisson's ratio in [0, 0.5)");
  dict.checkKeywords({"model"});
  K_ = E_ / (3.0 * (1.0 - 2.0 * nu_));
  G_ = E_ / (2.0 * (1.0 + nu_));
  const double t = std::tan(phi_ * deg);
  alphaPhi_ = t / std::sqrt(9.0 + 12.0 * t * t);
  kc_ = 3.0 * cohesion_ / std::sqrt(9.0 + 12.0 * t * t);
}

double DruckerPragerElasticPlastic::bulkSpeed() const { return std::sqrt(K_ / rho_); }

double DruckerPragerElasticPlastic::waveSpeed() const { return std::sqrt((K_ + 4.0 / 3.0 * G_) / rho_); }

double DruckerPragerElasticPlastic::yieldFunction(const SymmTensor& s, double p) const {
  return -3.0 * alphaPhi_ * p + rootJ2(s) - kc_;
}

SymmTensor DruckerPragerElasticPlastic::returnToYieldSurface(const SymmTensor& s, double p) const {
  const double strength = kc_ + 3.0 * alphaPhi_ * p;  // the largest √J2 at this pressure
  const double r = rootJ2(s);
  if (r <= strength) return s;
  return strength > 0 ? SymmTensor(s * (strength / r)) : SymmTensor::Zero();
}

SymmTensor DruckerPragerElasticPlastic::updateDeviatoric(const SymmTensor& s, double p, const Eigen::Matrix3d& gradU,
                                                         double dt) const {
  Eigen::Matrix3d S;
  S << s[0], s[1], s[2], s[1], s[3], s[4], s[2], s[4], s[5];
  const Eigen::Matrix3d spin = 0.5 * (gradU - gradU.transpose());
  Eigen::Matrix3d rate = 0.5 * (gradU + gradU.transpose());
  rate.diagonal().array() -= rate.trace() / 3.0;
  Eigen::Matrix3d next = S + dt * (spin * S - S * spin + 2.0 * G_ * rate);  // Jaumann rate (Bui et al. 2008)
  next.diagonal().array() -= next.trace() / 3.0;  // (round-off: s stays deviatoric)
  SymmTensor trial;
  trial << next(0, 0), next(0, 1), next(0, 2), next(1, 1), next(1, 2), next(2, 2);
  return returnToYieldSurface(trial, p);
}

std::string DruckerPragerElasticPlastic::describe() const {
  return fmt::format("{}: elasticPlastic (Drucker-Prager, Bui et al. 2008; non-dilatant), rho {} kg/m^3, phi {} deg, "
                     "cohesion {} Pa, E {:.4g} Pa, nu {} (K {:.4g} Pa, G {:.4g} Pa; sound speed sqrt(K/rho) {:.4g} "
                     "m/s, P-wave speed {:.4g} m/s); walls: Coulomb friction",
                     name_, rho_, phi_, cohesion_, E_, nu_, K_, G_, bulkSpeed(), waveSpeed());
}

namespace {
const bool registered = MaterialRegistry::add("elasticPlastic", [](const std::string& n, const Dictionary& d) {
  return std::make_unique<DruckerPragerElasticPlastic>(n, d);
});
}  // namespace

}  // namespace isph
