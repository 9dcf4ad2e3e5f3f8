// A load–displacement chart (VTK's vtkChartXY) in a vtkContextActor on a renderer of our own:
// vtkContextView is ruled out here: it would create an X window (offscreen_context.hpp). Lines and points
// are added once; their data can be replaced between frames (the curve so far, the current
// step). Axes are fixed by the caller so the chart does not rescale from frame to frame.
#pragma once

#include "palette.hpp"

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkChartXY;
class vtkContextActor;
class vtkPlot;
class vtkRenderer;
class vtkTable;

namespace plastica::render {

struct ChartSeries {
    std::string label;     // empty: not listed in the legend
    std::vector<double> x, y;
    Rgb colour;
    float width = 2.0f;    // line width, or marker size for points
    bool points = false;   // markers instead of a line
};

class LoadChart {
public:
    LoadChart(const std::string& x_title, const std::string& y_title, double text_scale);
    ~LoadChart();

    int add(const ChartSeries& series);                   // returns its index
    void replace(int index, const std::vector<double>& x, const std::vector<double>& y);
    void set_ranges(double x0, double x1, double y0, double y1);
    void show_legend(bool show);
    void set_legend_corner(bool right, bool bottom);      // inside the plot; top left unless set
    void set_log_scale();                                 // both axes
    void place_in(vtkRenderer* renderer);                 // the chart fills the renderer's viewport

private:
    vtkNew<vtkChartXY> chart_;
    vtkNew<vtkContextActor> actor_;
    std::vector<vtkSmartPointer<vtkTable>> tables_;
    std::vector<vtkPlot*> plots_;
    double text_scale_;
};

// An axis range with a little room around the data, starting at zero when the data is
// non-negative (a load–displacement curve starts at the origin).
void padded_range(const std::vector<double>& values, double& lo, double& hi);

} // namespace plastica::render
