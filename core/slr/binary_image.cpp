#include "core/slr/binary_image.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <tuple>

#include "core/common/text.hpp"

namespace lwb::core::slr {

namespace {
constexpr double kCoordLimit = 2305843009213693952.0;  // 2^61: max − min + 1 of two coordinates then fits in int64
constexpr size_t kMaxPoints = 0xFFFFFFFEu;

// Union-find over pixel indices: union by smaller index (deterministic roots), path halving.
struct UnionFind {
    std::vector<uint32_t> parent;
    explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t find(uint32_t x) {
        while (parent[x] != x) {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        return x;
    }
    // Joins the region of pixel k to that of a later pixel p whose root is rootP (updated):
    // union by the smaller root, so each region's root is its smallest pixel.
    void attach(uint32_t k, uint32_t& rootP) {
        const uint32_t a = find(k);
        if (a == rootP) return;
        if (a < rootP) {
            parent[rootP] = a;
            rootP = a;
        } else {
            parent[a] = rootP;
        }
    }
};
}  // namespace

std::string validate(const MappingParams& p) {
    if (!std::isfinite(p.magT) || !(p.magT > 0))
        return "mag_T must be a finite number > 0 (pixels per second of epoch), not " + formatDouble(p.magT, 6);
    if (!std::isfinite(p.magOc) || !(p.magOc > 0))
        return "mag_OC must be a finite number > 0 (pixels per second of O-C), not " + formatDouble(p.magOc, 6);
    if (p.magT > 1e15) return "mag_T " + formatDouble(p.magT, 6) + " is absurd (more than 1e15 pixels per second)";
    if (p.magOc > 1e18) return "mag_OC " + formatDouble(p.magOc, 6) + " is absurd (more than 1e18 pixels per second)";
    if (p.connectivity != 4 && p.connectivity != 8)
        return "connectivity must be 4 or 8, not " + std::to_string(p.connectivity);
    return {};
}

namespace {
// std::round (half away from zero) of |x| <= 2^61 as an integer, without the library call that
// was a sixth of a sparse pass's screening: the integer part by truncation, then the fraction,
// which x − trunc(x) gives exactly (above 2^52 every double is whole and the fraction is 0).
// Without branches: the fraction of a noise point's coordinate is random, and the two
// mispredicted jumps of `f >= 0.5 ? … : f <= −0.5 ? …` were a quarter of the null model's image.
inline int64_t roundToInt64(double x) {
    const int64_t i = static_cast<int64_t>(x);
    const double f = x - static_cast<double>(i);
    return i + static_cast<int64_t>(f >= 0.5) - static_cast<int64_t>(f <= -0.5);
}

// Bits needed to hold v (0 for 0).
inline int bitsFor(uint64_t v) {
    int b = 0;
    while (b < 64 && (v >> b) != 0) ++b;
    return b;
}

// LSD radix sort of a[0..n) on the low `bits` bits of keyOf(element), 11 bits a pass, stable
// (ties keep their order). The result is left in a (tmp: scratch of n). False when cancelled
// between passes.
template <class T, class KeyOf>
bool radixSort(std::unique_ptr<T[]>& a, size_t n, int bits, KeyOf keyOf, const Feedback* fb) {
    std::unique_ptr<T[]> tmp(new T[n]);
    std::vector<size_t> count(2049);
    for (int shift = 0; shift < bits; shift += 11) {
        std::fill(count.begin(), count.end(), 0);
        for (size_t i = 0; i < n; ++i) ++count[((keyOf(a[i]) >> shift) & 2047) + 1];
        for (size_t d = 1; d < count.size(); ++d) count[d] += count[d - 1];
        for (size_t i = 0; i < n; ++i) tmp[count[(keyOf(a[i]) >> shift) & 2047]++] = a[i];
        a.swap(tmp);
        if (cancelled(fb)) return false;
    }
    return true;
}

// mapPoint, inlined into the image's two passes over the points.
inline bool mapOne(double t, double oc, double magT, double magOc, int64_t* row, int64_t* col) {
    // |round(x)| > 2^61 exactly when |x| > 2^61 (the doubles there are whole); NaN and ±inf fail
    // the comparison.
    const double r = t * magT, c = oc * magOc;
    if (!(std::fabs(r) <= kCoordLimit) || !(std::fabs(c) <= kCoordLimit)) return false;
    *row = roundToInt64(r);
    *col = roundToInt64(c);
    return true;
}

// Labelling: pixels sorted by (row, col), so the neighbours of a pixel in the row above form a
// contiguous run found with a moving pointer, and the left neighbour is the previous pixel.
// 4-connectivity links (r, c−1) and (r−1, c); 8 adds (r−1, c±1). False when cancelled.
template <class Coord>
bool linkPixels(const Coord* row, const Coord* col, size_t pixels, bool eight, UnionFind& uf, const Feedback* fb) {
    size_t rowStart = 0, prevStart = 0, prevEnd = 0;  // current row run start; previous row run [prevStart, prevEnd)
    bool havePrev = false;
    size_t j = 0;  // pointer into the previous row
    for (size_t p = 0; p < pixels; ++p) {
        const int64_t r = row[p], c = col[p];
        if (p == 0 || r != row[p - 1]) {
            // New row: the previous row run is the one just finished, if it is exactly r − 1.
            if (p > 0) {
                havePrev = static_cast<int64_t>(row[p - 1]) == r - 1;
                prevStart = rowStart;
                prevEnd = p;
            }
            rowStart = p;
            j = prevStart;
        }
        // p's root, kept here: p joins the regions of earlier pixels only.
        uint32_t rootP = static_cast<uint32_t>(p);
        if (p > rowStart && static_cast<int64_t>(col[p - 1]) == c - 1) uf.attach(static_cast<uint32_t>(p - 1), rootP);
        if (havePrev) {
            const int64_t lo = eight ? c - 1 : c, hi = eight ? c + 1 : c;
            // The pointer advances by a data-dependent 0, 1, 2 … pixels: two steps without a
            // branch (col[prevEnd] is this row's first pixel, so the read stays in the image),
            // then the loop for the rest, which is seldom needed (a loop's varying trip count was
            // mispredicted at most pixels).
            j += static_cast<size_t>(j < prevEnd) & static_cast<size_t>(static_cast<int64_t>(col[j]) < lo);
            j += static_cast<size_t>(j < prevEnd) & static_cast<size_t>(static_cast<int64_t>(col[j]) < lo);
            while (j < prevEnd && static_cast<int64_t>(col[j]) < lo) ++j;
            for (size_t k = j; k < prevEnd && static_cast<int64_t>(col[k]) <= hi; ++k) uf.attach(static_cast<uint32_t>(k), rootP);
        }
        if ((p & 0xFFFFF) == 0xFFFFF && cancelled(fb)) return false;
    }
    return true;
}
}  // namespace

bool mapPoint(double t, double oc, double magT, double magOc, int64_t* row, int64_t* col) {
    return mapOne(t, oc, magT, magOc, row, col);
}

namespace {

// The points in the sort, as columns: each point's key (its row, or row and column in one key
// when both fit), its column where they do not (key2, absurd magnifications only), and its
// index. Columns rather than one 24-byte item a point: the sort's two copies of the items
// were a raw kHz pass's peak (48 bytes an event; 24 now, issue 44).
struct SortKeys {
    std::unique_ptr<uint64_t[]> key, key2;
    std::unique_ptr<uint32_t[]> idx;
};

// The pixels' extent, and whether the rows come in order (points in time order: the usual case).
struct MapExtent {
    int64_t rMin = 0, rMax = 0, cMin = 0, cMax = 0;
    bool rowsInOrder = true;  // rows never decrease
    size_t rowRuns = 0;       // runs of equal rows in index order
};

// Pass 1: finiteness, the pixel of every point and the coordinate range. Each point's row and
// column are kept in key and key2 (mapping twice cost a sixth of the image). False with *error.
bool mapPoints(const std::vector<double>& t, const std::vector<double>& oc, const MappingParams& params, const Feedback* fb,
               SortKeys& sk, MapExtent* ext, std::string* error) {
    const size_t n = t.size();
    uint64_t* rows = sk.key.get();
    uint64_t* cols = sk.key2.get();
    int64_t rMin = 0, rMax = 0, cMin = 0, cMax = 0;
    bool rowsInOrder = true;
    size_t rowRuns = 0;
    for (size_t i = 0; i < n; ++i) {
        if (!std::isfinite(t[i]) || !std::isfinite(oc[i])) {
            *error = "point " + std::to_string(i) + " has a non-finite " + (std::isfinite(t[i]) ? "O-C" : "epoch");
            return false;
        }
        int64_t r = 0, c = 0;
        if (!mapOne(t[i], oc[i], params.magT, params.magOc, &r, &c)) {
            *error = "magnification too large: point " + std::to_string(i) + " maps to a pixel coordinate beyond 2^61 (t*mag_T = " +
                     formatDouble(t[i] * params.magT, 4) + ", O-C*mag_OC = " + formatDouble(oc[i] * params.magOc, 4) + ")";
            return false;
        }
        rows[i] = static_cast<uint64_t>(r);
        cols[i] = static_cast<uint64_t>(c);
        // Without branches where the outcome is the data's (a new row every few points, a
        // noise column anywhere): these mispredicted about once a point.
        if (i == 0) {
            rMin = rMax = r;
            cMin = cMax = c;
            rowRuns = 1;
            continue;
        }
        rowsInOrder &= r >= rMax;
        rowRuns += static_cast<size_t>(r != static_cast<int64_t>(rows[i - 1]));
        rMin = std::min(rMin, r);
        rMax = std::max(rMax, r);
        cMin = std::min(cMin, c);
        cMax = std::max(cMax, c);
        if ((i & 0xFFFFF) == 0xFFFFF && cancelled(fb)) {
            *error = "cancelled";
            return false;
        }
    }
    *ext = MapExtent{rMin, rMax, cMin, cMax, rowsInOrder, rowRuns};
    return true;
}

// How the sorted pixels are keyed: one 64-bit key (row above the column's bits) when both fit.
struct PixelKeys {
    bool oneKey = false;
    int colBits = 0;
    uint64_t colMask = 0;
};

// LSD radix sort of (key, idx) on the low `bits` bits of key, 11 bits a pass, stable (ties keep
// their order). False when cancelled between passes.
bool radixSortKeys(SortKeys& sk, size_t n, int bits, const Feedback* fb) {
    std::unique_ptr<uint64_t[]> tmpKey(new uint64_t[n]);
    std::unique_ptr<uint32_t[]> tmpIdx(new uint32_t[n]);
    std::vector<size_t> count(2049);
    for (int shift = 0; shift < bits; shift += 11) {
        const uint64_t* key = sk.key.get();
        const uint32_t* idx = sk.idx.get();
        std::fill(count.begin(), count.end(), 0);
        for (size_t i = 0; i < n; ++i) ++count[((key[i] >> shift) & 2047) + 1];
        for (size_t d = 1; d < count.size(); ++d) count[d] += count[d - 1];
        for (size_t i = 0; i < n; ++i) {
            const size_t to = count[(key[i] >> shift) & 2047]++;
            tmpKey[to] = key[i];
            tmpIdx[to] = idx[i];
        }
        sk.key.swap(tmpKey);
        sk.idx.swap(tmpIdx);
        if (cancelled(fb)) return false;
    }
    return true;
}

// Pass 2: sort the points by shifted (row, col), ties in index order. Points whose rows never
// decrease, at most 2 to a row on average, are sorted row by row on the column by insertion
// (from 2.5 a row up the radix sort below was faster, 15–20 % of the image at 5–7 a row; the
// limit was 8). Otherwise one 64-bit key, row above the column's bits, when both fit (radix; the
// pixel back by a shift and a mask, not a 64-bit division), else a lexicographic pair compare
// (absurd magnifications: still O(n log n), never an image). False on cancel.
bool sortPoints(SortKeys& sk, size_t n, const MapExtent& ext, const BinaryImage& img, const Feedback* fb, PixelKeys* keys) {
    const int64_t rMin = ext.rMin, cMin = ext.cMin;
    const bool byRow = ext.rowsInOrder && n <= 2 * ext.rowRuns;
    const int colBits = bitsFor(static_cast<uint64_t>(img.cols - 1));
    const bool oneKey = colBits + bitsFor(static_cast<uint64_t>(img.rows - 1)) <= 63;
    const uint64_t colMask = colBits >= 64 ? ~uint64_t{0} : (uint64_t{1} << colBits) - 1;
    uint64_t* key = sk.key.get();
    uint64_t* key2 = sk.key2.get();
    for (size_t i = 0; i < n; ++i) {
        const uint64_t sr = key[i] - static_cast<uint64_t>(rMin), sc = key2[i] - static_cast<uint64_t>(cMin);
        key[i] = oneKey ? (sr << colBits) | sc : sr;
        key2[i] = sc;
    }
    if (oneKey) sk.key2.reset();
    sk.idx.reset(new uint32_t[n]);
    uint32_t* idx = sk.idx.get();
    for (size_t i = 0; i < n; ++i) idx[i] = static_cast<uint32_t>(i);
    if (byRow) {
        // Rows in order: each row's points sorted on (key, key2), ties in index order.
        auto less = [&](uint32_t u, uint32_t v) {
            if (key[u] != key[v]) return key[u] < key[v];
            if (!oneKey && key2[u] != key2[v]) return key2[u] < key2[v];
            return u < v;
        };
        std::vector<uint32_t> perm;
        std::vector<uint64_t> k1, k2;
        for (size_t a = 0; a < n;) {
            const uint64_t row = oneKey ? key[a] >> colBits : key[a];
            size_t b = a + 1;
            while (b < n && (oneKey ? key[b] >> colBits : key[b]) == row) ++b;
            // (idx[i] == i here: the points of [a, b) are still in place)
            perm.resize(b - a);
            for (size_t i = a; i < b; ++i) perm[i - a] = static_cast<uint32_t>(i);
            if (b - a <= 16) {  // insertion sort: stable
                for (size_t i = 1; i < perm.size(); ++i) {
                    const uint32_t x = perm[i];
                    size_t j = i;
                    for (; j > 0 && less(x, perm[j - 1]); --j) perm[j] = perm[j - 1];
                    perm[j] = x;
                }
            } else {
                std::sort(perm.begin(), perm.end(), less);
            }
            k1.resize(perm.size());
            k2.resize(perm.size());
            for (size_t i = 0; i < perm.size(); ++i) {
                k1[i] = key[perm[i]];
                if (!oneKey) k2[i] = key2[perm[i]];
            }
            for (size_t i = 0; i < perm.size(); ++i) {
                key[a + i] = k1[i];
                if (!oneKey) key2[a + i] = k2[i];
                idx[a + i] = perm[i];
            }
            a = b;
        }
    } else if (oneKey) {
        // Stable: ties stay in index order. (A cancellation is seen just below.)
        radixSortKeys(sk, n, bitsFor((static_cast<uint64_t>(img.rows - 1) << colBits) | colMask), fb);
    } else {
        std::sort(idx, idx + n, [&](uint32_t a, uint32_t b) {
            if (key[a] != key[b]) return key[a] < key[b];
            if (key2[a] != key2[b]) return key2[a] < key2[b];
            return a < b;
        });
        std::unique_ptr<uint64_t[]> k1(new uint64_t[n]), k2(new uint64_t[n]);
        for (size_t i = 0; i < n; ++i) {
            k1[i] = key[idx[i]];
            k2[i] = key2[idx[i]];
        }
        sk.key.swap(k1);
        sk.key2.swap(k2);
    }
    *keys = PixelKeys{oneKey, colBits, colMask};
    return !cancelled(fb);
}

// The pixels and the index matrix (CSR): each pixel's row, column and points, each point's pixel.
// Returns the number of pixels.
size_t buildPixels(const SortKeys& sk, size_t n, const PixelKeys& k, BinaryImage& img) {
    const bool oneKey = k.oneKey;
    const int colBits = k.colBits;
    const uint64_t colMask = k.colMask;
    const uint64_t* key = sk.key.get();
    const uint64_t* key2 = sk.key2.get();  // (null with one key)
    const uint32_t* idx = sk.idx.get();
    auto newPixel = [&](size_t i) { return i == 0 || key[i] != key[i - 1] || (!oneKey && key2[i] != key2[i - 1]); };
    img.pixelPoints.resize(n);
    size_t pixels = 0;
    for (size_t i = 0; i < n; ++i) pixels += newPixel(i);
    const bool wide = static_cast<uint64_t>(img.rows - 1) > UINT32_MAX || static_cast<uint64_t>(img.cols - 1) > UINT32_MAX;
    img.pixelRow.reset(pixels, wide);
    img.pixelCol.reset(pixels, wide);
    img.pixelPointStart.reserve(pixels + 1);
    for (size_t i = 0; i < n; ++i) {
        if (newPixel(i)) {
            img.pixelPointStart.push_back(static_cast<uint32_t>(i));
            if (oneKey) {
                img.pixelRow.push_back(static_cast<int64_t>(key[i] >> colBits));
                img.pixelCol.push_back(static_cast<int64_t>(key[i] & colMask));
            } else {
                img.pixelRow.push_back(static_cast<int64_t>(key[i]));
                img.pixelCol.push_back(static_cast<int64_t>(key2[i]));
            }
        }
        img.pixelPoints[i] = idx[i];
    }
    img.pixelPointStart.push_back(static_cast<uint32_t>(n));

    return pixels;
}

}  // namespace

namespace {
// Whether every field of r fits a 32-bit whole region.
bool fits32(const Region& r) {
    auto in = [](int64_t v) { return v >= 0 && v <= int64_t(UINT32_MAX); };
    return in(r.rowMin) && in(r.rowMax) && in(r.colMin) && in(r.colMax) && in(r.area) && in(r.points);
}
}  // namespace

RegionList::RegionList(const std::vector<Region>& regions) {
    bool wide = false;
    for (const Region& r : regions) wide = wide || !fits32(r);
    reserve(regions.size(), regions.size(), wide);
    for (const Region& r : regions) push_back(r);
}

// The list's coordinates and whole regions made 64-bit (a region given that a 32-bit one cannot hold).
void RegionList::widen() {
    if (m_row.wide()) return;
    const size_t n = size();
    PixelCoords rows, cols;
    rows.reset(n, true);
    cols.reset(n, true);
    for (size_t i = 0; i < n; ++i) {
        rows.push_back(m_row[i]);
        cols.push_back(m_col[i]);
    }
    std::vector<Region> whole;
    whole.reserve(m_whole32.size());
    std::vector<uint32_t> slot(m_slot);
    for (size_t i = 0; i < n; ++i)
        if (m_slot[i] != kPixel) {
            slot[i] = static_cast<uint32_t>(whole.size());
            whole.push_back((*this)[i]);
        }
    m_slot = std::move(slot);
    m_row = std::move(rows);
    m_col = std::move(cols);
    std::vector<Whole32>().swap(m_whole32);
    m_whole64 = std::move(whole);
}

Region RegionList::operator[](size_t i) const {
    const uint32_t s = m_slot[i];
    Region r;
    if (s == kPixel) {
        r.area = 1;
        r.points = m_points[i];
        r.rowMin = r.rowMax = m_row[i];
        r.colMin = r.colMax = m_col[i];
        r.row = static_cast<double>(r.rowMin);
        r.col = static_cast<double>(r.colMin);
    } else if (m_row.wide()) {
        r = m_whole64[s];
    } else {
        const Whole32& w = m_whole32[s];
        r.area = w.area, r.points = w.points, r.row = w.row, r.col = w.col;
        r.rowMin = w.rowMin, r.rowMax = w.rowMax, r.colMin = w.colMin, r.colMax = w.colMax;
    }
    return r;
}

int64_t RegionList::area(size_t i) const {
    const uint32_t s = m_slot[i];
    return s == kPixel ? 1 : m_row.wide() ? m_whole64[s].area : static_cast<int64_t>(m_whole32[s].area);
}

int64_t RegionList::rowMin(size_t i) const {
    const uint32_t s = m_slot[i];
    return s == kPixel ? m_row[i] : m_row.wide() ? m_whole64[s].rowMin : static_cast<int64_t>(m_whole32[s].rowMin);
}

void RegionList::reserve(size_t n, size_t whole, bool wide) {
    m_slot.reserve(n);
    m_row.reset(n, wide);
    m_col.reset(n, wide);
    m_points.reserve(n);
    if (wide) m_whole64.reserve(whole);
    else m_whole32.reserve(whole);
}

// Region i (its pixel entries already pushed) becomes the whole region r.
void RegionList::makeWhole(size_t i, const Region& r) {
    if (m_row.wide()) {
        m_slot[i] = static_cast<uint32_t>(m_whole64.size());
        m_whole64.push_back(r);
        return;
    }
    m_slot[i] = static_cast<uint32_t>(m_whole32.size());
    Whole32& w = m_whole32.emplace_back();
    w.row = r.row, w.col = r.col;
    w.area = static_cast<uint32_t>(r.area), w.points = static_cast<uint32_t>(r.points);
    w.rowMin = static_cast<uint32_t>(r.rowMin), w.rowMax = static_cast<uint32_t>(r.rowMax);
    w.colMin = static_cast<uint32_t>(r.colMin), w.colMax = static_cast<uint32_t>(r.colMax);
}

void RegionList::addPixel(int64_t row, int64_t col, int64_t points) {
    m_row.push_back(row);
    m_col.push_back(col);
    m_points.push_back(static_cast<uint8_t>(points <= 255 ? points : 0));
    m_slot.push_back(kPixel);
    if (points > 255) {
        Region r;
        r.area = 1;
        r.points = points;
        r.rowMin = r.rowMax = row;
        r.colMin = r.colMax = col;
        r.row = static_cast<double>(row);
        r.col = static_cast<double>(col);
        makeWhole(m_slot.size() - 1, r);
    }
}

void RegionList::addToRegion(size_t i, int64_t row, int64_t col, int64_t points) {
    if (m_slot[i] == kPixel) makeWhole(i, (*this)[i]);
    const uint32_t s = m_slot[i];
    if (m_row.wide()) {
        Region& r = m_whole64[s];
        r.area += 1;
        r.points += points;
        r.row += static_cast<double>(row);
        r.col += static_cast<double>(col);
        r.rowMax = std::max(r.rowMax, row);
        r.colMin = std::min(r.colMin, col);
        r.colMax = std::max(r.colMax, col);
        return;
    }
    Whole32& w = m_whole32[s];
    w.area += 1;
    w.points += static_cast<uint32_t>(points);
    w.row += static_cast<double>(row);
    w.col += static_cast<double>(col);
    w.rowMax = std::max(w.rowMax, static_cast<uint32_t>(row));
    w.colMin = std::min(w.colMin, static_cast<uint32_t>(col));
    w.colMax = std::max(w.colMax, static_cast<uint32_t>(col));
}

void RegionList::finish() {
    for (Region& r : m_whole64) {
        r.row /= static_cast<double>(r.area);
        r.col /= static_cast<double>(r.area);
    }
    for (Whole32& w : m_whole32) {
        w.row /= static_cast<double>(w.area);
        w.col /= static_cast<double>(w.area);
    }
}

void RegionList::push_back(const Region& r) {
    if (!fits32(r)) widen();
    // (a centroid of −0.0 is kept whole: from its pixel it would come back as +0.0)
    const bool onePixel = r.area == 1 && r.points <= 255 && r.points >= 0 && r.rowMin == r.rowMax && r.colMin == r.colMax &&
                          r.row == static_cast<double>(r.rowMin) && r.col == static_cast<double>(r.colMin) &&
                          !std::signbit(r.row) && !std::signbit(r.col);
    if (onePixel) {
        addPixel(r.rowMin, r.colMin, r.points);
        return;
    }
    m_row.push_back(0);
    m_col.push_back(0);
    m_points.push_back(0);
    m_slot.push_back(kPixel);
    makeWhole(m_slot.size() - 1, r);
}

namespace {

// Compact labels in order of each region's first pixel; per-region statistics. A root is the
// smallest pixel of its region (union by smaller index), so a pixel that is its own root starts
// a region and any other takes its root's label, given earlier. Every parent is a smaller pixel,
// so going up in pixel order the parent of each pixel before p already holds its root: one
// look-up finds p's. The centroid sums build up in row and col (divided by the area at the end).
void labelRegions(UnionFind& uf, size_t pixels, BinaryImage& img) {
    img.pixelRegion.assign(pixels, 0);
    uint32_t* parent = uf.parent.data();
    // Every pixel's root (its parent's is known by then), and which roots have other pixels
    // (flagged in pixelRegion, written with the labels below): the regions' storage sized once.
    size_t roots = 0, whole = 0;
    for (size_t p = 0; p < pixels; ++p) {
        uint32_t root = parent[p];
        if (root == p) {
            ++roots;
            continue;
        }
        root = parent[p] = parent[root];
        whole += img.pixelRegion[root] == 0;
        img.pixelRegion[root] = 1;
    }
    img.regions.reserve(roots, whole, img.pixelRow.wide());
    for (size_t p = 0; p < pixels; ++p) {
        const int64_t r = img.pixelRow[p], c = img.pixelCol[p];
        const int64_t pts = img.pixelPointStart[p + 1] - img.pixelPointStart[p];
        const uint32_t root = parent[p];
        if (root == p) {
            img.pixelRegion[p] = static_cast<uint32_t>(img.regions.size());
            img.regions.addPixel(r, c, pts);
            continue;
        }
        const uint32_t lab = img.pixelRegion[root];
        img.pixelRegion[p] = lab;
        img.regions.addToRegion(lab, r, c, pts);
    }
    img.regions.finish();
}

}  // namespace

std::vector<uint32_t> pointPixels(const BinaryImage& img) {
    std::vector<uint32_t> out(img.pixelPoints.size());
    for (size_t p = 0; p + 1 < img.pixelPointStart.size(); ++p)
        for (uint32_t k = img.pixelPointStart[p]; k < img.pixelPointStart[p + 1]; ++k) out[img.pixelPoints[k]] = static_cast<uint32_t>(p);
    return out;
}

BinaryImage buildBinaryImage(const std::vector<double>& t, const std::vector<double>& oc, const MappingParams& params,
                             const Feedback* fb) {
    BinaryImage img;
    img.params = params;
    if (const std::string e = validate(params); !e.empty()) {
        img.error = e;
        return img;
    }
    if (t.size() != oc.size()) {
        img.error = "epochs and O-C differ in length (" + std::to_string(t.size()) + " vs " + std::to_string(oc.size()) + ")";
        return img;
    }
    const size_t n = t.size();
    if (n > kMaxPoints) {
        img.error = "too many points (" + std::to_string(n) + "); at most 4294967294";
        return img;
    }
    if (n == 0) {
        img.ok = true;
        img.pixelPointStart.push_back(0);
        return img;
    }
    // Not value-initialised (every element is written by the mapping): zeroing them cost as much
    // as the mapping on the many small images of a scale search.
    SortKeys sk;
    sk.key.reset(new uint64_t[n]);
    sk.key2.reset(new uint64_t[n]);
    MapExtent ext;
    if (!mapPoints(t, oc, params, fb, sk, &ext, &img.error)) return img;
    img.rowOffset = ext.rMin;
    img.colOffset = ext.cMin;
    img.rows = ext.rMax - ext.rMin + 1;
    img.cols = ext.cMax - ext.cMin + 1;
    PixelKeys keys;
    if (!sortPoints(sk, n, ext, img, fb, &keys)) {
        img.error = "cancelled";
        return img;
    }
    const size_t pixels = buildPixels(sk, n, keys, img);
    sk = SortKeys();
    UnionFind uf(pixels);
    const bool linked = img.pixelRow.wide()
                            ? linkPixels(img.pixelRow.wideData(), img.pixelCol.wideData(), pixels, params.connectivity == 8, uf, fb)
                            : linkPixels(img.pixelRow.narrowData(), img.pixelCol.narrowData(), pixels, params.connectivity == 8, uf, fb);
    if (!linked) {
        img.error = "cancelled";
        return img;
    }
    labelRegions(uf, pixels, img);
    img.ok = true;
    return img;
}

std::vector<int64_t> regionAreas(const std::vector<double>& t, const std::vector<double>& oc, const MappingParams& params) {
    std::vector<int64_t> areas;
    const size_t n = std::min(t.size(), oc.size());
    if (!validate(params).empty() || n == 0 || n > kMaxPoints) return areas;
    // Not value-initialised: every element is written by the mapping.
    std::unique_ptr<int64_t[]> rows(new int64_t[n]), cols(new int64_t[n]);
    bool rowsInOrder = true;
    size_t rowRuns = 0;
    int64_t cMin = 0, cMax = 0;
    for (size_t i = 0; i < n; ++i) {
        if (!mapOne(t[i], oc[i], params.magT, params.magOc, &rows[i], &cols[i])) return areas;
        rowsInOrder = rowsInOrder && (i == 0 || rows[i] >= rows[i - 1]);
        rowRuns += i == 0 || rows[i] != rows[i - 1];
        cMin = i == 0 ? cols[i] : std::min(cMin, cols[i]);
        cMax = i == 0 ? cols[i] : std::max(cMax, cols[i]);
    }
    // The distinct pixels in (row, col) order. Points in time order (the usual case) are in row
    // order already: only each row's columns are sorted (by insertion when a row holds few).
    // Rows of more than 2 points on average are sorted all at once instead, by a radix sort of
    // one 8-byte key per point: row by row (std::sort past 16 points) was a sixth of a sparse
    // pass with many points; the null model is 20–45 % faster this way from 2.5 points a row up.
    size_t pixels = 0;
    const int colBits = bitsFor(static_cast<uint64_t>(cMax - cMin));
    if (rowsInOrder && n > 2 * rowRuns && colBits + bitsFor(static_cast<uint64_t>(rows[n - 1] - rows[0])) <= 63) {
        const uint64_t colMask = (uint64_t{1} << colBits) - 1;
        std::unique_ptr<uint64_t[]> key(new uint64_t[n]);
        for (size_t i = 0; i < n; ++i)
            key[i] = (static_cast<uint64_t>(rows[i] - rows[0]) << colBits) | static_cast<uint64_t>(cols[i] - cMin);
        radixSort(key, n, bitsFor((static_cast<uint64_t>(rows[n - 1] - rows[0]) << colBits) | colMask),
                  [](uint64_t x) { return x; }, nullptr);
        const int64_t row0 = rows[0];
        for (size_t i = 0; i < n; ++i)
            if (i == 0 || key[i] != key[i - 1]) {
                rows[pixels] = row0 + static_cast<int64_t>(key[i] >> colBits);
                cols[pixels++] = cMin + static_cast<int64_t>(key[i] & colMask);
            }
    } else if (rowsInOrder) {
        for (size_t a = 0; a < n;) {
            size_t b = a + 1;
            while (b < n && rows[b] == rows[a]) ++b;
            if (b - a <= 16) {
                for (size_t i = a + 1; i < b; ++i) {
                    const int64_t x = cols[i];
                    size_t j = i;
                    for (; j > a && cols[j - 1] > x; --j) cols[j] = cols[j - 1];
                    cols[j] = x;
                }
            } else {
                std::sort(cols.get() + a, cols.get() + b);
            }
            for (size_t i = a; i < b; ++i)
                if (i == a || cols[i] != cols[i - 1]) {
                    rows[pixels] = rows[a];
                    cols[pixels++] = cols[i];
                }
            a = b;
        }
    } else {
        std::vector<std::pair<int64_t, int64_t>> px(n);
        for (size_t i = 0; i < n; ++i) px[i] = {rows[i], cols[i]};
        std::sort(px.begin(), px.end());
        px.erase(std::unique(px.begin(), px.end()), px.end());
        pixels = px.size();
        for (size_t i = 0; i < pixels; ++i) std::tie(rows[i], cols[i]) = px[i];
    }
    UnionFind uf(pixels);
    linkPixels(rows.get(), cols.get(), pixels, params.connectivity == 8, uf, nullptr);
    std::vector<uint32_t> slot(pixels);  // a root's area slot (a root is its region's first pixel)
    uint32_t* parent = uf.parent.data();
    for (size_t p = 0; p < pixels; ++p) {
        // Parents are smaller pixels, resolved to their roots before p (as in buildBinaryImage).
        uint32_t root = parent[p];
        if (root != p) root = parent[p] = parent[root];
        if (root == p) {
            slot[p] = static_cast<uint32_t>(areas.size());
            areas.push_back(1);
        } else {
            ++areas[slot[root]];
        }
    }
    return areas;
}

}  // namespace lwb::core::slr
