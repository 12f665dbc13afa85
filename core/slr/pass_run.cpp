#include "core/slr/pass_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/common/text.hpp"
#include "core/slr/np_context.hpp"

namespace lwb::core::slr {

SlrParams commandDefaults() {
    SlrParams p;
    p.postfit.rejectSigma = 3;
    return p;
}


DeliveredNormalPoints deliveredNormalPoints(const PassRunResult& r) {
    DeliveredNormalPoints d;
    if (r.doubt.empty() && r.postOk) d.points = r.post.normalPoints;
    if (!d.points.empty()) return d;
    if (!r.doubt.empty()) d.noneReason = "doubtful: " + r.doubt;
    else if (r.acceptedCount == 0) d.noneReason = "no signal found";
    else if (!r.postOk) d.noneReason = r.postNote.empty() ? "no post-fit" : r.postNote;
    else if (!r.postNote.empty()) d.noneReason = r.postNote;
    else d.noneReason = "no bin holds the minimum number of kept points";
    return d;
}

bool applyPreset(const PassData& pass, const std::vector<SatellitePreset>& presets, const std::string& satellite,
                 SlrParams* params, std::string* presetName, std::string* error) {
    const SatellitePreset* p =
        satellite.empty() ? findPreset(presets, pass.satellite, pass.ilrsId) : findPreset(presets, satellite, satellite);
    if (!p) {
        std::string have;
        const size_t shown = std::min<size_t>(presets.size(), 20);  // a long file is not dumped whole
        for (size_t k = 0; k < shown; ++k) {
            const auto& q = presets[k];
            have += (have.empty() ? "" : ", ") + printableExcerpt(q.name.empty() ? q.ilrsId : q.name) +
                    (q.ilrsId.empty() || q.name.empty() ? "" : " (" + printableExcerpt(q.ilrsId) + ")");
        }
        if (presets.size() > shown) have += ", ... and " + std::to_string(presets.size() - shown) + " more";
        const std::string who =
            !satellite.empty() ? "\"" + satellite + "\""
            : pass.satellite.empty() && pass.ilrsId.empty()
                ? std::string("(none: an O-C table names no satellite; give --satellite NAME)")
                : "\"" + pass.satellite + "\"" + (pass.ilrsId.empty() ? "" : " (ILRS id " + pass.ilrsId + ")");
        *error = "no preset for satellite " + who + "; the file holds: " + (have.empty() ? "no entries" : have);
        return false;
    }
    *presetName = p->name.empty() ? p->ilrsId : p->name;
    params->screen = p->screen;  // (a preset holds the screening and the post-fit; the O-C is not a satellite's)
    params->postfit = p->postfit;
    return true;
}

bool passSettings(const PassData& pass, const SlrParams& base, const std::vector<SatellitePreset>* presets,
                  const std::string& satellite, const SinexFile* stations, PassSettings* out, std::string* error) {
    PassSettings s;
    s.params = base;
    if (presets && !applyPreset(pass, *presets, satellite, &s.params, &s.presetName, error)) return false;
    s.notes = passNormalPointContext(pass, stations, &s.params.postfit);
    *out = std::move(s);
    return true;
}

StationAgreement stationAgreement(const PassData& pass, const std::vector<uint8_t>& accepted, const PostfitResult* post) {
    StationAgreement a;
    for (int f : pass.stationFlag) {
        a.noise += f == 1;
        a.data += f == 2;
    }
    if (a.data == 0 || a.data + a.noise != static_cast<long long>(pass.stationFlag.size()) ||
        accepted.size() != pass.stationFlag.size())
        return a;
    a.available = true;
    long long tp = 0, fp = 0, keptTp = 0, keptFp = 0;
    const bool kept = post && post->ok && post->kept.size() == accepted.size();
    for (size_t i = 0; i < accepted.size(); ++i) {
        const bool sig = pass.stationFlag[i] == 2;
        tp += accepted[i] && sig;
        fp += accepted[i] && !sig;
        if (kept) {
            keptTp += post->kept[i] && sig;
            keptFp += post->kept[i] && !sig;
        }
    }
    a.precision = tp + fp ? double(tp) / double(tp + fp) : NAN;  // 0/0: nothing accepted, undefined
    a.recall = double(tp) / double(a.data);
    if (kept) {
        a.keptPrecision = keptTp + keptFp ? double(keptTp) / double(keptTp + keptFp) : NAN;
        a.keptRecall = double(keptTp) / double(a.data);
    }
    return a;
}

PostfitParams postfitForPass(PostfitParams pp, std::string* note, const PassData* pass) {
    if (pp.normalPoints && !(pp.binLengthS > 0) && !(pp.altitudeKm > 0)) {
        pp.normalPoints = false;
        if (note) *note = "no normal points: the satellite's altitude is unknown (give the bin length or the altitude)";
    }
    if (pass && pass->orbitTrend && pp.autoDegree && pp.splitGapS == 0) {
        pp.autoDegree = false;  // (its BIC would also try splines: a cubic through a few bursts)
        pp.degree = std::min(pp.degree, 1);
        pp.splitGapS = -1;
    }
    return pp;
}

namespace {
std::string twoTracksNote(double sepNs, size_t n1, size_t n2, double widthS) {
    return "two parallel tracks " + formatFixed(sepNs, 3) + " ns apart (" + std::to_string(n1) + " and " + std::to_string(n2) +
           " points, each " + formatFixed(widthS * 1e12, 0) +
           " ps wide): another target or a double echo merged into one track; screen them apart (a box in the "
           "workbench, or a narrower band) before forming normal points";
}

// The median and 1.4826 x MAD of sorted r[a, b).
void medianSpread(const std::vector<double>& r, size_t a, size_t b, double* centre, double* sigma) {
    const size_t m = b - a;
    *centre = m % 2 ? r[a + m / 2] : 0.5 * (r[a + m / 2 - 1] + r[a + m / 2]);
    std::vector<double> dev(m);
    for (size_t i = 0; i < m; ++i) dev[i] = std::fabs(r[a + i] - *centre);
    std::nth_element(dev.begin(), dev.begin() + static_cast<long>(m / 2), dev.end());
    *sigma = 1.4826 * dev[m / 2];
}

// The second track among noise (issue 41: a kHz pass with a ghost 3 ns beside its track, and
// the noise the band kept between them, so that no gap was empty). The main track: the densest
// tenth of the sorted residuals, then median and MAD over ±4 sigma of it, to convergence. The
// second: the window of the main track's width (±3 sigma) holding the most of the other points,
// taken as a track when it holds at least 10 points and 5 % of the main track's, when it stands
// at least 5 times above the density of the others beside it, and when a valley at most a
// quarter as dense, at least 2 sigma wide, parts it from the main track (a tail or a shoulder of
// one track falls off from its edge without one). "" or the note.
std::string secondTrackAmongNoise(const std::vector<double>& r) {
    const size_t n = r.size();
    const size_t h = std::max<size_t>(5, n / 10);
    size_t best = 0;
    for (size_t i = 0; i + h <= n; ++i)
        if (r[i + h - 1] - r[i] < r[best + h - 1] - r[best]) best = i;
    double c = 0.5 * (r[best] + r[best + h - 1]), sigma = (r[best + h - 1] - r[best]) / (2 * 0.1257);
    size_t a = 0, b = n;
    for (int it = 0; it < 30 && sigma > 0; ++it) {
        const size_t a2 = static_cast<size_t>(std::lower_bound(r.begin(), r.end(), c - 4 * sigma) - r.begin());
        const size_t b2 = static_cast<size_t>(std::upper_bound(r.begin(), r.end(), c + 4 * sigma) - r.begin());
        if (b2 <= a2 + 4) return {};
        double c2 = 0, s2 = 0;
        medianSpread(r, a2, b2, &c2, &s2);
        const bool same = a2 == a && b2 == b;
        a = a2, b = b2, c = c2, sigma = s2;
        if (same) break;
    }
    if (!(sigma > 0)) return {};
    const size_t nMain = b - a;
    const double w = 6 * sigma;  // a track's window
    // The densest window of width w among the points outside the main band, on either side.
    size_t bestCount = 0, bestLo = 0;
    auto scan = [&](size_t from, size_t to) {
        for (size_t i = from, j = from; i < to; ++i) {
            if (j < i) j = i;
            while (j < to && r[j] - r[i] <= w) ++j;
            if (j - i > bestCount) bestCount = j - i, bestLo = i;
        }
    };
    scan(0, a);
    scan(b, n);
    if (bestCount < std::max<size_t>(10, nMain / 20)) return {};
    const double lo = r[bestLo], hi = lo + w;
    const bool above = lo > c;
    // The valley: between the main band's edge and the window's near edge.
    const double v0 = above ? c + 4 * sigma : hi, v1 = above ? lo : c - 4 * sigma;
    if (!(v1 - v0 >= 2 * sigma)) return {};
    const size_t inValley = static_cast<size_t>(std::lower_bound(r.begin(), r.end(), v1) - std::upper_bound(r.begin(), r.end(), v0));
    const double windowDensity = static_cast<double>(bestCount) / w;
    if (!(static_cast<double>(inValley) / (v1 - v0) <= 0.25 * windowDensity)) return {};
    // The other points beside it (neither the main band nor the window): the noise's density.
    const size_t others = n - nMain - bestCount;
    const double span = std::max(r.back() - r.front() - 8 * sigma - w, w);
    const double noiseInWindow = static_cast<double>(others) * w / span;
    if (!(static_cast<double>(bestCount) >= 5 * noiseInWindow)) return {};
    // The second track's centre and width, by the same median and MAD.
    double c2 = 0, s2 = 0;
    medianSpread(r, bestLo, bestLo + bestCount, &c2, &s2);
    return twoTracksNote(std::fabs(c2 - c) * 1e9, nMain, bestCount, std::max(sigma, s2));
}
}  // namespace

std::string parallelTracks(const std::vector<double>& residuals) {
    const size_t n = residuals.size();
    if (n < 50) return {};
    std::vector<double> r = residuals;
    std::sort(r.begin(), r.end());
    std::vector<double> s1(n + 1, 0), s2(n + 1, 0);  // prefix sums (about the median, for precision)
    const double c = r[n / 2];
    for (size_t i = 0; i < n; ++i) {
        s1[i + 1] = s1[i] + (r[i] - c);
        s2[i + 1] = s2[i] + (r[i] - c) * (r[i] - c);
    }
    auto sd = [&](size_t a, size_t b) {  // [a, b)
        const double m = static_cast<double>(b - a), mean = (s1[b] - s1[a]) / m;
        return std::sqrt(std::max(0.0, (s2[b] - s2[a]) / m - mean * mean));
    };
    const size_t lo = std::max<size_t>(5, n / 10);
    double bestRatio = 0;
    size_t at = 0;
    for (size_t k = lo; k + lo <= n; ++k) {
        const double gap = r[k] - r[k - 1];
        const double spread = std::max(sd(0, k), sd(k, n));
        const double ratio = spread > 0 ? gap / spread : (gap > 0 ? INFINITY : 0);
        if (ratio > bestRatio) bestRatio = ratio, at = k;
    }
    if (!(bestRatio > 8)) return secondTrackAmongNoise(r);
    const double sepNs = ((s1[n] - s1[at]) / static_cast<double>(n - at) - s1[at] / static_cast<double>(at)) * 1e9;
    return twoTracksNote(sepNs, at, n - at, std::max(sd(0, at), sd(at, n)));
}

PassBias passBias(const PassData& pass, const std::vector<uint8_t>& kept) {
    PassBias b;
    const size_t n = pass.t.size();
    if (pass.ocOrigin.rfind("CPF prediction", 0) != 0) {
        b.why = "no prediction: the O-C is not against a CPF";
        return b;
    }
    if (pass.tof.size() != n || pass.oc.size() != n || kept.size() != n || n < 3) {
        b.why = "no times of flight";
        return b;
    }
    std::vector<size_t> order(n);
    for (size_t i = 0; i < n; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t c) { return pass.t[a] < pass.t[c]; });
    // Normal equations of O-C = b + τ·rate over the kept points (rate in s/s of predicted TOF).
    double s1 = 0, sx = 0, sxx = 0, sy = 0, sxy = 0;
    std::vector<std::pair<double, double>> xy;
    for (size_t k = 0; k < n; ++k) {
        const size_t i = order[k];
        if (!kept[i]) continue;
        const size_t a = order[k == 0 ? 0 : k - 1], c = order[k + 1 == n ? n - 1 : k + 1];
        const double dt = pass.t[c] - pass.t[a];
        if (!(dt > 0)) continue;
        const double rate = ((pass.tof[c] - pass.oc[c]) - (pass.tof[a] - pass.oc[a])) / dt;
        if (!std::isfinite(rate)) continue;
        xy.emplace_back(rate, pass.oc[i]);
        s1 += 1;
        sx += rate;
        sxx += rate * rate;
        sy += pass.oc[i];
        sxy += rate * pass.oc[i];
    }
    const double det = s1 * sxx - sx * sx;
    if (xy.size() < 3 || !(det > 0) || !(det > 1e-12 * s1 * sxx)) {
        b.why = "too few kept points, or no change of the range rate to tell a time bias by";
        return b;
    }
    b.timeBiasS = (s1 * sxy - sx * sy) / det;
    b.rangeBiasS = (sy - b.timeBiasS * sx) / s1;
    double rss = 0;
    for (const auto& [x, y] : xy) rss += (y - b.rangeBiasS - b.timeBiasS * x) * (y - b.rangeBiasS - b.timeBiasS * x);
    const double s2 = rss / static_cast<double>(xy.size() - 2);
    b.rangeBiasSigmaS = std::sqrt(s2 * sxx / det);
    b.timeBiasSigmaS = std::sqrt(s2 * s1 / det);
    b.points = static_cast<long long>(xy.size());
    b.ok = true;
    return b;
}

