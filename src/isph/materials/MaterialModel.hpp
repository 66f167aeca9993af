#pragma once
// A material's constitutive model, chosen by name in constant/materialProperties
// (`model newtonian;`) from a registry, so that a new model never edits the solver.
// Models give the effective (dynamic) viscosity η(p, |γ̇|) that the deviatoric stress
// s = 2 η D uses, with |γ̇| = √(2 D:D) (equal to |∂u/∂y| in simple shear).
#include <memory>
#include <string>

#include "core/Registry.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph {

// How a material meets a wall tangentially: a fluid sticks (no slip); a granular material
// slides with Coulomb friction from the wall patch's friction angle (WallFriction).
enum class WallContact { noSlip, coulombFriction };

// The scales of the scene a material sits in, for defaults derived from the scene
// (the regularisation of the rigid-plastic model): its height along gravity, |g|, dx.
struct SceneScales {
  double height = 0;   // [m] extent of the material's particles along gravity
  double gravity = 0;  // [m/s^2]
  double spacing = 0;  // [m] particle spacing
};

class MaterialModel {
 public:
  MaterialModel(std::string name, const Dictionary& dict);
  virtual ~MaterialModel() = default;

  const std::string& name() const { return name_; }
  double rho() const { return rho_; }

  virtual std::string type() const = 0;
  // False for an inviscid fluid: no deviatoric stress is computed at all.
  virtual bool hasDeviatoricStress() const = 0;
  // Effective dynamic viscosity [Pa s] at pressure p [Pa] and shear rate |γ̇| [1/s].
  virtual double viscosity(double p, double shearRate) const = 0;
  // Upper bound of viscosity() (for the explicit viscous time-step limit).
  virtual double maxViscosity() const = 0;
  virtual WallContact wallContact() const { return WallContact::noSlip; }
  // A granular material (a soil model): the schemes that isphSchemes applies to granular
  // materials (freeSurface's `compressed granular`) act on it.
  virtual bool granular() const { return false; }
  // True for a model that integrates its stress in time (elasticPlastic, ElasticPlasticStress)
  // instead of deriving it from a viscosity: viscosity() is then unused.
  virtual bool integratesStress() const { return false; }
  // Called once the particles are known, before describe(): models whose defaults
  // depend on the scene set them here.
  virtual void adaptToScene(const SceneScales&) {}
  // One line for the log.
  virtual std::string describe() const = 0;

 protected:
  std::string name_;
  double rho_;
};

using MaterialRegistry = Registry<MaterialModel, const std::string&, const Dictionary&>;

// The model named by `model` in `dict` (FatalError naming the file and line otherwise).
std::unique_ptr<MaterialModel> makeMaterialModel(const std::string& name, const Dictionary& dict);

}  // namespace isph
