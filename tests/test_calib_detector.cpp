// Ground detector array (paper 002 §3.2.3): the Gaussian surface fit recovers the simulator's
// exact footprint centre, its 1σ ellipse is honest, set-aside detectors carry their reason, and
// bad inputs fail clearly.
#include <QtTest>

#include "core/calib/detector_array.hpp"
#include "core/calib/geodesy.hpp"
#include "core/sim/calib_sim.hpp"
#include "core/common/rng.hpp"
#include "test_support.hpp"

using namespace lwb::core;
using namespace lwb::core::calib;

namespace {
DetectorFitParams matching(const sim::DetectorSimParams& sp) {
    DetectorFitParams p;
    p.model = SurfaceModel::Elliptical;
    p.noise = NoiseSource::Given;
    p.triggerThreshold = sp.triggerThreshold;
    p.relativeNoise = sp.relativeNoise;
    p.noiseFloor = sp.noiseFloor;
    if (sp.saturationLevel > 0) p.saturationLevel = sp.saturationLevel;
    return p;
}
// Squared Mahalanobis distance of the centre error under the reported covariance.
double mahalanobis2(const DetectorFitResult& r, double e0, double n0) {
    const Eigen::Vector2d d(r.centreE - e0, r.centreN - n0);
    const Eigen::Matrix2d c = r.covariance.block<2, 2>(1, 1);
    return d.dot(c.ldlt().solve(d));
}
Detector det(const std::string& id, double e, double n, double energy) {
    Detector d;
    d.id = id;
    d.e = e;
    d.n = n;
    d.energy = energy;
    return d;
}
}  // namespace

class TestCalibDetector : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString path(const QString& n) const { return m_dir.path() + "/" + n; }

