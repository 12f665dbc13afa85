#include "core/footprint/report_columns.hpp"

#include <cmath>
#include <limits>

#include "core/common/csv.hpp"
#include "core/common/text.hpp"
#include "core/footprint/background.hpp"

namespace lwb::core::footprint {

Verdict ReportRow::verdict() const {
    if (failed()) return Verdict::Rejected;
    return review && overridden ? manual : result->verdict;
}

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
using Row = ReportRow;

FilterCell text(std::string_view s) { return FilterCell::str(std::string(s)); }
FilterCell number(double v) { return FilterCell::num(v); }
// A fit quantity: only where the fit succeeded.
template <class F>
FilterCell fitted(const Row& r, F get) {
    return number(!r.failed() && r.result->fit.ok ? get(r.result->fit) : kNone);
}
// A position quantity: only where the row has a position (a fit, not rejected).
template <class F>
FilterCell placed(const Row& r, F get) {
    return number(!r.failed() && r.result->fit.ok && r.verdict() != Verdict::Rejected ? get(r.result->fit) : kNone);
}
std::string joined(const std::vector<std::string>& parts) {
    std::string s;
    for (size_t i = 0; i < parts.size(); ++i) s += (i ? "; " : "") + parts[i];
    return s;
}

FilterCell reasonsOf(const Row& r) {
    if (!r.result) return text("unreadable: " + std::string(r.readError));
    return text(r.result->ok ? joined(r.result->reasons) : r.result->error);
}

// (built on first use: other translation units read it during their static initialisation)
std::vector<FootprintColumn> makeColumns() {
    return {
        {"file", "", "the frame", ColumnType::Text, 0, false, [](const Row& r) { return text(r.file); }},
        {"x", "px", "spot centre x, full image (empty when rejected)", ColumnType::Real, 4, false,
         [](const Row& r) { return placed(r, [&](const SpotFit& f) { return f.x + r.originX; }); }},
        {"y", "px", "spot centre y, full image (empty when rejected)", ColumnType::Real, 4, false,
         [](const Row& r) { return placed(r, [&](const SpotFit& f) { return f.y + r.originY; }); }},
        {"verdict", "", "good, doubtful or rejected (the manual verdict where the review set one)", ColumnType::Text, 0, false,
         [](const Row& r) { return text(verdictName(r.verdict())); }},
        {"reasons", "", "the criteria that failed, or why the shot was rejected", ColumnType::Text, 0, false, reasonsOf},
        {"method", "", "centre method", ColumnType::Text, 0, false,
         [](const Row& r) { return text(methodName(r.failed() ? r.method : r.result->method)); }},
        {"noise_class", "", "background noise class", ColumnType::Text, 0, false,
         [](const Row& r) { return text(r.failed() ? "" : noiseClassName(r.result->background.noiseClass)); }},
        {"sigma_x", "px", "spread along the x-near axis", ColumnType::Real, 4, false,
         [](const Row& r) { return fitted(r, [](const SpotFit& f) { return f.sigmaX; }); }},
        {"sigma_y", "px", "spread along the other axis", ColumnType::Real, 4, false,
         [](const Row& r) { return fitted(r, [](const SpotFit& f) { return f.sigmaY; }); }},
        {"axis_ratio", "", "sigma_x / sigma_y", ColumnType::Real, 4, false,
         [](const Row& r) { return fitted(r, [](const SpotFit& f) { return f.axisRatio; }); }},
        {"tilt_deg", "°", "tilt of the x-near axis", ColumnType::Real, 3, false,
         [](const Row& r) { return fitted(r, [](const SpotFit& f) { return f.tiltRad * 180 / M_PI; }); }},
        {"major_axis_px", "px", "major axis at 1/e²", ColumnType::Real, 3, false,
         [](const Row& r) { return fitted(r, [](const SpotFit& f) { return f.majorAxisPx; }); }},
        {"mse", "", "fit mean square error", ColumnType::Real, -1, false,
         [](const Row& r) { return fitted(r, [](const SpotFit& f) { return f.mse; }); }},
        {"snr", "", "signal to noise ratio", ColumnType::Real, 2, false,
         [](const Row& r) { return fitted(r, [](const SpotFit& f) { return f.snr; }); }},
        {"crlb_px", "px", "Cramér–Rao bound on the radial error", ColumnType::Real, 5, false,
         [](const Row& r) { return number(!r.failed() && r.result->fit.ok ? r.result->crlbPx : kNone); }},
        {"roi", "", "ROI index within the frame", ColumnType::Integer, 0, false, [](const Row& r) { return number(r.roi); }},
        {"uncertainty_px", "px", "1-σ radial position uncertainty", ColumnType::Real, 5, false,
         [](const Row& r) { return fitted(r, [](const SpotFit& f) { return f.uncertaintyPx; }); }},
        {"eccentricity", "", "eccentricity", ColumnType::Real, 4, false,
         [](const Row& r) { return fitted(r, [](const SpotFit& f) { return f.eccentricity; }); }},
        {"area_px", "px", "pixels in the spot domain", ColumnType::Real, 0, false,
         [](const Row& r) { return fitted(r, [](const SpotFit& f) { return f.areaPx; }); }},
        {"amplitude_dn", "DN", "peak above background", ColumnType::Real, 1, false,
         [](const Row& r) { return fitted(r, [](const SpotFit& f) { return f.amplitude; }); }},
        {"background_dn", "DN", "background level (the fit's, else the estimate's)", ColumnType::Real, 1, false,
         [](const Row& r) {
             if (r.failed()) return number(kNone);
             return number(r.result->fit.ok ? r.result->fit.background : r.result->background.level);
         }},
        {"roi_x0", "px", "full-image x of the ROI's first pixel", ColumnType::Integer, 0, false,
         [](const Row& r) { return number(r.failed() ? kNone : r.originX); }},
        {"roi_y0", "px", "full-image y of the ROI's first pixel", ColumnType::Integer, 0, false,
         [](const Row& r) { return number(r.failed() ? kNone : r.originY); }},
        {"cov_xx_px2", "px²", "the centre's variance along x (uncertainty_px² = cov_xx + cov_yy; the Gaussian fit's)",
         ColumnType::Real, -1, false, [](const Row& r) { return placed(r, [](const SpotFit& f) { return f.covXX; }); }},
        {"cov_xy_px2", "px²", "the centre's x-y covariance", ColumnType::Real, -1, false,
         [](const Row& r) { return placed(r, [](const SpotFit& f) { return f.covXY; }); }},
        {"cov_yy_px2", "px²", "the centre's variance along y", ColumnType::Real, -1, false,
         [](const Row& r) { return placed(r, [](const SpotFit& f) { return f.covYY; }); }},
        {"radius95_px", "px", "radius holding the true centre in 95 % of shots", ColumnType::Real, 5, false,
         [](const Row& r) { return placed(r, [](const SpotFit& f) { return f.radius95Px; }); }},
        {"time", "", "time of the shot (as in the shot list or frame metadata)", ColumnType::Text, 0, false,
         [](const Row& r) { return text(r.time); }},
        {"beam", "", "beam label", ColumnType::Text, 0, false, [](const Row& r) { return text(r.beam); }},
        {"camera", "", "camera label", ColumnType::Text, 0, false, [](const Row& r) { return text(r.camera); }},
        {"auto_verdict", "", "the verdict computed (verdict is then the effective one)", ColumnType::Text, 0, true,
         [](const Row& r) { return text(verdictName(r.failed() ? Verdict::Rejected : r.result->verdict)); }},
        {"override", "", "manual where the analyst set the verdict", ColumnType::Text, 0, true,
         [](const Row& r) { return text(r.overridden ? "manual" : ""); }},
        {"note", "", "the analyst's note", ColumnType::Text, 0, true, [](const Row& r) { return text(r.note); }},
    };
}

}  // namespace

const std::vector<FootprintColumn>& footprintColumns() {
    static const std::vector<FootprintColumn> columns = makeColumns();
    return columns;
}

std::vector<std::string> footprintColumnNames(bool review) {
    std::vector<std::string> names;
    for (const FootprintColumn& c : footprintColumns())
        if (review || !c.reviewOnly) names.push_back(c.name);
    return names;
}

std::string footprintCsvCell(const FootprintColumn& c, const ReportRow& row) {
    const FilterCell v = c.value(row);
    switch (c.type) {
        case ColumnType::Text: return csvEscape(v.text);
        case ColumnType::Integer: return std::isfinite(v.number) ? std::to_string(static_cast<long long>(v.number)) : "";
        case ColumnType::Real:
            if (!std::isfinite(v.number)) return "";
            return c.decimals < 0 ? formatDouble(v.number, 4) : formatFixed(v.number, c.decimals);
    }
    return "";
}

}  // namespace lwb::core::footprint