std::string describeBias(const PassBias& b) {
    if (!b.ok) return "no range or time bias: " + b.why;
    const double mm = 0.5 * 299792458.0 * 1e3;  // two-way s -> one-way mm
    return "range bias " + formatFixed(b.rangeBiasS * mm, 1) + " ± " + formatFixed(b.rangeBiasSigmaS * mm, 1) +
           " mm (one-way), time bias " + formatFixed(b.timeBiasS * 1e6, 2) + " ± " + formatFixed(b.timeBiasSigmaS * 1e6, 2) +
           " µs (" + std::to_string(b.points) + " points)";
}

double trackSeparation(const PostfitResult& post) {
    const double sigma = post.stats.rms;
    if (!(sigma > 0) || post.residuals.empty()) return NAN;
    double lo = INFINITY, hi = -INFINITY;
    size_t in = 0, out = 0;
    for (double r : post.residuals) {
        if (!std::isfinite(r)) continue;
        lo = std::min(lo, r);
        hi = std::max(hi, r);
        (std::fabs(r) <= 3 * sigma ? in : out)++;
    }
    if (out == 0) return INFINITY;  // nothing beside the band: no noise to mistake it for
    const double band = 6 * sigma, rest = std::max(hi - lo - band, band);
    return static_cast<double>(in) / (static_cast<double>(out) * band / rest);
}

