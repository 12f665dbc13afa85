// SLR file readers and writers: CRD (v1/v2), CPF, SINEX. Real ILRS files from
// ../shared/data/slr (QSKIP when absent); small hand-written bad files in a QTemporaryDir.
#include <QtTest>

#include <QDate>
#include <QDir>
#include <QRegularExpression>
#include <cmath>
#include <map>
#include <set>

#include "core/slr/cpf.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/sinex.hpp"
#include "core/slr/slr_time.hpp"
#include "core/common/csv.hpp"
#include "test_support.hpp"

using namespace lwb::core::slr;

namespace {

const QStringList kCrdFiles = {"7080_Beacon-C_crd_071220_1715_0.frd", "7080_Beacon-C_crd_071220_1715_0.npt",
                               "7080_JASON1_crd_071220_2033_0.frd",   "7080_JASON1_crd_071220_2033_0.npt",
                               "7080_STELLA_crd_071220_2128_0.frd",   "7080_STELLA_crd_071220_2128_0.npt",
                               "beaconc_20070511.frd",                "beaconc_20070511.npt",
                               "blits_201206.frd",                    "hy2c_202109.fr2",
                               "crd201_all_samples.crd"};

/// Independent count, by regular expression on the raw text, of lines whose first field is `id`.
int countLines(const QByteArray& text, const QString& id) {
    const QRegularExpression re("^\\s*" + QRegularExpression::escape(id) + "(\\s|$)",
                                QRegularExpression::CaseInsensitiveOption | QRegularExpression::MultilineOption);
    int n = 0;
    auto it = re.globalMatch(QString::fromUtf8(text));
    while (it.hasNext()) {
        it.next();
        ++n;
    }
    return n;
}

/// Independent count of type-10 lines with a given filter flag (6th field).
int countFlag(const QByteArray& text, int flag) {
    int n = 0;
    for (const QByteArray& raw : text.split('\n')) {
        const QStringList f = QString::fromUtf8(raw).simplified().split(' ', Qt::SkipEmptyParts);
        if (f.size() >= 6 && f[0] == "10" && f[5].toInt() == flag) ++n;
    }
    return n;
}

size_t countRanges(const CrdFile& f, int flag = -1) {
    size_t n = 0;
    for (const auto& p : f.passes)
        for (const auto& r : p.ranges) n += flag < 0 || r.filterFlag == flag;
    return n;
}

size_t countNormalPoints(const CrdFile& f) {
    size_t n = 0;
    for (const auto& p : f.passes) n += p.normalPoints.size();
    return n;
}

template <class T, class M>
size_t countParsed(const CrdFile& f, M member) {
    size_t n = 0;
    for (const auto& p : f.passes) n += (p.*member).size();
    return n;
}

std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += x + "\n";
    return s;
}

/// True when a, b are the same double or both NaN.
bool same(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

/// Writes a small CRD file and reads it.
CrdReadResult readText(const QTemporaryDir& dir, const QString& name, const QByteArray& text, QString* path = nullptr) {
    const QString p = dir.filePath(name);
    if (path) *path = p;
    if (!lwbtest::writeText(p, text)) return CrdReadResult();
    return readCrd(lwbtest::str(p));
}

/// Empty when streamCrd hands out, one by one, the passes readCrd reads at once (their place,
/// records, parsed ranges and normal points, problems), or fails as readCrd does; else what
/// differs. A file readCrd refuses because none of its blocks is a pass is read by streamCrd
/// with every pass carrying its problem (the caller decides).
QString streamDiff(const QString& path) {
    const CrdReadResult r = readCrd(lwbtest::str(path));
    std::vector<CrdPass> got;
    size_t counted = 0;
    const CrdStreamResult s = streamCrd(
        lwbtest::str(path), {}, nullptr,
        [&](size_t n) {
            counted = n;
            return true;
        },
        [&](CrdPass&& p) {
            got.push_back(std::move(p));
            return true;
        });
    if (!r.ok) {
        if (!s.ok) return s.error == r.error ? QString() : QString("errors differ: %1 | %2").arg(s.error.c_str(), r.error.c_str());
        for (const CrdPass& p : got)
            if (p.problem.empty()) return "readCrd refused the file, streamCrd handed out a usable pass: " + QString(r.error.c_str());
        return r.error.rfind(got.front().problem, 0) == 0 ? QString() : QString("first problem differs: ") + r.error.c_str();
    }
    if (!s.ok) return "streamCrd failed: " + QString::fromStdString(s.error);
    if (counted != r.file.passes.size() || got.size() != counted || s.passes != counted)
        return QString("passes: counted %1, handed out %2, read %3").arg(counted).arg(got.size()).arg(r.file.passes.size());
    for (size_t i = 0; i < got.size(); ++i) {
        const CrdPass &a = got[i], &b = r.file.passes[i];
        const QString at = QString("pass %1: ").arg(i + 1);
        if (a.ordinal != i + 1 || b.ordinal != i + 1) return at + "ordinal";
        const std::vector<CrdRecord> ar = allRecords(a), br = allRecords(b);
        if (ar.size() != br.size()) return at + "record count";
        for (size_t k = 0; k < ar.size(); ++k)
            if (ar[k].text != br[k].text || ar[k].line != br[k].line || ar[k].id != br[k].id)
                return at + QString("record %1 (line %2)").arg(k).arg(br[k].line);
        if (a.ranges.size() != b.ranges.size() || a.normalPoints.size() != b.normalPoints.size()) return at + "parsed counts";
        for (size_t k = 0; k < a.ranges.size(); ++k)
            if (a.ranges[k].secOfDay != b.ranges[k].secOfDay || a.ranges[k].tofS != b.ranges[k].tofS)
                return at + QString("range %1").arg(k);
        if (a.problem != b.problem) return at + "problem: " + a.problem.c_str() + " | " + b.problem.c_str();
        if (a.inheritsHeaders != b.inheritsHeaders || a.endedWithH8 != b.endedWithH8) return at + "block flags";
        if (a.station.name != b.station.name || a.target.name != b.target.name || a.session.line != b.session.line)
            return at + "headers";
    }
    return {};
}

/// A sound small v2 pass: lines 1..10.
const QByteArray kGoodCrd =
    "H1 CRD 2 2021 9 1 21\n"                                  // 1
    "H2 GLSL 1824 81 1 4 EUROLAS\n"                           // 2
    "H3 hy2c 2006601 2209 46469 0 1 1\n"                      // 3
    "H4 0 2021 9 1 20 46 0 2021 9 1 20 47 19 0 0 0 0 1 0 2 1\n"  // 4
    "C0 0 532.000 sys1 las1\n"                                // 5
    "10 74760.420166021300 0.013024392652 sys1 2 2 0 0 0 na\n"  // 6
    "10 74776.082358022497 0.013108658267 sys1 2 2 0 0 0 na\n"  // 7
    "10 74777.099340164496 0.013115307576 sys1 2 2 0 0 0 na\n"  // 8
    "H8\n"                                                    // 9
    "H9\n";                                                   // 10

/// kGoodCrd as the readers accept it (LF, CRLF, CR alone, LF-CR: every line after the first
/// starting with a CR, a byte-order mark, no final line end) and a text of several blocks, each
/// with its file name.
QList<QPair<QString, QByteArray>> goodCrdForms(const QByteArray& blocks) {
    QByteArray crlf = kGoodCrd, cr = kGoodCrd, lfcr = kGoodCrd;
    crlf.replace("\n", "\r\n");
    cr.replace('\n', '\r');
    lfcr.replace("\n", "\n\r");
    return {{"good.frd", kGoodCrd},
            {"crlf.frd", crlf},
            {"cr.frd", cr},
            {"lfcr.frd", lfcr},
            {"bom.frd", "\xEF\xBB\xBF" + kGoodCrd},
            {"nofinal.frd", kGoodCrd.left(kGoodCrd.size() - 1)},
            {"blocks.frd", blocks}};
}

/// True when the read gave exactly one warning, starting with `prefix` and holding every part.
bool oneWarning(const CrdReadResult& r, const QString& prefix, const QStringList& parts, QString* why) {
    *why = QString::fromStdString(joined(r.warnings));
    if (r.warnings.size() != 1) return false;
    const QString w = QString::fromStdString(r.warnings[0]);
    if (!w.startsWith(prefix)) return false;
    for (const QString& part : parts)
        if (!w.contains(part)) return false;
    return true;
}

QByteArray replaceLine(const QByteArray& text, int line, const QByteArray& with) {
    QList<QByteArray> lines = text.split('\n');
    lines[line - 1] = with;
    return lines.join('\n');
}

}  // namespace

class TestSlrIo : public QObject {
    Q_OBJECT
private slots:
    // ---- issue 27: the file read pass by pass (streamCrd) gives what readCrd gives ----------------
    void streamedAsRead_data() { everyCrdFileParses_data(); }
    // Issue 41: an H4 whose end precedes its start was read without a word.
    void h4EndBeforeStartIsSaid() {
        QByteArray text = kGoodCrd;
        text.replace("H4 0 2021 9 1 20 46 0 2021 9 1 20 47 19", "H4 0 2021 9 1 20 46 0 2021 9 1 19 47 19");
        const CrdReadResult r = parseCrd(text.toStdString(), "back.frd");
        QVERIFY2(r.ok, r.error.c_str());
        bool said = false;
        for (const auto& w : r.warnings) said |= w.find("back.frd:4: H4 end date-time precedes its start") != std::string::npos;
        QVERIFY(said);
        const CrdReadResult good = parseCrd(kGoodCrd.toStdString(), "good.frd");
        for (const auto& w : good.warnings) QVERIFY2(w.find("precedes") == std::string::npos, w.c_str());
    }

    void streamedAsRead() {
        QFETCH(QString, file);
        if (!lwbtest::haveShared("slr/" + file)) QSKIP("shared SLR data absent (../shared/data/slr)");
        const QString why = streamDiff(lwbtest::sharedPath("slr/" + file));
        QVERIFY2(why.isEmpty(), qPrintable(why));
        // gzip-compressed (blits_201206.frd, 2.3 MB, crosses the reader's 1 MiB blocks both ways).
        QTemporaryDir dir;
        QCOMPARE(QProcess::execute("sh", {"-c", "gzip -c '" + lwbtest::sharedPath("slr/" + file) + "' > '" + dir.filePath("f.gz") + "'"}), 0);
        const QString gz = streamDiff(dir.filePath("f.gz"));
        QVERIFY2(gz.isEmpty(), qPrintable("gzip: " + gz));
    }

