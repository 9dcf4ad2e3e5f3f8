#include "model/model.hpp"

#include <algorithm>
#include <cmath>

namespace plastica {

bool Model::inelastic() const {
    for (const auto& s : sections)
        if (s.steel) return true;
    return false;
}

bool Model::has_plasticity(Plasticity kind) const {
    for (const ElementSpec& e : elements)
        if (sections[e.section].plasticity == kind) return true;
    return false;
}

int Model::integration_points() const {
    int most = 0;
    for (const ElementSpec& e : elements)
        if (sections[e.section].plasticity == Plasticity::distributed)
            most = std::max(most, sections[e.section].integration_points);
    return most;
}

bool Model::has_unilateral_base() const {
    for (const auto& s : springs)
        if (s.unilateral) return true;
    return false;
}

double Model::reference_load_norm() const {
    double sum = 0.0;
    for (const auto& l : loads)
        for (double v : l.value) sum += v * v;
    return std::sqrt(sum);
}

} // namespace plastica
