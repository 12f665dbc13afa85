#include "core/slr/screen_follow.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lwb::core::slr {

namespace {

double robustSigma(std::vector<double>& r) {
    if (r.empty()) return 0;
    for (double& v : r) v = std::fabs(v);
    const size_t m = r.size() / 2;
    std::nth_element(r.begin(), r.begin() + static_cast<long>(m), r.end());
    return 1.4826 * r[m];
}

// A polynomial of degree ≤ 2 in x = (t − t0) / scale, fitted by least squares, with the inverse
// normal matrix for the prediction variance factor.
struct LocalFit {
    int degree = -1;
    double t0 = 0, scale = 1;
    double c[3] = {0, 0, 0};
    double inv[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    double sigma = 0;  // robust σ of the residuals (s), when asked for (fitLocal's wantSigma)

    double at(double t) const {
        const double x = (t - t0) / scale;
        return c[0] + c[1] * x + c[2] * x * x;
    }
    // x·(XᵀX)⁻¹·xᵀ: the variance of the prediction in units of σ². (The sum over i, j in row
    // order; written out for the quadratic, the usual case.)
    double varFactor(double t) const {
        const double x = (t - t0) / scale, b[3] = {1, x, x * x};
        double v = 0;
        if (degree == 2) {
            v += b[0] * inv[0][0] * b[0];
            v += b[0] * inv[0][1] * b[1];
            v += b[0] * inv[0][2] * b[2];
            v += b[1] * inv[1][0] * b[0];
            v += b[1] * inv[1][1] * b[1];
            v += b[1] * inv[1][2] * b[2];
            v += b[2] * inv[2][0] * b[0];
            v += b[2] * inv[2][1] * b[1];
            v += b[2] * inv[2][2] * b[2];
        } else {
            for (int i = 0; i <= degree; ++i)
                for (int j = 0; j <= degree; ++j) v += b[i] * inv[i][j] * b[j];
        }
        return std::max(0.0, v);
    }
    // The curvature term |c₂|·Δ² in seconds of O-C for Δ seconds past t0.
    double curvature(double dt) const { return degree >= 2 ? std::fabs(c[2]) * (dt / scale) * (dt / scale) : 0; }
};

// Fits (T[i], O[i]) for the indices given; degree lowered to what the points allow. The robust
// σ of the residuals (a median: most of a fit's cost) only with wantSigma; else sigma = 0.
bool fitLocal(const std::vector<double>& T, const std::vector<double>& O, const uint32_t* idx, size_t n, double t0,
              int maxDegree, LocalFit* f, bool wantSigma = false) {
    if (n == 0) return false;
    double scale = 0;
    for (size_t k = 0; k < n; ++k) scale = std::max(scale, std::fabs(T[idx[k]] - t0));
    if (!(scale > 0)) scale = 1;
    int d = std::min<int>(maxDegree, n >= 6 ? 2 : n >= 3 ? 1 : 0);
    // The normal equations' sums, once for every degree tried: A[i][j] = Σ xⁱ·xʲ depends on
    // i + j only (Σ 1, x, x², x·x², x²·x²), y[i] = Σ xⁱ·O.
    double S[5] = {0, 0, 0, 0, 0}, Y[3] = {0, 0, 0};
    for (size_t k = 0; k < n; ++k) {
        const double x = (T[idx[k]] - t0) / scale, x2 = x * x, o = O[idx[k]];
        S[0] += 1;
        S[1] += x;
        S[2] += x2;
        S[3] += x * x2;
        S[4] += x2 * x2;
        Y[0] += o;
        Y[1] += x * o;
        Y[2] += x2 * o;
    }
    for (; d >= 0; --d) {
        const int m = d + 1;
        double A[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, y[3] = {0, 0, 0};
        for (int i = 0; i < m; ++i) {
            y[i] = Y[i];
            for (int j = 0; j < m; ++j) A[i][j] = S[i + j];
        }
        // Gauss–Jordan inverse of the m×m normal matrix.
        double M[3][6] = {};
        for (int i = 0; i < m; ++i) {
            for (int j = 0; j < m; ++j) M[i][j] = A[i][j];
            M[i][m + i] = 1;
        }
        bool singular = false;
        for (int col = 0; col < m && !singular; ++col) {
            int piv = col;
            for (int r = col + 1; r < m; ++r)
                if (std::fabs(M[r][col]) > std::fabs(M[piv][col])) piv = r;
            if (!(std::fabs(M[piv][col]) > 1e-12 * (1 + std::fabs(A[0][0])))) {
                singular = true;
                break;
            }
            if (piv != col)
                for (int j = 0; j < 2 * m; ++j) std::swap(M[piv][j], M[col][j]);
            const double inv = 1.0 / M[col][col];
            for (int j = 0; j < 2 * m; ++j) M[col][j] *= inv;
            for (int r = 0; r < m; ++r)
                if (r != col) {
                    const double f0 = M[r][col];
                    for (int j = 0; j < 2 * m; ++j) M[r][j] -= f0 * M[col][j];
                }
        }
        if (singular) continue;
        f->degree = d;
        f->t0 = t0;
        f->scale = scale;
        for (int i = 0; i < 3; ++i) {
            f->c[i] = 0;
            for (int j = 0; j < 3; ++j) f->inv[i][j] = 0;
        }
        for (int i = 0; i < m; ++i) {
            for (int j = 0; j < m; ++j) {
                f->inv[i][j] = M[i][m + j];
                f->c[i] += M[i][m + j] * y[j];
            }
        }
        f->sigma = 0;
        if (wantSigma) {
            std::vector<double> r(n);
            for (size_t k = 0; k < n; ++k) r[k] = O[idx[k]] - f->at(T[idx[k]]);
            f->sigma = robustSigma(r);
        }
        return true;
    }
    return false;
}

}  // namespace

std::vector<double> localTrackResiduals(const std::vector<double>& t, const std::vector<double>& oc,
                                        const std::vector<uint32_t>& idx, int side) {
    const size_t n = idx.size(), h = static_cast<size_t>(std::max(1, side));
    std::vector<double> r(n, NAN);
    std::vector<uint32_t> nb;
    LocalFit lf;
    for (size_t a = 0; a < n; ++a) {
        // `side` on each side, shifted inwards at the ends of the list.
        size_t lo = a >= h ? a - h : 0, hi = std::min(n - 1, lo + 2 * h);
        if (hi - lo < 2 * h) lo = hi >= 2 * h ? hi - 2 * h : 0;
        nb.clear();
        for (size_t q = lo; q <= hi; ++q)
            if (q != a) nb.push_back(idx[q]);
        if (nb.size() >= 3 && fitLocal(t, oc, nb.data(), nb.size(), t[idx[a]], 2, &lf)) r[a] = oc[idx[a]] - lf.at(t[idx[a]]);
    }
    return r;
}

double poissonTail(long long m, double mean) {
    if (m <= 0) return 1;
    if (!(mean > 0)) return 0;
    const double md = static_cast<double>(m);
    if (md <= mean) return 1;  // not improbable
    // Upper bound by the geometric series of the terms beyond m (ratio ≤ mean / (m + 1) < 1).
    const double logTerm = -mean + md * std::log(mean) - std::lgamma(md + 1);
    const double ratio = mean / (md + 1);
    return std::min(1.0, std::exp(logTerm) / (1 - ratio));
}

namespace {

// The track followed from the screening's accepted points, in stages: the pass prepared (time
// order, the O-C gate, the noise density in time bins), the anchors (runs of accepted points
// ranked by their quadratic fit's width) and the track width σ, the walk from each anchor
// outwards, then the accepted points inside a followed stretch but far from the track dropped.
class TrackFollower {
public:
    TrackFollower(const FollowParams& p, const Feedback* fb, FollowResult* res)
        : p_(p), fb_(fb), res_(res), anchorN_(static_cast<size_t>(std::max(4, p.anchorPoints))),
          fitN_(static_cast<size_t>(std::max(8, p.fitPoints))), k_(p.bandSigma) {}

