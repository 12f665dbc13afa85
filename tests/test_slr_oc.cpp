// O-C of full-rate passes: light time with Earth rotation (checked on a synthetic pass built with
// an independent inertial-frame computation), the refraction model (IERS Conventions test
// values), the BLITS passes of 26-29 June 2012 against their CPF and SLRF2014, the fitted-trend
// fallback on the MLRS passes, and the O-C CSV reader/writer.
#include <QtTest>

#include <Eigen/Dense>
#include <QElapsedTimer>
#include <cmath>
#include <cstdio>

#include "core/slr/cpf.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/oc.hpp"
#include "core/slr/oc_csv.hpp"
#include "core/slr/refraction.hpp"
#include "core/slr/sinex.hpp"
#include "core/slr/slr_time.hpp"
#include "test_support.hpp"

using namespace lwb::core::slr;

namespace {

constexpr double kC = 299792458.0;
constexpr double kHalfC = kC / 2;  // two-way seconds -> one-way metres

/// RMS of the residual of a least-squares polynomial of `degree` in normalised time.
double polyResidualRms(const std::vector<double>& t, const std::vector<double>& y, int degree) {
    const Eigen::Index n = static_cast<Eigen::Index>(t.size());
    const double t0 = *std::min_element(t.begin(), t.end()), t1 = *std::max_element(t.begin(), t.end());
    Eigen::MatrixXd a(n, degree + 1);
    Eigen::VectorXd b(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double x = 2 * (t[static_cast<size_t>(i)] - t0) / (t1 - t0) - 1;
        double p = 1;
        for (int k = 0; k <= degree; ++k, p *= x) a(i, k) = p;
        b(i) = y[static_cast<size_t>(i)];
    }
    const Eigen::VectorXd c = a.colPivHouseholderQr().solve(b);
    return std::sqrt((b - a * c).squaredNorm() / static_cast<double>(n));
}

double mean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
}

struct Shared {
    CrdReadResult blits;
    CpfReadResult cpf;
    SinexReadResult snx;
};

/// A synthetic circular orbit (inertial) that passes through the zenith of `station` at tm.
struct SynthOrbit {
    Eigen::Vector3d u, v;  // orbit plane basis (inertial = ITRF at t = 0 of the day)
    double radius = 7.2e6, rate = 0;
    double tm = 0;
    Eigen::Vector3d inertial(double t) const {
        const double a = rate * (t - tm);
        return radius * (std::cos(a) * u + std::sin(a) * v);
    }
    /// Earth-fixed: rotate the inertial vector back by the Earth's angle w t.
    static Eigen::Vector3d toFixed(const Eigen::Vector3d& x, double t) {
        const double a = -kEarthRotationRate * t;
        return Eigen::Vector3d(std::cos(a) * x.x() - std::sin(a) * x.y(), std::sin(a) * x.x() + std::cos(a) * x.y(), x.z());
    }
    static Eigen::Vector3d toInertial(const Eigen::Vector3d& x, double t) { return toFixed(x, -t); }
};

}  // namespace

class TestSlrOc : public QObject {
    Q_OBJECT

    Shared m_shared;
    bool m_have = false;

    std::vector<const CrdPass*> blitsPasses() const {
        std::vector<const CrdPass*> out;
        for (const auto& p : m_shared.blits.file.passes)
            if (p.session.startYear == 2012 && p.session.startMonth == 6 && p.session.startDay >= 26 &&
                p.session.startDay <= 29)
                out.push_back(&p);
        return out;
    }

private slots:
    void initTestCase() {
        m_have = lwbtest::haveShared("slr/blits_201206.frd") && lwbtest::haveShared("slr/blits_cpf_120626_6801.hts") &&
                 lwbtest::haveShared("slr/SLRF2014_POS+VEL_2030.0_200428.snx");
        if (!m_have) return;
        m_shared.blits = readCrd(lwbtest::str(lwbtest::sharedPath("slr/blits_201206.frd")));
        m_shared.cpf = readCpf(lwbtest::str(lwbtest::sharedPath("slr/blits_cpf_120626_6801.hts")));
        m_shared.snx = readSinex(lwbtest::str(lwbtest::sharedPath("slr/SLRF2014_POS+VEL_2030.0_200428.snx")));
        QVERIFY2(m_shared.blits.ok, m_shared.blits.error.c_str());
        QVERIFY2(m_shared.cpf.ok, m_shared.cpf.error.c_str());
        QVERIFY2(m_shared.snx.ok, m_shared.snx.error.c_str());
    }

    // ---- refraction model: the IERS Conventions (2010) test cases ----------------------------
    void mendesPavlisIersTestCase() {
        // FCUL_ZD_HPA test case: McDonald Observatory, lat 30.67166667°, 798.4188 hPa, water vapour
        // 14.322 hPa, 0.532 µm -> ZTD 1.935225924846803 m, ZHD 1.932992176591644 m, ZWD 0.002233748255158704 m.
        // The routine's header gives the height as 2010.344 m, but its printed outputs are those of
        // 2003.344 m (a known slip of the upstream header; 2010.344 m gives 3.8 µm less delay).
        const ZenithDelay z = mendesPavlisZenithDelay(30.67166667 * M_PI / 180, 2003.344, 798.4188, 14.322, 0.532);
        QVERIFY(std::fabs(z.totalM - 1.935225924846803) < 1e-9);  // published to 1e-15; 1 nm covers round-off
        QVERIFY(std::fabs(z.hydrostaticM - 1.932992176591644) < 1e-9);
        QVERIFY(std::fabs(z.nonHydrostaticM - 0.002233748255158704) < 1e-9);
        // FCUL_A test case: lat 30.67166667°, height 2075 m, 300.15 K, elevation 15° -> 3.800243667312344.
        const double m = fculaMapping(30.67166667 * M_PI / 180, 2075, 300.15, 15 * M_PI / 180);
        QVERIFY(std::fabs(m - 3.800243667312344) < 1e-12);
        // Water vapour: 100 % at 20 °C, 1013.25 hPa: saturation 23.39 hPa (tables) x enhancement 1.004.
        QVERIFY(std::fabs(waterVapourPressureHpa(293.15, 100, 1013.25) - 23.39 * 1.0044) < 0.05);
        QVERIFY(std::fabs(waterVapourPressureHpa(293.15, 50, 1013.25) - 0.5 * waterVapourPressureHpa(293.15, 100, 1013.25)) <
                1e-12);
    }

