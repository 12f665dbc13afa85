#include "core/slr/screen.hpp"

#include "core/slr/slr_params.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <future>
#include <memory>
#include <thread>
#include <tuple>

#include "core/common/allocator.hpp"
#include "core/common/select.hpp"
#include "core/common/text.hpp"
#include "core/common/rng.hpp"
#include "core/slr/kdtree2.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/screen_auto.hpp"
#include "core/slr/screen_follow.hpp"

namespace lwb::core::slr {

namespace {
using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// Line angle of the segment (Δrow, Δcol) in degrees, folded to (−90, 90].
double lineAngleDeg(double dRow, double dCol) {
    double a = std::atan2(dCol, dRow) * (180.0 / M_PI);
    if (a > 90) a -= 180;
    if (a <= -90) a += 180;
    return a;
}
}  // namespace

const char* pointClassName(PointClass c) {
    switch (c) {
        case PointClass::Noise: return "noise";
        case PointClass::Signal: return "signal";
        case PointClass::Recovered: return "recovered";
        case PointClass::Band: return "band";
    }
    return "?";
}

std::string validate(const ScreenParams& p) {
    SlrParams sp;
    sp.screen = p;
    return slrSchema().validate(sp, "screen.");
}

std::vector<uint32_t> splitByArea(const RegionList& regions, int64_t areaLimit) {
    std::vector<uint32_t> out;
    for (size_t i = 0; i < regions.size(); ++i)
        if (regions.area(i) >= areaLimit) out.push_back(static_cast<uint32_t>(i));
    return out;
}

int automaticAreaLimit(const std::vector<double>& t, const std::vector<double>& oc, const MappingParams& mapping,
                       double tolerance, size_t maxPoints) {
    const size_t n = std::min(t.size(), oc.size());
    if (n == 0) return 2;
    // The points of a central time window (all of them when few): same density per pixel.
    double tLo = -1e308, tHi = 1e308;
    if (n > maxPoints) {
        std::vector<double> ts(t.begin(), t.begin() + static_cast<long>(n));
        const size_t a = (n - maxPoints) / 2, b = a + maxPoints - 1;
        std::nth_element(ts.begin(), ts.begin() + static_cast<long>(a), ts.end());
        tLo = ts[a];
        std::nth_element(ts.begin(), ts.begin() + static_cast<long>(b), ts.end());
        tHi = ts[b];
    }
    std::vector<double> window, no;  // the window's epochs (all of them: t itself, not copied)
    double oLo = 1e308, oHi = -1e308;
    if (n <= maxPoints) {
        std::tie(oLo, oHi) = minMaxOf(oc.data(), n);
    } else {
        window.reserve(maxPoints);
        for (size_t i = 0; i < n; ++i)
            if (t[i] >= tLo && t[i] <= tHi) {
                window.push_back(t[i]);
                oLo = std::min(oLo, oc[i]);
                oHi = std::max(oHi, oc[i]);
            }
    }
    const std::vector<double>& nt = n <= maxPoints ? t : window;
    const size_t m = n <= maxPoints ? n : window.size();
    // Null model: the same epochs with O-C uniform over the span (a fixed seed: deterministic).
    // The seed depends on m only, so the uniform draws of the last m are kept for the next call
    // (every trial of a scale search draws them again for the same window).
    thread_local std::vector<double> uniforms;
    thread_local size_t uniformsFor = 0;
    if (uniformsFor != m || uniforms.size() != m) {
        Rng rng(0x6e756c6cULL ^ static_cast<uint64_t>(m));
        uniforms.resize(m);
        for (double& u : uniforms) u = rng.uniform();
        uniformsFor = m;
    }
    no.resize(m);
    for (size_t i = 0; i < m; ++i) no[i] = oLo + (oHi - oLo) * uniforms[i];
    const std::vector<int64_t> areas = regionAreas(nt, no, mapping);
    if (areas.empty()) return 2;
    std::vector<size_t> atLeast(66, 0);  // atLeast[a] = regions with area ≥ a (a ≤ 65)
    // Most noise regions are single pixels: counted in a register, not by incrementing one
    // memory cell ten thousand times in a row (each increment waited for the one before).
    size_t single = 0;
    for (int64_t area : areas) {
        if (area == 1) ++single;
        else ++atLeast[static_cast<size_t>(std::min<int64_t>(area, 65))];
    }
    atLeast[1] += single;
    for (size_t a = 64; a >= 1; --a) atLeast[a] += atLeast[a + 1];
    const double allowed = std::max(1.0, tolerance * static_cast<double>(areas.size()));
    for (size_t a = 2; a <= 64; ++a)
        if (static_cast<double>(atLeast[a]) <= allowed) return static_cast<int>(a);
    return 64;
}

namespace {

// A block's range of line angles: the peak bin of its smoothed histogram, grown towards the
// heavier side one bin at a time while the bins hold at least `fraction` of the peak (at most
// maxWidth bins), then one bin of margin on each side. inRange marks its bins.
struct SlopeRange {
    size_t left = 0, right = 0, width = 1;
};

SlopeRange slopeRangeOf(const std::vector<double>& smooth, size_t maxWidth, double fraction, std::vector<uint8_t>& inRange) {
    const size_t nb = smooth.size();
    size_t peak = 0;
    for (size_t q = 1; q < nb; ++q)
        if (smooth[q] > smooth[peak]) peak = q;
    std::fill(inRange.begin(), inRange.end(), 0);
    inRange[peak] = 1;
    const double floorW = fraction * smooth[peak];
    size_t left = peak, right = peak, width = 1;
    // Grow towards the heavier side first, one bin at a time, while the bins hold weight.
    while (width < maxWidth) {
        const size_t l = (left + nb - 1) % nb, r = (right + 1) % nb;
        const bool okL = !inRange[l] && smooth[l] >= floorW, okR = !inRange[r] && smooth[r] >= floorW;
        if (!okL && !okR) break;
        if (okL && (!okR || smooth[l] >= smooth[r])) {
            left = l;
            inRange[l] = 1;
        } else {
            right = r;
            inRange[r] = 1;
        }
        ++width;
    }
    // One bin of margin on each side.
    for (size_t* e : {&left, &right}) {
        const size_t q = e == &left ? (left + nb - 1) % nb : (right + 1) % nb;
        if (width < nb && !inRange[q]) {
            *e = q;
            inRange[q] = 1;
            ++width;
        }
    }
    return SlopeRange{left, right, width};
}

}  // namespace

LinearityResult findLinearRegions(const RegionList& regions, const std::vector<uint32_t>& candidates,
                                  const std::vector<Anchor>& piecesIn, const ScreenParams& p, const Feedback* fb) {
    LinearityResult res;
    if (candidates.empty()) return res;
    // The points of the slope analysis: the given pieces, or the candidates' centroids.
    std::vector<Anchor> pieces;
    if (piecesIn.empty()) {
        for (uint32_t c : candidates) {
            const Region r = regions[c];
            pieces.push_back({r.row, r.col, static_cast<double>(r.area), c});
        }
    } else {
        pieces = piecesIn;
    }
    const size_t np = pieces.size();
    if (np <= 2) {
        res.onLine = candidates;
        std::sort(res.onLine.begin(), res.onLine.end());
        res.warnings.push_back(std::to_string(candidates.size()) +
                               " candidate region(s) in " + std::to_string(np) + " piece(s) only: taken as the line without a slope test");
        return res;
    }
    // Pieces in time order (row), ties by input order.
    std::vector<uint32_t> order(np);
    for (size_t i = 0; i < np; ++i) order[i] = static_cast<uint32_t>(i);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return pieces[a].row < pieces[b].row; });
    std::vector<double> xs(np), ys(np);
    for (size_t i = 0; i < np; ++i) {
        xs[i] = pieces[order[i]].row;
        ys[i] = pieces[order[i]].col;
    }
    const detail::KdTree2 tree(xs, ys);
    const size_t k = std::min<size_t>(static_cast<size_t>(p.slopeNeighbours), np - 1);
    std::vector<float> angle(np * k), weight(np * k);
    std::vector<uint8_t> count(np);
    std::vector<uint32_t> nIdx(k);
    std::vector<double> nD2(k);
    for (size_t i = 0; i < np; ++i) {
        const size_t got = tree.nearest(xs[i], ys[i], k, static_cast<uint32_t>(i), nIdx.data(), nD2.data());
        count[i] = static_cast<uint8_t>(got);
        const double wi = pieces[order[i]].weight;
        for (size_t j = 0; j < got; ++j) {
            const uint32_t m = nIdx[j];
            angle[i * k + j] = static_cast<float>(lineAngleDeg(xs[m] - xs[i], ys[m] - ys[i]));
            weight[i * k + j] = static_cast<float>(std::min(wi, pieces[order[m]].weight) / std::max(1.0, std::sqrt(nD2[j])));
        }
        if ((i & 0xFFFF) == 0xFFFF && cancelled(fb)) return res;
    }
    // Time blocks, each with its own histogram of line angles.
    const size_t nb = std::max<size_t>(2, static_cast<size_t>(std::lround(180.0 / p.slopeBinDeg)));
    const double binDeg = 180.0 / static_cast<double>(nb);
    const size_t maxWidth = std::clamp<size_t>(static_cast<size_t>(std::lround(p.maxSlopeRangeDeg / binDeg)), 1, nb);
    auto binOf = [&](double a) {
        long b = static_cast<long>(std::floor((a + 90.0) / binDeg));
        b %= static_cast<long>(nb);
        if (b < 0) b += static_cast<long>(nb);
        return static_cast<size_t>(b);
    };
    const size_t blockSize = p.slopeBlockRegions > 0 ? static_cast<size_t>(p.slopeBlockRegions) : np;
    const size_t blocks = std::max<size_t>(1, np / blockSize);
    std::vector<double> hist(nb), smooth(nb);
    std::vector<uint8_t> inRange(nb);
    // Per candidate region: weight in range and in all (indexed by region id through a map).
    std::vector<uint32_t> slot(regions.size(), UINT32_MAX);
    for (size_t c = 0; c < candidates.size(); ++c) slot[candidates[c]] = static_cast<uint32_t>(c);
    std::vector<double> wIn(candidates.size(), 0.0), wAll(candidates.size(), 0.0);
    double widest = -1;
    for (size_t b = 0; b < blocks; ++b) {
        const size_t lo = b * np / blocks, hi = (b + 1) * np / blocks;
        std::fill(hist.begin(), hist.end(), 0.0);
        for (size_t i = lo; i < hi; ++i)
            for (size_t j = 0; j < count[i]; ++j) hist[binOf(angle[i * k + j])] += weight[i * k + j];
        for (size_t q = 0; q < nb; ++q)
            smooth[q] = 0.25 * hist[(q + nb - 1) % nb] + 0.5 * hist[q] + 0.25 * hist[(q + 1) % nb];
        const SlopeRange sr = slopeRangeOf(smooth, maxWidth, p.slopePeakFraction, inRange);
        const size_t left = sr.left, right = sr.right, width = sr.width;
        if (static_cast<double>(width) > widest) {
            widest = static_cast<double>(width);
            res.loDeg = -90.0 + static_cast<double>(left) * binDeg;
            res.hiDeg = -90.0 + static_cast<double>(right + 1) * binDeg;
            if (res.hiDeg > 90) res.hiDeg -= 180;
        }
        for (size_t i = lo; i < hi; ++i) {
            const uint32_t s = slot[pieces[order[i]].region];
            if (s == UINT32_MAX) continue;
            for (size_t j = 0; j < count[i]; ++j) {
                const double w = weight[i * k + j];
                wAll[s] += w;
                if (inRange[binOf(angle[i * k + j])]) wIn[s] += w;
            }
        }
    }
    for (size_t c = 0; c < candidates.size(); ++c) {
        const bool on = wAll[c] > 0 && wIn[c] >= p.slopeAgreeFraction * wAll[c] * (1 - 1e-12);
        (on ? res.onLine : res.offLine).push_back(candidates[c]);
    }
    std::sort(res.onLine.begin(), res.onLine.end());
    std::sort(res.offLine.begin(), res.offLine.end());
    return res;
}

