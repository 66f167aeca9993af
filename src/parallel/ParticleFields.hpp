#pragma once
// The per-particle arrays that travel with a particle from rank to rank: the nine fields of a
// ParticleCloud and any further arrays the caller adds (a std::vector of a trivially copyable
// value type each, all of one length), packed into bytes particle by particle for Zoltan's
// communication package (CommPlan).
#include <algorithm>
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
    fields_.push_back({sizeof(T), &field, &bytesOf<T>, &sizeOf<T>, &gatherOf<T>, &eraseOf<T>, &insertOf<T>});
  }

  std::size_t size() const;  // particles (FatalError if the fields differ in length)
  std::size_t bytesPerParticle() const;
  // The particles `which`, in that order, packed one after the other.
  std::vector<std::byte> pack(const std::vector<std::size_t>& which) const;
  // Appends `count` packed particles (as pack() writes them) to every field.
  void append(const std::byte* packed, std::size_t count);
  // Keeps the particles `which`, in that order.
  void keep(const std::vector<std::size_t>& which);
  // Removes the particles [first, first + count) / inserts `count` packed particles before
  // particle `at`: the others keep their order, and only those after move (a block move).
  void erase(std::size_t first, std::size_t count);
  void insert(std::size_t at, const std::byte* packed, std::size_t count);

 private:
  struct Field {
    std::size_t bytes;
    void* vector;
    std::byte* (*data)(void*);
    std::size_t (*size)(const void*);
    void (*gather)(void*, const std::vector<std::size_t>&);
    void (*erase)(void*, std::size_t, std::size_t);
    void (*insert)(void*, std::size_t, std::size_t);
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
  static void gatherOf(void* v, const std::vector<std::size_t>& which) {
    auto& field = *static_cast<std::vector<T>*>(v);
    std::vector<T> out;
    out.reserve(which.size());
    for (const std::size_t i : which) out.push_back(field[i]);
    field.swap(out);
  }
  template <class T>
  static void eraseOf(void* v, std::size_t first, std::size_t count) {
    auto& field = *static_cast<std::vector<T>*>(v);
    field.erase(field.begin() + static_cast<long>(first), field.begin() + static_cast<long>(first + count));
  }
  template <class T>
  static void insertOf(void* v, std::size_t at, std::size_t count) {
    auto& field = *static_cast<std::vector<T>*>(v);  // room for `count` before `at` (filled by the caller)
    const std::size_t old = field.size();
    field.resize(old + count);
    std::move_backward(field.begin() + static_cast<long>(at), field.begin() + static_cast<long>(old), field.end());
  }

  std::vector<Field> fields_;
};

}  // namespace isph
