#pragma once
// Quality verdict of a fitted spot: good / doubtful / rejected with the failed criteria.
// Presets: wu2021 (paper 000 step 7) and yao2021 (paper 001 step 6).
#include <cmath>
#include <string>
#include <vector>

#include "core/footprint/segment.hpp"
#include "core/footprint/spot.hpp"

namespace lwb::core::footprint {

enum class Verdict { Good, Doubtful, Rejected };
const char* verdictName(Verdict v);
bool parseVerdict(const std::string& s, Verdict* v);

/// An inclusive range lo ≤ value ≤ hi that can be switched off.
struct Range {
    bool enabled = false;
    double lo = 0, hi = 0;
    bool contains(double v) const { return v >= lo && v <= hi; }
};

struct VerdictParams {
    Range axisRatio{true, 1.0, 1.5};      ///< C = sigmaX / sigmaY (paper 000: (1, 1.5))
    Range majorAxisPx{true, 10, 18};      ///< L_A, full major axis at 1/e² (px) (paper 000: (10, 18))
    Range tiltDeg{true, -30, 30};         ///< θ of the x-near axis (deg) (paper 000: (−30°, 30°))
    Range eccentricity{false, 0.2, 0.8};  ///< paper 001: 0.2–0.8
    bool mseEnabled = true;
    double mseMax = 1e-5;                 ///< paper 000 eq. 8 residual, f normalised to unit sum
    /// A centre whose uncertainty_px (1-σ radial, from the shot's own ground for the Gaussian
    /// fit) exceeds this is doubtful: the shot does not locate the footprint to the precision
    /// the geolocation needs, whatever its shape.
    bool maxUncertaintyEnabled = true;
    double maxUncertaintyPx = 0.5;
    bool checkEdge = true;                ///< the spot's ellipse (1/e² × edgeExtent) must lie inside the ROI
    /// 1.25: the 2.5σ ellipse of a Gaussian (the 1/e² one leaves a spot whose minor axis points at
    /// an edge 4 px away "inside", with a tenth of its light cut off by the ROI's border).
    double edgeExtent = 1.25;
    bool checkSaturation = true;
    int saturationMaxPixels = 0;          ///< more saturated domain pixels than this: doubtful
    bool checkSecondSpot = true;
    double secondSpotFraction = 0.35;     ///< a separate peak this strong (of the main amplitude): doubtful
};

/// Known preset names, in display order.
std::vector<std::string> verdictPresetNames();
/// The named preset's criteria; false when the name is unknown.
bool verdictPreset(const std::string& name, VerdictParams* out);

struct Judgement {
    Verdict verdict = Verdict::Rejected;
    std::vector<std::string> reasons;  ///< every failed criterion, e.g. "axis_ratio 1.62 not in [1, 1.5]"
};

/// What the criteria look at, measured once from a fit and its domain: the verdict is these
/// numbers against the criteria (checkVerdict), so that a tuning (core/footprint/tune.hpp) can
/// judge the same shots under many criteria without fitting again.
struct VerdictMeasures {
    std::string refusal;        ///< not empty: no spot, or the fit failed (rejected, this reason)
    double axisRatio = NAN, majorAxisPx = NAN, tiltDeg = NAN, eccentricity = NAN, mse = NAN, uncertaintyPx = NAN;
    /// The largest edge_extent at which the spot's ellipse stays inside the ROI (pixel edges at
    /// −0.5 and size − 0.5); negative when the centre is outside; an axis without a number (a
    /// NaN centre or size) is left out, infinity when neither has one.
    double edgeRoom = INFINITY;
    int saturatedPixels = 0;
    bool faint = false;         ///< found by the ring look only: doubtful whatever the criteria
    double peakSnr = 0, localPeakSnr = 0, localTextureSnr = 0;
    double secondPeakFraction = 0;
    int secondPeakX = -1, secondPeakY = -1;
    /// The Gaussian fit had to start from moments (why): doubtful at best, whatever the criteria.
    std::string startNote;
};

/// The measures of a fit. `domain` supplies the no-spot, saturation and second-spot ones;
/// roiWidth / roiHeight the edge room.
VerdictMeasures measureVerdict(const SpotFit& fit, const SpotDomain& domain, int roiWidth, int roiHeight);

/// The verdict of measures under the criteria, with every failed criterion in *reasons; without
/// reasons (nullptr) it stops at the first failure and writes no text (a tuning's inner loop).
/// A criterion whose value the method does not give (NaN) is skipped.
Verdict checkVerdict(const VerdictMeasures& m, const VerdictParams& params, std::vector<std::string>* reasons = nullptr);

/// Judges a fit: checkVerdict(measureVerdict(...)) with its reasons.
Judgement judge(const SpotFit& fit, const SpotDomain& domain, int roiWidth, int roiHeight,
                const VerdictParams& params);


}  // namespace lwb::core::footprint