std::vector<Anchor> regionPieces(const BinaryImage& img, const std::vector<uint8_t>& selected, int pieceRows) {
    std::vector<Anchor> out;
    if (pieceRows <= 0) {
        for (size_t r = 0; r < img.regions.size(); ++r)
            if (selected[r]) {
                const Region reg = img.regions[r];
                out.push_back({reg.row, reg.col, static_cast<double>(reg.area), static_cast<uint32_t>(r)});
            }
        return out;
    }
    // Pixels are in (row, col) order, so each region's pieces come in increasing order: one
    // current piece per region is enough.
    // Only the selected regions' entries are ever read: only they are initialised (the
    // candidates or the signal, a few of the many regions of a sparse image).
    const size_t regions = img.regions.size();
    std::unique_ptr<int64_t[]> curPiece(new int64_t[regions]);
    std::unique_ptr<uint32_t[]> curAnchor(new uint32_t[regions]);
    for (size_t r = 0; r < regions; ++r)
        if (selected[r]) curPiece[r] = -1;
    std::vector<double> sumR, sumC;
    for (size_t p = 0; p < img.pixelCount(); ++p) {
        const uint32_t reg = img.pixelRegion[p];
        if (!selected[reg]) continue;
        const int64_t piece = (img.pixelRow[p] - img.regions.rowMin(reg)) / pieceRows;
        if (piece != curPiece[reg]) {
            curPiece[reg] = piece;
            curAnchor[reg] = static_cast<uint32_t>(out.size());
            out.push_back({0, 0, 0, reg});
            sumR.push_back(0);
            sumC.push_back(0);
        }
        const uint32_t a = curAnchor[reg];
        sumR[a] += static_cast<double>(img.pixelRow[p]);
        sumC[a] += static_cast<double>(img.pixelCol[p]);
        out[a].weight += 1;
    }
    for (size_t a = 0; a < out.size(); ++a) {
        out[a].row = sumR[a] / out[a].weight;
        out[a].col = sumC[a] / out[a].weight;
    }
    return out;
}

