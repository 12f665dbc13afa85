// One run by construction (issue 40): the same SLR inputs give byte-identical products whichever
// way they are given — one pass or a station's file of passes, with or without the command's own
// printed config, on one thread or two. (The workbench's side: ui_test_slr_workspace,
// workbenchAndCliWriteTheSameFiles and everyPassListedAndTheFirstFailureShown; Python's:
// tests/python/test_bindings.py, test_one_run_*.) Each case failed before the run was moved
// into core/slr/slr_run: the printed config lost every normal point of --all-passes (altitude
// 0 over the pass's), the default pass was a sampled-engineering block, and one pass alone and
// the same pass in the batch ended their files with h9 and H9, LF and CRLF, and flagged the
// accepted and the kept points.
#include <QtTest>

#include "core/common/csv.hpp"
#include "core/slr/crd.hpp"
#include "test_support.hpp"

using lwbtest::readAll;
using lwbtest::runCli;

namespace {

// Every file of a folder, by name.
QStringList filesOf(const QString& dir) { return QDir(dir).entryList(QDir::Files, QDir::Name); }

}  // namespace

class TestSlrOneRun : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString p(const QString& n) const { return m_dir.path() + "/" + n; }
    static QString slr(const QString& n) { return lwbtest::sharedPath("slr/" + n); }

    // A station's file of the real MLRS passes, as a day's file mixes them: the JASON1 pass
    // first as sampled engineering data (H4 data type 2) and the station's own normal points of
    // it, then the three Beacon-C passes of 2007-05-11, the JASON1 full-rate pass and STELLA.
    QString day() {
        const QString path = p("day.frd");
        if (QFile::exists(path)) return path;
        auto body = [](const QString& f) {
            QByteArray t = readAll(f);
            const int h9 = t.lastIndexOf("h9");
            return h9 >= 0 ? t.left(h9) : t;
        };
        QByteArray jason = body(slr("7080_JASON1_crd_071220_2033_0.frd"));
        QByteArray engineering = jason;
        const int h4 = engineering.indexOf("h4  0 ");
        if (h4 >= 0) engineering.replace(h4, 6, "h4  2 ");
        const QByteArray text = engineering + body(slr("7080_JASON1_crd_071220_2033_0.npt")) +
                                body(slr("beaconc_20070511.frd")) + jason +
                                readAll(slr("7080_STELLA_crd_071220_2128_0.frd"));
        lwbtest::writeText(path, text);
        return path;
    }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        // The normal points' H1 production date: one instant for every run.
        qputenv("SOURCE_DATE_EPOCH", "1700000000");
    }

    // The day's file as the batch sees it: blocks 1 and 2 are not passes, 3-7 are screened.
    void theDayIsWhatItSeems() {
        if (!lwbtest::haveShared("slr/beaconc_20070511.frd")) QSKIP("shared SLR data absent");
        const auto r = runCli({"slr", day(), "--all-passes", "--out-dir", p("plain"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const auto t = lwb::core::readCsv(lwbtest::str(p("plain/summary.csv")));
        QVERIFY2(t.ok, t.error.c_str());
        QCOMPARE(t.table.rows.size(), size_t(7));
        const int statusCol = t.table.column("status"), npsCol = t.table.column("normal_points");
        QVERIFY(statusCol >= 0 && npsCol >= 0);
        const size_t status = size_t(statusCol), nps = size_t(npsCol);
        QCOMPARE(t.table.rows[0][status], std::string("skipped"));
        QCOMPARE(t.table.rows[1][status], std::string("station normal points"));
        long long total = 0;
        for (size_t k = 2; k < 7; ++k) {
            QCOMPARE(t.table.rows[k][status], std::string("ok"));
            const long long n = std::stoll(t.table.rows[k][nps]);
            QVERIFY2(n > 0, ("pass " + std::to_string(k + 1) + " formed no normal point").c_str());
            total += n;
        }
        QVERIFY(total >= 20);
    }

    // The round trip the README promises: --print-config, given back with --config, gives the
    // same run — for a station's file as for one pass (it lost every normal point).
    void printedConfigGivesTheSameDay() {
        if (!lwbtest::haveShared("slr/beaconc_20070511.frd")) QSKIP("shared SLR data absent");
        const auto printed = runCli({"slr", "--print-config"});
        QCOMPARE(printed.exitCode, 0);
        QVERIFY(lwbtest::writeText(p("cfg.json"), printed.out.toUtf8()));
        if (!QFile::exists(p("plain/summary.csv"))) QVERIFY(runCli({"slr", day(), "--all-passes", "--out-dir", p("plain"), "-q"}).exitCode == 0);
        const auto r = runCli({"slr", day(), "--all-passes", "--out-dir", p("cfg"), "--config", p("cfg.json"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList names = filesOf(p("plain"));
        QCOMPARE(filesOf(p("cfg")), names);
        QVERIFY(names.contains("normal_points.npt"));
        for (const QString& n : names)
            if (n != "provenance.json")  // (it lists the config among the inputs)
                QVERIFY2(readAll(p("plain/" + n)) == readAll(p("cfg/" + n)), qPrintable(n + " differs with the printed config"));
    }

    // Each pass alone (--pass K, with and without the printed config) writes the bytes the batch
    // wrote for it: its CSV and its normal points; its flagged block, for a file of one pass.
    void onePassIsThePassInTheDay() {
        if (!lwbtest::haveShared("slr/beaconc_20070511.frd")) QSKIP("shared SLR data absent");
        if (!QFile::exists(p("plain/summary.csv"))) QVERIFY(runCli({"slr", day(), "--all-passes", "--out-dir", p("plain"), "-q"}).exitCode == 0);
        if (!QFile::exists(p("cfg.json"))) QVERIFY(lwbtest::writeText(p("cfg.json"), runCli({"slr", "--print-config"}).out.toUtf8()));
        for (int k = 3; k <= 7; ++k) {
            for (bool config : {false, true}) {
                const QString tag = QString("k%1%2").arg(k).arg(config ? "c" : "");
                QStringList args{"slr", day(), "--pass", QString::number(k), "-o", p(tag + ".csv"), "--npt-out", p(tag + ".npt"), "-q"};
                if (config) args << "--config" << p("cfg.json");
                const auto r = runCli(args);
                QVERIFY2(r.exitCode == 0, qPrintable(r.err));
                const QString name = QString("plain/pass%1").arg(k, 3, 10, QChar('0'));
                QVERIFY2(readAll(p(tag + ".csv")) == readAll(p(name + ".csv")), qPrintable(tag + ".csv"));
                QVERIFY2(readAll(p(tag + ".npt")) == readAll(p(name + ".npt")), qPrintable(tag + ".npt"));
            }
        }
        // A file of one pass: --crd-out (the whole file) is the batch's flagged block.
        const QString stella = slr("7080_STELLA_crd_071220_2128_0.frd");
        QVERIFY(runCli({"slr", stella, "--crd-out", p("stella.frd"), "--npt-out", p("stella.npt"), "-q"}).exitCode == 0);
        QVERIFY(runCli({"slr", stella, "--all-passes", "--out-dir", p("stella"), "-q"}).exitCode == 0);
        QCOMPARE(readAll(p("stella.frd")), readAll(p("stella/pass001.frd")));
        QCOMPARE(readAll(p("stella.npt")), readAll(p("stella/pass001.npt")));
        QVERIFY(readAll(p("stella.frd")).endsWith("h9\r\n"));  // the file's own line ends and case
        // In the day's file, the block's flags are the pass's flags in the whole-file output.
        QVERIFY(runCli({"slr", day(), "--pass", "7", "--crd-out", p("day7.frd"), "-q"}).exitCode == 0);
        const auto whole = lwb::core::slr::readCrd(lwbtest::str(p("day7.frd")));
        const auto block = lwb::core::slr::readCrd(lwbtest::str(p("plain/pass007.frd")));
        QVERIFY(whole.ok && block.ok);
        QCOMPARE(whole.file.passes.size(), size_t(7));
        const auto& a = whole.file.passes[6].ranges;
        const auto& b = block.file.passes[0].ranges;
        QCOMPARE(a.size(), b.size());
        for (size_t i = 0; i < a.size(); ++i) QCOMPARE(a[i].filterFlag, b[i].filterFlag);
    }

    // What a pass is, decided once (core isPassToScreen): the file opens on its first real
    // full-rate pass, and --pass K on a block that is not one says why (exit 2).
    void oneRuleForWhatAPassIs() {
        if (!lwbtest::haveShared("slr/beaconc_20070511.frd")) QSKIP("shared SLR data absent");
        if (!QFile::exists(p("plain/summary.csv"))) QVERIFY(runCli({"slr", day(), "--all-passes", "--out-dir", p("plain"), "-q"}).exitCode == 0);
        const auto first = runCli({"slr", day(), "-o", p("first.csv"), "-q"});
        QVERIFY2(first.exitCode == 0, qPrintable(first.err));
        QCOMPARE(readAll(p("first.csv")), readAll(p("plain/pass003.csv")));
        for (int k : {1, 2}) {
            const auto r = runCli({"slr", day(), "--pass", QString::number(k), "-o", p("no.csv"), "-q"});
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains("is not a pass to screen") &&
                         r.err.contains(k == 1 ? "sampled engineering data" : "station normal points"),
                     qPrintable(r.err));
            QVERIFY(!QFile::exists(p("no.csv")));
        }
    }

    // The batch on one thread and on two: the same bytes (summary.csv holds no times).
    void threadsDoNotChangeTheDay() {
        if (!lwbtest::haveShared("slr/beaconc_20070511.frd")) QSKIP("shared SLR data absent");
        if (!QFile::exists(p("plain/summary.csv"))) QVERIFY(runCli({"slr", day(), "--all-passes", "--out-dir", p("plain"), "-q"}).exitCode == 0);
        const auto r = runCli({"slr", day(), "--all-passes", "--out-dir", p("one"), "--threads", "1", "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList names = filesOf(p("plain"));
        QCOMPARE(filesOf(p("one")), names);
        for (const QString& n : names) QVERIFY2(readAll(p("plain/" + n)) == readAll(p("one/" + n)), qPrintable(n));
    }

    // The O-C's parameters are schema rows (oc.*): --set and a config reach the computation
    // (before, OcParams had no schema and nothing set it), the printed config gives the same run,
    // and a preset that would set them (computed before a preset applies) is refused.
    void ocRowsReachTheOcAndRoundTrip() {
        const QString pass = slr("blits_201206.frd"), cpf = slr("blits_cpf_120626_6801.hts"),
                      snx = slr("SLRF2014_POS+VEL_2030.0_200428.snx");
        const QStringList base{"slr", pass, "--pass", "3", "--cpf", cpf, "--stations", snx, "-q"};
        auto run = [&](const QStringList& extra, const QString& out) {
            const auto r = runCli(base + extra + QStringList{"-o", out});
            QVERIFY2(r.exitCode == 0 || r.exitCode == 3, qPrintable(r.err));
        };
        run({}, p("oc_mp.csv"));
        run({"--set", "oc.refraction=none"}, p("oc_none.csv"));
        const auto printed = runCli({"slr", "--print-config", "--set", "oc.refraction=none"});
        QVERIFY2(printed.exitCode == 0 && printed.out.contains("\"refraction\": \"none\""), qPrintable(printed.out.left(300)));
        QVERIFY(lwbtest::writeText(p("oc_none.json"), printed.out.toUtf8()));
        run({"--config", p("oc_none.json")}, p("oc_none_config.csv"));
        QCOMPARE(readAll(p("oc_none_config.csv")), readAll(p("oc_none.csv")));
        // Without the troposphere the O-C holds its delay: 2.3 m one-way at the zenith is 15 ns
        // two-way, more at low elevation (BLITS from Herstec: 20-60 degrees, 15-50 ns).
        const auto a = lwb::core::readCsv(lwbtest::str(p("oc_mp.csv"))), b = lwb::core::readCsv(lwbtest::str(p("oc_none.csv")));
        QVERIFY(a.ok && b.ok && a.table.rows.size() == b.table.rows.size() && a.table.rows.size() > 100);
        const int oc = a.table.column("oc_s");
        for (size_t r = 0; r < a.table.rows.size(); r += 25) {
            const double d = std::stod(b.table.rows[r][size_t(oc)]) - std::stod(a.table.rows[r][size_t(oc)]);
            QVERIFY2(d > 13e-9 && d < 60e-9, qPrintable(QString("row %1: the delay is %2 ns").arg(r).arg(d * 1e9)));
        }
        // A preset holding oc.* rows: refused, saying where they go.
        QVERIFY(lwbtest::writeText(p("oc_preset.json"),
                                   R"({"format": "laserwb-slr-presets", "version": 1, "satellites": [{"name": "BLITS", "oc": {"shapiro": false}}]})"));
        const auto refused = runCli(base + QStringList{"--preset", p("oc_preset.json"), "-o", p("never.csv")});
        QVERIFY2(refused.exitCode != 0 && refused.err.contains("the O-C's parameters are not a satellite's"), qPrintable(refused.err));
        QVERIFY(!QFile::exists(p("never.csv")));
    }
};

QTEST_GUILESS_MAIN(TestSlrOneRun)
#include "test_slr_one_run.moc"
