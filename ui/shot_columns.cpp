#include "ui/shot_columns.hpp"

#include <QDateTime>
#include <QFileInfo>
#include <cmath>
#include <limits>

#include "core/footprint/background.hpp"
#include "ui/footprint_controller.hpp"
#include "ui/shot_table_model.hpp"

namespace lwb::ui {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

enum Col {
    File, Time, Beam, Camera, X, Y, Dx, Dy, Verdict_, Computed, Manual, Reasons, Method_, NoiseClass, Noise, SigmaX,
    SigmaY, AxisRatio, TiltDeg, MajorAxis, Mse, Snr, Crlb, Roi, Uncertainty, Eccentricity, Area, Amplitude,
    Background, RoiX0, RoiY0, CovXX, CovXY, CovYY, Radius95, Note, Count
};
}  // namespace

const std::vector<ShotColumn>& shotColumns() {
    using K = ShotColumnKind;
    static const std::vector<ShotColumn> cols = {
        {"file", K::Text, "file name", ""},
        {"time", K::Time, "time of the shot (UTC, as in the list)", ""},
        {"beam", K::Text, "beam label", ""},
        {"camera", K::Text, "camera label", ""},
        {"x", K::Number, "spot centre x, full image (empty when rejected)", "px"},
        {"y", K::Number, "spot centre y, full image (empty when rejected)", "px"},
        {"dx", K::Number, "x minus the nominal centre (the ROI's middle when none is given)", "px"},
        {"dy", K::Number, "y minus the nominal centre (the ROI's middle when none is given)", "px"},
        {"verdict", K::Text, "verdict shown (good, doubtful, rejected, unreadable; manual when set)", ""},
        {"computed", K::Text, "verdict the pipeline gave", ""},
        {"manual", K::Number, "1 with a manual verdict, else 0", ""},
        {"reasons", K::Text, "failed criteria", ""},
        {"method", K::Text, "centre method", ""},
        {"noise_class", K::Text, "background noise class", ""},
        {"noise", K::Text, "background noise class (as noise_class)", ""},
        {"sigma_x", K::Number, "spread along the x-near axis", "px"},
        {"sigma_y", K::Number, "spread along the other axis", "px"},
        {"axis_ratio", K::Number, "sigma_x / sigma_y", ""},
        {"tilt_deg", K::Number, "tilt of the x-near axis", "°"},
        {"major_axis_px", K::Number, "major axis at 1/e²", "px"},
        {"mse", K::Number, "fit mean square error", ""},
        {"snr", K::Number, "signal to noise ratio", ""},
        {"crlb_px", K::Number, "Cramér–Rao bound on the radial error", "px"},
        {"roi", K::Number, "ROI index within the frame", ""},
        {"uncertainty_px", K::Number, "1-σ radial position uncertainty", "px"},
        {"eccentricity", K::Number, "eccentricity", ""},
        {"area_px", K::Number, "pixels in the spot domain", "px"},
        {"amplitude_dn", K::Number, "peak above background", "DN"},
        {"background_dn", K::Number, "background level", "DN"},
        {"roi_x0", K::Number, "full-image x of the ROI's first pixel", "px"},
        {"roi_y0", K::Number, "full-image y of the ROI's first pixel", "px"},
        {"cov_xx_px2", K::Number, "the centre's variance along x (uncertainty_px² = cov_xx + cov_yy)", "px²"},
        {"cov_xy_px2", K::Number, "the centre's x-y covariance", "px²"},
        {"cov_yy_px2", K::Number, "the centre's variance along y", "px²"},
        {"radius95_px", K::Number, "radius holding the true centre in 95 % of shots", "px"},
        {"note", K::Text, "the analyst's note", ""},
    };
    Q_ASSERT(int(cols.size()) == Count);
    return cols;
}

const std::vector<std::string>& shotColumnNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const ShotColumn& c : shotColumns()) n.push_back(c.name);
        return n;
    }();
    return names;
}

int shotColumnIndex(const QString& name) {
    const auto& cols = shotColumns();
    for (size_t i = 0; i < cols.size(); ++i)
        if (name.compare(QLatin1String(cols[i].name), Qt::CaseInsensitive) == 0) return int(i);
    return -1;
}

std::vector<int> plottableShotColumns() {
    std::vector<int> out;
    const auto& cols = shotColumns();
    for (size_t i = 0; i < cols.size(); ++i)
        if (cols[i].kind != ShotColumnKind::Text) out.push_back(int(i));
    return out;
}

int shotRoiIndex(const FootprintController& c, int row) {
    const Shot* s = c.shot(row);
    int roi = 0;
    while (s && roi < row && c.shot(row - roi - 1)->file == s->file) ++roi;
    return roi;
}

double shotTimeSeconds(const QString& t) {
    if (t.isEmpty()) return kNaN;
    QDateTime d = QDateTime::fromString(t, Qt::ISODateWithMs);
    if (!d.isValid()) d = QDateTime::fromString(t, Qt::ISODate);
    if (!d.isValid()) d = QDateTime::fromString(t.left(10), "yyyy-MM-dd");
    if (!d.isValid()) d = QDateTime::fromString(t.left(7) + "-15", "yyyy-MM-dd");
    if (!d.isValid()) return kNaN;
    if (d.timeSpec() == Qt::LocalTime) d.setTimeSpec(Qt::UTC);  // no offset written: UTC
    return d.toMSecsSinceEpoch() / 1000.0;
}