bool collinearAccept(double pRow, double pCol, double xRow, double xCol, double qRow, double qCol, double C) {
    // Lengths as sqrt(x² + y²), not std::hypot (a library call guarding against overflow that
    // pixel coordinates cannot reach; a sixtieth of a sparse pass's screening).
    auto norm = [](double x, double y) { return std::sqrt(x * x + y * y); };
    const double ux = pRow - xRow, uy = pCol - xCol, vx = qRow - xRow, vy = qCol - xCol;
    const double nu = norm(ux, uy), nv = norm(vx, vy);
    const double eps = 1e-12;
    if (nu < eps) return true;   // X on the nearest anchor
    if (nv < eps) return false;  // cannot happen with P nearest, unless P = Q = X
    const double cosX = (ux * vx + uy * vy) / (nu * nv);
    if (cosX < -C) return true;  // X between P and Q, on their line (paper case a)
    if (cosX <= C) return false;
    // Same side (paper case b): P, the nearer, must lie between X and Q, and X be at most one
    // step |PQ| beyond P.
    const double wx = xRow - pRow, wy = xCol - pCol, zx = qRow - pRow, zy = qCol - pCol;
    const double nw = norm(wx, wy), nz = norm(zx, zy);
    if (nz < eps || nw > nz) return false;
    const double cosP = (wx * zx + wy * zy) / (nw * nz);
    return cosP < -C;
}

