#include "solver/block_profile_ldlt.hpp"

#include "solver/bandwidth_order.hpp"

#include <algorithm>

namespace plastica {

namespace {

bool same_pattern(const SparseMatrix& K, int a, int b) {
    const int* start = K.outerIndexPtr();
    const int* rows = K.innerIndexPtr();
    return start[a + 1] - start[a] == start[b + 1] - start[b] &&
           std::equal(rows + start[a], rows + start[a + 1], rows + start[b]);
}

// c −= a·bᵀ for 3 × 3 row-major blocks.
inline void subtract_product_transposed(const double* a, const double* b, double* c) {
    for (int r = 0; r < 3; ++r)
        for (int s = 0; s < 3; ++s) c[3 * r + s] -= a[3 * r] * b[3 * s] + a[3 * r + 1] * b[3 * s + 1] + a[3 * r + 2] * b[3 * s + 2];
}

} // namespace

void BlockProfileLdlt::BlockPivots::solve(double* v) const {
    v[1] -= l10 * v[0];
    v[2] -= l20 * v[0] + l21 * v[1];
    v[0] *= inverse[0];
    v[1] *= inverse[1];
    v[2] *= inverse[2];
    v[1] -= l21 * v[2];
    v[0] -= l10 * v[1] + l20 * v[2];
}

bool BlockProfileLdlt::analyse(const SparseMatrix& K, double max_fill) {
    const int n = static_cast<int>(K.rows());
    // Blocks: runs of up to three consecutive equations with the same pattern.
    std::vector<int> block_of(static_cast<std::size_t>(n)), local_of(static_cast<std::size_t>(n));
    std::vector<int> leader; // each block's first equation
    for (int e = 0; e < n; ++e) {
        const bool joins = e > 0 && local_of[static_cast<std::size_t>(e) - 1] < 2 && same_pattern(K, e - 1, e);
        if (!joins) leader.push_back(e);
        block_of[static_cast<std::size_t>(e)] = static_cast<int>(leader.size()) - 1;
        local_of[static_cast<std::size_t>(e)] = joins ? local_of[static_cast<std::size_t>(e) - 1] + 1 : 0;
    }
    blocks_ = static_cast<int>(leader.size());
    const auto nb = static_cast<std::size_t>(blocks_);

    // The block graph, from each block's first column (its others have the same pattern).
    SparseMatrix graph(blocks_, blocks_);
    {
        std::vector<int> start(nb + 1, 0), next;
        for (std::size_t g = 0; g < nb; ++g) {
            for (SparseMatrix::InnerIterator it(K, leader[g]); it; ++it) {
                const int h = block_of[static_cast<std::size_t>(it.row())];
                if (next.size() == static_cast<std::size_t>(start[g]) || next.back() != h) next.push_back(h);
            }
            start[g + 1] = static_cast<int>(next.size());
        }
        graph.resizeNonZeros(static_cast<Eigen::Index>(next.size()));
        std::copy(start.begin(), start.end(), graph.outerIndexPtr());
        std::copy(next.begin(), next.end(), graph.innerIndexPtr());
        std::fill(graph.valuePtr(), graph.valuePtr() + next.size(), 1.0);
    }
    const std::vector<int> order = reverse_cuthill_mckee(graph);
    std::vector<int> position(nb);
    for (std::size_t p = 0; p < nb; ++p) position[static_cast<std::size_t>(order[p])] = static_cast<int>(p);

    // The envelope of the block rows in that order, against the nonzero blocks it must hold.
    first_.assign(nb, 0);
    double lower_blocks = 0.0;
    for (std::size_t p = 0; p < nb; ++p) first_[p] = static_cast<int>(p);
    for (std::size_t g = 0; g < nb; ++g) {
        const int p = position[g];
        for (SparseMatrix::InnerIterator it(graph, static_cast<Eigen::Index>(g)); it; ++it) {
            const int q = position[static_cast<std::size_t>(it.row())];
            if (q > p) continue;
            lower_blocks += 1.0;
            first_[static_cast<std::size_t>(p)] = std::min(first_[static_cast<std::size_t>(p)], q);
        }
    }
    start_.assign(nb + 1, 0);
    for (std::size_t p = 0; p < nb; ++p)
        start_[p + 1] = start_[p] + 9 * static_cast<std::size_t>(static_cast<int>(p) - first_[p] + 1);
    if (static_cast<double>(start_[nb]) / 9.0 > max_fill * lower_blocks) {
        *this = BlockProfileLdlt();
        return false;
    }

    // Where each equation sits in the padded vector, each block's size, and the pivots' order.
    padded_.resize(static_cast<std::size_t>(n));
    size_.assign(nb, 0);
    for (int e = 0; e < n; ++e) {
        const int p = position[static_cast<std::size_t>(block_of[static_cast<std::size_t>(e)])];
        padded_[static_cast<std::size_t>(e)] = 3 * p + local_of[static_cast<std::size_t>(e)];
        ++size_[static_cast<std::size_t>(p)];
    }
    pivot_equations_.resize(static_cast<std::size_t>(n));
    for (std::size_t p = 0, at = 0; p < nb; ++p)
        for (int l = 0; l < size_[p]; ++l) pivot_equations_[at++] = leader[static_cast<std::size_t>(order[p])] + l;
    pivots_of_.resize(static_cast<std::size_t>(n));
    for (std::size_t k = 0; k < pivot_equations_.size(); ++k) pivots_of_[static_cast<std::size_t>(pivot_equations_[k])] = static_cast<int>(k);
    pivots_.assign(static_cast<std::size_t>(n), 0.0);

    // Each value of K's lower triangle goes to the block below the diagonal that holds its pair
    // of equations, or into a diagonal block on both sides of it.
    from_.clear();
    to_.clear();
    const double* values = K.valuePtr();
    for (int col = 0; col < K.outerSize(); ++col)
        for (SparseMatrix::InnerIterator it(K, col); it; ++it) {
            if (it.row() < col) continue;
            int a = padded_[static_cast<std::size_t>(it.row())], b = padded_[static_cast<std::size_t>(col)];
            if (a / 3 < b / 3) std::swap(a, b);
            const int p = a / 3, q = b / 3;
            const std::size_t block = start_[static_cast<std::size_t>(p)] + 9 * static_cast<std::size_t>(q - first_[static_cast<std::size_t>(p)]);
            const int source = static_cast<int>(&it.value() - values);
            from_.push_back(source);
            to_.push_back(static_cast<int>(block + static_cast<std::size_t>(3 * (a % 3) + b % 3)));
            if (p == q && a != b) {
                from_.push_back(source);
                to_.push_back(static_cast<int>(block + static_cast<std::size_t>(3 * (b % 3) + a % 3)));
            }
        }
    value_.assign(start_[nb], 0.0);
    std::vector<bool> set(value_.size(), false);
    for (const int at : to_) set[static_cast<std::size_t>(at)] = true;
    unset_.clear();
    for (std::size_t at = 0; at < set.size(); ++at)
        if (!set[at]) unset_.push_back(static_cast<int>(at));
    block_pivots_.assign(nb, BlockPivots{});
    work_.assign(3 * nb, 0.0);
    return true;
}

bool BlockProfileLdlt::factorize(const SparseMatrix& K) {
    // The entries K does not fill (fill-in, padding) start from zero; the others are set.
    for (const int at : unset_) value_[static_cast<std::size_t>(at)] = 0.0;
    const double* values = K.valuePtr();
    for (std::size_t k = 0; k < from_.size(); ++k) value_[static_cast<std::size_t>(to_[k])] = values[from_[k]];
    std::size_t pivot = 0;
    for (int k = 0; k < blocks_; ++k) {
        const auto uk = static_cast<std::size_t>(k);
        const int first = first_[uk];
        double* row = value_.data() + start_[uk]; // block j at row + 9 (j − first)
        double* D = row + 9 * (k - first);
        for (int l = size_[uk]; l < 3; ++l) D[4 * l] = 1.0; // padding: an identity equation
        // U_kj = A_kj − Σ_i U_ki·L_jiᵀ over the blocks both rows hold (U_kj = L_kj·D_j).
        for (int j = first + 1; j < k; ++j) {
            const int first_j = first_[static_cast<std::size_t>(j)];
            const double* lj = value_.data() + start_[static_cast<std::size_t>(j)];
            for (int i = std::max(first, first_j); i < j; ++i)
                subtract_product_transposed(row + 9 * (i - first), lj + 9 * (i - first_j), row + 9 * (j - first));
        }
        // L_kj = U_kj·D_j⁻¹, row by row through D_j's own LDLᵀ; D_k −= U_kj·L_kjᵀ.
        for (int j = first; j < k; ++j) {
            double* block = row + 9 * (j - first);
            double L[9];
            for (int r = 0; r < 3; ++r) {
                for (int s = 0; s < 3; ++s) L[3 * r + s] = block[3 * r + s];
                block_pivots_[static_cast<std::size_t>(j)].solve(L + 3 * r);
            }
            subtract_product_transposed(block, L, D);
            std::copy(L, L + 9, block);
        }
        // D_k's own LDLᵀ, from its lower triangle.
        BlockPivots& f = block_pivots_[uk];
        f.d[0] = D[0];
        if (f.d[0] == 0.0) return false;
        f.l10 = D[3] / f.d[0];
        f.l20 = D[6] / f.d[0];
        f.d[1] = D[4] - f.l10 * f.l10 * f.d[0];
        if (f.d[1] == 0.0) return false;
        f.l21 = (D[7] - f.l20 * f.l10 * f.d[0]) / f.d[1];
        f.d[2] = D[8] - f.l20 * f.l20 * f.d[0] - f.l21 * f.l21 * f.d[1];
        if (f.d[2] == 0.0) return false;
        for (int l = 0; l < 3; ++l) f.inverse[l] = 1.0 / f.d[l];
        for (int l = 0; l < size_[uk]; ++l) pivots_[pivot++] = f.d[l];
    }
    return true;
}

template <std::size_t Count>
void BlockProfileLdlt::forward(const std::array<double*, Count>& w) const {
    // L y = b by block rows.
    for (int k = 0; k < blocks_; ++k) {
        const int first = first_[static_cast<std::size_t>(k)];
        const double* row = value_.data() + start_[static_cast<std::size_t>(k)];
        for (int j = first; j < k; ++j) {
            const double* L = row + 9 * (j - first);
            for (double* v : w) {
                double* vk = v + 3 * k;
                const double* vj = v + 3 * j;
                for (int r = 0; r < 3; ++r) vk[r] -= L[3 * r] * vj[0] + L[3 * r + 1] * vj[1] + L[3 * r + 2] * vj[2];
            }
        }
    }
}

template <std::size_t Count>
void BlockProfileLdlt::backward(const std::array<double*, Count>& w) const {
    // D z = y, then Lᵀ x = z by block rows from the last.
    for (int k = 0; k < blocks_; ++k)
        for (double* v : w) block_pivots_[static_cast<std::size_t>(k)].solve(v + 3 * k);
    for (int k = blocks_ - 1; k >= 0; --k) {
        const int first = first_[static_cast<std::size_t>(k)];
        const double* row = value_.data() + start_[static_cast<std::size_t>(k)];
        for (int j = first; j < k; ++j) {
            const double* L = row + 9 * (j - first);
            for (double* v : w) {
                const double* vk = v + 3 * k;
                double* vj = v + 3 * j;
                for (int s = 0; s < 3; ++s) vj[s] -= L[s] * vk[0] + L[3 + s] * vk[1] + L[6 + s] * vk[2];
            }
        }
    }
}

namespace {

// b in the padded order (its padding zero), and back.
void pad(const std::vector<int>& padded, const Eigen::VectorXd& b, std::vector<double>& w) {
    std::fill(w.begin(), w.end(), 0.0);
    for (std::size_t e = 0; e < padded.size(); ++e) w[static_cast<std::size_t>(padded[e])] = b[static_cast<Eigen::Index>(e)];
}

void unpad(const std::vector<int>& padded, const std::vector<double>& w, Eigen::VectorXd& x) {
    x.resize(static_cast<Eigen::Index>(padded.size()));
    for (std::size_t e = 0; e < padded.size(); ++e) x[static_cast<Eigen::Index>(e)] = w[static_cast<std::size_t>(padded[e])];
}

} // namespace

void BlockProfileLdlt::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const {
    pad(padded_, b, work_);
    const std::array<double*, 1> w{work_.data()};
    forward(w);
    backward(w);
    unpad(padded_, work_, x);
}

void BlockProfileLdlt::solve(const Eigen::VectorXd& b1, const Eigen::VectorXd& b2, Eigen::VectorXd& x1,
                             Eigen::VectorXd& x2) const {
    work2_.resize(work_.size());
    pad(padded_, b1, work_);
    pad(padded_, b2, work2_);
    const std::array<double*, 2> w{work_.data(), work2_.data()};
    forward(w);
    backward(w);
    unpad(padded_, work_, x1);
    unpad(padded_, work2_, x2);
}

} // namespace plastica
