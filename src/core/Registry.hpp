#pragma once
// Run-time selection by name, as OpenFOAM's selection tables: a model registers a
// factory under the name users write in a dictionary (`kernel WendlandC2;`), and the code
// that needs one asks the registry, so adding a model never edits the solver.
//
//   ISPH_REGISTER(Kernel, WendlandC2, "WendlandC2");   // in WendlandC2.cpp
//   auto k = Registry<Kernel, double, int>::create("WendlandC2", where, h, dim);
#include <fmt/format.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "core/Strings.hpp"

namespace isph {

template <class Base, class... Args>
class Registry {
 public:
  using Factory = std::function<std::unique_ptr<Base>(Args...)>;

  static bool add(const std::string& name, Factory factory) {
    table()[name] = std::move(factory);
    return true;
  }

  static std::vector<std::string> names() {
    std::vector<std::string> out;
    for (const auto& [name, f] : table()) out.push_back(name);
    return out;
  }

  // `what` names the selection in errors ("kernel"), `where` locates the keyword.
  static std::unique_ptr<Base> create(const std::string& name, const std::string& what, const SourceLocation& where,
                                      Args... args) {
    const auto it = table().find(name);
    if (it == table().end()) {
      fatalIOError(where, fmt::format("unknown {} '{}'; valid choices: {}{}", what, name, join(names(), ", "),
                                      didYouMean(name, names())));
    }
    return it->second(std::forward<Args>(args)...);
  }

 private:
  static std::map<std::string, Factory>& table() {
    static std::map<std::string, Factory> t;
    return t;
  }
};

}  // namespace isph