namespace {
// Anchors binned by row into bands at least `radius` tall, with the columns each band and its
// two neighbours span. farFromAll(row, col): no anchor lies within `radius` of (row, col) —
// decided with a margin, so it is never true of a point the exact distance would keep.
// A radius of 0 or a non-finite one: never far.
class RowBands {
public:
    RowBands(const std::vector<Anchor>& anchors, double radius) {
        if (!(radius > 0) || !std::isfinite(radius) || anchors.empty()) return;
        double lo = anchors.front().row, hi = lo;
        for (const Anchor& a : anchors) {
            lo = std::min(lo, a.row);
            hi = std::max(hi, a.row);
        }
        const double span = hi - lo;
        if (!std::isfinite(span)) return;
        m_radius = radius * (1 + 1e-9) + 1e-9;
        m_height = std::max(m_radius, span / 65536);  // at most ~65536 bands
        m_row0 = lo;
        const size_t bands = static_cast<size_t>(span / m_height) + 1;
        std::vector<double> cMin(bands, INFINITY), cMax(bands, -INFINITY);
        for (const Anchor& a : anchors) {
            const size_t b = std::min(bands - 1, static_cast<size_t>((a.row - lo) / m_height));
            cMin[b] = std::min(cMin[b], a.col);
            cMax[b] = std::max(cMax[b], a.col);
        }
        m_lo.assign(bands, INFINITY);
        m_hi.assign(bands, -INFINITY);
        for (size_t b = 0; b < bands; ++b)
            for (size_t k = b > 0 ? b - 1 : 0; k <= std::min(bands - 1, b + 1); ++k) {
                m_lo[b] = std::min(m_lo[b], cMin[k]);
                m_hi[b] = std::max(m_hi[b], cMax[k]);
            }
    }
    bool farFromAll(double row, double col) const {
        if (m_lo.empty() || !std::isfinite(row) || !std::isfinite(col)) return false;
        const double f = std::floor((row - m_row0) / m_height);
        const double last = static_cast<double>(m_lo.size() - 1);
        // Rows more than one band from the anchors' are more than the radius away; within one
        // band beyond the ends, the end band's neighbourhood covers them.
        if (f < -1 || f > last + 1) return true;
        const size_t b = static_cast<size_t>(std::clamp(f, 0.0, last));
        return col < m_lo[b] - m_radius || col > m_hi[b] + m_radius;
    }

private:
    double m_radius = 0, m_height = 1, m_row0 = 0;
    std::vector<double> m_lo, m_hi;
};
}  // namespace

RecoveryResult recoverPending(const RegionList& regions, const std::vector<uint32_t>& pending,
                              const std::vector<Anchor>& anchors, double cosineC, double gapFactor, const Feedback* fb) {
    RecoveryResult res;
    if (anchors.size() < 2 || pending.empty()) return res;
    std::vector<double> xs(anchors.size()), ys(anchors.size());
    for (size_t i = 0; i < anchors.size(); ++i) {
        xs[i] = anchors[i].row;
        ys[i] = anchors[i].col;
    }
    const detail::KdTree2 tree(std::move(xs), std::move(ys));
    uint32_t idx[2];
    double d2[2];
    double maxPair2 = 1e308;
    if (gapFactor > 0) {
        std::vector<double> nn;
        nn.reserve(anchors.size());
        for (size_t i = 0; i < anchors.size(); ++i)
            if (tree.nearest(anchors[i].row, anchors[i].col, 1, static_cast<uint32_t>(i), idx, d2) == 1) nn.push_back(d2[0]);
        std::nth_element(nn.begin(), nn.begin() + static_cast<long>(nn.size() / 2), nn.end());
        const double typical = std::sqrt(nn[nn.size() / 2]);
        res.maxPairDistance = gapFactor * std::max(typical, 1.0);
        maxPair2 = res.maxPairDistance * res.maxPairDistance;
    }
    // Acceptance needs |XP| ≤ |PQ| ≤ gap limit (or X between P and Q), so |XQ| ≤ 2·limit:
    // the search radius prunes the far-away pending regions, which are most of them. Before the
    // tree, bands of rows (at least 2·limit tall) hold the columns their anchors span: a pending
    // region whose column lies beyond 2·limit of every anchor in its band and the two beside it
    // has no anchor within 2·limit, and is passed over at once (the noise of a sparse pass in
    // a wide gate, far from its track). The test only skips what the search would not find.
    const RowBands bands(anchors, gapFactor > 0 ? 2 * res.maxPairDistance : 0);
    for (size_t i = 0; i < pending.size(); ++i) {
        const Region r = regions[pending[i]];
        if (bands.farFromAll(r.row, r.col)) continue;
        if (tree.nearest(r.row, r.col, 2, UINT32_MAX, idx, d2, 4 * maxPair2) < 2) continue;
        const Anchor& P = anchors[idx[0]];
        const Anchor& Q = anchors[idx[1]];
        const double pq2 = (P.row - Q.row) * (P.row - Q.row) + (P.col - Q.col) * (P.col - Q.col);
        if (pq2 > maxPair2) continue;
        if (collinearAccept(P.row, P.col, r.row, r.col, Q.row, Q.col, cosineC)) res.recovered.push_back(pending[i]);
        if ((i & 0xFFFF) == 0xFFFF && cancelled(fb)) break;
    }
    std::sort(res.recovered.begin(), res.recovered.end());
    return res;
}