namespace {
// P(X ≥ k) for X ~ Binomial(n, q): the terms summed from k up in log space.
double binomialUpperTail(long long k, long long n, double q) {
    if (k <= 0) return 1;
    if (k > n || !(q > 0)) return 0;
    if (q >= 1) return 1;
    const double lq = std::log(q), l1q = std::log1p(-q), lgn = std::lgamma(double(n) + 1);
    double sum = 0, first = NAN;
    for (long long j = k; j <= n; ++j) {
        const double lt = lgn - std::lgamma(double(j) + 1) - std::lgamma(double(n - j) + 1) + double(j) * lq + double(n - j) * l1q;
        if (std::isnan(first)) first = lt;
        const double term = std::exp(lt - first);
        sum += term;
        if (term < 1e-12 * sum && double(j) > double(n) * q) break;
    }
    return std::min(1.0, std::exp(first) * sum);
}
}  // namespace

std::string windowShapeDoubt(const PostfitResult& post, bool judgePeakedness) {
    std::vector<double> r;
    // (a point its own segment's fit passes through, residual 0 to a femtosecond, tells nothing
    // of the shape: a sparse pass's segments of one point would make a spike of them)
    for (size_t i = 0; i < post.residuals.size() && i < post.kept.size(); ++i)
        if (post.kept[i] && std::isfinite(post.residuals[i]) && std::fabs(post.residuals[i]) > 1e-15) r.push_back(post.residuals[i]);
    const size_t n = r.size();
    if (n < kMinCentralPoints) return "";
    double mean = 0, ss = 0;
    for (double v : r) mean += v;
    mean /= double(n);
    for (double v : r) ss += (v - mean) * (v - mean);
    const double rms = std::sqrt(ss / double(n));
    if (!(rms > 0)) return "";
    // A narrow track on a wide floor: too many points in the densest interval a fiftieth of the
    // RMS wide for one track (the track need not be at the median: a trend fitted through the
    // floor leaves it aside).
    std::sort(r.begin(), r.end());
    const auto quantile = [&](double p) { return r[static_cast<size_t>(p * double(n - 1))]; };
    size_t central = 0;
    for (size_t a = 0, b = 0; b < n; ++b) {
        while (r[b] - r[a] > rms / 50) ++a;
        central = std::max(central, b - a + 1);
    }
    const double share = double(central) / double(n),
                 most = kCentralShareBase + 4 * std::sqrt(kCentralShareBase * (1 - kCentralShareBase) / double(n));
    if (share > most)
        return "the " + std::to_string(n) + " kept points are a narrow track on a wide floor: " + formatFixed(100 * share, 0) +
               " % of them lie within " + formatFixed(rms / 50 * 1e12, 1) + " ps (a fiftieth of their RMS) of one another, "
               "where one track puts about 1 % (at most " + formatFixed(100 * most, 0) + " % with " + std::to_string(n) +
               " points): the post-fit's window, ±3 RMS, spans the floor";
    if (!judgePeakedness || n < kMinFlatWindowPoints) return "";
    const double q025 = quantile(0.025), q975 = quantile(0.975), q25 = quantile(0.25), q75 = quantile(0.75);
    const double peakedness = q75 > q25 ? (q975 - q025) / (q75 - q25) : 0;
    if (peakedness >= kMinTrackPeakedness) return "";
    return "the " + std::to_string(n) + " kept points fill the post-fit's window evenly (peakedness (q97.5 − q2.5)/(q75 − q25) " +
           formatFixed(peakedness, 2) + ", about 2.8 for a track, 1.9 for noise that fills the window): a track cannot be "
           "told from noise";
}

