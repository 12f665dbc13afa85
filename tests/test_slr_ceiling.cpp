// Issue 43, item 4: screening at its ceiling. On every simulated kind the automatic screening
// with the post-fit (what `laserwb-cli slr` keeps: the post-fit's kept points, or the accepted
// ones where there is no post-fit) is scored against the simulator's exact truth, beside the
// oracle ceiling (core/sim/slr_eval.hpp: the best band about the true track; no method that must
// find the track can do better, gaps aside). Asserted: F1 within 0.015 of the ceiling on every
// pass of every kind (seeds 1–3 fixed in advance). LWB_CEILING_SEEDS=N runs seeds 1..N instead
// (the tables in docs/slr-detection.md used 10); LWB_CEILING_BEFORE=1 turns postfit.noise_band and
// postfit.take_band off (the "before" column); LWB_CEILING_DEBUG=1 says where the returns were lost.
#include <QtTest>
#include <QTemporaryDir>
#include <cmath>

#include "core/sim/slr_eval.hpp"
#include "core/sim/slr_sim.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/pass_run.hpp"
#include "core/slr/postfit.hpp"
#include "test_support.hpp"

using namespace lwb::core;
using namespace lwb::core::slr;
namespace sim = lwb::core::sim;

namespace {

struct Case {
    const char* name;
    sim::SlrKind kind;
    bool day;
    double signalFraction;      // 0: the kind's noise rate
    long long points;           // 0: from the rates
    double durationS;           // 0: the kind's
    double driftNsPerS, curvatureNsPerS2;
    const char* gaps;
};

// Every kind of the simulator at three signal levels, by night and by day, and the hard cases of
// issue 13 (steep curved tracks, gaps, level shifts).
const Case kCases[] = {
    {"khz 50%", sim::SlrKind::Khz, false, 0.5, 0, 0, 0, 0, ""},
    {"khz 10%", sim::SlrKind::Khz, false, 0.1, 0, 0, 0, 0, ""},
    {"khz 3%", sim::SlrKind::Khz, false, 0.03, 0, 0, 0, 0, ""},
    {"khz night", sim::SlrKind::Khz, false, 0, 0, 0, 0, 0, ""},
    {"khz day", sim::SlrKind::Khz, true, 0, 0, 0, 0, 0, ""},
    {"khz day 3% gap", sim::SlrKind::Khz, true, 0.03, 18000, 900, 0, 0, "200:60"},
    {"conventional 50%", sim::SlrKind::Conventional, false, 0.5, 0, 0, 0, 0, ""},
    {"conventional 10%", sim::SlrKind::Conventional, false, 0.1, 0, 0, 0, 0, ""},
    {"conventional 3%", sim::SlrKind::Conventional, false, 0.03, 0, 0, 0, 0, ""},
    {"conventional day", sim::SlrKind::Conventional, true, 0, 0, 0, 0, 0, ""},
    {"conventional gaps", sim::SlrKind::Conventional, false, 0.1, 15000, 1200, 0, 0, "200:30,500:60,800:120"},
    {"diffuse 50%", sim::SlrKind::Diffuse, false, 0.5, 0, 0, 0, 0, ""},
    {"diffuse 10%", sim::SlrKind::Diffuse, false, 0.1, 0, 0, 0, 0, ""},
    {"diffuse 3%", sim::SlrKind::Diffuse, false, 0.03, 0, 0, 0, 0, ""},
    {"diffuse day", sim::SlrKind::Diffuse, true, 0, 0, 0, 0, 0, ""},
    {"leo night", sim::SlrKind::Leo, false, 0, 0, 0, 0, 0, ""},
    {"leo day (noisy LEO)", sim::SlrKind::Leo, true, 0, 0, 0, 0, 0, ""},
    {"leo day 3% steep", sim::SlrKind::Leo, true, 0.03, 18000, 900, 4, 0.01, ""},
    {"leo gaps 30%", sim::SlrKind::Leo, false, 0.3, 0, 0, 4, 0.02, "150:45,330:90"},
    {"daylight day (low SNR)", sim::SlrKind::Daylight, true, 0, 0, 0, 0, 0, ""},
    {"daylight day 2%", sim::SlrKind::Daylight, true, 0.02, 0, 0, 0, 0, ""},
    {"daylight night", sim::SlrKind::Daylight, false, 0, 0, 0, 0, 0, ""},
};

sim::SlrSimParams paramsOf(const Case& c) {
    sim::SlrSimParams p = sim::slrSimPreset(c.kind);
    p.daylight = c.day;
    p.signalFraction = c.signalFraction;
    p.points = c.points;
    if (c.durationS > 0) p.durationS = c.durationS;
    p.driftSPerS = c.driftNsPerS * 1e-9;
    p.driftSPerS2 = c.curvatureNsPerS2 * 1e-9;
    std::string err;
    if (*c.gaps) sim::parseSlrGaps(c.gaps, &p.gaps, &err);
    return p;
}

}  // namespace

