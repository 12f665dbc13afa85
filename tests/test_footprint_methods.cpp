// Footprint spot methods on spots with exact truth: noise-free checks of the algebra, the
// shape conventions, the CRLB, and each method on simulated shots.
#include <QtTest>
#include <cmath>
#include <random>

#include "core/footprint/batch.hpp"
#include "core/footprint/crlb.hpp"
#include "core/footprint/gauss_kernel.hpp"
#include "core/footprint/pipeline.hpp"
#include "core/sim/footprint_eval.hpp"
#include "core/sim/footprint_sim.hpp"
#include "core/common/rng.hpp"
#include "test_support.hpp"

using namespace lwb::core;
using namespace lwb::core::footprint;

namespace {
// A point-sampled rotated Gaussian on a flat background, no noise.
cv::Mat exactSpot(int n, double x0, double y0, double amp, double s1, double s2, double tiltDeg, double bg) {
    cv::Mat m(n, n, CV_32F);
    const double t = tiltDeg * M_PI / 180, c = std::cos(t), s = std::sin(t);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double dx = x - x0, dy = y - y0, u = dx * c + dy * s, v = -dx * s + dy * c;
            m.at<float>(y, x) = static_cast<float>(bg + amp * std::exp(-0.5 * (u * u / (s1 * s1) + v * v / (s2 * s2))));
        }
    return m;
}

FootprintParams paperExact() {
    FootprintParams p;
    p.gauss.xyTerm = false;
    p.gauss.guoIterations = 0;
    p.gauss.lmRefine = false;
    return p;
}
}  // namespace

class TestFootprintMethods : public QObject {
    Q_OBJECT
private slots:
    // The shots task (issue 28): the workbench's list and the CLI's per-ROI stage. Reused fits
    // judged under a new verdict give what fitting again gives; an unreadable shot stays empty.
    void shotsTaskReusesFitsForAVerdictChange() {
        ShotsTask::Inputs in;
        for (int i = 0; i < 24; ++i) {
            sim::FootprintSimParams sp;
            sp.scene = sim::Scene::Flat;
            cv::Mat f;
            sim::simulateFootprint(sp, sim::Rng::mix(5, i)).image.convertTo(f, CV_32F);
            in.rois.push_back(f);
        }
        in.rois.push_back(cv::Mat());
        const FootprintParams p0;
        const auto fits = std::make_shared<const std::vector<FootprintResult>>(runTask<ShotsTask>(in, p0));
        QCOMPARE(fits->size(), in.rois.size());
        QVERIFY(!fits->back().ok);
        FootprintParams p1 = p0;
        p1.verdict.axisRatio = {true, 1.0, 1.05};  // stricter: some good shots turn doubtful
        QCOMPARE(footprintSchema().firstChangedStage(p0, p1), int(kStageVerdict));
        ShotsTask::Reuse reuse{fits};
        const auto judged = ShotsTask::run(in, p1, reuse, nullptr);
        const auto fresh = runTask<ShotsTask>(in, p1);
        int changed = 0;
        for (size_t i = 0; i + 1 < in.rois.size(); ++i) {
            QCOMPARE(judged[i].verdict, fresh[i].verdict);
            QVERIFY(judged[i].reasons == fresh[i].reasons);
            QCOMPARE(judged[i].fit.x, fresh[i].fit.x);
            changed += judged[i].verdict != (*fits)[i].verdict;
        }
        QVERIFY(changed > 0);
    }

    void paperSystemIsExactOnANoiseFreeAxisAlignedSpot() {
        // Wu's f·ln f system is exact for an untilted Gaussian: the centre and σ come back to
        // rounding, and the paper's MSE (eq. 8) is ~0.
        const cv::Mat m = exactSpot(32, 15.3, 16.7, 5000, 3.6, 2.9, 0, 2000);
        const FootprintResult r = processRoi(m, paperExact());
        QVERIFY2(r.ok && r.fit.ok, r.fit.error.c_str());
        QVERIFY(std::fabs(r.fit.x - 15.3) < 1e-3);
        QVERIFY(std::fabs(r.fit.y - 16.7) < 1e-3);
        QVERIFY(std::fabs(r.fit.sigmaX - 3.6) < 1e-2);
        QVERIFY(std::fabs(r.fit.sigmaY - 2.9) < 1e-2);
        QVERIFY(std::fabs(r.fit.axisRatio - 3.6 / 2.9) < 1e-2);
        QVERIFY(std::fabs(r.fit.majorAxisPx - 4 * 3.6) < 0.05);  // L_A = 1/e² diameter = 4σ
        QVERIFY2(r.fit.mse < 1e-9, std::to_string(r.fit.mse).c_str());
        QCOMPARE(r.gaussStage, std::string("wu"));
    }