std::vector<BinEvidence> normalPointEvidence(const std::vector<double>& t, const PostfitResult& post) {
    std::vector<BinEvidence> out;
    const double h = 3 * post.stats.rms;  // the track's half window
    const double flank = 20 * 2 * h;      // each flank: 20 windows
    // The points of a bin: a range of the epochs when they are in time order (a pass as read),
    // else of an order sorted once. Scanning every point for every bin cost N × bins (a raw kHz
    // pass of 10^7 events with hundreds of bins).
    const size_t nPts = std::min(t.size(), post.residuals.size());
    std::vector<size_t> order;
    bool inOrder = true;  // (a NaN epoch is out of order: sorted last, never in a bin)
    for (size_t i = 0; i < nPts && inOrder; ++i) inOrder = std::isfinite(t[i]) && (i == 0 || t[i - 1] <= t[i]);
    if (!inOrder) {
        order.resize(nPts);
        for (size_t i = 0; i < nPts; ++i) order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
            return std::isnan(t[b]) ? !std::isnan(t[a]) : t[a] < t[b];
        });
    }
    // The fit's own band: the rejection's last limit where it is narrower than the window (a
    // rejection below 3σ, or the noise band), within which every point of the track is kept.
    const double band = std::isfinite(post.limitS) && post.limitS > 0 ? std::min(h, post.limitS) : h;
    const bool keptKnown = post.kept.size() == post.residuals.size();
    const auto epochAt = [&](size_t k) { return order.empty() ? t[k] : t[order[k]]; };
    const auto firstAtOrAfter = [&](double x) {
        size_t lo = 0, hi = nPts;  // first k with epochAt(k) >= x
        while (lo < hi) {
            const size_t mid = lo + (hi - lo) / 2;
            if (epochAt(mid) < x) lo = mid + 1;
            else hi = mid;
        }
        return lo;
    };
    std::vector<std::pair<double, double>> pts;  // (t, residual) in the bin
    std::vector<size_t> offWindow;               // places in pts of the points off the window
    size_t unmeasured = 0;                       // bins with fewer than 16 points off the window
    for (const NormalPoint& np : post.normalPoints) {
        BinEvidence e;
        e.binStartS = np.binStartS;
        pts.clear();
        for (size_t k = firstAtOrAfter(np.binStartS); k < nPts; ++k) {
            const size_t i = order.empty() ? k : order[k];
            if (!(t[i] < np.binStartS + np.windowS)) break;
            if (!std::isfinite(post.residuals[i])) continue;
            pts.emplace_back(t[i], post.residuals[i]);
            if (std::fabs(post.residuals[i]) <= band) {
                ++e.bandPoints;
                if (keptKnown && post.kept[i]) ++e.keptOnPoints;
            }
        }
        if (!(h > 0) || pts.empty()) {
            e.why = "no spread to judge the track by";
            out.push_back(e);
            continue;
        }
        std::sort(pts.begin(), pts.end());
        const size_t n = pts.size(), slices = std::clamp<size_t>(n / 20, 1, 20);
        double lambda = 0, lambdaPlus = 0;
        std::vector<double> rooms, extents;
        for (size_t s = 0; s < slices; ++s) {
            const size_t a = n * s / slices, b = n * (s + 1) / slices;
            double lo = INFINITY, hi = -INFINITY;
            long long on = 0, off = 0;
            for (size_t i = a; i < b; ++i) {
                const double r = pts[i].second;
                lo = std::min(lo, r);
                hi = std::max(hi, r);
                if (std::fabs(r) <= h) ++on;
                else if (std::fabs(r) <= h + flank) ++off;
            }
            const double offWidth = std::max(0.0, -h - std::max(lo, -h - flank)) + std::max(0.0, std::min(hi, h + flank) - h);
            e.onPoints += on;
            e.offPoints += off;
            extents.push_back(hi - lo);
            if (offWidth > 0) {
                lambda += double(off) * 2 * h / offWidth;
                lambdaPlus += (double(off) + 1.0 / double(slices)) * 2 * h / offWidth;
            }
        }
        // The gate's edges near each point of the track: the 16 nearest points in time off the
        // window (a trend that bends moves the edges within a slice), earlier first where two are
        // as near. Walked over the off-window points only: walking every point of the bin cost
        // n² where nearly all are on the window (a scale that leaves a wide post-fit RMS).
        offWindow.clear();
        for (size_t i = 0; i < n; ++i)
            if (std::fabs(pts[i].second) > h) offWindow.push_back(i);
        size_t next = 0;  // the first off-window point after i
        for (size_t i = 0; i < n; ++i) {
            if (std::fabs(pts[i].second) > h) {
                ++next;
                continue;
            }
            double lo = -h, hi = h;
            size_t a = next, b = next;  // off-window points [a, b) taken
            for (int got = 0; got < 16 && (a > 0 || b < offWindow.size()); ++got) {
                const bool left = a > 0 && (b >= offWindow.size() ||
                                            pts[i].first - pts[offWindow[a - 1]].first <= pts[offWindow[b]].first - pts[i].first);
                const double r = pts[offWindow[left ? --a : b++]].second;
                lo = std::min(lo, r);
                hi = std::max(hi, r);
            }
            rooms.push_back(std::min(-h - lo, hi - h) / (2 * h));
        }
        e.expectedNoise = lambda;
        if (rooms.empty()) {
            e.why = "no point of the bin on the track";
            out.push_back(e);
            continue;
        }
        std::nth_element(rooms.begin(), rooms.begin() + long(rooms.size() / 2), rooms.end());
        e.edgeRoom = rooms[rooms.size() / 2];
        std::nth_element(extents.begin(), extents.begin() + long(extents.size() / 2), extents.end());
        e.trials = std::max(1.0, std::pow(extents[extents.size() / 2] / (2 * h), 2));
        e.noiseShare = e.onPoints > 0 ? std::min(1.0, lambdaPlus / double(e.onPoints)) : 1;
        const double alpha = lambdaPlus / double(e.offPoints + 1);  // window / flanks, as the points measure it
        e.pValue = std::min(1.0, binomialUpperTail(e.onPoints, e.onPoints + e.offPoints, alpha / (1 + alpha)));
        const std::string window = "±" + formatFixed(h * 1e12, 0) + " ps";
        // (only where the noise is dense enough to show the gate: 3 points expected in 10 windows,
        // and the 16 points off the window the room is measured by)
        if (n < size_t(e.onPoints) + 16) {
            ++unmeasured;
            // Fewer than 16 points off the window: too few to measure the noise beside this bin
            // by (a station's narrow gate, the MLRS Beacon-C passes' 15 s bins); the pass-wide
            // test and the window's shape below judge it.
        } else if (e.edgeRoom < kMinEdgeRoom && 10 * lambda >= 3)
            e.why = "its track lies at the edge of the gate (" + formatFixed(std::max(0.0, e.edgeRoom), 1) +
                    " windows from it): a band of noise at the gate's edge cannot be told from a track";
        else if (e.pValue > kMaxBinFalseAlarm)
            e.why = std::to_string(e.onPoints) + " points within " + window + " of the track where the noise beside it puts " +
                    formatFixed(lambda, 1) + ": noise alone does that with a chance of " + formatFixed(e.pValue, 4);
        else if (e.noiseShare > kMaxBinNoiseShare)
            e.why = "about " + formatFixed(100 * e.noiseShare, 0) + " % of its " + std::to_string(e.onPoints) + " points within " +
                    window + " of the track are noise, by the density beside it";
        // (with or without noise beside the bin to measure: λ is 0 where there is none)
        if (e.why.empty() && keptKnown) {
            const double leftOut = double(e.bandPoints - e.keptOnPoints), noise = lambda * band / h;
            if (leftOut > kMaxWindowLeftOut * double(e.bandPoints) + noise + 3 * std::sqrt(noise + 1))
                e.why = "the fit kept " + std::to_string(e.keptOnPoints) + " of the " + std::to_string(e.bandPoints) +
                        " points within ±" + formatFixed(band * 1e12, 0) + " ps of the track, where the noise beside it puts " +
                        formatFixed(noise, 1) + ": the rest of the track was left out as noise, and a normal point of part of a "
                        "track is biased";
        }
        out.push_back(e);
    }
    // The track across the pass: the bins' counts together, against the tracks of that width one
    // could draw across the gate (the trials factor of the widest bin); a bin alone is judged
    // with its track given (the trend rests on the whole pass).
    long long on = 0, off = 0;
    double lam = 0, trials = 1;
    for (const BinEvidence& e : out) {
        on += e.onPoints;
        off += e.offPoints;
        lam += e.expectedNoise;
        trials = std::max(trials, e.trials);
    }
    // The window's shape: one track, or noise that fills it or a floor under a narrow track
    // (where the window spans the gate, the flanks beside it measure nothing).
    if (!out.empty()) {
        // The peakedness is judged where no bin has noise beside its window, or where the fit's
        // band is its whole window (a rejection narrower than 3σ, or the noise band, clips a
        // track's shoulders and flattens it: a Gaussian cut at 1.45σ, the limit a 2σ rejection
        // settles at, gives about 2.3).
        const bool wholeWindow = !(std::isfinite(post.limitS) && post.limitS < 0.99 * h);
        const std::string why = windowShapeDoubt(post, unmeasured == out.size() || wholeWindow);
        if (!why.empty())
            for (BinEvidence& e : out)
                if (e.why.empty()) e.why = why;
    }
    if (!out.empty()) {
        const double alpha = (lam + 1.0 * (h > 0 ? 2 * h / (2 * flank) : 0)) / double(off + 1);
        const double pPass = std::min(1.0, trials * binomialUpperTail(on, on + off, alpha / (1 + alpha)));
        if (pPass > kMaxBinFalseAlarm)
            for (BinEvidence& e : out)
                if (e.why.empty())
                    e.why = "the track's " + std::to_string(on) + " points within ±" + formatFixed(h * 1e12, 0) +
                            " ps, where the noise beside it puts " + formatFixed(lam, 1) +
                            ", could be noise: noise alone does that with a chance of " + formatFixed(pPass, 4) + " (" +
                            formatFixed(trials, 0) + " tracks of that width fit the gate)";
    }
    return out;
}