    // Time order, gate, noise density, anchors and σ; false when there is nothing to follow.
    bool prepare(const std::vector<double>& t, const std::vector<double>& oc, const std::vector<uint8_t>& accepted) {
        n_ = t.size();
        order_.resize(n_);
        std::iota(order_.begin(), order_.end(), 0u);
        if (!std::is_sorted(t.begin(), t.end()))
            std::stable_sort(order_.begin(), order_.end(), [&](uint32_t a, uint32_t b) { return t[a] < t[b]; });
        T_.resize(n_);
        O_.resize(n_);
        A_.resize(n_);
        for (size_t k = 0; k < n_; ++k) {
            T_[k] = t[order_[k]];
            O_[k] = oc[order_[k]];
            A_[k] = accepted[order_[k]] != 0;
        }
        span_ = T_[n_ - 1] - T_[0];
        if (!(span_ > 0) || !measureNoise()) return false;
        maxGap_ = p_.maxGapS > 0 ? p_.maxGapS : std::clamp(0.25 * span_, 30.0, 300.0);
        return findAnchors();
    }

    // Every anchor not yet on a track and shaped like a line, followed both ways.
    void followAll() {
        inTrack_.assign(n_, 0);
        for (const Run& run : runs_) {
            if (cancelled(fb_)) break;
            // Skip anchors already followed through (any of their points on a track) or not a line.
            bool taken = false;
            for (size_t q = run.first; q < run.first + anchorN_; ++q) taken = taken || inTrack_[acc_[q]];
            if (taken || run.sigma > 6 * sigmaTrack_) continue;
            followAnchor(run);
        }
    }

