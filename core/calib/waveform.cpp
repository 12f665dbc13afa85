#include "core/calib/waveform.hpp"
#include "core/calib/calib_params.hpp"

#include <algorithm>
#include <cmath>

#include "core/calib/geodesy.hpp"
#include "core/calib/least_squares.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"

namespace lwb::core::calib {

Waveform withSampleInterval(const Waveform& w, double sampleIntervalNs) {
    if (!w.timesFromInterval || !(sampleIntervalNs > 0) || sampleIntervalNs == w.readIntervalNs || !(w.readIntervalNs > 0))
        return w;
    Waveform out = w;
    for (double& t : out.timeNs) t = t / w.readIntervalNs * sampleIntervalNs;
    out.readIntervalNs = sampleIntervalNs;
    return out;
}

bool readWaveformCsv(const std::string& path, double dt, Waveform* out, std::string* error) {
    if (!(dt > 0 && std::isfinite(dt))) {
        *error = "sample interval must be > 0 ns";
        return false;
    }
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        *error = csv.error;
        return false;
    }
    const CsvTable& t = csv.table;
    const int ct = t.firstColumn({"time_ns", "t_ns", "time"}), cs = t.firstColumn({"sample", "index"});
    const int ca = t.firstColumn({"amplitude", "value", "counts", "dn"});
    if (ca < 0) {
        *error = path + ":1: header needs an amplitude column (and optionally time_ns or sample)";
        return false;
    }
    Waveform w;
    for (size_t i = 0; i < t.rows.size(); ++i) {
        const auto& row = t.rows[i];
        const std::string where = whereInFile(path, t.lines[i]);
        double a = 0, tt = 0;
        if (!parseDouble(row[ca], &a)) {
            *error = where + "amplitude must be a finite number, not \"" + printableExcerpt(row[ca]) + "\"";
            return false;
        }
        if (ct >= 0) {
            if (!parseDouble(row[ct], &tt)) {
                *error = where + "time must be a finite number, not \"" + printableExcerpt(row[ct]) + "\"";
                return false;
            }
        } else if (cs >= 0) {
            long long k = 0;
            if (!parseLong(row[cs], &k)) {
                *error = where + "sample must be a whole number, not \"" + printableExcerpt(row[cs]) + "\"";
                return false;
            }
            tt = k * dt;
        } else {
            tt = static_cast<double>(i) * dt;
        }
        if (!w.timeNs.empty() && !(tt > w.timeNs.back())) {
            *error = where + "times must increase";
            return false;
        }
        w.timeNs.push_back(tt);
        w.amplitude.push_back(a);
    }
    w.timesFromInterval = ct < 0;
    w.readIntervalNs = dt;
    if (w.timeNs.size() < 10) {
        *error = path + ": only " + std::to_string(w.timeNs.size()) + " samples (a two-peak fit needs at least 10)";
        return false;
    }
    *out = std::move(w);
    return true;
}

std::string validate(const WaveformParams& p) {
    CalibParams c;  // the ranges of the schema's rows (calib_params.cpp)
    c.waveform = p;
    return calibSchema().validate(c, "waveform.");
}

double heightFromDelay(double deltaTNs, double incidenceRad) {
    return deltaTNs * 1e-9 * kSpeedOfLight / 2 / std::cos(incidenceRad);
}