std::string judgeRun(const ScreenResult& screen, size_t acceptedCount, PostfitResult* post, std::string* postNote) {
    std::string doubt;
    if (acceptedCount > 0) {
        doubt = screen.doubt;
        // A track resting on a handful of image points with more recovered around them: the
        // recovery followed noise (a 2 %-signal lunar-like pass: 4 image points, 30 recovered,
        // 59 % of them noise, one normal point of 378 ps). A filtered pass (no noise floor) is
        // recovered whole by design and is not judged so.
        // Likewise a handful of image points with nothing recovered (issue 41: a 0.5 %-signal
        // debris pass, 20 signal points among 3980: 5 noise points, 1.4 ns apart within 15 s,
        // accepted as the track with exit 0).
        if (doubt.empty() && !screen.floorless && screen.signalPoints < kMinImagePoints) {
            const double sep = post && post->ok ? trackSeparation(*post) : NAN;
            if (!(sep >= kMinTrackSeparation))
                doubt = "the track rests on " + std::to_string(screen.signalPoints) + " point(s) the image found" +
                        (screen.recoveredPoints > 0 ? ", with " + std::to_string(screen.recoveredPoints) + " recovered around them,"
                                                    : std::string(" and none recovered,")) +
                        " and stands " +
                        (std::isfinite(sep) ? formatFixed(sep, 1) + " times" : std::string("not")) +
                        " above the noise's density (at least " + formatFixed(kMinTrackSeparation, 0) +
                        " needed): it cannot be told from noise";
        }
    } else if (!screen.doubt.empty()) {
        // Nothing accepted and no scale showed a track: not "no signal", but a signal (if any)
        // that this method cannot see.
        doubt = "no scale shows a clear track: a signal in this pass, if any, cannot be told from the noise";
    }
    if (doubt.empty() && post && post->ok) {
        std::vector<double> kept;
        for (size_t i = 0; i < post->kept.size(); ++i)
            if (post->kept[i]) kept.push_back(post->residuals[i]);
        doubt = parallelTracks(kept);
    }
    if (!doubt.empty() && post && !post->normalPoints.empty()) {
        post->normalPoints.clear();
        if (postNote) *postNote = "no normal points: " + doubt;
    }
    return doubt;
}

