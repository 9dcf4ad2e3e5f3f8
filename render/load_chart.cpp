#include "load_chart.hpp"
#include "text_and_mirror.hpp"

#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkDoubleArray.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotLine.h>
#include <vtkPlotPoints.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>

namespace plastica::render {

namespace {

void fill(vtkTable* table, const std::vector<double>& x, const std::vector<double>& y) {
    auto* xs = vtkDoubleArray::SafeDownCast(table->GetColumn(0));
    auto* ys = vtkDoubleArray::SafeDownCast(table->GetColumn(1));
    const vtkIdType n = static_cast<vtkIdType>(std::min(x.size(), y.size()));
    xs->SetNumberOfTuples(n);
    ys->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i) {
        xs->SetValue(i, x[i]);
        ys->SetValue(i, y[i]);
    }
    xs->Modified();
    ys->Modified();
    table->Modified();
}

void style_axis(vtkAxis* axis, const std::string& title, double s) {
    axis->SetTitle(title);
    use_text_font(axis->GetTitleProperties(), true);
    axis->GetTitleProperties()->SetFontSize(static_cast<int>(std::lround(15 * s)));
    axis->GetTitleProperties()->SetColor(0.1, 0.1, 0.1);
    use_text_font(axis->GetLabelProperties());
    axis->GetLabelProperties()->SetFontSize(static_cast<int>(std::lround(13 * s)));
    axis->GetLabelProperties()->SetColor(0.1, 0.1, 0.1);
    axis->GetGridPen()->SetColor(225, 225, 225);
    axis->GetPen()->SetColor(60, 60, 60);
}

} // namespace

LoadChart::LoadChart(const std::string& x_title, const std::string& y_title, double text_scale)
    : text_scale_(text_scale) {
    style_axis(chart_->GetAxis(vtkAxis::BOTTOM), x_title, text_scale);
    style_axis(chart_->GetAxis(vtkAxis::LEFT), y_title, text_scale);
    chart_->GetBackgroundBrush()->SetColor(255, 255, 255, 255);
    chart_->SetShowLegend(false);
    vtkChartLegend* legend = chart_->GetLegend();
    use_text_font(legend->GetLabelProperties());
    legend->GetLabelProperties()->SetFontSize(static_cast<int>(std::lround(13 * text_scale)));
    legend->SetHorizontalAlignment(vtkChartLegend::LEFT);
    legend->SetVerticalAlignment(vtkChartLegend::TOP);
    actor_->GetScene()->AddItem(chart_);
}

LoadChart::~LoadChart() = default;

int LoadChart::add(const ChartSeries& series) {
    auto table = vtkSmartPointer<vtkTable>::New();
    vtkNew<vtkDoubleArray> x, y;
    x->SetName("x");
    y->SetName(series.label.empty() ? "y" : series.label.c_str());
    table->AddColumn(x);
    table->AddColumn(y);
    fill(table, series.x, series.y);
    vtkPlot* plot = chart_->AddPlot(series.points ? vtkChart::POINTS : vtkChart::LINE);
    plot->SetInputData(table, 0, 1);
    plot->SetColor(series.colour.r, series.colour.g, series.colour.b, 255);
    plot->SetLabel(series.label);
    plot->SetLegendVisibility(!series.label.empty());
    if (series.points) {
        auto* points = vtkPlotPoints::SafeDownCast(plot);
        points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
        points->SetMarkerSize(series.width * static_cast<float>(text_scale_));
    } else {
        plot->SetWidth(series.width * static_cast<float>(text_scale_));
    }
    tables_.push_back(table);
    plots_.push_back(plot);
    return static_cast<int>(plots_.size()) - 1;
}

void LoadChart::replace(int index, const std::vector<double>& x, const std::vector<double>& y) {
    fill(tables_.at(index), x, y);
    vtkPlot* plot = plots_.at(index);
    // VTK complains about a line of fewer than two points; such a line is simply not drawn.
    plot->SetVisible(vtkPlotLine::SafeDownCast(plot) == nullptr || std::min(x.size(), y.size()) >= 2);
    plot->Modified();
}

void LoadChart::set_ranges(double x0, double x1, double y0, double y1) {
    for (auto [axis, lo, hi] : {std::tuple{vtkAxis::BOTTOM, x0, x1}, std::tuple{vtkAxis::LEFT, y0, y1}}) {
        vtkAxis* a = chart_->GetAxis(axis);
        a->SetBehavior(vtkAxis::FIXED);
        a->SetRange(lo, hi);
        if (a->GetLogScale()) continue;
        // One number format per axis: fixed decimals enough for the tick spacing, or scientific
        // for very large or very small values (VTK's default mixes "8e+06" with "500000").
        const double magnitude = std::max(std::abs(lo), std::abs(hi)), span = std::abs(hi - lo);
        if (magnitude >= 1e5 || (magnitude > 0.0 && magnitude < 1e-3)) {
            a->SetNotation(vtkAxis::SCIENTIFIC_NOTATION);
            a->SetPrecision(2);
        } else if (span > 0.0) {
            a->SetNotation(vtkAxis::FIXED_NOTATION);
            a->SetPrecision(std::max(0, -static_cast<int>(std::floor(std::log10(span / 20.0)))));
        }
    }
}

void LoadChart::show_legend(bool show) { chart_->SetShowLegend(show); }

void LoadChart::set_legend_corner(bool right, bool bottom) {
    vtkChartLegend* legend = chart_->GetLegend();
    legend->SetHorizontalAlignment(right ? vtkChartLegend::RIGHT : vtkChartLegend::LEFT);
    legend->SetVerticalAlignment(bottom ? vtkChartLegend::BOTTOM : vtkChartLegend::TOP);
}

void LoadChart::set_log_scale() {
    chart_->GetAxis(vtkAxis::BOTTOM)->SetLogScale(true);
    chart_->GetAxis(vtkAxis::LEFT)->SetLogScale(true);
}

void LoadChart::place_in(vtkRenderer* renderer) { renderer->AddViewProp(actor_); }

void padded_range(const std::vector<double>& values, double& lo, double& hi) {
    if (values.empty()) {
        lo = 0, hi = 1;
        return;
    }
    lo = *std::min_element(values.begin(), values.end());
    hi = *std::max_element(values.begin(), values.end());
    if (lo >= 0) lo = 0;
    if (hi <= 0) hi = 0;
    const double pad = 0.05 * std::max(hi - lo, 1e-300);
    if (lo < 0) lo -= pad;
    hi += pad;
    if (hi - lo <= 0) hi = lo + 1;
}

} // namespace plastica::render
