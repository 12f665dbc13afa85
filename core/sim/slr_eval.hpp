#pragma once
// How well a screening did against a simulator's exact truth, and the best any screening could
// do (issue 43, item 4). The ceiling is an oracle's: the true track known at every epoch, every
// point whose residual from it lies in one band [c − w, c + w] is taken, c and w chosen for the
// best F1 against the truth. With noise uniform over the gate and the signal's scatter unimodal
// and the same along the pass (what the simulators make), a fixed band about the true track is
// the best decision rule there is up to the band's choice, so no method that must find the
// track itself can do better, except where the oracle's band takes noise in a stretch without
// signal (a gap), which a method that sees the gap may leave out.
#include <cstdint>
#include <vector>

namespace lwb::core::sim {

struct DetectionScore {
    long long tp = 0, fp = 0, fn = 0;
    double precision = 0, recall = 0, f1 = 0;  ///< 0 where undefined (nothing accepted, no signal)
};
/// accepted and truth per point (non-zero = yes); sizes must match (the shorter one is used).
DetectionScore scoreDetection(const std::vector<uint8_t>& accepted, const std::vector<uint8_t>& truth);

struct BandCeiling {
    DetectionScore score;       ///< of the best band
    double centreS = 0;         ///< c: the band's centre, as an offset from the true track (s)
    double halfWidthS = 0;      ///< w (s)
    double signalSigmaS = 0;    ///< the true signal's RMS about the track (s): w / σ is the band's k
};
/// The oracle ceiling: ocS the points' O-C, trackOcS the true track at each point's epoch,
/// truth per point. Centres are tried over the signal residuals' 30–70 % quantiles (41 of them,
/// and their median), each with every half-width that changes the accepted set.
BandCeiling bandCeiling(const std::vector<double>& ocS, const std::vector<double>& trackOcS,
                        const std::vector<uint8_t>& truth);

}  // namespace lwb::core::sim
