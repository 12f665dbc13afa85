#pragma once
// Display limits and stretches for image viewing, as in SAOImage DS9: IRAF's zscale limits and
// the linear / sqrt / log / asinh stretches of normalised values. Pure math, no Qt.
#include <cstddef>
#include <string>
#include <vector>

namespace lwb::core {

/// IRAF zscale (the `display` task's algorithm, as its documentation describes it): sample the
/// image, sort the samples, fit a straight line to sorted value against rank with iterative
/// k-sigma rejection (rejected points grown by 1 % of the sample), and show
/// median ± (half the sample) × slope / contrast, clipped to the sample's min and max.
struct ZScaleParams {
    size_t maxSamples = 1000;   ///< at most this many pixels, taken at an even stride
    double contrast = 0.25;     ///< the slope is divided by it (smaller: wider limits)
    double rejectSigma = 2.5;   ///< k of the k-sigma rejection of fit residuals
    int maxIterations = 5;
    double maxReject = 0.5;     ///< give up (use min/max) when fewer than this share of samples remain
    size_t minSamples = 5;
};

struct ZScaleResult {
    bool ok = false;
    std::string error;
    double z1 = 0, z2 = 0;      ///< display limits
    double slope = 0;           ///< fitted slope per sample rank (before the contrast)
    size_t samples = 0, used = 0;  ///< samples taken; left after rejection
    bool fitFailed = false;     ///< too many rejected: z1, z2 are the sample's min and max
};

/// Non-finite values are skipped. An empty (or all non-finite) input gives ok = false.
ZScaleResult zscale(const float* values, size_t count, const ZScaleParams& p = {});

enum class StretchKind { Linear, Sqrt, Log, Asinh };
const char* stretchKindName(StretchKind k);

struct StretchParams {
    double logExponent = 1000;  ///< a of log(a x + 1) / log(a + 1) (DS9's default 1000)
    double asinhScale = 10;     ///< b of asinh(b x) / asinh(b) (DS9 uses asinh(10 x) / 3)
};

/// Maps x in [0, 1] (value between the limits) to [0, 1]; x is clamped first. Every stretch is
/// monotonic with f(0) = 0 and f(1) = 1.
double applyStretch(StretchKind k, double x, const StretchParams& p = {});
/// The inverse: the normalised value that the stretch maps to y (for colour-bar ticks).
double invertStretch(StretchKind k, double y, const StretchParams& p = {});

/// Limits from the min and max, or from percentiles (lo, hi in 0..100) of the finite values.
struct DisplayLimits {
    bool ok = false;
    double lo = 0, hi = 1;
};
DisplayLimits minMaxLimits(const float* values, size_t count);
DisplayLimits percentileLimits(const float* values, size_t count, double loPercent, double hiPercent);

/// Counts of finite values in `bins` equal bins over [lo, hi] (values outside are not counted).
std::vector<size_t> histogram(const float* values, size_t count, double lo, double hi, int bins);

}  // namespace lwb::core
