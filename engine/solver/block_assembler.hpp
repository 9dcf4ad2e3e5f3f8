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
        if (!column_runs_[block].empty()) {
            // Each node's three rows of a column are three neighbouring values: one slot per run.
            const int* run = column_runs_[block].data();
            for (int b = 0; b < n; ++b)
                for (int g = 0; g < n; g += 3, ++run) {
                    double* at = data + *run;
                    at[0] += values(g, b);
                    at[1] += values(g + 1, b);
                    at[2] += values(g + 2, b);
                }
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
    // Per block whose equations come in free node triples (3 consecutive equations each): the
    // slot of each column's run of three rows, column by column; empty for any other block.
    std::vector<std::vector<int>> column_runs_;
};

} // namespace plastica