namespace {
// Steps 1–6 at a fixed scale (areaLimit 0 = automaticAreaLimit).
void runFixed(const std::vector<double>& t, const std::vector<double>& oc, const ScreenParams& p, Feedback* fb,
              ScreenResult& res) {
    auto t0 = Clock::now();
    MappingParams mp;
    mp.magT = res.magT;
    mp.magOc = res.magOc;
    mp.connectivity = res.connectivity;
    // Step 3's null model reads only the input: on a long pass it is built beside the image (at
    // 10⁵ points a third of this function; the scale search's windows, at most autoMaxPoints
    // points and already side by side on the cores, are not split further).
    constexpr size_t kNullAside = 50000;
    std::future<int> nullLimit;
    if (p.areaLimit <= 0 && t.size() >= kNullAside && std::thread::hardware_concurrency() > 1)
        nullLimit = std::async(std::launch::async,
                               [&t, &oc, mp, tol = p.areaTolerance] {
                                   adviseThreadHeap();
                                   return automaticAreaLimit(t, oc, mp, tol, 200000);
                               });
    BinaryImage img = buildBinaryImage(t, oc, mp, fb);
    if (!img.ok) {
        res.error = img.error;
        return;  // (the future's destructor waits for the null model)
    }
    for (const auto& w : img.warnings) res.warnings.push_back(w);
    res.mapMs = msSince(t0);
    if (fb) fb->setProgress(0.6);
    // Step 3.
    res.areaLimit = p.areaLimit > 0       ? p.areaLimit
                    : nullLimit.valid() ? nullLimit.get()
                                        : automaticAreaLimit(t, oc, mp, p.areaTolerance, 200000);
    const std::vector<uint32_t> cand = splitByArea(img.regions, res.areaLimit);
    res.candidates = cand.size();
    // Step 4.
    t0 = Clock::now();
    std::vector<uint8_t> isCand(img.regions.size(), 0);
    for (uint32_t r : cand) isCand[r] = 1;
    LinearityResult lin = findLinearRegions(img.regions, cand, regionPieces(img, isCand, p.pieceRows), p, fb);
    if (cancelled(fb)) {
        res.error = "cancelled";
        return;
    }
    for (const auto& w : lin.warnings) res.warnings.push_back(w);
    res.slopeLoDeg = lin.loDeg;
    res.slopeHiDeg = lin.hiDeg;
    res.linearityMs = msSince(t0);
    if (fb) fb->setProgress(0.7);
    // Step 5.
    t0 = Clock::now();
    std::vector<uint8_t> isSignal(img.regions.size(), 0);
    for (uint32_t r : lin.onLine) isSignal[r] = 1;
    std::vector<uint32_t> pending;
    pending.reserve(img.regions.size() - lin.onLine.size());
    for (size_t r = 0; r < img.regions.size(); ++r)
        if (!isSignal[r]) pending.push_back(static_cast<uint32_t>(r));
    const std::vector<Anchor> anchors = regionPieces(img, isSignal, p.pieceRows);
    const RecoveryResult rec = recoverPending(img.regions, pending, anchors, p.cosineC, p.recoveryGapFactor, fb);
    if (cancelled(fb)) {
        res.error = "cancelled";
        return;
    }
    res.recoveryMs = msSince(t0);
    // Step 6: inverse mapping through the index matrix.
    res.regionClass.assign(img.regions.size(), RegionClass::Noise);
    for (uint32_t r : lin.onLine) res.regionClass[r] = RegionClass::Signal;
    for (uint32_t r : rec.recovered) res.regionClass[r] = RegionClass::Recovered;
    const size_t n = t.size();
    res.pointClass.assign(n, PointClass::Noise);
    res.pointRegion.assign(n, 0);
    for (size_t px = 0; px < img.pixelCount(); ++px) {
        const uint32_t reg = img.pixelRegion[px];
        const PointClass c = static_cast<PointClass>(res.regionClass[reg]);
        for (uint32_t k = img.pixelPointStart[px]; k < img.pixelPointStart[px + 1]; ++k) {
            const uint32_t i = img.pixelPoints[k];
            res.pointClass[i] = c;
            res.pointRegion[i] = reg;
        }
    }
    res.pixels = img.pixelCount();
    res.linearRegions = lin.onLine.size();
    res.recoveredRegions = rec.recovered.size();
    res.pendingRegions = pending.size();
    for (PointClass c : res.pointClass) {
        if (c == PointClass::Signal) ++res.signalPoints;
        else if (c == PointClass::Recovered) ++res.recoveredPoints;
        else ++res.noisePoints;
    }
    res.regionCount = img.regions.size();
    if (cand.empty())
        res.warnings.push_back("no region reaches the area limit (" + std::to_string(res.areaLimit) + " px): no signal found");
    else if (res.signalPoints + res.recoveredPoints == 0)
        res.warnings.push_back("no signal found");
    res.ok = true;
}
}  // namespace