// decomposeWaveform in named stages: the samples checked, a smoothed copy, the two peaks, the
// two-Gaussian fit from them, then the figures and the detection test.
namespace {

// Stage 1. Samples: as many times as amplitudes, at least 10, finite, times increasing.
std::string sampleProblem(const Waveform& w) {
    const size_t n = w.amplitude.size();
    if (w.timeNs.size() != n) return "waveform times and amplitudes differ in length";
    if (n < 10) return "only " + std::to_string(n) + " samples (a two-peak fit needs at least 10)";
    for (size_t i = 0; i < n; ++i) {
        if (!std::isfinite(w.amplitude[i]) || !std::isfinite(w.timeNs[i])) return "sample " + std::to_string(i) + " is not finite";
        if (i && !(w.timeNs[i] > w.timeNs[i - 1])) return "sample times must increase (sample " + std::to_string(i) + ")";
    }
    return {};
}

// Stage 2. The amplitudes smoothed by a Gaussian of sg samples (none below 0.3; a flat line when
// wider than the record).
std::vector<double> smoothed(const std::vector<double>& amp, double sg) {
    const size_t n = amp.size();
    if (sg < 0.3) return amp;
    if (3 * sg >= static_cast<double>(n)) {
        // Smoothing wider than the record: a flat line.
        double mean = 0;
        for (double a : amp) mean += a;
        return std::vector<double>(n, mean / static_cast<double>(n));
    }
    // At most the whole waveform each side: a smoothing wider than the record is a flat
    // line anyway, and an uncapped width (tiny sample spacing) would be a hang.
    std::vector<double> sm(n);
    const long half = static_cast<long>(std::min<double>(std::ceil(3 * sg), static_cast<double>(n)));
    for (size_t i = 0; i < n; ++i) {
        double s = 0, ws = 0;
        for (long k = -half; k <= half; ++k) {
            const long j = static_cast<long>(i) + k;
            if (j < 0 || j >= static_cast<long>(n)) continue;
            const double g = std::exp(-0.5 * k * k / (sg * sg));
            s += g * amp[j];
            ws += g;
        }
        sm[i] = s / ws;
    }
    return sm;
}

// Stage 3. The main peak of the smoothed copy above the baseline base0, and the highest second
// peak at least minSeparationNs away that reaches minSecondPeak of it with a dip between them.
// Their sample indices in time order, or the error.
std::string twoPeaks(const Waveform& w, const std::vector<double>& sm, double base0, const WaveformParams& params, size_t* a,
                     size_t* b) {
    const size_t n = sm.size();
    std::vector<size_t> peaks;
    for (size_t i = 1; i + 1 < n; ++i)
        if (sm[i] > sm[i - 1] && sm[i] >= sm[i + 1] && sm[i] > base0) peaks.push_back(i);
    if (peaks.empty()) return "the waveform has no peak above its baseline";
    size_t p1 = peaks[0];
    for (size_t p : peaks)
        if (sm[p] > sm[p1]) p1 = p;
    const double h1 = sm[p1] - base0;
    long p2 = -1;
    for (size_t p : peaks) {
        if (std::fabs(w.timeNs[p] - w.timeNs[p1]) < params.minSeparationNs) continue;
        if (sm[p] - base0 < params.minSecondPeak * h1) continue;
        // A true second return dips between the peaks.
        const size_t lo = std::min(p, p1), hi = std::max(p, p1);
        double dip = INFINITY;
        for (size_t k = lo; k <= hi; ++k) dip = std::min(dip, sm[k]);
        if (dip > base0 + 0.9 * (std::min(sm[p], sm[p1]) - base0)) continue;
        if (p2 < 0 || sm[p] > sm[static_cast<size_t>(p2)]) p2 = static_cast<long>(p);
    }
    if (p2 < 0)
        return "not a double-peak waveform: no second return at least " + formatDouble(params.minSeparationNs, 4) +
               " ns from the main peak reaching " + formatDouble(100 * params.minSecondPeak, 3) + " % of it";
    *a = std::min(p1, static_cast<size_t>(p2));
    *b = std::max(p1, static_cast<size_t>(p2));
    return {};
}

// Stage 4. Baseline + two Gaussians by Levenberg-Marquardt from the peaks (widths from their
// half maxima, at most half the separation).
LmOutcome fitTwoGaussians(const Waveform& w, const std::vector<double>& sm, double base0, double dt, size_t a, size_t b,
                          int maxIterations) {
    const size_t n = sm.size();
    auto halfWidth = [&](size_t p) {
        const double half = base0 + 0.5 * (sm[p] - base0);
        size_t l = p, r = p;
        while (l > 0 && sm[l] > half) --l;
        while (r + 1 < n && sm[r] > half) ++r;
        const double fwhm = w.timeNs[r] - w.timeNs[l];
        return std::max(fwhm / 2.3548, dt);
    };
    const double sep = w.timeNs[b] - w.timeNs[a];
    Eigen::VectorXd p0(7);
    p0 << base0, sm[a] - base0, w.timeNs[a], std::min(halfWidth(a), sep / 2), sm[b] - base0, w.timeNs[b],
        std::min(halfWidth(b), sep / 2);
    LmProblem prob;
    prob.parameters = 7;
    prob.evaluate = [&](const Eigen::VectorXd& p, Eigen::VectorXd* r, Eigen::MatrixXd* J) {
        if (!(p(3) > 0) || !(p(6) > 0)) return false;
        r->resize(static_cast<int>(n));
        if (J) J->resize(static_cast<int>(n), 7);
        for (size_t i = 0; i < n; ++i) {
            const int k = static_cast<int>(i);
            const double t = w.timeNs[i];
            const double u1 = (t - p(2)) / p(3), u2 = (t - p(5)) / p(6);
            const double g1 = std::exp(-0.5 * u1 * u1), g2 = std::exp(-0.5 * u2 * u2);
            (*r)(k) = p(0) + p(1) * g1 + p(4) * g2 - w.amplitude[i];
            if (!J) continue;
            (*J)(k, 0) = 1;
            (*J)(k, 1) = g1;
            (*J)(k, 2) = p(1) * g1 * u1 / p(3);
            (*J)(k, 3) = p(1) * g1 * u1 * u1 / p(3);
            (*J)(k, 4) = g2;
            (*J)(k, 5) = p(4) * g2 * u2 / p(6);
            (*J)(k, 6) = p(4) * g2 * u2 * u2 / p(6);
        }
        return true;
    };
    LmOptions opt;
    opt.maxIterations = maxIterations;
    return levenbergMarquardt(prob, p0, opt);
}

// Stage 6. A detection test: each return must stand at least kDetectSigma times the samples'
// noise (the residual RMS about the model) above the baseline. A noise-only waveform was
// "decomposed" into returns at 46.6 and 92.2 ns, h 6.83 +- 215.7 m, and matched a feature.
void detectionTest(WaveformResult* res) {
    constexpr double kDetectSigma = 5;
    const double noise = std::max(res->rmsResidual, 1e-300);
    for (const GaussComponent* g : {&res->first, &res->second})
        if (res->ok && !(g->amplitude >= kDetectSigma * noise)) {
            res->ok = false;
            res->error = std::string("no double return stands out of the noise: the ") +
                         (g == &res->first ? "earlier" : "later") + " return at " + formatFixed(g->centreNs, 1) + " ns is " +
                         formatFixed(g->amplitude / noise, 1) + " times the noise RMS (" + formatDouble(noise, 4) +
                         "), a return needs " + formatFixed(kDetectSigma, 0) + ": no height from this waveform";
        }
}

}  // namespace

