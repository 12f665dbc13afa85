// Paper 000's experiment on the simulator's synthetic ground (red-spectrum noise, roads, field
// edges, buildings), with the targets for the default method (full Gaussian: Wu f·ln f + xy term
// + Guo + LM), and the verdict targets. The harder photo ground (issue 14) has its own test,
// test_footprint_photo.cpp. Counts: 300 shots per scene, seed 1 (the same seed as
// docs/footprint-accuracy.md, which uses 2000 shots); a fixed seed keeps the test deterministic,
// it was not chosen to pass.
#include <QtTest>

#include "core/sim/footprint_eval.hpp"
#include "footprint_cases.hpp"
#include "test_support.hpp"

using namespace lwb::core;
using namespace lwb::core::sim;

namespace {
const EvalStats& statsFor(const std::vector<EvalStats>& all, Scene s) {
    for (const auto& st : all)
        if (st.scene == s) return st;
    static EvalStats none;
    return none;
}
}  // namespace

class TestFootprintAccuracy : public QObject {
    Q_OBJECT
    std::vector<EvalStats> m_normal;

private slots:
    void initTestCase() {
        MethodVariant def;
        QVERIFY(findVariant("gauss", &def));
        EvalParams ep;
        ep.countPerScene = 300;
        ep.seed = 1;
        ep.sim.ground = GroundSource::Synthetic;
        m_normal = evaluateFootprint(ep, {def});
        QCOMPARE(m_normal.size(), size_t(5));
        qInfo("\n%s", evalTableMarkdown(m_normal).c_str());
    }

    void meanRadialErrorTargets_data() { lwbtest::addClassTargetRows(); }
    void meanRadialErrorTargets() {
        QFETCH(int, scene);
        QFETCH(double, target);
        const EvalStats& s = statsFor(m_normal, Scene(scene));
        QVERIFY(s.fitted >= 0.95 * s.n);  // nearly every normal shot gets a centre
        QVERIFY2(s.meanErr <= target, qPrintable(QString("mean radial error %1 px").arg(s.meanErr)));
        // No catastrophic outliers.
        QVERIFY2(s.p99Err < 1.0, qPrintable(QString("p99 %1 px").arg(s.p99Err)));
    }

    void flatBackgroundReachesTheCramerRaoBound() {
        // RMS radial error against the RMS of the per-shot bound (photon + read noise, exact truth):
        // E|err|² ≥ E[CRLB²], so this ratio is ≥ 1 for an unbiased estimator; ≤ 1.2 is the target.
        const EvalStats& s = statsFor(m_normal, Scene::Flat);
        QVERIFY(s.meanCrlb > 0);
        const double ratio = s.rmsErr / s.meanCrlb;
        qInfo("flat: RMS %.4f px, CRLB %.4f px, ratio %.3f", s.rmsErr, s.meanCrlb, ratio);
        QVERIFY2(ratio <= 1.2, qPrintable(QString("ratio %1").arg(ratio)));
        QVERIFY2(ratio >= 0.85, "better than the bound: the bound or the error is computed wrongly");
    }

    void normalSpotsAreMarkedGood_data() {
        QTest::addColumn<int>("scene");
        QTest::newRow("weak") << int(Scene::Weak);
        QTest::newRow("moderate") << int(Scene::Moderate);
        QTest::newRow("night") << int(Scene::Night);
    }
    void normalSpotsAreMarkedGood() {
        QFETCH(int, scene);
        const EvalStats& s = statsFor(m_normal, Scene(scene));
        const double frac = double(s.good) / s.n;
        QVERIFY2(frac >= 0.90, qPrintable(QString("good %1 of %2").arg(s.good).arg(s.n)));
    }

    void noiseClassFollowsTheGround() {
        // Truth: the class of the noise-free ground's median over the ROI (where its histogram
        // concentrates). The estimate cannot see the ground under the spot and carries photon
        // noise and the spot's wings: an error of ~50 DN. Near a band edge that flips the class,
        // so the narrow moderate band (4000–4500 DN, 500 DN wide) is held to 85 % agreement and
        // the open-ended bands to 97 %.
        for (Scene sc : {Scene::Weak, Scene::Moderate, Scene::Strong, Scene::Night}) {
            const EvalStats& s = statsFor(m_normal, sc);
            const double need = sc == Scene::Moderate ? 0.85 : 0.97;
            qInfo("%s: noise class right for %d of %d", sceneName(sc), s.classCorrect, s.n);
            QVERIFY2(s.classCorrect >= need * s.n, qPrintable(QString("%1: %2 of %3 classified right")
                                                                  .arg(sceneName(sc)).arg(s.classCorrect).arg(s.n)));
        }
    }

    void doubtfulCasesAreNotMarkedGood_data() { lwbtest::addDoubtfulCaseRows(); }
    void doubtfulCasesAreNotMarkedGood() {
        QFETCH(int, spotCase);
        const lwbtest::CaseCounts k = lwbtest::doubtfulCaseCounts(SpotCase(spotCase), 100, GroundSource::Synthetic);
        const int good = k.good, n = k.n, rejected = k.rejected;
        QVERIFY2(good <= 0.05 * n, qPrintable(QString("%1 of %2 doubtful shots marked good").arg(good).arg(n)));
        if (SpotCase(spotCase) == SpotCase::NoSpot)  // nothing to fit: rejected, not just doubtful
            QVERIFY2(rejected >= 0.9 * n, qPrintable(QString("%1 of %2 rejected").arg(rejected).arg(n)));
    }
};

QTEST_GUILESS_MAIN(TestFootprintAccuracy)
#include "test_footprint_accuracy.moc"