    // Accepted points inside a followed stretch but far from the track: noise.
    void dropFarPoints() {
        if (!(p_.dropSigma > 0)) return;
        std::vector<uint32_t> tr;
        for (size_t q = 0; q < n_; ++q)
            if (inTrack_[q]) tr.push_back(static_cast<uint32_t>(q));
        LocalFit lf;
        for (size_t q = 0; q < n_ && !tr.empty(); ++q) {
            if (!A_[q] || inTrack_[q]) continue;
            bool inside = false;
            for (const auto& [a, b] : stretches_) inside = inside || (T_[q] >= a && T_[q] <= b);
            if (!inside) continue;
            // The followed points nearest in time (up to 10 on each side).
            const size_t pos = static_cast<size_t>(std::lower_bound(tr.begin(), tr.end(), static_cast<uint32_t>(q)) - tr.begin());
            const size_t a = pos >= 10 ? pos - 10 : 0, b = std::min(tr.size(), pos + 10);
            if (b - a < 3) continue;
            if (!fitLocal(T_, O_, tr.data() + a, b - a, T_[q], 2, &lf, true)) continue;
            if (std::fabs(O_[q] - lf.at(T_[q])) > p_.dropSigma * std::max(lf.sigma, sigmaTrack_)) {
                A_[q] = 0;
                ++res_->dropped;
            }
        }
    }

    // The mask back in input order.
    void write() const {
        for (size_t q = 0; q < n_; ++q) res_->accepted[order_[q]] = (A_[q] || inTrack_[q]) ? 1 : 0;
    }

private:
    struct Run {
        size_t first;  // index into acc_
        double sigma;
    };
    // One step of a walk: the local fit at the front and the band it predicts.
    struct Step {
        double tf = 0, spacing = 0;
        LocalFit lf;
    };

    // Robust O-C span (the gate) and the local noise rate from the points called noise.
    bool measureNoise() {
        std::vector<double> s;
        const size_t step = std::max<size_t>(1, n_ / 100000);
        for (size_t k = 0; k < n_; k += step) s.push_back(O_[k]);
        const size_t lo = static_cast<size_t>(0.005 * static_cast<double>(s.size() - 1));
        const size_t hi = static_cast<size_t>(0.995 * static_cast<double>(s.size() - 1) + 0.5);
        std::nth_element(s.begin(), s.begin() + static_cast<long>(lo), s.end());
        const double a = s[lo];
        std::nth_element(s.begin(), s.begin() + static_cast<long>(hi), s.end());
        gate_ = s[hi] - a;
        if (!(gate_ > 0)) return false;
        nBins_ = std::clamp<size_t>(static_cast<size_t>(span_ / 10.0), 1, 64);
        binW_ = span_ / static_cast<double>(nBins_);
        density_.assign(nBins_, 0.0);  // noise points per s per s of O-C
        for (size_t k = 0; k < n_; ++k)
            if (!A_[k]) density_[std::min(nBins_ - 1, static_cast<size_t>((T_[k] - T_[0]) / binW_))] += 1;
        for (double& d : density_) d = std::max(d, 1.0) / (binW_ * gate_);  // at least one point per bin: never a zero density
        return true;
    }