    /// The same exactness through the normal equations (built from weighted moments, the path
    /// taken when Guo passes follow), for the paper's 5-column system and the 6-column one.
    void normalEquationsAreExactOnANoiseFreeSpot() {
        for (bool xy : {false, true}) {
            FootprintParams p = paperExact();
            p.gauss.xyTerm = xy;
            p.gauss.guoIterations = 3;
            const cv::Mat m = exactSpot(32, 15.3, 16.7, 5000, 3.6, 2.9, 0, 2000);
            const FootprintResult r = processRoi(m, p);
            QVERIFY2(r.ok && r.fit.ok, r.fit.error.c_str());
            QCOMPARE(r.gaussStage, std::string("guo"));
            QVERIFY2(std::fabs(r.fit.x - 15.3) < 1e-3 && std::fabs(r.fit.y - 16.7) < 1e-3,
                     qPrintable(QString("xy %1: %2, %3").arg(xy).arg(r.fit.x).arg(r.fit.y)));
            QVERIFY(std::fabs(r.fit.sigmaX - 3.6) < 1e-2);
            QVERIFY(std::fabs(r.fit.sigmaY - 2.9) < 1e-2);
        }
        // Tilted: only the 6-column system recovers it.
        FootprintParams p = paperExact();
        p.gauss.xyTerm = true;
        p.gauss.guoIterations = 3;
        const FootprintResult r = processRoi(exactSpot(32, 16.2, 15.1, 6000, 4.0, 2.5, 25, 1000), p);
        QVERIFY(r.fit.ok);
        QVERIFY(std::hypot(r.fit.x - 16.2, r.fit.y - 15.1) < 1e-3);
        QVERIFY(std::fabs(r.fit.tiltRad * 180 / M_PI - 25) < 0.5);
    }

    void xyTermRecoversTilt() {
        const cv::Mat m = exactSpot(32, 16.2, 15.1, 6000, 4.0, 2.5, 25, 1000);
        FootprintParams withXy = paperExact();
        withXy.gauss.xyTerm = true;
        const FootprintResult r = processRoi(m, withXy);
        QVERIFY(r.ok && r.fit.ok);
        QVERIFY(std::fabs(r.fit.tiltRad * 180 / M_PI - 25) < 0.1);
        QVERIFY(std::fabs(r.fit.x - 16.2) < 1e-3 && std::fabs(r.fit.y - 15.1) < 1e-3);
        // Without the xy column the paper's model cannot tilt: θ stays 0 and the fit is worse.
        const FootprintResult p = processRoi(m, paperExact());
        QVERIFY(p.ok && p.fit.ok);
        QCOMPARE(p.fit.tiltRad, 0.0);
        QVERIFY(p.fit.mse > 10 * r.fit.mse);
    }

    void axisConventionFollowsThePaper() {
        // Long axis near y: the x-near axis is the short one, so C = σx/σy < 1 and the wu2021
        // ratio criterion (1, 1.5) fails; long axis near x: C > 1.
        const cv::Mat alongY = exactSpot(32, 16, 16, 5000, 4.0, 3.0, 80, 1000);
        const FootprintResult r = processRoi(alongY, FootprintParams{});
        QVERIFY(r.fit.ok);
        QVERIFY(r.fit.axisRatio < 1);
        QVERIFY(std::fabs(r.fit.tiltRad * 180 / M_PI - (-10)) < 0.5);  // x-near axis at −10°
        QCOMPARE(r.verdict, Verdict::Doubtful);
        QVERIFY(!r.reasons.empty() && r.reasons[0].find("axis_ratio") == 0);
        const FootprintResult q = processRoi(exactSpot(32, 16, 16, 5000, 4.0, 3.0, 10, 1000), FootprintParams{});
        QVERIFY(q.fit.axisRatio > 1);
        QCOMPARE(q.verdict, Verdict::Good);
    }

