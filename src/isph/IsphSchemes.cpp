#include "isph/IsphSchemes.hpp"

#include <fmt/format.h>

namespace isph {

namespace {

void requireRange(const Dictionary& d, const char* key, double value, double lo, double hi) {
  if (value < lo || value > hi) {
    const Entry* e = d.findEntry(key);
    fatalIOError(e ? e->location() : d.location(),
                 fmt::format("keyword '{}' in {}: {} is outside the valid range [{}, {}]", key, d.name(), value, lo, hi));
  }
}

}  // namespace

const char* toString(PpeSource s) {
  switch (s) {
    case PpeSource::densityInvariant: return "densityInvariant";
    case PpeSource::divergence: return "divergence";
    case PpeSource::mixed: return "mixed";
  }
  return "?";
}

namespace {

void readWeaklyCompressible(const Dictionary& d, IsphSchemes& s) {
  const Dictionary wc = d.subDictOrEmpty("wcsph");
  if (s.method == Method::wcsph) {
    if (wc.found("soundSpeed")) {  // else from the scene (the solver logs the value)
      s.wcsph.soundSpeed = wc.get<double>("soundSpeed");
      requireRange(wc, "soundSpeed", s.wcsph.soundSpeed, 1e-6, 1e6);
    }
    s.wcsph.densityDiffusion = wc.getOrDefault("densityDiffusion", s.wcsph.densityDiffusion);
    requireRange(wc, "densityDiffusion", s.wcsph.densityDiffusion, 0.0, 1.0);
    s.wcsph.artificialViscosity = wc.getOrDefault("artificialViscosity", s.wcsph.artificialViscosity);
    requireRange(wc, "artificialViscosity", s.wcsph.artificialViscosity, 0.0, 10.0);
  }
  wc.checkKeywords({"soundSpeed", "densityDiffusion", "artificialViscosity"});
}

// The PPE's Laplacian and source (the projection only).
void readPressurePoisson(const Dictionary& d, IsphSchemes& s) {
  const Dictionary lap = d.subDictOrEmpty("laplacian");
  s.ppe.laplacianEta = lap.getOrDefault("eta", s.ppe.laplacianEta);
  requireRange(lap, "eta", s.ppe.laplacianEta, 1e-6, 1.0);
  s.ppe.laplacianCorrection = lap.getOrDefault("correction", s.ppe.laplacianCorrection);
  lap.checkKeywords();

  const Dictionary src = d.subDictOrEmpty("source");
  const std::string type =
      src.getChoiceOrDefault("type", {"densityInvariant", "divergence", "mixed"}, "densityInvariant");
  s.ppe.source = type == "divergence" ? PpeSource::divergence
             : type == "mixed"    ? PpeSource::mixed
                                  : PpeSource::densityInvariant;
  if (s.ppe.source == PpeSource::mixed) {
    s.ppe.alpha = src.getOrDefault("alpha", s.ppe.alpha);
    requireRange(src, "alpha", s.ppe.alpha, 0.0, 1.0);
  }
  s.ppe.boundaryRelaxation = src.getOrDefault("relaxation", s.ppe.boundaryRelaxation);
  requireRange(src, "relaxation", s.ppe.boundaryRelaxation, 0.0, 1.0);
  src.checkKeywords({"alpha"});
}

void readFreeSurface(const Dictionary& d, int dimension, IsphSchemes& s) {
  const Dictionary fs = d.subDictOrEmpty("freeSurface");
  s.freeSurfaceThreshold = fs.getOrDefault("threshold", dimension == 2 ? 1.5 : 2.75);
  requireRange(fs, "threshold", s.freeSurfaceThreshold, 0.0, double(dimension));
  s.freeSurfaceGradient = fs.getOrDefault("gradientThreshold", s.freeSurfaceGradient);
  requireRange(fs, "gradientThreshold", s.freeSurfaceGradient, 0.0, 10.0);
  s.minNeighbourFraction = fs.getOrDefault("minNeighbourFraction", s.minNeighbourFraction);
  requireRange(fs, "minNeighbourFraction", s.minNeighbourFraction, 0.0, 1.0);
  const std::string compressed = fs.getChoiceOrDefault("compressed", {"granular", "none", "all"}, "granular");
  s.compressedSurface = compressed == "none" ? CompressedSurface::none
                        : compressed == "all" ? CompressedSurface::all
                                              : CompressedSurface::granular;
  fs.checkKeywords();
}

void readShifting(const Dictionary& d, IsphSchemes& s) {
  const Dictionary sh = d.subDictOrEmpty("shifting");
  s.shifting.enabled = sh.getOrDefault("enabled", s.shifting.enabled);
  if (s.shifting.enabled) {
    s.shifting.coefficient = sh.getOrDefault("coefficient", s.shifting.coefficient);
    requireRange(sh, "coefficient", s.shifting.coefficient, 0.0, 20.0);
    s.shifting.maxShift = sh.getOrDefault("maxShift", s.shifting.maxShift);
    requireRange(sh, "maxShift", s.shifting.maxShift, 0.0, 1.0);
    s.shifting.pairsNearSurface = sh.getChoiceOrDefault("nearSurface", {"none", "pairs"}, "none") == "pairs";
  }
  sh.checkKeywords({"coefficient", "maxShift", "nearSurface"});
}

// The time-step factors and the two safeguards.
void readStepControls(const Dictionary& d, IsphSchemes& s) {
  const Dictionary ts = d.subDictOrEmpty("timeStep");
  s.forceFactor = ts.getOrDefault("forceFactor", s.forceFactor);
  requireRange(ts, "forceFactor", s.forceFactor, 1e-6, 10.0);
  s.viscousFactor = ts.getOrDefault("viscousFactor", s.viscousFactor);
  requireRange(ts, "viscousFactor", s.viscousFactor, 1e-6, 10.0);
  s.maxGrowth = ts.getOrDefault("maxGrowth", s.maxGrowth);
  requireRange(ts, "maxGrowth", s.maxGrowth, 1.0, 10.0);
  ts.checkKeywords();

  const Dictionary col = d.subDictOrEmpty("collision");
  s.collisionDistance = col.getOrDefault("distance", s.collisionDistance);
  requireRange(col, "distance", s.collisionDistance, 0.0, 1.0);
  col.checkKeywords();

  const Dictionary ws = d.subDictOrEmpty("wallSafeguard");
  s.wallSafeguardDistance = ws.getOrDefault("distance", s.wallSafeguardDistance);
  requireRange(ws, "distance", s.wallSafeguardDistance, 0.0, 1.0);
  ws.checkKeywords();
}

// The deviatoric term, and the incremental projection with its lagged pressure and the form
// of Eq. 11 (the projection only).
void readViscousAndProjection(const Dictionary& d, IsphSchemes& s) {
  const bool wcsph = s.method == Method::wcsph;
  s.viscousTerm = d.getChoiceOrDefault("viscousTerm", {"implicit", "explicit"}, wcsph ? "explicit" : "implicit") ==
                          "explicit"
                      ? ViscousTerm::explicit_
                      : ViscousTerm::implicit;
  if (wcsph && s.viscousTerm == ViscousTerm::implicit) {
    fatalIOError(d.findEntry("viscousTerm")->location(),
                 fmt::format("keyword 'viscousTerm' in {}: 'implicit' needs 'method isph'; the weakly-compressible "
                             "method (method wcsph) is explicit: use 'viscousTerm explicit' or remove the entry",
                             d.name()));
  }
  if (wcsph) return;
  const std::string incremental = d.getChoiceOrDefault("incrementalPressure", {"none", "granular", "all"}, "none");
  s.incrementalPressure = incremental == "none" ? MaterialScope::none
                          : incremental == "all" ? MaterialScope::all
                                                 : MaterialScope::granular;

  const Dictionary lp = d.subDictOrEmpty("laggedPressure");
  s.laggedForm = lp.getChoiceOrDefault("form", {"pairs", "gradient"}, "pairs") == "gradient"
                     ? LaggedPressureForm::gradient
                     : LaggedPressureForm::pairs;
  s.laggedSmoothing = lp.getOrDefault("smoothing", s.laggedSmoothing);
  requireRange(lp, "smoothing", s.laggedSmoothing, 0, 10);
  if (s.laggedForm == LaggedPressureForm::pairs && s.laggedSmoothing > 0) {
    fatalIOError(lp.findEntry("smoothing")->location(),
                 fmt::format("keyword 'smoothing' in {}: the pair form uses pⁿ as it is; smoothing needs "
                             "'form gradient'",
                             lp.name()));
  }
  lp.checkKeywords();

  s.pressureGradient = d.getChoiceOrDefault("pressureGradient", {"renormalised", "symmetric"}, "renormalised") ==
                               "symmetric"
                           ? PressureGradientForm::symmetric
                           : PressureGradientForm::renormalised;
  if (const Entry* e = d.findEntry("pressureGradient")) s.pressureGradientAt = e->location();
}

void readWallFriction(const Dictionary& d, IsphSchemes& s) {
  const Dictionary wf = d.subDictOrEmpty("wallFriction");
  if (wf.found("slipSpeed")) {
    s.frictionSlipSpeed = wf.get<double>("slipSpeed");
    requireRange(wf, "slipSpeed", s.frictionSlipSpeed, 1e-12, 1.0);
  }
  s.frictionPasses = wf.getOrDefault("passes", s.frictionPasses);
  requireRange(wf, "passes", s.frictionPasses, 1, 20);
  s.frictionNormal = wf.getChoiceOrDefault("normalForce", {"wallPressure", "hydrostatic"}, "wallPressure") == "hydrostatic"
                         ? FrictionNormal::hydrostatic
                         : FrictionNormal::wallPressure;
  wf.checkKeywords();
}

}  // namespace

IsphSchemes IsphSchemes::read(const Dictionary& d, int dimension) {
  IsphSchemes s;
  s.method = d.getChoiceOrDefault("method", {"isph", "wcsph"}, "isph") == "wcsph" ? Method::wcsph : Method::isph;
  readWeaklyCompressible(d, s);
  d.markRead("kernel");  // (the kernel's: makeKernel, src/sph)
  d.markRead("hOverDx");
  s.kernelCorrection = d.getOrDefault("kernelCorrection", s.kernelCorrection);
  if (s.method == Method::isph) readPressurePoisson(d, s);
  readFreeSurface(d, dimension, s);
  s.tensionCutoff = d.getOrDefault("tensionCutoff", s.tensionCutoff);
  readShifting(d, s);
  readStepControls(d, s);
  readViscousAndProjection(d, s);
  readWallFriction(d, s);
  if (s.method == Method::wcsph) {  // no PPE, no implicit solve: the projection's entries are not read
    for (const char* key : {"laplacian", "source", "incrementalPressure", "laggedPressure", "pressureGradient"}) {
      if (const Entry* e = d.findEntry(key)) {
        warning(fmt::format("keyword '{}' in {} is the projection's (method isph): not used by method wcsph", key,
                            d.name()),
                e->location());
        d.markRead(key);
      }
    }
  }
  d.checkKeywords();
  return s;
}

std::string IsphSchemes::describe() const {
  std::string out;
  if (method == Method::wcsph) {
    out += fmt::format("    method: weakly-compressible SPH, explicit (linear equation of state, sound speed {}; "
                       "delta-SPH density diffusion {}; Monaghan artificial viscosity alpha {}); acoustic Courant "
                       "limit\n",
                       wcsph.soundSpeed > 0 ? fmt::format("{:.4g} m/s", wcsph.soundSpeed) : std::string("from the scene"),
                       wcsph.densityDiffusion > 0 ? fmt::format("delta = {}", wcsph.densityDiffusion) : std::string("off"),
                       wcsph.artificialViscosity);
  } else {
    out += "    method: incompressible SPH, projection (Chorin; Eqs. 6-11)\n";
  }
  out += fmt::format("    kernel gradient correction {}\n", kernelCorrection ? "on" : "off");
  const bool projection = method == Method::isph;
  if (projection) {
    out += fmt::format("    PPE: Shao-Lo Laplacian (eta {} h{}), source {}", ppe.laplacianEta,
                       ppe.laplacianCorrection ? ", first-order correction where the support is cut" : "",
                       toString(ppe.source));
    if (ppe.source == PpeSource::mixed) out += fmt::format(" (alpha {})", ppe.alpha);
    out += fmt::format("; next to the free surface and walls {} of the compression beyond the lattice density "
                       "undone per step\n",
                       ppe.boundaryRelaxation);
  }
  out += fmt::format("    free surface: div r < {}, or |grad C| h > {}, or fewer than {:.0f}% of a full "
                     "neighbourhood\n",
                     freeSurfaceThreshold, freeSurfaceGradient, 100 * minNeighbourFraction);
  if (projection) {
    out += fmt::format("    compressed free-surface particles (kernel sum above the lattice's, away from walls): {}\n",
                       compressedSurface == CompressedSurface::none ? "held at p = 0"
                       : compressedSurface == CompressedSurface::all
                           ? "unknowns of the PPE"
                           : "unknowns of the PPE in granular materials, p = 0 in fluids");
  }
  out += fmt::format("    tension cut-off: {}\n", !tensionCutoff ? "off"
                                                  : projection  ? "on, p >= 0 after the PPE solve"
                                                                : "on, p >= 0 from the equation of state");
  if (shifting.enabled) {
    out += fmt::format("    particle shifting: Lind et al. (2012), A = {}, |dr| <= {} dx; none at the free surface, "
                       "{} next to it\n",
                       shifting.coefficient, shifting.maxShift, shifting.pairsNearSurface ? "the pair term alone" : "none");
  } else {
    out += "    particle shifting: off\n";
  }
  out += collisionDistance > 0
             ? fmt::format("    minimum distance: material pairs closer than {} dx separated as inelastic contacts\n",
                           collisionDistance)
             : std::string("    minimum distance: off\n");
  out += fmt::format("    time step: force factor {}, viscous factor {}, growth <= {}x per step\n", forceFactor,
                     viscousFactor, maxGrowth);
  out += fmt::format("    deviatoric term (where a material has one): {}\n",
                     viscousTerm == ViscousTerm::implicit
                         ? fmt::format("semi-implicit (Morris operator, one PCG solve per component, or one for all "
                                       "components where a Coulomb wall drag acts, repeated up to {} times "
                                       "until the stick/slip state of every particle on a wall settles; no "
                                       "viscous time-step limit)",
                                       frictionPasses)
                         : std::string("explicit (Morris operator; viscous time-step limit)"));
  if (viscousTerm == ViscousTerm::implicit) {
    out += fmt::format("    pressure in the viscous solve: {}\n",
                       incrementalPressure == MaterialScope::none
                           ? "none (Eq. 11 corrects with the whole pressure)"
                           : std::string("incremental projection (a second viscous solve sees the last pressure "
                                         "force; a second PPE corrects it with the increment)") +
                                 (incrementalPressure == MaterialScope::granular ? " in scenes with a granular material"
                                                                                 : ""));
    if (incrementalPressure != MaterialScope::none) {
      out += laggedForm == LaggedPressureForm::pairs
                 ? std::string("    lagged pressure force: symmetric pair form; the friction walls' pairs give the "
                               "normal reaction for the Coulomb friction\n")
                 : fmt::format("    lagged pressure force: the renormalised gradient of Eq. 11 of p^n{}; Coulomb "
                               "friction from the wall pressures\n",
                               laggedSmoothing > 0 ? fmt::format(" after {} Shepard pass{}", laggedSmoothing,
                                                                 laggedSmoothing > 1 ? "es" : "")
                                                   : std::string());
    }
  }
  if (pressureGradient == PressureGradientForm::symmetric) {
    out += "    pressure gradient of Eq. 11: symmetric, sum m_b (p_a/rho_a^2 + p_b/rho_b^2) grad W (as the paper)\n";
  }
  if (frictionNormal == FrictionNormal::hydrostatic) {
    out += "    Coulomb wall friction: tan delta times the material's pressure carried hydrostatically to each wall "
           "particle\n";
  }
  return out;
}

}  // namespace isph
