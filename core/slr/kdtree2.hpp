#pragma once
// A static 2-D k-d tree over points (x, y) for k-nearest-neighbour queries: used by the
// linearity step (slopes to the k nearest candidate regions) and by the recovery step (the two
// nearest signal regions of a pending one), so neither is an O(R²) scan. Internal to core/slr.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace lwb::core::slr::detail {

class KdTree2 {
public:
    KdTree2() = default;
    KdTree2(std::vector<double> x, std::vector<double> y) : m_x(std::move(x)), m_y(std::move(y)) {
        m_idx.resize(m_x.size());
        for (size_t i = 0; i < m_idx.size(); ++i) m_idx[i] = static_cast<uint32_t>(i);
        build(0, m_idx.size(), 0);
    }
    size_t size() const { return m_idx.size(); }

    /// The k nearest points to (qx, qy), nearest first (ties by index), skipping index `skip`
    /// (pass UINT32_MAX to skip none). Writes at most k indices and squared distances.
    /// With maxD2 given, only points within that squared distance are considered.
    size_t nearest(double qx, double qy, size_t k, uint32_t skip, uint32_t* outIdx, double* outD2,
                   double maxD2 = 1e308) const {
        if (k == 0 || m_idx.empty()) return 0;
        Heap h{outIdx, outD2, 0, k, maxD2};
        search(0, m_idx.size(), 0, qx, qy, skip, h);
        // Insertion-sorted already (nearest first).
        return h.n;
    }

private:
    struct Heap {  // the k best so far, kept sorted ascending (k is small)
        uint32_t* idx;
        double* d2;
        size_t n, k;
        double limit;
        double worst() const { return n < k ? limit : d2[n - 1]; }
        void push(uint32_t i, double d) {
            if (d > limit) return;
            if (n == k && (d > d2[n - 1] || (d == d2[n - 1] && i > idx[n - 1]))) return;
            size_t pos = n < k ? n++ : n - 1;
            while (pos > 0 && (d2[pos - 1] > d || (d2[pos - 1] == d && idx[pos - 1] > i))) {
                d2[pos] = d2[pos - 1];
                idx[pos] = idx[pos - 1];
                --pos;
            }
            d2[pos] = d;
            idx[pos] = i;
        }
    };

    void build(size_t lo, size_t hi, int axis) {
        if (hi - lo <= kLeaf) return;
        const size_t mid = lo + (hi - lo) / 2;
        const std::vector<double>& v = axis ? m_y : m_x;
        std::nth_element(m_idx.begin() + lo, m_idx.begin() + mid, m_idx.begin() + hi,
                         [&](uint32_t a, uint32_t b) { return v[a] < v[b] || (v[a] == v[b] && a < b); });
        build(lo, mid, axis ^ 1);
        build(mid + 1, hi, axis ^ 1);
    }

    void search(size_t lo, size_t hi, int axis, double qx, double qy, uint32_t skip, Heap& h) const {
        if (hi - lo <= kLeaf) {
            for (size_t i = lo; i < hi; ++i) {
                const uint32_t p = m_idx[i];
                if (p == skip) continue;
                const double dx = m_x[p] - qx, dy = m_y[p] - qy;
                h.push(p, dx * dx + dy * dy);
            }
            return;
        }
        const size_t mid = lo + (hi - lo) / 2;
        const uint32_t p = m_idx[mid];
        const double split = axis ? m_y[p] : m_x[p];
        const double q = axis ? qy : qx;
        if (p != skip) {
            const double dx = m_x[p] - qx, dy = m_y[p] - qy;
            h.push(p, dx * dx + dy * dy);
        }
        const double diff = q - split;
        if (diff < 0) {
            search(lo, mid, axis ^ 1, qx, qy, skip, h);
            if (diff * diff <= h.worst()) search(mid + 1, hi, axis ^ 1, qx, qy, skip, h);
        } else {
            search(mid + 1, hi, axis ^ 1, qx, qy, skip, h);
            if (diff * diff <= h.worst()) search(lo, mid, axis ^ 1, qx, qy, skip, h);
        }
    }

    static constexpr size_t kLeaf = 8;
    std::vector<double> m_x, m_y;
    std::vector<uint32_t> m_idx;
};

}  // namespace lwb::core::slr::detail