std::vector<std::string> passNormalPointContext(const PassData& pass, const SinexFile* stations, PostfitParams* pp) {
    if (!(pp->altitudeKm > 0)) pp->altitudeKm = pass.altitudeKm;
    if (!pass.hasCrd || pass.passIndex < 0 || size_t(pass.passIndex) >= pass.crd->passes.size()) return {};
    // (day or night unknown: postfit.day_night auto takes the day minimum, 6)
    return fillNormalPointContext(pass.crd->passes[size_t(pass.passIndex)], pass.cdpPad, stations, pp);
}

namespace {
// The screening of a run: the earlier one, or at the scales it chose, or a fresh search.
ScreenResult screenStage(const PassData& pass, const ScreenParams& params, const PassTask::Reuse& reuse, PassRunResult* r,
                         Feedback* fb) {
    if (reuse.screen) {
        r->screenReused = true;
        return *reuse.screen;
    }
    if (reuse.scale) {
        r->scaleReused = true;
        return screenSignal(pass.t, pass.oc, params, *reuse.scale, fb);
    }
    return screenSignal(pass.t, pass.oc, params, fb);
}
}  // namespace

std::vector<double> normalPointTrendErrors(const PassData& pass, const PostfitResult& post) {
    double dof = NAN;
    const std::vector<double> factor = normalPointTrendFactors(pass.t, post, pass.trendHat, &dof);
    double ss = 0;
    for (size_t i = 0; i < pass.t.size() && i < post.kept.size() && i < post.residuals.size(); ++i)
        if (post.kept[i]) ss += post.residuals[i] * post.residuals[i];
    // (less than one degree of freedom left: the fits pass through the points, infinitely imprecise)
    const double sigma = !std::isfinite(dof) ? NAN : dof >= 1 ? std::sqrt(ss / dof) : INFINITY;
    std::vector<double> out(post.normalPoints.size(), NAN);
    for (size_t k = 0; k < out.size() && k < factor.size(); ++k)
        if (std::isfinite(factor[k])) out[k] = factor[k] > 0 ? sigma * factor[k] : 0.0;
    return out;
}

