#include "series_summary.hpp"
#include "line_load_shares.hpp"

#include "figure_text.hpp"
#include "render_error.hpp"
#include "result_schema.hpp"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace plastica::render {

namespace {

bool signed_quantity(const std::string& array) {
    using result::Quantity;
    try {
        const Quantity q = result::find(array).quantity;
        return q == Quantity::force || q == Quantity::moment || q == Quantity::length || q == Quantity::rotation ||
               q == Quantity::curvature;
    } catch (const std::out_of_range&) {
        return false; // not one of Plastica's arrays
    }
}

std::string array_names(vtkUnstructuredGrid* grid) {
    std::string names;
    for (vtkDataSetAttributes* data : {static_cast<vtkDataSetAttributes*>(grid->GetPointData()),
                                       static_cast<vtkDataSetAttributes*>(grid->GetCellData())})
        for (int i = 0; i < data->GetNumberOfArrays(); ++i)
            if (data->GetArray(i)) names += (names.empty() ? "" : ", ") + std::string(data->GetArrayName(i));
    return names;
}

int count_state(vtkDataArray* states, result::HingeCode state) {
    int n = 0;
    if (!states) return 0;
    for (vtkIdType i = 0; i < states->GetNumberOfTuples(); ++i) n += states->GetComponent(i, 0) == static_cast<int>(state);
    return n;
}

} // namespace

std::string with_unit(const std::string& label, const std::string& unit) {
    return unit.empty() ? label : label + " (" + unit + ")";
}

std::string array_unit(const SeriesSummary& s, const std::string& array) {
    try {
        return result::unit(result::find(array), s.length_unit, s.force_unit);
    } catch (const std::out_of_range&) {
        return {}; // an array of another program's series
    }
}

std::string array_unit_or_dimension(const SeriesSummary& s, const std::string& array) {
    if (std::string unit = array_unit(s, array); !unit.empty()) return unit;
    try {
        return result::unit(result::find(array), "length", "force");
    } catch (const std::out_of_range&) {
        return {};
    }
}

bool on_mirror_line(const SeriesSummary& summary, const double* initial_position) {
    const double x = initial_position[0];
    return summary.mirrored && std::abs(x - summary.mirror_x) <= 1e-9 * (1.0 + std::abs(x));
}

double tuple_magnitude(vtkDataArray* array, long long i) {
    const int c = array->GetNumberOfComponents();
    if (c == 1) return array->GetComponent(i, 0);
    double sum = 0.0;
    for (int k = 0; k < c; ++k) sum += array->GetComponent(i, k) * array->GetComponent(i, k);
    return std::sqrt(sum);
}

namespace {

// 1, 2 or 5 times a power of ten, at most x.
double round_down_nicely(double x) {
    const double decade = std::pow(10.0, std::floor(std::log10(x)));
    for (double m : {5.0, 2.0, 1.0})
        if (m * decade <= x) return m * decade;
    return decade;
}

// The factor for magnify = 0 (see the header), from a pass over the displacements, and why it
// is 1 when it is.
struct Magnification {
    double factor = 1.0;
    std::string why_not; // "" when the factor enlarges
};

Magnification chosen_magnification(const ResultSeries& series) {
    double largest = 0.0, b[4] = {1e300, -1e300, 1e300, -1e300};
    for (const SeriesStep& step : series.steps) {
        auto grid = read_step(step.file);
        vtkDataArray* u = grid->GetPointData()->GetArray(result::name::displacement);
        vtkDataArray* x0 = grid->GetPointData()->GetArray(result::name::initial_position);
        if (grid->GetPointData()->GetArray(result::name::contact_force))
            return {1.0, "--magnify auto draws at true scale: the structure rests on a base (a rigid base or a "
                         "tensionless bed), and enlarged it would seem to pass through it; give a factor to enlarge anyway"};
        if (!u || !x0) return {1.0, "--magnify auto draws at true scale: the series has no displacements"};
        for (vtkIdType i = 0; i < u->GetNumberOfTuples(); ++i) {
            largest = std::max(largest, std::hypot(u->GetComponent(i, 0), u->GetComponent(i, 1)));
            b[0] = std::min(b[0], x0->GetComponent(i, 0)), b[1] = std::max(b[1], x0->GetComponent(i, 0));
            b[2] = std::min(b[2], x0->GetComponent(i, 1)), b[3] = std::max(b[3], x0->GetComponent(i, 1));
        }
    }
    const double size = std::max(b[1] - b[0], b[3] - b[2]);
    if (!(largest > 0.0)) return {1.0, "--magnify auto draws at true scale: nothing moves"};
    if (largest >= 0.02 * size) {
        char why[160];
        std::snprintf(why, sizeof why, "--magnify auto draws at true scale: the largest displacement is already %.3g %% of the structure's size (auto enlarges below 2 %%)",
                      100.0 * largest / size);
        return {1.0, why};
    }
    return {std::max(1.0, round_down_nicely(0.1 * size / largest)), ""};
}

} // namespace

