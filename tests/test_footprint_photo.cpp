// Issue 14's targets on the harder simulator: real aerial photographs as ground (opencv-doc's
// aero1/aero3 cut at random zoom, rotation, flip and band), night texture 10–40 DN RMS. 2000
// shots per class with the default method, seed 1 (the figures in docs/footprint-accuracy.md);
// the uncertainty scales were calibrated on seed 11, so the coverage checked here is out of
// sample. Skipped when the photographs are not installed (.ci/install-deps installs them).
#include <QtTest>

#include "core/footprint/pipeline.hpp"
#include "core/sim/footprint_eval.hpp"
#include "core/sim/footprint_sim.hpp"
#include "core/common/rng.hpp"
#include "core/sim/texture_bound.hpp"
#include "core/sim/terrain_photo.hpp"
#include "footprint_cases.hpp"
#include "test_support.hpp"

using namespace lwb::core;
using namespace lwb::core::sim;

namespace {
const EvalStats* statsFor(const std::vector<EvalStats>& all, Scene s) {
    for (const auto& st : all)
        if (st.scene == s) return &st;
    return nullptr;
}
}  // namespace

class TestFootprintPhoto : public QObject {
    Q_OBJECT
    std::vector<EvalStats> m_normal;

private slots:
    void initTestCase() {
        if (!terrainPhotos().ok) QSKIP(terrainPhotos().error.c_str());
        MethodVariant def;
        QVERIFY(findVariant("gauss", &def));
        EvalParams ep;
        ep.countPerScene = 2000;
        ep.seed = 1;
        ep.scenes = {Scene::Weak, Scene::Moderate, Scene::Strong, Scene::Night};
        std::string err;
        m_normal = evaluateFootprint(ep, {def}, nullptr, &err);
        QVERIFY2(m_normal.size() == 4, err.c_str());
        qInfo("\n%s", evalTableMarkdown(m_normal).c_str());
    }

    void groundIsPhotographed() {
        FootprintSimParams sp;
        sp.scene = Scene::Strong;
        const FootprintSimShot shot = simulateFootprint(sp, 5);
        QVERIFY(shot.truth.groundPhoto);
        QVERIFY(shot.truth.groundNote.find("aero") == 0);
        // Scaled to the class: texture RMS within the strong range (flat patches less).
        QVERIFY(shot.truth.textureRms > 0 && shot.truth.textureRms <= 420);
        sp.scene = Scene::Night;
        const SceneLevels night = sceneLevels(Scene::Night, GroundSource::Photo);
        QCOMPARE(night.textureMin, 10.0);
        QCOMPARE(night.textureMax, 40.0);
    }

    void meanRadialError_data() { lwbtest::addClassTargetRows(); }
    void meanRadialError() {
        QFETCH(int, scene);
        QFETCH(double, target);
        const EvalStats* s = statsFor(m_normal, Scene(scene));
        QVERIFY(s && s->n == 2000);
        QVERIFY(s->fitted >= 0.99 * s->n);
        if (Scene(scene) == Scene::Night)
            QEXPECT_FAIL("", "night on photo ground: 0.062 px (seed 1, 2000 shots; photon CRLB 0.020). The 10-40 DN "
                             "texture, not photons, limits it: with the texture as Gaussian noise of the ground's "
                             "autocorrelation the bound is 0.062 px (nightTargetIsBelowTheTextureBound) and the fit "
                             "is at it; 0.05 px is 19 % below that bound", Continue);
        QVERIFY2(s->meanErr <= target, qPrintable(QString("mean radial error %1 px").arg(s->meanErr)));
    }

    void everyVisibleSpotIsPositioned() {
        // Visible: amplitude at least 5× the ground's texture RMS (every normal shot of the
        // simulator is). Positioned: good or doubtful, not rejected.
        for (Scene sc : {Scene::Weak, Scene::Moderate, Scene::Strong, Scene::Night}) {
            const EvalStats* s = statsFor(m_normal, sc);
            QVERIFY(s && s->visible > 0.99 * s->n);
            qInfo("%s: %d of %d visible spots positioned", sceneName(sc), s->visibleFitted, s->visible);
            QVERIFY2(s->visibleFitted == s->visible, qPrintable(QString("%1: %2 of %3 visible spots positioned")
                                                                    .arg(sceneName(sc)).arg(s->visibleFitted)
                                                                    .arg(s->visible)));
        }
    }

    void everyVisibleStrongSpotIsPositionedOnOtherSeeds() {
        // Seeds other than the test's own: on seeds 2, 5, 7, 11 and 12 the fit before
        // 2026-11-26 left one or two clearly visible strong-ground spots of 2000 without a
        // position (the ROI's σ, and the ring's, inflated by large bright and dark fields; or a
        // domain joined to brighter ground through a neck). Strong ground, 2000 shots each.
        MethodVariant def;
        QVERIFY(findVariant("gauss", &def));
        for (uint64_t seed : {2, 5, 7, 11, 12}) {
            EvalParams ep;
            ep.countPerScene = 2000;
            ep.seed = seed;
            ep.scenes = {Scene::Strong};
            std::string err;
            const std::vector<EvalStats> st = evaluateFootprint(ep, {def}, nullptr, &err);
            QVERIFY2(st.size() == 1, err.c_str());
            QVERIFY(st[0].visible > 0.99 * st[0].n);
            QVERIFY2(st[0].visibleFitted == st[0].visible,
                     qPrintable(QString("seed %1: %2 of %3 visible spots positioned")
                                    .arg(seed).arg(st[0].visibleFitted).arg(st[0].visible)));
        }
    }