    // The same on the forms of text the whole-file reader accepts (CRLF, CR alone, a byte-order
    // mark, no final line end, gzip in one or two members, blocks that are not passes) and its
    // errors (truncated gzip, NUL, blank only, no H4, data before H1), with the same messages.
    void streamedAsReadVariants() {
        QTemporaryDir dir;
        const QByteArray twoPasses = kGoodCrd.left(kGoodCrd.size() - 3) +
                                     "H4 0 2021 9 1 20 50 0 2021 9 1 20 51 0 0 0 0 0 1 0 2 1\n10 75000.5 0.0131 sys1 2 2 0 0 0 na\n"
                                     "H4 1 2021 9 1 21 46 0 -1 -1 -1 -1 -1 -1 0 0 0 0 1 0 2 0\nH9\n";
        QList<QPair<QString, QByteArray>> texts = goodCrdForms(twoPasses);
        texts += QList<QPair<QString, QByteArray>>{
            {"nul.frd", kGoodCrd + QByteArray("10 x\0y\n", 7)},
            {"blank.frd", "\n  \n\r\n"},
            {"noh4.frd", "H1 CRD 2 2021 9 1 21\nH2 GLSL 1824 81 1 4 EUROLAS\nH3 hy2c 2006601 2209 46469 0 1 1\nH9\n"},
            {"csv.frd", "epoch_s,oc_s\n1,2\n"},
            {"nodata.frd", replaceLine(replaceLine(replaceLine(kGoodCrd, 6, "00 gone"), 7, "00 gone"), 8, "00 gone")},
        };
        for (const auto& [name, text] : texts) {
            QVERIFY(lwbtest::writeText(dir.filePath(name), text));
            const QString why = streamDiff(dir.filePath(name));
            QVERIFY2(why.isEmpty(), qPrintable(name + ": " + why));
        }
        // gzip: one member, two members (cat a.gz b.gz), and cut short.
        QVERIFY(lwbtest::writeText(dir.filePath("a.frd"), twoPasses));
        QCOMPARE(QProcess::execute("sh", {"-c", "cd '" + dir.path() + "' && gzip -c a.frd > a.frd.gz && "
                                                 "head -c 200 a.frd | gzip -c > two.frd.gz && tail -c +201 a.frd | gzip -c >> two.frd.gz && "
                                                 "head -c 60 a.frd.gz > cut.frd.gz"}),
                 0);
        for (const QString name : {"a.frd.gz", "two.frd.gz", "cut.frd.gz"}) {
            const QString why = streamDiff(dir.filePath(name));
            QVERIFY2(why.isEmpty(), qPrintable(name + ": " + why));
        }
        const CrdStreamResult cut = streamCrd(lwbtest::str(dir.filePath("cut.frd.gz")), {}, nullptr, {}, [](CrdPass&&) { return true; });
        QVERIFY2(!cut.ok && cut.error.find("truncated") != std::string::npos, cut.error.c_str());
        // A pass is handed out as soon as it closes, and a callback returning false stops the read.
        size_t seen = 0;
        const CrdStreamResult stop = streamCrd(lwbtest::str(dir.filePath("blocks.frd")), {}, nullptr, {}, [&](CrdPass&&) {
            return ++seen < 2;
        });
        QVERIFY(!stop.ok);
        QVERIFY2(stop.error.find("cancelled") != std::string::npos, stop.error.c_str());
        QCOMPARE(seen, size_t(2));
    }

    // ---- CRD: every shared file ---------------------------------------------------------------
    void everyCrdFileParses_data() {
        QTest::addColumn<QString>("file");
        for (const QString& f : kCrdFiles) QTest::newRow(f.toUtf8().constData()) << f;
    }
    void everyCrdFileParses() {
        QFETCH(QString, file);
        if (!lwbtest::haveShared("slr/" + file)) QSKIP("shared SLR data absent (../shared/data/slr)");
        const QString path = lwbtest::sharedPath("slr/" + file);
        const QByteArray raw = lwbtest::readAll(path);
        const CrdReadResult r = readCrd(lwbtest::str(path));
        QVERIFY2(r.ok, r.error.c_str());
        // Counts against independent regex counts of the raw text.
        QCOMPARE(static_cast<int>(r.file.passes.size()), countLines(raw, "h4"));
        QCOMPARE(static_cast<int>(countRanges(r.file)), countLines(raw, "10"));
        QCOMPARE(static_cast<int>(countNormalPoints(r.file)), countLines(raw, "11"));
        QCOMPARE(static_cast<int>(countParsed<CrdRangeSupplement>(r.file, &CrdPass::supplements)), countLines(raw, "12"));
        QCOMPARE(static_cast<int>(countParsed<CrdMeteo>(r.file, &CrdPass::meteo)), countLines(raw, "20"));
        QCOMPARE(static_cast<int>(countParsed<CrdPointing>(r.file, &CrdPass::pointing)), countLines(raw, "30"));
        QCOMPARE(static_cast<int>(countParsed<CrdCalibration>(r.file, &CrdPass::calibrations)),
                 countLines(raw, "40") + countLines(raw, "41"));
        QCOMPARE(static_cast<int>(countParsed<CrdSystemConfig>(r.file, &CrdPass::configs)), countLines(raw, "c0"));
        // Every line is kept: records of all passes + trailer == lines of the file.
        size_t lines = r.file.trailer.size();
        for (const auto& p : r.file.passes) lines += p.records.size() + p.rangeLines.size();
        QCOMPARE(static_cast<int>(lines), static_cast<int>(raw.count('\n') + (raw.endsWith('\n') ? 0 : 1)));
        // Filter flags against an independent count.
        QCOMPARE(static_cast<int>(countRanges(r.file, 1)), countFlag(raw, 1));
        QCOMPARE(static_cast<int>(countRanges(r.file, 2)), countFlag(raw, 2));
        // Real station files need no warnings; the spec's sample file has one block without H8.
        if (file != "crd201_all_samples.crd") QVERIFY2(r.warnings.empty(), joined(r.warnings).c_str());
        for (const auto& p : r.file.passes) {
            QVERIFY(!p.station.name.empty());
            QVERIFY(p.station.cdpPadId > 0);
            QVERIFY(!p.target.name.empty());
            QVERIFY(validDate(p.session.startYear, p.session.startMonth, p.session.startDay));
            QVERIFY(!p.ranges.empty() || !p.normalPoints.empty());
            // (a plain file's type-10 lines are read again from it: none is held in memory)
            QVERIFY(p.rangeLines.empty() || !p.rangeLines.inMemory());
            std::vector<std::string> texts;
            CrdRangeLines::Reader rd(p.rangeLines);
            std::string_view t;
            while (rd.next(&t)) texts.emplace_back(t);
            QVERIFY2(rd.error().empty(), rd.error().c_str());
            QCOMPARE(texts.size(), p.rangeLines.size());
            for (const auto& x : p.ranges) {
                QVERIFY(x.record < p.rangeLines.size());
                QCOMPARE(p.rangeLines.line(x.record), x.line);
                QVERIFY(texts[x.record].substr(0, 2) == "10");
            }
        }
    }