WaveformResult decomposeWaveform(const Waveform& w, const WaveformParams& params) {
    WaveformResult res;
    if (const std::string e = validate(params); !e.empty()) {
        res.error = e;
        return res;
    }
    if (std::string e = sampleProblem(w); !e.empty()) {
        res.error = std::move(e);
        return res;
    }
    const size_t n = w.amplitude.size();
    const double dt = (w.timeNs.back() - w.timeNs.front()) / (n - 1);
    // Peak search on a smoothed copy.
    const std::vector<double> sm = smoothed(w.amplitude, params.smoothSigmaNs / dt);
    std::vector<double> sorted = w.amplitude;
    std::nth_element(sorted.begin(), sorted.begin() + n / 4, sorted.end());
    const double base0 = sorted[n / 4];  // lower quartile: the baseline under sparse returns
    size_t a = 0, b = 0;
    if (std::string e = twoPeaks(w, sm, base0, params, &a, &b); !e.empty()) {
        res.error = std::move(e);
        return res;
    }
    const LmOutcome o = fitTwoGaussians(w, sm, base0, dt, a, b, params.maxIterations);
    if (!o.ok) {
        res.error = "waveform decomposition failed: " + o.error;
        return res;
    }
    // Stage 5. The returns in time order with their σ, the delay, the height and the model.
    if (!o.converged) res.warnings.push_back("the decomposition stopped at the iteration limit before converging");
    Eigen::VectorXd p = o.params;
    Eigen::MatrixXd cov;
    double rcond = 0;
    if (!covarianceFromJacobian(o.jacobian, 1e-13, &cov, &rcond)) {
        res.error = "the two returns are not separable in this waveform (singular fit)";
        return res;
    }
    const int dof = static_cast<int>(n) - 7;
    cov *= o.cost / std::max(dof, 1);
    int i1 = 1, i2 = 4;
    if (p(5) < p(2)) std::swap(i1, i2);
    auto comp = [&](int i) {
        GaussComponent c;
        c.amplitude = p(i);
        c.centreNs = p(i + 1);
        c.sigmaNs = p(i + 2);
        c.amplitudeSd = std::sqrt(cov(i, i));
        c.centreSdNs = std::sqrt(cov(i + 1, i + 1));
        c.sigmaSdNs = std::sqrt(cov(i + 2, i + 2));
        return c;
    };
    res.first = comp(i1);
    res.second = comp(i2);
    res.baseline = p(0);
    if (res.first.amplitude <= 0 || res.second.amplitude <= 0) {
        res.error = "the decomposition produced a negative return: not a double-peak waveform";
        return res;
    }
    res.deltaTNs = res.second.centreNs - res.first.centreNs;
    res.deltaTSdNs = sqrtVariance(cov(i1 + 1, i1 + 1) + cov(i2 + 1, i2 + 1) - 2 * cov(i1 + 1, i2 + 1));
    const double th = params.incidenceDeg * kDeg;
    res.heightM = heightFromDelay(res.deltaTNs, th);
    res.heightSdM = heightFromDelay(res.deltaTSdNs, th);
    res.iterations = static_cast<int>(o.history.size()) - 1;
    res.rmsResidual = std::sqrt(o.cost / n);
    res.model.resize(n);
    for (size_t i = 0; i < n; ++i) res.model[i] = o.residuals(static_cast<int>(i)) + w.amplitude[i];
    if (res.deltaTNs < 2 * std::max(res.first.sigmaNs, res.second.sigmaNs))
        res.warnings.push_back("the two returns overlap (separation < 2 sigma): the height is less reliable");
    if (res.first.centreNs < w.timeNs.front() || res.second.centreNs > w.timeNs.back())
        res.warnings.push_back("a fitted return lies outside the sampled window");
    res.ok = std::isfinite(res.heightM);
    if (!res.ok) res.error = "the decomposition produced a non-finite height";
    detectionTest(&res);
    return res;
}

