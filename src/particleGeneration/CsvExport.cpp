#include "particleGeneration/CsvExport.hpp"

#include <fmt/format.h>

#include <string>

#include "core/io/AtomicFile.hpp"

namespace isph {

void writeCloudCsv(const std::filesystem::path& file, const ParticleCloud& cloud) {
  std::string text = "x,y,z,kind,material,patch,nx,ny,mass,p\n";
  text.reserve(text.size() + cloud.size() * 96);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const Vec3& x = cloud.positions[i];
    const Vec3& n = cloud.normal[i];
    fmt::format_to(std::back_inserter(text),
                   "{:.9g},{:.9g},{:.9g},{},{},{},{:.6g},{:.6g},{:.9g},{:.9g}\n", x.x(), x.y(),
                   x.z(), cloud.kind[i], cloud.material[i], cloud.patch[i], n.x(), n.y(),
                   cloud.mass[i], cloud.p[i]);
  }
  std::filesystem::create_directories(file.parent_path());
  writeFileAtomic(file, text);
}

}  // namespace isph
