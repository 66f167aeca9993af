#pragma once
// What field I/O needs to know about each particle field type: its OpenFOAM class name,
// its number of components and how to reach them, and what an error says was expected.
#include <type_traits>

#include "core/Types.hpp"

namespace isph {

template <class T>
struct FieldTraits;

template <>
struct FieldTraits<scalar> {
  using Component = scalar;
  static constexpr int nComponents = 1;
  static constexpr const char* className = "scalarField";
  static constexpr const char* expected = "a number";
};

template <>
struct FieldTraits<label> {
  using Component = label;
  static constexpr int nComponents = 1;
  static constexpr const char* className = "labelField";
  static constexpr const char* expected = "a label (an integer)";
};

template <>
struct FieldTraits<Vec3> {
  using Component = scalar;
  static constexpr int nComponents = 3;
  static constexpr const char* className = "vectorField";
  static constexpr const char* expected = "a vector (x y z)";
};

template <>
struct FieldTraits<SymmTensor> {
  using Component = scalar;
  static constexpr int nComponents = 6;
  static constexpr const char* className = "symmTensorField";
  static constexpr const char* expected = "a symmTensor (xx xy xz yy yz zz)";
};

// Binary I/O copies whole arrays: every type must be its components, tightly packed.
template <class T>
constexpr bool isPackedField = sizeof(T) == FieldTraits<T>::nComponents *
                                                sizeof(typename FieldTraits<T>::Component) &&
                               std::is_trivially_copyable_v<typename FieldTraits<T>::Component>;

}  // namespace isph
