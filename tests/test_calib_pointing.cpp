// Pointing and range calibration (paper 002 eq. 2–5): the geolocation model's geometry, the
// recovery of the simulator's known pointing and range errors within their stated σ, honest
// σ over seeded trials, convergence in about three iterations as the paper reports, and clear
// errors for singular geometries and bad input.
#include <QtTest>

#include "core/calib/geodesy.hpp"
#include "core/calib/pointing.hpp"
#include "core/common/atomic_file.hpp"
#include "core/sim/calib_sim.hpp"
#include "core/common/rng.hpp"
#include "test_support.hpp"

using namespace lwb::core;
using namespace lwb::core::calib;

namespace {
struct Errors {
    double v[6];  // dα1, dβ1, dρ1, dα2, dβ2, dρ2: estimate − truth
    double sd[6];
};
Errors errorsOf(const PointingCalibResult& r, const sim::CalibSimulation& s) {
    Errors e{};
    for (int b = 0; b < 2; ++b) {
        const BeamCalibration& c = r.beams[b];
        e.v[3 * b] = c.dAlphaRad - s.dAlpha[b];
        e.v[3 * b + 1] = c.dBetaRad - s.dBeta[b];
        e.v[3 * b + 2] = c.dRhoM - s.dRho[b];
        e.sd[3 * b] = c.dAlphaSdRad;
        e.sd[3 * b + 1] = c.dBetaSdRad;
        e.sd[3 * b + 2] = c.dRhoSdM;
    }
    return e;
}
const char* kNames[6] = {"dalpha1", "dbeta1", "drho1", "dalpha2", "dbeta2", "drho2"};
}  // namespace

