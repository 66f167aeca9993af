#include "parallel/ParticleFields.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"

namespace isph {

ParticleFields::ParticleFields(ParticleCloud& cloud) {
  add(cloud.positions);
  add(cloud.origId);
  add(cloud.U);
  add(cloud.p);
  add(cloud.material);
  add(cloud.kind);
  add(cloud.patch);
  add(cloud.normal);
  add(cloud.mass);
}

std::size_t ParticleFields::size() const {
  if (fields_.empty()) return 0;
  const std::size_t n = fields_[0].size(fields_[0].vector);
  for (std::size_t f = 1; f < fields_.size(); ++f) {
    if (fields_[f].size(fields_[f].vector) != n) {
      fatalError(fmt::format("ParticleFields: field {} has {} values, field 0 has {}", f,
                             fields_[f].size(fields_[f].vector), n));
    }
  }
  return n;
}

std::size_t ParticleFields::bytesPerParticle() const {
  std::size_t bytes = 0;
  for (const Field& f : fields_) bytes += f.bytes;
  return bytes;
}

std::vector<std::byte> ParticleFields::pack(const std::vector<std::size_t>& which) const {
  const std::size_t n = size(), stride = bytesPerParticle();
  std::vector<std::byte> out(which.size() * stride);
  std::size_t offset = 0;
  for (const Field& f : fields_) {
    const std::byte* from = f.data(f.vector);
    for (std::size_t k = 0; k < which.size(); ++k) {
      if (which[k] >= n) fatalError(fmt::format("ParticleFields::pack: particle {} of {}", which[k], n));
      std::memcpy(out.data() + k * stride + offset, from + which[k] * f.bytes, f.bytes);
    }
    offset += f.bytes;
  }
  return out;
}

void ParticleFields::append(const std::byte* packed, std::size_t count) { insert(size(), packed, count); }

void ParticleFields::keep(const std::vector<std::size_t>& which) {
  const std::size_t n = size();
  for (const std::size_t i : which) {
    if (i >= n) fatalError(fmt::format("ParticleFields::keep: particle {} of {}", i, n));
  }
  for (Field& f : fields_) f.gather(f.vector, which);
}

void ParticleFields::erase(std::size_t first, std::size_t count) {
  if (first + count > size()) fatalError(fmt::format("ParticleFields::erase: [{}, {}) of {}", first, first + count, size()));
  for (Field& f : fields_) f.erase(f.vector, first, count);
}

void ParticleFields::insert(std::size_t at, const std::byte* packed, std::size_t count) {
  if (at > size()) fatalError(fmt::format("ParticleFields::insert: before {} of {}", at, size()));
  const std::size_t stride = bytesPerParticle();
  std::size_t offset = 0;
  for (Field& f : fields_) {
    f.insert(f.vector, at, count);
    std::byte* to = f.data(f.vector) + at * f.bytes;
    for (std::size_t k = 0; k < count; ++k) std::memcpy(to + k * f.bytes, packed + k * stride + offset, f.bytes);
    offset += f.bytes;
  }
}

}  // namespace isph
