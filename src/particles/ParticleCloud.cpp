#include "particles/ParticleCloud.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"

namespace isph {

void ParticleCloud::resize(std::size_t n) {
  positions.resize(n, Vec3::Zero());
  origId.resize(n, -1);
  U.resize(n, Vec3::Zero());
  p.resize(n, 0.0);
  material.resize(n, -1);
  kind.resize(n, static_cast<label>(ParticleKind::material));
  patch.resize(n, -1);
  normal.resize(n, Vec3::Zero());
  mass.resize(n, 0.0);
}

void ParticleCloud::reserve(std::size_t n) {
  positions.reserve(n);
  origId.reserve(n);
  U.reserve(n);
  p.reserve(n);
  material.reserve(n);
  kind.reserve(n);
  patch.reserve(n);
  normal.reserve(n);
  mass.reserve(n);
}

void ParticleCloud::push_back(const Vec3& x, label id, const Vec3& u, scalar pressure, label mat, ParticleKind k,
                              label patchIndex, const Vec3& n, scalar m) {
  positions.push_back(x);
  origId.push_back(id);
  U.push_back(u);
  p.push_back(pressure);
  material.push_back(mat);
  kind.push_back(static_cast<label>(k));
  patch.push_back(patchIndex);
  normal.push_back(n);
  mass.push_back(m);
}

namespace {
template <class T>
void permuteField(std::vector<T>& field, const std::vector<int>& order) {
  std::vector<T> out(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) out[i] = field[static_cast<std::size_t>(order[i])];
  field.swap(out);
}
}  // namespace

void ParticleCloud::permute(const std::vector<int>& order) {
  if (order.size() != size()) fatalError("ParticleCloud::permute: the order has the wrong length");
  permuteField(positions, order);
  permuteField(origId, order);
  permuteField(U, order);
  permuteField(p, order);
  permuteField(material, order);
  permuteField(kind, order);
  permuteField(patch, order);
  permuteField(normal, order);
  permuteField(mass, order);
}

void ParticleCloud::checkSizes(const std::string& where) const {
  const std::size_t n = positions.size();
  auto check = [&](std::size_t size, const char* field) {
    if (size != n) {
      fatalError(fmt::format("{}: field '{}' of cloud '{}' has {} values but positions has {}", where, field, name,
                             size, n));
    }
  };
  check(origId.size(), "origId");
  check(U.size(), "U");
  check(p.size(), "p");
  check(material.size(), "material");
  check(kind.size(), "kind");
  check(patch.size(), "patch");
  check(normal.size(), "normal");
  check(mass.size(), "mass");
}

}  // namespace isph
