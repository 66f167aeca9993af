#pragma once
// Helpers for the time tests: a temporary case folder and FatalError capture.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/Error.hpp"

namespace isph::test {

// A fresh temporary case folder, removed at the end of the test.
class TempCase {
 public:
  TempCase() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            (std::string("isphTime_") + info->test_suite_name() + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  TempCase(const TempCase&) = delete;
  TempCase& operator=(const TempCase&) = delete;
  ~TempCase() { std::filesystem::remove_all(path_); }
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path write(const std::string& relative, const std::string& text) const {
    const auto file = path_ / relative;
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
  }
  void mkdir(const std::string& relative) const {
    std::filesystem::create_directories(path_ / relative);
  }
  bool has(const std::string& relative) const { return std::filesystem::exists(path_ / relative); }

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

}  // namespace isph::test
