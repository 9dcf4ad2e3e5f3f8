// A grid of frames across a run in one image (VTK's vtkImageResize and vtkImageAppend): the
// frames to keep are chosen up front and shrunk as they are drawn, so memory stays small.
#pragma once

#include <vtkSmartPointer.h>

#include <cstddef>
#include <vector>

class vtkImageData;

namespace plastica::render {

class ContactSheet {
public:
    // Keeps up to `columns × rows` of `frame_count` frames, evenly spread, first and last
    // included, in a grid shrunk to fit them.
    ContactSheet(std::size_t frame_count, int columns = 3, int rows = 3, double shrink = 0.5);

    bool wants(std::size_t frame) const;
    void keep(std::size_t frame, vtkImageData* image);
    vtkSmartPointer<vtkImageData> compose() const; // null when nothing was kept

private:
    int columns_, rows_;
    double shrink_;
    std::vector<std::size_t> chosen_;
    std::vector<vtkSmartPointer<vtkImageData>> tiles_;
};

} // namespace plastica::render