    void crlbClosedFormMatchesFisher() {
        CameraParams cam;
        for (double sigma : {2.5, 3.5, 4.5})
            for (double bg : {400.0, 3000.0}) {
                GaussModel g;
                g.amplitude = 3000;
                g.x0 = 15.6;
                g.y0 = 16.2;
                g.a = g.c = 1 / (sigma * sigma);
                g.bg0 = bg;
                const CrlbResult f = crlbFisher(g, 32, 32, cam, 4);
                const CrlbResult c = crlbClosedForm(3000, sigma, sigma, bg, cam, true);
                QVERIFY(f.ok && c.ok);
                // Rieger & Stallinga state their formula to within ~10 % of the full bound.
                QVERIFY2(std::fabs(c.radialPx / f.radialPx - 1) < 0.15,
                         qPrintable(QString("sigma %1 bg %2: closed %3 fisher %4").arg(sigma).arg(bg).arg(c.radialPx).arg(f.radialPx)));
            }
    }

    void eachMethodOnSimulatedShots_data() {
        QTest::addColumn<QString>("variant");
        QTest::addColumn<QString>("scene");
        QTest::addColumn<double>("maxMeanErr");
        // Tolerances: the paper's baselines are far from the spot centre by design (GCM weighs
        // the whole chip), so each bound is the method's own scale, not a target.
        QTest::newRow("gcm flat") << "gcm" << "flat" << 3.5;
        QTest::newRow("tefm flat") << "tefm" << "flat" << 0.10;
        QTest::newRow("tefm night") << "tefm" << "night" << 0.15;
        QTest::newRow("gauss-paper flat") << "gauss-paper" << "flat" << 0.03;
        QTest::newRow("gauss-paper weak") << "gauss-paper" << "weak" << 0.25;
        QTest::newRow("gauss-guo weak") << "gauss-guo" << "weak" << 0.20;
        QTest::newRow("gauss night") << "gauss" << "night" << 0.05;
    }
    void eachMethodOnSimulatedShots() {
        QFETCH(QString, variant);
        QFETCH(QString, scene);
        QFETCH(double, maxMeanErr);
        sim::MethodVariant v;
        QVERIFY(sim::findVariant(variant.toStdString(), &v));
        sim::EvalParams ep;
        ep.countPerScene = 150;
        ep.seed = 101;
        // The synthetic ground these scales were set on; photo ground: test_footprint_photo.
        ep.sim.ground = sim::GroundSource::Synthetic;
        sim::Scene s;
        QVERIFY(sim::parseScene(scene.toStdString(), &s));
        ep.scenes = {s};
        const auto stats = sim::evaluateFootprint(ep, {v});
        QCOMPARE(stats.size(), size_t(1));
        QCOMPARE(stats[0].fitted, 150);  // every shot gets a centre
        QVERIFY2(stats[0].meanErr <= maxMeanErr, qPrintable(QString("mean error %1 px").arg(stats[0].meanErr)));
    }

    void gcmWithoutBackgroundIsPulledToTheChipCentre() {
        // Paper 001: GCM over the raw chip is biased towards the chip centre by the ground.
        const cv::Mat m = exactSpot(40, 12.0, 27.0, 4000, 2.5, 2.5, 0, 2500);
        FootprintParams p;
        p.method = Method::Gcm;
        const FootprintResult raw = processRoi(m, p);
        QVERIFY(raw.fit.ok);
        QVERIFY(raw.fit.x > 14 && raw.fit.y < 25);  // pulled towards (19.5, 19.5)
        p.gcm.subtractBackground = true;
        const FootprintResult sub = processRoi(m, p);
        QVERIFY(std::hypot(sub.fit.x - 12, sub.fit.y - 27) < 0.01);
    }

    void tefmStepsOnACleanSpot() {
        const cv::Mat m = exactSpot(40, 20.4, 19.3, 5000, 2.5, 2.0, 0, 2000);
        FootprintParams p;
        p.method = Method::Tefm;
        p.tefm.backgroundOffset = 2000;  // the paper's fixed offset, exact here
        const FootprintResult r = processRoi(m, p);
        QVERIFY2(r.fit.ok, r.fit.error.c_str());
        QVERIFY(std::hypot(r.fit.x - 20.4, r.fit.y - 19.3) < 0.05);
        // The ellipse sits near the 1/e² contour (semi-axes 2σ) less the erosion's pixel.
        QVERIFY(r.tefm.ellipseA > 3.0 && r.tefm.ellipseA < 5.5);
        QVERIFY(r.fit.eccentricity > 0.2 && r.fit.eccentricity < 0.8);
    }