    void geodeticHelpers() {
        // GRS80: a point 1000 m above latitude 40.6°, longitude 16.7°.
        const double lat = 40.6 * M_PI / 180, lon = 16.7 * M_PI / 180, h = 1000;
        const double a = 6378137.0, f = 1 / 298.257222101, e2 = f * (2 - f);
        const double n = a / std::sqrt(1 - e2 * std::sin(lat) * std::sin(lat));
        const Eigen::Vector3d x((n + h) * std::cos(lat) * std::cos(lon), (n + h) * std::cos(lat) * std::sin(lon),
                                (n * (1 - e2) + h) * std::sin(lat));
        const Geodetic g = geodeticFromEcef(x);
        QVERIFY(std::fabs(g.latitudeRad - lat) < 1e-11);
        QVERIFY(std::fabs(g.longitudeRad - lon) < 1e-12);
        QVERIFY(std::fabs(g.heightM - h) < 1e-6);
        // A target straight up is at 90°, one due east on the horizon at azimuth 90°, elevation 0.
        const Eigen::Vector3d up(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
        const Eigen::Vector3d east(-std::sin(lon), std::cos(lon), 0);
        double az = 0, el = 0;
        azimuthElevation(x, g, x + 1e6 * up, &az, &el);
        QVERIFY(std::fabs(el - M_PI / 2) < 1e-9);
        azimuthElevation(x, g, x + 1e6 * east, &az, &el);
        QVERIFY(std::fabs(el) < 1e-9);
        QVERIFY(std::fabs(az - M_PI / 2) < 1e-9);
    }

    // ---- light time with Earth rotation: synthetic pass, independent inertial computation ----
    void synthesisedPassHasZeroOc_data() {
        QTest::addColumn<int>("event");
        QTest::newRow("epoch = ground transmit (2)") << 2;
        QTest::newRow("epoch = ground receive (0)") << 0;
        QTest::newRow("epoch = spacecraft bounce (1)") << 1;
    }
    void synthesisedPassHasZeroOc() {
        QFETCH(int, event);
        const long mjd = mjdFromDate(2012, 6, 28);  // the day of the H4 below
        // Station: MLRO's SLRF2014 position (rounded), fixed on the Earth.
        const Eigen::Vector3d st(4641978.617, 1393067.723, 4133249.623);
        SynthOrbit o;
        o.tm = 40000.0;
        o.rate = std::sqrt(kEarthGm / std::pow(o.radius, 3));
        o.u = SynthOrbit::toInertial(st, o.tm).normalized();
        o.v = o.u.cross(Eigen::Vector3d(0.3, -0.2, 1.0)).normalized();
        // CPF: Earth-fixed positions every 30 s (the convention of the file: instantaneous, body-fixed).
        QByteArray cpf = "H1 CPF 2 TST 2012 6 28 0 1 1 synth\nH9\n";
        for (double t = 38000; t <= 42000; t += 30) {
            const Eigen::Vector3d x = SynthOrbit::toFixed(o.inertial(t), t);
            char line[160];
            std::snprintf(line, sizeof line, "10 0 %ld %.6f 0 %.6f %.6f %.6f\n", mjd, t, x.x(), x.y(), x.z());
            cpf += line;
        }
        const CpfReadResult c = parseCpf(cpf.toStdString(), "synth.cpf");
        QVERIFY2(c.ok, c.error.c_str());
        // Observations: exact two-way light time in the inertial frame (station moving with the Earth).
        auto station = [&](double t) { return SynthOrbit::toInertial(st, t); };
        QByteArray crd = "H1 CRD 2 2012 6 28 12\nH2 MLRO 7941 77 1 4 ILRS\nH3 synth 9999901 9999 99999 0 1 1\n"
                         "H4 0 2012 6 28 11 3 0 2012 6 28 11 10 0 0 0 0 0 1 0 2 0\nC0 0 532.000 std\n";
        int points = 0;
        for (double t = o.tm - 240; t <= o.tm + 240; t += 4.0 + 0.123) {
            // Durations, not differences of absolute times (whose last bit at 4e4 s is 7e-12 s).
            double up = 0, down = 0;
            if (event == 2) {  // t = transmit
                for (int k = 0; k < 20; ++k) up = (o.inertial(t + up) - station(t)).norm() / kC;
                for (int k = 0; k < 20; ++k) down = (station(t + up + down) - o.inertial(t + up)).norm() / kC;
            } else if (event == 0) {  // t = receive
                for (int k = 0; k < 20; ++k) down = (station(t) - o.inertial(t - down)).norm() / kC;
                for (int k = 0; k < 20; ++k) up = (o.inertial(t - down) - station(t - down - up)).norm() / kC;
            } else {  // t = bounce
                for (int k = 0; k < 20; ++k) up = (o.inertial(t) - station(t - up)).norm() / kC;
                for (int k = 0; k < 20; ++k) down = (station(t + down) - o.inertial(t)).norm() / kC;
            }
            const double tof = up + down;
            char line[160];
            std::snprintf(line, sizeof line, "10 %.12f %.15f std %d 2 0 0\n", t, tof, event);
            crd += line;
            ++points;
        }
        crd += "H8\nH9\n";
        const CrdReadResult r = parseCrd(crd.toStdString(), "synth.fr2");
        QVERIFY2(r.ok, r.error.c_str());
        OcParams p;
        p.refraction = RefractionModel::None;
        p.shapiro = false;
        const OcResult oc = computeOc(r.file.passes.front(), c.file, st, p);
        QVERIFY2(oc.ok, oc.error.c_str());
        QCOMPARE(static_cast<int>(oc.oc_s.size()), points);
        double worst = 0;
        for (double v : oc.oc_s) worst = std::max(worst, std::fabs(v));
        qInfo("synthetic pass, epoch event %d: worst |O-C| %.3g s (%.3g mm one-way)", event, worst, worst * kHalfC * 1e3);
        // Bound: the CRD fields are written to 1e-15 s (TOF) and 1e-12 s (epoch, x 7.4 km/s = 7 nm);
        // Lagrange at a 30 s step is exact to < 1 µm; the iteration stops at 1e-13 s.
        // 1e-13 s two-way = 0.015 mm (measured: 3e-15 s).
        QVERIFY(worst < 1e-13);
        // Elevation peaks near the (geocentric) zenith pass: 90° less the geodetic-geocentric
        // latitude difference (0.19°) and the 4 s sampling (~1.2°).
        QVERIFY(*std::max_element(oc.elevation_rad.begin(), oc.elevation_rad.end()) > 88 * M_PI / 180);

        // The same pass with the Earth's rotation ignored would be off by metres: the check has teeth.
        // (Shift the station by the rotation during the flight, ~ w r tau ~ 1.4 m, and compare.)
        const Eigen::Vector3d moved = SynthOrbit::toFixed(st, 0.005);
        const OcResult wrong = computeOc(r.file.passes.front(), c.file, moved, p);
        QVERIFY(wrong.ok);
        double worstWrong = 0;
        for (double v : wrong.oc_s) worstWrong = std::max(worstWrong, std::fabs(v));
        QVERIFY(worstWrong > 1e-10);
        // Shapiro delay on: a few mm, positive, computed > geometric so O-C decreases.
        p.shapiro = true;
        const OcResult rel = computeOc(r.file.passes.front(), c.file, st, p);
        QVERIFY(rel.ok);
        const double shapiroM = -mean(rel.oc_s) * kHalfC;
        QVERIFY2(shapiroM > 0.001 && shapiroM < 0.01, QByteArray::number(shapiroM).constData());
    }

    // A damaged prediction is refused with the record's line (issue 27): every position at the
    // Earth's centre, one record 1000 km (or 5 km) off the orbit, records out of time order. An
    // undamaged LEO prediction at a 240 s step (neighbours' interpolation good to ~100 m) passes.
    void damagedPredictionsAreRefused() {
        SynthOrbit o;
        o.tm = 40000.0;
        o.radius = 7.2e6;  // a 830 km LEO, BLITS-like: the hardest case for the interpolation
        o.rate = std::sqrt(kEarthGm / std::pow(o.radius, 3));
        o.u = Eigen::Vector3d(1, 0, 0);
        o.v = Eigen::Vector3d(0, 0.6, 0.8);
        auto text = [&](double offsetAt, double offsetM, bool zero, bool swap) {
            QByteArray cpf = "H1 CPF 2 TST 2012 6 28 0 1 1 synth\nH9\n";
            QList<QByteArray> recs;
            for (double t = 30000; t <= 50000; t += 240) {
                Eigen::Vector3d x = SynthOrbit::toFixed(o.inertial(t), t);
                if (t == offsetAt) x += offsetM * x.normalized();  // (outward: not into the Earth)
                if (zero) x.setZero();
                char line[160];
                std::snprintf(line, sizeof line, "10 0 56106 %.6f 0 %.3f %.3f %.3f\n", t, x.x(), x.y(), x.z());
                recs << line;
            }
            if (swap) std::swap(recs[40], recs[41]);
            for (const auto& r : recs) cpf += r;
            return (cpf + "99\n").toStdString();
        };
        CpfReadResult c = parseCpf(text(0, 0, false, false), "good.cpf");
        QVERIFY2(c.ok, c.error.c_str());
        QCOMPARE(QString::fromStdString(cpfPlausibilityProblem(c.file)), QString());
        // Line of the record at t = 30000 + 40 * 240 = 39600: the 41st record, line 43.
        for (double off : {1e6, 5e3}) {
            c = parseCpf(text(39600, off, false, false), "off.cpf");
            QVERIFY(c.ok);
            const QString why = QString::fromStdString(cpfPlausibilityProblem(c.file));
            QVERIFY2(why.startsWith("off.cpf:43:") && why.contains("off the orbit"), qPrintable(why));
        }
        // 500 m off is within what a real prediction's interpolation residual may be: not judged.
        c = parseCpf(text(39600, 500, false, false), "small.cpf");
        QCOMPARE(QString::fromStdString(cpfPlausibilityProblem(c.file)), QString());
        c = parseCpf(text(0, 0, true, false), "zero.cpf");
        QVERIFY(c.ok);
        QVERIFY2(QString::fromStdString(cpfPlausibilityProblem(c.file)).contains("inside the Earth"),
                 cpfPlausibilityProblem(c.file).c_str());
        c = parseCpf(text(0, 0, false, true), "swapped.cpf");
        QVERIFY(!c.ok);
        QVERIFY2(QString::fromStdString(c.error).startsWith("swapped.cpf:44:") && QString::fromStdString(c.error).contains("out of time order"),
                 c.error.c_str());
    }

    void ocParamsValidate() {
        OcParams p;
        QVERIFY(validate(p).empty());
        p.wavelengthNm = 100;
        QVERIFY(!validate(p).empty());
        p = OcParams();
        p.maxIterations = 0;
        QVERIFY(!validate(p).empty());
        TrendOcParams t;
        QVERIFY(validate(t).empty());
        t.degree = 0;
        QVERIFY(!validate(t).empty());
    }

    // ---- BLITS, 26-29 June 2012 -----------------------------------------------------------------
    void blitsPassesAreSmooth() {
        if (!m_have) QSKIP("shared SLR data absent (../shared/data/slr)");
        const auto passes = blitsPasses();
        QCOMPARE(passes.size(), size_t(7));  // 7 of the 54 passes fall within the CPF's 26 Jun - 1 Jul span
        for (const CrdPass* p : passes) {
            for (RefractionModel model : {RefractionModel::None, RefractionModel::MendesPavlis}) {
                OcParams params;
                params.refraction = model;
                const OcResult oc = computeOc(*p, m_shared.cpf.file, m_shared.snx.file, params);
                QVERIFY2(oc.ok, oc.error.c_str());
                QCOMPARE(oc.oc_s.size(), p->ranges.size());  // every record has an O-C
                QCOMPARE(oc.refractionApplied, model == RefractionModel::MendesPavlis);
                QCOMPARE(oc.stationCode, std::to_string(p->station.cdpPadId));
                for (size_t i = 0; i < oc.oc_s.size(); ++i) {
                    QVERIFY(oc.elevation_rad[i] > 5 * M_PI / 180 && oc.elevation_rad[i] < M_PI / 2);
                    QCOMPARE(oc.line[i], p->ranges[oc.range_index[i]].line);
                }
                const double rms = polyResidualRms(oc.epoch_s, oc.oc_s, 8) * kHalfC;
                const bool matm = p->station.cdpPadId == 7941;
                qInfo("%s %04d-%02d-%02d %02d:%02d  n=%zu  refraction %s  mean O-C %.3f m  deg-8 residual RMS %.2f mm",
                      p->station.name.c_str(), p->session.startYear, p->session.startMonth, p->session.startDay,
                      p->session.startHour, p->session.startMinute, oc.oc_s.size(),
                      model == RefractionModel::None ? "off" : "on ", mean(oc.oc_s) * kHalfC, rms * 1e3);
                // 2 cm one-way: single-shot ranging noise of these stations (CHAL/SJUL/POT3 ~1 cm).
                QVERIFY2(rms < 0.02, QByteArray::number(rms).constData());
                // MATM (MLRO, 7941): its calibration RMS in these three passes is 7.8-9.0 ps two-way
                // (1.2-1.35 mm one-way, the 40 records) and BLITS is a single-reflector target: 5 mm is
                // ~4x the calibration RMS and 4x tighter than the general bound (measured 2.7-3.5 mm).
                if (matm) QVERIFY2(rms < 0.005, QByteArray::number(rms).constData());
            }
        }
    }

    /// Computed elevations against MLRO's own pointing records (type 30, commanded from its prediction,
    /// not refraction-corrected): same geometry to 0.01° (the target moves <= 0.3°/s; 3 ms of flight
    /// between epoch and bounce is 0.001°).
    void blitsElevationMatchesStationPointing() {
        if (!m_have) QSKIP("shared SLR data absent");
        int compared = 0;
        for (const CrdPass* p : blitsPasses()) {
            if (p->station.cdpPadId != 7941) continue;
            OcParams params;
            params.refraction = RefractionModel::None;
            const OcResult oc = computeOc(*p, m_shared.cpf.file, m_shared.snx.file, params);
            QVERIFY2(oc.ok, oc.error.c_str());
            size_t j = 0;
            for (size_t i = 0; i < oc.oc_s.size(); ++i) {
                const double sod = p->ranges[oc.range_index[i]].secOfDay;
                while (j < p->pointing.size() && p->pointing[j].secOfDay < sod - 1e-6) ++j;
                if (j >= p->pointing.size() || std::fabs(p->pointing[j].secOfDay - sod) > 1e-6) continue;
                QVERIFY(std::fabs(oc.elevation_rad[i] * 180 / M_PI - p->pointing[j].elevationDeg) < 0.01);
                double daz = std::fabs(oc.azimuth_rad[i] * 180 / M_PI - p->pointing[j].azimuthDeg);
                daz = std::min(daz, 360 - daz);
                QVERIFY(daz * std::cos(oc.elevation_rad[i]) < 0.01);
                ++compared;
            }
        }
        QVERIFY(compared > 300);  // the three MATM passes have a pointing record for every range
    }

    /// Refraction: the correction is what the model gives at each point, it is the difference between
    /// the two O-C series, and its size is an optical zenith delay over sin(elevation).
    void blitsRefractionEffect() {
        if (!m_have) QSKIP("shared SLR data absent");
        for (const CrdPass* p : blitsPasses()) {
            OcParams off, on;
            off.refraction = RefractionModel::None;
            const OcResult a = computeOc(*p, m_shared.cpf.file, m_shared.snx.file, off);
            const OcResult b = computeOc(*p, m_shared.cpf.file, m_shared.snx.file, on);
            QVERIFY2(a.ok && b.ok, (a.error + b.error).c_str());
            QVERIFY(b.refractionApplied);
            QCOMPARE(b.wavelengthNm, p->configs.front().wavelengthNm);  // from the pass's C0
            double pmin = 1e9, pmax = 0;
            for (const auto& m : p->meteo) {
                pmin = std::min(pmin, m.pressureMbar);
                pmax = std::max(pmax, m.pressureMbar);
            }
            const Geodetic g = geodeticFromEcef(b.stationEcef);
            const double f = 1 - 0.00266 * std::cos(2 * g.latitudeRad) - 0.00000028 * g.heightM;
            for (size_t i = 0; i < b.oc_s.size(); ++i) {
                // O-C(off) - O-C(on) is the two-way delay that was added (round-off: 1e-15 s).
                QVERIFY(std::fabs((a.oc_s[i] - b.oc_s[i]) - b.refraction_s[i]) < 1e-14);
                QCOMPARE(a.refraction_s[i], 0.0);
                // One-way delay ~ 2.4166 mm/hPa x P / f / sin(e) at 532 nm (the hydrostatic term; the
                // wet term adds < 1 %): within 4 % down to 13° (FCULa vs 1/sin e: < 2.5 %).
                const double oneWay = b.refraction_s[i] * kHalfC;
                const double se = std::sin(b.elevation_rad[i]);
                QVERIFY(oneWay > 0.96 * 0.0024166 * pmin / f / se);
                QVERIFY(oneWay < 1.04 * 0.0024166 * pmax / f / se);
            }
            const double shift = (mean(a.oc_s) - mean(b.oc_s)) * kHalfC;
            qInfo("%s %02d-%02d %02d:%02d  O-C mean %.3f m -> %.3f m with refraction (shift %.3f m)",
                  p->station.name.c_str(), p->session.startMonth, p->session.startDay, p->session.startHour,
                  p->session.startMinute, mean(a.oc_s) * kHalfC, mean(b.oc_s) * kHalfC, shift);
            // Shift = the mean one-way delay: 2.1..2.5 m zenith over sin(13..63°) -> 2.3..10.5 m.
            QVERIFY(shift > 2.0 && shift < 11.0);
        }
    }

    /// Refraction, pass by pass. The O-C mean alone is a poor judge: the CPF's along-track error
    /// (a time bias) and its radial error (a range bias) move it by metres. Both are removed
    /// here by a least-squares fit O-C = b + tau * d(TOF)/dt (range bias b, time bias tau; the
    /// TOF rate from a degree-10 polynomial of the observed TOF, which is the prediction's rate
    /// to far better than needed); what is left holds the elevation-dependent part, which a
    /// bias and a time bias cannot absorb (the delay goes as ~1/sin e: metres at 15 deg, 2.3 m
    /// at the zenith). The Mendes-Pavlis correction must leave the smaller residual on every
    /// pass of 26-29 June.
    void blitsRefractionAfterBiasFit() {
        if (!m_have) QSKIP("shared SLR data absent");
        int passes = 0;
        QString failed;
        for (const CrdPass* p : blitsPasses()) {
            OcParams off, on;
            off.refraction = RefractionModel::None;
            const OcResult a = computeOc(*p, m_shared.cpf.file, m_shared.snx.file, off);
            const OcResult b = computeOc(*p, m_shared.cpf.file, m_shared.snx.file, on);
            QVERIFY2(a.ok && b.ok, (a.error + b.error).c_str());
            QVERIFY(b.refractionApplied);
            const Eigen::Index n = static_cast<Eigen::Index>(a.oc_s.size());
            // d(TOF)/dt from a degree-10 polynomial of the TOF in normalised time.
            const double t0 = a.epoch_s.front(), t1 = a.epoch_s.back(), half = 0.5 * (t1 - t0), mid = 0.5 * (t0 + t1);
            const int deg = 10;
            Eigen::MatrixXd v(n, deg + 1);
            Eigen::VectorXd tof(n);
            for (Eigen::Index i = 0; i < n; ++i) {
                const double x = (a.epoch_s[size_t(i)] - mid) / half;
                double pw = 1;
                for (int k = 0; k <= deg; ++k, pw *= x) v(i, k) = pw;
                tof(i) = a.tof_s[size_t(i)];
            }
            const Eigen::VectorXd c = v.colPivHouseholderQr().solve(tof);
            Eigen::MatrixXd design(n, 2);
            for (Eigen::Index i = 0; i < n; ++i) {
                const double x = (a.epoch_s[size_t(i)] - mid) / half;
                double rate = 0, pw = 1;
                for (int k = 1; k <= deg; ++k, pw *= x) rate += k * c(k) * pw;
                design(i, 0) = 1;
                design(i, 1) = rate / half;  // s of TOF per s
            }
            auto residualRms = [&](const std::vector<double>& oc, double* bias, double* tau) {
                Eigen::VectorXd y(n);
                for (Eigen::Index i = 0; i < n; ++i) y(i) = oc[size_t(i)];
                const Eigen::Vector2d s = design.colPivHouseholderQr().solve(y);
                *bias = s(0);
                *tau = s(1);
                return std::sqrt((y - design * s).squaredNorm() / static_cast<double>(n));
            };
            double bOff = 0, tauOff = 0, bOn = 0, tauOn = 0;
            const double rmsOff = residualRms(a.oc_s, &bOff, &tauOff) * kHalfC;
            const double rmsOn = residualRms(b.oc_s, &bOn, &tauOn) * kHalfC;
            double emin = 90, emax = 0;
            for (double e : b.elevation_rad) {
                emin = std::min(emin, e * 180 / M_PI);
                emax = std::max(emax, e * 180 / M_PI);
            }
            qInfo("%s %02d-%02d %02d:%02d  elevation %.0f-%.0f deg  after range bias + time bias: residual RMS %.1f mm "
                  "(refraction off) -> %.1f mm (on); range bias %.3f -> %.3f m, time bias %.2f -> %.2f ms",
                  p->station.name.c_str(), p->session.startMonth, p->session.startDay, p->session.startHour,
                  p->session.startMinute, emin, emax, rmsOff * 1e3, rmsOn * 1e3, bOff * kHalfC, bOn * kHalfC, tauOff * 1e3,
                  tauOn * 1e3);
            if (!(rmsOn < rmsOff))
                failed += QString("%1 %2-%3 %4:%5 (%6 mm on vs %7 mm off); ").arg(p->station.name.c_str()).arg(p->session.startMonth)
                              .arg(p->session.startDay).arg(p->session.startHour).arg(p->session.startMinute)
                              .arg(rmsOn * 1e3, 0, 'f', 1).arg(rmsOff * 1e3, 0, 'f', 1);
            ++passes;
        }
        QCOMPARE(passes, 7);
        // Measured (2026-11): refraction on lowers the residual on MATM 06-27/06-28/06-29 and SJUL
        // 06-26, not on CHAL 06-27, POT3 06-26, SJUL 06-27: there the residual after b + tau is
        // 65 mm - 0.7 m, i.e. the CPF's error over those passes is not a range bias plus a time
        // bias (it curves), and what is left is larger than and correlated with the few-cm
        // elevation signature of the refraction. Kept as a known failure, not loosened.
        QEXPECT_FAIL("", "CPF error beyond a range bias + time bias on CHAL 06-27, POT3 06-26, SJUL 06-27", Continue);
        QVERIFY2(failed.isEmpty(), qPrintable("refraction does not reduce the residual on: " + failed));
    }

    void blitsErrors() {
        if (!m_have) QSKIP("shared SLR data absent");
        // A pass outside the prediction span: an error saying by how much.
        const CrdPass* early = nullptr;
        for (const auto& p : m_shared.blits.file.passes)
            if (p.session.startDay == 2) early = &p;
        QVERIFY(early);
        const OcResult r = computeOc(*early, m_shared.cpf.file, m_shared.snx.file, OcParams());
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("s before the first prediction record") != std::string::npos, r.error.c_str());
        // A station that is not in the SINEX file.
        CrdPass p = *blitsPasses().front();
        p.station.cdpPadId = 1234;
        const OcResult s = computeOc(p, m_shared.cpf.file, m_shared.snx.file, OcParams());
        QVERIFY(!s.ok);
        QVERIFY2(s.error.find("1234") != std::string::npos, s.error.c_str());
        // No met records: refraction is switched off with a warning, the O-C still computed.
        p = *blitsPasses().front();
        p.meteo.clear();
        const OcResult m = computeOc(p, m_shared.cpf.file, m_shared.snx.file, OcParams());
        QVERIFY2(m.ok, m.error.c_str());
        QVERIFY(!m.refractionApplied);
        bool warned = false;
        for (const auto& w : m.warnings) warned |= w.find("no usable met") != std::string::npos;
        QVERIFY(warned);
        // One-way epoch events are skipped with a warning.
        p = *blitsPasses().front();
        p.ranges.setEpochEvent(0, 3);
        const OcResult e = computeOc(p, m_shared.cpf.file, m_shared.snx.file, OcParams());
        QVERIFY(e.ok);
        QCOMPARE(e.oc_s.size(), p.ranges.size() - 1);
        // A station position that is not on the Earth.
        QVERIFY(!computeOc(p, m_shared.cpf.file, Eigen::Vector3d(0, 0, 0), OcParams()).ok);
        // Cancellation.
        lwb::core::Feedback fb;
        fb.cancel();
        const OcResult c = computeOc(p, m_shared.cpf.file, m_shared.snx.file, OcParams(), &fb);
        QVERIFY(!c.ok);
    }

