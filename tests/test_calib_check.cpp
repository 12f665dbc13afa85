// Validation of a calibration on independent check points (paper 002 §3.3): with the exact
// corrections a noise-free simulation geolocates to its control points; with a calibration
// solved from other passes the height differences are at the simulated noise; bad input is
// named.
#include <QtTest>

#include "core/calib/calib_check.hpp"
#include "core/calib/validation_stats.hpp"
#include "core/sim/calib_sim.hpp"

using namespace lwb::core;
using namespace lwb::core::calib;

namespace {
// A calibration result holding the simulator's exact corrections.
PointingCalibResult exactCalibration(const sim::CalibSimulation& s) {
    PointingCalibResult r;
    r.ok = true;
    for (size_t k = 0; k < s.beams.size(); ++k) {
        BeamCalibration b;
        b.id = s.beams[k].id;
        b.solved = b.rangeSolved = true;
        b.alphaRad = s.beams[k].alphaRad + s.dAlpha[k];
        b.betaRad = s.beams[k].betaRad + s.dBeta[k];
        b.dRhoM = s.dRho[k];
        r.beams.push_back(b);
    }
    return r;
}
double rms(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return std::sqrt(s / v.size());
}
}  // namespace

class TestCalibCheck : public QObject {
    Q_OBJECT
private slots:
    void exactCorrectionsReproduceNoiseFreeControlPoints() {
        sim::CalibSimParams p;
        p.passes = 6;
        p.sigmaHorizontalM = p.sigmaVerticalM = p.sigmaRangeM = p.sigmaAttitudeRad = p.sigmaOrbitM = 0;
        const sim::CalibSimulation s = sim::simulateCalibration(p, 3);
        const CalibrationCheckResult r = checkCalibration(s.beams, exactCalibration(s), s.points);
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.points.size(), s.points.size());
        for (const auto& d : r.points) {
            QVERIFY2(std::fabs(d.e) < 1e-3 && std::fabs(d.n) < 1e-3 && std::fabs(d.u) < 1e-3,
                     qPrintable(QString("%1: %2 %3 %4").arg(d.id.c_str()).arg(d.e).arg(d.n).arg(d.u)));
            QCOMPARE(d.plan, std::hypot(d.e, d.n));
        }
        // The design values miss by the simulated errors: tens of metres in plan (40 µrad and
        // 2 mrad of azimuth at 0.7° off nadir from 500 km), about a metre in range.
        CalibrationCheckParams before;
        before.applyCalibration = false;
        const CalibrationCheckResult r0 = checkCalibration(s.beams, PointingCalibResult{}, s.points, before);
        QVERIFY2(r0.ok, r0.error.c_str());
        for (const auto& d : r0.points) QVERIFY2(d.plan > 5, qPrintable(QString::number(d.plan)));
        QCOMPARE(heightDifferences(r0, 1).size() + heightDifferences(r0, 2).size(), r0.points.size());
        QCOMPARE(heightDifferences(r0).size(), r0.points.size());
    }

    void calibrationFromOtherPassesValidatesAtTheNoiseLevel() {
        // Calibrate on 4 passes, validate on 22 independent ones (paper 002: 22 and 24 points).
        sim::CalibSimParams p;
        const sim::CalibSimulation cal = sim::simulateCalibration(p, 11);
        PointingCalibParams cp = cal.matchingParams;
        const PointingCalibResult calib = calibratePointing(cal.beams, cal.points, cp);
        QVERIFY2(calib.ok, calib.error.c_str());
        p.passes = 22;
        const sim::CalibSimulation val = sim::simulateCalibration(p, 12);
        const CalibrationCheckResult after = checkCalibration(val.beams, calib, val.points);
        QVERIFY2(after.ok, after.error.c_str());
        CalibrationCheckParams design;
        design.applyCalibration = false;
        const CalibrationCheckResult before = checkCalibration(val.beams, calib, val.points, design);
        QVERIFY(before.ok);
        for (int beam : {1, 2}) {
            const std::vector<double> d = heightDifferences(after, beam);
            QCOMPARE(int(d.size()), 22);
            const ElevationStatsResult st = elevationStats(d);
            QVERIFY(st.ok);
            // Range noise 0.1 m and survey 0.05 m: the differences scatter by ≈ 0.11 m; the
            // calibration's own error adds a few cm of bias at most.
            QVERIFY2(st.stats.rmsAboutZero < 0.25, qPrintable(QString::number(st.stats.rmsAboutZero)));
            QVERIFY2(st.stats.stdSample > 0.05, qPrintable(QString::number(st.stats.stdSample)));
            // Uncalibrated, the range bias (−1.0 / −1.3 m) dominates the height.
            QVERIFY(rms(heightDifferences(before, beam)) > 0.8);
        }
        double planAfter = 0, planBefore = 0;
        for (size_t i = 0; i < after.points.size(); ++i) {
            planAfter += after.points[i].plan / after.points.size();
            planBefore += before.points[i].plan / before.points.size();
        }
        QVERIFY2(planAfter < 3 && planBefore > 10, qPrintable(QString("%1 %2").arg(planAfter).arg(planBefore)));
    }

    void badInputIsNamed() {
        sim::CalibSimParams p;
        p.passes = 2;
        sim::CalibSimulation s = sim::simulateCalibration(p, 5);
        const PointingCalibResult exact = exactCalibration(s);
        std::vector<ControlPoint> pts = s.points;
        pts[1].beam = 3;
        pts[1].id = "P7";
        pts[1].line = 9;
        CalibrationCheckResult r = checkCalibration(s.beams, exact, pts);
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("P7") != std::string::npos && r.error.find("line 9") != std::string::npos &&
                     r.error.find("beam 3") != std::string::npos,
                 r.error.c_str());
        pts = s.points;
        pts[0].shot.rangeM = NAN;
        r = checkCalibration(s.beams, exact, pts);
        QVERIFY(!r.ok && r.error.find("non-finite") != std::string::npos);
        r = checkCalibration(s.beams, exact, {});
        QVERIFY(!r.ok && r.error.find("no check points") != std::string::npos);
        PointingCalibResult failed;
        failed.error = "singular geometry";
        r = checkCalibration(s.beams, failed, s.points);
        QVERIFY(!r.ok && r.error.find("singular geometry") != std::string::npos);
        PointingCalibResult unsolved = exact;
        unsolved.beams[1].solved = false;
        r = checkCalibration(s.beams, unsolved, s.points);
        QVERIFY(!r.ok && r.error.find("not calibrated") != std::string::npos);
        PointingCalibResult oneBeam = exact;
        oneBeam.beams.pop_back();
        r = checkCalibration(s.beams, oneBeam, s.points);
        QVERIFY(!r.ok && r.error.find("2") != std::string::npos);
    }
};

QTEST_MAIN(TestCalibCheck)
#include "test_calib_check.moc"