class TestSlrCeiling : public QObject {
    Q_OBJECT
private slots:
    // The oracle itself: on a pass of pure Gaussian signal the best band takes everything; on a
    // constructed case the band and its F1 are the ones worked out by hand.
    void ceilingIsTheBestBand() {
        std::vector<double> oc{0, 1, -1, 2, 10, 11, -30};
        std::vector<double> track(oc.size(), 0.0);
        std::vector<uint8_t> truth{1, 1, 1, 1, 0, 0, 0};
        sim::BandCeiling c = sim::bandCeiling(oc, track, truth);
        QCOMPARE(c.score.tp, 4LL);
        QCOMPARE(c.score.fp, 0LL);
        QCOMPARE(c.score.f1, 1.0);
        // A noise point inside the signal (0.5 between returns at -1, 0, 1, 2): every band that
        // takes all four returns takes it too, 2·4/(8 + 1) = 0.889; the best band without it holds
        // two returns (0 and -1, or 1 and 2), 2·2/(4 + 2) = 0.667.
        truth = {1, 1, 0, 1, 1, 0, 0};
        oc = {-1, 0, 0.5, 1, 2, 11, -30};
        c = sim::bandCeiling(oc, track, truth);
        QCOMPARE(c.score.tp, 4LL);
        QCOMPARE(c.score.fp, 1LL);
        QVERIFY(std::fabs(c.score.f1 - 8.0 / 9.0) < 1e-12);
        const sim::DetectionScore s = sim::scoreDetection({1, 1, 1, 0, 0, 0, 1}, {1, 1, 0, 1, 0, 0, 0});
        QCOMPARE(s.tp, 2LL);
        QCOMPARE(s.fp, 2LL);
        QCOMPARE(s.fn, 1LL);
    }

    void screeningReachesTheCeiling_data() {
        QTest::addColumn<int>("index");
        for (int i = 0; i < int(sizeof kCases / sizeof kCases[0]); ++i) QTest::newRow(kCases[i].name) << i;
    }
    void screeningReachesTheCeiling() {
        QFETCH(int, index);
        const Case& c = kCases[index];
        const int seeds = qEnvironmentVariableIsSet("LWB_CEILING_SEEDS") ? qEnvironmentVariableIntValue("LWB_CEILING_SEEDS") : 3;
        double sumF1 = 0, sumCeil = 0, worstGap = -1;
        for (int seed = 1; seed <= seeds; ++seed) {
            const sim::SlrSimParams p = paramsOf(c);
            const sim::SlrSimPass s = sim::simulateSlrPass(p, static_cast<uint64_t>(seed));
            QVERIFY2(s.ok, s.error.c_str());
            PassData pass;
            pass.t = s.epochS;
            pass.oc = s.ocS;
            pass.tof = s.tofS;
            pass.altitudeKm = p.altitudeKm;
            SlrParams params = commandDefaults();
            if (qEnvironmentVariableIsSet("LWB_CEILING_BEFORE")) params.postfit.noiseBand = params.postfit.takeBand = false;
            const PassRunResult r = runPass(pass, params);
            QVERIFY2(r.ok, r.error.c_str());
            const std::vector<uint8_t>& kept = r.postOk ? r.post.kept : r.accepted;
            const sim::DetectionScore screen = sim::scoreDetection(r.accepted, s.isSignal);
            const sim::DetectionScore fin = sim::scoreDetection(kept, s.isSignal);
            const sim::BandCeiling ceil = sim::bandCeiling(s.ocS, s.trackOcS, s.isSignal);
            const double gap = ceil.score.f1 - fin.f1;
            qInfo("%-24s seed %d: %6zu points %5lld signal  screening F1 %.4f  kept P %.4f R %.4f F1 %.4f  ceiling %.4f "
                  "(±%.2f σ)  gap %+.4f%s",
                  c.name, seed, s.epochS.size(), s.signalCount, screen.f1, fin.precision, fin.recall, fin.f1,
                  ceil.score.f1, ceil.halfWidthS / std::max(ceil.signalSigmaS, 1e-18), gap,
                  r.doubt.empty() ? "" : (" doubt: " + r.doubt).c_str());
            if (qEnvironmentVariableIsSet("LWB_CEILING_DEBUG")) {
                long long missedByScreen = 0, cutByPost = 0, inBandNotAccepted = 0;
                for (size_t i = 0; i < s.isSignal.size(); ++i) {
                    if (!s.isSignal[i]) continue;
                    if (!r.accepted[i]) {
                        ++missedByScreen;
                        if (r.postOk && std::fabs(r.post.residuals[i]) <= 3 * r.post.sigmaS) ++inBandNotAccepted;
                    } else if (!kept[i]) {
                        ++cutByPost;
                    }
                }
                qInfo("   returns missed by the screening %lld (%lld of them within 3 sigma of the trend), cut by the post-fit "
                      "%lld; band %.1f ps, signal sigma %.1f ps, kept RMS %.1f ps, noise density %.3g /ns",
                      missedByScreen, inBandNotAccepted, cutByPost, r.post.noiseBandS * 1e12, r.post.signalSigmaS * 1e12,
                      r.post.sigmaS * 1e12, r.post.noiseDensity * 1e-9);
            }
            sumF1 += fin.f1;
            sumCeil += ceil.score.f1;
            worstGap = std::max(worstGap, gap);
        }
        qInfo("%-24s mean F1 %.4f ceiling %.4f, worst gap %+.4f", c.name, sumF1 / seeds, sumCeil / seeds, worstGap);
        QVERIFY2(worstGap <= 0.015, qPrintable(QString("%1: F1 %2 below its ceiling").arg(c.name).arg(worstGap)));
    }

