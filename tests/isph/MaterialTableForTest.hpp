#pragma once
// A MaterialTable from the text of a `materials { ... }` dictionary, for tests that build a
// ParticleSystem by hand: written to a temporary constant/materialProperties and read back.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "isph/materials/MaterialTable.hpp"

namespace isph::test {

inline std::unique_ptr<MaterialTable> materialTable(const std::string& name, const std::string& materials,
                                                    const std::vector<std::string>& used) {
  // One file per process: ctest runs the cases of one suite at once in separate processes, and
  // a shared name let one case remove the file another was reading (seen under -j2).
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / (name + "." + std::to_string(::getpid()) + ".materialProperties");
  std::ofstream(file) << "FoamFile { version 2.0; format ascii; class dictionary; object materialProperties; }\n"
                      << "materials { " << materials << " }\n";
  auto table = std::make_unique<MaterialTable>(file, used);
  std::filesystem::remove(file);
  return table;
}

}  // namespace isph::test
