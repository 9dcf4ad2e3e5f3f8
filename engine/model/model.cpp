#include "model/model.hpp"

#include <cmath>

namespace plastica {

bool Model::inelastic() const {
    for (const auto& s : sections)
        if (s.steel) return true;
    return false;
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