    double densityOver(double a, double b) const {
        if (a > b) std::swap(a, b);
        const size_t i0 = std::min(nBins_ - 1, static_cast<size_t>(std::max(0.0, (a - T_[0]) / binW_)));
        const size_t i1 = std::min(nBins_ - 1, static_cast<size_t>(std::max(0.0, (b - T_[0]) / binW_)));
        double m = 0;
        for (size_t i = i0; i <= i1; ++i) m = std::max(m, density_[i]);
        return m;
    }

    // Anchors: runs of anchorN consecutive accepted points, ranked by their quadratic fit's
    // width; then the track width σ: leave-one-out residuals of the accepted points about a
    // quadratic through their 4 + 4 accepted neighbours in time, robust σ over the pass
    // (1.4826·MAD), less the prediction's own spread (a factor ≈ 1.2 for 8 neighbours).
    bool findAnchors() {
        for (size_t q = 0; q < n_; ++q)
            if (A_[q]) acc_.push_back(static_cast<uint32_t>(q));
        LocalFit lf;
        for (size_t a = 0; a + anchorN_ <= acc_.size(); a += std::max<size_t>(1, anchorN_ / 2)) {
            if (!fitLocal(T_, O_, acc_.data() + a, anchorN_, T_[acc_[a + anchorN_ / 2]], 2, &lf)) continue;
            double worst = 0;
            for (size_t q = a; q < a + anchorN_; ++q) worst = std::max(worst, std::fabs(O_[acc_[q]] - lf.at(T_[acc_[q]])));
            runs_.push_back({a, worst});
        }
        if (runs_.empty()) return false;
        std::sort(runs_.begin(), runs_.end(),
                  [](const Run& x, const Run& y) { return x.sigma < y.sigma || (x.sigma == y.sigma && x.first < y.first); });
        std::vector<double> r = localTrackResiduals(T_, O_, acc_, 4);
        r.erase(std::remove_if(r.begin(), r.end(), [](double v) { return !std::isfinite(v); }), r.end());
        sigmaTrack_ = robustSigma(r) / 1.2;
        if (!(sigmaTrack_ > 0)) sigmaTrack_ = runs_.front().sigma / 1.5;
        sigmaTrack_ = std::max(sigmaTrack_, 1e-15);
        res_->sigmaS = sigmaTrack_;
        return true;
    }

    // The walks of one anchor. Walks to do: (seed points in walk order, direction). A piece
    // found beyond a gap becomes a seed of its own (followed back towards the gap, and onwards
    // on its own fit).
    void followAnchor(const Run& run) {
        ++res_->pieces;
        for (size_t q = run.first; q < run.first + anchorN_; ++q) inTrack_[acc_[q]] = 1;
        double lo = T_[acc_[run.first]], hi = T_[acc_[run.first + anchorN_ - 1]];
        std::vector<std::pair<std::vector<uint32_t>, int>> tasks;
        for (int dir : {-1, +1}) {
            std::vector<uint32_t> seed;
            for (size_t q = 0; q < anchorN_; ++q) seed.push_back(acc_[dir > 0 ? run.first + q : run.first + anchorN_ - 1 - q]);
            tasks.push_back({seed, dir});
        }
        while (!tasks.empty()) {
            std::vector<uint32_t> walk = std::move(tasks.back().first);
            const int dir = tasks.back().second;
            tasks.pop_back();
            walkOn(std::move(walk), dir, &tasks, &lo, &hi);
        }
        stretches_.push_back({lo, hi});
    }

    // The band half-width the fit predicts at tc: k·σ·sqrt(1 + v) plus the curvature's reach,
    // at most gate / 8.
    double band(const Step& s, double tc) const {
        const double dt = std::fabs(tc - s.tf);
        return std::min(gate_ / 8, k_ * sigmaTrack_ * std::sqrt(1 + s.lf.varFactor(tc)) + s.lf.curvature(dt));
    }