namespace {
// The extraction score (screen_auto.hpp) of a result over the whole pass, on the O-C it was
// screened on (`order`: the points in time order).
ExtractionScore wholePassScore(const std::vector<uint32_t>& order, const std::vector<double>& t, const std::vector<double>& oc,
                               const ScreenResult& r) {
    std::vector<double> st(order.size()), so(order.size());
    std::vector<uint8_t> sel(order.size());
    for (size_t k = 0; k < order.size(); ++k) {
        st[k] = t[order[k]];
        so[k] = oc[order[k]];
        sel[k] = r.pointClass[order[k]] != PointClass::Noise;
    }
    return scoreExtraction(st.data(), so.data(), sel.data(), st.size());
}

// ScreenParams::refineRounds: screen again on the O-C less the trend of the accepted track.
void refine(const std::vector<double>& t, const std::vector<double>& oc, const ScreenParams& params, Feedback* fb,
            ScreenResult& res) {
    const size_t n = t.size();
    std::vector<uint32_t> order(n);
    for (uint32_t i = 0; i < n; ++i) order[i] = i;
    const bool inOrder = std::is_sorted(t.begin(), t.end());
    if (!inOrder) std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return t[a] < t[b]; });
    // The result's score on the O-C as given: kept with it unless a round replaces it (then the
    // search scores the new result itself).
    res.inputScore = wholePassScore(order, t, oc, res);
    res.inputScoreKnown = inOrder;
    double score = res.inputScore.score;
    // A result that shows no track (score ≤ 0: everything, nothing or scattered noise selected)
    // is not refined: a trend fitted to it flattens nothing. Inside a scale search these are the
    // trials at scales far from the track's, a fifth to a third of them and the dearest (their
    // screening selects most of the points); refining them cost a tenth of a sparse pass.
    if (!(score > 0)) return;
    std::vector<double> shift(n, 0.0), flat(n);
    ScreenParams again = params;
    again.refineRounds = 0;
    again.acceptFloorless = false;  // judged once, on the whole result
    // Track following runs once, after the refinement, on the O-C as given (screenSignal). Run
    // here too, on the flattened O-C, it followed the kinks at the ends of the subtracted trend,
    // and the round's score compared a followed result with an unfollowed one.
    again.followTrack = false;
    for (int round = 0; round < params.refineRounds; ++round) {
        if (cancelled(fb)) return;
        const std::vector<uint8_t> mask = acceptedMask(res);
        size_t used = 0;
        for (uint8_t m : mask) used += m;
        if (used < 10) return;  // too few points for a trend worth following
        // The accepted points' trend in the current (flattened) O-C.
        for (size_t i = 0; i < n; ++i) flat[i] = oc[i] - shift[i];
        PostfitParams pp;
        pp.degree = 8;
        pp.autoDegree = false;  // the refinement's trend as before: one degree-8 polynomial,
        pp.splitGapS = -1;      // no segments and no gross-outlier pass (the 3σ clip does)
        pp.grossSigma = 0;
        pp.rejectSigma = 3;
        pp.normalPoints = false;
        pp.binLengthS = 1;  // unused (no normal points); keeps validate() content
        pp.trendOnly = true;
        const PostfitResult f = postfit(t, flat, mask, {}, pp, fb);
        if (!f.ok) return;
        double lo = INFINITY, hi = -INFINITY;
        for (size_t i = 0; i < n; ++i)
            if (f.kept[i]) {
                lo = std::min(lo, t[i]);
                hi = std::max(hi, t[i]);
            }
        if (!(hi > lo)) return;
        // A trend within one O-C pixel of a straight line changes nothing the image can see:
        // a straight track (a pass against a good prediction) is not screened again.
        {
            const double yLo = evaluateTrend(f, lo), yHi = evaluateTrend(f, hi);
            double dev = 0;
            for (int k = 1; k < 64; ++k) {
                const double x = lo + (hi - lo) * k / 64.0;
                dev = std::max(dev, std::fabs(evaluateTrend(f, x) - (yLo + (yHi - yLo) * (x - lo) / (hi - lo))));
            }
            if (dev * res.magOc < 1) return;
        }
        std::vector<double> nextShift(shift), tc(n), trend(n);
        for (size_t i = 0; i < n; ++i) tc[i] = std::clamp(t[i], lo, hi);
        evaluateTrendMany(f, tc.data(), n, trend.data());
        for (size_t i = 0; i < n; ++i) {
            nextShift[i] += trend[i];
            flat[i] = oc[i] - nextShift[i];
        }
        again.previousMagOc = res.magOc;
        ScreenResult r2 = screenSignal(t, flat, again, fb);
        if (!r2.ok) return;
        const double score2 = wholePassScore(order, t, flat, r2).score;
        if (!(score2 >= score)) return;
        r2.autoMs += res.autoMs;
        r2.mapMs += res.mapMs;
        r2.linearityMs += res.linearityMs;
        r2.recoveryMs += res.recoveryMs;
        r2.autoArea = res.autoArea;
        r2.refinedRounds = res.refinedRounds + 1;
        // (the first round's scale, on the O-C as given, travels with the kept round)
        r2.baseMagT = res.refinedRounds > 0 ? res.baseMagT : res.magT;
        r2.baseMagOc = res.refinedRounds > 0 ? res.baseMagOc : res.magOc;
        r2.baseAreaLimit = res.refinedRounds > 0 ? res.baseAreaLimit : res.areaLimit;
        r2.baseConnectivity = res.refinedRounds > 0 ? res.baseConnectivity : res.connectivity;
        shift = nextShift;
        r2.flattenS = shift;
        res = std::move(r2);
        score = score2;
    }
}
}  // namespace

