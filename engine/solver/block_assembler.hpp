// Assembly of element blocks into one sparse matrix whose pattern is fixed at construction:
// every block's entries are mapped once to their slots in the compressed storage, so each
// Newton iteration only zeroes and adds values (no allocation, no sorting).
#pragma once

#include <Eigen/Sparse>
#include <vector>

namespace plastica {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

class BlockAssembler {
public:
    // Each block lists its equation numbers; −1 marks a DOF that is not assembled.
    BlockAssembler(int size, const std::vector<std::vector<int>>& blocks);

    void set_zero();
    // Adds the dense block (row-major order of its equations) to the matrix.
    template <class Dense>
    void add(std::size_t block, const Dense& values) {
        const std::vector<int>& slots = slots_[block];
        const int n = static_cast<int>(values.rows());
        double* data = matrix_.valuePtr();
        if (complete_[block]) { // no DOF left out: no test per entry
            for (int a = 0; a < n; ++a)
                for (int b = 0; b < n; ++b) data[slots[a * n + b]] += values(a, b);
            return;
        }
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) {
                const int slot = slots[a * n + b];
                if (slot >= 0) data[slot] += values(a, b);
            }
    }
    const SparseMatrix& matrix() const { return matrix_; }

private:
    SparseMatrix matrix_;
    std::vector<std::vector<int>> slots_;
    std::vector<bool> complete_; // per block: every entry has a slot
};

} // namespace plastica
