#include "postProcessing/vtk/CloudPolyData.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>

#include <string>
#include <type_traits>

namespace isph {

namespace {

// Full 3×3 tensor, row by row, from OpenFOAM's symmTensor order (xx xy xz yy yz zz).
void fullTensor(const SymmTensor& s, double* out) {
  const double t[9] = {s[0], s[1], s[2], s[1], s[3], s[4], s[2], s[4], s[5]};
  std::copy(t, t + 9, out);
}

vtkSmartPointer<vtkDataArray> toArray(const NamedField& f, const std::vector<vtkIdType>& keep) {
  return std::visit(
      [&](const auto& values) -> vtkSmartPointer<vtkDataArray> {
        using T = typename std::decay_t<decltype(values)>::value_type;
        if constexpr (std::is_same_v<T, label>) {
          auto a = vtkSmartPointer<vtkIntArray>::New();
          a->SetName(f.name.c_str());
          a->SetNumberOfTuples(static_cast<vtkIdType>(keep.size()));
          for (std::size_t k = 0; k < keep.size(); ++k) a->SetValue(static_cast<vtkIdType>(k), values[keep[k]]);
          return a;
        } else {
          auto a = vtkSmartPointer<vtkDoubleArray>::New();
          a->SetName(f.name.c_str());
          constexpr int nc = std::is_same_v<T, scalar> ? 1 : std::is_same_v<T, Vec3> ? 3 : 9;
          a->SetNumberOfComponents(nc);
          a->SetNumberOfTuples(static_cast<vtkIdType>(keep.size()));
          for (std::size_t k = 0; k < keep.size(); ++k) {
            double* out = a->GetPointer(static_cast<vtkIdType>(k) * nc);
            const T& v = values[static_cast<std::size_t>(keep[k])];
            if constexpr (std::is_same_v<T, scalar>) out[0] = v;
            else if constexpr (std::is_same_v<T, Vec3>) std::copy(v.data(), v.data() + 3, out);
            else fullTensor(v, out);
          }
          return a;
        }
      },
      f.values);
}

vtkSmartPointer<vtkStringArray> names(const char* name, const std::vector<std::string>& values) {
  auto a = vtkSmartPointer<vtkStringArray>::New();
  a->SetName(name);
  for (const auto& v : values) a->InsertNextValue(v);
  return a;
}

template <class T>
const std::vector<T>* valuesOf(const CloudFields& cf, const std::string& name) {
  const NamedField* f = cf.find(name);
  return f ? std::get_if<std::vector<T>>(&f->values) : nullptr;
}

void addDerived(const CloudFields& cf, const std::vector<vtkIdType>& keep, vtkPointData* pd) {
  const auto n = static_cast<vtkIdType>(keep.size());
  if (const auto* U = valuesOf<Vec3>(cf, "U")) {
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName("magU");
    a->SetNumberOfTuples(n);
    for (vtkIdType k = 0; k < n; ++k) a->SetValue(k, (*U)[static_cast<std::size_t>(keep[k])].norm());
    pd->AddArray(a);
  }
  if (const auto* p = valuesOf<scalar>(cf, "p")) {
    const auto* tau = valuesOf<SymmTensor>(cf, "tau");
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName("stress");
    a->SetNumberOfComponents(9);
    a->SetNumberOfTuples(n);
    for (vtkIdType k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(keep[k]);
      SymmTensor s = tau ? (*tau)[i] : SymmTensor::Zero();
      s[0] -= (*p)[i];
      s[3] -= (*p)[i];
      s[5] -= (*p)[i];
      fullTensor(s, a->GetPointer(k * 9));
    }
    pd->AddArray(a);
  }
}

}  // namespace

vtkSmartPointer<vtkPolyData> cloudPolyData(const CloudFields& cf, double time, const PolyDataOptions& options) {
  const ParticleCloud& c = cf.cloud;
  std::vector<vtkIdType> keep;
  keep.reserve(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!options.noWalls || c.kind[i] == static_cast<label>(ParticleKind::material)) {
      keep.push_back(static_cast<vtkIdType>(i));
    }
  }
  const auto n = static_cast<vtkIdType>(keep.size());

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  auto verts = vtkSmartPointer<vtkCellArray>::New();
  verts->AllocateExact(n, n);
  for (vtkIdType k = 0; k < n; ++k) {
    points->SetPoint(k, c.positions[static_cast<std::size_t>(keep[k])].data());
    verts->InsertNextCell(1, &k);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetVerts(verts);

  vtkPointData* pd = poly->GetPointData();
  for (const auto& f : cf.fields) pd->AddArray(toArray(f, keep));
  addDerived(cf, keep, pd);

  auto timeValue = vtkSmartPointer<vtkDoubleArray>::New();
  timeValue->SetName("TimeValue");
  timeValue->InsertNextValue(time);
  vtkFieldData* fd = poly->GetFieldData();
  fd->AddArray(timeValue);
  fd->AddArray(names("materialNames", c.properties.materials));
  std::vector<std::string> patches;
  for (const auto& p : c.properties.patches) patches.push_back(p.name);
  fd->AddArray(names("patchNames", patches));
  fd->AddArray(names("kindNames", {"material", "wall", "dummy"}));
  return poly;
}

}  // namespace isph
