#include "core/footprint/verdict.hpp"

#include <algorithm>
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
// One failed criterion: true when the check is to stop (no reasons wanted).
bool fails(std::vector<std::string>* reasons, const std::string& why) {
    if (!reasons) return true;
    reasons->push_back(why);
    return false;
}
bool failsRange(const char* name, double v, const Range& r, int digits, std::vector<std::string>* reasons) {
    if (!r.enabled || std::isnan(v) || r.contains(v)) return false;
    return reasons ? fails(reasons, std::string(name) + " " + formatDouble(v, digits) + " not in " + rangeText(r)) : true;
}
// The room along one axis: the extent e at which centre ∓ e·h reaches the pixel edge `dist` away.
double room(double dist, double h) {
    if (std::isnan(dist) || std::isnan(h)) return NAN;
    if (h > 0) return dist / h;
    return dist >= 0 ? INFINITY : -INFINITY;
}
}  // namespace

VerdictMeasures measureVerdict(const SpotFit& fit, const SpotDomain& domain, int roiWidth, int roiHeight) {
    VerdictMeasures m;
    if (!domain.found) {
        m.refusal = domain.why.empty() ? "no spot" : domain.why;
        return m;
    }
    if (!fit.ok) {
        m.refusal = fit.error.empty() ? "fit failed" : fit.error;
        return m;
    }
    m.axisRatio = fit.axisRatio;
    m.majorAxisPx = fit.majorAxisPx;
    m.tiltDeg = fit.tiltRad * 180.0 / M_PI;
    m.eccentricity = fit.eccentricity;
    m.mse = fit.mse;
    m.uncertaintyPx = fit.uncertaintyPx;
    // Half extents, per unit of edge_extent, of the ellipse of full axes major/minor at the
    // fit's orientation.
    const double big = std::max(fit.sigmaX, fit.sigmaY);
    const double scale = big > 0 ? 0.5 * fit.majorAxisPx / big : 0;
    const double ax = fit.sigmaX * scale, ay = fit.sigmaY * scale;
    const double c = std::cos(fit.tiltRad), s = std::sin(fit.tiltRad);
    const double hx = std::hypot(ax * c, ay * s), hy = std::hypot(ax * s, ay * c);
    const double rooms[4] = {room(fit.x + 0.5, hx), room(roiWidth - 0.5 - fit.x, hx), room(fit.y + 0.5, hy),
                             room(roiHeight - 0.5 - fit.y, hy)};
    // (an axis without a number is not checked, as a comparison with NaN never failed)
    for (double r : rooms)
        if (!std::isnan(r)) m.edgeRoom = std::min(m.edgeRoom, r);
    m.saturatedPixels = domain.saturatedPixels;
    m.faint = domain.faint;
    m.peakSnr = domain.peakSnr;
    m.localPeakSnr = domain.localPeakSnr;
    m.localTextureSnr = domain.localTextureSnr;
    m.secondPeakFraction = domain.secondPeakFraction;
    m.secondPeakX = domain.secondPeakX;
    m.secondPeakY = domain.secondPeakY;
    return m;
}

Verdict checkVerdict(const VerdictMeasures& m, const VerdictParams& p, std::vector<std::string>* reasons) {
    if (!m.refusal.empty()) {
        if (reasons) reasons->push_back(m.refusal);
        return Verdict::Rejected;
    }
    const size_t before = reasons ? reasons->size() : 0;
    if (failsRange("axis_ratio", m.axisRatio, p.axisRatio, 3, reasons) ||
        failsRange("major_axis_px", m.majorAxisPx, p.majorAxisPx, 3, reasons) ||
        failsRange("tilt_deg", m.tiltDeg, p.tiltDeg, 3, reasons) ||
        failsRange("eccentricity", m.eccentricity, p.eccentricity, 3, reasons))
        return Verdict::Doubtful;
    if (p.mseEnabled && std::isfinite(m.mse) && !(m.mse < p.mseMax) &&
        fails(reasons, reasons ? "mse " + formatDouble(m.mse, 3) + " not below " + formatDouble(p.mseMax, 3) : ""))
        return Verdict::Doubtful;
    if (p.maxUncertaintyEnabled && std::isfinite(m.uncertaintyPx) && m.uncertaintyPx > p.maxUncertaintyPx &&
        fails(reasons, reasons ? "uncertainty_px " + formatDouble(m.uncertaintyPx, 3) + " above " +
                                     formatDouble(p.maxUncertaintyPx, 4)
                               : ""))
        return Verdict::Doubtful;
    if (p.checkEdge && p.edgeExtent > m.edgeRoom && fails(reasons, "spot touches the ROI edge")) return Verdict::Doubtful;
    if (p.checkSaturation && m.saturatedPixels > p.saturationMaxPixels &&
        fails(reasons, reasons ? "saturated: " + std::to_string(m.saturatedPixels) + " px at full scale" : ""))
        return Verdict::Doubtful;
    if (m.faint && fails(reasons, reasons ? "faint: peak " + formatDouble(m.peakSnr, 3) + " sigma above the ROI's ground, " +
                                                formatDouble(m.localPeakSnr, 3) + " above the ring around it, " +
                                                formatDouble(m.localTextureSnr, 3) + " above its pixel-scale texture"
                                          : ""))
        return Verdict::Doubtful;
    if (p.checkSecondSpot && m.secondPeakFraction >= p.secondSpotFraction &&
        fails(reasons, reasons ? "second spot at (" + std::to_string(m.secondPeakX) + ", " +
                                     std::to_string(m.secondPeakY) + "), " +
                                     formatDouble(100 * m.secondPeakFraction, 3) + "% of the main peak"
                               : ""))
        return Verdict::Doubtful;
    if (!m.startNote.empty() && fails(reasons, m.startNote)) return Verdict::Doubtful;
    return reasons && reasons->size() > before ? Verdict::Doubtful : Verdict::Good;
}

Judgement judge(const SpotFit& fit, const SpotDomain& domain, int roiWidth, int roiHeight, const VerdictParams& p) {
    Judgement j;
    j.verdict = checkVerdict(measureVerdict(fit, domain, roiWidth, roiHeight), p, &j.reasons);
    return j;
}

}  // namespace lwb::core::footprint
