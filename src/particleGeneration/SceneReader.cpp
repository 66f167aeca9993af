#include "particleGeneration/SceneReader.hpp"

#include <fmt/format.h>

#include <cmath>

#include "core/Log.hpp"
#include "core/Plausibility.hpp"
#include "core/Registry.hpp"
#include "core/dictionary/Dictionary.hpp"
#include "particleGeneration/Extrusion.hpp"
#include "particleGeneration/SceneMaterials.hpp"
#include "particleGeneration/ShapeInput.hpp"
#include "particleGeneration/ZSlabs.hpp"
#include "sph/kernels/Kernel.hpp"

namespace isph {

namespace {

using RegionRegistry = Registry<Region, const Dictionary&, const ShapeContext&>;
using WallRegistry = Registry<WallSurface, const Dictionary&, const ShapeContext&>;

[[noreturn]] void invalid(const Dictionary& dict, std::string_view key, const std::string& what) {
  const Entry* e = dict.findEntry(key);
  fatalIOError(e ? e->location() : dict.location(),
               fmt::format("keyword '{}' in {}: {}", key, dict.name(), what));
}

const Dictionary& entryDict(const Entry& e, const Dictionary& parent, const char* example) {
  if (!e.isDict()) {
    fatalIOError(e.location(),
                 fmt::format("entry '{}' in {}: expected a sub-dictionary, for example\n    {} {}",
                             e.key(), parent.name(), e.key(), example));
  }
  return e.dict();
}

void readLattice(const Dictionary& dict, std::optional<double> spacing, Scene& scene) {
  scene.spacing = dict.get<double>("spacing");
  if (spacing) {
    if (!(*spacing > 0)) fatalError(fmt::format("option -spacing: must be positive, found {}", *spacing));
    scene.spacing = *spacing;
  }
  if (!(scene.spacing > 0))
    invalid(dict, "spacing", fmt::format("must be positive, found {}", scene.spacing));
  scene.spacingWhere = dict.findEntry("spacing")->location();
  scene.maxParticles = dict.getOrDefault("maxParticles", scene.maxParticles);
  if (!(scene.maxParticles >= 1))
    invalid(dict, "maxParticles", fmt::format("must be at least 1, found {}", scene.maxParticles));
  if (const Entry* e = dict.findEntry("maxParticles")) scene.maxParticlesWhere = e->location();
  scene.cloudName = dict.getOrDefault<std::string>("cloud", "particles");
  scene.dimension = dict.getOrDefault<int>("dimension", 2);
  if (scene.dimension != 2 && scene.dimension != 3) {
    invalid(dict, "dimension",
            fmt::format("expected 2 (plane strain in x-y) or 3 (the x-y scene extruded along z "
                        "over `width`), found {}",
                        scene.dimension));
  }
  scene.lattice =
      dict.getChoiceOrDefault("lattice", {"square", "hexagonal"}, "square") == "hexagonal"
          ? LatticeType::hexagonal
          : LatticeType::square;
  if (scene.dimension == 3) {
    if (!dict.found("width"))
      invalid(dict, "dimension", "a 3D scene needs `width`, its extent in z [m] (width 0.2;)");
    scene.width = dict.get<double>("width");
    if (!(scene.width >= scene.spacing)) {
      invalid(dict, "width",
              fmt::format("the scene's extent in z must be at least one spacing ({} m), found {}",
                          scene.spacing, scene.width));
    }
    if (scene.lattice != LatticeType::square)
      invalid(dict, "lattice", "a 3D scene is filled on the cubic lattice: lattice square");
  } else if (dict.found("width")) {
    invalid(dict, "width", "is the extent in z of a 3D scene: it needs dimension 3");
  }
  scene.latticeOrigin = toVec2(dict.getOrDefault<Vec3>("latticeOrigin", Vec3::Zero()));
  scene.wallClearance = dict.getOrDefault("wallClearance", 0.5);
  if (!(scene.wallClearance >= 0 && scene.wallClearance <= 2)) {
    invalid(dict, "wallClearance",
            fmt::format("must be between 0 and 2 (× spacing), found {}", scene.wallClearance));
  }
}

void readWallLayers(const Dictionary& dict, const std::filesystem::path& caseDir, Scene& scene) {
  const auto kernel = caseKernel(caseDir, scene.spacing, scene.dimension);
  const int needed = kernelWallLayers(kernel->supportRadius(), scene.spacing);
  const std::string why =
      fmt::format("kernel {} with h/dx = {:.4g}: support {:.4g} dx, ceil = {}", kernel->name(),
                  kernel->h() / scene.spacing, kernel->supportRadius() / scene.spacing, needed);
  if (const auto layers = dict.getOptional<int>("wallLayers")) {
    if (*layers < 1)
      invalid(dict, "wallLayers", fmt::format("must be at least 1, found {}", *layers));
    scene.wallLayers = *layers;
    info("Wall layers: {} (wallLayers in particleMeshDict; the {} layers)", *layers, why);
    if (*layers < needed) {
      warning(fmt::format(
                  "wallLayers {} does not fill the kernel support ({}): fluid near walls will miss "
                  "neighbours",
                  *layers, why),
              dict.findEntry("wallLayers")->location());
    }
  } else {
    scene.wallLayers = needed;
    info("Wall layers: {} (1 wall + {} dummy; {})", needed, needed - 1, why);
  }
}

// The optional sub-dictionary `key`: null when absent, an error when not a dictionary.
const Dictionary* optionalSubDict(const Dictionary& dict, std::string_view key, const char* example) {
  const Dictionary* d = dict.findDict(key);
  dict.markRead(key);
  if (!d && dict.found(key)) invalid(dict, key, fmt::format("expected a sub-dictionary {}", example));
  return d;
}

void readTransform(const Dictionary& dict, Scene& scene) {
  const Dictionary* t = optionalSubDict(dict, "transform", "{ rotate 45; ... }");
  if (!t) return;
  const double angle = t->getOrDefault("rotate", 0.0);
  const Vec3 origin = t->getOrDefault<Vec3>("origin", Vec3::Zero());
  const Vec3 translate = t->getOrDefault<Vec3>("translate", Vec3::Zero());
  scene.transform = Transform(angle, origin, translate);
  t->checkKeywords();
}

void readInitialState(const Dictionary& dict, const std::filesystem::path& caseDir, Scene& scene) {
  scene.initialPressure =
      dict.getChoiceOrDefault("initialPressure", {"zero", "lithostatic"}, "zero") == "lithostatic"
          ? InitialPressure::lithostatic
          : InitialPressure::zero;
  if (scene.initialPressure != InitialPressure::lithostatic) return;
  const std::filesystem::path gFile = caseDir / "constant" / "g";
  if (!std::filesystem::exists(gFile)) {
    invalid(dict, "initialPressure",
            fmt::format("lithostatic pressure needs gravity from {}, which does not exist "
                        "(value (0 -9.81 0);)",
                        gFile.string()));
  }
  const Dictionary g = Dictionary::readFile(gFile);
  scene.gravity = g.get<Vec3>("value");
  if (scene.gravity.head<2>().norm() == 0) {
    invalid(dict, "initialPressure",
            fmt::format("lithostatic pressure needs gravity in the x-y plane; {} gives {}",
                        gFile.string(), ValueTraits<Vec3>::write(scene.gravity)));
  }
}

// `zRange (z0 z1);` of a region: 3D only, inside the width, holding a layer.
std::optional<ZRange> readZRange(const Dictionary& d, const Scene& scene) {
  if (!d.found("zRange")) return std::nullopt;
  if (scene.dimension != 3)
    invalid(d, "zRange", "bounds a region in z in a 3D scene: it needs dimension 3 (a 2D region spans the unit width)");
  const auto z = d.get<std::vector<double>>("zRange");
  if (z.size() != 2) invalid(d, "zRange", fmt::format("expected two values (z0 z1) [m], found {}", z.size()));
  const double extent = static_cast<double>(extrusionLayers(scene).size()) * scene.spacing;
  if (!(z[0] < z[1] && z[0] >= 0 && z[1] <= extent * (1 + 1e-12))) {
    invalid(d, "zRange",
            fmt::format("expected 0 <= z0 < z1 <= {:.6g} (the scene's width), found ({} {})", extent, z[0], z[1]));
  }
  ZRange range{z[0], z[1], d.findEntry("zRange")->location()};
  if (layersIn(scene, range) == 0) {
    invalid(d, "zRange",
            fmt::format("({} {}) holds no layer: the layers lie at z = (k + 1/2) dx = {:.6g}, {:.6g}, ... (a region is "
                        "present in the layers whose z is in the range)",
                        z[0], z[1], scene.spacing / 2, 1.5 * scene.spacing));
  }
  return range;
}

void readRegions(const Dictionary& dict, const std::filesystem::path& caseDir,
                 const ShapeContext& context, const Vec3& initialVelocity, Scene& scene) {
  const Dictionary& regions = dict.subDict("regions");
  if (regions.size() == 0)
    warning("no material regions: the cloud will hold walls only", regions.location());
  SceneMaterials table;
  bool tableRead = false;
  for (const Entry& e : regions.entries()) {
    const Dictionary& d =
        entryDict(e, regions, "{ type box; min (0 0 0); max (1 1 0); material sand; }");
    RegionSpec r;
    r.name = e.key();
    r.where = e.location();
    const std::string type = d.get<std::string>("type");
    r.shape =
        RegionRegistry::create(type, "region type", d.findEntry("type")->location(), d, context);
    const std::string material = d.get<std::string>("material");
    if (!tableRead) {
      table = SceneMaterials::read(caseDir / "constant" / "materialProperties");
      scene.materials = table.names();
      tableRead = true;
    }
    r.material = table.index(material, d.findEntry("material")->location());
    r.density = table.density(r.material);
    r.initialVelocity = d.getOptional<Vec3>("initialVelocity").value_or(initialVelocity);
    r.zRange = readZRange(d, scene);
    if (r.shape->dimension() == 3) {
      if (scene.dimension != 3)
        invalid(d, "type", fmt::format("a {} is a 3D region: it needs dimension 3 (and width)", type));
      if (r.zRange) invalid(d, "zRange", fmt::format("a {} is bounded in z already: zRange is for x-y shapes", type));
    }
    d.checkKeywords();
    scene.regions.push_back(std::move(r));
  }
}

label patchLabel(Scene& scene, const std::string& name, double frictionAngle, const Dictionary& d) {
  for (std::size_t k = 0; k < scene.patches.size(); ++k) {
    if (scene.patches[k].name != name) continue;
    if (scene.patches[k].frictionAngle != frictionAngle) {
      invalid(d, "frictionAngle",
              fmt::format("patch '{}' already has frictionAngle {}; walls of one patch share it",
                          name, scene.patches[k].frictionAngle));
    }
    return static_cast<label>(k);
  }
  scene.patches.push_back({name, frictionAngle});
  return static_cast<label>(scene.patches.size() - 1);
}

void readWalls(const Dictionary& dict, const ShapeContext& context, Scene& scene) {
  const Dictionary walls = dict.subDictOrEmpty("walls");
  dict.markRead("walls");
  const double defaultDensity = scene.regions.empty() ? 1000.0 : scene.regions.front().density;
  for (const Entry& e : walls.entries()) {
    const Dictionary& d =
        entryDict(e, walls, "{ type polyline; points ((0 0 0) (1 0 0)); frictionAngle 25; }");
    WallSpec w;
    w.name = e.key();
    w.where = e.location();
    const std::string type = d.get<std::string>("type");
    w.surface =
        WallRegistry::create(type, "wall type", d.findEntry("type")->location(), d, context);
    const double phi = d.get<double>("frictionAngle");
    if (!(phi >= 0 && phi < 90))
      invalid(d, "frictionAngle", fmt::format("must be in [0, 90) degrees, found {}", phi));
    warnIfImplausibleFrictionAngle(phi, fmt::format("wall '{}': frictionAngle", e.key()),
                                   d.findEntry("frictionAngle")->location(), true);
    w.patch = patchLabel(scene, d.getOrDefault<std::string>("patch", e.key()), phi, d);
    if (w.surface->isClosed()) {
      if (d.found("materialSide")) {
        invalid(d, "materialSide",
                fmt::format("a {} wall is a solid with the material outside; materialSide is for "
                            "polylines",
                            type));
      }
    } else {
      const std::string side =
          d.getChoiceOrDefault("materialSide", {"left", "right", "auto"}, "auto");
      w.side = side == "left"    ? MaterialSide::left
               : side == "right" ? MaterialSide::right
                                 : MaterialSide::automatic;
    }
    if (d.found("zRange")) {
      invalid(d, "zRange",
              "a wall spans the scene's width: a wall of part of it (its end faces) is not available; zRange "
              "bounds a region");
    }
    w.density = d.getOrDefault("rho", defaultDensity);
    if (!(w.density > 0)) invalid(d, "rho", fmt::format("must be positive, found {}", w.density));
    d.checkKeywords();
    scene.walls.push_back(std::move(w));
  }
}

void readSideWalls(const Dictionary& dict, Scene& scene) {
  const Dictionary* d = optionalSubDict(dict, "sideWalls", "{ frictionAngle 25; }");
  if (!d) return;
  if (scene.dimension != 3) {
    invalid(dict, "sideWalls",
            "closes the ends z = 0 and z = width of a 3D scene: it needs dimension 3");
  }
  SideWallSpec s;
  s.where = dict.findEntry("sideWalls")->location();
  const double phi = d->get<double>("frictionAngle");
  if (!(phi >= 0 && phi < 90))
    invalid(*d, "frictionAngle", fmt::format("must be in [0, 90) degrees, found {}", phi));
  warnIfImplausibleFrictionAngle(phi, "sideWalls: frictionAngle",
                                 d->findEntry("frictionAngle")->location(), true);
  if (d->found("patch") && d->found("patches"))
    invalid(*d, "patches", "give one patch for both side walls (patch) or one each (patches), not both");
  if (const auto names = d->getOptional<std::vector<std::string>>("patches")) {
    if (names->size() != 2)
      invalid(*d, "patches", fmt::format("expected two names, the wall at z = 0 and at z = width, found {}", names->size()));
    for (int k = 0; k < 2; ++k) s.patch[k] = patchLabel(scene, (*names)[static_cast<std::size_t>(k)], phi, *d);
  } else {
    s.patch[0] = s.patch[1] = patchLabel(scene, d->getOrDefault<std::string>("patch", "sideWalls"), phi, *d);
  }
  if (d->found("min")) s.min = readPoint2D(*d, "min");
  if (d->found("max")) s.max = readPoint2D(*d, "max");
  if (!(s.max.x() > s.min.x() && s.max.y() > s.min.y())) {
    invalid(*d, d->found("max") ? "max" : "min",
            fmt::format("the side walls' extent: max ({} {}) must exceed min ({} {}) in x and in y", s.max.x(),
                        s.max.y(), s.min.x(), s.min.y()));
  }
  s.density =
      d->getOrDefault("rho", scene.regions.empty() ? 1000.0 : scene.regions.front().density);
  if (!(s.density > 0)) invalid(*d, "rho", fmt::format("must be positive, found {}", s.density));
  d->checkKeywords();
  scene.sideWalls = s;
}

}  // namespace

int kernelWallLayers(double supportRadius, double dx) {
  return std::max(1, static_cast<int>(std::ceil(supportRadius / dx - 1e-9)));
}

Scene readScene(const std::filesystem::path& caseDir, std::optional<double> spacing) {
  const Dictionary dict = Dictionary::readFile(caseDir / "system" / "particleMeshDict");
  Scene scene;
  const ShapeContext context{caseDir};
  readLattice(dict, spacing, scene);
  readWallLayers(dict, caseDir, scene);
  readTransform(dict, scene);
  const Vec3 initialVelocity = dict.getOrDefault<Vec3>("initialVelocity", Vec3::Zero());
  readInitialState(dict, caseDir, scene);
  readRegions(dict, caseDir, context, initialVelocity, scene);
  readWalls(dict, context, scene);
  readSideWalls(dict, scene);
  dict.checkKeywords();
  return scene;
}

}  // namespace isph
