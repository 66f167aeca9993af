#pragma once
// The per-particle arrays that travel with a particle from rank to rank: the nine fields of a
// ParticleCloud and any further arrays the caller adds (a std::vector of a trivially copyable
// value type each, all of one length), packed into bytes particle by particle for Zoltan's
// communication package (CommPlan).
#include <cstddef>
#include <cstring>
#include <type_traits>
#include <vector>

#include "particles/ParticleCloud.hpp"

namespace isph {

class ParticleFields {
 public:
  ParticleFields() = default;
  // The cloud's nine fields (the cloud must outlive this object).
  explicit ParticleFields(ParticleCloud& cloud);

  template <class T>
  void add(std::vector<T>& field) {
    // Copied as bytes: plain values, or fixed-size Eigen vectors (a plain array of doubles
    // underneath, though Eigen declares its own copy constructor).
    static_assert(std::is_trivially_destructible_v<T> && std::is_standard_layout_v<T>,
                  "a particle field must be a plain value");
    fields_.push_back({sizeof(T), &field, &bytesOf<T>, &sizeOf<T>, &resizeOf<T>});
  }

  std::size_t size() const;  // particles (FatalError if the fields differ in length)
  std::size_t bytesPerParticle() const;
  // The particles `which`, in that order, packed one after the other.
  std::vector<std::byte> pack(const std::vector<std::size_t>& which) const;
  // Appends `count` packed particles (as pack() writes them) to every field.
  void append(const std::byte* packed, std::size_t count);
  // Keeps the particles `which`, in that order.
  void keep(const std::vector<std::size_t>& which);

 private:
  struct Field {
    std::size_t bytes;
    void* vector;
    std::byte* (*data)(void*);
    std::size_t (*size)(const void*);
    void (*resize)(void*, std::size_t);
  };
  template <class T>
  static std::byte* bytesOf(void* v) {
    return reinterpret_cast<std::byte*>(static_cast<std::vector<T>*>(v)->data());
  }
  template <class T>
  static std::size_t sizeOf(const void* v) {
    return static_cast<const std::vector<T>*>(v)->size();
  }
  template <class T>
  static void resizeOf(void* v, std::size_t n) {
    static_cast<std::vector<T>*>(v)->resize(n);
  }

  std::vector<Field> fields_;
};

}  // namespace isph