bool readFeatureCsv(const std::string& path, std::vector<FeatureCandidate>* out, std::string* error) {
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        *error = csv.error;
        return false;
    }
    const CsvTable& t = csv.table;
    const int cid = t.firstColumn({"id", "feature", "name"}), ch = t.firstColumn({"h", "height", "height_m"});
    int ce = t.firstColumn({"e", "east", "x", "lat", "latitude"}), cn = t.firstColumn({"n", "north", "y", "lon", "longitude"});
    if (ch < 0) {
        *error = path + ":1: header needs a height column (h)";
        return false;
    }
    std::vector<FeatureCandidate> v;
    for (size_t i = 0; i < t.rows.size(); ++i) {
        const auto& row = t.rows[i];
        const std::string where = whereInFile(path, t.lines[i]);
        FeatureCandidate c;
        c.line = t.lines[i];
        c.id = cid >= 0 ? std::string(trim(row[cid])) : std::to_string(i + 1);
        if (!parseDouble(row[ch], &c.heightM)) {
            *error = where + "height must be a finite number, not \"" + printableExcerpt(row[ch]) + "\"";
            return false;
        }
        if (ce >= 0 && !trim(row[ce]).empty() && !parseDouble(row[ce], &c.e)) {
            *error = where + "position must be a finite number, not \"" + printableExcerpt(row[ce]) + "\"";
            return false;
        }
        if (cn >= 0 && !trim(row[cn]).empty() && !parseDouble(row[cn], &c.n)) {
            *error = where + "position must be a finite number, not \"" + printableExcerpt(row[cn]) + "\"";
            return false;
        }
        v.push_back(std::move(c));
    }
    if (v.empty()) {
        *error = path + ": no candidate rows";
        return false;
    }
    *out = std::move(v);
    return true;
}

std::string validate(const FeatureMatchParams& p) {
    CalibParams c;  // the range of the schema's row (calib_params.cpp)
    c.match = p;
    return calibSchema().validate(c, "waveform.thred_h");
}

FeatureMatchResult matchFeature(const std::vector<FeatureCandidate>& candidates, double hWaveform,
                                const FeatureMatchParams& params) {
    FeatureMatchResult res;
    if (const std::string e = validate(params); !e.empty()) {
        res.error = e;
        return res;
    }
    if (!std::isfinite(hWaveform)) {
        res.error = "the waveform height is not a finite number";
        return res;
    }
    if (candidates.empty()) {
        res.error = "no candidate features";
        return res;
    }
    for (size_t i = 0; i < candidates.size(); ++i) {
        if (!std::isfinite(candidates[i].heightM)) {
            res.error = "candidate " + candidates[i].id + " has no finite height";
            return res;
        }
        const double d = std::fabs(candidates[i].heightM - hWaveform);
        res.ranking.push_back({i, d, d <= params.thresholdM + 1e-9});
    }
    std::stable_sort(res.ranking.begin(), res.ranking.end(),
                     [](const FeatureDelta& a, const FeatureDelta& b) { return a.deltaHM < b.deltaHM; });
    res.best = res.ranking[0].index;
    res.bestDeltaHM = res.ranking[0].deltaHM;
    res.found = res.ranking[0].belowThreshold;
    if (res.found && res.ranking.size() > 1 && res.ranking[1].belowThreshold)
        res.warnings.push_back("ambiguous: candidates " + candidates[res.ranking[0].index].id + " and " +
                               candidates[res.ranking[1].index].id + " are both within thred_h of the waveform height");
    res.ok = true;
    return res;
}

}  // namespace lwb::core::calib
