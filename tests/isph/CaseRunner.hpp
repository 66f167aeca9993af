#pragma once
// Runs a copy of a tutorial case in a temporary folder, with dictionary edits, for the
// solver's validation tests.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>

#include "particles/ParticleCloud.hpp"

namespace isph::test {

// The whole content of a text file ("" if it cannot be read).
inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A folder of its own for each test and process: ctest -j runs the tests of one binary at
// once, and two tests that copy the same tutorial must not share a case (they did: the two
// sliding-block tests overwrote each other's time directories).
inline std::filesystem::path caseFolder(const std::string& name) {
  std::string id = "isphTest-" + name;
  if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info()) {
    id += std::string("-") + info->test_suite_name() + "." + info->name();
  }
  for (char& ch : id) {
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '.' && ch != '_') ch = '_';
  }
  return std::filesystem::temp_directory_path() / (id + "-" + std::to_string(::getpid()));
}

class CaseRunner {
 public:
  CaseRunner(const std::string& tutorial, const std::string& name) : dir_(caseFolder(name)) {
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    // The case's dictionaries and data only: not the results of a run of the tutorial itself.
    for (const auto& e : std::filesystem::directory_iterator(std::string(ISPH_TUTORIALS) + "/" + tutorial)) {
      const std::string name = e.path().filename().string();
      if (name == "system" || name == "constant" || name == "validation") {
        std::filesystem::copy(e.path(), dir_ / name, std::filesystem::copy_options::recursive);
      }
    }
  }
  ~CaseRunner() {
    std::error_code ec;
    if (!::testing::Test::HasFailure()) std::filesystem::remove_all(dir_, ec);
  }

  // Replaces the value of `keyword` (a whole "keyword value;" line) in a case file.
  void set(const std::string& file, const std::string& keyword, const std::string& value) {
    std::ifstream in(dir_ / file);
    std::stringstream text;
    text << in.rdbuf();
    const std::regex line("(^|\n)(" + keyword + ")[ \t]+[^;\n]*;");
    const std::string edited = std::regex_replace(text.str(), line, "$1$2 " + value + ";");
    ASSERT_NE(edited, text.str()) << keyword << " not found in " << file;
    std::ofstream(dir_ / file) << edited;
  }

  // Replaces the text `from` (which must occur) by `to` in a case file.
  void replaceText(const std::string& file, const std::string& from, const std::string& to) {
    std::ifstream in(dir_ / file);
    std::stringstream text;
    text << in.rdbuf();
    std::string edited = text.str();
    const auto at = edited.find(from);
    ASSERT_NE(at, std::string::npos) << "'" << from << "' not found in " << file;
    edited.replace(at, from.size(), to);
    std::ofstream(dir_ / file) << edited;
  }

  // A tutorial's variant (`./Allrun -<suffix>`): every system/X.<suffix> and constant/X.<suffix>
  // of the copy replaces X.
  void useVariant(const std::string& suffix) {
    for (const char* folder : {"system", "constant"}) {
      for (const auto& e : std::filesystem::directory_iterator(dir_ / folder)) {
        const auto name = e.path().filename().string();
        const std::string ending = "." + suffix;
        if (name.size() > ending.size() && name.ends_with(ending)) {
          std::filesystem::rename(e.path(), dir_ / folder / name.substr(0, name.size() - ending.size()));
        }
      }
    }
  }

  // Appends `text` to a case file (e.g. an entry at the end of a dictionary).
  void append(const std::string& file, const std::string& text) {
    ASSERT_TRUE(std::filesystem::exists(dir_ / file)) << file << " not found";
    // In a file of its own, #included at the end: its entries may override the file's (a key
    // written twice in one file is an error).
    const std::filesystem::path extra = dir_ / (file + ".append" + std::to_string(++appended_));
    std::ofstream(extra) << text << "\n";
    std::ofstream(dir_ / file, std::ios::app) << "\n#include \"" << extra.filename().string() << "\"\n";
  }

  // Runs an application in the case; returns its exit code (its log is log.<name>).
  // `environment`: assignments put before the command, e.g. "OMP_NUM_THREADS=2".
  int run(const std::string& exe, const std::string& name, const std::string& options = "",
          const std::string& environment = "") const {
    const std::string cmd = (environment.empty() ? "" : environment + " ") + "'" + exe + "' " + options + " -case '" +
                            dir_.string() + "' > '" + (dir_ / ("log." + name)).string() + "' 2>&1";
    const int rc = std::system(cmd.c_str());
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
  }

  // particleMesh, then the solver, each expected to succeed (call in ASSERT_NO_FATAL_FAILURE).
  void meshAndSolve() const {
    ASSERT_EQ(run(PARTICLEMESH_EXE, "particleMesh"), 0) << "see " << dir_ / "log.particleMesh";
    ASSERT_EQ(run(SOLVER_EXE, "isphLandslideFoam"), 0) << "see " << dir_ / "log.isphLandslideFoam";
  }

  // The rest of the last line of log.<name> that starts with `prefix` (trimmed); "" if none.
  std::string logValue(const std::string& name, const std::string& prefix) const {
    std::ifstream in(dir_ / ("log." + name));
    std::string line, value;
    while (std::getline(in, line)) {
      const auto at = line.find(prefix);
      if (at == std::string::npos) continue;
      value = line.substr(at + prefix.size());
      value.erase(0, value.find_first_not_of(" \t"));
      value.erase(value.find_last_not_of(" \t") + 1);
    }
    return value;
  }

  const std::filesystem::path& path() const { return dir_; }

 private:
  std::filesystem::path dir_;
  int appended_ = 0;
};

// The mean x of a cloud's material particles (its centre of mass where they have equal masses).
inline double meanMaterialX(const ParticleCloud& cloud) {
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (cloud.kind[i] != 0) continue;
    sum += cloud.positions[i].x();
    ++n;
  }
  return sum / n;
}

// The largest distance any material particle has moved between two clouds of a case.
// (Of the particles whose start position satisfies `from`, if given.)
inline double largestMaterialDisplacement(const ParticleCloud& start, const ParticleCloud& end,
                                          const std::function<bool(const Vec3&)>& from = {}) {
  std::map<label, Vec3> initial;
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (start.kind[i] == 0) initial[start.origId[i]] = start.positions[i];
  }
  double largest = 0;
  for (std::size_t i = 0; i < end.size(); ++i) {
    if (end.kind[i] != 0) continue;
    const Vec3& x0 = initial.at(end.origId[i]);
    if (!from || from(x0)) largest = std::max(largest, (end.positions[i] - x0).norm());
  }
  return largest;
}

// The largest differences in position and velocity between the same particles (by origId)
// of two clouds, e.g. of two runs of one case that should agree.
struct CloudDifference {
  double position = 0;
  double velocity = 0;
};
inline CloudDifference largestDifference(const ParticleCloud& A, const ParticleCloud& B) {
  std::map<label, std::size_t> indexOf;
  for (std::size_t i = 0; i < B.size(); ++i) indexOf[B.origId[i]] = i;
  CloudDifference d;
  for (std::size_t i = 0; i < A.size(); ++i) {
    const std::size_t j = indexOf.at(A.origId[i]);
    d.position = std::max(d.position, (A.positions[i] - B.positions[j]).norm());
    d.velocity = std::max(d.velocity, (A.U[i] - B.U[j]).norm());
  }
  return d;
}

}  // namespace isph::test
