#include "contact_sheet.hpp"

#include <vtkImageAppend.h>
#include <vtkImageData.h>
#include <vtkImageResize.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace plastica::render {

ContactSheet::ContactSheet(std::size_t frame_count, int columns, int rows, double shrink)
    : columns_(columns), rows_(rows), shrink_(shrink) {
    const std::size_t cells = static_cast<std::size_t>(columns * rows);
    if (frame_count == 0) return;
    const std::size_t n = std::min(cells, frame_count);
    // A grid no larger than its frames: 4 frames in 2 × 2, 2 in a row, 5 or 6 in 3 × 2 (no
    // rows of blank cells).
    const int count = static_cast<int>(n);
    columns_ = std::min(columns, count == 4 && columns >= 2 ? 2 : count);
    rows_ = std::min(rows, (count + columns_ - 1) / columns_);
    for (std::size_t k = 0; k < n; ++k)
        chosen_.push_back(n == 1 ? 0 : static_cast<std::size_t>(std::lround(double(k) * (frame_count - 1) / (n - 1))));
    tiles_.resize(chosen_.size());
}

bool ContactSheet::wants(std::size_t frame) const {
    return std::find(chosen_.begin(), chosen_.end(), frame) != chosen_.end();
}

void ContactSheet::keep(std::size_t frame, vtkImageData* image) {
    const auto at = std::find(chosen_.begin(), chosen_.end(), frame);
    if (at == chosen_.end()) return;
    int dims[3];
    image->GetDimensions(dims);
    vtkNew<vtkImageResize> resize;
    resize->SetInputData(image);
    resize->SetResizeMethodToOutputDimensions();
    resize->SetOutputDimensions(static_cast<int>(dims[0] * shrink_), static_cast<int>(dims[1] * shrink_), 1);
    resize->InterpolateOn();
    resize->Update();
    auto tile = vtkSmartPointer<vtkImageData>::New();
    tile->DeepCopy(resize->GetOutput());
    tiles_[static_cast<std::size_t>(at - chosen_.begin())] = tile;
}

vtkSmartPointer<vtkImageData> ContactSheet::compose() const {
    const auto first = std::find_if(tiles_.begin(), tiles_.end(), [](const auto& t) { return t != nullptr; });
    if (first == tiles_.end()) return nullptr;
    int dims[3];
    (*first)->GetDimensions(dims);
    // Empty cells of the grid are white.
    auto blank = vtkSmartPointer<vtkImageData>::New();
    blank->SetDimensions(dims[0], dims[1], 1);
    blank->AllocateScalars(VTK_UNSIGNED_CHAR, (*first)->GetNumberOfScalarComponents());
    auto* pixels = static_cast<unsigned char*>(blank->GetScalarPointer());
    std::memset(pixels, 255, static_cast<std::size_t>(dims[0]) * dims[1] * blank->GetNumberOfScalarComponents());
    // Images grow upwards: the first row of the sheet is appended last.
    vtkNew<vtkImageAppend> sheet;
    sheet->SetAppendAxis(1);
    for (int row = rows_ - 1; row >= 0; --row) {
        vtkNew<vtkImageAppend> line;
        line->SetAppendAxis(0);
        for (int col = 0; col < columns_; ++col) {
            const std::size_t k = static_cast<std::size_t>(row * columns_ + col);
            line->AddInputData(k < tiles_.size() && tiles_[k] ? tiles_[k].Get() : blank.Get());
        }
        line->Update();
        auto copy = vtkSmartPointer<vtkImageData>::New();
        copy->DeepCopy(line->GetOutput());
        sheet->AddInputData(copy);
    }
    sheet->Update();
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->DeepCopy(sheet->GetOutput());
    return image;
}

} // namespace plastica::render
