// Issue 32: uncertainty_px from the shot's own ground, checked on ground it was not calibrated
// on. Its calibrated factors (gauss.uncertainty_scale, gauss.radius95_factor) were set on the
// photo simulator cut from one photograph only (aero1, eval seed 11); here the coverage is
// measured on the other photograph (aero3), on fractal 1/f^β ground with sharp edges and water
// (β 1.5-3.5: a spectrum the photographs do not have) and on the photographs cut finer and
// coarser in mixed colour bands, each in the four noise classes, on eval seed 3. A 1-σ radial
// bound must cover 63.2 % (1 − e⁻¹), radius95_px 95 %.
//
// Sample size: kShots shots per class and family. The binomial standard error of a 63.2 %
// coverage is √(0.632·0.368/n) = 1.5 % at n = 1000, so the 58-68 % band is ±3.3 s.e.; of a 95 %
// coverage 0.7 %, so 93-97 % is ±2.9 s.e. (At n = 500 one class, fractal weak, read 92.4 % for
// the radius95 that holds 94.4 % at n = 1000: the sample was too small for this band.) The seeds are fixed, so the result is deterministic;
// the test fails when a coverage leaves its band (the quick estimate of before issue 32 does on
// these families: test quickEstimateMissesTheBand). The synthetic ground (the simulator before
// issue 14) is held out too but not in the band: there uncertainty_px is conservative (docs).
#include <QtTest>

#include <cmath>
#include <string>

#include "core/footprint/pipeline.hpp"
#include "core/sim/footprint_eval.hpp"
#include "core/sim/footprint_sim.hpp"
#include "core/sim/terrain_photo.hpp"

using namespace lwb::core;
using namespace lwb::core::footprint;
using namespace lwb::core::sim;

namespace {
constexpr int kShots = 1000;
constexpr double kLevel = 0.632;  // 1 − e⁻¹

struct Family {
    const char* name;
    GroundSource ground;
    int photo;  // -1 = both photographs
};

std::vector<EvalStats> evaluate(const Family& f, const FootprintParams& params, int count, uint64_t seed) {
    EvalParams ep;
    ep.countPerScene = count;
    ep.seed = seed;
    ep.scenes = {Scene::Weak, Scene::Moderate, Scene::Strong, Scene::Night};
    ep.sim.ground = f.ground;
    ep.sim.photo = f.photo;
    std::string err;
    std::vector<EvalStats> s = evaluateFootprint(ep, {{"gauss", params}}, nullptr, &err);
    if (s.size() != 4) qWarning("%s", err.c_str());
    return s;
}

// lo1..hi1: the band of P(|err| < u); lo95..hi95 that of P(|err| < radius95_px).
void checkCoverage(const Family& f, const std::vector<EvalStats>& stats, double lo1 = 0.58, double hi1 = 0.68,
                   double lo95 = 0.93, double hi95 = 0.97) {
    QCOMPARE(int(stats.size()), 4);
    for (const EvalStats& s : stats) {
        QVERIFY(s.fitted > 0.9 * s.n);
        const double c1 = double(s.covered) / s.fitted, c95 = double(s.covered95) / s.fitted;
        qInfo("%-10s %-8s n %d: P(|err| < u) = %.3f, P(|err| < radius95) = %.3f, mean error %.3f px", f.name,
              sceneName(s.scene), s.fitted, c1, c95, s.meanErr);
        QVERIFY2(c1 >= lo1 && c1 <= hi1,
                 qPrintable(QString("%1 %2: coverage %3").arg(f.name).arg(sceneName(s.scene)).arg(c1)));
        QVERIFY2(c95 >= lo95 && c95 <= hi95,
                 qPrintable(QString("%1 %2: 95 %% coverage %3").arg(f.name).arg(sceneName(s.scene)).arg(c95)));
    }
}
}  // namespace

class TestFootprintUncertainty : public QObject {
    Q_OBJECT

private slots:
    void heldOutFamilies_data() {
        QTest::addColumn<int>("family");
        QTest::newRow("fractal") << 0;
        QTest::newRow("photo-cuts") << 1;
        QTest::newRow("aero3") << 2;
    }
    void heldOutFamilies() {
        QFETCH(int, family);
        const Family families[] = {{"fractal", GroundSource::Fractal, -1},
                                   {"photo-cuts", GroundSource::PhotoCuts, -1},
                                   {"aero3", GroundSource::Photo, 1}};
        const Family& f = families[family];
        if ((f.ground == GroundSource::Photo || f.ground == GroundSource::PhotoCuts) && !terrainPhotos().ok)
            QSKIP(terrainPhotos().error.c_str());
        checkCoverage(f, evaluate(f, FootprintParams{}, kShots, 3));
    }

