#include "isph/IsphSchemes.hpp"

#include <fmt/format.h>

#include "core/dictionary/RequireRange.hpp"

namespace isph {

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
    s.shifting.deformationSpeed =
        sh.getChoiceOrDefault("speed", {"velocity", "deformation"}, "velocity") == "deformation";
  }
  sh.checkKeywords({"coefficient", "maxShift", "nearSurface", "speed"});
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

// The weakly-compressible method's deviatoric term is explicit (the projection's is a stage:
// stages/DeviatoricTerm.hpp).
void readWeaklyCompressibleViscousTerm(const Dictionary& d) {
  if (d.getChoiceOrDefault("viscousTerm", {"implicit", "explicit"}, "explicit") == "implicit") {
    fatalIOError(d.findEntry("viscousTerm")->location(),
                 fmt::format("keyword 'viscousTerm' in {}: 'implicit' needs 'method isph'; the weakly-compressible "
                             "method (method wcsph) is explicit: use 'viscousTerm explicit' or remove the entry",
                             d.name()));
  }
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
  for (const char* key : {"incrementalPressure", "laggedPressure", "pressureGradient"}) {
    if (const Entry* e = d.findEntry(key)) {
      fatalIOError(e->location(),
                   fmt::format("keyword '{}' in {} was removed (issue 48): every scene runs the plain projection, "
                               "Eq. 11 in its renormalised difference form (doc/numerics.md §4); remove the line",
                               key, d.name()));
    }
  }
  s.kernelCorrection = d.getOrDefault("kernelCorrection", s.kernelCorrection);
  if (s.method == Method::isph) readPressurePoisson(d, s);
  readFreeSurface(d, dimension, s);
  s.tensionCutoff = d.getOrDefault("tensionCutoff", s.tensionCutoff);
  readShifting(d, s);
  readStepControls(d, s);
  readWallFriction(d, s);
  if (s.method == Method::wcsph) {
    readWeaklyCompressibleViscousTerm(d);  // no PPE, no implicit solve: the projection's entries are not read
    for (const char* key : {"laplacian", "source"}) {
      if (const Entry* e = d.findEntry(key)) {
        warning(fmt::format("keyword '{}' in {} is the projection's (method isph): not used by method wcsph", key,
                            d.name()),
                e->location());
        d.markRead(key);
      }
    }
  }
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
    out += fmt::format("    particle shifting: Lind et al. (2012), A = {}, D from {}, |dr| <= {} dx; none at the free "
                       "surface, {} next to it\n",
                       shifting.coefficient,
                       shifting.deformationSpeed ? "the speed of deformation h |gamma dot|" : "the speed |u|",
                       shifting.maxShift, shifting.pairsNearSurface ? "the pair term alone" : "none");
  } else {
    out += "    particle shifting: off\n";
  }
  out += collisionDistance > 0
             ? fmt::format("    minimum distance: material pairs closer than {} dx separated as inelastic contacts\n",
                           collisionDistance)
             : std::string("    minimum distance: off\n");
  out += fmt::format("    time step: force factor {}, viscous factor {}, growth <= {}x per step\n", forceFactor,
                     viscousFactor, maxGrowth);
  if (method == Method::wcsph) out += "    deviatoric term (where a material has one): explicit (Morris operator; viscous time-step limit)\n";
  if (frictionNormal == FrictionNormal::hydrostatic) {
    out += "    Coulomb wall friction: tan delta times the material's pressure carried hydrostatically to each wall "
           "particle\n";
  }
  return out;
}

}  // namespace isph
