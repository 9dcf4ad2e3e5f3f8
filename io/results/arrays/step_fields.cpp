// The step as a whole (field data): its time, load factor, reported load and displacement,
// counts, stage and pattern factors, and the names and units the pictures are labelled with
// (the render stage reads them from here, not from the scene file).
#include "arrays/output_array.hpp"

#include <algorithm>

namespace plastica {

namespace {

using namespace result;

void fill_step_fields(const StepView& v, XmlDataset& out) {
    const Model& m = v.model;
    const StepResult& r = v.result;
    std::vector<XmlArray>& fd = out.field_data;
    fd.push_back(field_value(name::time_value, v.time));
    if (v.has(name::model_time)) {
        fd.push_back(field_value(name::model_time, r.time));
        const EnergyTerms& e = r.energy;
        XmlArray energy = real_array(name::energy, 1, 8);
        const double terms[8] = {e.kinetic, e.strain, e.plastic, e.damping, e.contact, e.external, e.ground, e.error};
        std::copy(terms, terms + 8, real(energy).begin());
        fd.push_back(std::move(energy));
    }
    fd.push_back(field_value(name::load_factor, r.load_factor));
    fd.push_back(field_value(name::load, r.load));
    fd.push_back(field_value(name::control_displacement, r.control_displacement));
    fd.push_back(field_value(name::step, r.step));
    fd.push_back(field_value(name::iterations, r.iterations));
    fd.push_back(field_value(name::contact_count, r.contact_count));
    if (v.has(name::surface_contact_count))
        fd.push_back(field_value(name::surface_contact_count, static_cast<int>(r.surface_contacts.size())));
    fd.push_back(field_value(name::hinge_count, r.hinge_count));
    if (v.has(name::stage)) fd.push_back(field_value(name::stage, r.stage));
    if (v.has(name::pattern_factors)) {
        const std::vector<int> patterns = active_patterns(m);
        XmlArray factors = real_array(name::pattern_factors, patterns.size());
        std::string names;
        for (std::size_t k = 0; k < patterns.size(); ++k) {
            const std::size_t p = static_cast<std::size_t>(patterns[k]);
            real(factors)[k] = p < r.pattern_factors.size() ? r.pattern_factors[p] : 0.0;
            names += (k ? "," : "") + m.patterns[p];
        }
        fd.push_back(std::move(factors));
        fd.push_back(field_text(name::pattern_names, names));
    }
    if (v.has(name::mirror_x)) fd.push_back(field_value(name::mirror_x, *m.report.mirror_x));
    fd.push_back(field_text(name::scene, m.name));
    fd.push_back(field_text(name::title, m.title));
    fd.push_back(field_text(name::load_label, m.report.load_label));
    fd.push_back(field_text(name::displacement_label, m.report.displacement_label));
    // Units, when the scene names them: those of the reported load and displacement follow
    // from what they measure.
    if (v.has(name::length_unit)) {
        fd.push_back(field_text(name::length_unit, m.report.length_unit));
        fd.push_back(field_text(name::force_unit, m.report.force_unit));
        fd.push_back(field_text(name::load_unit, v.load_unit));
        fd.push_back(field_text(name::displacement_unit, v.displacement_unit));
    }
}

} // namespace

OutputGroup step_field_arrays() {
    const Where F = Where::field;
    const Type R = Type::float64, S = Type::text;
    return {{
                {name::time_value, F, R, 1, Quantity::none, When::always, "the PVD time: step index, arc length, or model time (static steps of a scene in time a millionth of a time step apart)"},
                {name::model_time, F, R, 1, Quantity::none, When::transient, "the step's time in the model (0 before the first transient stage)"},
                {name::energy, F, R, 8, Quantity::none, When::transient, "kinetic, strain, plastic, damping, contact, external, ground-motion energy, and the balance's error (curve.csv's columns)"},
                {name::load_factor, F, R, 1, Quantity::none, When::always, "λ"},
                {name::load, F, R, 1, Quantity::reported_load, When::always, "the reported load (total in its direction, or λ)"},
                {name::control_displacement, F, R, 1, Quantity::reported_displacement, When::always, "the controlled displacement"},
                {name::step, F, R, 1, Quantity::none, When::always, "step number"},
                {name::iterations, F, R, 1, Quantity::none, When::always, "Newton iterations of the step"},
                {name::contact_count, F, R, 1, Quantity::none, When::always, "nodes in contact"},
                {name::surface_contact_count, F, R, 1, Quantity::none, When::self_contact, "pairs of surfaces in contact (a node, or a point along a member, against a segment)"},
                {name::hinge_count, F, R, 1, Quantity::none, When::always, "element ends yielding or fully plastic"},
                {name::stage, F, R, 1, Quantity::none, When::staged, "1 for [analysis], then 2, 3, … for each [[stage]]"},
                {name::pattern_factors, F, R, 1, Quantity::none, When::patterns, "each load pattern's factor, one value per pattern in the order of pattern_names"},
                {name::pattern_names, F, S, 1, Quantity::none, When::patterns, "the load patterns, comma-separated"},
                {name::mirror_x, F, R, 1, Quantity::length, When::half_model, "x of the symmetry line of a half model"},
                {name::scene, F, S, 1, Quantity::none, When::always, "scene name"},
                {name::title, F, S, 1, Quantity::none, When::always, "scene title"},
                {name::load_label, F, S, 1, Quantity::none, When::always, "what the load axis shows"},
                {name::displacement_label, F, S, 1, Quantity::none, When::always, "what the displacement axis shows"},
                {name::length_unit, F, S, 1, Quantity::none, When::units, "[report] length_unit"},
                {name::force_unit, F, S, 1, Quantity::none, When::units, "[report] force_unit"},
                {name::load_unit, F, S, 1, Quantity::none, When::units, "unit of `load`"},
                {name::displacement_unit, F, S, 1, Quantity::none, When::units, "unit of `control_displacement`"},
            },
            fill_step_fields};
}

} // namespace plastica
