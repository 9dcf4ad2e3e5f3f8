#include "curve_writer.hpp"

#include "analysis/support_reactions.hpp"

#include <stdexcept>

namespace plastica {

CurveWriter::CurveWriter(const std::string& path, const Model& model) : out_(path), model_(&model) {
    if (!out_) throw std::runtime_error("cannot write " + path);
    out_ << "step,load_factor,load,control_displacement,iterations,contact_count,hinge_count,"
            "plastic_hinge_count,base_reaction,contact_length,negative_pivots,accepted_by,residual";
    for (const std::string& name : reaction_columns(model)) out_ << ',' << name;
    out_ << '\n';
    out_.precision(12);
}

void CurveWriter::operator()(const StepResult& r) {
    out_ << r.step << ',' << r.load_factor << ',' << r.load << ',' << r.control_displacement << ','
         << r.iterations << ',' << r.contact_count << ',' << r.hinge_count << ','
         << r.plastic_hinge_count << ',' << r.base_reaction << ',' << r.contact_length << ','
         << r.negative_pivots << ',' << to_string(r.accepted_by) << ',' << r.residual;
    for (const SupportReaction& s : support_reactions(*model_, r))
        for (int d = 0; d < dofs_per_node; ++d)
            if (s.reported[d]) out_ << ',' << s.force[d];
    out_ << '\n';
    out_.flush();
}

} // namespace plastica
