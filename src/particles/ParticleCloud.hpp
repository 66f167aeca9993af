#pragma once
// The particles of one cloud as structure-of-arrays: one std::vector per field, all of
// the same length. Loops over particles write only their own entries.
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "particles/ParticleKind.hpp"

namespace isph {

// What the `material` and `patch` labels index, written beside the fields
// (<time>/lagrangian/<cloud>/cloudProperties) so that every tool can name them.
struct PatchInfo {
  std::string name;
  double frictionAngle = 0.0;  // degrees; Coulomb wall friction (0: frictionless)
};

struct CloudProperties {
  std::vector<std::string> materials;  // material label -> name in constant/materialProperties
  std::vector<PatchInfo> patches;      // patch label -> patch
  int dimension = 2;
  double spacing = 0.0;                // initial particle spacing dx [m]
  std::string lattice = "square";      // square | hexagonal: the initial lattice of material sites
};

struct ParticleCloud {
  std::string name = "particles";
  CloudProperties properties;

  std::vector<Vec3> positions;  // [m]
  std::vector<label> origId;    // persistent id, survives reordering and restarts
  std::vector<Vec3> U;          // velocity [m/s]
  std::vector<scalar> p;        // pressure (mean normal stress, compression positive) [Pa]
  std::vector<label> material;  // index into properties.materials (-1 for walls)
  std::vector<label> kind;      // ParticleKind
  std::vector<label> patch;     // index into properties.patches (-1 for material particles)
  std::vector<Vec3> normal;     // outward unit normal of the wall surface (zero for others)
  std::vector<scalar> mass;     // [kg] per unit width in 2D

  std::size_t size() const { return positions.size(); }
  void resize(std::size_t n);
  void reserve(std::size_t n);
  // Append one particle (all fields).
  void push_back(const Vec3& x, label id, const Vec3& u, scalar pressure, label mat, ParticleKind k,
                 label patchIndex, const Vec3& n, scalar m);

  // Reorder all fields: new particle i is old particle order[i] (a permutation).
  void permute(const std::vector<int>& order);

  // Throws a FatalError naming the field if any field's length differs from positions'.
  void checkSizes(const std::string& where) const;
};

}  // namespace isph
