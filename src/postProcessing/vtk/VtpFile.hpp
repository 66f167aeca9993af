#pragma once
// Writing PolyData as a VTK XML .vtp file with vtkXMLPolyDataWriter: binary, zlib-compressed
// appended data by default (ascii to read by eye), built in memory and published with
// writeFileAtomic, so that ParaView never opens a half-written file.
#include <vtkPolyData.h>

#include <filesystem>

namespace isph {

enum class VtkFormat { binary, ascii };

void writeVtp(vtkPolyData* data, const std::filesystem::path& file, VtkFormat format = VtkFormat::binary);

}  // namespace isph
