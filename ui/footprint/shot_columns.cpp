#include "ui/footprint/shot_columns.hpp"

#include <QDateTime>
#include <QFileInfo>
#include <cmath>
#include <limits>

#include <algorithm>

#include "core/footprint/background.hpp"
#include "core/footprint/report_columns.hpp"
#include "ui/footprint/footprint_controller.hpp"
#include "ui/footprint/shot_table_model.hpp"

namespace lwb::ui {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
namespace fp = core::footprint;
using core::FilterCell;

// A shot as a row of the report's column table (core/footprint/report_columns.hpp), as the
// review export writes it. Its strings are held here, filled only for a text column.
struct ShotRow {
    std::string file, time, beam, camera, note, readError;
    fp::ReportRow row;
    ShotRow(const Shot& s, int roiIndex, bool withText) {
        if (withText) {
            file = s.file.toStdString();
            time = s.time.toStdString();
            beam = s.beam.toStdString();
            camera = s.camera.toStdString();
            note = s.note.toStdString();
            readError = s.loadError.toStdString();
        }
        row.file = file;
        row.time = time;
        row.beam = beam;
        row.camera = camera;
        row.note = note;
        row.readError = readError;
        row.result = s.loadError.isEmpty() ? &s.result : nullptr;
        row.roi = roiIndex;
        row.originX = s.origin.x();
        row.originY = s.origin.y();
        row.method = s.result.method;
        row.review = true;
        row.overridden = s.overridden;
        row.manual = s.overrideVerdict;
    }
};

// The workbench's own columns: what the table shows beside the report's (dx, dy, the state,
// the computed verdict as the list has it) and the two it shows its own way (file: the name;
// verdict: unreadable and pending too).
struct OwnColumn {
    ShotColumn column;
    FilterCell (*cell)(const Shot&, int roiIndex);
};

FilterCell offset(const Shot& s, bool isX) {
    const bool failed = !s.loadError.isEmpty();
    const bool shown = s.fit.ok && !failed && s.effectiveVerdict() != Verdict::Rejected;
    if (!shown || (!s.hasCenter && s.roi.empty())) return FilterCell::num(kNaN);
    const double nominal = s.hasCenter ? (isX ? s.center.x() : s.center.y())
                                       : (isX ? s.origin.x() + (s.roi.cols - 1) / 2.0 : s.origin.y() + (s.roi.rows - 1) / 2.0);
    return FilterCell::num((isX ? s.fullX() : s.fullY()) - nominal);
}

using K = ShotColumnKind;
const std::vector<OwnColumn> kOwn = {
    {{"file", K::Text, "file name", ""},
     [](const Shot& s, int) { return FilterCell::str(QFileInfo(s.file).fileName().toStdString()); }},
    {{"dx", K::Number, "x minus the nominal centre (the ROI's middle when none is given)", "px"},
     [](const Shot& s, int) { return offset(s, true); }},
    {{"dy", K::Number, "y minus the nominal centre (the ROI's middle when none is given)", "px"},
     [](const Shot& s, int) { return offset(s, false); }},
    {{"verdict", K::Text, "verdict shown (good, doubtful, rejected, unreadable; manual when set)", ""},
     [](const Shot& s, int) { return FilterCell::str(shotStateLabel(shotState(s)).toStdString()); }},
    {{"computed", K::Text, "verdict the pipeline gave", ""},
     [](const Shot& s, int) {
         const bool failed = !s.loadError.isEmpty();
         return FilterCell::str(failed ? "unreadable" : !s.processed ? "" : verdictLabel(s.verdict).toStdString());
     }},
    {{"manual", K::Number, "1 with a manual verdict, else 0", ""}, [](const Shot& s, int) { return FilterCell::num(s.overridden ? 1 : 0); }},
    {{"noise", K::Text, "background noise class (as noise_class)", ""},
     [](const Shot& s, int) { return FilterCell::str(s.noiseClass.toStdString()); }},
};

// The table's order: the report's columns (by name) and the workbench's own among them.
const char* const kOrder[] = {"file", "time", "beam", "camera", "x", "y", "dx", "dy", "verdict", "computed", "manual",
                              "reasons", "method", "noise_class", "noise"};

struct Entry {
    ShotColumn column;
    const OwnColumn* own = nullptr;          ///< the workbench's column, or
    const fp::FootprintColumn* report = nullptr;  ///< the report's
};

const std::vector<Entry>& entries() {
    static const std::vector<Entry> all = [] {
        std::vector<Entry> out;
        std::vector<std::string> placed;
        auto add = [&](const std::string& name) {
            for (const OwnColumn& o : kOwn)
                if (name == o.column.name) {
                    out.push_back({o.column, &o, nullptr});
                    placed.push_back(name);
                    return;
                }
            for (const fp::FootprintColumn& c : fp::footprintColumns())
                if (name == c.name) {
                    // (the review's auto_verdict and override are the table's computed and manual)
                    const K kind = name == "time" ? K::Time : c.type == fp::ColumnType::Text ? K::Text : K::Number;
                    out.push_back({{c.name, kind, c.doc, c.unit}, nullptr, &c});
                    placed.push_back(name);
                    return;
                }
        };
        for (const char* n : kOrder) add(n);
        for (const fp::FootprintColumn& c : fp::footprintColumns())
            if (std::find(placed.begin(), placed.end(), c.name) == placed.end() && std::string(c.name) != "auto_verdict" &&
                std::string(c.name) != "override")
                add(c.name);
        return out;
    }();
    return all;
}
}  // namespace

const std::vector<ShotColumn>& shotColumns() {
    static const std::vector<ShotColumn> cols = [] {
        std::vector<ShotColumn> c;
        for (const Entry& e : entries()) c.push_back(e.column);
        return c;
    }();
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
    const auto& all = entries();
    if (col < 0 || col >= int(all.size())) return {};
    const Entry& e = all[size_t(col)];
    if (e.own) return e.own->cell(s, roiIndex);
    const ShotRow r(s, roiIndex, e.report->type == fp::ColumnType::Text);
    return e.report->value(r.row);
}

double shotNumber(const Shot& s, int roiIndex, int col) {
    static const int time = shotColumnIndex("time");
    if (col == time) return shotTimeSeconds(s.time);
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
