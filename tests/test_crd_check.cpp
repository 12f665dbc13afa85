// The CRD checker (core/slr/crd_check, laserwb-cli crd check; issue 43): every shared ILRS file
// with the problems it really has, a clean file kept clean, and damaged copies (cut short, records
// swapped, wrong field counts, values out of range, an undefined configuration, epochs going back)
// each found at its line; the CLI's output, exit codes and `slr PASS` with no output.
#include <QtTest>

#include "core/slr/crd_check.hpp"
#include "test_support.hpp"

using namespace lwb::core::slr;
using lwbtest::runCli;
using lwbtest::runProgram;

namespace {

QString slr(const QString& f) { return lwbtest::sharedPath("slr/" + f); }
bool haveShared() { return lwbtest::haveShared("slr/7080_STELLA_crd_071220_2128_0.frd"); }

QString listing(const CrdCheckResult& r) {
    QString s = QString::fromStdString(crdCheckSummary(r, r.path)) + "\n";
    for (const auto& p : r.problems) s += QString::fromStdString(formatCrdProblem(r.path, p)) + "\n";
    return s;
}

/// The problem of `rule` at `line` (nullptr when none).
const CrdProblem* find(const CrdCheckResult& r, long line, const std::string& rule) {
    for (const auto& p : r.problems)
        if (p.line == line && p.rule == rule) return &p;
    return nullptr;
}

#define EXPECT(r, line, rule, sev)                                                                           \
    do {                                                                                                     \
        const CrdCheckResult& r_ = (r);                                                                      \
        const CrdProblem* p_ = find(r_, line, rule);                                                         \
        QVERIFY2(p_, qPrintable(QString("no %1 at line %2:\n%3").arg(rule).arg(line).arg(listing(r_))));     \
        QVERIFY2(p_->severity == (sev), qPrintable(QString("%1 at line %2 has the wrong severity:\n%3")      \
                                                       .arg(rule).arg(line).arg(listing(r_))));              \
    } while (0)

size_t countRule(const CrdCheckResult& r, const std::string& rule) {
    size_t n = 0;
    for (const auto& p : r.problems) n += p.rule == rule ? p.count : 0;
    return n;
}

/// A clean CRD v2 full-rate (or normal-point) file: its lines, 1-based as listed.
///   1 H1, 2 H2, 3 H3, 4 H4, 5 C0, 6 C1, 7 20, 8 40, 9..(8+n) data, then 50, H8, H9.
QStringList cleanV2(int n = 10, bool normalPoints = false) {
    QStringList l;
    l << "H1 CRD 2 2024 03 01 12"
      << "H2 MATM 7941 77 1 4 ILRS"
      << "H3 lageos1 7603901 1155 8820 0 1 1"
      << QString("H4 %1 2024 03 01 10 00 00 2024 03 01 10 %2 00 0 0 0 0 1 0 2 0").arg(normalPoints ? 1 : 0).arg(n / 60 + 1, 2, 10, QChar('0'))
      << "C0 0 532.000 std ml1"
      << "C1 0 ml1 Nd-Yag 1064.00 10.00 100.00 200.0 na 1"
      << "20 36000.000 1013.25 288.15 50.0 0"
      << "40 36000.000 0 std 1000 980 na -600.5 0.0 58.4 na na na 3 3 0 3 na";
    for (int i = 1; i <= n; ++i) {
        const QString t = QString::number(36000 + i) + ".000000000000", tof = QString::number(0.045 + i * 1e-6, 'f', 12);
        if (normalPoints) l << "11 " + t + " " + tof + " std 2 30 40 86.2 1.486 -0.464 -120.5 13.33 0 5.0";
        else l << "10 " + t + " " + tof + " std 2 2 0 0 na na";
    }
    l << "50 std 80.1 na na na 0"
      << "H8"
      << "H9";
    return l;
}

CrdCheckResult check(const QStringList& lines, const QString& name = "pass.fr2", bool finalLineEnd = true) {
    std::string text = lines.join("\n").toStdString();
    if (finalLineEnd) text += "\n";
    return checkCrdText(text, name.toStdString());
}

}  // namespace

class TestCrdCheck : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString p(const QString& f) const { return m_dir.filePath(f); }