    // ---- no prediction: O-C against a fitted trend ----------------------------------------------
    void trendFallbackOnMlrsPasses_data() {
        QTest::addColumn<QString>("file");
        QTest::newRow("JASON1") << "7080_JASON1_crd_071220_2033_0.frd";
        QTest::newRow("STELLA") << "7080_STELLA_crd_071220_2128_0.frd";
        QTest::newRow("Beacon-C") << "7080_Beacon-C_crd_071220_1715_0.frd";
        QTest::newRow("beaconc 3 passes") << "beaconc_20070511.frd";
    }
    void trendFallbackOnMlrsPasses() {
        QFETCH(QString, file);
        if (!lwbtest::haveShared("slr/" + file)) QSKIP("shared SLR data absent");
        const CrdReadResult r = readCrd(lwbtest::str(lwbtest::sharedPath("slr/" + file)));
        QVERIFY2(r.ok, r.error.c_str());
        for (const CrdPass& p : r.file.passes) {
            const OcResult oc = computeTrendOc(p, TrendOcParams());
            QVERIFY2(oc.ok, oc.error.c_str());
            QCOMPARE(oc.method, OcMethod::FittedTrend);
            QCOMPARE(oc.oc_s.size(), p.ranges.size());
            // What the O-C is relative to is a note, not a warning about the file (issue 42).
            bool noted = false, warned = false;
            for (const auto& n : oc.notes) noted |= n.find("relative to a robust") != std::string::npos;
            for (const auto& w : oc.warnings) warned |= w.find("relative to a robust") != std::string::npos;
            QVERIFY(noted);
            QVERIFY(!warned);
            // The filter flags are not used: clearing them gives the same O-C.
            CrdPass blind = p;
            for (size_t k = 0; k < blind.ranges.size(); ++k) blind.ranges.setFilterFlag(k, 0);
            const OcResult oc2 = computeTrendOc(blind, TrendOcParams());
            QVERIFY(oc2.ok);
            QVERIFY(oc2.oc_s == oc.oc_s);
            // The station's signal (flag 2) lies on a smooth, nearly straight track: its RMS about a
            // quadratic is < 3 % of the spread of the noise (flag 1) in the range gate (measured <= 1.2 %).
            std::vector<double> ts, os;
            double lo = 1e9, hi = -1e9;
            for (size_t i = 0; i < oc.oc_s.size(); ++i) {
                if (oc.filter_flag[i] == 2) {
                    ts.push_back(oc.epoch_s[i]);
                    os.push_back(oc.oc_s[i]);
                } else if (oc.filter_flag[i] == 1) {
                    lo = std::min(lo, oc.oc_s[i]);
                    hi = std::max(hi, oc.oc_s[i]);
                }
            }
            const double track = polyResidualRms(ts, os, 2);
            qInfo("%s %02d:%02d  trend degree %d  signal RMS about a quadratic %.1f ns, noise spread %.0f ns",
                  p.station.name.c_str(), p.session.startHour, p.session.startMinute, oc.trendDegree, track * 1e9,
                  (hi - lo) * 1e9);
            QVERIFY(hi - lo > 1e-6);  // the MLRS range gate is several microseconds wide
            QVERIFY(track < 0.03 * (hi - lo));
            // Elevation from the pass's pointing records: a column per point where the pass has
            // them, none where it has not (issue 44); no refraction from a trend.
            QCOMPARE(oc.elevation_rad.size(), p.pointing.empty() ? size_t(0) : oc.oc_s.size());
            QCOMPARE(oc.azimuth_rad.size(), oc.elevation_rad.size());
            QVERIFY(oc.refraction_s.empty());
            for (double e : oc.elevation_rad) QVERIFY(e > 0 && e < M_PI / 2);
        }
    }

