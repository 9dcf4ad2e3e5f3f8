#include "solver/block_assembler.hpp"

#include <algorithm>

namespace plastica {

namespace {

// The slots of each column's runs of three rows when every group of three equations of the
// block is a node's three consecutive free equations (so their rows lie next to each other in
// every column), else none.
std::vector<int> column_runs(const std::vector<int>& eqs, const std::vector<int>& slots) {
    const std::size_t n = eqs.size();
    if (n % 3 != 0) return {};
    for (std::size_t g = 0; g < n; g += 3)
        if (eqs[g] < 0 || eqs[g + 1] != eqs[g] + 1 || eqs[g + 2] != eqs[g] + 2) return {};
    std::vector<int> runs;
    for (std::size_t b = 0; b < n; ++b)
        for (std::size_t g = 0; g < n; g += 3) {
            const int first = slots[g * n + b];
            if (slots[(g + 1) * n + b] != first + 1 || slots[(g + 2) * n + b] != first + 2) return {};
            runs.push_back(first);
        }
    return runs;
}

} // namespace

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
        column_runs_.push_back(column_runs(eqs, slots));
        slots_.push_back(std::move(slots));
    }
}

void BlockAssembler::set_zero() {
    std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
}

} // namespace plastica