    // One walk: from the front of `walk`, a window of L s searched for points within the band;
    // a consistent set that noise is unlikely to make is taken and the walk goes on; else the
    // window doubles up to maxGap.
    void walkOn(std::vector<uint32_t> walk, int dir, std::vector<std::pair<std::vector<uint32_t>, int>>* tasks, double* lo,
                double* hi) {
        double L = 0;
        size_t sinceJump = 0;  // walk position of the first point beyond the last gap crossed
        for (;;) {
            const uint32_t front = walk.back();
            Step s;
            s.tf = T_[front];
            // Local fit through the last fitN followed points (only those beyond the last gap
            // crossed, once there are 6 of them: the track may change level or slope there).
            size_t m = std::min(fitN_, walk.size());
            if (walk.size() - sinceJump >= 6) m = std::min(m, walk.size() - sinceJump);
            fitIdx_.assign(walk.end() - static_cast<long>(m), walk.end());
            if (!fitLocal(T_, O_, fitIdx_.data(), m, s.tf, 2, &s.lf)) break;
            // Window: a few typical spacings of the followed points, doubling up to maxGap.
            s.spacing = std::max(1e-7, std::fabs(T_[walk.back()] - T_[walk[walk.size() - m]]) /
                                           static_cast<double>(std::max<size_t>(1, m - 1)));
            if (L == 0) L = 3 * s.spacing;
            bool metTrack = false, pastEnd = true;
            candidates(s, front, dir, L, &metTrack, &pastEnd);
            // Expected noise in the search band over the window (trapezoid over 16 steps): with
            // it the test below counts how many narrow bands the wide one holds (look-elsewhere).
            const double tEnd = s.tf + dir * L;
            double area = 0, bandA = band(s, s.tf);
            for (int q = 0; q < 16; ++q) {
                const double bandB = band(s, s.tf + dir * L * (q + 1) / 16.0);
                area += 0.5 * (bandA + bandB) * 2 * (L / 16.0);
                bandA = bandB;
            }
            const double rho = densityOver(s.tf, tEnd);
            const double eWide = area * rho;
            // Too many candidates to sort out: the track is lost here. (A wide band is not, by
            // itself: until 2026-12-07 the walk also ended where the band expected more than 5
            // noise points, and on sparse, steep stretches, whose extrapolated band widens faster
            // than the returns come, it stopped with returns left on both sides; the Poisson test
            // with the band's look-elsewhere factor is what decides, docs/slr-detection.md.)
            if (cand_.size() > 64) break;
            // Beyond a gap the candidates are judged among themselves (a fit across the gap
            // would have to bend to both sides), when there are enough of them.
            const bool jump = !cand_.empty() && dir * (T_[cand_.front()] - s.tf) > 4 * s.spacing;
            consistentCandidates(walk, s.tf, jump);
            bool took = false;
            if (!keep_.empty()) {
                // The density contrast: m consistent points where the narrow band (k·σ about the
                // track over the window) expects eLine noise points, with the number of such
                // bands the search band holds as the look-elsewhere factor.
                const double eLine = std::max(1e-300, rho * 2 * k_ * sigmaTrack_ * L);
                const double trials = std::max(1.0, eWide / eLine);
                if (poissonTail(static_cast<long long>(keep_.size()), eLine) * trials < p_.alpha) {
                    std::sort(keep_.begin(), keep_.end());
                    if (dir < 0) std::reverse(keep_.begin(), keep_.end());
                    for (uint32_t q : keep_) {
                        inTrack_[q] = 1;
                        walk.push_back(q);
                        res_->added += !A_[q];
                        *lo = std::min(*lo, T_[q]);
                        *hi = std::max(*hi, T_[q]);
                    }
                    if (jump && keep_.size() >= 3) {
                        // A piece beyond a gap: followed on its own fit, and back towards the gap.
                        sinceJump = walk.size() - keep_.size();
                        tasks->push_back({std::vector<uint32_t>(keep_.rbegin(), keep_.rend()), -dir});
                    }
                    took = true;
                    L = 0;
                }
            }
            if (metTrack) break;
            if (!took) {
                if (L >= maxGap_ || pastEnd) break;
                L = std::min(2 * L, maxGap_);
            }
        }
    }

