#include "postProcessing/vtk/PvdCollection.hpp"

#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <fmt/format.h>

#include <algorithm>

#include "core/Error.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/time/TimeName.hpp"

namespace isph {

namespace {

std::string xmlEscaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

double timeValue(const PvdEntry& e) {
  double v = 0;
  if (!parseTimeName(e.time, v)) fatalError(fmt::format("pvd entry '{}' has timestep '{}', not a number", e.file, e.time));
  return v;
}

}  // namespace

std::vector<PvdEntry> readPvd(const std::filesystem::path& pvd) {
  std::vector<PvdEntry> entries;
  if (!std::filesystem::exists(pvd)) return entries;
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(pvd.string().c_str());
  vtkXMLDataElement* root = parser->Parse() ? parser->GetRootElement() : nullptr;
  vtkXMLDataElement* collection = root ? root->FindNestedElementWithName("Collection") : nullptr;
  if (!collection) {
    fatalError(fmt::format("{} is not a ParaView collection (expected <VTKFile type=\"Collection\"> with a "
                           "<Collection> element); remove it and convert again",
                           pvd.string()));
  }
  for (int k = 0; k < collection->GetNumberOfNestedElements(); ++k) {
    vtkXMLDataElement* e = collection->GetNestedElement(k);
    const char* time = e->GetAttribute("timestep");
    const char* file = e->GetAttribute("file");
    if (std::string(e->GetName()) != "DataSet" || !time || !file) {
      fatalError(fmt::format("{}: element {} of the collection is not <DataSet timestep=\"...\" file=\"...\"/>",
                             pvd.string(), k + 1));
    }
    entries.push_back({time, file});
  }
  return entries;
}

std::vector<PvdEntry> mergePvd(std::vector<PvdEntry> existing, const std::vector<PvdEntry>& added,
                               const std::filesystem::path& folder) {
  for (const auto& a : added) {
    const double t = timeValue(a);
    std::erase_if(existing, [&](const PvdEntry& e) { return findTime({{timeValue(e), e.time}}, t) != nullptr; });
    existing.push_back(a);
  }
  std::erase_if(existing, [&](const PvdEntry& e) { return !std::filesystem::exists(folder / e.file); });
  std::stable_sort(existing.begin(), existing.end(),
                   [](const PvdEntry& a, const PvdEntry& b) { return timeValue(a) < timeValue(b); });
  return existing;
}

std::string pvdText(const std::vector<PvdEntry>& entries) {
  std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
                  "  <Collection>\n";
  for (const auto& e : entries) {
    s += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", xmlEscaped(e.time),
                     xmlEscaped(e.file));
  }
  return s + "  </Collection>\n</VTKFile>\n";
}

std::vector<PvdEntry> updatePvd(const std::filesystem::path& pvd, const std::vector<PvdEntry>& added) {
  auto entries = mergePvd(readPvd(pvd), added, pvd.parent_path());
  writeFileAtomic(pvd, pvdText(entries));
  return entries;
}

}  // namespace isph