// acceptFloorless: on a pass with no noise floor, every point within 5σ of the robust trend is
// accepted (screen.hpp says why).
static void acceptIfFloorless(const NoiseFloorCheck& c, ScreenResult& res) {
    if (!c.checked) return;
    res.floorless = c.floorless;
    res.floorSigmaS = c.sigmaS;
    res.floorBeyond = c.beyondFraction;
    if (!c.floorless) return;
    // No noise floor: the pass is a station's filtered ranges, and no scale could show a track
    // against noise that is not there; that is no doubt about the result.
    if (!res.doubt.empty()) {
        res.warnings.erase(std::remove(res.warnings.begin(), res.warnings.end(), res.doubt), res.warnings.end());
        res.doubt.clear();
    }
    for (size_t i = 0; i < res.pointClass.size(); ++i) {
        if (res.pointClass[i] != PointClass::Noise || !(std::fabs(c.residualS[i]) <= 5 * c.sigmaS)) continue;
        res.pointClass[i] = PointClass::Recovered;
        ++res.recoveredPoints;
        --res.noisePoints;
        ++res.floorlessAdded;
    }
    // The image found nothing, but the track is there (a short filtered pass): not "no signal".
    if (res.floorlessAdded > 0)
        res.warnings.erase(std::remove_if(res.warnings.begin(), res.warnings.end(),
                                          [](const std::string& w) { return w.find("no signal found") != std::string::npos; }),
                           res.warnings.end());
}

