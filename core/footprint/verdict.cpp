#include "core/footprint/verdict.hpp"

#include <cmath>

#include "core/common/text.hpp"

namespace lwb::core::footprint {

const char* verdictName(Verdict v) {
    switch (v) {
        case Verdict::Good: return "good";
        case Verdict::Doubtful: return "doubtful";
        case Verdict::Rejected: return "rejected";
    }
    return "?";
}

bool parseVerdict(const std::string& s, Verdict* v) {
    const std::string l = toLower(trim(s));
    if (l == "good") *v = Verdict::Good;
    else if (l == "doubtful") *v = Verdict::Doubtful;
    else if (l == "rejected") *v = Verdict::Rejected;
    else return false;
    return true;
}

std::vector<std::string> verdictPresetNames() { return {"wu2021", "yao2021"}; }

bool verdictPreset(const std::string& name, VerdictParams* out) {
    VerdictParams p;
    if (name == "wu2021") {
        // Paper 000 step 7: C ∈ (1, 1.5), L_A ∈ (10, 18) px, MSE < 1e-5, θ ∈ (−30°, 30°).
    } else if (name == "yao2021") {
        // Paper 001 step 6: eccentricity 0.2–0.8, axis limit widened to 20 px.
        p.axisRatio.enabled = false;
        p.majorAxisPx = {true, 0, 20};
        p.tiltDeg.enabled = false;
        p.eccentricity = {true, 0.2, 0.8};
        p.mseEnabled = false;
    } else {
        return false;
    }
    *out = p;
    return true;
}

namespace {
std::string rangeText(const Range& r) {
    return "[" + formatDouble(r.lo, 4) + ", " + formatDouble(r.hi, 4) + "]";
}
void checkRange(const char* name, double v, const Range& r, int digits, std::vector<std::string>* reasons) {
    if (!r.enabled || std::isnan(v) || r.contains(v)) return;
    reasons->push_back(std::string(name) + " " + formatDouble(v, digits) + " not in " + rangeText(r));
}
}  // namespace

Judgement judge(const SpotFit& fit, const SpotDomain& domain, int roiWidth, int roiHeight,
                const VerdictParams& p) {
    Judgement j;
    if (!domain.found) {
        j.reasons.push_back(domain.why.empty() ? "no spot" : domain.why);
        return j;
    }
    if (!fit.ok) {
        j.reasons.push_back(fit.error.empty() ? "fit failed" : fit.error);
        return j;
    }
    checkRange("axis_ratio", fit.axisRatio, p.axisRatio, 3, &j.reasons);
    checkRange("major_axis_px", fit.majorAxisPx, p.majorAxisPx, 3, &j.reasons);
    checkRange("tilt_deg", fit.tiltRad * 180.0 / M_PI, p.tiltDeg, 3, &j.reasons);
    checkRange("eccentricity", fit.eccentricity, p.eccentricity, 3, &j.reasons);
    if (p.mseEnabled && std::isfinite(fit.mse) && !(fit.mse < p.mseMax))
        j.reasons.push_back("mse " + formatDouble(fit.mse, 3) + " not below " + formatDouble(p.mseMax, 3));
    if (p.maxUncertaintyEnabled && std::isfinite(fit.uncertaintyPx) && fit.uncertaintyPx > p.maxUncertaintyPx)
        j.reasons.push_back("uncertainty_px " + formatDouble(fit.uncertaintyPx, 3) + " above " +
                            formatDouble(p.maxUncertaintyPx, 4));
    if (p.checkEdge) {
        // Half extents of the ellipse of full axes major/minor at the fit's orientation.
        const double big = std::max(fit.sigmaX, fit.sigmaY);
        const double scale = big > 0 ? 0.5 * fit.majorAxisPx / big * p.edgeExtent : 0;
        const double ax = fit.sigmaX * scale, ay = fit.sigmaY * scale;
        const double c = std::cos(fit.tiltRad), s = std::sin(fit.tiltRad);
        const double hx = std::hypot(ax * c, ay * s), hy = std::hypot(ax * s, ay * c);
        if (fit.x - hx < -0.5 || fit.y - hy < -0.5 || fit.x + hx > roiWidth - 0.5 || fit.y + hy > roiHeight - 0.5)
            j.reasons.push_back("spot touches the ROI edge");
    }
    if (p.checkSaturation && domain.saturatedPixels > p.saturationMaxPixels)
        j.reasons.push_back("saturated: " + std::to_string(domain.saturatedPixels) + " px at full scale");
    if (domain.faint)
        j.reasons.push_back("faint: peak " + formatDouble(domain.peakSnr, 3) + " sigma above the ROI's ground, " +
                            formatDouble(domain.localPeakSnr, 3) + " above the ring around it, " +
                            formatDouble(domain.localTextureSnr, 3) + " above its pixel-scale texture");
    if (p.checkSecondSpot && domain.secondPeakFraction >= p.secondSpotFraction)
        j.reasons.push_back("second spot at (" + std::to_string(domain.secondPeakX) + ", " +
                            std::to_string(domain.secondPeakY) + "), " +
                            formatDouble(100 * domain.secondPeakFraction, 3) + "% of the main peak");
    j.verdict = j.reasons.empty() ? Verdict::Good : Verdict::Doubtful;
    return j;
}

}  // namespace lwb::core::footprint
