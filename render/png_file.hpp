// PNG files: written through libpng (settings for fast frames), read through libpng with bounds (png_decode.hpp). Writing goes to a temporary name and a
// rename, so no half-written PNG ever has its final name.
#pragma once

#include <vtkSmartPointer.h>

#include <string>

class vtkImageData;

namespace plastica::render {

std::string encode_png(vtkImageData* image);
void write_png(vtkImageData* image, const std::string& path);
// Throws RenderError naming the file when it is missing, not a PNG, truncated or too large.
vtkSmartPointer<vtkImageData> read_png(const std::string& path);

} // namespace plastica::render
