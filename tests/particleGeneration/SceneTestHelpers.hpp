#pragma once
// Helpers for the particle generation tests: scenes built in code, a temporary case folder,
// FatalError capture, and brute-force checks of a generated cloud.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/Error.hpp"
#include "geometry/Polyline.hpp"
#include "particleGeneration/ParticleGenerator.hpp"

namespace isph::test {

inline Scene emptyScene(double dx, LatticeType lattice = LatticeType::square) {
  Scene s;
  s.spacing = dx;
  s.lattice = lattice;
  s.materials = {"sand", "clay"};
  s.patches = {{"walls", 25.0}};
  return s;
}

inline void addRegion(Scene& s, const std::string& name, std::unique_ptr<Region> shape,
                      double rho = 1000, label material = 0) {
  RegionSpec r;
  r.name = name;
  r.shape = std::move(shape);
  r.density = rho;
  r.material = material;
  s.regions.push_back(std::move(r));
}

// An open polyline wall (material side auto) or a closed solid given counter-clockwise.
inline void addWall(Scene& s, const std::string& name, std::vector<Vec2> points,
                    bool solid = false) {
  WallSpec w;
  w.name = name;
  w.density = 1000;
  w.side = MaterialSide::automatic;
  if (solid) std::reverse(points.begin(), points.end());
  w.surface = std::make_unique<WallSurface>(Polyline(std::move(points), solid),
                                            solid ? "polygon" : "polyline");
  s.walls.push_back(std::move(w));
}

inline long countKind(const ParticleCloud& c, ParticleKind k) {
  return std::count(c.kind.begin(), c.kind.end(), static_cast<label>(k));
}

// A fresh temporary case folder, removed at the end of the test.
class TempCase {
 public:
  TempCase() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            (std::string("isphMesh_") + info->test_suite_name() + "_" + info->name() + "_" +
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