    // The points the post-fit's band takes are a class of their own, the same in the run, the
    // CLI's CSV and its summary: "band" rows exactly where the run took them, accepted exactly
    // where the class is not noise, and the summary's noise count the points not accepted (it
    // had counted the band's points both as accepted and as noise). On the low-SNR pass of
    // seed 6 the screening and the track following leave a return that the band takes (seed 7's
    // two are followed since the walk no longer ends where its band expects 5 noise points).
    void bandPointsAreAClassEverywhere() {
        QTemporaryDir dir;
        const QString frd = dir.path() + "/day6.frd";
        lwbtest::CliRun sim = lwbtest::runCli({"simulate", "slr", "--kind", "daylight", "--day", "--seed", "6", "-q", frd});
        QVERIFY2(sim.exitCode == 0, qPrintable(sim.err));
        const PassInputResult in = loadPass(frd.toStdString(), 0, PassInputParams{});
        QVERIFY2(in.ok, in.error.c_str());
        PassSettings set;
        std::string err;
        QVERIFY2(passSettings(in.pass, commandDefaults(), nullptr, "", nullptr, &set, &err), err.c_str());
        const PassRunResult r = runPass(in.pass, set.params);
        QVERIFY2(r.ok && r.postOk, r.error.c_str());
        QVERIFY2(r.bandTaken > 0, "the low-SNR pass of seed 6 has a return the image and the following left within the band");
        QCOMPARE(r.classes.size(), in.pass.t.size());
        long long band = 0;
        for (size_t i = 0; i < r.classes.size(); ++i) {
            band += r.classes[i] == PointClass::Band;
            QCOMPARE(bool(r.accepted[i]), r.classes[i] != PointClass::Noise);
            if (r.classes[i] == PointClass::Band) QCOMPARE(r.screen.pointClass[i], PointClass::Noise);
        }
        QCOMPARE(band, r.bandTaken);
        const QString csv = dir.path() + "/day6.csv";
        lwbtest::CliRun cli = lwbtest::runCli({"slr", frd, "-o", csv});
        QVERIFY2(cli.exitCode == 0, qPrintable(cli.err));
        const QList<QByteArray> rows = lwbtest::readAll(csv).split('\n');
        long long csvBand = 0;
        for (qsizetype k = 1; k < rows.size(); ++k) {
            const QList<QByteArray> f = rows[k].split(',');
            if (f.size() < 4) continue;
            const size_t i = size_t(k - 1);
            QVERIFY(i < r.classes.size());
            QCOMPARE(f[3].toStdString(), std::string(pointClassName(r.classes[i])));
            csvBand += f[3] == "band";
        }
        QCOMPARE(csvBand, r.bandTaken);
        QVERIFY2(cli.err.contains(QString("accepted %1 (").arg(r.acceptedCount)) &&
                     cli.err.contains(QString(" + %1 within the post-fit's band), noise %2\n").arg(r.bandTaken).arg(qulonglong(in.pass.t.size() - r.acceptedCount))),
                 qPrintable(cli.err));
    }

