#pragma once
// Track following after the binary-image screening (issue 13): the screening finds the pieces of
// a track that form dense, straight regions at the chosen scale; on a hard pass (a steep, curved
// track; gaps of tens of seconds; a signal fraction of a few percent in daylight) it misses the
// stretches between those pieces, the sparse ends of the arc and pieces on the far side of a
// gap. This step follows the track from the accepted pieces through the whole pass.
//
// Method. Points in time order. Anchors: runs of `anchorPoints` consecutive accepted points that
// a quadratic fits to within the track's width (the best run first). From an anchor the track
// is followed forwards and backwards: a local polynomial (degree 2, or 1 / 0 with few points)
// through the last `fitPoints` followed points predicts the track beyond the frontier; the
// search band is k·σ·sqrt(1 + prediction variance) widened by the extrapolated curvature term
// |c₂|·Δ² (the unknown change of curvature across a gap), at most an eighth of the O-C span.
// The window beyond the frontier starts at a few typical spacings and doubles up to maxGapS.
// Candidates in the band are refitted together with the followed points and the inconsistent
// ones (beyond k·σ of the refit) dropped one by one; the rest are taken when their number is
// improbable for noise alone: the noise density (points per second per second of O-C, measured
// locally from the points the screening called noise, over the robust O-C span) times the
// band's area gives the expected count E, and the Poisson tail P(N ≥ m | E) must be below
// alpha (the density contrast along the candidate track, not an absolute area). A gap is
// crossed when the piece beyond it lies in the band; the piece on the other side is followed
// from its own anchor backwards too, so a gap is bridged from both sides.
// Accepted points that a followed stretch passes farther than dropSigma·σ from the track are
// returned to noise (a noise region the image took for part of the line).
#include <cstdint>
#include <vector>

#include "core/common/feedback.hpp"

namespace lwb::core::slr {

struct FollowParams {
    double bandSigma = 3.5;      ///< k: half-width of the band about the local fit, in robust σ; 2..10
    double alpha = 1e-4;       ///< false-alarm probability allowed per step (Poisson tail); (0, 0.1]
    double maxGapS = 0;        ///< longest stretch without returns that is bridged (s); 0 = automatic:
                               ///< a quarter of the pass, at least 30 s, at most 300 s
    int anchorPoints = 8;      ///< consecutive accepted points of an anchor; 4..100
    int fitPoints = 16;        ///< followed points in the local fit; 8..1000
    double dropSigma = 10;     ///< accepted points this far from a followed stretch become noise; 0 = keep all
};

struct FollowResult {
    bool ok = false;
    std::vector<uint8_t> accepted;  ///< per point (input order): 1 = on the track after following
    long long added = 0;            ///< points accepted that the screening had called noise
    long long dropped = 0;          ///< screening-accepted points returned to noise
    int pieces = 0;                 ///< anchors followed
    double sigmaS = 0;              ///< robust track width of the first anchor (s)
};

/// Follows the track from the accepted points (`accepted`: 1 = accepted by the screening).
/// t and oc in seconds, same length, finite. Deterministic. With fewer than anchorPoints
/// accepted points nothing changes (ok = true, the mask as given).
FollowResult followTrack(const std::vector<double>& t, const std::vector<double>& oc,
                         const std::vector<uint8_t>& accepted, const FollowParams& params,
                         const Feedback* fb = nullptr);

/// Leave-one-out residuals about the local track: for each point of `idx` (indices into t/oc,
/// in time order), O-C minus a quadratic through its `side` neighbours on each side in that list
/// (fewer at the ends). NaN where fewer than 3 neighbours exist. Used for the track width here
/// and for the gross-outlier test before the post-fit.
std::vector<double> localTrackResiduals(const std::vector<double>& t, const std::vector<double>& oc,
                                        const std::vector<uint32_t>& idx, int side = 4);

/// P(N ≥ m) for N ~ Poisson(mean): the chance that noise alone puts m or more points in a band.
double poissonTail(long long m, double mean);

}  // namespace lwb::core::slr