class TestCalibPointing : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void threeAxisAnglesOfTheDesignBeams() {
        // Beam 1: 0.7° off nadir toward body +Y: u = (0, sin 0.7°, cos 0.7°), so by eq. 5
        // Angle_X = 90°, Angle_Y = 89.3°, Angle_Z = 0.7° exactly.
        const auto beams = sim::gf7Beams();
        const ThreeAxisAngles a = threeAxisAngles(bodyPointing(beams[0], 0, 0));
        QVERIFY(std::fabs(a.x / kDeg - 90.0) < 1e-9);
        QVERIFY(std::fabs(a.y / kDeg - 89.3) < 1e-9);
        QVERIFY(std::fabs(a.z / kDeg - 0.7) < 1e-9);
        const ThreeAxisAngles b = threeAxisAngles(bodyPointing(beams[1], 0, 0));
        QVERIFY(std::fabs(b.y / kDeg - 90.7) < 1e-9);  // beam 2 to the left: toward −Y
        // Angle_X² + ... : cos² of the three angles sum to one for any unit vector.
        const ThreeAxisAngles c = threeAxisAngles(Eigen::Vector3d(0.3, -0.4, 0.8));
        QVERIFY(std::fabs(std::pow(std::cos(c.x), 2) + std::pow(std::cos(c.y), 2) + std::pow(std::cos(c.z), 2) - 1) < 1e-12);
    }

    void geolocationOfANadirShot() {
        // A satellite 500 km above (42.7°, 112.6°) with body +Z toward the ellipsoid normal and a
        // beam along +Z: 500 km of range lands exactly on the ellipsoid below it.
        const double lat = 42.7 * kDeg, lon = 112.6 * kDeg;
        BeamDesign b;
        b.alphaRad = 0;
        b.betaRad = 0;
        LaserShot s;
        s.satEcef = geodeticToEcef(lat, lon, 500e3);
        const Eigen::Matrix3d enu = ecefToEnuRotation(lat, lon);
        Eigen::Matrix3d att;
        att.col(0) = enu.row(1).transpose();   // X north
        att.col(2) = -enu.row(2).transpose();  // Z down
        att.col(1) = att.col(2).cross(att.col(0));
        s.bodyToEcef = Eigen::Quaterniond(att);
        s.rangeM = 500e3;
        const Eigen::Vector3d g = geolocate(b, s, 0, 0, 0);
        QVERIFY((g - geodeticToEcef(lat, lon, 0)).norm() < 1e-6);
        // A range bias moves the point along the beam by exactly that much.
        QVERIFY(std::fabs((geolocate(b, s, 0, 0, 1.25) - g).norm() - 1.25) < 1e-6);
        // The laser origin offset is carried by the attitude: 1 m along body +X = 1 m north.
        b.offsetBodyM = Eigen::Vector3d(1, 0, 0);
        QVERIFY(std::fabs((enu * (geolocate(b, s, 0, 0, 0) - g)).y() - 1) < 1e-6);
    }

    void recoversTheSimulatedErrors_data() {
        QTest::addColumn<int>("seed");
        QTest::addColumn<bool>("dual");
        for (int s : {1, 2, 3}) {
            QTest::newRow(qPrintable(QString("single, seed %1").arg(s))) << s << false;
            QTest::newRow(qPrintable(QString("dual, seed %1").arg(s))) << s << true;
        }
    }
    void recoversTheSimulatedErrors() {
        QFETCH(int, seed);
        QFETCH(bool, dual);
        const sim::CalibSimParams sp;  // 4 passes, both beams, GF-7 geometry at ~500 km
        const sim::CalibSimulation s = sim::simulateCalibration(sp, static_cast<uint64_t>(seed));
        PointingCalibParams p = s.matchingParams;
        p.model = dual ? CalibModel::DualBeam : CalibModel::SingleBeam;
        const PointingCalibResult r = calibratePointing(s.beams, s.points, p);
        QVERIFY2(r.ok, r.error.c_str());
        const Errors e = errorsOf(r, s);
        for (int k = 0; k < 6; ++k) {
            qInfo("%s: true %.6g, recovered %.6g +- %.3g", kNames[k], (k % 3 == 0 ? s.dAlpha : k % 3 == 1 ? s.dBeta : s.dRho)[k / 3],
                  (k % 3 == 0 ? r.beams[k / 3].dAlphaRad : k % 3 == 1 ? r.beams[k / 3].dBetaRad : r.beams[k / 3].dRhoM), e.sd[k]);
            QVERIFY2(std::fabs(e.v[k]) <= 3 * e.sd[k],
                     qPrintable(QString("%1: error %2, sigma %3").arg(kNames[k]).arg(e.v[k]).arg(e.sd[k])));
        }
        // The σ are what the simulated noise implies (derived by hand, 4 points per beam):
        //   horizontal per point √(σh² + (ρ·σatt)² + σorb²) = √(0.5² + 0.5² + 0.05²) = 0.709 m;
        //   σ(Δα) = 0.709 m / ρ / √4 ≈ 0.71 µrad (ρ ≈ 500 km);
        //   σ(Δβ) = 0.709 m / (ρ·sin 0.7°) / √4 ≈ 58 µrad;
        //   σ(Δρ) = √(σv² + σρ² + σorb²) / √4 = √(0.05² + 0.1² + 0.05²) / 2 ≈ 0.061 m.
        // Ranges vary by ±2 % with the pass geometry; the check allows 15 %.
        const double expect[3] = {0.709 / 500e3 / 2, 0.709 / (500e3 * std::sin(0.7 * kDeg)) / 2,
                                  std::sqrt(0.05 * 0.05 + 0.1 * 0.1 + 0.05 * 0.05) / 2};
        for (int k = 0; k < 6; ++k)
            QVERIFY2(std::fabs(e.sd[k] / expect[k % 3] - 1) < 0.15,
                     qPrintable(QString("%1: sigma %2, expected %3").arg(kNames[k]).arg(e.sd[k]).arg(expect[k % 3])));
        // Before: the design pointing misses by tens of metres (simulated errors); after: sub-metre.
        QVERIFY(r.iterations.front().rmsPlanM > 5);
        QVERIFY(r.iterations.back().rmsPlanM < 1.5);
        QVERIFY(r.iterations.back().rmsHeightM < 0.3);
        QCOMPARE(r.residuals.size(), s.points.size());
        QCOMPARE(r.iterations.front().residuals.size(), s.points.size());
    }

    // Paper 002: "converges in 3 iterations". Here too: at most 3 accepted steps, χ² never rising.
    void convergesInAFewIterations() {
        for (uint64_t seed = 1; seed <= 20; ++seed) {
            const auto s = sim::simulateCalibration({}, seed);
            PointingCalibParams p = s.matchingParams;
            p.model = CalibModel::DualBeam;
            const PointingCalibResult r = calibratePointing(s.beams, s.points, p);
            QVERIFY2(r.ok, r.error.c_str());
            QVERIFY(r.converged);
            QVERIFY2(r.iterations.size() - 1 <= 3, qPrintable(QString::number(r.iterations.size() - 1)));
            for (size_t i = 1; i < r.iterations.size(); ++i) QVERIFY(r.iterations[i].chi2 <= r.iterations[i - 1].chi2);
            QCOMPARE(r.iterations.front().params.size(), r.paramNames.size());
        }
    }

    // True error within 3σ in ≥ 95 % of seeded trials, for every parameter; and the σ neither
    // hides nor inflates the scatter (RMS error / RMS σ within 0.8..1.25).
    void uncertaintiesAreHonest() {
        const int trials = 200;
        int inside[6] = {0};
        double e2[6] = {0}, s2[6] = {0};
        for (int i = 0; i < trials; ++i) {
            const auto s = sim::simulateCalibration({}, sim::Rng::mix(2024, i));
            const PointingCalibResult r = calibratePointing(s.beams, s.points, s.matchingParams);
            QVERIFY2(r.ok, r.error.c_str());
            const Errors e = errorsOf(r, s);
            for (int k = 0; k < 6; ++k) {
                if (std::fabs(e.v[k]) <= 3 * e.sd[k]) ++inside[k];
                e2[k] += e.v[k] * e.v[k];
                s2[k] += e.sd[k] * e.sd[k];
            }
        }
        for (int k = 0; k < 6; ++k) {
            const double ratio = std::sqrt(e2[k] / s2[k]);
            qInfo("%s: within 3 sigma in %d of %d; RMS error / RMS sigma = %.3f", kNames[k], inside[k], trials, ratio);
            QVERIFY2(inside[k] >= 0.95 * trials, kNames[k]);
            QVERIFY2(ratio > 0.8 && ratio < 1.25, kNames[k]);
        }
    }

    void dualModelIsAReparametrisationOfTwoSingles() {
        const auto s = sim::simulateCalibration({}, 11);
        PointingCalibParams p = s.matchingParams;
        p.model = CalibModel::SingleBeam;
        const PointingCalibResult a = calibratePointing(s.beams, s.points, p);
        p.model = CalibModel::DualBeam;
        const PointingCalibResult b = calibratePointing(s.beams, s.points, p);
        QVERIFY(a.ok && b.ok);
        QCOMPARE(b.paramNames.size(), size_t(6));
        QCOMPARE(b.paramNames[3], std::string("rel_r"));
        // Same minimum (6 free parameters both ways): beams agree to 1 % of their σ.
        for (int k = 0; k < 2; ++k) {
            QVERIFY(std::fabs(a.beams[k].dAlphaRad - b.beams[k].dAlphaRad) < 0.01 * a.beams[k].dAlphaSdRad);
            QVERIFY(std::fabs(a.beams[k].dBetaRad - b.beams[k].dBetaRad) < 0.01 * a.beams[k].dBetaSdRad);
            QVERIFY(std::fabs(a.beams[k].dRhoM - b.beams[k].dRhoM) < 0.01 * a.beams[k].dRhoSdM);
            QVERIFY(std::fabs(a.beams[k].dAlphaSdRad / b.beams[k].dAlphaSdRad - 1) < 0.01);
        }
        QVERIFY(std::fabs(a.chi2 - b.chi2) < 1e-6 * a.chi2 + 1e-9);
    }

    void rigidBeamsWithTheRelativeRotationHeld() {
        // Make beam 2's true error the rigid image of beam 1's: u2 = ΔR0 · u1(true).
        sim::CalibSimParams sp;
        const auto beams = sim::gf7Beams();
        const Eigen::Vector3d u2 =
            dualBeamRotation(beams[0], beams[1], 0, 0, 0) * bodyPointing(beams[0], sp.dAlpha[0], sp.dBeta[0]);
        double a2, b2;
        pointingAngles(beams[1].laserToBody.inverse() * u2, &a2, &b2);
        sp.dAlpha[1] = a2 - beams[1].alphaRad;
        sp.dBeta[1] = std::remainder(b2 - beams[1].betaRad, 2 * M_PI);
        const auto s = sim::simulateCalibration(sp, 5);
        PointingCalibParams p = s.matchingParams;
        p.model = CalibModel::DualBeam;
        p.fixRelativeRotation = true;
        const PointingCalibResult rigid = calibratePointing(s.beams, s.points, p);
        QVERIFY2(rigid.ok, rigid.error.c_str());
        QCOMPARE(rigid.paramNames.size(), size_t(4));  // dα1, dβ1, dρ1, dρ2
        const Errors e = errorsOf(rigid, s);
        for (int k = 0; k < 6; ++k) QVERIFY2(std::fabs(e.v[k]) <= 3 * e.sd[k], kNames[k]);
        // Both beams' points now constrain one pointing: beam 1's σ(Δα) shrinks by about √2.
        p.fixRelativeRotation = false;
        const PointingCalibResult free = calibratePointing(s.beams, s.points, p);
        QVERIFY(free.ok);
        QVERIFY(rigid.beams[0].dAlphaSdRad < 0.85 * free.beams[0].dAlphaSdRad);
    }

    void coarseStepSolvesPointingOnly() {
        sim::CalibSimParams sp;
        sp.dRho[0] = sp.dRho[1] = 0;  // the coarse step assumes the range right
        const auto s = sim::simulateCalibration(sp, 3);
        PointingCalibParams p = s.matchingParams;
        p.solveRange = false;
        const PointingCalibResult r = calibratePointing(s.beams, s.points, p);
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.paramNames.size(), size_t(4));
        QVERIFY(!r.beams[0].rangeSolved);
        const Errors e = errorsOf(r, s);
        for (int k : {0, 1, 3, 4}) QVERIFY2(std::fabs(e.v[k]) <= 3 * e.sd[k], kNames[k]);
        // One control point per beam is enough for the coarse step (paper 002 §3.1).
        std::vector<ControlPoint> two = {s.points[0], s.points[1]};
        const PointingCalibResult one = calibratePointing(s.beams, two, p);
        QVERIFY2(one.ok, one.error.c_str());
    }

    void singularGeometriesAreClearErrors() {
        auto s = sim::simulateCalibration({}, 4);
        s.matchingParams.model = CalibModel::SingleBeam;
        // A beam pointing at nadir: its azimuth correction moves nothing.
        {
            auto beams = s.beams;
            beams[0].alphaRad = 0;
            const PointingCalibResult r = calibratePointing(beams, s.points, s.matchingParams);
            QVERIFY(!r.ok);
            QVERIFY2(r.error.find("singular") != std::string::npos && r.error.find("dbeta_b1") != std::string::npos,
                     r.error.c_str());
        }
        // The same control point repeated, heights unused: along-beam range and off-nadir angle
        // move the footprint the same way.
        {
            std::vector<ControlPoint> same(5, s.points[0]);
            for (auto& c : same) c.useHeight = false;
            const PointingCalibResult r = calibratePointing(s.beams, same, s.matchingParams);
            QVERIFY(!r.ok);
            QVERIFY2(r.error.find("singular") != std::string::npos, r.error.c_str());
        }
        // Too few equations.
        {
            std::vector<ControlPoint> one = {s.points[0]};
            one[0].useHeight = false;
            const PointingCalibResult r = calibratePointing(s.beams, one, s.matchingParams);
            QVERIFY(!r.ok);
            QVERIFY2(r.error.find("too few control points") != std::string::npos, r.error.c_str());
        }
        // Dual model without beam 2 points.
        {
            std::vector<ControlPoint> b1;
            for (const auto& c : s.points)
                if (c.beam == 1) b1.push_back(c);
            PointingCalibParams p = s.matchingParams;
            p.model = CalibModel::DualBeam;
            const PointingCalibResult r = calibratePointing(s.beams, b1, p);
            QVERIFY(!r.ok);
            QVERIFY2(r.error.find("beam 2 has no control points") != std::string::npos, r.error.c_str());
            // The single model calibrates beam 1 and says beam 2 was not.
            p.model = CalibModel::SingleBeam;
            const PointingCalibResult r1 = calibratePointing(s.beams, b1, p);
            QVERIFY2(r1.ok, r1.error.c_str());
            QVERIFY(!r1.beams[1].solved);
            QVERIFY(!r1.warnings.empty());
        }
        QVERIFY(!calibratePointing(s.beams, {}, s.matchingParams).ok);
    }

    void badInputsAreNamed() {
        const auto s = sim::simulateCalibration({}, 4);
        auto pts = s.points;
        pts[2].beam = 7;
        PointingCalibResult r = calibratePointing(s.beams, pts, s.matchingParams);
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("beam 7 has no design") != std::string::npos, r.error.c_str());
        pts = s.points;
        pts[1].shot.rangeM = NAN;
        r = calibratePointing(s.beams, pts, s.matchingParams);
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("non-finite") != std::string::npos, r.error.c_str());
        PointingCalibParams bad = s.matchingParams;
        bad.sigmaVerticalM = 0;
        QVERIFY(!calibratePointing(s.beams, s.points, bad).ok);
    }

    void csvAndJsonRoundTrip() {
        const auto s = sim::simulateCalibration({}, 6);
        const std::string cp = (m_dir.path() + "/cp.csv").toStdString(), bj = (m_dir.path() + "/beams.json").toStdString();
        std::string err;
        QVERIFY2(writeControlPointCsv(cp, s.points, &err), err.c_str());
        QVERIFY(writeFileAtomic(bj, beamsToJson(s.beams), &err));
        std::vector<ControlPoint> pts;
        std::vector<BeamDesign> beams;
        QVERIFY2(readControlPointCsv(cp, &pts, &err), err.c_str());
        QVERIFY2(readBeamsJson(bj, &beams, &err), err.c_str());
        QCOMPARE(pts.size(), s.points.size());
        QCOMPARE(beams.size(), size_t(2));
        const PointingCalibResult a = calibratePointing(s.beams, s.points, s.matchingParams);
        const PointingCalibResult b = calibratePointing(beams, pts, s.matchingParams);
        QVERIFY(a.ok && b.ok);
        // The file keeps 0.1 mm and 1e-15 of the quaternion: results agree to 1 % of σ.
        for (size_t j = 0; j < a.params.size(); ++j) QVERIFY(std::fabs(a.params[j] - b.params[j]) < 0.01 * a.paramSd[j]);
    }

    void malformedFilesNameTheLine() {
        const QString p = m_dir.path() + "/bad.csv";
        const QByteArray head = "beam,sat_x,sat_y,sat_z,q_w,q_x,q_y,q_z,range_m,gcp_x,gcp_y,gcp_z\n";
        std::vector<ControlPoint> pts;
        std::string err;
        QVERIFY(lwbtest::writeText(p, head + "1,1,2,3,1,0,0,0,500000,4,5,6\n1,1,2,3,0.5,0,0,0,500000,4,5,6\n"));
        QVERIFY(!readControlPointCsv(p.toStdString(), &pts, &err));
        QVERIFY2(err.find("bad.csv:3:") != std::string::npos && err.find("unit quaternion") != std::string::npos, err.c_str());
        QVERIFY(lwbtest::writeText(p, head + "1,1,2,3,1,0,0,0,nan,4,5,6\n"));
        QVERIFY(!readControlPointCsv(p.toStdString(), &pts, &err));
        QVERIFY2(err.find(":2:") != std::string::npos && err.find("range_m") != std::string::npos, err.c_str());
        QVERIFY(lwbtest::writeText(p, "beam,sat_x\n1,2\n"));
        QVERIFY(!readControlPointCsv(p.toStdString(), &pts, &err));
        QVERIFY2(err.find(":1:") != std::string::npos, err.c_str());
        const QString j = m_dir.path() + "/b.json";
        std::vector<BeamDesign> beams;
        QVERIFY(lwbtest::writeText(j, "{\"beams\": [{\"id\": 1, \"alpha_deg\": 0.7}]}"));
        QVERIFY(!readBeamsJson(j.toStdString(), &beams, &err));
        QVERIFY(lwbtest::writeText(j, "{\"beams\": [{\"id\": 1, \"alpha_deg\": 0.7, \"beta_deg\": 90,}]}"));
        QVERIFY(!readBeamsJson(j.toStdString(), &beams, &err));
        QVERIFY2(err.find("b.json:1:") != std::string::npos, err.c_str());
    }
};

QTEST_GUILESS_MAIN(TestCalibPointing)
#include "test_calib_pointing.moc"