    void uncertaintyIsHonest() {
        // The reported uncertainty u = sqrt(var x + var y) should cover the true error as a 2-D
        // Gaussian would: for isotropic errors of σ per axis, u = √2·σ and the radial error is
        // Rayleigh, so P(|err| < u) = 1 − e⁻¹ = 63 %. Accept 50–76 % (200 shots: ±3.4 % s.d.).
        int inside = 0, n = 0;
        for (int i = 0; i < 200; ++i) {
            sim::FootprintSimParams sp;
            sp.scene = sim::Scene::Flat;
            const auto shot = sim::simulateFootprint(sp, sim::Rng::mix(77, i));
            cv::Mat f;
            shot.image.convertTo(f, CV_32F);
            const FootprintResult r = processRoi(f, FootprintParams{});
            if (!r.fit.ok) continue;
            ++n;
            const double e = std::hypot(r.fit.x - shot.truth.x, r.fit.y - shot.truth.y);
            if (e < r.fit.uncertaintyPx) ++inside;
        }
        QCOMPARE(n, 200);
        const double frac = double(inside) / n;
        qInfo("uncertainty coverage P(|err| < u) = %.3f (Rayleigh: 0.632)", frac);
        QVERIFY2(frac > 0.50 && frac < 0.76, qPrintable(QString("coverage %1").arg(frac)));
    }

    /// The log fit's weighted moments (kernel::logMoments, vectorised, -ffast-math) equal the sums
    /// taken one by one in long double, to 1e-12 of the sum of magnitudes.
    void logMomentsMatchDirectSums() {
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> pos(-9, 9), wt(0, 2), ln(-8, 0);
        for (int n : {7, 8, 33, 250}) {
            std::vector<double> pix(static_cast<size_t>(4 * n)), w(static_cast<size_t>(n));
            for (int i = 0; i < n; ++i) {
                pix[size_t(4 * i)] = pos(rng);
                pix[size_t(4 * i + 1)] = pos(rng);
                pix[size_t(4 * i + 2)] = 1;
                pix[size_t(4 * i + 3)] = ln(rng);
                w[size_t(i)] = wt(rng);
            }
            double m[15], r[6];
            kernel::logMoments(pix.data(), w.data(), n, m, r);
            const int powers[15][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}, {3, 0}, {2, 1},
                                       {1, 2}, {0, 3}, {4, 0}, {3, 1}, {2, 2}, {1, 3}, {0, 4}};
            const int cols[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
            auto check = [&](double got, auto term, const char* what, int k) {
                long double sum = 0, mag = 0;
                for (int i = 0; i < n; ++i) {
                    const long double t = term(i);
                    sum += t;
                    mag += std::fabs(t);
                }
                if (std::fabs(got - double(sum)) > 1e-12 * double(mag) + 1e-300)
                    QFAIL(qPrintable(QString("n %1, %2 %3: %4, not %5").arg(n).arg(what).arg(k).arg(got).arg(double(sum))));
            };
            for (int k = 0; k < 15; ++k)
                check(m[k], [&](int i) {
                    const long double u = pix[size_t(4 * i)], v = pix[size_t(4 * i + 1)], w2 = (long double)w[size_t(i)] * w[size_t(i)];
                    return w2 * std::pow(u, powers[k][0]) * std::pow(v, powers[k][1]);
                }, "moment", k);
            for (int k = 0; k < 6; ++k)
                check(r[k], [&](int i) {
                    const long double u = pix[size_t(4 * i)], v = pix[size_t(4 * i + 1)], w2 = (long double)w[size_t(i)] * w[size_t(i)];
                    return w2 * pix[size_t(4 * i + 3)] * std::pow(u, cols[k][0]) * std::pow(v, cols[k][1]);
                }, "rhs", k);
        }
    }