private slots:
    void recoversTheSimulatedCentre_data() {
        QTest::addColumn<int>("seed");
        for (int s : {1, 2, 3, 4, 5, 6}) QTest::newRow(qPrintable(QString("seed %1").arg(s))) << s;
    }
    void recoversTheSimulatedCentre() {
        QFETCH(int, seed);
        const sim::DetectorSimParams sp;  // 5 m grid, 15 m footprint, 5 % + 2 energy noise
        const sim::DetectorSimulation s = sim::simulateDetectorArray(sp, static_cast<uint64_t>(seed));
        const DetectorFitResult r = fitDetectorArray(s.array, matching(sp));
        QVERIFY2(r.ok, r.error.c_str());
        QVERIFY(r.used >= 7);
        qInfo("centre (%.3f, %.3f) m, true (%.3f, %.3f) m, 1-sigma (%.3f, %.3f) m, %d detectors", r.centreE, r.centreN,
              s.truth.e0, s.truth.n0, r.centreEllipse.sigmaE, r.centreEllipse.sigmaN, r.used);
        // Tolerance: 3 × the fitted 1σ per axis (the honesty of that σ is checked below).
        const double se = r.centreEllipse.sigmaE, sn = r.centreEllipse.sigmaN;
        QVERIFY2(std::fabs(r.centreE - s.truth.e0) <= 3 * se,
                 qPrintable(QString("E %1 vs %2, sigma %3").arg(r.centreE).arg(s.truth.e0).arg(se)));
        QVERIFY2(std::fabs(r.centreN - s.truth.n0) <= 3 * sn,
                 qPrintable(QString("N %1 vs %2, sigma %3").arg(r.centreN).arg(s.truth.n0).arg(sn)));
        // And the σ itself is what 5 % noise on ~10 detectors allows: a few cm, not metres.
        QVERIFY(se > 0.005 && se < 0.3 && sn > 0.005 && sn < 0.3);
        // Widths within 3σ of the truth too, with the fit's own σ of each width (the simulated
        // spot is elliptical, axis ratio up to 1.2, σ_major·σ_minor = sp.sigmaM²).
        QVERIFY2(std::isfinite(r.sigmaMajorSd) && std::isfinite(r.sigmaMinorSd), "width uncertainties missing");
        QVERIFY2(std::fabs(r.surface.sigmaMajor - s.truth.sigmaMajor) <= 3 * r.sigmaMajorSd,
                 qPrintable(QString("major %1 vs %2, sd %3").arg(r.surface.sigmaMajor).arg(s.truth.sigmaMajor).arg(r.sigmaMajorSd)));
        QVERIFY2(std::fabs(r.surface.sigmaMinor - s.truth.sigmaMinor) <= 3 * r.sigmaMinorSd,
                 qPrintable(QString("minor %1 vs %2, sd %3").arg(r.surface.sigmaMinor).arg(s.truth.sigmaMinor).arg(r.sigmaMinorSd)));
        // Everything a plot needs is there.
        QCOMPARE(r.detectors.size(), s.array.detectors.size());
        QCOMPARE(r.covariance.rows(), 7);
        QVERIFY(!r.costPerIteration.empty());
        QVERIFY(r.costPerIteration.back() <= r.costPerIteration.front());
    }

    // The true centre lies inside the 3σ region (χ²₂ ≤ 11.83, 99.73 %) in at least 95 % of trials.
    void uncertaintyEllipseIsHonest() {
        const sim::DetectorSimParams sp;
        const int trials = 300;
        int inside = 0, ok = 0;
        double se2 = 0, sigma2 = 0;
        for (int i = 0; i < trials; ++i) {
            const auto s = sim::simulateDetectorArray(sp, sim::Rng::mix(4242, i));
            const DetectorFitResult r = fitDetectorArray(s.array, matching(sp));
            if (!r.ok) continue;
            ++ok;
            if (mahalanobis2(r, s.truth.e0, s.truth.n0) <= 11.83) ++inside;
            se2 += std::pow(r.centreE - s.truth.e0, 2) + std::pow(r.centreN - s.truth.n0, 2);
            sigma2 += r.centreEllipse.sigmaE * r.centreEllipse.sigmaE + r.centreEllipse.sigmaN * r.centreEllipse.sigmaN;
        }
        QCOMPARE(ok, trials);
        qInfo("centre inside 3 sigma in %d of %d trials; RMS error %.4f m, RMS reported sigma %.4f m (per axis)", inside,
              trials, std::sqrt(se2 / trials / 2), std::sqrt(sigma2 / trials / 2));
        QVERIFY2(inside >= 0.95 * trials, qPrintable(QString::number(inside)));
        // The reported σ neither hides nor inflates the scatter: ratio within 0.8..1.25.
        const double ratio = std::sqrt(se2 / sigma2);
        QVERIFY2(ratio > 0.8 && ratio < 1.25, qPrintable(QString::number(ratio)));
    }

    void saturatedAndUntriggeredDetectorsCarryTheirReason() {
        sim::DetectorSimParams sp;
        sp.saturationLevel = 750;  // the peak (1000) clips: the central detectors saturate
        int sawSaturated = 0;
        for (uint64_t seed = 10; seed < 20; ++seed) {
            const auto s = sim::simulateDetectorArray(sp, seed);
            const DetectorFitResult r = fitDetectorArray(s.array, matching(sp));
            QVERIFY2(r.ok, r.error.c_str());
            for (size_t i = 0; i < r.detectors.size(); ++i) {
                const auto& o = r.detectors[i];
                const auto& d = s.array.detectors[i];
                // Censored by default: a saturated detector says "at least", an untriggered one "at most".
                if (d.saturated == 1) {
                    ++sawSaturated;
                    QCOMPARE(int(o.status), int(DetectorStatus::AtLeast));
                    QVERIFY(!o.reason.empty());
                    QCOMPARE(o.bound, sp.saturationLevel);
                } else if (d.triggered == 0) {
                    QCOMPARE(int(o.status), int(DetectorStatus::AtMost));
                    QVERIFY(!o.reason.empty());
                    QCOMPARE(o.bound, sp.triggerThreshold);
                } else {
                    QCOMPARE(int(o.status), int(DetectorStatus::Used));
                    QVERIFY(o.reason.empty());
                    QVERIFY(std::isfinite(o.residual));
                }
            }
            // Without the clipped peak the centre is still found within 3σ.
            QVERIFY(std::fabs(r.centreE - s.truth.e0) <= 3 * r.centreEllipse.sigmaE);
            QVERIFY(std::fabs(r.centreN - s.truth.n0) <= 3 * r.centreEllipse.sigmaN);
        }
        QVERIFY(sawSaturated > 0);  // the scenario did exercise saturation
    }

    void thresholdsDecideWhenTheFileHasNoFlags() {
        DetectorArray a;
        // A 5 m grid under a circular Gaussian (A = 100, σ = 4 m, centre (1, −2)), no noise.
        for (int i = -3; i <= 3; ++i)
            for (int j = -3; j <= 3; ++j) {
                const double e = 5 * i, n = 5 * j;
                a.detectors.push_back(det("d", e, n, 100 * std::exp(-0.5 * ((e - 1) * (e - 1) + (n + 2) * (n + 2)) / 16)));
            }
        DetectorFitParams p;
        p.triggerThreshold = 2;
        p.saturationLevel = 80;  // the detector at (0, 0) sees 85.5
        p.noise = NoiseSource::Given;
        p.censor = false;  // set aside, each with its reason
        p.relativeNoise = 0;
        p.noiseFloor = 0.01;
        const DetectorFitResult r = fitDetectorArray(a, p);
        QVERIFY2(r.ok, r.error.c_str());
        int sat = 0, untrig = 0;
        for (size_t i = 0; i < r.detectors.size(); ++i) {
            const double en = a.detectors[i].energy;
            if (en >= 80) {
                ++sat;
                QCOMPARE(int(r.detectors[i].status), int(DetectorStatus::Saturated));
                QVERIFY(r.detectors[i].reason.find("saturation level") != std::string::npos);
            } else if (en <= 2) {
                ++untrig;
                QCOMPARE(int(r.detectors[i].status), int(DetectorStatus::Untriggered));
                QVERIFY(r.detectors[i].reason.find("trigger threshold") != std::string::npos);
            }
        }
        QVERIFY(sat >= 1 && untrig >= 1);
        // Noise-free data: the centre is exact to the solver's precision (1 mm).
        QVERIFY(std::fabs(r.centreE - 1) < 1e-3 && std::fabs(r.centreN + 2) < 1e-3);
        QVERIFY(std::fabs(r.surface.sigmaMajor - 4) < 1e-3 && std::fabs(r.surface.sigmaMinor - 4) < 1e-3);
    }

    void fewerDetectorsThanParametersIsAClearError() {
        // Six detectors under a circular Gaussian (A = 100, σ = 4 m, centre (4, 3)), no noise.
        DetectorArray a;
        for (int i = 0; i < 6; ++i) {
            const double e = i % 3 * 5.0, n = i / 3 * 5.0;
            a.detectors.push_back(det("d" + std::to_string(i), e, n, 100 * std::exp(-0.5 * ((e - 4) * (e - 4) + (n - 3) * (n - 3)) / 16)));
        }
        DetectorFitParams e;
        e.model = SurfaceModel::Elliptical;
        const DetectorFitResult r = fitDetectorArray(a, e);
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("only 6 detectors with a measurement") != std::string::npos, r.error.c_str());
        QVERIFY2(r.error.find("at least 7") != std::string::npos, r.error.c_str());
        // The circular model without background has 4 parameters: six detectors determine it, and
        // the default (Auto) chooses it for six.
        const DetectorFitResult ra = fitDetectorArray(a, {});
        QVERIFY2(ra.ok, ra.error.c_str());
        QCOMPARE(int(ra.modelUsed), int(SurfaceModel::Circular));
        QCOMPARE(ra.covariance.rows(), 4);
        DetectorFitParams c;
        c.model = SurfaceModel::Circular;
        c.fitBackground = false;
        c.noise = NoiseSource::Given;
        c.relativeNoise = 0;
        c.noiseFloor = 0.01;
        const DetectorFitResult rc = fitDetectorArray(a, c);
        QVERIFY2(rc.ok, rc.error.c_str());
        QCOMPARE(rc.covariance.rows(), 4);
        QVERIFY(std::fabs(rc.centreE - 4) < 1e-3 && std::fabs(rc.centreN - 3) < 1e-3);  // exact data: 1 mm
        // Two untriggered of the six leave four: still enough for 4 parameters, not for 5.
        a.detectors[0].triggered = 0;
        a.detectors[5].triggered = 0;
        c.fitBackground = true;
        const DetectorFitResult r5 = fitDetectorArray(a, c);
        QVERIFY(!r5.ok);
        QVERIFY2(r5.error.find("2 untriggered") != std::string::npos, r5.error.c_str());
    }

    void collinearDetectorsAreAClearError() {
        DetectorArray a;
        for (int i = 0; i < 12; ++i) a.detectors.push_back(det("d", 5.0 * i, 5.0 * i, 100 * std::exp(-0.02 * (i - 6) * (i - 6))));
        const DetectorFitResult r = fitDetectorArray(a, {});
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("one line") != std::string::npos, r.error.c_str());
    }

    // Also across the antimeridian (issue 27: an array at 179.9999 and -179.9999 averaged its
    // longitudes to 0, and the centre came out 3 900 km off with a sigma of 0.14 m).
    void geographicInputRoundTrips_data() {
        QTest::addColumn<double>("lat");
        QTest::addColumn<double>("lon");
        QTest::newRow("Inner Mongolia") << 42.7 << 112.6;
        QTest::newRow("across 180 (Fiji)") << -16.5 << 179.99995;
        QTest::newRow("across 180, west side") << 0.0 << -179.99998;
    }
    void geographicInputRoundTrips() {
        QFETCH(double, lat);
        QFETCH(double, lon);
        sim::DetectorSimParams sp;
        sp.geographic = true;
        sp.originLatDeg = lat;
        sp.originLonDeg = lon;
        const auto s = sim::simulateDetectorArray(sp, 77);
        const QString p = path("geo.csv");
        std::string err;
        QVERIFY2(writeDetectorCsv(p.toStdString(), s.array, &err), err.c_str());
        QVERIFY(lwbtest::readAll(p).startsWith("id,lat,lon,"));
        DetectorArray back;
        QVERIFY2(readDetectorCsv(p.toStdString(), &back, &err), err.c_str());
        QVERIFY(back.geographic);
        const DetectorFitResult r = fitDetectorArray(back, matching(sp));
        QVERIFY2(r.ok, r.error.c_str());
        // Truth in lat/lon through the simulator's own tangent plane; compare in metres.
        const LocalFrame f(sp.originLatDeg * kDeg, sp.originLonDeg * kDeg, sp.heightM);
        const Eigen::Vector3d t = f.toEcef(Eigen::Vector3d(s.truth.e0, s.truth.n0, 0));
        const Eigen::Vector3d got = geodeticToEcef(r.centreLatDeg * kDeg, r.centreLonDeg * kDeg, sp.heightM);
        const double dist = (f.toEnu(got) - f.toEnu(t)).head<2>().norm();
        const double tol = 3 * r.centreEllipse.semiMajor + 0.01;  // 3σ, plus 1 cm for the projection round trip
        QVERIFY2(dist <= tol, qPrintable(QString("%1 m > %2 m").arg(dist).arg(tol)));
        QVERIFY(std::fabs(r.centreH - sp.heightM) < 0.01);  // every detector at 1000 m
    }

    void malformedCsvNamesFileAndLine() {
        std::string err;
        DetectorArray a;
        const QString p = path("bad.csv");
        QVERIFY(lwbtest::writeText(p, "id,e,n,energy\nA,0,0,10\nB,5,zz,11\n"));
        QVERIFY(!readDetectorCsv(p.toStdString(), &a, &err));
        QVERIFY2(err.find("bad.csv:3:") != std::string::npos, err.c_str());
        QVERIFY(lwbtest::writeText(p, "id,e,n,energy\nA,0,0,10\nB,5,5,nan\n"));
        QVERIFY(!readDetectorCsv(p.toStdString(), &a, &err));
        QVERIFY2(err.find(":3:") != std::string::npos && err.find("energy") != std::string::npos, err.c_str());
        QVERIFY(lwbtest::writeText(p, "id,e,n\nA,0,0\n"));
        QVERIFY(!readDetectorCsv(p.toStdString(), &a, &err));
        QVERIFY2(err.find("energy") != std::string::npos, err.c_str());
        QVERIFY(lwbtest::writeText(p, "id,e,n,energy\nA,0,0,10,4\n"));
        QVERIFY(!readDetectorCsv(p.toStdString(), &a, &err));
        QVERIFY2(err.find(":2:") != std::string::npos, err.c_str());
        // An empty energy is fine only for a detector marked untriggered.
        QVERIFY(lwbtest::writeText(p, "id,e,n,energy,triggered\nA,0,0,,0\nB,5,5,,1\n"));
        QVERIFY(!readDetectorCsv(p.toStdString(), &a, &err));
        QVERIFY2(err.find(":3:") != std::string::npos, err.c_str());
    }

    void nonFiniteInMemoryInputIsRejected() {
        DetectorArray a;
        for (int i = 0; i < 10; ++i) a.detectors.push_back(det("d", i % 4 * 5.0, i / 4 * 5.0, 100));
        a.detectors[3].e = NAN;
        const DetectorFitResult r = fitDetectorArray(a, {});
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("non-finite") != std::string::npos, r.error.c_str());
        DetectorFitParams bad;
        bad.relativeNoise = 2;
        QVERIFY(!validate(bad).empty());
        QVERIFY(!fitDetectorArray(a, bad).ok);
    }
};

QTEST_GUILESS_MAIN(TestCalibDetector)
#include "test_calib_detector.moc"