namespace {
// On a short pass on its own fitted TOF trend (PassData::trendHat), each normal point's
// precision as the fitted trends leave it (normalPointTrendErrors); those beyond
// kMaxNpTrendErrorMm are dropped with the reason, and a pass left with none is doubtful (issue
// 43: on sparse LEO passes without a prediction, normal points 5-73 mm off that the trends,
// fitted to the same 10-30 points, had moved). A normal point whose precision could not be
// estimated is not known to be precise: dropped too.
void dropImpreciseNormalPoints(const PassData& pass, PassRunResult* r) {
    const std::vector<double> error = normalPointTrendErrors(pass, r->post);
    std::vector<NormalPoint> precise;
    std::string why;
    for (size_t k = 0; k < r->post.normalPoints.size(); ++k) {
        const NormalPoint& np = r->post.normalPoints[k];
        const double mm = error[k] * 0.5 * kSpeedOfLight * 1e3;
        if (mm <= kMaxNpTrendErrorMm) {
            precise.push_back(np);
        } else if (why.empty()) {  // (NaN: not estimated, so not known to be precise)
            why = "the trends fitted to this pass's " + std::to_string(r->post.stats.n) + " kept points leave the normal point at " +
                  hmsRounded(np.secondsOfDay) + " UTC " +
                  (std::isfinite(mm) ? "±" + formatFixed(mm, 1) + " mm"
                   : std::isinf(mm)  ? std::string("undetermined (no degree of freedom left)")
                                     : std::string("with a precision that could not be estimated")) +
                  " (one sigma; at most " + formatFixed(kMaxNpTrendErrorMm, 1) +
                  " mm kept): a prediction (CPF) would fix the trend";
        }
    }
    const size_t dropped = r->post.normalPoints.size() - precise.size();
    if (dropped == 0) return;
    if (precise.empty()) {
        r->doubt = "no normal point is precise enough: " + why;
        r->post.normalPoints.clear();
        r->postNote = "no normal points: " + r->doubt;
        return;
    }
    r->post.normalPoints = std::move(precise);
    const std::string note = std::to_string(dropped) + " normal point(s) dropped: " + why;
    r->postNote = r->postNote.empty() ? note : r->postNote + "; " + note;
}
}  // namespace