    /// The lag sums of the ground covariance (kernel::lagSums: accumulators in registers, 8 lanes
    /// × 1..8 vectors picked by the lag count, even and odd pixels in two sets) equal the sums in
    /// long double to 1e-5 of the sum of magnitudes (a float sum's error; the message shows the
    /// scalar float sum beside them); cross sums (u ≠ w) as well as auto.
    void lagSumsMatchDirectSums() {
        std::mt19937 rng(7);
        std::uniform_real_distribution<float> val(-40, 40);
        const int shapes[][4] = {{5, 4, 1, 1}, {13, 13, 6, 6}, {32, 32, 11, 11}, {23, 17, 11, 8}, {40, 9, 19, 4},
                                 {64, 64, 31, 31}, {9, 30, 4, 14}, {20, 20, 3, 9}};
        for (const auto& sh : shapes) {
            const int W = sh[0], H = sh[1], lxMax = sh[2], lyMax = sh[3], stride = 2 * lxMax + 1;
            std::vector<float> u(size_t(W * H)), w(size_t(W * H));
            for (float& x : u) x = val(rng);
            for (float& x : w) x = val(rng);
            for (const bool cross : {false, true}) {
                const std::vector<float>& v = cross ? w : u;
                std::vector<float> out(size_t(stride * (lyMax + 1)), NAN);
                kernel::lagSums(u.data(), v.data(), W, H, lxMax, lyMax, out.data());
                for (int ly = 0; ly <= lyMax; ++ly)
                    for (int lx = -lxMax; lx <= lxMax; ++lx) {
                        float f = 0;
                        long double ld = 0, mag = 0;
                        for (int y = 0; y + ly < H; ++y)
                            for (int x = 0; x < W; ++x) {
                                if (x + lx < 0 || x + lx >= W) continue;
                                const float a = u[size_t(y * W + x)], b = v[size_t((y + ly) * W + x + lx)];
                                f += a * b;
                                ld += (long double)a * b;
                                mag += std::fabs((long double)a * b);
                            }
                        const float got = out[size_t(ly * stride + lx + lxMax)];
                        if (!(std::fabs((long double)got - ld) <= 1e-5L * mag + 1e-30L))
                            QFAIL(qPrintable(QString("%1x%2 lags ±%3/%4 (%5), lag (%6, %7): %8, not %9 (long double %10)")
                                                 .arg(W).arg(H).arg(lxMax).arg(lyMax).arg(cross ? "cross" : "auto")
                                                 .arg(lx).arg(ly).arg(double(got), 0, 'g', 9).arg(double(f), 0, 'g', 9)
                                                 .arg(double(ld), 0, 'g', 9)));
                    }
            }
        }
    }

    /// The difference fit's Gram kernel (register-blocked, vectorised) equals the sums taken one
    /// by one, for horizontal and vertical differences and for windows longer than its block.
    void differenceGramMatchesDirectSums() {
        std::mt19937 rng(6);
        std::uniform_real_distribution<double> val(-50, 50), wt(0, 1);
        constexpr int K = kernel::kGramColumns;
        for (int n : {5, 9, 400, 2500}) {  // 5 < step 7: no differences, every sum 0
            for (int step : {1, 7}) {
                std::vector<double> P(static_cast<size_t>(K * n)), w(static_cast<size_t>(n)), r(static_cast<size_t>(n));
                for (double& x : P) x = val(rng);
                for (int i = 0; i < n; ++i) {
                    w[size_t(i)] = wt(rng);
                    r[size_t(i)] = val(rng);
                }
                double gram[K * K], rhs[K], wd[K], sw = 0, swr = 0;
                kernel::differenceGram(P.data(), n, step, w.data(), r.data(), gram, rhs, wd, &sw, &swr);
                const int m = n - step;
                auto d = [&](int u, int i) { return (long double)P[size_t(u * n + i + step)] - P[size_t(u * n + i)]; };
                auto near = [](double got, long double want, long double mag) {
                    return std::fabs((long double)got - want) <= 1e-12L * mag + 1e-300L;
                };
                long double s0 = 0, s1 = 0, mag0 = 0, mag1 = 0;
                for (int i = 0; i < m; ++i) {
                    s0 += w[size_t(i)];
                    s1 += w[size_t(i)] * (long double)r[size_t(i)];
                    mag0 += w[size_t(i)];
                    mag1 += std::fabs(w[size_t(i)] * (long double)r[size_t(i)]);
                }
                QVERIFY(near(sw, s0, mag0));
                QVERIFY(near(swr, s1, mag1));
                for (int u = 0; u < K; ++u) {
                    long double g1 = 0, m1 = 0, g2 = 0, m2 = 0;
                    for (int i = 0; i < m; ++i) {
                        g1 += w[size_t(i)] * d(u, i) * r[size_t(i)];
                        m1 += std::fabs(w[size_t(i)] * d(u, i) * r[size_t(i)]);
                        g2 += w[size_t(i)] * d(u, i);
                        m2 += std::fabs(w[size_t(i)] * d(u, i));
                    }
                    QVERIFY2(near(rhs[u], g1, m1), qPrintable(QString("rhs %1, n %2, step %3").arg(u).arg(n).arg(step)));
                    QVERIFY2(near(wd[u], g2, m2), qPrintable(QString("wd %1, n %2, step %3").arg(u).arg(n).arg(step)));
                    for (int v = 0; v <= u; ++v) {
                        long double g = 0, mg = 0;
                        for (int i = 0; i < m; ++i) {
                            g += w[size_t(i)] * d(u, i) * d(v, i);
                            mg += std::fabs(w[size_t(i)] * d(u, i) * d(v, i));
                        }
                        QVERIFY2(near(gram[u * K + v], g, mg),
                                 qPrintable(QString("gram %1,%2, n %3, step %4").arg(u).arg(v).arg(n).arg(step)));
                    }
                }
            }
        }
    }