    /// A pass of more records than a trend's robust fit takes (TrendOcParams::fitMaxPoints, 20 000:
    /// a kHz pass) is fitted on every k-th record and its residuals computed for all (the fit's
    /// QRs of the whole pass took 20 s of a 10^6-event pass). Measured here on real BLITS passes
    /// of 1200+ records with the limit lowered to 400: with the polynomial alone, and with the arc
    /// where both fits choose the same model, the trend at every station-flagged point is within
    /// half the whole fit's robust scale of the whole pass's (a fit of k coefficients to m
    /// records is uncertain by about scale * sqrt(k / m), 0.11 scale for 5 of 400; its worst
    /// over the pass a few times that: 0.15-0.43 measured, 15-124 ps). Which model is chosen may
    /// differ: on one pass the arc at the search's lowest rate (with the Earth's rotation terms,
    /// 49 ps) passes the orbit check (arcIsAnOrbit) for one fit and misses it for the other, so
    /// that the whole pass keeps its polynomial (288 ps); at most one pass may differ so. (No
    /// BLITS pass this long takes the arc under both fits: the arc's sampled path runs there
    /// only on that pass.)
    void trendOfALongPassFromEvenlyTakenRecords() {
        if (!lwbtest::haveShared("slr/blits_201206.frd")) QSKIP("shared SLR data absent");
        const CrdReadResult r = readCrd(lwbtest::str(lwbtest::sharedPath("slr/blits_201206.frd")));
        QVERIFY2(r.ok, r.error.c_str());
        int compared = 0, otherModel = 0;
        for (const bool arc : {false, true}) {
            TrendOcParams whole, sampled;
            whole.orbitArc = sampled.orbitArc = arc;
            sampled.fitMaxPoints = 400;
            for (const CrdPass& p : r.file.passes) {
                if (p.ranges.size() < 1200) continue;  // (at least 3 records for every one fitted)
                const OcResult a = computeTrendOc(p, whole);
                const OcResult b = computeTrendOc(p, sampled);
                QVERIFY2(a.ok && b.ok, (a.error + b.error).c_str());
                QCOMPARE(b.oc_s.size(), p.ranges.size());
                const bool arcA = std::isfinite(a.trendArcRateRadS), arcB = std::isfinite(b.trendArcRateRadS);
                if (arcA != arcB || a.trendDegree != b.trendDegree) {
                    qInfo("%zu records: the models differ (whole pass: %s, %.0f ps; 400 records: %s, %.0f ps)", p.ranges.size(),
                          arcA ? "arc" : "polynomial", a.trendScaleS * 1e12, arcB ? "arc" : "polynomial", b.trendScaleS * 1e12);
                    ++otherModel;
                    continue;
                }
                double worst = 0;
                for (size_t i = 0; i < p.ranges.size(); ++i)
                    if (a.filter_flag[i] == 2) worst = std::max(worst, std::fabs(b.oc_s[i] - a.oc_s[i]));
                qInfo("%zu records, %s: the trend of 400 of them within %.1f ps of the whole pass's at the station's "
                      "signal (%.2f of its robust scale)",
                      p.ranges.size(), arcA ? "arc" : "polynomial", worst * 1e12, worst / a.trendScaleS);
                QVERIFY2(worst < 0.5 * a.trendScaleS,
                         qPrintable(QString("%1 ps, scale %2 ps").arg(worst * 1e12).arg(a.trendScaleS * 1e12)));
                ++compared;
            }
        }
        QVERIFY(compared >= 12);
        QVERIFY(otherModel <= 1);
    }

