#pragma once
// The free surface of a flow as a height profile over bins along the bed, and its distance
// to a measured profile (a polyline).
//
// Convention: the bed is the line through `origin` along `direction` (in the x-y plane); the
// position of a particle along the bed is s = (r - origin) . e, its height h = (r - origin) . n,
// with n the direction turned by +90 degrees (e = x gives n = y). The bins are
// [xMin + k w, xMin + (k + 1) w), k = 0 .. ceil((xMax - xMin) / w) - 1. A bin holds material if
// a material particle (kind 0; walls and dummies never count) has its centre in it; its height
// is then the highest such centre plus half the initial spacing dx, since a particle stands for
// the cell of size dx around it (a column of n particles on the bed gives n dx). A bin without
// material has height 0. The run-out (toe) is `runOut` of RunOut.hpp.
#include <filesystem>
#include <vector>

#include "core/Types.hpp"
#include "particles/ParticleCloud.hpp"

namespace isph {

struct SurfaceSpec {
  double binWidth = 0.0;           // [m], > 0
  double xMin = 0.0, xMax = 0.0;   // along the bed from the origin [m], xMax > xMin
  Vec3 origin = Vec3::Zero();
  Vec3 direction = Vec3::UnitX();  // normalised by surfaceProfile; z is ignored
};

struct SurfaceProfile {
  double binWidth = 0.0;       // [m]
  std::vector<double> x;       // bin centres along the bed [m]
  std::vector<double> height;  // [m]; 0 where the bin has no material
  std::vector<bool> filled;    // whether the bin holds material

  // The height at position s along the bed, linear between bin centres (empty bins count as
  // height 0); the end bins' values between xMin (xMax) and their centres; 0 outside them.
  double heightAt(double s) const;
};

// FatalError when binWidth is not positive, xMax <= xMin or direction has no x-y part.
SurfaceProfile surfaceProfile(const ParticleCloud& cloud, const SurfaceSpec& spec);

struct ProfilePoint {
  double x, height;
};

// A measured profile from a CSV file of x,height lines: lines starting with '#', empty lines
// and a header that is not numeric are skipped. FatalError naming the file if it cannot be
// read, a line is malformed or no point is found.
std::vector<ProfilePoint> readProfileCsv(const std::filesystem::path& file);

// The root mean square of heightAt(x_i) - height_i over the reference points.
double rmsDistance(const SurfaceProfile& computed, const std::vector<ProfilePoint>& reference);

}  // namespace isph