ScreenResult screenSignal(const std::vector<double>& t, const std::vector<double>& oc, const ScreenParams& params,
                          Feedback* fb) {
    const auto t0 = Clock::now();
    ScreenResult res;
    if (const std::string e = validate(params); !e.empty()) {
        res.error = e;
        return res;
    }
    if (t.size() != oc.size()) {
        res.error = "epochs and O-C differ in length (" + std::to_string(t.size()) + " vs " + std::to_string(oc.size()) + ")";
        return res;
    }
    const size_t n = t.size();
    if (n < 3) {
        res.error = n == 0 ? "no points to screen" : "only " + std::to_string(n) + " point(s): at least 3 are needed to find a track";
        return res;
    }
    for (size_t i = 0; i < n; ++i)
        if (!std::isfinite(t[i]) || !std::isfinite(oc[i])) {
            res.error = "point " + std::to_string(i) + " has a non-finite " + (std::isfinite(t[i]) ? "O-C" : "epoch");
            return res;
        }
    res.magT = params.magT;
    res.magOc = params.magOc;
    res.connectivity = params.connectivity;
    res.autoArea = params.areaLimit == 0;
    if (params.magT == 0 || params.magOc == 0 || params.connectivity == 0) {
        const auto ta = Clock::now();
        AutoScaleResult a = chooseScale(t, oc, params, fb);
        res.autoMs = msSince(ta);
        for (const auto& w : a.warnings) res.warnings.push_back(w);
        res.doubt = a.doubt;
        if (!a.ok) {
            res.error = a.error;
            return res;
        }
        res.autoMagT = params.magT == 0;
        res.autoMagOc = params.magOc == 0;
        res.autoConnectivity = params.connectivity == 0;
        res.magT = a.magT;
        res.magOc = a.magOc;
        res.connectivity = a.connectivity;
        res.trials = std::move(a.trials);
    }
    if (fb) fb->setProgress(0.4);
    runFixed(t, oc, params, fb, res);
    const double span = n > 1 ? *std::max_element(t.begin(), t.end()) - *std::min_element(t.begin(), t.end()) : 0;
    const bool sparse = params.sparseRateBelow <= 0 || !(span > 0) || double(n) / span < params.sparseRateBelow;
    // The refinement, the track following and the floorless check have switches of their own:
    // the automatic mode chooses the scale, area limit and connectivity only, so that turning it
    // off on the scale it chose keeps them (issue 28: unticking Automatic lost 17 of 100 points).
    if (res.ok && params.refineRounds > 0 && sparse) refine(t, oc, params, fb, res);
    // Track following for sparse passes (like the refinement): a dense pass's track forms
    // regions at any usable scale, and following 10⁵ returns costs a third of a 10⁶-point run.
    const bool follow = res.ok && params.followTrack && sparse && !cancelled(fb);
    const bool floor = res.ok && params.acceptFloorless;
    // The noise-floor check reads only the input, so it runs beside the track following (on a
    // dense pass, which is not followed, it runs alone as before: no second copy of its buffers
    // beside a 10⁶-point screening).
    std::future<NoiseFloorCheck> floorCheck;
    if (follow && floor && std::thread::hardware_concurrency() > 1)
        floorCheck = std::async(std::launch::async, [&t, &oc] {
            adviseThreadHeap();
            return checkNoiseFloor(t, oc);
        });
    if (follow) {
        const auto tf = Clock::now();
        // On the O-C as given: smooth, whereas a refinement's flattened O-C has kinks at the
        // ends of the trend it subtracted (held constant beyond the accepted span).
        const FollowResult f = followTrack(t, oc, acceptedMask(res), FollowParams{}, fb);
        if (f.ok) {
            for (size_t i = 0; i < n; ++i) {
                const bool was = res.pointClass[i] != PointClass::Noise, now = f.accepted[i] != 0;
                if (was == now) continue;
                if (now) {
                    res.pointClass[i] = PointClass::Recovered;
                    ++res.recoveredPoints;
                    --res.noisePoints;
                } else {
                    (res.pointClass[i] == PointClass::Signal ? res.signalPoints : res.recoveredPoints)--;
                    res.pointClass[i] = PointClass::Noise;
                    ++res.noisePoints;
                }
            }
            res.followedAdded = f.added;
            res.followedDropped = f.dropped;
        }
        res.recoveryMs += msSince(tf);
    }
    if (floorCheck.valid()) {
        const NoiseFloorCheck c = floorCheck.get();
        if (!cancelled(fb)) acceptIfFloorless(c, res);
    } else if (floor && !cancelled(fb)) {
        acceptIfFloorless(checkNoiseFloor(t, oc), res);
    }
    res.totalMs = msSince(t0);
    if (res.ok && fb) fb->setProgress(1.0);
    return res;
}

ScaleChoice scaleChoice(const ScreenResult& r) {
    if (r.refinedRounds > 0 && r.baseMagT > 0)
        return {r.baseMagT, r.baseMagOc, r.baseAreaLimit, r.baseConnectivity, r.autoMagT, r.autoMagOc, r.autoArea, r.autoConnectivity};
    return {r.magT, r.magOc, r.areaLimit, r.connectivity, r.autoMagT, r.autoMagOc, r.autoArea, r.autoConnectivity};
}

ScreenResult screenSignal(const std::vector<double>& t, const std::vector<double>& oc, const ScreenParams& params,
                          const ScaleChoice& scale, Feedback* fb) {
    ScreenParams p = params;
    if (p.magT == 0) p.magT = scale.magT;
    if (p.magOc == 0) p.magOc = scale.magOc;
    if (p.areaLimit == 0) p.areaLimit = scale.areaLimit;
    if (p.connectivity == 0) p.connectivity = scale.connectivity;
    ScreenResult r = screenSignal(t, oc, p, fb);
    r.autoMagT = params.magT == 0 && scale.autoMagT;
    r.autoMagOc = params.magOc == 0 && scale.autoMagOc;
    r.autoArea = params.areaLimit == 0 && scale.autoArea;
    r.autoConnectivity = params.connectivity == 0 && scale.autoConnectivity;
    return r;
}

std::vector<uint8_t> acceptedMask(const ScreenResult& r) {
    std::vector<uint8_t> m(r.pointClass.size());
    for (size_t i = 0; i < m.size(); ++i) m[i] = r.pointClass[i] != PointClass::Noise;
    return m;
}

}  // namespace lwb::core::slr
