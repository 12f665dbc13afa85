// The calibration workspace under the offscreen platform: the demo's fits against the
// simulators' truth, parameter changes reaching the results shown, the same numbers as the CLI
// on the same files, exports, a corrupt input that leaves the state alone, sessions.
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QJsonDocument>
#include <QLabel>
#include <QStandardPaths>
#include <QTableWidget>
#include <QtTest>
#include <qcustomplot.h>

#include "core/common/csv.hpp"
#include "session_refused.hpp"
#include "test_support.hpp"
#include "ui/calib/calib_workspace.hpp"

using namespace lwb::ui;
using namespace lwb::core::calib;

namespace {
double csvNumber(const lwb::core::CsvTable& t, size_t row, const char* column) {
    const int c = t.column(column);
    if (c < 0 || row >= t.rows.size()) return NAN;
    return std::stod(t.rows[row][size_t(c)]);
}
QCPGraph* graphNamed(QCustomPlot* p, const QString& name) {
    for (int i = 0; i < p->graphCount(); ++i)
        if (p->graph(i)->name() == name) return p->graph(i);
    return nullptr;
}
}  // namespace

class TestCalibWorkspace : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString path(const QString& f) const { return m_dir.path() + "/" + f; }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        const auto r = lwbtest::runCli({"simulate", "calib", path("sim"), "--seed", "4", "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
    }

    void demoShowsTheSimulatedTruthWithinItsUncertainty() {
        CalibWorkspace w;
        CalibController* c = w.controller();
        w.openDemo();
        QVERIFY(c->waitIdle(30000));
        const CalibRun& run = c->run();
        // Detector array: the fitted centre against the simulator's centre, within 3σ per axis.
        QVERIFY(run.hasDetector);
        QVERIFY2(run.detector.ok, run.detector.error.c_str());
        QVERIFY(c->data().hasDetectorTruth);
        const GaussSurface& t = c->data().detectorTruth;
        const UncertaintyEllipse& e = run.detector.centreEllipse;
        QVERIFY(e.sigmaE > 0 && e.sigmaE < 0.2 && e.sigmaN > 0 && e.sigmaN < 0.2);
        QVERIFY2(std::fabs(run.detector.centreE - t.e0) < 3 * e.sigmaE,
                 qPrintable(QString("E %1 vs %2 ± %3").arg(run.detector.centreE).arg(t.e0).arg(e.sigmaE)));
        QVERIFY2(std::fabs(run.detector.centreN - t.n0) < 3 * e.sigmaN,
                 qPrintable(QString("N %1 vs %2 ± %3").arg(run.detector.centreN).arg(t.n0).arg(e.sigmaN)));
        // ... and that is what the workspace shows: the centre in the summary and on the map.
        QVERIFY(w.detectorSummary()->text().contains(QString::number(run.detector.centreE, 'f', 3)));
        QCPGraph* centre = graphNamed(w.energyPlot(), "fitted centre");
        QVERIFY(centre && centre->dataCount() == 1);
        QCOMPARE(centre->data()->at(0)->key, run.detector.centreE);
        QCPGraph* truth = graphNamed(w.centrePlot(), "simulated centre");
        QVERIFY(truth && truth->dataCount() == 1);  // in cm from the fitted centre
        QVERIFY(std::fabs(truth->data()->at(0)->key - 100 * (t.e0 - run.detector.centreE)) < 1e-9);
        // Pointing: every correction within 3σ of the simulated one.
        QVERIFY2(run.pointing.ok, run.pointing.error.c_str());
        for (int k = 0; k < 2; ++k) {
            const BeamCalibration& b = run.pointing.beams[size_t(k)];
            QVERIFY(std::fabs(b.dAlphaRad - c->data().trueDAlpha[k]) < 3 * b.dAlphaSdRad);
            QVERIFY(std::fabs(b.dBetaRad - c->data().trueDBeta[k]) < 3 * b.dBetaSdRad);
            QVERIFY(std::fabs(b.dRhoM - c->data().trueDRho[k]) < 3 * b.dRhoSdM);
        }
        QVERIFY(run.pointing.iterations.size() >= 2);
        QVERIFY(run.pointing.iterations.back().rmsPlanM < run.pointing.iterations.front().rmsPlanM / 5);
        QVERIFY(w.pointingConvergencePlot()->graphCount() == 3);
        QCOMPARE(w.pointingConvergencePlot()->graph(0)->dataCount(), int(run.pointing.iterations.size()));
        QCOMPARE(w.detectorConvergencePlot()->graph(0)->dataCount(), int(run.detector.costPerIteration.size()));
        // Validation statistics: two beams of 22 independent check points, labelled rows.
        QCOMPARE(int(run.stats.size()), 2);
        QTableWidget* st = w.statsTable();
        QCOMPARE(st->columnCount(), 2);
        QCOMPARE(st->horizontalHeaderItem(0)->text(), QString("beam 1"));
        QCOMPARE(st->item(0, 0)->text(), QString("22"));
        QCOMPARE(st->item(0, 1)->text(), QString("22"));
        const ElevationStats& s1 = run.stats[0].stats.stats;
        QVERIFY(s1.rmsAboutZero > 0.05 && s1.rmsAboutZero < 0.3);  // range noise 0.1 m, survey 0.05 m
        int rmsRow = -1, stdRow = -1;
        for (int r = 0; r < st->rowCount(); ++r) {
            if (st->verticalHeaderItem(r)->text().startsWith("RMS about zero")) rmsRow = r;
            if (st->verticalHeaderItem(r)->text().startsWith("sample std")) stdRow = r;
        }
        QVERIFY(rmsRow >= 0 && stdRow >= 0);
        QCOMPARE(st->item(rmsRow, 0)->text(), QString::number(s1.rmsAboutZero, 'f', 4));
        QCOMPARE(st->item(stdRow, 0)->text(), QString::number(s1.stdSample, 'f', 4));
        // Waveform: the feature height within 3σ of the simulated 2.93 m, the 2.9 m wood chosen.
        QVERIFY2(run.waveform.ok, run.waveform.error.c_str());
        QVERIFY(std::fabs(run.waveform.heightM - c->data().trueHeightM) < 3 * run.waveform.heightSdM + 1e-3);
        QVERIFY(run.match.ok && run.match.found);
        QCOMPARE(w.rankingTable()->rowCount(), 6);
        QCOMPARE(w.rankingTable()->item(0, 1)->text(), QString("wood W1"));
    }

    void parameterChangesReachTheResults() {
        CalibWorkspace w;
        CalibController* c = w.controller();
        w.openDemo();
        QVERIFY(c->waitIdle(30000));
        const int usedBefore = c->run().detector.used;
        const double eBefore = c->run().detector.centreE;
        const QString summaryBefore = w.detectorSummary()->text();
        // The trigger threshold: detectors at or below it leave the fit.
        w.triggerField()->setValue(150);
        QVERIFY(c->waitIdle(30000));
        const CalibRun& run = c->run();
        QVERIFY2(run.detector.ok, run.detector.error.c_str());
        QCOMPARE(run.params.detector.triggerThreshold, 150.0);
        int above = 0;
        for (const auto& d : c->data().array.detectors) above += std::isfinite(d.energy) && d.energy > 150;
        QCOMPARE(run.detector.used, above);
        QVERIFY(run.detector.used < usedBefore);
        QVERIFY(run.detector.centreE != eBefore);
        QVERIFY(w.detectorSummary()->text() != summaryBefore);
        QVERIFY(w.detectorSummary()->text().contains(QString("%1 of %2 detectors").arg(above).arg(c->data().array.detectors.size())));
        // Detectors at or below the threshold stay in the fit as "at most" bounds (censoring).
        QCPGraph* aside = graphNamed(w.energyPlot(), "in the fit as a bound (threshold / saturation)");
        QVERIFY(aside);
        QCOMPARE(aside->dataCount(), usedBefore - above);
        // The map draws what the fit did: bounds and set-aside detectors as the fit's own statuses.
        int bounds = 0, setAside = 0;
        for (size_t i = 0; i < run.detector.detectors.size(); ++i) {
            const auto& d = c->data().array.detectors[i];
            if (!std::isfinite(d.energy) || d.triggered == 0) continue;
            const auto st = run.detector.detectors[i].status;
            if (st == DetectorStatus::AtLeast || st == DetectorStatus::AtMost) ++bounds;
            else if (st != DetectorStatus::Used) ++setAside;
        }
        QCOMPARE(aside->dataCount(), bounds);
        QCPGraph* setAsideGraph = graphNamed(w.energyPlot(), "set aside (outlier, or censoring off)");
        QCOMPARE(setAsideGraph ? setAsideGraph->dataCount() : 0, setAside);
        // thred_h below the wood's Δh: no candidate any more, and the table says so.
        const double dh = c->run().match.bestDeltaHM;
        QVERIFY(dh > 0.005);
        w.thresholdField()->setValue(dh / 2);
        QVERIFY(c->waitIdle(30000));
        QVERIFY(c->run().match.ok && !c->run().match.found);
        QCOMPARE(w.rankingTable()->item(0, 4)->text(), QString("no"));
        // The dual-beam model: a different parameter set (relative rotation r, a).
        w.pointingModelBox()->setCurrentIndex(1);
        QVERIFY(c->waitIdle(30000));
        QCOMPARE(c->run().pointing.model, CalibModel::DualBeam);
        bool hasR = false;
        for (const auto& n : c->run().pointing.paramNames) hasR |= n == "rel_r";
        QVERIFY(hasR);
        bool shown = false;
        for (int r = 0; r < w.paramTable()->rowCount(); ++r) shown |= w.paramTable()->item(r, 0)->text().startsWith("relative rotation r");
        QVERIFY(shown);
    }

    // waveform.sample_interval_ns means the same in the workbench as in the CLI (issue 28: the
    // workbench read an amplitude-only waveform at a literal 0.5 ns): at 0.25 ns the same ranking
    // file and half the height.
    void waveformSampleIntervalAsTheCli() {
        const QString dir = path("sim");
        QByteArray amp = "amplitude\n";
        const QList<QByteArray> lines = lwbtest::readAll(dir + "/waveform.csv").split('\n');
        for (int i = 1; i < lines.size(); ++i)
            if (!lines[i].isEmpty()) amp += lines[i].split(',').value(1) + "\n";
        QVERIFY(lwbtest::writeText(path("amp_only.csv"), amp));
        const auto cli = lwbtest::runCli({"calib", "waveform", path("amp_only.csv"), "--features", dir + "/features.csv",
                                          "--set", "waveform.sample_interval_ns=0.25", "-o", path("rank_025.csv")});
        QVERIFY2(cli.exitCode == 0 || cli.exitCode == 3, qPrintable(cli.err));
        CalibWorkspace w;
        CalibController* c = w.controller();
        QString err;
        CalibParams p = c->params();
        p.waveform.sampleIntervalNs = 0.25;
        QVERIFY2(c->setParams(p, &err), qPrintable(err));
        QVERIFY2(c->openWaveform(path("amp_only.csv"), &err), qPrintable(err));
        QVERIFY2(c->openFeatures(dir + "/features.csv", &err), qPrintable(err));
        QVERIFY(c->waitIdle(30000));
        QVERIFY2(c->run().waveform.ok, c->run().waveform.error.c_str());
        const double h025 = c->run().waveform.heightM;
        QVERIFY2(c->exportRanking(path("rank_gui_025.csv"), &err), qPrintable(err));
        QCOMPARE(lwbtest::readAll(path("rank_gui_025.csv")), lwbtest::readAll(path("rank_025.csv")));
        p.waveform.sampleIntervalNs = 0.5;
        QVERIFY2(c->setParams(p, &err), qPrintable(err));
        QVERIFY(c->waitIdle(30000));
        QVERIFY(std::fabs(c->run().waveform.heightM - 2 * h025) < 1e-6 * h025);
    }

    void filesGiveTheCliResults() {
        const QString dir = path("sim");
        const auto cli = lwbtest::runCli({"calib", "detector", dir + "/detectors.csv", "-o", path("centre.csv"), "-q"});
        QVERIFY2(cli.exitCode == 0, qPrintable(cli.err));
        const auto cliP = lwbtest::runCli({"calib", "pointing", dir + "/control_points.csv", "--beams", dir + "/beams.json", "-o",
                                           path("beams_out.csv"), "--params", path("params.csv"), "-q"});
        QVERIFY2(cliP.exitCode == 0, qPrintable(cliP.err));
        const auto cliW = lwbtest::runCli({"calib", "waveform", dir + "/waveform.csv", "--features", dir + "/features.csv", "-o",
                                           path("rank.csv")});
        QVERIFY2(cliW.exitCode == 0, qPrintable(cliW.err));

        CalibWorkspace w;
        CalibController* c = w.controller();
        QString err;
        QVERIFY2(c->openDetectors(dir + "/detectors.csv", &err), qPrintable(err));
        QVERIFY2(c->openControlPoints(dir + "/control_points.csv", QString(), &err), qPrintable(err));
        QCOMPARE(c->inputs().beams, dir + "/beams.json");  // found beside the control points
        QVERIFY2(c->openWaveform(dir + "/waveform.csv", &err), qPrintable(err));
        QVERIFY2(c->openFeatures(dir + "/features.csv", &err), qPrintable(err));
        QVERIFY(c->waitIdle(30000));
        const CalibRun& run = c->run();
        QVERIFY(run.detector.ok && run.pointing.ok && run.waveform.ok && run.match.ok);
        const auto centre = lwb::core::readCsv(path("centre.csv").toStdString());
        QVERIFY(centre.ok);
        QVERIFY(std::fabs(csvNumber(centre.table, 0, "centre_e_m") - run.detector.centreE) < 1e-4);
        QVERIFY(std::fabs(csvNumber(centre.table, 0, "centre_n_m") - run.detector.centreN) < 1e-4);
        QCOMPARE(int(csvNumber(centre.table, 0, "used")), run.detector.used);
        const auto params = lwb::core::readCsv(path("params.csv").toStdString());
        QVERIFY(params.ok);
        QCOMPARE(params.table.rows.size(), run.pointing.params.size());
        for (size_t j = 0; j < run.pointing.params.size(); ++j) {
            const double v = csvNumber(params.table, j, "value");
            QVERIFY2(std::fabs(v - run.pointing.params[j]) <= 1e-8 * std::max(1e-6, std::fabs(v)),
                     qPrintable(QString("%1: %2 vs %3").arg(run.pointing.paramNames[j].c_str()).arg(v).arg(run.pointing.params[j])));
        }
        // The ranking: same order as the CLI's; the export writes the same file.
        QVERIFY2(c->exportRanking(path("rank_gui.csv"), &err), qPrintable(err));
        QCOMPARE(lwbtest::readAll(path("rank_gui.csv")), lwbtest::readAll(path("rank.csv")));
        // No check points or differences: the statistics are the calibration's own residuals.
        QVERIFY(run.statsSource.contains("not independent"));
        QVERIFY2(c->openDifferences(dir + "/../diffs.csv", "beam", &err) == false, "a missing file is an error");
        QVERIFY(lwbtest::writeText(path("diffs.csv"), "beam,d\n1,0.1\n1,-0.05\n1,0.02\n2,0.3\n2,0.1\n"));
        QVERIFY2(c->openDifferences(path("diffs.csv"), "beam", &err), qPrintable(err));
        QVERIFY(c->waitIdle(30000));
        QCOMPARE(int(c->run().stats.size()), 2);
        QCOMPARE(c->run().stats[1].name, QString("beam 2"));
        QCOMPARE(w.statsTable()->item(0, 1)->text(), QString("2"));
        QCOMPARE(w.statsTable()->item(1, 1)->text(), QString("0.2000"));  // mean of 0.3 and 0.1
    }

    // Issue 28, GUI = CLI: the workbench's exports of a calibration run are the files laserwb-cli
    // writes for the same inputs and settings, byte for byte — centre and detector report
    // (calib detector -o, --detectors), pointing parameters, beams and iterations (calib pointing
    // --params, -o, --iterations; the beams export is the pointing CSV), waveform ranking, and
    // the statistics of the differences grouped by beam (calib stats --group beam).
    void workbenchAndCliWriteTheSameFiles() {
        const QString dir = path("sim");
        const QString out = path("same");
        QVERIFY(QDir().mkpath(out));
        auto cli = [](const QStringList& args) {
            const auto r = lwbtest::runCli(args + QStringList{"-q"});
            QVERIFY2(r.exitCode == 0, qPrintable(args.join(' ') + ": " + r.err));
        };
        cli({"calib", "detector", dir + "/detectors.csv", "-o", out + "/centre_cli.csv", "--detectors", out + "/report_cli.csv"});
        cli({"calib", "pointing", dir + "/control_points.csv", "--beams", dir + "/beams.json", "-o", out + "/beams_cli.csv",
             "--params", out + "/params_cli.csv", "--iterations", out + "/iter_cli.csv"});
        cli({"calib", "waveform", dir + "/waveform.csv", "--features", dir + "/features.csv", "-o", out + "/rank_cli.csv"});
        cli({"calib", "stats", dir + "/diffs.csv", "--group", "beam", "-o", out + "/stats_cli.csv"});

        CalibWorkspace w;
        CalibController* c = w.controller();
        QString err;
        QVERIFY2(c->openDetectors(dir + "/detectors.csv", &err), qPrintable(err));
        QVERIFY2(c->openControlPoints(dir + "/control_points.csv", dir + "/beams.json", &err), qPrintable(err));
        QVERIFY2(c->openWaveform(dir + "/waveform.csv", &err), qPrintable(err));
        QVERIFY2(c->openFeatures(dir + "/features.csv", &err), qPrintable(err));
        QVERIFY2(c->openDifferences(dir + "/diffs.csv", "beam", &err), qPrintable(err));
        QVERIFY(c->waitIdle(30000));
        QVERIFY2(c->exportCentre(out + "/centre_gui.csv", &err), qPrintable(err));
        QVERIFY2(c->exportDetectorReport(out + "/report_gui.csv", &err), qPrintable(err));
        QVERIFY2(c->exportPointing(out + "/params_gui.csv", &err), qPrintable(err));
        QVERIFY2(c->exportIterations(out + "/iter_gui.csv", &err), qPrintable(err));
        QVERIFY2(c->exportRanking(out + "/rank_gui.csv", &err), qPrintable(err));
        QVERIFY2(c->exportStats(out + "/stats_gui.csv", &err), qPrintable(err));
        for (const char* f : {"centre", "report", "params", "iter", "rank", "stats"}) {
            const QByteArray gui = lwbtest::readAll(out + "/" + f + "_gui.csv"), cliFile = lwbtest::readAll(out + "/" + f + "_cli.csv");
            QVERIFY2(!gui.isEmpty(), f);
            QVERIFY2(gui == cliFile, qPrintable(QString("%1: the workbench's export differs from laserwb-cli's:\n%2\n---\n%3")
                                                    .arg(f, QString::fromUtf8(gui.left(400)), QString::fromUtf8(cliFile.left(400)))));
        }
    }

    void exportsWriteTheExpectedRows() {
        CalibWorkspace w;
        CalibController* c = w.controller();
        w.openDemo();
        QVERIFY(c->waitIdle(30000));
        QString err;
        QVERIFY2(c->exportDetectorReport(path("report.csv"), &err), qPrintable(err));
        const auto rep = lwb::core::readCsv(path("report.csv").toStdString());
        QVERIFY(rep.ok);
        QCOMPARE(rep.table.rows.size(), c->data().array.detectors.size());
        int used = 0;
        for (const auto& row : rep.table.rows) used += row[size_t(rep.table.column("status"))] == "used";
        QCOMPARE(used, c->run().detector.used);
        QVERIFY2(c->exportStats(path("stats.csv"), &err), qPrintable(err));
        const auto st = lwb::core::readCsv(path("stats.csv").toStdString());
        QVERIFY(st.ok);
        QCOMPARE(st.table.rows.size(), size_t(2));
        QCOMPARE(int(csvNumber(st.table, 0, "n")), 22);
        QVERIFY(std::fabs(csvNumber(st.table, 1, "std_sample") - c->run().stats[1].stats.stats.stdSample) < 1e-6);
        QVERIFY2(c->exportCentre(path("centre_demo.csv"), &err), qPrintable(err));
        const auto ce = lwb::core::readCsv(path("centre_demo.csv").toStdString());
        QVERIFY(ce.ok && ce.table.rows.size() == 1);
        QVERIFY(std::fabs(csvNumber(ce.table, 0, "sigma_e_m") - c->run().detector.centreEllipse.sigmaE) < 1e-4);
        QVERIFY2(c->exportPointing(path("params_demo.csv"), &err), qPrintable(err));
        const auto pp = lwb::core::readCsv(path("params_demo.csv").toStdString());
        QVERIFY(pp.ok);
        QCOMPARE(pp.table.rows.size(), c->run().pointing.params.size());
        QVERIFY2(c->exportIterations(path("iter.csv"), &err), qPrintable(err));
        const auto it = lwb::core::readCsv(path("iter.csv").toStdString());
        QVERIFY(it.ok);
        QCOMPARE(it.table.rows.size(), c->run().pointing.iterations.size());
        QVERIFY2(c->exportRanking(path("rank_demo.csv"), &err), qPrintable(err));
        const auto rk = lwb::core::readCsv(path("rank_demo.csv").toStdString());
        QVERIFY(rk.ok && rk.table.rows.size() == 6);
        QCOMPARE(rk.table.rows[0][size_t(rk.table.column("chosen"))], std::string("1"));
        // An export into a folder that does not exist fails with a message, never a crash.
        QVERIFY(!c->exportStats(path("no/such/dir/stats.csv"), &err));
        QVERIFY(!err.isEmpty());
    }

    void corruptInputKeepsThePreviousState() {
        CalibWorkspace w;
        CalibController* c = w.controller();
        w.openDemo();
        QVERIFY(c->waitIdle(30000));
        const size_t detectors = c->data().array.detectors.size();
        const double centre = c->run().detector.centreE;
        const quint64 gen = c->run().generation;
        QVERIFY(lwbtest::writeText(path("bad_det.csv"), "id,e,n,energy\nD1,0,0,5\nD2,1,0,abc\nD3,0,1,7\n"));
        QString err;
        QVERIFY(!c->openDetectors(path("bad_det.csv"), &err));
        QVERIFY2(err.contains("bad_det.csv:3"), qPrintable(err));
        QVERIFY(!c->busy());
        QCOMPARE(c->data().array.detectors.size(), detectors);
        QCOMPARE(c->inputs().detectors, QString("demo"));
        QCOMPARE(c->run().generation, gen);
        QCOMPARE(c->run().detector.centreE, centre);
        QVERIFY(lwbtest::writeText(path("bad_cp.csv"), "beam,sat_x\n1,2\n"));
        QVERIFY(!c->openControlPoints(path("bad_cp.csv"), "demo", &err));
        QVERIFY2(err.contains("bad_cp.csv"), qPrintable(err));
        QCOMPARE(c->inputs().controlPoints, QString("demo"));
        QVERIFY(lwbtest::writeText(path("bad_wave.csv"), "time_ns,amplitude\n0,1\n0.5,x\n"));
        QVERIFY(!c->openWaveform(path("bad_wave.csv"), &err));
        QVERIFY2(err.contains("bad_wave.csv:3"), qPrintable(err));
        QCOMPARE(c->inputs().waveform, QString("demo"));
        QVERIFY(!c->openFeatures(path("missing.csv"), &err));
        QVERIFY(!err.isEmpty());
        // Control points without any beam designs: refused (no silent default design).
        QDir().mkpath(path("cp_only"));
        QVERIFY(QFile::copy(path("sim/control_points.csv"), path("cp_only/control_points.csv")));
        CalibController fresh;
        QVERIFY(!fresh.openControlPoints(path("cp_only/control_points.csv"), QString(), &err));
        QVERIFY2(err.contains("beam designs"), qPrintable(err));
        QVERIFY(fresh.data().points.empty());
        QVERIFY2(fresh.openControlPoints(path("cp_only/control_points.csv"), path("sim/beams.json"), &err), qPrintable(err));
        QCOMPARE(fresh.data().points.size(), size_t(8));
        // An input the fit cannot use (three detectors) is shown as an error, not a crash.
        QVERIFY(lwbtest::writeText(path("three.csv"), "id,e,n,energy\nA,0,0,5\nB,1,0,6\nC,0,1,7\n"));
        QVERIFY2(c->openDetectors(path("three.csv"), &err), qPrintable(err));
        QVERIFY(c->waitIdle(30000));
        QVERIFY(!c->run().detector.ok);
        QVERIFY(w.detectorSummary()->text().contains("failed"));
        QVERIFY(c->run().pointing.ok);  // the other parts go on
    }

    void sessionRoundTrip() {
        QJsonObject state;
        double centre = 0, k = 0;
        {
            CalibWorkspace a;
            a.openDemo();
            a.triggerField()->setValue(120);
            a.pointingModelBox()->setCurrentIndex(1);
            a.thresholdField()->setValue(0.2);
            QVERIFY(a.controller()->waitIdle(30000));
            centre = a.controller()->run().detector.centreN;
            k = a.controller()->run().pointing.chi2;
            // Through text, as a session file.
            state = QJsonDocument::fromJson(QJsonDocument(a.saveState()).toJson()).object();
        }
        CalibWorkspace b;
        QString err;
        QVERIFY2(b.restoreState(state, &err), qPrintable(err));
        QVERIFY(b.controller()->waitIdle(30000));
        QCOMPARE(b.controller()->params().detector.triggerThreshold, 120.0);
        QCOMPARE(b.controller()->params().pointing.model, CalibModel::DualBeam);
        QCOMPARE(b.controller()->params().match.thresholdM, 0.2);
        QCOMPARE(b.triggerField()->value(), 120.0);
        QCOMPARE(b.pointingModelBox()->currentIndex(), 1);
        QCOMPARE(b.controller()->inputs().detectors, QString("demo"));
        QCOMPARE(b.controller()->run().detector.centreN, centre);  // deterministic demo, same parameters
        QCOMPARE(b.controller()->run().pointing.chi2, k);
        // Invalid parameters or an unreadable input: refused, the state stays.
        QJsonObject bad = state;
        QJsonObject params = bad["params"].toObject();
        QJsonObject det = params["detector"].toObject();
        det["rel_noise"] = 3.0;
        params["detector"] = det;
        bad["params"] = params;
        QVERIFY(!b.restoreState(bad, &err));
        QVERIFY2(err.contains("detector"), qPrintable(err));
        QCOMPARE(b.controller()->params().detector.relativeNoise, 0.05);
        det["rel_noise"] = "high";
        params["detector"] = det;
        bad["params"] = params;
        QVERIFY(!b.restoreState(bad, &err));
        QVERIFY2(err.contains("rel_noise"), qPrintable(err));
        bad = state;
        QJsonObject in = bad["inputs"].toObject();
        in["detectors"] = path("does_not_exist.csv");
        bad["inputs"] = in;
        QVERIFY(!b.restoreState(bad, &err));
        QVERIFY2(err.contains("does_not_exist.csv"), qPrintable(err));
        QCOMPARE(b.controller()->inputs().detectors, QString("demo"));
        QCOMPARE(b.controller()->params().detector.triggerThreshold, 120.0);
        QVERIFY(b.controller()->waitIdle(30000));
        QCOMPARE(b.controller()->run().detector.centreN, centre);
    }

    // A bad value in a session file is named with the file, line and column (issue 9): the
    // parameter block through the schema, an unknown key, an input that is not a path.
    void sessionErrorsNameLineAndColumn_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("where");
        QTest::addColumn<QString>("what");
        QTest::newRow("rel_noise 3") << "{\n \"calibration\": {\n  \"params\": {\"detector\":\n   {\"rel_noise\": 3}}}}"
                                     << "s.json:4:" << "rel_noise";
        QTest::newRow("unknown key") << "{\n \"calibration\": {\n  \"params\": {},\n  \"colour\": 1}}" << "s.json:4:"
                                     << "colour";
        QTest::newRow("input not a path") << "{\"calibration\": {\n \"inputs\": {\n  \"detectors\": 7}}}" << "s.json:3:"
                                          << "detectors";
        QTest::newRow("dual-only rule")
            << "{\"calibration\": {\n \"params\": {\"pointing\": {\"fix_relative\": true}}}}" << "s.json:2:"
            << "fix_relative";
    }
    void sessionErrorsNameLineAndColumn() {
        QFETCH(QString, text);
        QFETCH(QString, where);
        QFETCH(QString, what);
        lwbtest::expectSessionRefused<CalibWorkspace>(text, "calibration", where, what);
    }
};

QTEST_MAIN(TestCalibWorkspace)
#include "test_calib_workspace.moc"
