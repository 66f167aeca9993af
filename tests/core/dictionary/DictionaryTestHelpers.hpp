#pragma once
// Helpers shared by the dictionary tests: temporary case folders and error capture.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <unistd.h>

#include "core/Error.hpp"

namespace isph::test {

// A fresh temporary folder removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            (std::string("isph_") + info->test_suite_name() + "_" + info->name() + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& relative, const std::string& text) const {
    const auto file = path_ / relative;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
  }

 private:
  std::filesystem::path path_;
};

// Runs `f`, expects a FatalError and returns it (fails the test if none is thrown).
inline FatalError expectFatal(const std::function<void()>& f) {
  try {
    f();
  } catch (const FatalError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a FatalError";
  return FatalError("none");
}

// The error is located in `file` at `line` and its message contains every `part`.
inline void expectErrorAt(const FatalError& e, const std::string& file, int line,
                          std::initializer_list<std::string> parts) {
  ASSERT_TRUE(e.where().file) << e.what();
  EXPECT_EQ(*e.where().file, file) << e.report();
  EXPECT_EQ(e.where().line, line) << e.report();
  const std::string report = e.report();
  EXPECT_NE(report.find(file + ", line " + std::to_string(line)), std::string::npos) << report;
  for (const auto& part : parts) EXPECT_NE(report.find(part), std::string::npos) << "missing '" << part << "' in" << report;
}

}  // namespace isph::test