    // The points of the window within the band (cand_); *metTrack when the walk reached a point
    // already on a track inside the band, *pastEnd when the window runs past the pass.
    void candidates(const Step& s, uint32_t front, int dir, double L, bool* metTrack, bool* pastEnd) {
        cand_.clear();
        for (long q = static_cast<long>(front) + dir; q >= 0 && q < static_cast<long>(n_); q += dir) {
            const double dt = dir * (T_[q] - s.tf);
            if (dt > L) {
                *pastEnd = false;
                break;
            }
            // The band is at most gate / 8 wide: a point farther from the fit is outside it
            // without computing the band there.
            const double off = std::fabs(O_[q] - s.lf.at(T_[q]));
            if (inTrack_[q]) {
                *metTrack = off <= gate_ / 8 && off <= band(s, T_[q]);
                if (*metTrack) break;
                continue;
            }
            if (off <= gate_ / 8 && off <= band(s, T_[q])) cand_.push_back(static_cast<uint32_t>(q));
        }
    }

    // Candidates consistent among themselves (keep_): each within k·σ·sqrt(1 + v) of a fit
    // through the other candidates and the last followed points (leave one out, so that a noise
    // point cannot pull the fit onto itself); the worst dropped while one is beyond.
    void consistentCandidates(const std::vector<uint32_t>& walk, double tf, bool jump) {
        keep_ = cand_;
        while (!keep_.empty()) {
            const size_t near = jump && keep_.size() >= 5 ? 0 : std::min<size_t>(walk.size(), 6);
            size_t worst = 0;
            double wr = -1;
            for (size_t c = 0; c < keep_.size(); ++c) {
                fitIdx_.assign(walk.end() - static_cast<long>(near), walk.end());
                for (size_t e = 0; e < keep_.size(); ++e)
                    if (e != c) fitIdx_.push_back(keep_[e]);
                std::sort(fitIdx_.begin(), fitIdx_.end());
                LocalFit cf;
                if (!fitLocal(T_, O_, fitIdx_.data(), fitIdx_.size(), tf, 2, &cf)) continue;
                const double r = std::fabs(O_[keep_[c]] - cf.at(T_[keep_[c]])) / std::sqrt(1 + cf.varFactor(T_[keep_[c]]));
                if (r > wr) {
                    wr = r;
                    worst = c;
                }
            }
            if (wr <= k_ * sigmaTrack_) break;
            keep_.erase(keep_.begin() + static_cast<long>(worst));
        }
    }

    const FollowParams& p_;
    const Feedback* fb_;
    FollowResult* res_;
    const size_t anchorN_, fitN_;
    const double k_;
    size_t n_ = 0, nBins_ = 1;
    double span_ = 0, gate_ = 0, binW_ = 1, maxGap_ = 0, sigmaTrack_ = 0;
    std::vector<uint32_t> order_, acc_;
    std::vector<double> T_, O_, density_;
    std::vector<uint8_t> A_, inTrack_;
    std::vector<Run> runs_;
    std::vector<uint32_t> cand_, keep_, fitIdx_;
    std::vector<std::pair<double, double>> stretches_;  // followed time spans
};

}  // namespace

FollowResult followTrack(const std::vector<double>& t, const std::vector<double>& oc,
                         const std::vector<uint8_t>& accepted, const FollowParams& p, const Feedback* fb) {
    FollowResult res;
    const size_t n = t.size();
    res.accepted = accepted;
    if (oc.size() != n || accepted.size() != n) return res;
    res.ok = true;
    size_t nAcc = 0;
    for (uint8_t a : accepted) nAcc += a != 0;
    if (nAcc < static_cast<size_t>(std::max(4, p.anchorPoints)) || n < 3) return res;
    TrackFollower follower(p, fb, &res);
    if (!follower.prepare(t, oc, accepted)) return res;
    follower.followAll();
    follower.dropFarPoints();
    follower.write();
    return res;
}

}  // namespace lwb::core::slr