PassRunResult PassTask::run(const Inputs& in, const SlrParams& params, const Reuse& reuse, Feedback* fb) {
    PassRunResult r;
    if (!in.pass) {
        r.error = "no pass";
        return r;
    }
    const PassData& pass = *in.pass;
    const auto t0 = std::chrono::steady_clock::now();
    const PostfitParams pp = postfitForPass(params.postfit, &r.postNote, &pass);
    r.screen = screenStage(pass, params.screen, reuse, &r, fb);
    if (cancelled(fb)) return r;
    if (!r.screen.ok) {
        r.error = "screening failed: " + r.screen.error;
        return r;
    }
    r.accepted = acceptedMask(r.screen);
    r.classes = r.screen.pointClass;
    for (size_t i = 0; i < r.accepted.size() && i < in.forced.size(); ++i)
        if (in.forced[i] != 0) {
            r.accepted[i] = in.forced[i] > 0 ? 1 : 0;
            if ((r.classes[i] == PointClass::Noise) == bool(r.accepted[i]))
                r.classes[i] = r.accepted[i] ? PointClass::Signal : PointClass::Noise;
        }
    for (uint8_t v : r.accepted) r.acceptedCount += v;
    if (r.acceptedCount >= 2) {
        r.post = postfit(pass.t, pass.oc, r.accepted, pass.tof, pp, fb);
        if (cancelled(fb)) return r;
        r.postOk = r.post.ok;
        // Where the binary image stopped, the trend goes on: the points within its band are
        // taken and the trend fitted again with them (once). Only where the noise beside the
        // band was measured and the band set by it (PostfitResult::noiseDensity), so that what
        // the band takes is known to be more signal than noise: on a sparse lunar pass a k·σ
        // band about a trend of a few returns takes noise (issue 43's adversarial passes).
        // Not on a filtered pass, whose screening already kept everything within 5 sigma.
        if (r.post.ok && pp.takeBand && !r.screen.floorless && std::isfinite(r.post.noiseDensity)) {
            const std::vector<uint32_t> more = pointsInBand(pass.t, r.post, r.accepted, in.forced);
            if (!more.empty()) {
                std::vector<uint8_t> accepted = r.accepted;
                for (uint32_t i : more) accepted[i] = 1;
                PostfitResult again = postfit(pass.t, pass.oc, accepted, pass.tof, pp, fb);
                if (cancelled(fb)) return r;
                if (again.ok) {
                    for (uint32_t i : more) r.classes[i] = PointClass::Band;
                    r.accepted = std::move(accepted);
                    r.acceptedCount += more.size();
                    r.bandTaken = static_cast<long long>(more.size());
                    r.post = std::move(again);
                }
            }
        }
        if (!r.post.ok) r.postNote = "post-fit not done: " + r.post.error;
    } else {
        r.post.error = std::to_string(r.acceptedCount) + " point(s) accepted";
        r.postNote = "post-fit not done: " + r.post.error;
    }
    r.doubt = judgeRun(r.screen, r.acceptedCount, r.postOk ? &r.post : nullptr, &r.postNote);
    if (r.acceptedCount == 0 && pass.tof.size() == pass.t.size() && pass.t.size() < kMinOwnTrendPoints &&
        pass.ocOrigin.rfind("fitted TOF trend", 0) == 0)
        r.doubt = std::to_string(pass.t.size()) + " points on the pass's own TOF trend (no prediction): too few to tell "
                  "a track from the trend's misfit; give a CPF (--cpf) to judge this pass";
    // Each normal point must stand above the noise beside it (issue 43: real lunar passes).
    if (r.doubt.empty() && r.postOk && !r.screen.floorless && !r.post.normalPoints.empty()) {
        r.binEvidence = normalPointEvidence(pass.t, r.post);
        std::vector<NormalPoint> standing;
        std::string why;
        for (size_t k = 0; k < r.binEvidence.size(); ++k) {
            if (r.binEvidence[k].why.empty()) standing.push_back(r.post.normalPoints[k]);
            else if (why.empty()) why = r.binEvidence[k].why;
        }
        const size_t dropped = r.post.normalPoints.size() - standing.size();
        if (standing.empty()) {
            r.doubt = "no normal point stands above the noise: " + why;
            r.post.normalPoints.clear();
            r.postNote = "no normal points: " + r.doubt;
        } else if (dropped > 0) {
            r.post.normalPoints = std::move(standing);
            const std::string note = std::to_string(dropped) + " normal point(s) dropped: " + why;
            r.postNote = r.postNote.empty() ? note : r.postNote + "; " + note;
        }
    }
    if (r.doubt.empty() && r.postOk && !r.post.normalPoints.empty() && !pass.trendHat.empty())
        dropImpreciseNormalPoints(pass, &r);
    r.agreement = stationAgreement(pass, r.accepted, r.postOk ? &r.post : nullptr);
    if (r.postOk && r.doubt.empty()) r.bias = passBias(pass, r.post.kept);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.ok = true;
    return r;
}

std::vector<uint32_t> pointsInBand(const std::vector<double>& t, const PostfitResult& post,
                                   const std::vector<uint8_t>& accepted, const std::vector<int8_t>& forced) {
    std::vector<uint32_t> out;
    if (!(post.limitS > 0) || post.residuals.size() != t.size() || accepted.size() != t.size()) return out;
    for (size_t i = 0; i < t.size(); ++i) {
        if (accepted[i] || (i < forced.size() && forced[i] < 0)) continue;
        if (!(std::fabs(post.residuals[i]) <= post.limitS)) continue;
        const bool inside = std::any_of(post.segments.begin(), post.segments.end(),
                                        [&](const TrendSegment& g) { return t[i] >= g.tStart && t[i] <= g.tEnd; });
        if (inside) out.push_back(static_cast<uint32_t>(i));
    }
    return out;
}

PassRunResult runPass(const PassData& pass, const SlrParams& params, Feedback* fb) {
    // The pass is borrowed for the call (an aliasing pointer that owns nothing).
    return runTask<PassTask>({std::shared_ptr<const PassData>(std::shared_ptr<const void>(), &pass), {}}, params, fb);
}

BlockStatus runStatus(const PassData& pass, const PassRunResult& r) {
    if (!r.doubt.empty()) return {"doubtful", r.doubt};
    if (r.acceptedCount == 0) return {"no signal", "no signal found"};
    return {"ok", !pass.ocNote.empty() ? pass.ocNote : r.postNote};
}

}  // namespace lwb::core::slr