private slots:
    // ------------------------------------------------------------------ a clean file stays clean
    void cleanFileIsClean() {
        for (bool np : {false, true}) {
            const CrdCheckResult r = check(cleanV2(10, np), np ? "pass.np2" : "pass.fr2");
            QVERIFY2(r.ok && r.clean(), qPrintable(listing(r)));
            QCOMPARE(r.passes.size(), size_t(1));
            QCOMPARE(r.passes[0].h4Line, 4L);
            QCOMPARE(r.passes[0].lastLine, 20L);
            QCOMPARE(r.passes[0].dataType, np ? 1 : 0);
            QCOMPARE(np ? r.passes[0].normalPoints : r.passes[0].ranges, size_t(10));
            QCOMPARE(r.passes[0].start, std::string("2024-03-01 10:00:00"));
            QCOMPARE(r.version, 2);
        }
        // A session across midnight: seconds of day start again at 0 (no epoch going back), the
        // H4 end on the next day.
        QStringList l = cleanV2(4);
        l[3] = "H4 0 2024 03 01 23 59 58 2024 03 02 00 00 03 0 0 0 0 1 0 2 0";
        l[6] = "20 86398.000 1013.25 288.15 50.0 0";
        l[7] = "40 86398.000 0 std 1000 980 na -600.5 0.0 58.4 na na na 3 3 0 3 na";
        const char* sod[] = {"86398.5", "86399.5", "0.5", "1.5"};
        for (int i = 0; i < 4; ++i) l[8 + i] = QString("10 %1 0.045000000000 std 2 2 0 0 na na").arg(sod[i]);
        const CrdCheckResult r = check(l);
        QVERIFY2(r.clean(), qPrintable(listing(r)));
        // 23:59:60 on a day that ends with a leap second (2016-12-31) is a valid epoch.
        l[3] = "H4 0 2016 12 31 23 59 58 2017 01 01 00 00 03 0 0 0 0 1 0 2 0";
        l[0] = "H1 CRD 2 2017 01 01 12";
        l[9] = "10 86400.5 0.045000000000 std 2 2 0 0 na na";
        QVERIFY2(check(l).clean(), qPrintable(listing(check(l))));
    }

    // ------------------------------------------------------------------ every shared file, as it is
    // The real files are not all clean: what each has is asserted, not hidden.
    void sharedFiles() {
        if (!haveShared()) QSKIP("shared SLR data absent (../shared/data/slr)");
        // MLRS's 2007 files call themselves "version 0" (the drafts before v1.00): that alone.
        for (const char* f : {"7080_Beacon-C_crd_071220_1715_0.frd", "7080_Beacon-C_crd_071220_1715_0.npt",
                              "7080_JASON1_crd_071220_2033_0.frd", "7080_JASON1_crd_071220_2033_0.npt",
                              "7080_STELLA_crd_071220_2128_0.frd", "7080_STELLA_crd_071220_2128_0.npt"}) {
            const CrdCheckResult r = checkCrd(slr(f).toStdString());
            QVERIFY2(r.ok && r.errors == 0 && r.warnings == 1 && r.problems.size() == 1, qPrintable(listing(r)));
            EXPECT(r, 1, "version", CrdSeverity::Warning);
            QCOMPARE(r.passes.size(), size_t(1));
            QCOMPARE(r.version, 0);
            qInfo("%s", qPrintable(QString::fromStdString(crdCheckSummary(r, f))));
        }
        {  // beaconc (converted in 2015 to "version 0"): H4s of 20 fields that say normal point over
           // full-rate data, records 20 and 10 a field short.
            const CrdCheckResult r = checkCrd(slr("beaconc_20070511.frd").toStdString());
            qInfo("%s", qPrintable(listing(r)));
            QVERIFY(r.ok);
            QCOMPARE(r.passes.size(), size_t(3));
            for (long h4 : {4L, 210L, 398L}) {
                EXPECT(r, h4, "field-count", CrdSeverity::Error);  // (missing: data quality alert indicator)
                EXPECT(r, h4, "data-type", CrdSeverity::Error);    // no 11 record in a normal-point session
                EXPECT(r, h4, "file-name", CrdSeverity::Warning);  // a .frd of data type 1
            }
            EXPECT(r, 3, "range", CrdSeverity::Warning);  // target type 0
            EXPECT(r, 10, "field-count", CrdSeverity::Error);
            EXPECT(r, 13, "data-type", CrdSeverity::Error);
            QVERIFY(find(r, 13, "data-type")->message.find("142 such records") != std::string::npos);
            EXPECT(r, 13, "field-count", CrdSeverity::Error);  // 10: 7 fields of 8
            QCOMPARE(countRule(r, "field-count"), size_t(3 + 3 + 386));  // 3 H4, 3 records 20, every record 10
            QCOMPARE(r.errors, size_t(398));
            QCOMPARE(r.warnings, size_t(5));
        }
        {
            const CrdCheckResult r = checkCrd(slr("beaconc_20070511.npt").toStdString());
            qInfo("%s", qPrintable(listing(r)));
            QVERIFY(r.ok);
            for (long h4 : {4L, 27L, 42L}) EXPECT(r, h4, "field-count", CrdSeverity::Error);
            for (long met : {11L, 34L, 49L}) EXPECT(r, met, "field-count", CrdSeverity::Error);
            QCOMPARE(r.errors, size_t(6));
            QCOMPARE(r.warnings, size_t(2));
        }
        {  // MATM's Blits month (v1): 54 sessions; a T2L2 component no C record defines, epochs a
           // few seconds outside their H4's start and end, no line end after the last H9.
            const CrdCheckResult r = checkCrd(slr("blits_201206.frd").toStdString());
            qInfo("%s", qPrintable(listing(r)));
            QVERIFY(r.ok);
            QCOMPARE(r.passes.size(), size_t(54));
            QCOMPARE(r.errors, size_t(0));
            QCOMPARE(countRule(r, "config-id"), size_t(9));
            QVERIFY(find(r, 11851, "config-id")->message.find("\"t2l2\"") != std::string::npos);
            EXPECT(r, 12095, "h4-span", CrdSeverity::Warning);
            EXPECT(r, 40209, "line-end", CrdSeverity::Warning);
            QCOMPARE(r.warnings, size_t(18));
            size_t records = 0;
            for (const auto& pass : r.passes) records += pass.ranges;
            QCOMPARE(records, size_t(33601));
        }
        {  // HY-2C (v2, 2021): the C0s name a component "none"; no line end after the H9.
            const CrdCheckResult r = checkCrd(slr("hy2c_202109.fr2").toStdString());
            qInfo("%s", qPrintable(listing(r)));
            QVERIFY(r.ok);
            QCOMPARE(r.passes.size(), size_t(6));
            QCOMPARE(r.errors, size_t(0));
            for (long c0 : {5L, 23L, 46L, 79L, 95L, 112L}) EXPECT(r, c0, "config-id", CrdSeverity::Warning);
            EXPECT(r, 222, "line-end", CrdSeverity::Warning);
            QCOMPARE(r.warnings, size_t(7));
        }
        {  // The samples of the CRD v2.01 specification, one after the other: not a file a station
           // sends (5 targets), and the samples' own slips: 28.21 K, curly quotes in a comment, a
           // record 21 without its sky temperature, "File 1" of 6.6 with no H8, v2 records in the
           // blocks that say "CRD 1".
            const CrdCheckResult r = checkCrd(slr("crd201_all_samples.crd").toStdString());
            qInfo("%s", qPrintable(listing(r)));
            QVERIFY(r.ok);
            QCOMPARE(r.passes.size(), size_t(9));
            EXPECT(r, 0, "targets", CrdSeverity::Warning);
            EXPECT(r, 10, "range", CrdSeverity::Warning);
            QVERIFY(find(r, 10, "range")->message.find("28.21") != std::string::npos);
            EXPECT(r, 136, "ascii", CrdSeverity::Warning);
            EXPECT(r, 178, "field-count", CrdSeverity::Error);
            EXPECT(r, 202, "order", CrdSeverity::Error);
            EXPECT(r, 203, "field-count", CrdSeverity::Warning);  // H2 with a v2 network in a v1 block
            EXPECT(r, 208, "field-count", CrdSeverity::Warning);  // C2 of 16 fields, v1 has 13
            QCOMPARE(r.errors, size_t(2));
            QCOMPARE(r.warnings, size_t(39));
        }
    }

    // The same text checked from a file, from memory and through gzip gives the same problems.
    void fileTextAndGzipAgree() {
        QStringList l = cleanV2(6);
        l[9] = "10 36002.000000000000 0.045000000000 xyz 2 2 0 0 na na";  // undefined configuration
        l[11] = "10 36004.000000000000 0.045000000000 std 2 7 0 0 na na";  // filter flag 7
        const QByteArray text = l.join("\n").toUtf8() + "\n";
        QVERIFY(lwbtest::writeText(p("a.fr2"), text));
        const CrdCheckResult fromText = checkCrdText(text.toStdString(), p("a.fr2").toStdString());
        const CrdCheckResult fromFile = checkCrd(p("a.fr2").toStdString());
        QVERIFY(fromFile.ok);
        QCOMPARE(listing(fromFile), listing(fromText));
        QCOMPARE(fromFile.errors, size_t(2));
        const auto gz = runProgram("gzip", {"-k", "-f", p("a.fr2")});
        if (gz.exitCode != 0) QSKIP("no gzip program");
        const CrdCheckResult fromGz = checkCrd(p("a.fr2.gz").toStdString());
        QVERIFY(fromGz.ok);
        QCOMPARE(fromGz.problems.size(), fromFile.problems.size());
        for (size_t i = 0; i < fromGz.problems.size(); ++i) {
            QCOMPARE(fromGz.problems[i].line, fromFile.problems[i].line);
            QCOMPARE(fromGz.problems[i].rule, fromFile.problems[i].rule);
        }
        // A file that is not there, or a folder: not checked, said so.
        const CrdCheckResult none = checkCrd(p("missing.frd").toStdString());
        QVERIFY(!none.ok);
        QVERIFY2(none.error.find("missing.frd") != std::string::npos, none.error.c_str());
        QVERIFY(!checkCrd(m_dir.path().toStdString()).ok);
    }

    // ------------------------------------------------------------------ damaged copies
    void truncated() {
        const QStringList full = cleanV2(10);
        {  // cut in the middle of the record 10 of line 13 (no line end after it)
            QStringList l = full.mid(0, 13);
            l[12] = l[12].left(20);  // "10 36005.00000000000"
            const CrdCheckResult r = check(l, "cut.fr2", false);
            EXPECT(r, 13, "field-count", CrdSeverity::Error);
            EXPECT(r, 13, "session-end", CrdSeverity::Error);
            EXPECT(r, 13, "file-end", CrdSeverity::Error);
            EXPECT(r, 13, "line-end", CrdSeverity::Warning);
            QVERIFY(r.ok && !r.clean());
        }
        {  // cut after the last data record: no H8, no H9
            const QStringList l = full.mid(0, 18);
            const CrdCheckResult r = check(l);
            EXPECT(r, 18, "session-end", CrdSeverity::Error);
            EXPECT(r, 18, "file-end", CrdSeverity::Error);
            QVERIFY(!find(r, 18, "line-end"));
            QCOMPARE(r.errors, size_t(2));
        }
        {  // cut after the H8: only the H9 is missing
            const CrdCheckResult r = check(full.mid(0, 20));
            EXPECT(r, 20, "file-end", CrdSeverity::Error);
            QCOMPARE(r.errors, size_t(1));
            QCOMPARE(r.warnings, size_t(0));
        }
        // A real file cut short (the STELLA full-rate pass, cut in its record 10 of line 150).
        if (!haveShared()) QSKIP("shared SLR data absent");
        const QList<QByteArray> lines = lwbtest::readAll(slr("7080_STELLA_crd_071220_2128_0.frd")).split('\n');
        QByteArray cut;
        for (int i = 0; i < 149; ++i) cut += lines[i] + "\n";
        cut += lines[149].left(25);
        QVERIFY(lwbtest::writeText(p("stella-cut.frd"), cut));
        const CrdCheckResult r = checkCrd(p("stella-cut.frd").toStdString());
        QVERIFY(r.ok);
        EXPECT(r, 150, "field-count", CrdSeverity::Error);
        EXPECT(r, 150, "session-end", CrdSeverity::Error);
        EXPECT(r, 150, "file-end", CrdSeverity::Error);
        EXPECT(r, 150, "line-end", CrdSeverity::Warning);
    }

    void swappedRecords() {
        {  // a normal point before the H4 (it moved up from line 9 to line 4)
            QStringList l = cleanV2(5, true);
            l.insert(3, l.takeAt(8));
            const CrdCheckResult r = check(l, "np.np2");
            EXPECT(r, 4, "order", CrdSeverity::Error);
            QVERIFY(find(r, 4, "order")->message.find("outside a session") != std::string::npos);
        }
        {  // the H8 right after the C0: the data after it is outside any session, and the
           // session has no range record
            QStringList l = cleanV2(5);
            l.insert(5, l.takeAt(14));  // H8 from line 15 to line 6
            const CrdCheckResult r = check(l);
            EXPECT(r, 7, "order", CrdSeverity::Error);  // the C1, now after the H8
            QVERIFY2(find(r, 7, "order")->message.find("after the H8 at line 6") != std::string::npos, qPrintable(listing(r)));
            EXPECT(r, 4, "data-type", CrdSeverity::Error);
            QVERIFY(find(r, 9, "order") || countRule(r, "order") >= 5);
        }
        {  // an H4 inside a session: the first has no H8
            QStringList l = cleanV2(5);
            l.insert(10, "H4 0 2024 03 01 10 00 00 2024 03 01 10 01 00 0 0 0 0 1 0 2 0");
            const CrdCheckResult r = check(l);
            EXPECT(r, 11, "order", CrdSeverity::Error);
            QCOMPARE(r.passes.size(), size_t(2));
            // (the second session has no C0: its records name an undefined configuration)
            EXPECT(r, 12, "config-id", CrdSeverity::Error);
        }
        {  // records after the H9, and an H8 with no session
            QStringList l = cleanV2(3);
            l << "H8" << "10 36009.0 0.045 std 2 2 0 0 na na";
            const CrdCheckResult r = check(l);
            EXPECT(r, 15, "order", CrdSeverity::Error);  // after the H9 (and an H8 with no session)
            EXPECT(r, 16, "order", CrdSeverity::Error);  // outside a session
        }
        {  // the headers out of order: H3 before H2
            QStringList l = cleanV2(3);
            l.swapItemsAt(1, 2);
            const CrdCheckResult r = check(l);
            EXPECT(r, 2, "order", CrdSeverity::Error);  // H3 before any H2
        }
        {  // the epochs of two ranges swapped: the second goes back
            QStringList l = cleanV2(6);
            const QString a = l[10], b = l[11];
            l[10] = b;
            l[11] = a;
            const CrdCheckResult r = check(l);
            EXPECT(r, 12, "epoch-order", CrdSeverity::Error);
            QCOMPARE(countRule(r, "epoch-order"), size_t(1));
            QVERIFY(find(r, 12, "epoch-order")->message.find("line 11") != std::string::npos);
        }
    }

    void wrongFieldCounts() {
        QStringList l = cleanV2(5);
        l[3] = "H4 0 2024 03 01 10 00 00 2024 03 01 10 01 00 0 0 0 0 1 0 2";  // 20 fields
        l[4] = "C0 0 532.000";                                                // no configuration id
        l[9] = "10 36002.000000000000 0.045 std 2 2 0 0 na na 17";            // 10 fields
        l[10] = "10 36003.000000000000 0.045 std 2 2 0";                       // 6 fields
        l[6] = "20 36000.000 1013.25 288.15";                                  // 3 fields
        const CrdCheckResult r = check(l);
        EXPECT(r, 4, "field-count", CrdSeverity::Error);
        QVERIFY(find(r, 4, "field-count")->message.find("data quality alert indicator") != std::string::npos);
        EXPECT(r, 5, "field-count", CrdSeverity::Error);
        EXPECT(r, 7, "field-count", CrdSeverity::Error);
        EXPECT(r, 10, "field-count", CrdSeverity::Warning);  // one extra: said, not an error
        EXPECT(r, 11, "field-count", CrdSeverity::Error);
        // (the C0 defines no id: the calibration and the ranges name an undefined configuration)
        EXPECT(r, 8, "config-id", CrdSeverity::Error);
        // A v1 file with v2 records: the v2 layout said, records of v2 only said.
        QStringList v1 = cleanV2(3);
        v1[0] = "H1 CRD  1 2024  3  1 12";
        v1[1] = "H2 MATM       7941 77  1  4";
        v1[2] = "H3 lageos1     7603901 1155     8820 0 1";
        v1[3] = "H4  0 2024  3  1 10  0  0 2024  3  1 10  1  0  0 0 0 0 1 0 2 0";
        v1[5] = "C1 0 ml1 Nd-Yag 1064.00 10.00 100.00 200.0 -1 1";
        v1[7] = "41 36000.000 0 std 1000 980 -1 -600.5 0.0 58.4 -1 -1 -1 3 3 0 1 -1";
        for (int i = 8; i < 11; ++i) v1[i] = QString("10 %1.0 0.045 std 2 2 0 0 -1").arg(36000 + i - 7);
        v1[11] = "50 std 80.1 -1 -1 -1 0";
        const CrdCheckResult r1 = check(v1, "v1.frd");
        EXPECT(r1, 8, "version", CrdSeverity::Warning);
        QVERIFY2(r1.errors == 0 && r1.warnings == 2, qPrintable(listing(r1)));  // (41: v2 only, and 17 fields of 15)
        EXPECT(r1, 8, "field-count", CrdSeverity::Warning);
        // ... and a v1 header out of its fixed columns
        v1[1] = "H2 MATM 7941 77 1 4";
        EXPECT(check(v1, "v1.frd"), 2, "fixed-format", CrdSeverity::Warning);
    }

    void valuesOutOfRange() {
        QStringList l = cleanV2(8);
        l[1] = "H2 MATM 7941 77 1 5 ILRS";                                        // time scale 5
        l[3] = "H4 0 2024 03 01 10 00 00 2024 03 01 10 01 00 0 0 0 0 1 0 9 0";   // range type 9
        l[6] = "20 36000.000 1013.25 288.15 150.0 0";                             // humidity 150 %
        l[9] = "10 36002.000000000000 0.045 std 2 7 0 0 na na";                   // filter flag 7
        l[10] = "10 90000.000000000000 0.045 std 2 2 0 0 na na";                  // 25 h into the day
        l[11] = "10 36004.000000000000 0.045 std 9 2 0 0 na na";                  // epoch event 9
        l[12] = "10 36005.000000000000 -0.045 std 2 2 0 0 na na";                 // negative time of flight
        l[13] = "10 36006.000000000000 0.045 std 2 2 0 0 na na";
        l[7] = "40 36000.000 7 std 1000 1200 na -600.5 0.0 58.4 na na na 3 3 0 3 na";  // data type 7, used > recorded
        l[14] = "10 86400.500000000000 0.045 std 2 2 0 0 na na";                  // 23:59:60 on a day without
        const CrdCheckResult r = check(l);
        EXPECT(r, 2, "range", CrdSeverity::Error);
        EXPECT(r, 4, "range", CrdSeverity::Error);
        EXPECT(r, 7, "range", CrdSeverity::Warning);
        EXPECT(r, 8, "range", CrdSeverity::Error);
        EXPECT(r, 10, "range", CrdSeverity::Error);
        QVERIFY(find(r, 10, "range")->message.find("filter flag") != std::string::npos);
        EXPECT(r, 11, "range", CrdSeverity::Error);
        EXPECT(r, 12, "range", CrdSeverity::Error);
        EXPECT(r, 13, "range", CrdSeverity::Error);
        EXPECT(r, 15, "leap-second", CrdSeverity::Error);
        // "na" where a value is required, text where a number is
        l = cleanV2(3);
        l[8] = "10 36001.0 na std 2 2 0 0 na na";
        l[9] = "10 36002.0 0.045 std two 2 0 0 na na";
        const CrdCheckResult r2 = check(l);
        EXPECT(r2, 9, "na", CrdSeverity::Error);
        EXPECT(r2, 10, "field-format", CrdSeverity::Error);
        // a data epoch outside the H4's start and end
        l = cleanV2(3);
        l[3] = "H4 0 2024 03 01 10 00 00 2024 03 01 10 00 01 0 0 0 0 1 0 2 0";
        EXPECT(check(l), 11, "h4-span", CrdSeverity::Warning);
    }

    void configurations() {
        QStringList l = cleanV2(5);
        l[10] = "10 36003.000000000000 0.045 xyz 2 2 0 0 na na";  // line 11: no C0 defines "xyz"
        l[11] = "10 36004.000000000000 0.045 xyz 2 2 0 0 na na";
        l[4] = "C0 0 532.000 std ml1 det9";                          // det9: no C2 defines it
        const CrdCheckResult r = check(l);
        EXPECT(r, 11, "config-id", CrdSeverity::Error);
        QVERIFY(find(r, 11, "config-id")->message.find("2 records use it") != std::string::npos);
        EXPECT(r, 5, "config-id", CrdSeverity::Warning);
        // a second C0 of the same id; a C0 after its first use
        l = cleanV2(3);
        l.insert(5, "C0 0 1064.000 std");
        EXPECT(check(l), 6, "config-id", CrdSeverity::Error);
        l = cleanV2(3);
        l.insert(10, "C0 0 1064.000 ir");
        l[8] = "10 36001.0 0.045 ir 2 2 0 0 na na";
        const CrdCheckResult late = check(l);
        EXPECT(late, 11, "order", CrdSeverity::Warning);
        QVERIFY(!find(late, 9, "config-id"));
        // data of the wrong type for the H4
        l = cleanV2(3);
        l[9] = "11 36002.0 0.045 std 2 30 40 86.2 1.486 -0.464 -120.5 13.33 0 5.0";
        EXPECT(check(l), 10, "data-type", CrdSeverity::Error);
    }

    void fileLevel() {
        QStringList l = cleanV2(3);
        l.insert(6, "");                     // a blank line
        l.insert(7, "17 36000.0 1 2 3");     // an unknown record type
        const CrdCheckResult r = check(l);
        EXPECT(r, 7, "blank-line", CrdSeverity::Error);
        EXPECT(r, 8, "record-type", CrdSeverity::Error);
        l = cleanV2(3);
        l[0] = "H1 CRD 3 2024 03 01 12";
        EXPECT(check(l), 1, "version", CrdSeverity::Error);
        l[0] = "H1 CPF 2 2024 03 01 12";
        EXPECT(check(l), 1, "h1", CrdSeverity::Error);
        // empty text; comments only
        QVERIFY(checkCrdText("", "e.frd").ok);
        EXPECT(checkCrdText("", "e.frd"), 0, "empty", CrdSeverity::Error);
        const CrdCheckResult c = checkCrdText("00 nothing here\n", "c.frd");
        EXPECT(c, 0, "order", CrdSeverity::Error);  // no session
        EXPECT(c, 1, "file-end", CrdSeverity::Error);
        // binary data: said at its line, not read on
        std::string bin = "H1 CRD 2 2024 03 01 12\nH2 ";
        bin += '\0';
        bin += "x\n";
        const CrdCheckResult b = checkCrdText(bin, "b.frd");
        EXPECT(b, 2, "text", CrdSeverity::Error);
        // a problem on many records: the first maxRepeats listed, the others counted in one line
        l = cleanV2(30);
        for (int i = 8; i < 38; ++i) l[i] = l[i].replace(" std 2 2 ", " std 2 5 ");
        CrdCheckParams few;
        few.maxRepeats = 4;
        const CrdCheckResult many = checkCrdText((l.join("\n") + "\n").toStdString(), "m.fr2", few);
        QCOMPARE(countRule(many, "range"), size_t(30));
        const CrdProblem* rest = find(many, 13, "range");
        QVERIFY2(rest && rest->count == 26 && rest->lastLine == 38, qPrintable(listing(many)));
        // ... and the reader, which skips every one of them, says so of the lines not listed too:
        // only that the pass has no record it can use (at its H4) is news.
        EXPECT(many, 4, "reader", CrdSeverity::Error);
        QVERIFY(find(many, 4, "reader")->message.find("no readable range record") != std::string::npos);
        QCOMPARE(many.errors, size_t(31));
        QCOMPARE(many.warnings, size_t(0));
    }

    // ------------------------------------------------------------------ the command line
    void cli() {
        // The simulator's pass is clean (exit 0, one summary line).
        auto r = runCli({"simulate", "slr", "--kind", "conventional", "--seed", "5", "-q", p("sim.frd")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = runCli({"crd", "check", p("sim.frd")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.startsWith(p("sim.frd") + ": clean (1 session,"), qPrintable(r.out));
        QCOMPARE(r.out.count('\n'), 1);
        // A damaged copy: FILE:LINE: severity rule: reason, then the summary; exit 3.
        QStringList l = cleanV2(5);
        l[9] = "10 36002.000000000000 0.045 std 2 7 0 0 na na";
        l[6] = "20 36000.000 1013.25 28.15 50.0 0";
        QVERIFY(lwbtest::writeText(p("bad.fr2"), l.join("\n").toUtf8() + "\n"));
        r = runCli({"crd", "check", p("bad.fr2"), p("sim.frd")});
        QCOMPARE(r.exitCode, 3);
        const QStringList out = r.out.trimmed().split('\n');
        QCOMPARE(out.size(), 4);
        QVERIFY2(out[0] == p("bad.fr2") + ":7: warning range: record 20 field 3 (surface temperature) is 28.15; outside 200..350",
                 qPrintable(r.out));
        QVERIFY2(QRegularExpression("^" + QRegularExpression::escape(p("bad.fr2")) + ":10: error range: record 10 field 5 \\(filter flag\\)")
                     .match(out[1]).hasMatch(),
                 qPrintable(r.out));
        QCOMPARE(out[2], p("bad.fr2") + ": 1 error, 1 warning (1 session, 10 records, 16 lines, CRD v2)");
        QVERIFY(out[3].startsWith(p("sim.frd") + ": clean"));
        // --warnings-ok: a file with warnings alone passes.
        l[9] = "10 36002.000000000000 0.045 std 2 2 0 0 na na";
        QVERIFY(lwbtest::writeText(p("warn.fr2"), l.join("\n").toUtf8() + "\n"));
        QCOMPARE(runCli({"crd", "check", p("warn.fr2")}).exitCode, 3);
        QCOMPARE(runCli({"crd", "check", "--warnings-ok", p("warn.fr2")}).exitCode, 0);
        // -q: nothing printed, the exit code says.
        r = runCli({"crd", "check", "-q", p("bad.fr2")});
        QCOMPARE(r.exitCode, 3);
        QVERIFY(r.out.isEmpty());
        // Standard input.
        lwbtest::RunOptions o;
        o.input = lwbtest::readAll(p("bad.fr2"));
        r = runProgram(QString(LWB_CLI), {"crd", "check", "-"}, o);
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.out.startsWith("-:7: warning range:"), qPrintable(r.out));
        // A missing file: said on stderr, the others still checked; exit 1.
        r = runCli({"crd", "check", p("nope.frd"), p("sim.frd")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("nope.frd"), qPrintable(r.err));
        QVERIFY(r.out.contains(p("sim.frd") + ": clean"));
        // Usage errors: exit 2.
        for (const QStringList& args : {QStringList{"crd", "check"}, QStringList{"crd"}, QStringList{"crd", "verify", "x"},
                                        QStringList{"crd", "check", "--bogus", p("sim.frd")},
                                        QStringList{"crd", "check", "--max-repeats", "-1", p("sim.frd")},
                                        QStringList{"crd", "check", "-", "-"}}) {
            r = runCli(args);
            QVERIFY2(r.exitCode == 2, qPrintable(args.join(' ') + ": " + r.err));
        }
        QCOMPARE(runCli({"crd", "check", "--help"}).exitCode, 0);
        // The normal points the slr command writes are clean CRD.
        r = runCli({"slr", p("sim.frd"), "--npt-out", p("sim.npt"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = runCli({"crd", "check", p("sim.npt")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
    }

    // `laserwb-cli slr PASS` with no output: the summary, and nothing written.
    void slrWithoutOutput() {
        QVERIFY(QFile::exists(p("sim.frd")) ||
                runCli({"simulate", "slr", "--kind", "conventional", "--seed", "5", "-q", p("sim.frd")}).exitCode == 0);
        QTemporaryDir cwd;
        lwbtest::RunOptions o;
        o.cwd = cwd.path();
        const QStringList before = lwbtest::filesIn(m_dir.path());
        const auto r = runProgram(QString(LWB_CLI), {"slr", p("sim.frd")}, o);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains("points ") && r.err.contains("accepted") && r.err.contains("normal points"), qPrintable(r.err));
        QVERIFY2(r.err.contains("nothing written"), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
        QCOMPARE(lwbtest::filesIn(m_dir.path()), before);
        QVERIFY(lwbtest::filesIn(cwd.path()).isEmpty());
        // -q: nothing at all
        const auto q = runProgram(QString(LWB_CLI), {"slr", p("sim.frd"), "-q"}, o);
        QCOMPARE(q.exitCode, 0);
        QVERIFY(q.err.isEmpty() && q.out.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestCrdCheck)
#include "test_crd_check.moc"
