#pragma once
// Helpers shared by the post-processing tests: a temporary folder, small clouds with known
// values, and running a utility as a user does.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "particles/ParticleCloud.hpp"

namespace isph::pptest {

// A fresh folder under the system's temporary directory, removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("isph_pp_") + info->test_suite_name() + "_" + info->name() + "_" +
                       std::to_string(::getpid());
    std::replace(name.begin(), name.end(), '/', '_');
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& relative) const { return path_ / relative; }

 private:
  std::filesystem::path path_;
};

inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void writeText(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// Runs `command` through the shell with stdout and stderr into `log`; returns the exit status.
inline int run(const std::string& command, const std::filesystem::path& log) {
  const int rc = std::system((command + " > '" + log.string() + "' 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

// A flat bed y = 0 of `n` wall particles dx apart (x = (i+½) dx, normal +y, patch 0 "bed"),
// a dummy under each (patch 0) and a material particle above each; all pressures `p`.
inline ParticleCloud flatBed(int n, double dx, double p) {
  ParticleCloud c;
  c.properties.materials = {"water"};
  c.properties.patches = {{"bed", 0.0}, {"barrier", 0.0}};
  c.properties.spacing = dx;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) * dx;
    c.push_back(Vec3(x, 0, 0), 3 * i, Vec3::Zero(), p, -1, ParticleKind::wall, 0, Vec3(0, 1, 0), 0);
    c.push_back(Vec3(x, -dx, 0), 3 * i + 1, Vec3::Zero(), 10 * p, -1, ParticleKind::dummy, 0, Vec3::Zero(), 0);
    c.push_back(Vec3(x, dx, 0), 3 * i + 2, Vec3(1, 0, 0), p, 0, ParticleKind::material, -1, Vec3::Zero(), 1);
  }
  return c;
}

}  // namespace isph::pptest
