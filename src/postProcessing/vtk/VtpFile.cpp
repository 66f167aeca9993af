#include "postProcessing/vtk/VtpFile.hpp"

#include <vtkNew.h>
#include <vtkXMLPolyDataWriter.h>

#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/io/AtomicFile.hpp"

namespace isph {

void writeVtp(vtkPolyData* data, const std::filesystem::path& file, VtkFormat format) {
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(data);
  writer->SetWriteToOutputString(true);
  writer->SetHeaderTypeToUInt64();  // arrays above 4 GB
  if (format == VtkFormat::ascii) {
    writer->SetDataModeToAscii();
    writer->SetCompressorTypeToNone();
  } else {
    writer->SetDataModeToAppended();
    writer->SetEncodeAppendedData(false);  // raw bytes, not base64
    writer->SetCompressorTypeToZLib();
  }
  if (writer->Write() != 1) fatalError(fmt::format("VTK could not write {}", file.string()));
  writeFileAtomic(file, writer->GetOutputString());
}

}  // namespace isph