    // The shared real passes with a noise floor, against the station's own filter flags (2 data,
    // 1 noise). Their ceiling: the best band about the station's own track (the post-fit's trend
    // through the station's data points, no rejection) reproducing the station's flags. The
    // issue's noisy Jason-class pass reached F1 0.951 of 0.982.
    void realPassesAgainstTheStationsCeiling_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("pass");
        QTest::newRow("JASON1 7080 2007-12-20") << "7080_JASON1_crd_071220_2033_0.frd" << 0;
        QTest::newRow("STELLA 7080 2007-12-20") << "7080_STELLA_crd_071220_2128_0.frd" << 0;
        QTest::newRow("Beacon-C 7080 2007-12-20") << "7080_Beacon-C_crd_071220_1715_0.frd" << 0;
        for (int k = 0; k < 3; ++k) QTest::newRow(qPrintable(QString("beaconc 2007-05-11 pass %1").arg(k + 1))) << "beaconc_20070511.frd" << k;
    }
    void realPassesAgainstTheStationsCeiling() {
        QFETCH(QString, file);
        QFETCH(int, pass);
        if (!lwbtest::haveShared("slr/" + file)) QSKIP("shared data not found");
        const PassInputResult in = loadPass(lwbtest::sharedPath("slr/" + file).toStdString(), pass, PassInputParams{});
        QVERIFY2(in.ok, in.error.c_str());
        const PassData& d = in.pass;
        PassSettings set;
        std::string err;
        QVERIFY2(passSettings(d, commandDefaults(), nullptr, "", nullptr, &set, &err), err.c_str());
        const PassRunResult r = runPass(d, set.params);
        QVERIFY2(r.ok && r.postOk, (r.error + r.postNote).c_str());
        std::vector<uint8_t> truth(d.t.size());
        for (size_t i = 0; i < truth.size(); ++i) truth[i] = d.stationFlag[i] == 2;
        PostfitParams own = postfitForPass(set.params.postfit, nullptr);
        own.rejectSigma = 0;
        own.normalPoints = false;
        const PostfitResult track = postfit(d.t, d.oc, truth, d.tof, own);
        QVERIFY2(track.ok, track.error.c_str());
        const sim::BandCeiling ceil = sim::bandCeiling(track.residuals, std::vector<double>(d.t.size(), 0.0), truth);
        const sim::DetectionScore screen = sim::scoreDetection(r.accepted, truth);
        const sim::DetectionScore fin = sim::scoreDetection(r.post.kept, truth);
        if (qEnvironmentVariableIsSet("LWB_CEILING_DEBUG"))
            for (size_t i = 0; i < d.t.size(); ++i)
                if (bool(r.post.kept[i]) != bool(truth[i]))
                    qInfo("  %s at %.1f s: residual from the station's track %.1f ps, from ours %.1f ps (band %.1f ps, σ %.1f)",
                          truth[i] ? "missed" : "kept noise", d.t[i], track.residuals[i] * 1e12, r.post.residuals[i] * 1e12,
                          r.post.limitS * 1e12, r.post.sigmaS * 1e12);
        qInfo("%s: %zu points, %lld data: screening F1 %.4f, kept P %.4f R %.4f F1 %.4f, ceiling %.4f (±%.2f σ), gap %+.4f",
              qPrintable(QString(QTest::currentDataTag())), d.t.size(), ceil.score.tp + ceil.score.fn, screen.f1,
              fin.precision, fin.recall, fin.f1, ceil.score.f1, ceil.halfWidthS / ceil.signalSigmaS, ceil.score.f1 - fin.f1);
        // Tolerance 0.02 on real passes (0.015 on simulated ones): here the ceiling's track is
        // itself a fit through the station's points, not a truth (JASON1: a point 2 ps from our
        // trend that the station flagged noise is 3.4 ns from that fit), and one pass of 59 data
        // points moves F1 by 0.017 a point.
        QVERIFY2(ceil.score.f1 - fin.f1 <= 0.02, qPrintable(QString("F1 %1 of %2").arg(fin.f1).arg(ceil.score.f1)));
    }
};

QTEST_GUILESS_MAIN(TestSlrCeiling)
#include "test_slr_ceiling.moc"
