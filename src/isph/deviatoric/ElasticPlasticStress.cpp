#include "isph/deviatoric/ElasticPlasticStress.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/Error.hpp"
#include "isph/materials/DruckerPragerElasticPlastic.hpp"

namespace isph {

std::pair<double, double> elasticPlasticSpeeds(const MaterialTable& materials, Method method) {
  double sound = 0, wave = 0;
  std::size_t elastic = 0;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    if (!materials[i].integratesStress()) continue;
    ++elastic;
    const auto& m = static_cast<const DruckerPragerElasticPlastic&>(materials[i]);
    sound = std::max(sound, m.bulkSpeed());
    wave = std::max(wave, m.waveSpeed());
  }
  if (elastic > 0 && (method != Method::wcsph || elastic != materials.size())) {
    fatalError(fmt::format("constant/materialProperties: model elasticPlastic runs with `method wcsph;` in "
                           "system/isphSchemes and with no other model in the scene; found {} of {} materials "
                           "elasticPlastic{}",
                           elastic, materials.size(), method != Method::wcsph ? " and the projection method" : ""));
  }
  return {sound, wave};
}

void ElasticPlasticStress::initialise(const ParticleSystem& ps, const std::vector<SymmTensor>* written) {
  s_.assign(ps.size(), SymmTensor::Zero());
  if (!written) return;
  for (std::size_t a = 0; a < ps.nMaterial; ++a) s_[a] = (*written)[a];
}

void ElasticPlasticStress::update(const ParticleSystem& ps, const MaterialTable& materials, double dt) {
  const auto& c = ps.cloud;
  const auto& nl = ps.neighbours;
  s_.resize(ps.size(), SymmTensor::Zero());
  const long n = static_cast<long>(ps.nMaterial);
#pragma omp parallel for schedule(static)
  for (long ia = 0; ia < n; ++ia) {
    const auto a = static_cast<std::size_t>(ia);
    Eigen::Matrix3d gradU = Eigen::Matrix3d::Zero();  // ∂u_i/∂x_j = Σ V_b (u_b − u_a) ⊗ ∇W
    for (long k = nl.start[a]; k < nl.start[a + 1]; ++k) {
      const auto kk = static_cast<std::size_t>(k);
      const auto b = static_cast<std::size_t>(nl.index[kk]);
      if (!ps.isMaterial(b)) continue;
      const Vec3 gradW = nl.F[kk] * (c.positions[a] - c.positions[b]);
      gradU.noalias() += ps.volume[b] * (c.U[b] - c.U[a]) * gradW.transpose();
    }
    if (ps.dimension == 2) gradU.row(2).setZero(), gradU.col(2).setZero();  // plane strain
    const auto& model =
        static_cast<const DruckerPragerElasticPlastic&>(materials[static_cast<std::size_t>(c.material[a])]);
    s_[a] = model.updateDeviatoric(s_[a], c.p[a], gradU, dt);
  }
}

void ElasticPlasticStress::permute(const std::vector<int>& order) {
  std::vector<SymmTensor> old(s_.begin(), s_.begin() + static_cast<long>(order.size()));
  for (std::size_t i = 0; i < order.size(); ++i) s_[i] = old[static_cast<std::size_t>(order[i])];
}

}  // namespace isph