    /// LM stops once a step would move the centre less than lm_tolerance_fraction (0.1) of the
    /// centre's uncertainty u and the amplitude and shape by less than lm_tolerance_shape (1 %),
    /// and takes that last step unevaluated. Against a fit run to convergence (1e-7 px, shape
    /// 1e-12, up to 300 iterations) on textured ground: the centre 0.03–0.05 u away on average
    /// and 0.2 u at most (the robust loss converges linearly, so the distance left is of the
    /// order of the last step), bounds 0.06 u and 0.3 u; amplitude and major axis within 0.6 % and
    /// 1 % (800 shots), bound 2 %; the error against the truth within 1 %; the verdicts the same
    /// (at most one of 200 on a criterion's edge); under 70 % of the iterations (about half).
    void lmStopsAtAFractionOfTheUncertainty() {
        const sim::Scene scenes[] = {sim::Scene::Weak, sim::Scene::Moderate, sim::Scene::Strong, sim::Scene::Night};
        FootprintParams converged;
        converged.gauss.lmToleranceFraction = 0;
        converged.gauss.lmTolerancePx = 1e-7;
        converged.gauss.lmToleranceShape = 1e-12;
        converged.gauss.lmMaxIterations = 300;
        const FootprintParams byDefault;
        QCOMPARE(byDefault.gauss.lmToleranceFraction, 0.1);
        QCOMPARE(byDefault.gauss.lmToleranceShape, 0.01);
        double worst = 0, sum = 0, errConverged = 0, errDefault = 0, worstAmp = 0, worstAxis = 0;
        int n = 0, itConverged = 0, itDefault = 0, verdicts = 0;
        for (int i = 0; i < 200; ++i) {
            sim::FootprintSimParams sp;
            sp.scene = scenes[i % 4];
            const auto shot = sim::simulateFootprint(sp, sim::Rng::mix(91, i));
            cv::Mat f;
            shot.image.convertTo(f, CV_32F);
            const FootprintResult a = processRoi(f, converged), b = processRoi(f, byDefault);
            if (!a.fit.ok || !b.fit.ok || a.gaussStage != "lm" || b.gaussStage != "lm") continue;
            const double rel = std::hypot(a.fit.x - b.fit.x, a.fit.y - b.fit.y) / a.fit.uncertaintyPx;
            worst = std::max(worst, rel);
            sum += rel;
            ++n;
            itConverged += a.fit.iterations;
            itDefault += b.fit.iterations;
            errConverged += std::hypot(a.fit.x - shot.truth.x, a.fit.y - shot.truth.y);
            errDefault += std::hypot(b.fit.x - shot.truth.x, b.fit.y - shot.truth.y);
            worstAmp = std::max(worstAmp, std::fabs(b.fit.amplitude / a.fit.amplitude - 1));
            worstAxis = std::max(worstAxis, std::fabs(b.fit.majorAxisPx / a.fit.majorAxisPx - 1));
            verdicts += a.verdict != b.verdict;
        }
        qInfo("%d shots: the default stop is %.3f u from convergence at most, %.4f u on average; amplitude "
              "%.4f, major axis %.4f at most; mean error %.4f -> %.4f px; %d verdicts differ; iterations %d -> %d",
              n, worst, sum / n, worstAmp, worstAxis, errConverged / n, errDefault / n, verdicts, itConverged, itDefault);
        QVERIFY(n >= 190);
        QVERIFY2(worst <= 0.3, qPrintable(QString::number(worst)));
        QVERIFY2(sum / n <= 0.06, qPrintable(QString::number(sum / n)));
        QVERIFY2(worstAmp <= 0.02 && worstAxis <= 0.02, qPrintable(QString("%1 %2").arg(worstAmp).arg(worstAxis)));
        QVERIFY2(std::fabs(errDefault / errConverged - 1) <= 0.01, qPrintable(QString::number(errDefault / errConverged)));
        QVERIFY(verdicts <= 1);
        QVERIFY(itDefault < 0.7 * itConverged);
    }

