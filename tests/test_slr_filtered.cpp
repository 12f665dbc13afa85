// Filtered passes (no noise floor). Station full-rate files often hold only the points the
// station kept: the shared BLITS file has 54 passes from 9 stations with every range flagged
// "data". With no noise outside the track the image's automatic score cannot tell the track
// from a piece of it, and the screening kept 28 % of a clean 3577-point CHAL pass (recall 0.38
// median over the file). The noise-floor check (ScreenParams::acceptFloorless) must accept such
// passes whole and must not fire on passes that do have noise.
#include <QtTest>

#include <cmath>

#include "core/common/csv.hpp"
#include "core/common/text.hpp"
#include "core/sim/slr_sim.hpp"
#include "core/slr/screen_auto.hpp"
#include "test_support.hpp"

using namespace lwbtest;
using namespace lwb::core;

class TestSlrFiltered : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString p(const QString& n) const { return m_dir.path() + "/" + n; }

    static sim::SlrSimPass simulate(sim::SlrKind kind, double signalFraction, uint64_t seed, double gateS = 0) {
        sim::SlrSimParams sp = sim::slrSimPreset(kind);
        sp.points = 3000;
        sp.signalFraction = signalFraction;
        if (gateS > 0) {
            // A narrow gate follows the prediction: the track sits in it, flat (no range or
            // time bias to carry it across a gate of a few ns).
            sp.gateS = gateS;
            sp.rangeBiasMaxS = 0;
            sp.timeBiasMaxS = 0;
        }
        return sim::simulateSlrPass(sp, seed);
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // The check alone on simulated passes with exact truth: signal only is floorless; any real
    // noise floor (30 %, 5 % signal; noise in a gate only 20× the jitter) is not.
    void floorCheckOnSimulatedPasses_data() {
        QTest::addColumn<int>("kind");
        QTest::addColumn<double>("signalFraction");
        QTest::addColumn<double>("gateS");
        QTest::addColumn<bool>("floorless");
        for (auto k : {sim::SlrKind::Khz, sim::SlrKind::Conventional, sim::SlrKind::Diffuse, sim::SlrKind::Leo}) {
            const std::string name = sim::slrKindName(k);
            // Diffuse (debris) ranging jitters by ~2 ns, above the 1 ns a filtered pass may have:
            // never called floorless (a stated limit; the paper's screening runs as before).
            QTest::newRow((name + " signal only").c_str()) << int(k) << 1.0 << 0.0 << (k != sim::SlrKind::Diffuse);
            QTest::newRow((name + " 30 % signal").c_str()) << int(k) << 0.3 << 0.0 << false;
            QTest::newRow((name + " 5 % signal").c_str()) << int(k) << 0.05 << 0.0 << false;
        }
        // A narrow gate: the noise lies within a few σ of the track, where "beyond 5σ" cannot
        // see it; the flat distribution (peakedness) must.
        // Stated limit: with a 3 ns gate and 70 % noise the spike is too wide to tell from a
        // filtered track's tails (seed 2: central share 0.30); such a row is not asserted.
        for (double gate : {3e-9, 5e-9, 10e-9})
            for (double sf : {0.3, 0.6, 0.9})
                if (gate > 4e-9 || sf > 0.5) QTest::newRow(qPrintable(QString("khz %1 % signal, %2 ns gate").arg(100 * sf).arg(gate * 1e9)))
                    << int(sim::SlrKind::Khz) << sf << gate << false;
    }
    void floorCheckOnSimulatedPasses() {
        QFETCH(int, kind);
        QFETCH(double, signalFraction);
        QFETCH(double, gateS);
        QFETCH(bool, floorless);
        for (uint64_t seed = 1; seed <= 5; ++seed) {
            const sim::SlrSimPass pass = simulate(sim::SlrKind(kind), signalFraction, seed, gateS);
            QVERIFY2(pass.ok, pass.error.c_str());
            const slr::NoiseFloorCheck c = slr::checkNoiseFloor(pass.epochS, pass.ocS);
            QVERIFY(c.checked);
            QVERIFY2(c.floorless == floorless,
                     qPrintable(QString("seed %1: sigma %2 ps, peakedness %3, central %5, beyond 5 sigma %4 %")
                                    .arg(seed)
                                    .arg(c.sigmaS * 1e12, 0, 'f', 1)
                                    .arg(c.peakedness, 0, 'f', 2)
                                    .arg(100 * c.beyondFraction, 0, 'f', 2)
                                    .arg(c.centralFraction, 0, 'f', 3)));
        }
    }

    // The screening on simulated signal-only passes accepts (nearly) every point.
    void signalOnlyPassIsAcceptedWhole() {
        const sim::SlrSimPass pass = simulate(sim::SlrKind::Conventional, 1.0, 7);
        QVERIFY2(pass.ok, pass.error.c_str());
        const slr::ScreenResult r = slr::screenSignal(pass.epochS, pass.ocS, slr::ScreenParams{});
        QVERIFY2(r.ok, r.error.c_str());
        QVERIFY(r.floorless);
        const double accepted = double(r.signalPoints + r.recoveredPoints) / double(pass.epochS.size());
        // Tolerance: a Gaussian jitter with an exponential tail keeps > 99.5 % within 5σ.
        QVERIFY2(accepted >= 0.995, qPrintable(QString::number(accepted)));
        slr::ScreenParams off;
        off.acceptFloorless = false;
        const slr::ScreenResult r0 = slr::screenSignal(pass.epochS, pass.ocS, off);
        QVERIFY(r0.ok && !r0.floorless && r0.floorlessAdded == 0);
    }

    // The shared BLITS file: every pass with at least 20 ranges, all flagged data by the station,
    // is accepted with recall >= 0.90 (mean >= 0.95) and precision 1 against those flags.
    // Before the check: median recall 0.38, 26 of 44 passes below 0.9.
    void filteredStationPassesAreKept() {
        const QString in = sharedPath("slr/blits_201206.frd");
        if (!QFile::exists(in)) QSKIP("shared SLR data absent");
        const CliRun r = runCli({"slr", in, "--all-passes", "--out-dir", p("blits"), "-q"});
        // KTZL's 11 ranges (2012-06-25) spread over ±300 ns about the own-TOF polynomial, so no
        // scale showed a track (doubtful since issue 29; "ok" with nothing accepted before); on
        // the orbit-arc trend (issue 43) all 11 are accepted, RMS 190 ps, recall 1 against the
        // station's flags. Its normal points are not delivered: the trends fitted to its 11
        // ranges leave them ±13 mm (one sigma), and two more passes without a prediction (KTZL
        // 06-08, 20 ranges, ±4.6 mm; WETL 06-02, 23 ranges, ±2.4 mm) are doubtful for the same
        // reason (pass_run.hpp kMaxNpTrendErrorMm). Every other pass is ok.
        QCOMPARE(r.exitCode, 3);
        const CsvReadResult s = readCsv(p("blits/summary.csv").toStdString());
        QVERIFY2(s.ok, s.error.c_str());
        const int cStatus = s.table.column("status"), cReason = s.table.column("reason");
        QStringList doubtful;
        for (const auto& row : s.table.rows) {
            if (row[size_t(cStatus)] == "ok") continue;
            QCOMPARE(row[size_t(cStatus)], std::string("doubtful"));
            QVERIFY2(row[size_t(cReason)].find("no normal point is precise enough") != std::string::npos, row[size_t(cReason)].c_str());
            doubtful << QString::fromStdString(row[0]);
        }
        QCOMPARE(doubtful, QStringList({"5", "21", "49"}));
        const int cPoints = s.table.column("points"), cRecall = s.table.column("station_recall"),
                  cPrecision = s.table.column("station_precision");
        QVERIFY(cPoints >= 0 && cRecall >= 0 && cPrecision >= 0);
        double sum = 0;
        int n = 0;
        for (const auto& row : s.table.rows) {
            long long points = 0;
            double recall = 0, precision = 0;
            if (!parseLong(row[size_t(cPoints)], &points) || points < 20) continue;
            if (!parseDouble(row[size_t(cRecall)], &recall) || !parseDouble(row[size_t(cPrecision)], &precision)) continue;
            QVERIFY2(recall >= 0.90, qPrintable(QString("pass %1 (%2 points): recall %3")
                                                    .arg(row[0].c_str()).arg(points).arg(recall)));
            QVERIFY2(precision >= 0.999, qPrintable(QString("pass %1: precision %2").arg(row[0].c_str()).arg(precision)));
            sum += recall;
            ++n;
        }
        QVERIFY2(n >= 40, qPrintable(QString::number(n)));
        QVERIFY2(sum / n >= 0.95, qPrintable(QString::number(sum / n)));
    }

    // Real passes with noise (the station flagged 17–200 ranges as noise): the check must not fire.
    void noisyStationPassesAreNotFloorless_data() {
        QTest::addColumn<QString>("file");
        QTest::newRow("Beacon-C") << "slr/7080_Beacon-C_crd_071220_1715_0.frd";
        QTest::newRow("JASON1") << "slr/7080_JASON1_crd_071220_2033_0.frd";
        QTest::newRow("STELLA") << "slr/7080_STELLA_crd_071220_2128_0.frd";
        QTest::newRow("beaconc 2007-05-11") << "slr/beaconc_20070511.frd";
    }
    void noisyStationPassesAreNotFloorless() {
        QFETCH(QString, file);
        const QString in = sharedPath(file);
        if (!QFile::exists(in)) QSKIP("shared SLR data absent");
        const CliRun r = runCli({"slr", in, "-o", p("noisy.csv")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(!r.err.contains("no noise floor"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestSlrFiltered)
#include "test_slr_filtered.moc"
