#include "solver/block_assembler.hpp"

#include <algorithm>

namespace plastica {

BlockAssembler::BlockAssembler(int size, const std::vector<std::vector<int>>& blocks)
    : matrix_(size, size) {
    std::vector<Eigen::Triplet<double>> pattern;
    for (const auto& eqs : blocks)
        for (int a : eqs)
            for (int b : eqs)
                if (a >= 0 && b >= 0) pattern.emplace_back(a, b, 0.0);
    // Every diagonal entry exists so that a DOF with no stiffness is reported, not lost.
    for (int i = 0; i < size; ++i) pattern.emplace_back(i, i, 0.0);
    matrix_.setFromTriplets(pattern.begin(), pattern.end());
    matrix_.makeCompressed();

    slots_.reserve(blocks.size());
    for (const auto& eqs : blocks) {
        std::vector<int> slots(eqs.size() * eqs.size(), -1);
        for (std::size_t a = 0; a < eqs.size(); ++a)
            for (std::size_t b = 0; b < eqs.size(); ++b) {
                if (eqs[a] < 0 || eqs[b] < 0) continue;
                const int col = eqs[b];
                const int* rows = matrix_.innerIndexPtr();
                const int begin = matrix_.outerIndexPtr()[col];
                const int end = matrix_.outerIndexPtr()[col + 1];
                const int* hit = std::lower_bound(rows + begin, rows + end, eqs[a]);
                slots[a * eqs.size() + b] = static_cast<int>(hit - rows);
            }
        complete_.push_back(std::find(slots.begin(), slots.end(), -1) == slots.end());
        slots_.push_back(std::move(slots));
    }
}

void BlockAssembler::set_zero() {
    std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
}

} // namespace plastica