    /// The opening that cuts roads off the domain runs on 64-bit rows for ROIs up to 64 px wide
    /// and pixel by pixel beyond: a road-crossed spot gives the same domain either way (the same
    /// ROI padded with flat background to 64, 65 and 80 px), and the road through the spot is cut.
    void openingIsTheSameOnWideRois() {
        cv::Mat roi = exactSpot(32, 15.3, 16.6, 3000, 3.0, 2.5, 20, 1000);
        for (int y = 0; y < 32; ++y)  // a 2 px bright road through the spot, and one beside it
            for (int x : {14, 15, 24, 25}) roi.at<float>(y, x) += 900;
        SegmentParams sp;
        QVERIFY(sp.openingRadius > 0);
        const SpotDomain a = segmentSpot(roi, 1000, 20, 65535, sp);
        QVERIFY(a.found);
        for (int width : {64, 65, 80}) {  // the last bit-row width, and the first two byte-path ones
            cv::Mat wide(40, width, CV_32F, cv::Scalar(1000));
            const int x0 = width - 32 - 2;
            roi.copyTo(wide(cv::Rect(x0, 4, 32, 32)));
            const SpotDomain b = segmentSpot(wide, 1000, 20, 65535, sp);
            QVERIFY(b.found);
            std::vector<int> pa, pb = b.pixels;
            for (int p : a.pixels) pa.push_back((p / 32 + 4) * width + p % 32 + x0);
            std::sort(pa.begin(), pa.end());
            std::sort(pb.begin(), pb.end());
            QVERIFY2(pa == pb, qPrintable(QString("width %1: %2 vs %3 pixels").arg(width).arg(pb.size()).arg(pa.size())));
        }
        // The opening did its work: the road through the spot (columns 14-15) reaches the ROI's
        // top and bottom rows in the domain without it, and not with it.
        auto endRows = [](const SpotDomain& d) {
            int n = 0;
            for (int y : {0, 31})
                for (int x : {14, 15}) n += d.mask[size_t(y) * 32 + x] != 0;
            return n;
        };
        SegmentParams noOpening = sp;
        noOpening.openingRadius = 0;
        QCOMPARE(endRows(segmentSpot(roi, 1000, 20, 65535, noOpening)), 4);
        QCOMPARE(endRows(a), 0);
    }

    void invalidParamsAreRefused() {
        FootprintParams p;
        p.segment.thresholdFactor = NAN;
        const FootprintResult r = processRoi(cv::Mat(32, 32, CV_32F, cv::Scalar(100)), p);
        QVERIFY(!r.ok);
        QVERIFY(r.error.find("threshold") != std::string::npos);
        p = FootprintParams{};
        p.verdict.axisRatio = {true, 2, 1};
        QVERIFY(!validate(p).empty());
        p = FootprintParams{};
        p.camera.gainEPerDn = -1;
        QVERIFY(!validate(p).empty());
    }

    void flatImageIsRejectedNotCrashed() {
        const FootprintResult r = processRoi(cv::Mat(32, 32, CV_32F, cv::Scalar(1234)), FootprintParams{});
        QVERIFY(r.ok);
        QCOMPARE(r.verdict, Verdict::Rejected);
        QVERIFY(r.reasons[0].find("no spot") == 0);
    }
};

QTEST_GUILESS_MAIN(TestFootprintMethods)
#include "test_footprint_methods.moc"
