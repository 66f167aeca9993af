#include "isph/materials/DruckerPragerRigidPlastic.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/Plausibility.hpp"
#include "isph/materials/EquivalentFriction.hpp"

namespace isph {

namespace {

constexpr double deg = std::numbers::pi / 180.0;

double angleEntry(const Dictionary& dict, const std::string& key, const std::string& material) {
  const double v = dict.get<double>(key);
  if (!(v > 0 && v < 90)) {
    fatalIOError(dict.findEntry(key)->location(),
                 fmt::format("material '{}': {} must be an angle in degrees between 0 and 90, got {}", material,
                             key, v));
  }
  return v;
}

std::optional<double> positiveEntry(const Dictionary& dict, const std::string& key, const std::string& material) {
  const auto v = dict.getOptional<double>(key);
  if (v && !(*v > 0)) {
    fatalIOError(dict.findEntry(key)->location(),
                 fmt::format("material '{}': {} must be a positive viscosity (Pa s), got {}", material, key, *v));
  }
  return v;
}

}  // namespace

DruckerPragerRigidPlastic::DruckerPragerRigidPlastic(const std::string& name, const Dictionary& dict)
    : MaterialModel(name, dict) {
  phi_ = angleEntry(dict, "phi", name);
  warnIfImplausibleFrictionAngle(phi_, fmt::format("material '{}': phi", name), dict.findEntry("phi")->location());
  phiEffective_ = phi_;
  frictionNote_ = "no pore pressure";
  if (dict.found("phiEquivalent") && dict.found("waterTable")) {
    fatalIOError(dict.findEntry("waterTable")->location(),
                 fmt::format("material '{}': give either phiEquivalent or waterTable (Eq. 12), not both", name));
  }
  if (dict.found("phiEquivalent")) {
    phiEffective_ = angleEntry(dict, "phiEquivalent", name);
    if (phiEffective_ > phi_) {
      fatalIOError(dict.findEntry("phiEquivalent")->location(),
                   fmt::format("material '{}': phiEquivalent {} exceeds phi {}: pore pressure can only lower the "
                               "friction (Eq. 12)",
                               name, phiEffective_, phi_));
    }
    frictionNote_ = fmt::format("pore pressure by phiEquivalent (Eq. 12, u/p' = {:.4g})",
                                std::sin(phi_ * deg) / std::sin(phiEffective_ * deg) - 1.0);
  } else if (dict.isDict("waterTable")) {
    const Dictionary& wt = dict.subDict("waterTable");
    WaterTable w;
    w.height = wt.get<double>("height");
    w.soilDepth = wt.get<double>("soilDepth");
    w.rhoWater = wt.getOrDefault("rhoWater", 1000.0);
    wt.checkKeywords();
    double ratio = 0;
    try {
      ratio = infiniteSlopePorePressureRatio(w, rho_);
    } catch (const std::invalid_argument& e) {
      fatalIOError(wt.location(), fmt::format("material '{}': waterTable: {}", name, e.what()));
    }
    phiEffective_ = equivalentFrictionAngle(phi_, ratio);
    frictionNote_ = fmt::format("pore pressure from a water table {} m above the slip surface under {} m of soil "
                                "(infinite slope, seepage parallel): u/p' = {:.4g}, phi_e = {:.4g} deg (Eq. 12)",
                                w.height, w.soilDepth, ratio, phiEffective_);
  }
  mu_ = std::sin(phiEffective_ * deg);
  etaMaxGiven_ = positiveEntry(dict, "etaMax", name);
  etaMinGiven_ = positiveEntry(dict, "etaMin", name);
  if (etaMaxGiven_ && etaMinGiven_ && *etaMinGiven_ > *etaMaxGiven_) {
    fatalIOError(dict.findEntry("etaMin")->location(),
                 fmt::format("material '{}': etaMin {} exceeds etaMax {}", name, *etaMinGiven_, *etaMaxGiven_));
  }
  if (etaMaxGiven_) etaMax_ = *etaMaxGiven_;
  if (etaMinGiven_) etaMin_ = *etaMinGiven_;
  dict.checkKeywords({"model"});
}

void DruckerPragerRigidPlastic::adaptToScene(const SceneScales& s) {
  std::string maxNote = "given", minNote = "given";
  if (!etaMaxGiven_) {
    etaMax_ = 1e4 * rho_ * std::sqrt(s.gravity * s.height * s.height * s.height);
    maxNote = fmt::format("default 1e4 rho sqrt(g H^3), H = {:.4g} m", s.height);
  }
  if (!etaMinGiven_) {
    etaMin_ = rho_ * s.spacing * std::sqrt(s.gravity * s.spacing);
    minNote = fmt::format("default rho dx sqrt(g dx), dx = {:.4g} m", s.spacing);
  }
  if (!(etaMax_ > 0)) etaMax_ = etaMin_ > 0 ? etaMin_ : 1.0;  // no gravity or height: a finite cap anyway
  etaMin_ = std::min(etaMin_, etaMax_);
  surfacePressure_ = 0.5 * rho_ * s.gravity * s.spacing;
  etaNote_ = fmt::format("etaMax {:.4g} Pa s ({}), etaMin {:.4g} Pa s ({})", etaMax_, maxNote, etaMin_, minNote);
}

double DruckerPragerRigidPlastic::viscosity(double p, double shearRate) const {
  const double strength = mu_ * (std::max(p, 0.0) + surfacePressure_);  // Eq. 3, |s| = p sin φ
  const double eta = shearRate > 0 ? strength / shearRate : etaMax_;
  return std::clamp(eta, etaMin_, etaMax_);
}

std::string DruckerPragerRigidPlastic::describe() const {
  return fmt::format("{}: rigidPlastic (Drucker-Prager, Eq. 3), rho {} kg/m^3, phi {} deg, phi_e {:.4g} deg "
                     "(sin phi_e = {:.4g}; {}); {}; strength from p + {:.4g} Pa (half a layer, see the model's "
                     "header); walls: Coulomb friction",
                     name_, rho_, phi_, phiEffective_, mu_, frictionNote_, etaNote_, surfacePressure_);
}

namespace {
const bool registered = MaterialRegistry::add("rigidPlastic", [](const std::string& n, const Dictionary& d) {
  return std::make_unique<DruckerPragerRigidPlastic>(n, d);
});
}  // namespace

}  // namespace isph
