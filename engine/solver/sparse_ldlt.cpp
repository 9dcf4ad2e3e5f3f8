#include "solver/sparse_ldlt.hpp"

namespace plastica {

void SparseLdlt::analyse(const SparseMatrix& upper) {
    n_ = static_cast<int>(upper.rows());
    const int* start = upper.outerIndexPtr();
    const int* rows = upper.innerIndexPtr();
    const auto n = static_cast<std::size_t>(n_);

    // The elimination tree and the count of each column of L.
    std::vector<int> parent(n, -1), count(n, 0), tag(n, -1);
    for (int k = 0; k < n_; ++k) {
        tag[static_cast<std::size_t>(k)] = k;
        for (int p = start[k]; p < start[k + 1]; ++p)
            for (int i = rows[p]; i < k && tag[static_cast<std::size_t>(i)] != k; i = parent[static_cast<std::size_t>(i)]) {
                if (parent[static_cast<std::size_t>(i)] == -1) parent[static_cast<std::size_t>(i)] = k;
                ++count[static_cast<std::size_t>(i)];
                tag[static_cast<std::size_t>(i)] = k;
            }
    }
    column_start_.assign(n + 1, 0);
    for (std::size_t k = 0; k < n; ++k) column_start_[k + 1] = column_start_[k] + count[k];
    row_.assign(static_cast<std::size_t>(column_start_[n]), 0);
    value_.assign(row_.size(), 0.0);

    // Each row's reach, in the order the up-looking factorisation visits it: the path from
    // each entry of A(:, k) up the tree to a node already visited, the paths stacked so that
    // the one found last is eliminated first.
    reach_start_.assign(n + 1, 0);
    reach_column_.clear();
    reach_column_.reserve(row_.size());
    // The counts are spent: their storage counts the entries formed. One array holds both the
    // stack (at its end) and the path being walked (at its start): a row's reach never
    // exceeds n, so the two never meet (a large model's peak memory is in these arrays).
    std::vector<int>& filled = count;
    std::fill(filled.begin(), filled.end(), 0);
    std::vector<int> stack(n);
    std::fill(tag.begin(), tag.end(), -1);
    for (int k = 0; k < n_; ++k) {
        int top = n_;
        tag[static_cast<std::size_t>(k)] = k;
        for (int p = start[k]; p < start[k + 1]; ++p) {
            if (rows[p] > k) continue;
            int length = 0;
            for (int i = rows[p]; tag[static_cast<std::size_t>(i)] != k; i = parent[static_cast<std::size_t>(i)]) {
                stack[static_cast<std::size_t>(length++)] = i;
                tag[static_cast<std::size_t>(i)] = k;
            }
            while (length > 0) stack[static_cast<std::size_t>(--top)] = stack[static_cast<std::size_t>(--length)];
        }
        for (; top < n_; ++top) {
            const auto i = static_cast<std::size_t>(stack[static_cast<std::size_t>(top)]);
            row_[static_cast<std::size_t>(column_start_[i] + filled[i]++)] = k;
            reach_column_.push_back(static_cast<int>(i));
        }
        reach_start_[static_cast<std::size_t>(k) + 1] = static_cast<int>(reach_column_.size());
    }
    d_ = Eigen::VectorXd::Zero(n_);
    y_.assign(n, 0.0);
    filled_.assign(n, 0);
}

bool SparseLdlt::factorize(const SparseMatrix& upper) {
    const int* start = upper.outerIndexPtr();
    const int* rows = upper.innerIndexPtr();
    const double* a = upper.valuePtr();
    double* y = y_.data();
    double* lx = value_.data();
    const int* li = row_.data();
    int* filled = filled_.data();
    std::fill(filled_.begin(), filled_.end(), 0);
    for (int k = 0; k < n_; ++k) {
        y[k] = 0.0;
        for (int p = start[k]; p < start[k + 1]; ++p)
            if (rows[p] <= k) y[rows[p]] += a[p];
        // As Eigen forms it, with its (identity) shift: the same bits.
        double d = y[k] * 1.0 + 0.0;
        y[k] = 0.0;
        for (int r = reach_start_[static_cast<std::size_t>(k)]; r < reach_start_[static_cast<std::size_t>(k) + 1]; ++r) {
            const int i = reach_column_[static_cast<std::size_t>(r)];
            const double yi = y[i];
            y[i] = 0.0;
            const double l_ki = yi / d_[i];
            const int above = column_start_[static_cast<std::size_t>(i)] + filled[i]++;
            for (int p = column_start_[static_cast<std::size_t>(i)]; p < above; ++p) y[li[p]] -= lx[p] * yi;
            d -= l_ki * yi;
            lx[above] = l_ki;
        }
        d_[k] = d;
        if (d == 0.0) {
            // Leave the work row clean for the next factorisation.
            std::fill(y_.begin(), y_.end(), 0.0);
            return false;
        }
    }
    return true;
}

void SparseLdlt::solve_in_place(Eigen::VectorXd& x) const {
    const int* li = row_.data();
    const double* lx = value_.data();
    // L y = b, column by column (zeros skipped, as Eigen's sparse triangular solve does).
    for (int i = 0; i < n_; ++i) {
        const double xi = x[i];
        if (xi != 0.0)
            for (int p = column_start_[static_cast<std::size_t>(i)]; p < column_start_[static_cast<std::size_t>(i) + 1]; ++p)
                x[li[p]] -= xi * lx[p];
    }
    // D z = y, through the pivots' reciprocals as Eigen's diagonal inverse does.
    for (int i = 0; i < n_; ++i) x[i] = (1.0 / d_[i]) * x[i];
    // Lᵀ x = z, row by row from the last.
    for (int i = n_ - 1; i >= 0; --i) {
        double xi = x[i];
        for (int p = column_start_[static_cast<std::size_t>(i)]; p < column_start_[static_cast<std::size_t>(i) + 1]; ++p)
            xi -= lx[p] * x[li[p]];
        x[i] = xi;
    }
}

void SparseLdlt::solve_in_place(Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    const int* li = row_.data();
    const double* lx = value_.data();
    for (int i = 0; i < n_; ++i) {
        const double xi = x[i], yi = y[i];
        const int begin = column_start_[static_cast<std::size_t>(i)], end = column_start_[static_cast<std::size_t>(i) + 1];
        if (xi != 0.0 && yi != 0.0)
            for (int p = begin; p < end; ++p) {
                x[li[p]] -= xi * lx[p];
                y[li[p]] -= yi * lx[p];
            }
        else if (xi != 0.0)
            for (int p = begin; p < end; ++p) x[li[p]] -= xi * lx[p];
        else if (yi != 0.0)
            for (int p = begin; p < end; ++p) y[li[p]] -= yi * lx[p];
    }
    for (int i = 0; i < n_; ++i) {
        const double inverse = 1.0 / d_[i];
        x[i] = inverse * x[i];
        y[i] = inverse * y[i];
    }
    for (int i = n_ - 1; i >= 0; --i) {
        double xi = x[i], yi = y[i];
        for (int p = column_start_[static_cast<std::size_t>(i)]; p < column_start_[static_cast<std::size_t>(i) + 1]; ++p) {
            xi -= lx[p] * x[li[p]];
            yi -= lx[p] * y[li[p]];
        }
        x[i] = xi;
        y[i] = yi;
    }
}

} // namespace plastica
