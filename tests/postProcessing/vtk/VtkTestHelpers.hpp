#pragma once
// A small cloud with known values in a time directory, and reading .vtp files back with VTK's
// own reader, for the VTK output tests.
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include "../PostProcessingTestHelpers.hpp"
#include "core/fields/FieldIO.hpp"
#include "particles/CloudIO.hpp"

namespace isph::pptest {

// 4 wall, 4 dummy and 4 material particles (flatBed) with p_i = 1.5 i + t, U_i = (i, −2i, 0),
// plus the solver's extra fields freeSurface (label: i % 2) and tau (symmTensor: i (1..6)).
inline ParticleCloud writeSampleTime(const std::filesystem::path& caseDir, const std::string& timeName, double t) {
  ParticleCloud c = flatBed(4, 0.1, 0.0);
  c.properties.patches = {{"bed", 0.0}, {"barrier", 0.0}};
  for (std::size_t i = 0; i < c.size(); ++i) {
    c.p[i] = 1.5 * static_cast<double>(i) + t;
    c.U[i] = Vec3(static_cast<double>(i), -2.0 * static_cast<double>(i), 0);
  }
  const auto timeDir = caseDir / timeName;
  writeCloud(timeDir, timeName, c, FieldWriteOptions{WriteFormat::binary, 17, ""});
  std::vector<label> flags(c.size());
  std::vector<SymmTensor> tau(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    flags[i] = static_cast<label>(i % 2);
    tau[i] << 1, 2, 3, 4, 5, 6;
    tau[i] *= static_cast<double>(i);
  }
  const auto cloudDir = timeDir / "lagrangian" / "particles";
  writeField(cloudDir / "freeSurface", flags, FieldWriteOptions{WriteFormat::ascii, 17, ""});
  writeField(cloudDir / "tau", tau, FieldWriteOptions{WriteFormat::ascii, 17, ""});
  return c;
}

inline vtkSmartPointer<vtkPolyData> readVtp(const std::filesystem::path& file) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkSmartPointer<vtkPolyData> out = reader->GetOutput();
  return out;
}

inline std::vector<std::string> stringsOf(vtkPolyData* data, const char* name) {
  std::vector<std::string> out;
  auto* a = vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name));
  if (!a) return out;
  for (vtkIdType k = 0; k < a->GetNumberOfValues(); ++k) out.push_back(a->GetValue(k));
  return out;
}

}  // namespace isph::pptest