    void trendFallbackErrors() {
        CrdPass p;
        p.session.startYear = 2020, p.session.startMonth = 1, p.session.startDay = 1;
        for (int i = 0; i < 4; ++i) {  // one fewer than a pass needs (kMinPassPoints = 5)
            CrdRange r;
            r.secOfDay = 100 + i;
            r.tofS = 0.01;
            p.ranges.push_back(r);
        }
        const OcResult a = computeTrendOc(p, TrendOcParams());
        QVERIFY(!a.ok);
        QVERIFY2(a.error.find("at least 5") != std::string::npos, a.error.c_str());
        CrdRanges oneEpoch;
        for (CrdRange r : p.ranges) {
            r.secOfDay = 100;
            oneEpoch.push_back(r);
        }
        p.ranges = oneEpoch;
        TrendOcParams tp;
        tp.minPoints = 3;
        const OcResult b = computeTrendOc(p, tp);
        QVERIFY(!b.ok);
        QVERIFY2(b.error.find("one epoch") != std::string::npos, b.error.c_str());
    }

    // ---- O-C CSV --------------------------------------------------------------------------------
    void ocCsvRoundTrip() {
        // A real O-C series when the shared data are here, else a synthetic one.
        OcTable t;
        if (m_have) {
            const OcResult oc = computeOc(*blitsPasses().front(), m_shared.cpf.file, m_shared.snx.file, OcParams());
            QVERIFY2(oc.ok, oc.error.c_str());
            t = ocTableFrom(oc);
        } else {
            for (int i = 0; i < 1000; ++i) {
                t.epoch_s.push_back(40000 + i * 0.1234567891);
                t.oc_s.push_back(1e-9 * std::sin(i * 0.37));
            }
            t.extraNames = {"elevation_deg"};
            t.extra = {std::vector<double>(1000, 42.0)};
        }
        t.extra.front()[3] = NAN;  // an absent value is written as an empty field
        QTemporaryDir dir;
        const std::string path = lwbtest::str(dir.filePath("oc.csv"));
        std::string err;
        QVERIFY2(writeOcCsv(path, t, &err), err.c_str());
        QCOMPARE(lwbtest::filesIn(dir.path()), QStringList{"oc.csv"});
        OcCsvParams params;
        params.extraColumns = t.extraNames;
        const OcCsvReadResult r = readOcCsv(path, params);
        QVERIFY2(r.ok, r.error.c_str());
        QVERIFY(r.table.epoch_s == t.epoch_s);  // shortest round-trip text: the same doubles
        QVERIFY(r.table.oc_s == t.oc_s);
        QCOMPARE(r.table.extra.size(), t.extra.size());
        QVERIFY(std::isnan(r.table.extra.front()[3]));
        for (size_t k = 0; k < t.extra.size(); ++k)
            for (size_t i = 0; i < t.extra[k].size(); ++i)
                if (i != 3 || k != 0) QCOMPARE(r.table.extra[k][i], t.extra[k][i]);
        QCOMPARE(r.table.line.front(), 2L);
        // Inconsistent tables are refused.
        OcTable bad = t;
        bad.oc_s.pop_back();
        QVERIFY(!writeOcCsv(path, bad, &err));
    }

