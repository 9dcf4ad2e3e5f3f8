#include "flat_marks.hpp"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <vector>

namespace plastica::render {

FlatMarks::FlatMarks(double depth, bool on_screen) : depth_(depth) {
    colours_->SetNumberOfComponents(3);
    colours_->SetName("colour");
    data_->SetPoints(points_);
    data_->SetPolys(polygons_);
    data_->GetCellData()->SetScalars(colours_);
    if (on_screen) {
        vtkNew<vtkPolyDataMapper2D> mapper;
        mapper->SetInputData(data_);
        mapper->SetColorModeToDirectScalars();
        mapper->SetScalarModeToUseCellData();
        auto actor = vtkSmartPointer<vtkActor2D>::New();
        actor->SetMapper(mapper);
        prop_ = actor;
        return;
    }
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(data_);
    mapper->SetColorModeToDirectScalars();
    mapper->SetScalarModeToUseCellData();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->LightingOff();
    prop_ = actor;
}

FlatMarks::~FlatMarks() = default;

void FlatMarks::clear() {
    points_->Reset();
    polygons_->Reset();
    colours_->Reset();
    data_->Modified();
}

void FlatMarks::polygon(const double* xy, int n, Rgb colour) {
    std::vector<vtkIdType> ids(n);
    for (int i = 0; i < n; ++i) ids[i] = points_->InsertNextPoint(xy[2 * i], xy[2 * i + 1], depth_);
    polygons_->InsertNextCell(n, ids.data());
    const unsigned char rgb[3] = {colour.r, colour.g, colour.b};
    colours_->InsertNextTypedTuple(rgb);
    points_->Modified();
    data_->Modified();
}

void FlatMarks::disc(double x, double y, double radius, Rgb colour) {
    constexpr int sides = 24;
    double xy[2 * sides];
    for (int i = 0; i < sides; ++i) {
        const double a = 2.0 * M_PI * i / sides;
        xy[2 * i] = x + radius * std::cos(a);
        xy[2 * i + 1] = y + radius * std::sin(a);
    }
    polygon(xy, sides, colour);
}

void FlatMarks::bar(const double a[2], const double b[2], double width, Rgb colour) {
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double length = std::hypot(dx, dy);
    if (length <= 0.0) return;
    const double nx = -dy / length * width / 2, ny = dx / length * width / 2;
    const double xy[8] = {a[0] + nx, a[1] + ny, a[0] - nx, a[1] - ny, b[0] - nx, b[1] - ny, b[0] + nx, b[1] + ny};
    polygon(xy, 4, colour);
}

void FlatMarks::arrow(const double tail[2], const double tip[2], double width, Rgb colour) {
    const double dx = tip[0] - tail[0], dy = tip[1] - tail[1];
    const double length = std::hypot(dx, dy);
    if (length <= 0.0) return;
    const double ux = dx / length, uy = dy / length;
    // The head keeps its shape for short arrows and takes at most 60 % of the length.
    const double head = std::min(3.0 * width, 0.6 * length);
    const double neck[2] = {tip[0] - head * ux, tip[1] - head * uy};
    bar(tail, neck, width, colour);
    const double half = 1.2 * width;
    const double xy[6] = {tip[0], tip[1], neck[0] - half * uy, neck[1] + half * ux, neck[0] + half * uy, neck[1] - half * ux};
    polygon(xy, 3, colour);
}

void FlatMarks::cross(double x, double y, double size, double width, Rgb colour) {
    const double h = size / 2;
    const double a[2] = {x - h, y - h}, b[2] = {x + h, y + h}, c[2] = {x - h, y + h}, d[2] = {x + h, y - h};
    bar(a, b, width, colour);
    bar(c, d, width, colour);
}

} // namespace plastica::render
