#pragma once
// How each C++ type is read from (and written to) dictionary tokens. Dictionary::get<T>
// uses ValueTraits<T>; add a specialisation to make a new type readable.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <concepts>
#include <limits>
#include <string>
#include <vector>

#include "core/Types.hpp"
#include "core/dictionary/DictionaryLimits.hpp"
#include "core/dictionary/TokenReader.hpp"

namespace isph {

template <class T>
struct ValueTraits;

// Shortest text that reads back to the same double ("0.1", "1e-05", "2.5").
std::string formatScalar(double value);

template <std::floating_point T>
struct ValueTraits<T> {
  static std::string expected() { return "a number"; }
  static T read(TokenReader& in) { return static_cast<T>(in.nextNumber(expected()).number); }
  static std::string write(T v) { return formatScalar(static_cast<double>(v)); }
};

template <std::integral T>
  requires(!std::same_as<T, bool>)
struct ValueTraits<T> {
  static std::string expected() { return "an integer"; }
  static T read(TokenReader& in) {
    const Token& t = in.peek();
    if (!t.isNumber()) in.nextNumber(expected());  // throws (and says so for nan or inf)
    if (!t.isInteger) in.expected(expected());
    if (t.number < static_cast<double>(std::numeric_limits<T>::min()) ||
        t.number > static_cast<double>(std::numeric_limits<T>::max())) {
      in.errorAt(t, fmt::format("integer {} is out of range", t.text));
    }
    in.next();
    return static_cast<T>(t.number);
  }
  static std::string write(T v) { return std::to_string(v); }
};

template <>
struct ValueTraits<bool> {
  static std::string expected() { return "a switch (on/off, yes/no, true/false)"; }
  static bool read(TokenReader& in);
  static std::string write(bool v) { return v ? "true" : "false"; }
};

template <>
struct ValueTraits<std::string> {
  static std::string expected() { return "a word or a quoted string"; }
  static std::string read(TokenReader& in) {
    const Token& t = in.peek();
    if (!(t.isWord() || t.isString())) in.expected(expected());
    in.next();
    return t.text;
  }
  static std::string write(const std::string& v);
};

// Fixed-size vectors: (x y z), (x y), six-component symmetric tensors.
template <int N>
struct ValueTraits<Eigen::Matrix<double, N, 1>> {
  using V = Eigen::Matrix<double, N, 1>;
  static std::string expected() {
    if constexpr (N == 3) return "a vector (x y z)";
    if constexpr (N == 2) return "a 2D vector (x y)";
    if constexpr (N == 6) return "a symmetric tensor (xx xy xz yy yz zz)";
    return fmt::format("a list of {} numbers", N);
  }
  static V read(TokenReader& in) {
    if (in.atEnd() || !in.peek().isPunct('(')) in.expected(expected());
    in.next();
    V v;
    for (int k = 0; k < N; ++k) v[k] = in.nextNumber(fmt::format("{} numbers in {}", N, expected())).number;
    if (in.atEnd() || !in.peek().isPunct(')')) in.expected(fmt::format("')' closing {}", expected()));
    in.next();
    return v;
  }
  static std::string write(const V& v) {
    std::string out = "(";
    for (int k = 0; k < N; ++k) {
      if (k) out += ' ';
      out += formatScalar(v[k]);
    }
    return out + ")";
  }
};

// Lists: (a b c), N(a b c) or N{a} (N copies of a).
template <class T>
struct ValueTraits<std::vector<T>> {
  static std::string expected() { return "a list ( ... ) of " + ValueTraits<T>::expected(); }
  static std::vector<T> read(TokenReader& in) {
    std::vector<T> out;
    long size = -1;
    if (!in.atEnd() && in.peek().isNumber() && in.peek().isInteger) {
      const Token& n = in.next();
      if (n.number < 0) in.errorAt(n, "a list size must not be negative");
      if (n.number > static_cast<double>(DictionaryLimits::maxListElements)) {
        in.errorAt(n, fmt::format("a list of {} elements is more than the {} a dictionary list may hold", n.text,
                                  DictionaryLimits::maxListElements));
      }
      size = static_cast<long>(n.number);
      if (in.acceptPunct('{')) {  // uniform list N{value}
        T value = ValueTraits<T>::read(in);
        in.expectPunct('}', "closing a uniform list N{value}");
        return std::vector<T>(static_cast<std::size_t>(size), value);
      }
    }
    if (in.atEnd() || !in.peek().isPunct('(')) in.expected(expected());
    const Token& open = in.next();
    while (!in.atEnd() && !in.peek().isPunct(')')) out.push_back(ValueTraits<T>::read(in));
    if (in.atEnd()) in.errorAt(open, "the list opened here is not closed with ')'");
    in.next();
    if (size >= 0 && static_cast<long>(out.size()) != size) {
      in.errorAt(open, fmt::format("the list says it has {} elements but holds {}", size, out.size()));
    }
    return out;
  }
  static std::string write(const std::vector<T>& v) {
    std::string out = "(";
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (k) out += ' ';
      out += ValueTraits<T>::write(v[k]);
    }
    return out + ")";
  }
};

// OpenFOAM dimension set [mass length time temperature moles current luminosity].
struct DimensionSet {
  std::array<double, 7> exponents{};
  bool operator==(const DimensionSet&) const = default;
};

template <>
struct ValueTraits<DimensionSet> {
  static std::string expected() { return "a dimension set [M L T Θ N I J]"; }
  static DimensionSet read(TokenReader& in);
  static std::string write(const DimensionSet& d);
};

}  // namespace isph
