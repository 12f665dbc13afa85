#include "core/sim/footprint_eval.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "core/common/parallel.hpp"
#include "core/common/text.hpp"
#include "core/footprint/crlb.hpp"
#include "core/common/rng.hpp"

namespace lwb::core::sim {

using namespace footprint;

std::vector<MethodVariant> standardVariants() {
    std::vector<MethodVariant> v;
    FootprintParams base;
    FootprintParams gcm = base;
    gcm.method = Method::Gcm;
    v.push_back({"gcm", gcm});
    FootprintParams tefm = base;
    tefm.method = Method::Tefm;
    v.push_back({"tefm", tefm});
    FootprintParams paper = base;
    paper.gauss.xyTerm = false;
    paper.gauss.guoIterations = 0;
    paper.gauss.lmRefine = false;
    v.push_back({"gauss-paper", paper});
    FootprintParams xy = paper;
    xy.gauss.xyTerm = true;
    v.push_back({"gauss-xy", xy});
    FootprintParams guo = xy;
    guo.gauss.guoIterations = base.gauss.guoIterations;
    v.push_back({"gauss-guo", guo});
    v.push_back({"gauss", base});
    return v;
}

bool findVariant(const std::string& name, MethodVariant* out) {
    for (const auto& v : standardVariants())
        if (v.name == name) {
            *out = v;
            return true;
        }
    return false;
}

namespace {
// The 95 % radius of a circular 2-D Gaussian error: 2.4477 σ per axis, and u = √(var x + var y) =
// √2 σ, so √(−ln 0.05) = 1.7308 u (P(|err| < k·u) = 1 − e^(−k²)).
constexpr double kRadius95 = 1.7308;
// The class the ground's true median falls in, with the pipeline's thresholds.
NoiseClass trueClass(double groundMedian, const BackgroundParams& b) {
    if (groundMedian < b.nightBelow) return NoiseClass::Night;
    if (groundMedian < b.weakBelow) return NoiseClass::Weak;
    if (groundMedian <= b.strongAbove) return NoiseClass::Moderate;
    return NoiseClass::Strong;
}

struct ShotOutcome {
    bool fitted = false;
    double err = NAN;
    Verdict verdict = Verdict::Rejected;
    bool classOk = false;
    double reportedCrlb = NAN;
    bool visible = false;
    bool covered = false, covered95 = false;
};
}  // namespace

std::vector<EvalStats> evaluateFootprint(const EvalParams& params, const std::vector<MethodVariant>& variants,
                                         Feedback* fb, std::string* error) {
    std::vector<EvalStats> out;
    for (Scene scene : params.scenes) {
        FootprintSimParams sp = params.sim;
        sp.scene = scene;
        if (const std::string e = groundProblem(sp); !e.empty()) {
            if (error) *error = e;
            return out;
        }
    }
    const size_t nv = variants.size();
    const int total = params.countPerScene * static_cast<int>(params.scenes.size());
    std::atomic<int> progress{0};
    for (Scene scene : params.scenes) {
        if (cancelled(fb)) break;
        const int n = params.countPerScene;
        std::vector<ShotOutcome> outcomes(size_t(n) * nv);
        std::vector<double> crlb(n, NAN);
        std::atomic<int> next{0};
        auto worker = [&](size_t) {
            for (int i = next++; i < n && !cancelled(fb); i = next++) {
                FootprintSimParams sp = params.sim;
                sp.scene = scene;
                sp.spotCase = params.spotCase;
                const FootprintSimShot shot =
                    simulateFootprint(sp, Rng::mix(params.seed, static_cast<uint64_t>(scene) * 1000003ULL + i));
                cv::Mat roi;
                shot.image.convertTo(roi, CV_32F);
                const FootprintSimTruth& t = shot.truth;
                if (t.hasSpot) {
                    const GaussModel gm = truthModel(t);
                    const CrlbResult cr = crlbFisher(gm, roi.cols, roi.rows, sp.camera, 3);
                    if (cr.ok) crlb[i] = cr.radialPx;
                }
                for (size_t v = 0; v < nv; ++v) {
                    const FootprintResult r = processRoi(roi, variants[v].params);
                    ShotOutcome& o = outcomes[size_t(i) * nv + v];
                    o.verdict = r.ok ? r.verdict : Verdict::Rejected;
                    o.classOk = r.ok && trueClass(t.groundMedian, variants[v].params.background) == r.background.noiseClass;
                    o.fitted = r.ok && r.fit.ok && r.verdict != Verdict::Rejected;
                    if (o.fitted && t.hasSpot) o.err = std::hypot(r.fit.x - t.x, r.fit.y - t.y);
                    o.covered = o.fitted && t.hasSpot && o.err < r.fit.uncertaintyPx;
                    o.covered95 = o.fitted && t.hasSpot &&
                                  o.err < (std::isfinite(r.fit.radius95Px) ? r.fit.radius95Px : kRadius95 * r.fit.uncertaintyPx);
                    o.visible = t.hasSpot && t.amplitude >= 5 * std::max(t.textureRms, 1.0);
                    o.reportedCrlb = r.crlbPx;
                }
                const int p = ++progress;
                if (fb && p % 50 == 0) fb->setProgress(static_cast<double>(p) / total);
            }
        };
        int threads = params.threads > 0 ? params.threads : static_cast<int>(std::thread::hardware_concurrency());
        threads = std::max(1, threads);
        runOnThreads(static_cast<size_t>(threads), worker);
        for (size_t v = 0; v < nv; ++v) {
            EvalStats s;
            s.variant = variants[v].name;
            s.scene = scene;
            s.spotCase = params.spotCase;
            s.n = n;
            std::vector<double> errs;
            double crlbSum = 0, repSum = 0;
            int crlbN = 0, repN = 0;
            for (int i = 0; i < n; ++i) {
                const ShotOutcome& o = outcomes[size_t(i) * nv + v];
                if (o.verdict == Verdict::Good) ++s.good;
                else if (o.verdict == Verdict::Doubtful) ++s.doubtful;
                else ++s.rejected;
                if (o.classOk) ++s.classCorrect;
                if (o.fitted) ++s.fitted;
                if (o.visible) ++s.visible;
                if (o.visible && o.fitted) ++s.visibleFitted;
                if (o.covered) ++s.covered;
                if (o.covered95) ++s.covered95;
                if (std::isfinite(o.err)) errs.push_back(o.err);
                if (std::isfinite(crlb[i])) {
                    crlbSum += crlb[i] * crlb[i];
                    ++crlbN;
                }
                if (std::isfinite(o.reportedCrlb)) {
                    repSum += o.reportedCrlb;
                    ++repN;
                }
            }
            if (!errs.empty()) {
                double sum = 0, sum2 = 0;
                for (double e : errs) {
                    sum += e;
                    sum2 += e * e;
                }
                const double m = sum / errs.size();
                s.meanErr = m;
                s.rmsErr = std::sqrt(sum2 / errs.size());
                s.varErr = errs.size() > 1 ? (sum2 - errs.size() * m * m) / (errs.size() - 1) : 0;
                std::sort(errs.begin(), errs.end());
                s.medianErr = errs[errs.size() / 2];
                s.p99Err = errs[std::min(errs.size() - 1, static_cast<size_t>(std::ceil(0.99 * errs.size())) - 1)];
                s.maxErr = errs.back();
            } else {
                s.meanErr = s.rmsErr = s.varErr = s.medianErr = s.p99Err = s.maxErr = NAN;
            }
            s.meanCrlb = crlbN ? std::sqrt(crlbSum / crlbN) : NAN;
            s.meanReportedCrlb = repN ? repSum / repN : NAN;
            out.push_back(s);
        }
    }
    return out;
}

std::string evalTableMarkdown(const std::vector<EvalStats>& stats) {
    std::string t =
        "| method | scene | case | n | fitted | good | doubtful | rejected | mean err (px) | var (px²) | RMS (px) | "
        "median | p99 | max | CRLB (px) | covered by u | by radius95 |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& s : stats) {
        t += "| " + s.variant + " | " + sceneName(s.scene) + " | " + spotCaseName(s.spotCase) + " | " +
             std::to_string(s.n) + " | " + std::to_string(s.fitted) + " | " + std::to_string(s.good) + " | " +
             std::to_string(s.doubtful) + " | " + std::to_string(s.rejected) + " | " + formatFixed(s.meanErr, 3) +
             " | " + formatFixed(s.varErr, 4) + " | " + formatFixed(s.rmsErr, 3) + " | " + formatFixed(s.medianErr, 3) +
             " | " + formatFixed(s.p99Err, 3) + " | " + formatFixed(s.maxErr, 3) + " | " + formatFixed(s.meanCrlb, 4) +
             " | " + (s.fitted ? formatFixed(100.0 * s.covered / s.fitted, 1) + " %" : std::string("—")) + " | " +
             (s.fitted ? formatFixed(100.0 * s.covered95 / s.fitted, 1) + " %" : std::string("—")) + " |\n";
    }
    return t;
}

}  // namespace lwb::core::sim
