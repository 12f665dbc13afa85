// One run by construction, footprint family (issue 40): the same shots give the same report
// bytes whichever way they are given — a shot list or its frames one at a time, with or without
// the command's own printed config, on one thread or two — because every front end hands its
// sources to core/footprint/footprint_run (setUpFootprintRun) and nothing else. (The
// workbench's side: ui_test_footprint_review, shotListGivesTheCliReport and
// workbenchTakesThePrintedConfig; Python's: tests/python/test_bindings.py, test_one_run_footprint.)
// Failed before the run was moved into core: `--roi 48 --print-config` printed a config that,
// given back, cut smaller ROIs where --roi 48 refuses a frame smaller than the ROI (the strict
// size was a flag outside the schema), and Python's fit_batch read a shot list as a frame.
#include <QtTest>

#include "core/common/csv.hpp"
#include "test_support.hpp"

using lwbtest::readAll;
using lwbtest::runCli;

class TestFootprintOneRun : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString p(const QString& n) const { return m_dir.path() + "/" + n; }

    // The data rows of a report (its header dropped).
    static QByteArray rowsOf(const QByteArray& report) { return report.mid(report.indexOf('\n') + 1); }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        // 9 shots of every doubtful case (32 px ROIs) and 3 full frames with a nominal centre.
        auto sim = runCli({"simulate", "footprint", "--count", "9", "--seed", "11", "--case", "mixed", "-q", p("rois")});
        QVERIFY2(sim.exitCode == 0, qPrintable(sim.err));
        sim = runCli({"simulate", "footprint", "--count", "3", "--seed", "12", "--full-frame", "-q", p("frames")});
        QVERIFY2(sim.exitCode == 0, qPrintable(sim.err));
        // A shot list over both: times, beams, cameras; the full frames cut at their own centre.
        QByteArray list = "file,time,beam,camera,center_x,center_y\n";
        for (int i = 0; i < 9; ++i)
            list += QString("rois/shot_%1.png,2021-0%2-1%3T10:00:00Z,%4,LFI,,\n").arg(i, 6, 10, QChar('0')).arg(1 + i / 4).arg(i).arg(1 + i % 2).toUtf8();
        for (int i = 0; i < 3; ++i)
            list += QString("frames/shot_%1.png,2021-05-0%2,1,LFI,122,262\n").arg(i, 6, 10, QChar('0')).arg(i + 1).toUtf8();
        QVERIFY(lwbtest::writeText(p("list.csv"), list));
    }

    // The printed config, given back, is the same run: every setting of the command line is in
    // the schema (the strict ROI size among them), so nothing is lost on the way.
    void printedConfigGivesTheSameBytes() {
        for (const QStringList& opts :
             {QStringList{"--roi", "48", "--keep-going"}, QStringList{"--preset", "yao2021", "--method", "tefm"},
              QStringList{"--set", "roi.size=24", "--set", "verdict.max_uncertainty_px=0.2", "--method", "gcm"}}) {
            const QString tag = opts.join('_').remove('-').replace('=', '_').replace('.', '_');
            auto direct = runCli(QStringList{"footprint", p("list.csv"), "-q", "-o", p(tag + "_direct.csv")} + opts);
            QVERIFY2(direct.exitCode == 0, qPrintable(tag + ": " + direct.err));
            QStringList printOpts = opts;
            printOpts.removeAll("--keep-going");
            const auto printed = runCli(QStringList{"footprint", "--print-config"} + printOpts);
            QVERIFY2(printed.exitCode == 0, qPrintable(printed.err));
            QVERIFY(lwbtest::writeText(p(tag + ".json"), printed.out.toUtf8()));
            QStringList again{"footprint", p("list.csv"), "-q", "--config", p(tag + ".json"), "-o", p(tag + "_config.csv")};
            if (opts.contains("--keep-going")) again << "--keep-going";
            const auto viaConfig = runCli(again);
            QVERIFY2(viaConfig.exitCode == 0, qPrintable(tag + ": " + viaConfig.err));
            const QByteArray a = readAll(p(tag + "_direct.csv")), b = readAll(p(tag + "_config.csv"));
            QVERIFY(a.count('\n') == 13);  // header + 12 shots
            QVERIFY2(a == b, qPrintable(tag + ": the report differs with the printed config"));
        }
        // The strict size is what made them differ: 32 px frames refused under --roi 48.
        const auto t = lwb::core::readCsv(lwbtest::str(p("roi_48_keepgoing_direct.csv")));
        QVERIFY(t.ok);
        const int verdict = t.table.column("verdict"), reasons = t.table.column("reasons");
        int refused = 0;
        for (const auto& r : t.table.rows) refused += r[size_t(verdict)] == "rejected" && r[size_t(reasons)].find("larger than the image") != std::string::npos;
        QVERIFY2(refused == 9, qPrintable(QString("%1 of the 32 px ROIs refused under --roi 48").arg(refused)));
    }

    // The list at once, on one thread or two, is its shots one at a time (each a one-row list).
    void batchIsEachShotAlone() {
        const auto all1 = runCli({"footprint", p("list.csv"), "-q", "--threads", "1", "-o", p("all1.csv")});
        const auto all2 = runCli({"footprint", p("list.csv"), "-q", "--threads", "2", "-o", p("all2.csv")});
        QVERIFY2(all1.exitCode == 0 && all2.exitCode == 0, qPrintable(all1.err + all2.err));
        const QByteArray all = readAll(p("all1.csv"));
        QCOMPARE(readAll(p("all2.csv")), all);
        const QList<QByteArray> lines = readAll(p("list.csv")).split('\n');
        QByteArray alone;
        for (int i = 1; i < lines.size(); ++i) {
            if (lines[i].isEmpty()) continue;
            const QString one = p(QString("one_%1.csv").arg(i));
            QVERIFY(lwbtest::writeText(one, lines[0] + "\n" + lines[i] + "\n"));
            const auto r = runCli({"footprint", one, "-q", "-o", one + ".out"});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            alone += rowsOf(readAll(one + ".out"));
        }
        QCOMPARE(alone, rowsOf(all));
        // And the ROI shots given as their folder are the list's rows but for time, beam, camera.
        const auto folder = runCli({"footprint", p("rois"), "-q", "-o", p("folder.csv")});
        QVERIFY2(folder.exitCode == 0, qPrintable(folder.err));
        const auto f = lwb::core::readCsv(lwbtest::str(p("folder.csv"))), l = lwb::core::readCsv(lwbtest::str(p("all1.csv")));
        QVERIFY(f.ok && l.ok);
        QCOMPARE(f.table.rows.size(), size_t(9));
        const int time = l.table.column("time");
        for (size_t r = 0; r < 9; ++r)
            for (size_t k = 1; k < size_t(time); ++k) QCOMPARE(f.table.rows[r][k], l.table.rows[r][k]);
    }
};

QTEST_GUILESS_MAIN(TestFootprintOneRun)
#include "test_footprint_one_run.moc"
