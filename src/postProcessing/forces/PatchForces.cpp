#include "postProcessing/forces/PatchForces.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>

#include "core/Error.hpp"
#include "parallel/Reduce.hpp"
#include "postProcessing/forces/WallStress.hpp"

namespace isph {

double PatchForces::tangential(const Vec3& F) const {
  if (dimension == 2) return F.dot(tangent);
  return (F - F.dot(meanNormal) * meanNormal).norm();
}

PatchForces patchForces(const PatchForceInput& in) {
  const ParticleCloud& cloud = in.cloud;
  const CloudProperties& props = cloud.properties;
  const auto nPatches = static_cast<label>(props.patches.size());
  for (const label p : in.patches) {
    if (p < 0 || p >= nPatches) {
      fatalError(fmt::format("patchForces: patch label {} is out of range 0..{} of cloud '{}'", p, nPatches - 1,
                             cloud.name));
    }
  }
  if (!(props.spacing > 0)) {
    fatalError(fmt::format("patchForces: cloud '{}' has spacing {}; expected a positive particle spacing dx",
                           cloud.name, props.spacing));
  }
  if (!(in.width > 0) || (props.dimension == 3 && in.width != 1.0)) {
    fatalError(fmt::format("patchForces: width {} of a {}D cloud; expected a positive width (2D) or none (3D)",
                           in.width, props.dimension));
  }
  if (in.wallTau && in.wallTau->size() != cloud.size()) {
    fatalError(fmt::format("patchForces: {} values of the wall stress for {} particles", in.wallTau->size(),
                           cloud.size()));
  }
  if (in.wallFriction && in.wallFriction->size() != cloud.size()) {
    fatalError(fmt::format("patchForces: {} values of the wall friction for {} particles", in.wallFriction->size(),
                           cloud.size()));
  }

  std::vector<char> inSet(props.patches.size(), 0);
  for (const label p : in.patches) inSet[static_cast<std::size_t>(p)] = 1;

  const double dx = props.spacing;
  const double area = props.dimension == 2 ? dx * in.width : dx * dx;
  const auto wall = static_cast<label>(ParticleKind::wall);

  const double facingNorm = in.facing.norm();
  const Vec3 facing = facingNorm > 0 ? Vec3(in.facing / facingNorm) : Vec3::Zero();

  PatchForces out;
  out.dimension = props.dimension;
  Vec3 normalSum = Vec3::Zero();
  for (std::size_t w = 0; w < cloud.size(); ++w) {
    if (cloud.kind[w] != wall || cloud.patch[w] < 0 || !inSet[static_cast<std::size_t>(cloud.patch[w])]) continue;
    if (in.owned && !(*in.owned)[w]) continue;  // a ghost: its owner counts it
    const Vec3& n = cloud.normal[w];
    if (facingNorm > 0 && !(n.dot(facing) > 0.5)) continue;
    const Vec3 arm = cloud.positions[w] - in.CofR;
    const Vec3 fp = -cloud.p[w] * area * n;
    // A sliding material (wallFriction given): pressure and friction only (see the header).
    const Vec3 fd = in.wallTau && !in.wallFriction ? Vec3(area * dotSymm((*in.wallTau)[w], n)) : Vec3::Zero();
    const Vec3 ff = in.wallFriction ? Vec3(area * (*in.wallFriction)[w]) : Vec3::Zero();
    out.pressure += fp;
    out.deviatoric += fd;
    out.friction += ff;
    out.momentPressure += arm.cross(fp);
    out.momentDeviatoric += arm.cross(fd);
    out.momentFriction += arm.cross(ff);
    normalSum += n;
    ++out.nWall;
  }
  if (in.owned) {  // the sums over all ranks
    double sums[22];
    Vec3* parts[] = {&out.pressure, &out.deviatoric, &out.friction, &out.momentPressure,
                     &out.momentDeviatoric, &out.momentFriction, &normalSum};
    for (int i = 0; i < 7; ++i) {
      for (int d = 0; d < 3; ++d) sums[3 * i + d] = (*parts[i])[d];
    }
    sums[21] = static_cast<double>(out.nWall);
    sumOverRanks(std::span<double>(sums));
    for (int i = 0; i < 7; ++i) {
      for (int d = 0; d < 3; ++d) (*parts[i])[d] = sums[3 * i + d];
    }
    out.nWall = static_cast<long>(sums[21]);
  }
  out.total = out.pressure + out.deviatoric + out.friction;
  out.momentTotal = out.momentPressure + out.momentDeviatoric + out.momentFriction;
  // Normals that cancel (two facing walls) leave no meaningful direction: keep n̄ = 0.
  if (normalSum.norm() > 1e-6 * static_cast<double>(out.nWall)) {
    out.meanNormal = normalSum.normalized();
    if (out.dimension == 2) out.tangent = out.meanNormal.cross(Vec3::UnitZ());
  }
  return out;
}

}  // namespace isph