    /// The figures the data README states, and the station's own labels.
    void readmeCounts_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("passes");
        QTest::addColumn<int>("points");
        QTest::addColumn<int>("signal");  // filter flag 2, -1: not checked
        QTest::addColumn<int>("noise");   // filter flag 1
        QTest::newRow("JASON1") << "7080_JASON1_crd_071220_2033_0.frd" << 1 << 259 << 59 << 200;
        QTest::newRow("STELLA") << "7080_STELLA_crd_071220_2128_0.frd" << 1 << 236 << 150 << 86;
        QTest::newRow("Beacon-C") << "7080_Beacon-C_crd_071220_1715_0.frd" << 1 << 96 << 50 << 46;
        QTest::newRow("beaconc 3 passes") << "beaconc_20070511.frd" << 3 << 386 << 237 << 149;
        QTest::newRow("blits") << "blits_201206.frd" << 54 << 33601 << -1 << 0;
        QTest::newRow("hy2c") << "hy2c_202109.fr2" << 6 << 143 << -1 << -1;
    }
    void readmeCounts() {
        QFETCH(QString, file);
        QFETCH(int, passes);
        QFETCH(int, points);
        QFETCH(int, signal);
        QFETCH(int, noise);
        if (!lwbtest::haveShared("slr/" + file)) QSKIP("shared SLR data absent");
        const CrdReadResult r = readCrd(lwbtest::str(lwbtest::sharedPath("slr/" + file)));
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(static_cast<int>(r.file.passes.size()), passes);
        QCOMPARE(static_cast<int>(countRanges(r.file)), points);
        if (signal >= 0) QCOMPARE(static_cast<int>(countRanges(r.file, 2)), signal);
        if (noise >= 0) QCOMPARE(static_cast<int>(countRanges(r.file, 1)), noise);
    }

    /// Fields of known records, read off the files themselves.
    void fieldValues() {
        if (!lwbtest::haveShared("slr/hy2c_202109.fr2")) QSKIP("shared SLR data absent");
        const CrdReadResult r = readCrd(lwbtest::str(lwbtest::sharedPath("slr/hy2c_202109.fr2")));
        QVERIFY2(r.ok, r.error.c_str());
        const CrdPass& p = r.file.passes.front();
        // "H1 CRD 02 2021  9  1 21"
        QCOMPARE(p.format.version, 2);
        // "H2       GLSL 1824 81  1  4 EUROLAS"
        QCOMPARE(p.station.name, std::string("GLSL"));
        QCOMPARE(p.station.cdpPadId, 1824);
        QCOMPARE(p.station.cdpSystem, 81);
        QCOMPARE(p.station.cdpOccupancy, 1);
        QCOMPARE(p.station.timeScale, 4);
        QCOMPARE(p.station.network, std::string("EUROLAS"));
        // "H3       hy2c 2006601 2209 46469 0 1 1"
        QCOMPARE(p.target.name, std::string("hy2c"));
        QCOMPARE(p.target.ilrsId, std::string("2006601"));
        QCOMPARE(p.target.sic, 2209L);
        QCOMPARE(p.target.norad, 46469L);
        QCOMPARE(p.target.targetType, 1);
        QCOMPARE(p.target.targetClass, 1);
        // "H4 0 2021  9  1 20 46  0 2021  9  1 20 47 19  0 0 0 0 1 0 2 1"
        QCOMPARE(p.session.dataType, 0);
        QCOMPARE(p.session.startHour, 20);
        QCOMPARE(p.session.startMinute, 46);
        QCOMPARE(p.session.endSecond, 19);
        QCOMPARE(p.session.stationDelayApplied, 1);
        QCOMPARE(p.session.rangeType, 2);
        QCOMPARE(p.session.qualityAlert, 1);
        QCOMPARE(p.startMjd(), 59458L);  // 2021-09-01 (MJD of 2000-01-01 is 51544; +7914 days)
        // "C0 0    532.000 sys1 las1 det1 tim1 none"
        QCOMPARE(p.configs.size(), size_t(1));
        QCOMPARE(p.configs[0].wavelengthNm, 532.0);
        QVERIFY(p.config("SYS1") != nullptr);  // ids compare case-insensitively
        // "10 74760.420166021300     0.013024392652 sys1 2 2 0 0     0 na"
        const CrdRange& x = p.ranges.front();
        QCOMPARE(x.secOfDay, 74760.4201660213);
        QCOMPARE(x.tofS, 0.013024392652);
        QCOMPARE(x.configId, std::string("sys1"));
        QCOMPARE(x.epochEvent, 2);
        QCOMPARE(x.filterFlag, 2);
        QCOMPARE(x.receiveAmplitude, 0.0);
        QVERIFY(std::isnan(x.transmitAmplitude));  // "na"
        // "20 74760.420166021300  990.10 288.40   92 1"
        QCOMPARE(p.meteo.front().pressureMbar, 990.10);
        QCOMPARE(p.meteo.front().temperatureK, 288.40);
        QCOMPARE(p.meteo.front().humidityPct, 92.0);
        QCOMPARE(p.meteo.front().origin, 1);
        // "40 72713.000000000000 0 sys1      766      264   8.943   217074.0 ..."
        QCOMPARE(p.calibrations.front().systemDelayPs, 217074.0);
        QCOMPARE(p.calibrations.front().pointsRecorded, 766L);
        QVERIFY(!p.calibrations.front().detail);
        QVERIFY(p.calibrations[1].detail);  // the 41 records
    }

    /// crd201_all_samples.crd: the specification's samples hold every record type.
    void everyRecordTypePresent() {
        if (!lwbtest::haveShared("slr/crd201_all_samples.crd")) QSKIP("shared SLR data absent");
        const CrdReadResult r = readCrd(lwbtest::str(lwbtest::sharedPath("slr/crd201_all_samples.crd")));
        QVERIFY2(r.ok, r.error.c_str());
        std::set<std::string> ids;
        for (const auto& p : r.file.passes)
            for (const auto& rec : allRecords(p)) ids.insert(rec.id);
        for (const auto& rec : r.file.trailer) ids.insert(rec.id);
        for (const char* id : {"h1", "h2", "h3", "h4", "h5", "h8", "h9", "c0", "c1", "c2", "c3", "c4", "c5", "c6", "c7",
                               "10", "11", "12", "20", "21", "30", "40", "41", "42", "50", "91", "92", "93", "00"})
            QVERIFY2(ids.count(id), id);
        // Upper- and lower-case ids, v1 and v2 blocks.
        std::set<int> versions;
        for (const auto& p : r.file.passes) versions.insert(p.format.version);
        QVERIFY(versions.count(1) && versions.count(2));
        bool upper = false, lower = false;
        for (const auto& p : r.file.passes) {
            upper |= p.session.text.rfind("H4", 0) == 0;
            lower |= p.session.text.rfind("h4", 0) == 0;
        }
        QVERIFY(upper && lower);
        // Parsed samples: the first full-rate record "10 55432.0414338 0.047960587856 std1 2 0 0 0 na na".
        const CrdRange& x = r.file.passes.front().ranges.front();
        QCOMPARE(x.secOfDay, 55432.0414338);
        QCOMPARE(x.tofS, 0.047960587856);
        QCOMPARE(x.filterFlag, 0);
        QVERIFY(std::isnan(x.receiveAmplitude));
        // A v2 normal point with SNR: "11  2726.697640514675 0.013737698432 std 2 15 1 72.7 1.494 -0.536 -32.4 0.67 0 20.7"
        bool found = false;
        for (const auto& p : r.file.passes)
            for (const auto& n : p.normalPoints)
                if (n.secOfDay == 2726.697640514675) {
                    found = true;
                    QCOMPARE(n.windowS, 15.0);
                    QCOMPARE(n.numRanges, 1);
                    QCOMPARE(n.binRmsPs, 72.7);
                    QCOMPARE(n.skew, 1.494);
                    QCOMPARE(n.kurtosis, -0.536);
                    QCOMPARE(n.peakMinusMeanPs, -32.4);
                    QCOMPARE(n.returnRatePct, 0.67);
                    QCOMPARE(n.detectorChannel, 0);
                    QCOMPARE(n.snr, 20.7);
                }
        QVERIFY(found);
        // The free-format sample: "File 1" has no h8 before "File 2"'s h1: a warning naming the line.
        QCOMPARE(r.warnings.size(), size_t(1));
        QVERIFY2(r.warnings[0].find("crd201_all_samples.crd:202:") != std::string::npos, r.warnings[0].c_str());
        // Pointing (30) of the full-rate block: "30 2717.996 326.8923 32.9177 0 1 1 na na"
        bool p30 = false;
        for (const auto& p : r.file.passes)
            for (const auto& a : p.pointing)
                if (a.secOfDay == 2717.996) {
                    p30 = true;
                    QCOMPARE(a.azimuthDeg, 326.8923);
                    QCOMPARE(a.elevationDeg, 32.9177);
                    QVERIFY(std::isnan(a.azimuthRate));
                }
        QVERIFY(p30);
    }

    /// Several passes per file with repeated H1..H3, and the day roll-over rule.
    void passesAndEpochs() {
        if (!lwbtest::haveShared("slr/beaconc_20070511.frd")) QSKIP("shared SLR data absent");
        const CrdReadResult r = readCrd(lwbtest::str(lwbtest::sharedPath("slr/beaconc_20070511.frd")));
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.file.passes.size(), size_t(3));
        // One h1/h2/h3 at the top; the second and third h4 blocks inherit them.
        QVERIFY(!r.file.passes[0].inheritsHeaders);
        QVERIFY(r.file.passes[1].inheritsHeaders);
        QVERIFY(r.file.passes[2].inheritsHeaders);
        QCOMPARE(r.file.passes[2].station.cdpPadId, 7080);
        QCOMPARE(r.file.passes[2].target.name, std::string("Beacon-C"));
        for (const auto& p : r.file.passes) {
            QVERIFY(p.endedWithH8);
            // Every epoch lies within the H4 start..end window (1 s margin).
            const double start = p.session.startHour * 3600 + p.session.startMinute * 60 + p.session.startSecond;
            const double end = p.session.endHour * 3600 + p.session.endMinute * 60 + p.session.endSecond;
            for (const auto& x : p.ranges) {
                QVERIFY(p.passSeconds(x.secOfDay) >= start - 1);
                QVERIFY(p.passSeconds(x.secOfDay) <= end + 1);
            }
        }
        // Roll-over: a pass that starts at 23:50 and has a record at 00:01:40.
        CrdPass p;
        p.session.startYear = 2020, p.session.startMonth = 1, p.session.startDay = 1;
        p.session.startHour = 23, p.session.startMinute = 50;
        QCOMPARE(p.passSeconds(100.0), 86500.0);
        QCOMPARE(p.passSeconds(85810.0), 85810.0);
        QCOMPARE(p.passSeconds(85700.0), 85700.0);  // a record 10 min before the H4 start stays on that day
    }

    // ---- CRD: write back -------------------------------------------------------------------------
    void roundTrip_data() { everyCrdFileParses_data(); }
    void roundTrip() {
        QFETCH(QString, file);
        if (!lwbtest::haveShared("slr/" + file)) QSKIP("shared SLR data absent");
        const QString path = lwbtest::sharedPath("slr/" + file);
        const CrdReadResult a = readCrd(lwbtest::str(path));
        QVERIFY2(a.ok, a.error.c_str());
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string out = lwbtest::str(dir.filePath("copy.crd"));
        std::string err;
        QVERIFY2(writeCrd(out, a.file, &err), err.c_str());
        QCOMPARE(lwbtest::filesIn(dir.path()), QStringList{"copy.crd"});  // no temporary left behind
        // Byte-identical copy (CRLF files stay CRLF); a missing line end after the last line is added.
        QByteArray original = lwbtest::readAll(path);
        if (!original.endsWith('\n')) original += a.file.crlf ? "\r\n" : "\n";
        QCOMPARE(lwbtest::readAll(QString::fromStdString(out)), original);
        const CrdReadResult b = readCrd(out);
        QVERIFY2(b.ok, b.error.c_str());
        QCOMPARE(b.file.passes.size(), a.file.passes.size());
        for (size_t k = 0; k < a.file.passes.size(); ++k) {
            const CrdPass &pa = a.file.passes[k], &pb = b.file.passes[k];
            const std::vector<CrdRecord> ra = allRecords(pa), rb = allRecords(pb);
            QCOMPARE(rb.size(), ra.size());
            for (size_t i = 0; i < ra.size(); ++i) {
                QCOMPARE(rb[i].text, ra[i].text);
                QCOMPARE(rb[i].line, ra[i].line);
            }
            QCOMPARE(pb.ranges.size(), pa.ranges.size());
            for (size_t i = 0; i < pa.ranges.size(); ++i) {
                QCOMPARE(pb.ranges[i].secOfDay, pa.ranges[i].secOfDay);
                QCOMPARE(pb.ranges[i].tofS, pa.ranges[i].tofS);
                QCOMPARE(pb.ranges[i].filterFlag, pa.ranges[i].filterFlag);
                QVERIFY(same(pb.ranges[i].receiveAmplitude, pa.ranges[i].receiveAmplitude));
            }
            QCOMPARE(pb.normalPoints.size(), pa.normalPoints.size());
            QCOMPARE(pb.meteo.size(), pa.meteo.size());
        }
        QCOMPARE(b.file.trailer.size(), a.file.trailer.size());
    }

    /// Writing an LF file without a final line end adds one; nothing else changes.
    void roundTripNoFinalNewline() {
        QTemporaryDir dir;
        QByteArray text = kGoodCrd;
        text.chop(1);
        const CrdReadResult a = readText(dir, "nofinal.fr2", text);
        QVERIFY2(a.ok, a.error.c_str());
        QCOMPARE(QByteArray::fromStdString(formatCrd(a.file)), kGoodCrd);
    }

    // A byte order mark or classic Mac line ends (CR alone) read as the same file (issue 27:
    // "not a CRD record \xef\xbb\xbfH1" and "no H4 session header in 1 lines"); the same for a
    // CSV table.
    void byteOrderMarkAndCrOnlyLineEnds() {
        const CrdReadResult plain = parseCrd(kGoodCrd.toStdString(), "plain.frd");
        QVERIFY2(plain.ok, plain.error.c_str());
        const CrdReadResult bom = parseCrd(("\xEF\xBB\xBF" + kGoodCrd).toStdString(), "bom.frd");
        QVERIFY2(bom.ok, bom.error.c_str());
        QCOMPARE(formatCrd(bom.file), formatCrd(plain.file));
        QByteArray cr = kGoodCrd;
        cr.replace('\n', '\r');
        const CrdReadResult mac = parseCrd(cr.toStdString(), "mac.frd");
        QVERIFY2(mac.ok, mac.error.c_str());
        QCOMPARE(formatCrd(mac.file), formatCrd(plain.file));
        QCOMPARE(mac.file.passes.front().ranges.size(), plain.file.passes.front().ranges.size());
        const lwb::core::CsvReadResult csv = lwb::core::parseCsv("\xEF\xBB\xBF" "a,b\r1,2\r3,4\r", "mac.csv");
        QVERIFY2(csv.ok, csv.error.c_str());
        QCOMPARE(csv.table.header.front(), std::string("a"));
        QCOMPARE(csv.table.rows.size(), size_t(2));
        QCOMPARE(csv.table.lines.back(), 3L);
        // A column named twice is refused (it was the first one, silently).
        const lwb::core::CsvReadResult twice = lwb::core::parseCsv("time,beam,x,y,X\n2020-01,1,2,3,4\n", "twice.csv");
        QVERIFY(!twice.ok);
        QVERIFY2(QString::fromStdString(twice.error).startsWith("twice.csv:1: column \"x\" appears twice"), twice.error.c_str());
    }

    // 86 400 s and beyond is 23:59:60: a leap second only on a day that ends with one (issue 27:
    // 86400.5 s on 2021-09-01 was taken as the next day, a residual of half an hour); a pass
    // across a leap second is said to be one.
    void leapSecondRecords() {
        QByteArray text = kGoodCrd;
        text.replace("10 74777.099340164496", "10 86400.500000000000");
        CrdReadResult r = parseCrd(text.toStdString(), "noleap.fr2");
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.file.passes.front().ranges.size(), size_t(2));
        QCOMPARE(r.file.passes.front().skippedLines, std::vector<long>{8});
        bool said = false;
        for (const auto& w : r.warnings) said = said || (w.find("noleap.fr2:8:") == 0 && w.find("2021-09-01 ends without one") != std::string::npos);
        QVERIFY(said);
        // 2016-12-31 ended with a leap second: kept; and a pass from before to after it is said to cross it.
        QByteArray leap = text;
        leap.replace("2021 9 1", "2016 12 31");
        leap.replace("H1 CRD 2 2016 12 31 21", "H1 CRD 2 2016 12 31 23");
        leap.replace("H4 0 2016 12 31 20 46 0", "H4 0 2016 12 31 23 59 50");
        leap.replace("10 74760.420166021300", "10 86390.000000000000");
        leap.replace("10 74776.082358022497", "10 5.000000000000");
        r = parseCrd(leap.toStdString(), "leap.fr2");
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.file.passes.front().ranges.size(), size_t(3));
        QVERIFY(r.file.passes.front().skippedLines.empty());
        said = false;
        for (const auto& w : r.warnings) said = said || w.find("crosses the leap second 2016-12-31 23:59:60") != std::string::npos;
        QVERIFY(said);
        QVERIFY(leapSecondAtEndOf(mjdFromDate(2016, 12, 31)));
        QVERIFY(leapSecondAtEndOf(mjdFromDate(1972, 6, 30)));
        QVERIFY(!leapSecondAtEndOf(mjdFromDate(2016, 12, 30)));
        QVERIFY(!leapSecondAtEndOf(mjdFromDate(2020, 12, 31)));
    }

    // Issue 44: a plain file's type-10 lines are not held in memory but read again from the file
    // when written; what is written is what the same text held in memory gives (CRLF, a
    // byte-order mark, no final line end, several passes). A gzip file, a CR-only text and a
    // text given in memory keep their lines. A file changed or removed since it was read is
    // refused with the reason, and nothing is written.
    void typeTenLinesReadAgainFromTheirFile() {
        QTemporaryDir dir;
        const QList<QPair<QString, QByteArray>> texts = goodCrdForms(
            kGoodCrd.left(kGoodCrd.size() - 3) +
            "H4 0 2021 9 1 20 50 0 2021 9 1 20 51 0 0 0 0 0 1 0 2 1\n10 75000.5 0.0131 sys1 2 2 0 0 0 na\n"
            "20 75000.5 1013.2 288.1 50 0\n10 75001.5 0.0131 sys1 2 0 0 0 0 na\n10 75002.5 0.0131 sys1 2 0 0 0 0 na\nH8\nH9\n");
        for (const auto& [name, text] : texts) {
            const std::string path = lwbtest::str(dir.filePath(name));
            QVERIFY(lwbtest::writeText(dir.filePath(name), text));
            const bool plain = name != "cr.frd";
            // What the same text held in memory gives, every range flagged noise.
            CrdReadResult mem = parseCrd(text.toStdString(), path);
            QVERIFY2(mem.ok, mem.error.c_str());
            std::string err;
            for (CrdPass& p : mem.file.passes) {
                QVERIFY(p.rangeLines.inMemory());
                QVERIFY2(setFilterFlags(&p, std::vector<int>(p.ranges.size(), 1), &err), err.c_str());
            }
            const std::string expected = formatCrd(mem.file);
            QVERIFY(!expected.empty());
            const CrdReadResult r = readCrd(path);
            QVERIFY2(r.ok, r.error.c_str());
            std::vector<CrdPass> streamed;
            QVERIFY(streamCrd(path, {}, nullptr, {}, [&](CrdPass&& p) { streamed.push_back(std::move(p)); return true; }).ok);
            QCOMPARE(streamed.size(), r.file.passes.size());
            for (size_t k = 0; k < r.file.passes.size(); ++k) {
                QCOMPARE(r.file.passes[k].rangeLines.inMemory(), !plain);
                QCOMPARE(streamed[k].rangeLines.inMemory(), !plain);
            }
            // The whole file with every pass's flags set, one pass at a time, as written.
            CrdFile flagged = r.file;
            for (size_t k = 0; k < flagged.passes.size(); ++k) {
                const std::string out = lwbtest::str(dir.filePath(name + QString(".%1.out").arg(k)));
                const std::vector<int> flags(flagged.passes[k].ranges.size(), 1);
                QVERIFY2(writeCrdWithFlags(out, flagged, k, flags, false, &err), err.c_str());
                QVERIFY2(setFilterFlags(&flagged.passes[k], flags, &err), err.c_str());
                QVERIFY(flagged.passes[k].rangeLines.inMemory());  // (read back to be changed)
            }
            QCOMPARE(formatCrd(flagged), expected);
            const std::string last = lwbtest::str(dir.filePath(name + QString(".%1.out").arg(flagged.passes.size() - 1)));
            if (flagged.passes.size() == 1) QCOMPARE(lwbtest::readAll(QString::fromStdString(last)).toStdString(), expected);
            // Alone: the pass with its own H9.
            const std::string alone = lwbtest::str(dir.filePath(name + ".alone"));
            QVERIFY2(writeCrdWithFlags(alone, r.file, 0, std::vector<int>(r.file.passes[0].ranges.size(), 1), true, &err),
                     err.c_str());
            QCOMPARE(lwbtest::readAll(QString::fromStdString(alone)).toStdString(), formatCrd(passAlone(flagged.passes[0])));
        }
        // Read by a relative name, written after the working folder changed: the same file.
        {
            const QString was = QDir::currentPath();
            QVERIFY(QDir::setCurrent(dir.path()));
            const CrdReadResult rel = readCrd("good.frd");
            QVERIFY(QDir::setCurrent(QDir::tempPath()));
            std::string err;
            const std::string out = lwbtest::str(dir.filePath("rel.out"));
            const bool ok = writeCrdWithFlags(out, rel.file, 0, std::vector<int>(3, 1), false, &err);
            QVERIFY(QDir::setCurrent(was));
            QVERIFY2(rel.ok && ok, (rel.error + err).c_str());
            QVERIFY(!rel.file.passes[0].rangeLines.inMemory());
        }
        // gzip keeps its lines in memory (they are not at offsets of the file).
        QCOMPARE(QProcess::execute("sh", {"-c", "cd '" + dir.path() + "' && gzip -c good.frd > good.frd.gz"}), 0);
        const CrdReadResult gz = readCrd(lwbtest::str(dir.filePath("good.frd.gz")));
        QVERIFY2(gz.ok, gz.error.c_str());
        QVERIFY(gz.file.passes[0].rangeLines.inMemory());
        // Changed since it was read (a comment line added at the top), then removed: refused, nothing written.
        const std::string moved = lwbtest::str(dir.filePath("moved.frd"));
        QVERIFY(lwbtest::writeText(dir.filePath("moved.frd"), kGoodCrd));
        const CrdReadResult before = readCrd(moved);
        QVERIFY2(before.ok, before.error.c_str());
        QVERIFY(lwbtest::writeText(dir.filePath("moved.frd"), "00 a comment\n" + kGoodCrd));
        const std::string out = lwbtest::str(dir.filePath("moved.out"));
        std::string err;
        QVERIFY(!writeCrdWithFlags(out, before.file, 0, std::vector<int>(3, 1), false, &err));
        QVERIFY2(err.find("moved.frd: the file changed since it was read") != std::string::npos, err.c_str());
        QVERIFY(!QFile::exists(QString::fromStdString(out)));
        QVERIFY(!writeCrd(out, before.file, &err));
        QVERIFY(!QFile::exists(QString::fromStdString(out)));
        QVERIFY(allRecords(before.file.passes[0], &err).empty());
        QVERIFY(QFile::remove(dir.filePath("moved.frd")));
        QVERIFY(!writeCrd(out, before.file, &err));
        QVERIFY2(err.find("cannot read the file's type-10 records again") != std::string::npos, err.c_str());
        QVERIFY(!QFile::exists(QString::fromStdString(out)));
    }

    // Issue 44: a range's record index and line are kept as runs rising by one (CrdStepColumn).
    // Every value comes back as pushed: one run, runs broken by other records, a pattern that
    // breaks every other value (then one value per record), an erase; and on every shared file,
    // each range's line is its type-10 line's (rangeLines, by its record index, rising) and its
    // text starts "10".
    void rangeRecordsAndLinesComeBackAsPushed() {
        const std::vector<std::vector<uint32_t>> cases = {
            {}, {7}, {0, 1, 2, 3, 4}, {5, 6, 7, 20, 21, 22, 40, 41}, {3, 3, 3}, {9, 8, 7, 6},
            {0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30, 32, 34, 36, 38, 40, 42, 44, 46, 48, 50},
            {UINT32_MAX - 1, UINT32_MAX, 0, 1}};
        for (const auto& values : cases) {
            CrdStepColumn<uint32_t> c;
            for (uint32_t v : values) c.push(v);
            QCOMPARE(c.size(), values.size());
            QCOMPARE(c.empty(), values.empty());
            for (size_t i = 0; i < values.size(); ++i) QCOMPARE(c.at(i), values[i]);
            const CrdStepColumn<uint32_t> same = CrdStepColumn<uint32_t>::of(values);
            QCOMPARE(same.size(), values.size());
            for (size_t i = 0; i < values.size(); ++i) QCOMPARE(same.at(i), values[i]);
            if (values.size() > 20) QVERIFY(c.bytes() <= (values.size() + 16) * 2 * sizeof(uint32_t));
            if (values.size() < 3) continue;
            std::vector<uint32_t> rest = values;
            rest.erase(rest.begin() + 1);
            c.erase(1);
            c.push(1000);
            rest.push_back(1000);
            QCOMPARE(c.size(), rest.size());
            for (size_t i = 0; i < rest.size(); ++i) QCOMPARE(c.at(i), rest[i]);
            c.erase(c.size() - 1);  // the last one
            rest.pop_back();
            QCOMPARE(c.size(), rest.size());
            for (size_t i = 0; i < rest.size(); ++i) QCOMPARE(c.at(i), rest[i]);
            // Moved from: empty, as a vector is; the moved-to column has the values.
            CrdStepColumn<uint32_t> moved = std::move(c);
            QCOMPARE(c.size(), size_t(0));
            QVERIFY(c.empty());
            QCOMPARE(moved.size(), rest.size());
            for (size_t i = 0; i < rest.size(); ++i) QCOMPARE(moved.at(i), rest[i]);
            c.push(5);  // (usable again)
            QCOMPARE(c.at(0), 5u);
        }
        CrdStepColumn<uint32_t> big;
        for (uint32_t v = 0; v < 1000000; ++v) big.push(v + (v >= 500000 ? 3 : 0));  // a meteorological line between
        QCOMPARE(big.at(499999), 499999u);
        QCOMPARE(big.at(500000), 500003u);
        QVERIFY2(big.bytes() < 1000, qPrintable(QString::number(big.bytes())));  // two runs, not 4 MB
        big.erase(10);  // (an erased record, a leap second's: still runs)
        QCOMPARE(big.size(), size_t(999999));
        QCOMPARE(big.at(9), 9u);
        QCOMPARE(big.at(10), 11u);
        QCOMPARE(big.at(499998), 499999u);
        QCOMPARE(big.at(499999), 500003u);
        QVERIFY2(big.bytes() < 1000, qPrintable(QString::number(big.bytes())));
        int files = 0;
        for (const QString& name : QDir(lwbtest::sharedPath("slr")).entryList({"*.frd", "*.fr2", "*.npt", "*.np2"})) {
            const CrdReadResult r = parseCrd(lwbtest::readAll(lwbtest::sharedPath("slr/" + name)).toStdString(), "x");
            if (!r.ok) continue;
            ++files;
            for (const CrdPass& p : r.file.passes) {
                for (size_t i = 0; i < p.ranges.size(); ++i) {
                    const size_t k = p.ranges.record(i);
                    QVERIFY(k < p.rangeLines.size() && (i == 0 || k > p.ranges.record(i - 1)));
                    QCOMPARE(p.ranges.line(i), p.rangeLines.line(k));
                    QCOMPARE(p.ranges[i].line, p.ranges.line(i));
                    QCOMPARE(p.ranges[i].record, k);
                    QVERIFY(p.rangeLines.text(k).substr(0, 2) == "10");
                }
            }
        }
        if (files == 0) QSKIP("shared SLR data absent");
    }

    void setFilterFlagsChangesOnlyTheFlag() {
        if (!lwbtest::haveShared("slr/7080_JASON1_crd_071220_2033_0.frd")) QSKIP("shared SLR data absent");
        CrdReadResult a = readCrd(lwbtest::str(lwbtest::sharedPath("slr/7080_JASON1_crd_071220_2033_0.frd")));
        QVERIFY2(a.ok, a.error.c_str());
        CrdPass& p = a.file.passes.front();
        const CrdPass before = p;
        std::vector<int> flags;
        for (const auto& r : p.ranges) flags.push_back(r.filterFlag == 2 ? 1 : 2);  // swap the classes
        std::string err;
        QVERIFY(!setFilterFlags(&p, std::vector<int>(flags.size() - 1, 2), &err));  // wrong size
        QVERIFY(!err.empty());
        QVERIFY(!setFilterFlags(&p, std::vector<int>(flags.size(), 3), &err));      // not a class
        QVERIFY2(setFilterFlags(&p, flags, &err), err.c_str());
        QTemporaryDir dir;
        const std::string out = lwbtest::str(dir.filePath("flags.frd"));
        QVERIFY2(writeCrd(out, a.file, &err), err.c_str());
        const CrdReadResult b = readCrd(out);
        QVERIFY2(b.ok, b.error.c_str());
        QCOMPARE(countRanges(b.file, 2), size_t(200));
        QCOMPARE(countRanges(b.file, 1), size_t(59));
        const std::vector<CrdRecord> q = allRecords(b.file.passes.front()), was = allRecords(before);
        QCOMPARE(q.size(), was.size());
        for (size_t i = 0; i < q.size(); ++i) {
            if (q[i].id != "10") {
                QCOMPARE(q[i].text, was[i].text);
                continue;
            }
            // Same fields except the 6th; same spacing.
            QStringList fa = QString::fromStdString(was[i].text).split(' ');
            QStringList fb = QString::fromStdString(q[i].text).split(' ');
            QCOMPARE(fb.size(), fa.size());
            int diffs = 0;
            for (int k = 0; k < fa.size(); ++k) diffs += fa[k] != fb[k];
            QCOMPARE(diffs, 1);
        }
        const CrdPass& qp = b.file.passes.front();
        for (size_t i = 0; i < qp.ranges.size(); ++i) {
            QCOMPARE(qp.ranges[i].filterFlag, flags[i]);
            QCOMPARE(qp.ranges[i].tofS, before.ranges[i].tofS);
        }
    }

    void normalPointsWrittenAndReadBack() {
        if (!lwbtest::haveShared("slr/7080_JASON1_crd_071220_2033_0.npt")) QSKIP("shared SLR data absent");
        const CrdReadResult np = readCrd(lwbtest::str(lwbtest::sharedPath("slr/7080_JASON1_crd_071220_2033_0.npt")));
        const CrdReadResult fr = readCrd(lwbtest::str(lwbtest::sharedPath("slr/7080_JASON1_crd_071220_2033_0.frd")));
        QVERIFY2(np.ok && fr.ok, (np.error + fr.error).c_str());
        const std::vector<CrdNormalPoint> station = np.file.passes.front().normalPoints;  // the station's own NPs
        QCOMPARE(station.size(), size_t(11));
        std::vector<CrdNormalPoint> mine = station;
        mine[0].snr = 12.5;
        mine[1].binRmsPs = NAN;  // absent value
        for (int version : {2, 1}) {
            CrdPass src = fr.file.passes.front();
            src.format.version = version;
            CrdPass out;
            std::string err;
            QVERIFY2(makeNormalPointPass(src, mine, &out, &err), err.c_str());
            CrdFile f;
            f.passes.push_back(out);
            QTemporaryDir dir;
            const std::string path = lwbtest::str(dir.filePath("made.npt"));
            QVERIFY2(writeCrd(path, f, &err), err.c_str());
            const CrdReadResult back = readCrd(path);
            QVERIFY2(back.ok, back.error.c_str());
            const CrdPass& b = back.file.passes.front();
            QCOMPARE(b.session.dataType, 1);  // H4 data type set to normal point
            QVERIFY(b.ranges.empty());
            QVERIFY(b.pointing.empty());
            QCOMPARE(b.meteo.size(), src.meteo.size());  // met and calibration records kept
            QCOMPARE(b.calibrations.size(), src.calibrations.size());
            QCOMPARE(b.normalPoints.size(), mine.size());
            for (size_t i = 0; i < mine.size(); ++i) {
                const CrdNormalPoint &a = mine[i], &c = b.normalPoints[i];
                // Written with 12 decimals: 1 ps in time of flight, 1 ps in epoch (plus the double's own step).
                QVERIFY(std::fabs(c.secOfDay - a.secOfDay) < 1e-9);
                QVERIFY(std::fabs(c.tofS - a.tofS) < 1e-12);
                QCOMPARE(c.configId, a.configId);
                QCOMPARE(c.epochEvent, a.epochEvent);
                QCOMPARE(c.windowS, a.windowS);
                QCOMPARE(c.numRanges, a.numRanges);
                if (i == 1) {
                    if (version >= 2) QVERIFY(std::isnan(c.binRmsPs));  // "na"
                    else QCOMPARE(c.binRmsPs, -1.0);                    // v1 has no "na": -1
                } else {
                    QVERIFY(std::fabs(c.binRmsPs - a.binRmsPs) < 0.05 + 1e-9);  // 1 decimal
                }
                QVERIFY(std::fabs(c.skew - a.skew) < 5e-4 + 1e-9);  // 3 decimals
                QVERIFY(std::fabs(c.returnRatePct - a.returnRatePct) < 5e-3 + 1e-9);
                if (i == 0 && version >= 2) QCOMPARE(c.snr, 12.5);
                if (version < 2) QVERIFY(std::isnan(c.snr));  // v1 has no SNR field
            }
        }
        // Replace and append in place on the station's NP pass.
        CrdPass p = np.file.passes.front();
        const size_t records = p.records.size();
        std::string err;
        std::vector<CrdNormalPoint> three(station.begin(), station.begin() + 3);
        QVERIFY2(setNormalPoints(&p, three, NormalPointMode::Replace, &err), err.c_str());
        QCOMPARE(p.normalPoints.size(), size_t(3));
        QCOMPARE(p.records.size(), records - 8);
        QVERIFY2(setNormalPoints(&p, three, NormalPointMode::Append, &err), err.c_str());
        QCOMPARE(p.normalPoints.size(), size_t(6));
        QCOMPARE(p.records.back().id, std::string("h8"));  // still closed by its H8
        std::vector<CrdNormalPoint> bad = three;
        bad[2].tofS = NAN;
        QVERIFY(!setNormalPoints(&p, bad, NormalPointMode::Replace, &err));
        QVERIFY2(err.find("normal point 2") != std::string::npos, err.c_str());
        QCOMPARE(p.normalPoints.size(), size_t(6));  // unchanged by the refused call
    }

    // ---- CRD: bad input --------------------------------------------------------------------------
    void goodSmallFile() {
        QTemporaryDir dir;
        const CrdReadResult r = readText(dir, "good.fr2", kGoodCrd);
        QVERIFY2(r.ok, r.error.c_str());
        QVERIFY(r.warnings.empty());
        QCOMPARE(r.file.passes.front().ranges.size(), size_t(3));
    }

    /// A bad record inside a sound pass: skipped with a warning that names file and line.
    void badRecordWarns_data() {
        QTest::addColumn<QByteArray>("line6");
        QTest::addColumn<QString>("what");
        QTest::newRow("truncated line") << QByteArray("10 74760.42") << "missing";
        QTest::newRow("text in a number") << QByteArray("10 74760.420166021300 0.0130x4392652 sys1 2 2 0 0 0 na")
                                          << "not a finite number";
        QTest::newRow("NaN tof") << QByteArray("10 74760.420166021300 NaN sys1 2 2 0 0 0 na") << "not a finite number";
        QTest::newRow("nan epoch") << QByteArray("10 nan 0.013024392652 sys1 2 2 0 0 0 na") << "not a finite number";
        QTest::newRow("inf amplitude") << QByteArray("10 74760.420166021300 0.013024392652 sys1 2 2 0 0 inf na")
                                       << "not a finite number";
        QTest::newRow("na tof") << QByteArray("10 74760.420166021300 na sys1 2 2 0 0 0 na") << "\"na\"";
        QTest::newRow("bad flag") << QByteArray("10 74760.420166021300 0.013024392652 sys1 2 7 0 0 0 na")
                                  << "filter flag";
        QTest::newRow("negative tof") << QByteArray("10 74760.420166021300 -0.013 sys1 2 2 0 0 0 na") << "outside";
        QTest::newRow("day overflow") << QByteArray("10 99999.5 0.013024392652 sys1 2 2 0 0 0 na") << "outside";
        QTest::newRow("unknown record") << QByteArray("77 garbage here") << "unknown record type";
    }
    void badRecordWarns() {
        QFETCH(QByteArray, line6);
        QFETCH(QString, what);
        QTemporaryDir dir;
        QString path;
        const CrdReadResult r = readText(dir, "bad.fr2", replaceLine(kGoodCrd, 6, line6), &path);
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.file.passes.front().ranges.size(), size_t(2));  // the two sound records are kept
        QString why;
        QVERIFY2(oneWarning(r, path + ":6: ", {what}, &why), qPrintable(why));
        // The bad line is still written back: nothing is lost.
        QCOMPARE(QByteArray::fromStdString(formatCrd(r.file)), replaceLine(kGoodCrd, 6, line6));
    }

    /// Files that cannot be read: a clear error that names file and line.
    void badFileErrors_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("where");  // ":LINE:" or "" for file-level errors
        QTest::addColumn<QString>("what");
        QTest::newRow("empty file") << QByteArray() << "" << "empty file";
        QTest::newRow("blank lines only") << QByteArray("\n  \n\r\n") << "" << "empty file";
        QTest::newRow("data before any H4")
            << QByteArray("H1 CRD 2 2021 9 1 21\nH2 GLSL 1824 81 1 4 EUROLAS\nH3 hy2c 2006601 2209 46469 0 1 1\n"
                          "10 74760.42 0.0130 sys1 2 2 0 0 0 na\nH8\n")
            << ":4:" << "no H4";
        QTest::newRow("data before the H1") << QByteArray("10 74760.42 0.0130 sys1 2 2 0 0 0 na\n") << ":1:" << "H1";
        QTest::newRow("H4 before H1") << QByteArray("H4 0 2021 9 1 20 46 0 2021 9 1 20 47 19 0 0 0 0 1 0 2 1\n")
                                      << ":1:" << "before any H1";
        QTest::newRow("H4 without H2") << QByteArray("H1 CRD 2 2021 9 1 21\nH3 hy2c 2006601 2209 46469 0 1 1\n"
                                                     "H4 0 2021 9 1 20 46 0 2021 9 1 20 47 19 0 0 0 0 1 0 2 1\n")
                                       << ":3:" << "H2";
        QTest::newRow("pass with zero data records")
            << replaceLine(replaceLine(replaceLine(kGoodCrd, 6, "00 gone"), 7, "00 gone"), 8, "00 gone") << ":4:"
            << "no readable range record";
        QTest::newRow("pass whose only data are bad")
            << replaceLine(replaceLine(replaceLine(kGoodCrd, 6, "10 x"), 7, "10 y"), 8, "10 z") << ":4:"
            << "no readable range record";
        QTest::newRow("bad H4 date") << replaceLine(kGoodCrd, 4, "H4 0 2021 13 1 20 46 0 2021 9 1 20 47 19 0 0 0 0 1 0 2 1")
                                     << ":4:" << "not a valid date";
        QTest::newRow("truncated H4") << replaceLine(kGoodCrd, 4, "H4 0 2021 9 1 20") << ":4:" << "H4 needs";
        QTest::newRow("NaN in H4") << replaceLine(kGoodCrd, 4, "H4 0 2021 nan 1 20 46 0 2021 9 1 20 47 19 0 0 0 0 1 0 2 1")
                                   << ":4:" << "not an integer";
        QTest::newRow("binary garbage with NUL")
            << QByteArray("\x7f" "ELF\x02\x01\x01\x00\x00\x00\n\xff\xfe\x00\x01", 16) << ":1:" << "binary data";
        QTest::newRow("binary garbage without NUL") << QByteArray("\xff\xd8\xff\xe0 JFIF\n\x89PNG\r\n") << ":1:"
                                                    << "not a CRD record";
        QTest::newRow("a CSV file") << QByteArray("epoch_s,oc_s\n1,2\n") << ":1:" << "not a CRD record";
    }
    void badFileErrors() {
        QFETCH(QByteArray, text);
        QFETCH(QString, where);
        QFETCH(QString, what);
        QTemporaryDir dir;
        QString path;
        const CrdReadResult r = readText(dir, "bad.crd", text, &path);
        QVERIFY(!r.ok);
        QVERIFY(r.file.passes.empty());
        const QString e = QString::fromStdString(r.error);
        QVERIFY2(e.startsWith(path + (where.isEmpty() ? QString(":") : where)), r.error.c_str());
        QVERIFY2(e.contains(what), r.error.c_str());
    }

    void missingFileAndFolder() {
        const CrdReadResult a = readCrd("/nonexistent/x.frd");
        QVERIFY(!a.ok);
        QVERIFY(a.error.find("/nonexistent/x.frd") != std::string::npos);
        QTemporaryDir dir;
        const CrdReadResult b = readCrd(lwbtest::str(dir.path()));
        QVERIFY(!b.ok);
        QVERIFY2(b.error.find("folder") != std::string::npos, b.error.c_str());
    }

    /// Passes closed without H8, and H1..H3 inherited by a following H4.
    void structureVariants() {
        QTemporaryDir dir;
        const QByteArray text = "00 leading comment\n"
                                "h1 crd 1 2021 9 1 21\nh2 GLSL 1824 81 1 4\nh3 hy2c 2006601 2209 46469 0 1\n"
                                "h4 0 2021 9 1 20 46 0 2021 9 1 20 47 19 0 0 0 0 1 0 2 0\n"
                                "10 74760.4 0.0130 sys1 2 2 0 0\n"
                                "h4 0 2021 9 1 21 46 0 2021 9 1 21 47 19 0 0 0 0 1 0 2 0\n"  // line 7: new H4, no H8
                                "10 78360.4 0.0131 sys1 2 1\n"
                                "93 user record kept\n"
                                "h8\n";
        const CrdReadResult r = readText(dir, "variants.frd", text);
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.file.passes.size(), size_t(2));
        QVERIFY(!r.file.passes[0].endedWithH8);
        QVERIFY(r.file.passes[1].endedWithH8);
        QVERIFY(!r.file.passes[0].inheritsHeaders);
        QVERIFY(r.file.passes[1].inheritsHeaders);
        QCOMPARE(r.file.passes[1].station.cdpPadId, 1824);
        QCOMPARE(r.file.passes[1].ranges.front().filterFlag, 1);
        QCOMPARE(r.file.passes[1].ranges.front().detectorChannel, kCrdAbsent);  // v1 short record
        QCOMPARE(r.warnings.size(), size_t(1));
        QVERIFY2(r.warnings[0].find(":7:") != std::string::npos, r.warnings[0].c_str());
        QCOMPARE(QByteArray::fromStdString(formatCrd(r.file)), text);
        // A normal-point pass made from the second one carries the inherited headers.
        CrdPass np;
        std::string err;
        CrdNormalPoint n;
        n.secOfDay = 78360.4;
        n.tofS = 0.0131;
        n.windowS = 5;
        n.numRanges = 1;
        QVERIFY2(makeNormalPointPass(r.file.passes[1], {n}, &np, &err), err.c_str());
        QCOMPARE(np.records.front().id, std::string("h1"));
        QVERIFY(!np.inheritsHeaders);
    }

    // ---- issue 8, item 9: other projects' fixtures (written here from their description) --------

    /// A last block whose H4 gives the end date-time as unknown (-1 in all six fields): read with
    /// a note, the end unknown; a bare H4 with no record, or a bad H4, costs only its own block.
    void unusableBlockKeepsTheOtherPasses_data() {
        QTest::addColumn<QByteArray>("lastBlock");
        QTest::addColumn<bool>("usable");     // the last block is read as a pass
        QTest::addColumn<QString>("what");    // in the warning at line 11 (the last H4)
        QTest::newRow("end unknown, with records")
            << QByteArray("H4 0 2021 9 1 21 46 0 -1 -1 -1 -1 -1 -1 0 0 0 0 1 0 2 0\n"
                          "10 78360.4 0.0131 sys1 2 2 0 0 0 na\nH8\n")
            << true << "end date-time is not given";
        QTest::newRow("end unknown (na), with records")
            << QByteArray("h4 0 2021 9 1 21 46 0 na na na na na na 0 0 0 0 1 0 2 0\n"
                          "10 78360.4 0.0131 sys1 2 2 0 0 0 na\nh8\n")
            << true << "end date-time is not given";
        QTest::newRow("bare H4, end unknown, no record")
            << QByteArray("H4 1 2021 9 1 21 46 0 -1 -1 -1 -1 -1 -1 0 0 0 0 1 0 2 0\n") << false
            << "no readable range record";
        QTest::newRow("start unknown") << QByteArray("H4 0 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 -1 0 0 0 0 1 0 2 0\n"
                                                     "10 78360.4 0.0131 sys1 2 2 0 0 0 na\nH8\n")
                                       << false << "start date-time is not a valid date";
        QTest::newRow("end half unknown") << QByteArray("H4 0 2021 9 1 21 46 0 2021 -1 -1 -1 -1 -1 0 0 0 0 1 0 2 0\n"
                                                        "10 78360.4 0.0131 sys1 2 2 0 0 0 na\nH8\n")
                                          << false << "end date-time is not a valid date";
    }
    void unusableBlockKeepsTheOtherPasses() {
        QFETCH(QByteArray, lastBlock);
        QFETCH(bool, usable);
        QFETCH(QString, what);
        // Two sound passes (lines 1-9, the second inheriting H1-H3), then the block at line 11.
        QByteArray text = kGoodCrd;
        text.chop(3);  // no H9 yet
        text += "H4 0 2021 9 1 20 50 0 2021 9 1 20 51 0 0 0 0 0 1 0 2 1\n"  // 9
                "10 75000.5 0.0131 sys1 2 2 0 0 0 na\n"                     // 10
                + lastBlock + "H9\n";
        text.replace("H8\nH4 0 2021 9 1 20 50", "H4 0 2021 9 1 20 50");  // the first pass ends with the new H4
        QTemporaryDir dir;
        QString path;
        const CrdReadResult r = readText(dir, "blocks.crd", text, &path);
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.file.passes.size(), size_t(3));
        QCOMPARE(r.file.passes[0].ranges.size(), size_t(3));
        QCOMPARE(r.file.passes[1].ranges.size(), size_t(1));
        QVERIFY(r.file.passes[0].problem.empty() && r.file.passes[1].problem.empty());
        const CrdPass& last = r.file.passes[2];
        QCOMPARE(last.problem.empty(), usable);
        QCOMPARE(last.ranges.size(), size_t(usable ? 1 : 0));
        if (usable) QCOMPARE(last.session.endYear, kCrdAbsent);
        // The message about the block names its H4 line (and, when skipped, the pass).
        int about = 0;
        for (const auto& w : r.warnings)
            about += w.rfind(lwbtest::str(path) + ":11: ", 0) == 0 && QString::fromStdString(w).contains(what) &&
                     (usable || w.find("pass 3 skipped") != std::string::npos);
        QVERIFY2(about == 1, joined(r.warnings).c_str());
        // Nothing is lost on writing back, the unusable block included.
        QCOMPARE(QByteArray::fromStdString(formatCrd(r.file)), text);
        // A file whose every block is unusable is still refused, naming the first one.
        const CrdReadResult alone = readText(dir, "alone.crd", "H1 CRD 2 2021 9 1 21\nH2 GLSL 1824 81 1 4 EUROLAS\n"
                                                               "H3 hy2c 2006601 2209 46469 0 1 1\n" + lastBlock);
        if (!usable) {
            QVERIFY(!alone.ok);
            QVERIFY2(alone.error.find(":4: ") != std::string::npos && QString::fromStdString(alone.error).contains(what),
                     alone.error.c_str());
        }
    }

    /// H4 flags outside their ranges: a warning naming the field, read as unknown.
    void h4FlagsOutOfRange_data() {
        QTest::addColumn<QByteArray>("h4");
        QTest::addColumn<QString>("what");
        QTest::newRow("range type 9") << QByteArray("H4 0 2021 9 1 20 46 0 2021 9 1 20 47 19 0 0 0 0 1 0 9 1")
                                      << "field 20 (range type indicator) is 9, outside 0..4";
        QTest::newRow("quality alert 7") << QByteArray("H4 0 2021 9 1 20 46 0 2021 9 1 20 47 19 0 0 0 0 1 0 2 7")
                                         << "field 21 (data quality alert indicator) is 7";
        QTest::newRow("refraction flag 2") << QByteArray("H4 0 2021 9 1 20 46 0 2021 9 1 20 47 19 0 2 0 0 1 0 2 1")
                                           << "field 15 (tropospheric refraction applied indicator) is 2";
        QTest::newRow("text flag") << QByteArray("H4 0 2021 9 1 20 46 0 2021 9 1 20 47 19 0 0 0 0 x 0 2 1")
                                   << "station system delay applied indicator";
    }
    void h4FlagsOutOfRange() {
        QFETCH(QByteArray, h4);
        QFETCH(QString, what);
        QTemporaryDir dir;
        QString path;
        const CrdReadResult r = readText(dir, "flags.fr2", replaceLine(kGoodCrd, 4, h4), &path);
        QVERIFY2(r.ok, r.error.c_str());
        QString why;
        QVERIFY2(oneWarning(r, path + ":4: H4 ", {what, "read as unknown"}, &why), qPrintable(why));
        const CrdSession& s = r.file.passes.front().session;
        const int flags[8] = {s.releaseFlag, s.refractionApplied, s.comApplied, s.receiveAmpApplied, s.stationDelayApplied,
                              s.spacecraftDelayApplied, s.rangeType, s.qualityAlert};
        int unknown = 0;
        for (int f : flags) unknown += f == kCrdAbsent;
        QCOMPARE(unknown, 1);  // only the bad one
    }

    /// An H1 naming CPF is a prediction given as ranging data: refused at its line. Another
    /// unknown format name is read as CRD v1 with one warning (not one per reading of the H1).
    void h1FormatName() {
        QTemporaryDir dir;
        QString path;
        const CrdReadResult cpf = readText(dir, "h1.v2C", replaceLine(kGoodCrd, 1, "H1 CPF 2 2021 9 1 21"), &path);
        QVERIFY(!cpf.ok);
        QVERIFY2(QString::fromStdString(cpf.error).startsWith(path + ":1: "), cpf.error.c_str());
        QVERIFY2(cpf.error.find("\"CPF\", not \"CRD\"") != std::string::npos, cpf.error.c_str());
        const CrdReadResult other = readText(dir, "h1.frd", replaceLine(kGoodCrd, 1, "h1 XRD 2 2021 9 1 21"), &path);
        QVERIFY2(other.ok, other.error.c_str());
        QString why;
        QVERIFY2(oneWarning(other, path + ":1: ", {"read as CRD v1"}, &why), qPrintable(why));
    }

    /// A corrupted time of flight in a type-11 (normal point) or type-10 record: skipped with a
    /// warning that names the line and the field.
    void corruptedTimeOfFlight_data() {
        QTest::addColumn<QByteArray>("record");
        QTest::newRow("type 11") << QByteArray("11 74776.082358022497   corrupted    sys1 2 120.0 1515 72.1 0.227 2.222 -14.0 1.3 0 5.7");
        QTest::newRow("type 10") << QByteArray("10 74776.082358022497   corrupted    sys1 2 2 0 0 0 na");
    }
    void corruptedTimeOfFlight() {
        QFETCH(QByteArray, record);
        QTemporaryDir dir;
        QString path;
        QByteArray text = replaceLine(kGoodCrd, 7, record);
        if (record.startsWith("11")) {  // a normal-point pass
            text = replaceLine(text, 4, "H4 1 2021 9 1 20 46 0 2021 9 1 20 47 19 0 0 0 0 1 0 2 1");
            text = replaceLine(text, 6, "11 74760.420166021300 0.013024392652 sys1 2 120.0 1457 70.0 0.319 2.496 -12.0 1.2 0 5.7");
            text = replaceLine(text, 8, "11 74777.099340164496 0.013115307576 sys1 2 120.0 894 66.8 0.255 2.620 -7.0 0.7 0 5.7");
        }
        const CrdReadResult r = readText(dir, "tof.crd", text, &path);
        QVERIFY2(r.ok, r.error.c_str());
        QString why;
        QVERIFY2(oneWarning(r, path + ":7: type 1", {"time of flight", "corrupted"}, &why), qPrintable(why));
        QCOMPARE(r.file.passes.front().skippedLines, std::vector<long>{7});
    }

    void cancelStopsTheRead() {
        lwb::core::Feedback fb;
        fb.cancel();
        const CrdReadResult r = parseCrd(kGoodCrd.toStdString(), "mem", {}, &fb);
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("cancelled") != std::string::npos, r.error.c_str());
    }

    /// Inputs the fuzzer produced: each once crashed, leaked or hung (see docs/fuzzing.md).
    void fuzzRegressions_data() {
        QTest::addColumn<QByteArray>("bytes");
        // Fuzz run 1 (docs/fuzzing.md): an LF file with a line ending "\r\r\n" read back differently after writing
        // (one CR stripped, the other written before an LF and stripped on the next read).
        QTest::newRow("double CR before LF") << replaceLine(kGoodCrd, 6, QByteArray(
            "10 74760.420166021300 0.013024392652 sys1 2 2 0 0 0 na\r\r"));
    }
    void fuzzRegressions() {
        QFETCH(QByteArray, bytes);
        const std::string_view s(bytes.constData(), static_cast<size_t>(bytes.size()));
        const CrdReadResult c = parseCrd(s, "fuzz");
        // Every regression row is a sound CRD file with one odd byte sequence: it must read.
        QVERIFY2(c.ok, c.error.c_str());
        {
            // The fuzz target's invariant: written and read back, the same records and the same text.
            const std::string written = formatCrd(c.file);
            const CrdReadResult again = parseCrd(written, "fuzz");
            QVERIFY(again.ok);
            QCOMPARE(again.file.passes.size(), c.file.passes.size());
            for (size_t k = 0; k < c.file.passes.size(); ++k) {
                QCOMPARE(again.file.passes[k].records.size(), c.file.passes[k].records.size());
                for (size_t i = 0; i < c.file.passes[k].records.size(); ++i)
                    QCOMPARE(again.file.passes[k].records[i].text, c.file.passes[k].records[i].text);
            }
            QCOMPARE(formatCrd(again.file), written);
        }
        // The same bytes are no CPF and no SINEX: refused with a message, not a crash.
        const CpfReadResult p = parseCpf(s, "fuzz");
        QVERIFY(!p.ok && !p.error.empty());
        const SinexReadResult x = parseSinex(s, "fuzz");
        QVERIFY(!x.ok && !x.error.empty());
    }

    // ---- CPF ------------------------------------------------------------------------------------
    void cpfReads() {
        if (!lwbtest::haveShared("slr/blits_cpf_120626_6801.hts")) QSKIP("shared SLR data absent");
        const QString path = lwbtest::sharedPath("slr/blits_cpf_120626_6801.hts");
        const CpfReadResult r = readCpf(lwbtest::str(path));
        QVERIFY2(r.ok, r.error.c_str());
        QVERIFY(r.warnings.empty());
        QCOMPARE(static_cast<int>(r.file.positions.size()), countLines(lwbtest::readAll(path), "10"));
        // "H1 CPF  1  HTS 2012  6 26 12  6801 blits            NONE"
        const CpfHeader& h = r.file.header;
        QCOMPARE(h.version, 1);
        QCOMPARE(h.source, std::string("HTS"));
        QCOMPARE(h.targetName, std::string("blits"));
        QCOMPARE(h.sequence, std::string("6801"));
        // "H2  0904907 5558    35871 2012 06 26  0  0  0 2012 07 01  0  0  0   240 1 1  0 0 1"
        QCOMPARE(h.ilrsId, std::string("0904907"));
        QCOMPARE(h.norad, 35871L);
        QCOMPARE(h.stepS, 240.0);
        QCOMPARE(h.startMjd, mjdFromDate(2012, 6, 26));
        QCOMPARE(h.endMjd, mjdFromDate(2012, 7, 1));
        QCOMPARE(h.comApplied, 1);
        // "10 0 56103  85200.00000  0    -490800.267    1737692.785   -6977919.039"
        const CpfPosition& p0 = r.file.positions.front();
        QCOMPARE(p0.mjd, 56103L);
        QCOMPARE(p0.sod, 85200.0);
        QCOMPARE(p0.position.x(), -490800.267);
        QCOMPARE(p0.position.z(), -6977919.039);
        QCOMPARE(mjdFromDate(2012, 6, 25), 56103L);  // the first record is 25 June 23:40
    }

    void cpfInterpolation() {
        if (!lwbtest::haveShared("slr/blits_cpf_120626_6801.hts")) QSKIP("shared SLR data absent");
        const CpfReadResult r = readCpf(lwbtest::str(lwbtest::sharedPath("slr/blits_cpf_120626_6801.hts")));
        QVERIFY2(r.ok, r.error.c_str());
        const CpfFile& f = r.file;
        const CpfInterpolator full(f);
        QVERIFY2(full.ok(), full.error().c_str());
        // At a node the interpolant is the node itself (round-off only: 1 µm).
        for (size_t k : {size_t(0), size_t(5), size_t(900), f.positions.size() - 1}) {
            const CpfState s = full.at(f.positions[k].mjd, f.positions[k].sod);
            QVERIFY2(s.ok, s.error.c_str());
            QVERIFY((s.position - f.positions[k].position).norm() < 1e-6);
        }
        // Physical sanity of the interpolated state: radius and speed of a circular 832 km orbit.
        const CpfState mid = full.at(56105, 43210.5);
        QVERIFY(mid.ok);
        const double radius = mid.position.norm();
        QVERIFY(radius > 6378137.0 + 780e3 && radius < 6378137.0 + 880e3);
        // Body-fixed velocity: inertial sqrt(GM/r) ~ 7.43 km/s minus up to w r ~ 0.53 km/s.
        QVERIFY(mid.velocity.norm() > 6.8e3 && mid.velocity.norm() < 8.0e3);
        // The derivative matches a central difference of the interpolant (1 mm/s).
        const CpfState a = full.at(56105, 43210.0, false), b = full.at(56105, 43211.0, false);
        QVERIFY(((b.position - a.position) - mid.velocity).norm() < 1e-3);
        // Outside the table: an error saying by how much.
        const CpfState before = full.at(f.positions.front().mjd, f.positions.front().sod - 100.0);
        QVERIFY(!before.ok);
        QVERIFY2(before.error.find("100.000 s before") != std::string::npos, before.error.c_str());
        const CpfState after = full.at(f.positions.back().mjd + 1, f.positions.back().sod);
        QVERIFY(!after.ok);
        QVERIFY2(after.error.find("86400.000 s after") != std::string::npos, after.error.c_str());
        // A gap in the table is refused rather than bridged.
        CpfFile gap = f;
        gap.positions.erase(gap.positions.begin() + 500, gap.positions.begin() + 510);
        const CpfState g = CpfInterpolator(gap).at(f.positions[505].mjd, f.positions[505].sod);
        QVERIFY(!g.ok);
        QVERIFY2(g.error.find("gap") != std::string::npos, g.error.c_str());
        CpfInterpParams bad;
        bad.points = 1;
        QVERIFY(!validate(bad).empty());
        QVERIFY(!CpfInterpolator(f, bad).ok());
    }

    /// Accuracy on an analytic orbit: circular, 830 km, inclined 74°, turned into body-fixed
    /// coordinates with the Earth's rotation and written to the table at 1 mm like a CPF.
    /// Truncation bound for 10 nodes at step h: R (w h)^10 x 872 / 10! = 1.6 mm at 240 s,
    /// 2^-10 of that at 120 s; rounding to 1 mm adds about 1 mm.
    void cpfInterpolationAccuracy() {
        const double r0 = 7.21e6, n = std::sqrt(3.986004418e14 / (r0 * r0 * r0)), w = 7.292115e-5, inc = 1.3;
        auto pos = [&](double t) {
            const double a = n * t, th = -w * t;
            const Eigen::Vector3d xi(r0 * std::cos(a), r0 * std::sin(a) * std::cos(inc), r0 * std::sin(a) * std::sin(inc));
            return Eigen::Vector3d(std::cos(th) * xi.x() - std::sin(th) * xi.y(),
                                   std::sin(th) * xi.x() + std::cos(th) * xi.y(), xi.z());
        };
        for (double step : {240.0, 120.0}) {
            CpfFile f;
            for (double t = 0; t <= 86400; t += step) {
                CpfPosition p;
                p.mjd = 56000;
                p.sod = t;
                p.position = pos(t);
                for (int k = 0; k < 3; ++k) p.position[k] = std::round(p.position[k] * 1000) / 1000;
                f.positions.push_back(p);
            }
            const CpfInterpolator ip(f);
            QVERIFY(ip.ok());
            double worst = 0;
            for (double t = 3000; t < 83000; t += 7.3) {
                const CpfState s = ip.at(56000, t, false);
                QVERIFY(s.ok);
                worst = std::max(worst, (s.position - pos(t)).norm());
            }
            qInfo("Lagrange 10 points, analytic LEO orbit, step %.0f s: worst error %.2f mm", step, worst * 1e3);
            QVERIFY(worst < (step > 200 ? 3e-3 : 1.5e-3));
        }
    }

    void cpfBadInput_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<QString>("what");   // in the error, or in one of the warnings
        QTest::addColumn<int>("warnings");
        const QByteArray head = "H1 CPF 2 HTS 2012 6 26 12 6801 1 blits\nH9\n";
        QByteArray many;
        for (int i = 0; i < 12; ++i) many += "10 0 56104 " + QByteArray::number(i * 240) + ".0 0 7000000 0 0\n";
        QTest::newRow("empty") << QByteArray() << false << "empty file" << 0;
        QTest::newRow("not a CPF") << QByteArray("hello\n") << false << ":1:" << 0;
        QTest::newRow("binary") << QByteArray("H1 CPF\x00\x01", 8) << false << "binary" << 0;
        QTest::newRow("no positions") << head + "99\n" << false << "no readable type 10" << 0;
        QTest::newRow("NaN coordinate") << head + "10 0 56104 0.0 0 nan 0 0\n" + many + "99\n" << true << ":3:" << 1;
        QTest::newRow("text in MJD") << head + "10 0 5610x4 0.0 0 1 0 0\n" + many + "99\n" << true << ":3:" << 1;
        QTest::newRow("corrupted X") << head + "10 0 56104 0.0 0 corrupted 0 0\n" + many + "99\n" << true
                                     << "p.cpf:3: type 10 record skipped: X, Y, Z must be finite numbers" << 1;
        // Going back in time: the file is out of order (issue 27: a shuffled CPF ended in "a gap of
        // 158160 s"); repeating the previous epoch: that record skipped.
        QTest::newRow("out of order") << head + many + "10 0 56104 100.0 0 7000000 0 0\n99\n" << false
                                      << "p.cpf:15: position record out of time order" << 0;
        QTest::newRow("repeated epoch") << head + many + "10 0 56104 2640.0 0 7000000 0 0\n99\n" << true
                                        << "p.cpf:15: epoch repeats the previous record's; skipped" << 1;
        // The format ends every file with a 99 record: a file without it was probably cut short.
        QTest::newRow("no 99 end record") << head + many << true << "p.cpf:14: the file ends without the 99" << 1;
        QTest::newRow("cut inside a record") << head + many + "10 0 56104 2880.0 0 70000" << true
                                             << "p.cpf:15: the file ends without the 99" << 2;
        QTest::newRow("a CRD file") << QByteArray(kGoodCrd) << false
                                    << "p.cpf:1: H1 must start with \"CPF <version>\": this H1 names CRD ranging data" << 0;
        QTest::newRow("v2 sound") << head + many + "99\n" << true << "" << 0;
    }
    void cpfBadInput() {
        QFETCH(QByteArray, text);
        QFETCH(bool, ok);
        QFETCH(QString, what);
        QFETCH(int, warnings);
        const CpfReadResult r = parseCpf(std::string(text.constData(), static_cast<size_t>(text.size())), "p.cpf");
        QCOMPARE(r.ok, ok);
        if (!ok) {
            QVERIFY2(QString::fromStdString(r.error).contains(what), r.error.c_str());
            return;
        }
        QCOMPARE(r.file.header.version, 2);
        QCOMPARE(r.file.header.targetName, std::string("blits"));  // v2 H1 has the sub-daily sequence first
        QCOMPARE(r.file.positions.size(), size_t(12));
        QCOMPARE(int(r.warnings.size()), warnings);
        bool found = what.isEmpty();
        for (const auto& w : r.warnings) found = found || QString::fromStdString(w).contains(what);
        QVERIFY2(found, joined(r.warnings).c_str());
    }

    // ---- SINEX ----------------------------------------------------------------------------------
    void sinexReads() {
        if (!lwbtest::haveShared("slr/SLRF2014_POS+VEL_2030.0_200428.snx")) QSKIP("shared SLR data absent");
        const QString path = lwbtest::sharedPath("slr/SLRF2014_POS+VEL_2030.0_200428.snx");
        const QByteArray raw = lwbtest::readAll(path);
        const SinexReadResult r = readSinex(lwbtest::str(path));
        QVERIFY2(r.ok, r.error.c_str());
        QVERIFY(r.warnings.empty());
        // One solution per STAX line; SITE/ID lines counted independently.
        int stax = 0;
        for (auto it = QRegularExpression("\\n\\s*\\d+ STAX ").globalMatch(QString::fromUtf8(raw)); it.hasNext(); it.next()) ++stax;
        QCOMPARE(static_cast<int>(r.file.solutions.size()), stax);
        const QString text = QString::fromUtf8(raw);
        const int from = text.indexOf("+SITE/ID"), to = text.indexOf("-SITE/ID");
        int siteLines = 0;
        for (const QString& l : text.mid(from, to - from).split('\n').mid(1))
            if (!l.startsWith('*') && !l.trimmed().isEmpty()) ++siteLines;
        QCOMPARE(static_cast<int>(r.file.sites.size()), siteLines);
        for (const auto& s : r.file.solutions) QCOMPARE(s.haveMask, 0x3f);  // every SLRF site has X Y Z and velocities

        // Matera MLRO (7941) on 2012-06-27 0h: STAX + VELX * dt with the file's own values
        //   STAX 7941 ... 10:001:00000 m   0.464197861713781E+07 ; VELX ... m/y -.188102608696727E-01
        const double dtYears = QDate(2010, 1, 1).daysTo(QDate(2012, 6, 27)) / 365.25;
        const StationPositionResult m = stationPositionByPad(r.file, 7941, mjdFromDate(2012, 6, 27), 0.0);
        QVERIFY2(m.ok, m.error.c_str());
        QVERIFY(m.warnings.empty());
        QCOMPARE(m.code, std::string("7941"));
        QVERIFY(std::fabs(m.position.x() - (0.464197861713781e7 + -0.188102608696727e-1 * dtYears)) < 1e-6);
        QVERIFY(std::fabs(m.position.y() - (0.139306772310455e7 + 0.190425787582322e-1 * dtYears)) < 1e-6);
        QVERIFY(std::fabs(m.position.z() - (0.413324962267129e7 + 0.144917604701781e-1 * dtYears)) < 1e-6);
        QVERIFY2(m.description.find("Matera") != std::string::npos, m.description.c_str());
        const StationPositionResult byCode = stationPosition(r.file, "7941", mjdFromDate(2012, 6, 27), 0.0);
        QVERIFY(byCode.position == m.position);
        // The SLRF keys sites by the CDP pad id; its SITE/ID also carries the CDP-SOD.
        bool sod = false;
        for (const auto& s : r.file.sites)
            if (s.code == "7941") sod = s.cdpSod == "79417701";
        QVERIFY(sod);

        // Changchun (7237) has three solutions: 96:070-08:073, 08:076-11:069, 11:079-open.
        QCOMPARE(stationPositionByPad(r.file, 7237, mjdFromDate(2012, 6, 27), 0).soln, std::string("3"));
        QCOMPARE(stationPositionByPad(r.file, 7237, mjdFromDate(2009, 1, 1), 0).soln, std::string("2"));
        QCOMPARE(stationPositionByPad(r.file, 7237, mjdFromDate(2000, 1, 1), 0).soln, std::string("1"));
        // Wettzell (8834) between its solutions 2 (to 09:045) and 3 (from 10:325): nearest, with a warning.
        const StationPositionResult w = stationPositionByPad(r.file, 8834, mjdFromDate(2010, 9, 1), 0);
        QVERIFY(w.ok);
        QCOMPARE(w.soln, std::string("3"));
        QCOMPARE(w.warnings.size(), size_t(1));
        QVERIFY2(w.warnings[0].find("outside every solution") != std::string::npos, w.warnings[0].c_str());
        const StationPositionResult none = stationPositionByPad(r.file, 1234, mjdFromDate(2012, 6, 27), 0);
        QVERIFY(!none.ok);
        QVERIFY2(none.error.find("1234") != std::string::npos, none.error.c_str());
        QVERIFY(!stationPositionByPad(r.file, -1, 56000, 0).ok);
    }

    void sinexBadInput_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("what");
        QTest::newRow("empty") << QByteArray() << "empty file";
        QTest::newRow("not SINEX") << QByteArray("H1 CRD 2\n") << ":1:";
        QTest::newRow("no estimates") << QByteArray("%=SNX 2.02\n+SITE/ID\n 7941  A 12734S008 L Matera\n-SITE/ID\n%ENDSNX\n")
                                      << "no station coordinates";
        QTest::newRow("binary") << QByteArray("%=SNX\x00", 6) << "binary";
    }
    void sinexBadInput() {
        QFETCH(QByteArray, text);
        QFETCH(QString, what);
        const SinexReadResult r = parseSinex(std::string(text.constData(), static_cast<size_t>(text.size())), "s.snx");
        QVERIFY(!r.ok);
        QVERIFY2(QString::fromStdString(r.error).contains(what), r.error.c_str());
    }

    void sinexRecordWarnings() {
        const QByteArray text =
            "%=SNX 2.02 XXX 12:001:00000 XXX 12:001:00000 12:001:00000 C 00006 2 X V\n"
            "+SOLUTION/ESTIMATE\n"
            "     1 STAX   7941  A    1 10:001:00000 m    2 0.464197861713781E+07 0.26019E-03\n"
            "     2 STAY   7941  A    1 10:001:00000 m    2 nan 0.54338E-03\n"  // line 4
            "     3 STAZ   7941  A    1 10:0x1:00000 m    2 0.413324962267129E+07 0.23469E-03\n"  // line 5
            "-SOLUTION/ESTIMATE\n%ENDSNX\n";
        const SinexReadResult r = parseSinex(text.toStdString(), "w.snx");
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.warnings.size(), size_t(2));
        QVERIFY2(r.warnings[0].rfind("w.snx:4:", 0) == 0, r.warnings[0].c_str());
        QVERIFY2(r.warnings[1].rfind("w.snx:5:", 0) == 0, r.warnings[1].c_str());
        const StationPositionResult p = stationPosition(r.file, "7941", 56000, 0);
        QVERIFY(!p.ok);  // STAY and STAZ were refused
        QVERIFY2(p.error.find("STAX/STAY/STAZ") != std::string::npos, p.error.c_str());
    }

    // ---- time helpers -----------------------------------------------------------------------------
    void dates() {
        QCOMPARE(mjdFromDate(1858, 11, 17), 0L);
        QCOMPARE(mjdFromDate(2000, 1, 1), 51544L);
        // Against Qt's own calendar for a range of days.
        const QDate epoch(1858, 11, 17);
        for (QDate d(1899, 12, 25); d < QDate(2101, 1, 10); d = d.addDays(37)) {
            QCOMPARE(mjdFromDate(d.year(), d.month(), d.day()), static_cast<long>(epoch.daysTo(d)));
            int y = 0, m = 0, dd = 0;
            dateFromMjd(static_cast<long>(epoch.daysTo(d)), &y, &m, &dd);
            QCOMPARE(QDate(y, m, dd), d);
        }
        QVERIFY(validDate(2012, 2, 29));
        QVERIFY(!validDate(2100, 2, 29));
        QVERIFY(!validDate(2021, 4, 31));
        long mjd = 0;
        double sod = 0;
        QVERIFY(parseSinexEpoch("10:001:00000", &mjd, &sod));
        QCOMPARE(mjd, mjdFromDate(2010, 1, 1));
        QVERIFY(parseSinexEpoch("98:194:53047", &mjd, &sod));
        QCOMPARE(mjd, mjdFromDate(1998, 7, 13));  // day 194 of 1998
        QCOMPARE(sod, 53047.0);
        QVERIFY(!parseSinexEpoch("10:1:0", &mjd, &sod));
        QVERIFY(!parseSinexEpoch("10:400:00000", &mjd, &sod));
        QVERIFY(!parseSinexEpoch("1x:001:00000", &mjd, &sod));
    }
};

QTEST_GUILESS_MAIN(TestSlrIo)
#include "test_slr_io.moc"
