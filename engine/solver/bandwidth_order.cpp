#include "solver/bandwidth_order.hpp"

#include <algorithm>

namespace plastica {

namespace {

// The symmetric adjacency of K's pattern, without the diagonal.
struct Graph {
    std::vector<int> start, next;
    int degree(int v) const { return start[static_cast<std::size_t>(v) + 1] - start[static_cast<std::size_t>(v)]; }
};

Graph adjacency(const SparseMatrix& K) {
    const auto n = static_cast<std::size_t>(K.rows());
    Graph g;
    g.start.assign(n + 1, 0);
    for (int col = 0; col < K.outerSize(); ++col)
        for (SparseMatrix::InnerIterator it(K, col); it; ++it)
            if (it.row() != col) {
                ++g.start[static_cast<std::size_t>(it.row()) + 1];
                ++g.start[static_cast<std::size_t>(col) + 1];
            }
    for (std::size_t v = 0; v < n; ++v) g.start[v + 1] += g.start[v];
    g.next.resize(static_cast<std::size_t>(g.start[n]));
    std::vector<int> fill(g.start.begin(), g.start.end() - 1);
    for (int col = 0; col < K.outerSize(); ++col)
        for (SparseMatrix::InnerIterator it(K, col); it; ++it)
            if (it.row() != col) {
                g.next[static_cast<std::size_t>(fill[static_cast<std::size_t>(it.row())]++)] = col;
                g.next[static_cast<std::size_t>(fill[static_cast<std::size_t>(col)]++)] = static_cast<int>(it.row());
            }
    // Both triangles stored give each edge twice: keep one of each.
    std::vector<int> start(n + 1, 0);
    std::size_t kept = 0;
    for (std::size_t v = 0; v < n; ++v) {
        auto* begin = g.next.data() + g.start[v];
        auto* end = g.next.data() + g.start[v + 1];
        std::sort(begin, end);
        end = std::unique(begin, end);
        for (auto* p = begin; p != end; ++p) g.next[kept++] = *p;
        start[v + 1] = static_cast<int>(kept);
    }
    g.next.resize(kept);
    g.start = std::move(start);
    return g;
}

// The equations reached from a root, level by level (each equation's new neighbours by
// increasing degree), written into `order` from `at`.
struct Sweep {
    std::size_t reached = 0;    // equations reached
    std::size_t last_level = 0; // where the last level starts, from `at`
    int levels = 0;
};

Sweep breadth_first(const Graph& g, int root, std::vector<int>& order, std::size_t at, std::vector<int>& mark, int stamp) {
    Sweep sweep;
    std::size_t head = at, tail = at;
    order[tail++] = root;
    mark[static_cast<std::size_t>(root)] = stamp;
    while (head < tail) {
        ++sweep.levels;
        sweep.last_level = head - at;
        const std::size_t level_end = tail;
        for (; head < level_end; ++head) {
            const int v = order[head];
            const std::size_t first_new = tail;
            for (int p = g.start[static_cast<std::size_t>(v)]; p < g.start[static_cast<std::size_t>(v) + 1]; ++p) {
                const int w = g.next[static_cast<std::size_t>(p)];
                if (mark[static_cast<std::size_t>(w)] == stamp) continue;
                mark[static_cast<std::size_t>(w)] = stamp;
                order[tail++] = w;
            }
            std::stable_sort(order.begin() + static_cast<long>(first_new), order.begin() + static_cast<long>(tail),
                             [&](int a, int b) { return g.degree(a) < g.degree(b); });
        }
    }
    sweep.reached = tail - at;
    return sweep;
}

} // namespace

std::vector<int> reverse_cuthill_mckee(const SparseMatrix& K) {
    const auto n = static_cast<std::size_t>(K.rows());
    const Graph g = adjacency(K);
    std::vector<int> order(n), mark(n, -1);
    std::vector<bool> placed(n, false);
    int stamp = 0;
    std::size_t at = 0;
    for (std::size_t seed = 0; seed < n; ++seed) {
        if (placed[seed]) continue;
        // A pseudo-peripheral root: move to a least-connected equation of the last level for as
        // long as that deepens the levels (a few moves at most).
        int root = static_cast<int>(seed);
        Sweep sweep = breadth_first(g, root, order, at, mark, stamp++);
        for (int move = 0; move < 8; ++move) {
            int candidate = order[at + sweep.last_level];
            for (std::size_t k = at + sweep.last_level; k < at + sweep.reached; ++k)
                if (g.degree(order[k]) < g.degree(candidate)) candidate = order[k];
            const Sweep from_candidate = breadth_first(g, candidate, order, at, mark, stamp++);
            if (from_candidate.levels <= sweep.levels) {
                sweep = breadth_first(g, root, order, at, mark, stamp++);
                break;
            }
            root = candidate;
            sweep = from_candidate;
        }
        for (std::size_t k = at; k < at + sweep.reached; ++k) placed[static_cast<std::size_t>(order[k])] = true;
        at += sweep.reached;
    }
    std::reverse(order.begin(), order.end());
    return order;
}

} // namespace plastica