core::FilterCell shotCell(const Shot& s, int roiIndex, int col) {
    using core::FilterCell;
    const bool failed = !s.loadError.isEmpty();
    const Verdict v = failed ? Verdict::Rejected : s.effectiveVerdict();
    const bool shown = s.fit.ok && !failed && v != Verdict::Rejected;  // x, y as the table shows them
    const core::footprint::SpotFit& f = s.fit;
    auto fitNum = [&](double x) { return FilterCell::num(f.ok && !failed ? x : kNaN); };
    switch (col) {
        case File: return FilterCell::str(QFileInfo(s.file).fileName().toStdString());
        case Time: return FilterCell::str(s.time.toStdString());
        case Beam: return FilterCell::str(s.beam.toStdString());
        case Camera: return FilterCell::str(s.camera.toStdString());
        case X: return FilterCell::num(shown ? s.fullX() : kNaN);
        case Y: return FilterCell::num(shown ? s.fullY() : kNaN);
        case Dx:
        case Dy: {
            if (!shown) return FilterCell::num(kNaN);
            const bool isX = col == Dx;
            const double nominal = s.hasCenter ? (isX ? s.center.x() : s.center.y())
                                               : (isX ? s.origin.x() + (s.roi.cols - 1) / 2.0
                                                      : s.origin.y() + (s.roi.rows - 1) / 2.0);
            if (!s.hasCenter && s.roi.empty()) return FilterCell::num(kNaN);
            return FilterCell::num((isX ? s.fullX() : s.fullY()) - nominal);
        }
        case Verdict_: return FilterCell::str(shotStateLabel(shotState(s)).toStdString());
        case Computed:
            return FilterCell::str(failed ? "unreadable" : !s.processed ? "" : verdictLabel(s.verdict).toStdString());
        case Manual: return FilterCell::num(s.overridden ? 1 : 0);
        case Reasons: return FilterCell::str((failed ? QStringList{s.loadError} : s.reasons).join("; ").toStdString());
        case Method_:
            return FilterCell::str(s.processed && !failed ? core::footprint::methodName(s.result.method) : "");
        case NoiseClass:
        case Noise: return FilterCell::str(s.noiseClass.toStdString());
        case SigmaX: return fitNum(f.sigmaX);
        case SigmaY: return fitNum(f.sigmaY);
        case AxisRatio: return fitNum(f.axisRatio);
        case TiltDeg: return fitNum(f.tiltRad * 180 / M_PI);
        case MajorAxis: return fitNum(f.majorAxisPx);
        case Mse: return fitNum(f.mse);
        case Snr: return fitNum(f.snr);
        case Crlb: return fitNum(s.result.crlbPx);
        case Roi: return FilterCell::num(roiIndex);
        case Uncertainty: return fitNum(f.uncertaintyPx);
        case Eccentricity: return fitNum(f.eccentricity);
        case Area: return fitNum(f.areaPx);
        case Amplitude: return fitNum(f.amplitude);
        case Background:
            return FilterCell::num(failed || !s.processed ? kNaN : f.ok ? f.background : s.result.background.level);
        case RoiX0: return FilterCell::num(failed ? kNaN : s.origin.x());
        case RoiY0: return FilterCell::num(failed ? kNaN : s.origin.y());
        case CovXX: return fitNum(f.covXX);
        case CovXY: return fitNum(f.covXY);
        case CovYY: return fitNum(f.covYY);
        case Radius95: return fitNum(f.radius95Px);
        case Note: return FilterCell::str(s.note.toStdString());
    }
    return {};
}

double shotNumber(const Shot& s, int roiIndex, int col) {
    if (col == Time) return shotTimeSeconds(s.time);
    return shotCell(s, roiIndex, col).number;
}

QString shotFilterHelp() {
    // Compact (the tooltip of a field near the top of the window): the names in one paragraph,
    // text columns in italics, the meaning of the ones that are not in the report.
    QStringList names;
    for (const ShotColumn& c : shotColumns())
        names << (c.kind == ShotColumnKind::Number ? QString("<b>%1</b>") : QString("<i>%1</i>")).arg(QLatin1String(c.name));
    return QObject::tr("<p>Shows the shots for which the expression holds, with the verdict choice beside it "
                       "(Alt+I). For example <code>snr &lt; 10 and beam == 2</code>, "
                       "<code>verdict == \"doubtful\" or note != \"\"</code>, <code>abs(dx) &gt; 0.5</code>, "
                       "<code>not (roi == 1)</code>.</p><p>&lt; &lt;= &gt; &gt;= == !=, and / or / not, "
                       "( ), numbers, \"text\", + - * /, abs() and sqrt(). Names and text compare without regard "
                       "to case. A missing number (a rejected shot's x) makes every comparison with it false.</p>"
                       "<p>Columns (<i>text</i>): %1.</p><p>dx, dy: the centre less the nominal centre (the ROI's "
                       "middle when none is given); verdict: as shown (manual where set); computed: the "
                       "pipeline's; manual: 1 or 0; roi: the ROI's index in its frame.</p>")
        .arg(names.join(", "));
}

}  // namespace lwb::ui