    void ocCsvFlexibleHeader() {
        const OcCsvReadResult r = parseOcCsv("\xEF\xBB\xBF# comment line\r\n"
                                             "station, OC_S ,\"note, with comma\",epoch_s\r\n"
                                             "\r\n"
                                             "MATM,1.5e-9,\"x, y\",40000.25\r\n"
                                             "MATM,-2e-10,z,+40000.5\r\n",
                                             "f.csv");
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.table.epoch_s.size(), size_t(2));
        QCOMPARE(r.table.epoch_s[0], 40000.25);
        QCOMPARE(r.table.oc_s[0], 1.5e-9);
        QCOMPARE(r.table.epoch_s[1], 40000.5);
        QCOMPARE(r.table.oc_s[1], -2e-10);
        QCOMPARE(r.table.line[0], 4L);
        QCOMPARE(r.table.line[1], 5L);
    }

    void ocCsvErrors_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("where");
        QTest::addColumn<QString>("what");
        const QByteArray h = "epoch_s,oc_s\n";
        QTest::newRow("NaN") << h + "1,2e-9\n2,NaN\n" << "c.csv:3:" << "oc_s is not a finite number";
        QTest::newRow("nan lower") << h + "nan,2e-9\n" << "c.csv:2:" << "epoch_s";
        QTest::newRow("inf") << h + "1,inf\n" << "c.csv:2:" << "not a finite number";
        QTest::newRow("-infinity") << h + "1,-Infinity\n" << "c.csv:2:" << "not a finite number";
        QTest::newRow("overflow") << h + "1,1e999\n" << "c.csv:2:" << "not a finite number";
        QTest::newRow("text") << h + "1,2\n# ok\n3,abc\n" << "c.csv:4:" << "\"abc\"";
        QTest::newRow("trailing garbage") << h + "1,2x\n" << "c.csv:2:" << "not a finite number";
        QTest::newRow("empty field") << h + "1,\n" << "c.csv:2:" << "oc_s";
        QTest::newRow("hex") << h + "0x10,1\n" << "c.csv:2:" << "epoch_s";
        QTest::newRow("two signs") << h + "+-1,1\n" << "c.csv:2:" << "epoch_s";
        QTest::newRow("too few fields") << h + "1,2\n3\n" << "c.csv:3:" << "1 fields, the header has 2";
        QTest::newRow("too many fields") << h + "1,2,3\n" << "c.csv:2:" << "3 fields";
        QTest::newRow("no epoch column") << QByteArray("t,oc_s\n1,2\n") << "c.csv:1:" << "epoch_s and oc_s";
        QTest::newRow("duplicate column") << QByteArray("epoch_s,oc_s,oc_s\n1,2,3\n") << "c.csv:1:" << "twice";
        QTest::newRow("unterminated quote") << h + "\"1,2\n" << "c.csv:2:" << "unterminated";
        QTest::newRow("header only") << h << "c.csv:" << "no data rows";
        QTest::newRow("empty") << QByteArray() << "c.csv:" << "empty file";
        QTest::newRow("binary") << QByteArray("epoch_s,oc_s\n1,\x00\x02\n", 18) << "c.csv:2:" << "binary";
    }
    void ocCsvErrors() {
        QFETCH(QByteArray, text);
        QFETCH(QString, where);
        QFETCH(QString, what);
        const OcCsvReadResult r = parseOcCsv(std::string_view(text.constData(), static_cast<size_t>(text.size())), "c.csv");
        QVERIFY(!r.ok);
        QVERIFY2(QString::fromStdString(r.error).startsWith(where), r.error.c_str());
        QVERIFY2(QString::fromStdString(r.error).contains(what), r.error.c_str());
        OcCsvParams p;
        p.extraColumns = {"elevation"};
        QVERIFY(!parseOcCsv("epoch_s,oc_s\n1,2\n", "c.csv", p).ok);  // a requested column must exist
        p.extraColumns = {"OC_S"};
        QVERIFY(!validate(p).empty());
    }

    /// A table past 1 MB is parsed in stretches on the cores: its rows, their line numbers
    /// (comments and blank lines counted) and its first error in file order are those of one
    /// pass through the file. Line numbers were counted per stretch in the first version.
    void ocCsvLongTableInStretches() {
        std::string text = "# a long table\nepoch_s,oc_s\n";
        std::vector<long> lines;
        long line = 2;
        const size_t n = 60000;  // about 1.6 MB: 8 stretches
        char buf[64];
        for (size_t i = 0; i < n; ++i) {
            if (i % 997 == 0) {
                text += "# comment\n\n";
                line += 2;
            }
            const int len = std::snprintf(buf, sizeof buf, "%zu.5,%zu.25e-9\r\n", i, i % 1000);
            text.append(buf, static_cast<size_t>(len));
            lines.push_back(++line);
        }
        QVERIFY(text.size() > (1u << 20));
        OcCsvReadResult r = parseOcCsv(text, "long.csv");
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.table.epoch_s.size(), n);
        QVERIFY(r.table.line == lines);
        for (size_t i : {size_t(0), size_t(7499), size_t(7500), size_t(31234), n - 1}) {
            QCOMPARE(r.table.epoch_s[i], static_cast<double>(i) + 0.5);
            std::snprintf(buf, sizeof buf, "%zu.25e-9", i % 1000);
            QCOMPARE(r.table.oc_s[i], std::strtod(buf, nullptr));
        }
        // Two bad rows far apart: the first in the file is reported, with its line.
        auto rowAt = [&](size_t i) {
            std::snprintf(buf, sizeof buf, "\n%zu.5,%zu.25e-9\r\n", i, i % 1000);
            return text.find(buf) + 1;
        };
        std::string bad = text;
        bad.replace(rowAt(52000), std::to_string(52000).size(), "x");
        bad.replace(rowAt(41000), std::to_string(41000).size(), "y");
        r = parseOcCsv(bad, "long.csv");
        QVERIFY(!r.ok);
        QVERIFY2(QString::fromStdString(r.error).startsWith(QString("long.csv:%1: epoch_s is not a finite number").arg(lines[41000])),
                 r.error.c_str());
    }

    /// 10^6 rows: read completely and correctly. The time is printed, not asserted (benchmarks belong
    /// elsewhere).
    void ocCsvMillionRows() {
        const size_t n = 1000000;
        std::string text = "epoch_s,oc_s,elevation_deg\n";
        text.reserve(n * 48);
        char buf[96];
        for (size_t i = 0; i < n; ++i) {
            const int len = std::snprintf(buf, sizeof buf, "%.6f,%.6e,%.3f\n", 30000.0 + 0.001 * static_cast<double>(i),
                                          1e-9 * std::sin(static_cast<double>(i) * 1e-3), 20.0 + static_cast<double>(i % 700) * 0.1);
            text.append(buf, static_cast<size_t>(len));
        }
        QTemporaryDir dir;
        const QString path = dir.filePath("million.csv");
        QVERIFY(lwbtest::writeText(path, QByteArray::fromStdString(text)));
        QElapsedTimer timer;
        timer.start();
        const OcCsvReadResult r = readOcCsv(lwbtest::str(path));
        const qint64 ms = timer.elapsed();
        QVERIFY2(r.ok, r.error.c_str());
        qInfo("O-C CSV: %zu rows (%.1f MB) read and parsed in %lld ms", r.table.epoch_s.size(), text.size() / 1e6,
              static_cast<long long>(ms));
        QCOMPARE(r.table.epoch_s.size(), n);
        QCOMPARE(r.table.epoch_s[123456], 30123.456);  // "%.6f" of 30123.456 reads back to the nearest double
        std::snprintf(buf, sizeof buf, "%.6e", 1e-9 * std::sin(999999 * 1e-3));
        QCOMPARE(r.table.oc_s.back(), std::strtod(buf, nullptr));
        QCOMPARE(r.table.line.back(), static_cast<long>(n + 1));
    }
};

QTEST_GUILESS_MAIN(TestSlrOc)
#include "test_slr_oc.moc"
