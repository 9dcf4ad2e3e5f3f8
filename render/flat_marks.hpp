// Flat two-dimensional marks — discs, arrows, crosses, bars, polygons — built as polygons with one
// colour per mark and drawn unlit, so the colour on screen is exactly the colour asked for (the
// pixel tests rely on it). Sizes are in world units; marks are rebuilt for each frame.
#pragma once

#include "palette.hpp"

#include <vtkNew.h>
#include <vtkProp.h>
#include <vtkSmartPointer.h>

class vtkCellArray;
class vtkPoints;
class vtkPolyData;
class vtkUnsignedCharArray;

namespace plastica::render {

class FlatMarks {
public:
    // depth: the z of every mark (larger is drawn on top). With on_screen the coordinates are
    // pixels of the viewport and the marks are a 2D overlay (legends).
    explicit FlatMarks(double depth, bool on_screen = false);
    ~FlatMarks();
    void clear();

    void disc(double x, double y, double radius, Rgb colour);
    void arrow(const double tail[2], const double tip[2], double width, Rgb colour);
    void bar(const double a[2], const double b[2], double width, Rgb colour);
    void cross(double x, double y, double size, double width, Rgb colour);
    // A filled convex polygon of n corners given as x0, y0, x1, y1, …
    void polygon(const double* xy, int n, Rgb colour);

    vtkProp* prop() { return prop_; }

private:
    double depth_;
    vtkNew<vtkPoints> points_;
    vtkNew<vtkCellArray> polygons_;
    vtkNew<vtkUnsignedCharArray> colours_;
    vtkNew<vtkPolyData> data_;
    vtkSmartPointer<vtkProp> prop_;
};

} // namespace plastica::render
