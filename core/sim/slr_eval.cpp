#include "core/sim/slr_eval.hpp"

#include <algorithm>
#include <cmath>

namespace lwb::core::sim {

namespace {

void finish(DetectionScore* s) {
    s->precision = s->tp + s->fp ? double(s->tp) / double(s->tp + s->fp) : 0;
    s->recall = s->tp + s->fn ? double(s->tp) / double(s->tp + s->fn) : 0;
    s->f1 = s->precision + s->recall > 0 ? 2 * s->precision * s->recall / (s->precision + s->recall) : 0;
}

}  // namespace

DetectionScore scoreDetection(const std::vector<uint8_t>& accepted, const std::vector<uint8_t>& truth) {
    DetectionScore s;
    const size_t n = std::min(accepted.size(), truth.size());
    for (size_t i = 0; i < n; ++i) {
        const bool a = accepted[i] != 0, t = truth[i] != 0;
        s.tp += a && t;
        s.fp += a && !t;
        s.fn += !a && t;
    }
    finish(&s);
    return s;
}

BandCeiling bandCeiling(const std::vector<double>& ocS, const std::vector<double>& trackOcS,
                        const std::vector<uint8_t>& truth) {
    BandCeiling best;
    const size_t n = std::min({ocS.size(), trackOcS.size(), truth.size()});
    std::vector<double> sig;
    long long signal = 0;
    for (size_t i = 0; i < n; ++i)
        if (truth[i]) {
            sig.push_back(ocS[i] - trackOcS[i]);
            ++signal;
        }
    best.score.fn = signal;
    if (sig.empty()) return best;
    double mean = 0;
    for (double d : sig) mean += d;
    mean /= double(sig.size());
    double ss = 0;
    for (double d : sig) ss += (d - mean) * (d - mean);
    best.signalSigmaS = std::sqrt(ss / double(sig.size()));
    std::sort(sig.begin(), sig.end());
    auto quantile = [&](double q) { return sig[std::min(sig.size() - 1, size_t(q * double(sig.size() - 1) + 0.5))]; };
    std::vector<double> centres{quantile(0.5)};
    for (int k = 0; k <= 40; ++k) centres.push_back(quantile(0.3 + 0.4 * k / 40.0));
    std::vector<std::pair<double, uint8_t>> dist(n);
    for (double c : centres) {
        for (size_t i = 0; i < n; ++i) dist[i] = {std::fabs(ocS[i] - trackOcS[i] - c), truth[i] ? uint8_t(1) : uint8_t(0)};
        std::sort(dist.begin(), dist.end());
        long long tp = 0, fp = 0;
        for (size_t i = 0; i < n; ++i) {
            (dist[i].second ? tp : fp) += 1;
            if (i + 1 < n && dist[i + 1].first == dist[i].first) continue;  // a width takes ties together
            const double f1 = 2.0 * double(tp) / double(2 * tp + fp + (signal - tp));
            if (f1 > best.score.f1) {
                best.score.tp = tp;
                best.score.fp = fp;
                best.score.fn = signal - tp;
                best.score.f1 = f1;
                best.centreS = c;
                best.halfWidthS = dist[i].first;
            }
        }
    }
    finish(&best.score);
    return best;
}

}  // namespace lwb::core::sim