vtkSmartPointer<vtkUnstructuredGrid> magnified(vtkUnstructuredGrid* step, double k) {
    if (k == 1.0) return step;
    vtkDataArray* u = step->GetPointData()->GetArray(result::name::displacement);
    vtkDataArray* x0 = step->GetPointData()->GetArray(result::name::initial_position);
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->ShallowCopy(step);
    if (!u || !x0) return grid;
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(step->GetNumberOfPoints());
    for (vtkIdType i = 0; i < step->GetNumberOfPoints(); ++i)
        points->SetPoint(i, x0->GetComponent(i, 0) + k * u->GetComponent(i, 0), x0->GetComponent(i, 1) + k * u->GetComponent(i, 1), 0.0);
    grid->SetPoints(points);
    return grid;
}

SeriesSummary summarise(const ResultSeries& series, const std::string& requested, double magnify) {
    SeriesSummary s;
    if (!(magnify >= 0.0) || !std::isfinite(magnify)) throw RenderError("--magnify takes 'auto' or a positive factor");
    if (magnify == 0.0) {
        const Magnification chosen = chosen_magnification(series);
        s.magnify = chosen.factor;
        if (!chosen.why_not.empty()) s.notes.push_back(chosen.why_not);
    } else {
        s.magnify = magnify;
        if (magnify != 1.0 && !series.base_file.empty())
            s.notes.push_back("--magnify " + number(magnify) + ": a fixed base is drawn where it is and a moving plate at " +
                              number(magnify) + " times its travel, so a node drawn near a base may seem to pass through it");
    }
    std::string field = requested;
    const double inf = std::numeric_limits<double>::infinity();
    double b[4] = {inf, -inf, inf, -inf};
    double range[2] = {inf, -inf};
    std::vector<double> load_direction; // each node's first load direction (x, y)
    bool loads_turn = false;             // some node's load changes direction (a follower pressure)
    std::vector<double> step_contact_force; // each step's largest contact force
    for (std::size_t k = 0; k < series.steps.size(); ++k) {
        const std::string& file = series.steps[k].file;
        auto grid = magnified(read_step(file), s.magnify);
        if (k == 0) {
            s.scene = field_text(grid, result::name::scene, "result");
            s.title = field_text(grid, result::name::title);
            s.load_label = field_text(grid, result::name::load_label, "load");
            s.displacement_label = field_text(grid, result::name::displacement_label, "control displacement");
            s.length_unit = field_text(grid, result::name::length_unit);
            s.force_unit = field_text(grid, result::name::force_unit);
            s.load_unit = field_text(grid, result::name::load_unit);
            s.displacement_unit = field_text(grid, result::name::displacement_unit);
            s.unilateral = grid->GetPointData()->GetArray(result::name::contact_force) != nullptr;
            s.inelastic = grid->GetCellData()->GetArray(result::name::hinge_state_i) != nullptr;
            if (grid->GetFieldData()->GetArray(result::name::mirror_x)) {
                s.mirrored = true;
                s.mirror_x = field_value(grid, result::name::mirror_x);
            }
            // Unless asked otherwise: the spread of plasticity where the members have fibre
            // sections along them, else the bending moment.
            if (field.empty())
                field = grid->GetCellData()->GetArray(result::name::yielded_share) ? result::name::yielded_share : result::name::bending_moment;
            s.field.name = field;
            vtkDataArray* a = grid->GetPointData()->GetArray(field.c_str());
            if (!a) {
                a = grid->GetCellData()->GetArray(field.c_str());
                s.field.on_cells = a != nullptr;
            }
            if (!a)
                throw RenderError(file + ": no array '" + field + "' to colour by; the series has: " + array_names(grid));
            s.field.components = a->GetNumberOfComponents();
            s.field.is_signed = s.field.components == 1 && signed_quantity(field);
        }
        vtkDataArray* initial = grid->GetPointData()->GetArray(result::name::initial_position);
        for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
            double p[3];
            grid->GetPoint(i, p);
            const double* q = initial->GetTuple3(i);
            for (const double* xy : {static_cast<const double*>(p), q}) {
                b[0] = std::min(b[0], xy[0]);
                b[1] = std::max(b[1], xy[0]);
                b[2] = std::min(b[2], xy[1]);
                b[3] = std::max(b[3], xy[1]);
            }
        }
        vtkDataArray* values = s.field.on_cells ? grid->GetCellData()->GetArray(field.c_str())
                                                : grid->GetPointData()->GetArray(field.c_str());
        if (!values) throw RenderError(file + ": no array '" + field + "' (present in the first step)");
        for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i) {
            const double v = tuple_magnitude(values, i);
            if (!std::isfinite(v)) throw RenderError(file + ": '" + field + "' holds NaN or Inf");
            range[0] = std::min(range[0], v);
            range[1] = std::max(range[1], v);
        }
        CurvePoint c;
        c.step = static_cast<int>(field_value(grid, result::name::step));
        c.displacement = field_value(grid, result::name::control_displacement);
        c.load = field_value(grid, result::name::load);
        if (grid->GetFieldData()->GetArray(result::name::contact_count)) c.contact_count = static_cast<int>(field_value(grid, result::name::contact_count));
        if (grid->GetFieldData()->GetArray(result::name::hinge_count)) c.hinge_count = static_cast<int>(field_value(grid, result::name::hinge_count));
        if (grid->GetFieldData()->GetArray(result::name::critical_point)) {
            c.critical = static_cast<int>(field_value(grid, result::name::critical_point));
            c.critical_load_factor = field_value(grid, result::name::critical_load_factor);
        }
        if (grid->GetFieldData()->GetArray(result::name::model_time)) {
            s.in_time = true;
            c.time = field_value(grid, result::name::model_time);
            if (vtkDataArray* energy = grid->GetFieldData()->GetArray(result::name::energy); energy && energy->GetNumberOfComponents() == 8)
                for (int k = 0; k < 8; ++k) c.energy[static_cast<std::size_t>(k)] = energy->GetComponent(0, k);
        }
        if (vtkDataArray* reaction = grid->GetPointData()->GetArray(result::name::reaction))
            for (vtkIdType i = 0; i < reaction->GetNumberOfTuples(); ++i) c.base_shear -= reaction->GetComponent(i, 0);
        step_contact_force.push_back(0.0);
        if (vtkDataArray* force = grid->GetPointData()->GetArray(result::name::contact_force)) {
            vtkDataArray* state = grid->GetPointData()->GetArray(result::name::contact);
            for (vtkIdType i = 0; i < force->GetNumberOfTuples(); ++i)
                if (!state || state->GetComponent(i, 0) > 0)
                    step_contact_force.back() = std::max(step_contact_force.back(), tuple_magnitude(force, i));
            s.max_contact_force = std::max(s.max_contact_force, step_contact_force.back());
            s.any_contact = s.any_contact || step_contact_force.back() > 0.0;
        }
        if (vtkDataArray* force = grid->GetPointData()->GetArray(result::name::surface_contact_force))
            for (vtkIdType i = 0; i < force->GetNumberOfTuples(); ++i)
                s.max_surface_contact_force = std::max(s.max_surface_contact_force, tuple_magnitude(force, i));
        s.curve.push_back(c);
        const struct {
            const char* force;
            const char* moment;
            SeriesSummary::NodalArrows* stats;
        } arrows[] = {{result::name::applied_load, result::name::applied_moment, &s.loads},
                      {result::name::reaction, result::name::reaction_moment, &s.reactions}};
        // Line loads are drawn along their members: their nodal shares leave the load arrows.
        const std::vector<double> shares = line_load_shares(grid);
        if (vtkDataArray* line = grid->GetCellData()->GetArray(result::name::line_load))
            for (vtkIdType c = 0; c < line->GetNumberOfTuples(); ++c) {
                const double wx = line->GetComponent(c, 0), wy = line->GetComponent(c, 1), w = std::hypot(wx, wy);
                s.line_loads.max_intensity = std::max(s.line_loads.max_intensity, w);
                if (w <= 0.0) continue;
                s.line_loads.sides |= (wx > 1e-6 * w ? 1 : 0) | (wx < -1e-6 * w ? 2 : 0) | (wy > 1e-6 * w ? 4 : 0) | (wy < -1e-6 * w ? 8 : 0);
            }
        for (const auto& [force, moment, stats] : arrows) {
            vtkDataArray* a = grid->GetPointData()->GetArray(force);
            vtkDataArray* m = grid->GetPointData()->GetArray(moment);
            if (!a || !m) continue;
            const bool loads = stats == &s.loads;
            if (loads) load_direction.resize(static_cast<std::size_t>(a->GetNumberOfTuples()) * 2, 0.0);
            for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i) {
                const double whole = on_mirror_line(s, initial->GetTuple3(i)) ? 2.0 : 1.0;
                const bool drop = loads && !shares.empty();
                const double fx = whole * (a->GetComponent(i, 0) - (drop ? shares[2 * static_cast<std::size_t>(i)] : 0.0));
                const double fy = whole * (a->GetComponent(i, 1) - (drop ? shares[2 * static_cast<std::size_t>(i) + 1] : 0.0));
                const double f = std::hypot(fx, fy);
                stats->max_force = std::max(stats->max_force, f);
                stats->max_moment = std::max(stats->max_moment, whole * std::abs(m->GetComponent(i, 0)));
                if (f <= 0.0) continue;
                // An arrow points at its node, so its tail lies on the side the force comes from;
                // drawn by components, each component's arrow counts.
                const double share = loads ? 1e-6 : 0.3;
                if (fx > share * f) stats->sides |= 1;
                if (fx < -share * f) stats->sides |= 2;
                if (fy > share * f) stats->sides |= 4;
                if (fy < -share * f) stats->sides |= 8;
                if (!loads) continue;
                double* first = &load_direction[static_cast<std::size_t>(i) * 2];
                if (first[0] == 0.0 && first[1] == 0.0) first[0] = fx / f, first[1] = fy / f;
                else if (std::abs(first[0] * fy - first[1] * fx) > 1e-6 * f) loads_turn = true;
            }
        }
        for (const char* end : {result::name::hinge_state_i, result::name::hinge_state_j}) {
            vtkDataArray* st = grid->GetCellData()->GetArray(end);
            s.any_yielding = s.any_yielding || count_state(st, result::HingeCode::yielding) > 0;
            s.any_plastic = s.any_plastic || count_state(st, result::HingeCode::plastic) > 0;
            s.any_failed = s.any_failed || count_state(st, result::HingeCode::failed) > 0;
        }
    }
    // Landing: the first step with more nodes in contact than at the start. Before it the
    // structure carries the load alone; a load 10 times that peak afterwards is the base's.
    if (s.unilateral && !s.curve.empty()) {
        double low = 0.0, high = 0.0, largest = 0.0;
        bool landed = false;
        for (const CurvePoint& c : s.curve) {
            landed = landed || c.contact_count > s.curve.front().contact_count;
            if (!landed) low = std::min(low, c.load), high = std::max(high, c.load);
            largest = std::max(largest, std::abs(c.load));
        }
        const double before = std::max(high, -low);
        if (landed && before > 0.0 && largest > 10.0 * before) {
            // The structure's own range, and as much again above it for the landing.
            s.load_axis_cut[0] = low - 0.05 * (2.0 * before - low);
            s.load_axis_cut[1] = 2.0 * before;
            s.largest_load = largest;
        }
    }
    s.loads.by_components = !loads_turn;
    s.load_arrow_reference = s.loads.max_force;
    s.contact_arrow_reference = s.max_contact_force;
    if (s.load_axis_cut[1] > 0.0) {
        s.load_arrow_reference *= std::min(1.0, s.load_axis_cut[1] / s.largest_load);
        double in_view = 0.0;
        for (std::size_t k = 0; k < s.curve.size(); ++k)
            if (s.curve[k].load >= s.load_axis_cut[0] && s.curve[k].load <= s.load_axis_cut[1])
                in_view = std::max(in_view, step_contact_force[k]);
        if (in_view > 0.0) s.contact_arrow_reference = in_view;
    }
    if (s.mirrored) {
        const double lo = std::min(b[0], 2 * s.mirror_x - b[1]), hi = std::max(b[1], 2 * s.mirror_x - b[0]);
        b[0] = lo;
        b[1] = hi;
    }
    std::copy(b, b + 4, s.bounds);
    s.field_range[0] = range[0];
    s.field_range[1] = range[1];
    return s;
}

} // namespace plastica::render
