#include "sph/kernels/Kernel.hpp"

#include <fmt/format.h>

#include "core/Registry.hpp"
#include "core/dictionary/Dictionary.hpp"

namespace isph {

std::unique_ptr<Kernel> makeKernel(const std::string& name, double h, int dimension, const SourceLocation& where) {
  return Registry<Kernel, double, int>::create(name, "kernel", where, h, dimension);
}

std::unique_ptr<Kernel> makeKernel(const Dictionary& schemes, double dx, int dimension) {
  const std::string name = schemes.getOrDefault<std::string>("kernel", "WendlandC2");
  const double hOverDx = schemes.getOrDefault("hOverDx", 1.3);
  if (!(hOverDx >= 0.5 && hOverDx <= 4.0)) {
    fatalIOError(schemes.findEntry("hOverDx")->location(),
                 fmt::format("hOverDx {} is outside the range 0.5 to 4 that SPH supports", hOverDx));
  }
  const Entry* e = schemes.findEntry("kernel");
  return makeKernel(name, hOverDx * dx, dimension, e ? e->location() : schemes.location());
}

std::unique_ptr<Kernel> caseKernel(const std::filesystem::path& caseDir, double dx, int dimension) {
  const std::filesystem::path file = caseDir / "system" / "isphSchemes";
  const Dictionary schemes = std::filesystem::exists(file) ? Dictionary::readFile(file) : Dictionary(file.string());
  return makeKernel(schemes, dx, dimension);
}

}  // namespace isph
