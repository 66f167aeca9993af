#include "parallel/Migration.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "parallel/CommPlan.hpp"
#include "parallel/Reduce.hpp"

namespace isph {

std::size_t migrateParticles(ParticleFields& fields, const std::vector<int>& destination) {
  const std::size_t n = fields.size();
  if (destination.size() != n) {
    fatalError(fmt::format("migrateParticles: {} destinations for {} particles", destination.size(), n));
  }
  const int me = thisRank(), ranks = nRanks();
  std::vector<std::size_t> stay, leave;
  std::vector<int> to;
  for (std::size_t i = 0; i < n; ++i) {
    if (destination[i] < 0 || destination[i] >= ranks) {
      fatalError(fmt::format("migrateParticles: particle {} is sent to rank {} of {}", i, destination[i], ranks));
    }
    if (destination[i] == me) {
      stay.push_back(i);
    } else {
      leave.push_back(i);
      to.push_back(destination[i]);
    }
  }
  const CommPlan plan(to);
  const std::vector<std::byte> out = fields.pack(leave);
  std::vector<std::byte> in(plan.nReceived() * fields.bytesPerParticle());
  plan.exchange(out.data(), fields.bytesPerParticle(), in.data());
  fields.keep(stay);
  fields.append(in.data(), plan.nReceived());
  return plan.nReceived();
}

}  // namespace isph