    // Synthetic ground: held out, conservative (the robust fit does better there than the
    // sandwich says), never optimistic.
    void syntheticGroundIsNotOptimistic() {
        checkCoverage({"synthetic", GroundSource::Synthetic, -1}, evaluate({"synthetic", GroundSource::Synthetic, -1},
                                                                           FootprintParams{}, 200, 3),
                      0.58, 0.85, 0.93, 1.0);
    }

    // The quick estimate (uncertainty_from_ground off: the texture-shift term calibrated on the
    // photo simulator, with 1.7308 u as its 95 % radius) is what issue 32 found optimistic on
    // other ground: it leaves the bands, so the checks above can fail.
    void quickEstimateMissesTheBand() {
        FootprintParams quick;
        quick.gauss.uncertaintyFromGround = false;
        int outside = 0;
        for (const Family& f : {Family{"fractal", GroundSource::Fractal, -1}, Family{"photo-cuts", GroundSource::PhotoCuts, -1}}) {
            if (f.ground == GroundSource::PhotoCuts && !terrainPhotos().ok) continue;
            const std::vector<EvalStats> s = evaluate(f, quick, 200, 3);
            QCOMPARE(int(s.size()), 4);
            for (const EvalStats& st : s) {
                const double c1 = double(st.covered) / st.fitted, c95 = double(st.covered95) / st.fitted;
                qInfo("quick estimate, %s %-8s: P(|err| < u) = %.3f, P(|err| < 1.73 u) = %.3f", f.name,
                      sceneName(st.scene), c1, c95);
                outside += c1 < 0.58 || c1 > 0.68 || c95 < 0.93 || c95 > 0.97;
            }
        }
        QVERIFY(outside >= 4);
    }

    // The covariance terms are reported and make uncertainty_px; a shot whose uncertainty exceeds
    // verdict.max_uncertainty_px is doubtful with that reason.
    void uncertaintyAboveTheLimitIsDoubtful() {
        FootprintSimParams sp;
        sp.scene = Scene::Weak;
        sp.ground = GroundSource::Fractal;
        int checked = 0;
        for (uint64_t seed = 1; seed < 40 && checked < 5; ++seed) {
            const FootprintSimShot shot = simulateFootprint(sp, seed);
            cv::Mat roi;
            shot.image.convertTo(roi, CV_32F);
            FootprintParams p;
            const FootprintResult r = processRoi(roi, p);
            if (!r.ok || r.verdict != Verdict::Good) continue;
            ++checked;
            QVERIFY(std::isfinite(r.fit.covXX) && r.fit.covXX > 0 && r.fit.covYY > 0);
            QVERIFY(r.fit.covXY * r.fit.covXY < r.fit.covXX * r.fit.covYY);
            QVERIFY(std::fabs(r.fit.uncertaintyPx - std::sqrt(r.fit.covXX + r.fit.covYY)) < 1e-12);
            QVERIFY(std::fabs(r.fit.radius95Px - p.gauss.radius95Factor * r.fit.uncertaintyPx) < 1e-12);
            QVERIFY(r.fit.uncertaintyPx < p.verdict.maxUncertaintyPx);
            p.verdict.maxUncertaintyPx = 0.9 * r.fit.uncertaintyPx;
            FootprintResult again = r;
            judgeResult(&again, roi.cols, roi.rows, p.verdict);
            QCOMPARE(again.verdict, Verdict::Doubtful);
            bool named = false;
            for (const std::string& why : again.reasons) named |= why.rfind("uncertainty_px", 0) == 0;
            QVERIFY(named);
            p.verdict.maxUncertaintyEnabled = false;
            judgeResult(&again, roi.cols, roi.rows, p.verdict);
            QCOMPARE(again.verdict, Verdict::Good);
        }
        QCOMPARE(checked, 5);
    }
};

QTEST_GUILESS_MAIN(TestFootprintUncertainty)
#include "test_footprint_uncertainty.moc"