    void spotJoinedToBrighterGroundIsFittedFromItsCore() {
        // `simulate footprint --seed 5 --scene strong`, shot 1778: a clear spot (3635 DN on
        // ground of 407 DN RMS) whose domain runs through a neck into brighter ground at the
        // ROI's lower left; the domain's log-intensity is a saddle and LM from its moments ran
        // 3.6 px towards the bright ground. Fitted from the pixels joined to the peak above 30 %
        // of its height, the spot is positioned, doubtful, within 0.1 px of the truth.
        FootprintSimParams sp;
        sp.scene = Scene::Strong;
        const FootprintSimShot shot = simulateFootprint(sp, Rng::mix(5, 1778));
        QVERIFY(shot.truth.hasSpot);
        cv::Mat roi;
        shot.image.convertTo(roi, CV_32F);
        footprint::FootprintParams p;
        const footprint::FootprintResult r = footprint::processRoi(roi, p);
        QVERIFY2(r.fit.ok, r.fit.error.c_str());
        QCOMPARE(int(r.verdict), int(footprint::Verdict::Doubtful));
        QVERIFY(!r.startNote.empty());
        const double err = std::hypot(r.fit.x - shot.truth.x, r.fit.y - shot.truth.y);
        QVERIFY2(err < 0.1, qPrintable(QString("error %1 px").arg(err)));
        // Without the core fit (coreFraction 0) the same shot gets no position: the case is real.
        p.gauss.coreFraction = 0;
        const footprint::FootprintResult old = footprint::processRoi(roi, p);
        QVERIFY(!old.fit.ok || old.verdict == footprint::Verdict::Rejected);
    }

    void nightTargetIsBelowTheTextureBound() {
        // Why night stays at 0.062 px: with the ground's texture counted as noise (a Gaussian
        // field with the photo ground's ensemble autocorrelation, 1000 patches) the Cramér–Rao
        // bound of the centre over the test's first 200 night shots is above the 0.05 px target,
        // and the fit is within 10 % of it. (A bound for that model, not for every patch: real
        // patches differ from the ensemble, and on those 200 shots the fit is 6 % below it.)
        // Without the texture the same computation gives the photon bound of the eval table.
        const GroundCorrelation rho = photoGroundCorrelation(1000, 23, 77);
        QVERIFY2(rho.ok, rho.error.c_str());
        QVERIFY(rho.at(1, 0) > 0.5 && rho.at(1, 0) < 1);  // real ground: strongly correlated neighbours
        double bound = 0, white = 0;
        int n = 0;
        for (int i = 0; i < 200; ++i) {
            FootprintSimParams sp;
            sp.scene = Scene::Night;
            const FootprintSimShot shot = simulateFootprint(sp, Rng::mix(1, uint64_t(Scene::Night) * 1000003ULL + i));
            const TextureBound b = textureBound(shot.truth, shot.image.cols, shot.image.rows, sp.camera, rho);
            QVERIFY(b.ok);
            bound += b.radialPx;
            white += b.whiteRadialPx;
            ++n;
        }
        bound /= n;
        white /= n;
        const EvalStats* s = statsFor(m_normal, Scene::Night);
        QVERIFY(s);
        qInfo("night: bound with texture %.4f px, photons only %.4f px; the fit %.4f px", bound, white, s->meanErr);
        QVERIFY2(white > 0.015 && white < 0.025, qPrintable(QString("photon bound %1 px").arg(white)));
        QVERIFY2(bound > 0.05, qPrintable(QString("texture bound %1 px").arg(bound)));
        QVERIFY2(s->meanErr <= 1.1 * bound, qPrintable(QString("fit %1 px, bound %2 px").arg(s->meanErr).arg(bound)));
    }

    void uncertaintyCoversTheTruthAtItsLevel() {
        // uncertainty_px = sqrt(var x + var y): for a 2-D Gaussian error P(|err| < u) = 1 − e⁻¹.
        const double level = 1 - std::exp(-1.0);
        for (Scene sc : {Scene::Weak, Scene::Moderate, Scene::Strong, Scene::Night}) {
            const EvalStats* s = statsFor(m_normal, sc);
            QVERIFY(s && s->fitted > 0);
            const double cover = double(s->covered) / s->fitted;
            qInfo("%s: P(|err| < uncertainty_px) = %.3f (level %.3f)", sceneName(sc), cover, level);
            QVERIFY2(std::fabs(cover - level) <= 0.05,
                     qPrintable(QString("%1: coverage %2").arg(sceneName(sc)).arg(cover)));
        }
    }

    void doubtfulCasesAreNotMarkedGood_data() { lwbtest::addDoubtfulCaseRows(); }
    void doubtfulCasesAreNotMarkedGood() {
        QFETCH(int, spotCase);
        const lwbtest::CaseCounts k = lwbtest::doubtfulCaseCounts(SpotCase(spotCase), 150, GroundSource::Photo);
        QCOMPARE(k.n, 600);
        qInfo("%s: %d of %d marked good", spotCaseName(SpotCase(spotCase)), k.good, k.n);
        QVERIFY2(k.good <= 0.01 * k.n, qPrintable(QString("%1 of %2 doubtful shots marked good").arg(k.good).arg(k.n)));
    }
};

QTEST_GUILESS_MAIN(TestFootprintPhoto)
#include "test_footprint_photo.moc"
