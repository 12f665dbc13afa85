// One run by construction, calibration family (issue 40): every front end hands its files to
// core/calib/calib_run (loadCalibInputs / loadCalibPart) and its parameters to the same schema,
// so a calib command given its own printed config writes the same bytes, and an input the
// command line refuses is refused by the core for everyone. (The workbench's side:
// ui_test_calib_workspace, workbenchAndCliWriteTheSameFiles and emptyControlPointsAsTheCli;
// Python's: tests/python/test_bindings.py, test_calib_*.) Unlike the SLR and footprint
// families, no output differed here before the loading moved into core (each front end read
// the files itself, with the same readers): these tests pin that it stays so.
#include <QtTest>

#include "core/calib/calib_run.hpp"
#include "test_support.hpp"

using lwbtest::readAll;
using lwbtest::runCli;

class TestCalibOneRun : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString p(const QString& n) const { return m_dir.path() + "/" + n; }
    QString p_(const QString& n) const { return p(n); }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        const auto r = runCli({"simulate", "calib", p("sim"), "--seed", "9", "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        // The waveform as amplitudes alone: its times come from waveform.sample_interval_ns.
        QByteArray amp = "amplitude\n";
        const QList<QByteArray> lines = readAll(p("sim/waveform.csv")).split('\n');
        for (int i = 1; i < lines.size(); ++i)
            if (!lines[i].isEmpty()) amp += lines[i].split(',').value(1) + "\n";
        QVERIFY(lwbtest::writeText(p("amp.csv"), amp));
    }

    // Each command with options, and with the config it prints for those options: the same files.
    void printedConfigGivesTheSameBytes() {
        struct Case {
            QString tag;
            QStringList run, opts, outputs;
        };
        const QString s = p("sim");
        const QList<Case> cases = {
            {"detector", {"calib", "detector", s + "/detectors.csv"}, {"--set", "detector.model=elliptical"}, {"-o", "--detectors"}},
            {"pointing", {"calib", "pointing", s + "/control_points.csv", "--beams", s + "/beams.json"}, {"--model", "dual"},
             {"-o", "--params", "--residuals", "--iterations"}},
            {"waveform", {"calib", "waveform", p("amp.csv"), "--features", s + "/features.csv"},
             {"--set", "waveform.sample_interval_ns=0.25"}, {"-o", "--model"}},
            {"stats", {"calib", "stats", s + "/diffs.csv", "--group", "beam"}, {}, {"-o"}},
        };
        for (const Case& c : cases) {
            const auto printed = runCli(c.run.mid(0, 2) + QStringList{"--print-config"} + c.opts);
            QVERIFY2(printed.exitCode == 0, qPrintable(c.tag + ": " + printed.err));
            QVERIFY(lwbtest::writeText(p(c.tag + ".json"), printed.out.toUtf8()));
            for (const QString& way : {QString("direct"), QString("config")}) {
                QStringList args = c.run + QStringList{"-q"};
                args += way == "direct" ? c.opts : QStringList{"--config", p(c.tag + ".json")};
                for (const QString& o : c.outputs) args << o << p(c.tag + "_" + way + o.mid(o.lastIndexOf('-')) + ".csv");
                const auto r = runCli(args);
                QVERIFY2(r.exitCode == 0 || r.exitCode == 3, qPrintable(c.tag + " " + way + ": " + r.err));
            }
            for (const QString& o : c.outputs) {
                const QString end = o.mid(o.lastIndexOf('-')) + ".csv";
                const QByteArray a = readAll(p(c.tag + "_direct" + end)), b = readAll(p(c.tag + "_config" + end));
                QVERIFY2(!a.isEmpty(), qPrintable(c.tag + end));
                QVERIFY2(a == b, qPrintable(c.tag + " " + o + ": the printed config gives other bytes"));
            }
        }
        // The model of an amplitude-only waveform is timed at the interval set: 0.25 ns steps.
        const QList<QByteArray> model = readAll(p("waveform_direct-model.csv")).split('\n');
        QVERIFY(model.size() > 3);
        QCOMPARE(model[2].split(',').value(0).toDouble() - model[1].split(',').value(0).toDouble(), 0.25);
    }

    // One loader refuses for everyone, with one message: a control-point file without points.
    void emptyControlPointsAreRefusedByTheCore() {
        QVERIFY(lwbtest::writeText(p("no_points.csv"), readAll(p("sim/control_points.csv")).split('\n').value(0) + "\n"));
        const auto cli = runCli({"calib", "pointing", p("no_points.csv"), "--beams", p("sim/beams.json"), "-o", p("x.csv")});
        QCOMPARE(cli.exitCode, 1);
        QVERIFY2(cli.err.contains("no_points.csv: no control-point rows"), qPrintable(cli.err));
        QVERIFY(!QFile::exists(p("x.csv")));
        lwb::core::calib::CalibSources src;
        src.controlPoints = lwbtest::str(p("no_points.csv"));
        src.beams = lwbtest::str(p("sim/beams.json"));
        lwb::core::calib::CalibInputData in;
        std::string err;
        QVERIFY(!lwb::core::calib::loadCalibInputs(src, &in, &err));
        QVERIFY2(cli.err.contains(QString::fromStdString(err)), err.c_str());
        // Control points without beam designs: said, not run.
        src.beams.clear();
        QVERIFY(!lwb::core::calib::loadCalibInputs(src, &in, &err));
        QVERIFY2(err.find("need beam designs") != std::string::npos, err.c_str());
    }

    // A rule between rows is the schema's, so every front end refuses the same settings: the
    // chi-square scaling of a given noise model was checked by `calib detector` alone (the
    // workbench and Python ran it on the data's noise). In either order of the settings.
    void rulesBetweenRowsAreEveryonesAndOrderFree() {
        lwb::core::calib::CalibParams p;
        p.detector.scaleByChi2 = true;
        const std::string e = lwb::core::calib::validate(p);
        QVERIFY2(e.find("scale_chi2") != std::string::npos && e.find("given noise") != std::string::npos, e.c_str());
        const auto cli = runCli({"calib", "detector", p_("sim/detectors.csv"), "--set", "detector.scale_chi2=true", "-o", p_("c.csv")});
        QCOMPARE(cli.exitCode, 2);
        QVERIFY2(cli.err.contains(QString::fromStdString(e)), qPrintable(cli.err));
        for (const QStringList& order : {QStringList{"detector.noise=given", "detector.scale_chi2=true"},
                                         QStringList{"detector.scale_chi2=true", "detector.noise=given"}}) {
            QStringList args{"calib", "detector", p_("sim/detectors.csv"), "-q", "-o", p_("ok.csv")};
            for (const QString& kv : order) args << "--set" << kv;
            const auto r = runCli(args);
            QVERIFY2(r.exitCode == 0 || r.exitCode == 3, qPrintable(order.join(' ') + ": " + r.err));
        }
    }
};

QTEST_GUILESS_MAIN(TestCalibOneRun)
#include "test_calib_one_run.moc"
