#pragma once
// A MaterialTable from the text of a `materials { ... }` dictionary, for tests that build a
// ParticleSystem by hand: written to a temporary constant/materialProperties and read back.
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "isph/materials/MaterialTable.hpp"

namespace isph::test {

inline std::unique_ptr<MaterialTable> materialTable(const std::string& name, const std::string& materials,
                                                    const std::vector<std::string>& used) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() / (name + ".materialProperties");
  std::ofstream(file) << "FoamFile { version 2.0; format ascii; class dictionary; object materialProperties; }\n"
                      << "materials { " << materials << " }\n";
  auto table = std::make_unique<MaterialTable>(file, used);
  std::filesystem::remove(file);
  return table;
}

}  // namespace isph::test
