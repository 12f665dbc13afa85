// Issue 32: uncertainty_px from the shot's own ground, checked on ground it was not calibrated
// on. Its one calibrated factor (gauss.uncertainty_scale) was set on the photo simulator cut from
// one photograph only (aero1, eval seed 11); here the coverage is measured on the other
// photograph (aero3), on the synthetic ground, on fractal 1/f^β ground with sharp edges and
// water (β 1.5-3.5: a spectrum none of the others has) and on the photographs cut finer and
// coarser in mixed colour bands, each in the four noise classes. A 1-σ radial bound must cover
// 63.2 % (1 − e⁻¹); the 95 % radius (2.45 σ per axis = 1.7308 u) 95 %.
//
// Sample size: kShots shots per class and family. The binomial standard error of a 63.2 %
// coverage is √(0.632·0.368/n) = 2.2 % at n = 500, so the 58-68 % band is ±2.3 s.e.; of a 95 %
// coverage 1.0 %, so 93-97 % is ±2 s.e. The seeds are fixed: the result is deterministic,
// and it fails when the coverage leaves the band (e.g. the quick estimate of before issue 32
// covers 36-54 % on fractal ground: test quickEstimateMissesOnFractalGround).
#include <QtTest>

#include <cmath>

#include "core/footprint/pipeline.hpp"
#include "core/sim/footprint_eval.hpp"
#include "core/sim/footprint_sim.hpp"
#include "core/sim/terrain_photo.hpp"

using namespace lwb::core;
using namespace lwb::core::footprint;
using namespace lwb::core::sim;

namespace {
constexpr int kShots = 500;
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

void checkCoverage(const Family& f, const std::vector<EvalStats>& stats) {
    QCOMPARE(int(stats.size()), 4);
    for (const EvalStats& s : stats) {
        QVERIFY(s.fitted > 0.9 * s.n);
        const double c1 = double(s.covered) / s.fitted, c95 = double(s.covered95) / s.fitted;
        qInfo("%-10s %-8s n %d: P(|err| < u) = %.3f, P(|err| < 1.73 u) = %.3f, mean error %.3f px", f.name,
              sceneName(s.scene), s.fitted, c1, c95, s.meanErr);
        QVERIFY2(c1 >= 0.58 && c1 <= 0.68,
                 qPrintable(QString("%1 %2: coverage %3").arg(f.name).arg(sceneName(s.scene)).arg(c1)));
        QVERIFY2(c95 >= 0.93 && c95 <= 0.97,
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
        QTest::newRow("synthetic") << 3;
    }
    void heldOutFamilies() {
        QFETCH(int, family);
        const Family families[] = {{"fractal", GroundSource::Fractal, -1},
                                   {"photo-cuts", GroundSource::PhotoCuts, -1},
                                   {"aero3", GroundSource::Photo, 1},
                                   {"synthetic", GroundSource::Synthetic, -1}};
        const Family& f = families[family];
        if ((f.ground == GroundSource::Photo || f.ground == GroundSource::PhotoCuts) && !terrainPhotos().ok)
            QSKIP(terrainPhotos().error.c_str());
        checkCoverage(f, evaluate(f, FootprintParams{}, kShots, 3));
    }

    // The quick estimate (uncertainty_from_ground off: the texture-shift term calibrated on the
    // photo simulator) is what issue 32 found optimistic on other ground: on fractal ground it
    // leaves the band, so the check above can fail.
    void quickEstimateMissesOnFractalGround() {
        FootprintParams quick;
        quick.gauss.uncertaintyFromGround = false;
        const std::vector<EvalStats> s = evaluate({"fractal", GroundSource::Fractal, -1}, quick, 300, 3);
        QCOMPARE(int(s.size()), 4);
        int outside = 0;
        for (const EvalStats& st : s) {
            const double c1 = double(st.covered) / st.fitted;
            qInfo("quick estimate, fractal %-8s: P(|err| < u) = %.3f", sceneName(st.scene), c1);
            outside += c1 < 0.58 || c1 > 0.68;
        }
        QVERIFY(outside >= 2);
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
