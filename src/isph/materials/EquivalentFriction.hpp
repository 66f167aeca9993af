#pragma once
// Pore pressure as an equivalent friction (the paper's Eq. 12): with the pore pressure u
// held at its initial value and p' = p − u the effective mean stress,
//
//   μ_e = sin φ_e = μ_crit / (1 + u/p'),   μ_crit = sin φ'_crit.
//
// The infinite-slope estimate of u/p' (the paper's case 3): a water table at height h_w
// above the slip surface, seepage parallel to the slope, soil of depth z (both measured
// vertically) above the slip surface. Then at the slip surface
//   σ_n = ρ g z cos²β,   u = ρ_w g h_w cos²β,   p' = σ_n − u,
// so u/p' = ρ_w h_w / (ρ z − ρ_w h_w): the slope angle β cancels. Assumptions: the normal
// stress stands for the mean stress p (the rigid-plastic model is isotropic at rest, K = 1),
// the unit weight above the water table is the bulk ρ g, pore pressures stay as initialised.

namespace isph {

struct WaterTable {
  double height = 0;       // h_w [m], vertically above the slip surface
  double soilDepth = 0;    // z [m], vertical depth of soil above the slip surface
  double rhoWater = 1000;  // [kg/m^3]
};

struct EquivalentFriction {
  double porePressureRatio = 0;  // u/p'
  double phiDegrees = 0;         // φ_e
};

// Eq. 12 for a given u/p' (≥ 0).
double equivalentFrictionAngle(double phiCritDegrees, double porePressureRatio);

// u/p' from the infinite-slope estimate; throws std::invalid_argument if the inputs make
// p' ≤ 0 (the water table lifts the soil) or are not positive.
double infiniteSlopePorePressureRatio(const WaterTable& w, double rhoSoil);

}  // namespace isph
