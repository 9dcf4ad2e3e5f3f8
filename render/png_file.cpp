#include "png_file.hpp"
#include "render_error.hpp"

#include "atomic_file.hpp"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>

#include <filesystem>

namespace plastica::render {

std::string encode_png(vtkImageData* image) {
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputData(image);
    writer->WriteToMemoryOn();
    // Level 4 is within a few per cent of the smallest file at less than half the time of 9.
    writer->SetCompressionLevel(4);
    writer->Write();
    vtkUnsignedCharArray* bytes = writer->GetResult();
    return std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)), static_cast<std::size_t>(bytes->GetNumberOfTuples()));
}

void write_png(vtkImageData* image, const std::string& path) { write_file_atomically(path, encode_png(image)); }

vtkSmartPointer<vtkImageData> read_png(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw RenderError(path + ": missing");
    vtkNew<vtkPNGReader> reader;
    if (!reader->CanReadFile(path.c_str())) throw RenderError(path + ": not a PNG image");
    reader->SetFileName(path.c_str());
    reader->Update();
    if (reader->GetErrorCode() != 0) throw RenderError(path + ": unreadable PNG");
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->DeepCopy(reader->GetOutput());
    return image;
}

} // namespace plastica::render
