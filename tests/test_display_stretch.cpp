// Display limits and stretches (core/common/display_stretch): IRAF zscale on inputs whose answer
// follows by hand from the algorithm's description, and the stretch curves at points with known
// values.
#include <QtTest>
#include <cmath>
#include <vector>

#include "core/common/display_stretch.hpp"

using namespace lwb::core;

class TestDisplayStretch : public QObject {
    Q_OBJECT
private slots:
    void zscaleOfARampWithOutliers() {
        // Sorted samples: 0..999, then 20 outliers at 1e6. The first fit is pulled by the outliers,
        // they are rejected (grown by 1 % = 10 ranks), and the refit on 0..989 has slope 1 exactly.
        // n = 1020, centre rank 509, median 509.5: z1 = max(0, 509.5 - 509 / 0.25) = 0 and
        // z2 = min(1e6, 509.5 + 510 / 0.25) = 2549.5.
        std::vector<float> v;
        for (int i = 999; i >= 0; --i) v.push_back(float(i));  // unsorted input
        for (int i = 0; i < 20; ++i) v.insert(v.begin() + 37 * i, 1e6f);
        ZScaleParams p;
        p.maxSamples = 5000;
        const ZScaleResult r = zscale(v.data(), v.size(), p);
        QVERIFY(r.ok);
        QCOMPARE(r.samples, size_t(1020));
        QVERIFY(!r.fitFailed);
        QVERIFY(std::fabs(r.slope - 1.0) < 1e-9);
        QCOMPARE(r.used, size_t(990));
        QCOMPARE(r.z1, 0.0);
        QVERIFY(std::fabs(r.z2 - 2549.5) < 1e-6);
        // Contrast 1: the line itself, 509.5 -/+ 509 and 510 ranks.
        p.contrast = 1;
        const ZScaleResult r1 = zscale(v.data(), v.size(), p);
        QVERIFY(std::fabs(r1.z1 - 0.5) < 1e-6);
        QVERIFY(std::fabs(r1.z2 - 1019.5) < 1e-6);
    }

    void zscaleSamplesAtAStrideAndSkipsNonFinite() {
        // 100000 values of a ramp 0..99999 with every 7th a NaN: at most 1000 samples at stride 100.
        std::vector<float> v(100000);
        for (size_t i = 0; i < v.size(); ++i) v[i] = i % 7 == 3 ? NAN : float(i);
        const ZScaleResult r = zscale(v.data(), v.size());
        QVERIFY(r.ok);
        QVERIFY(r.samples <= 1000 && r.samples > 800);
        // Slope 100 DN per rank; the limits reach the sample's ends (contrast 0.25 widens 4x).
        QVERIFY(std::fabs(r.slope - 100) < 20);
        QCOMPARE(r.z1, 0.0);
        QVERIFY(r.z2 >= 99000);
    }

    void zscaleOfAConstantAndOfNothing() {
        std::vector<float> c(400, 123.f);
        const ZScaleResult r = zscale(c.data(), c.size());
        QVERIFY(r.ok);
        QCOMPARE(r.z1, 123.0);
        QCOMPARE(r.z2, 123.0);
        std::vector<float> nan(10, NAN);
        const ZScaleResult e = zscale(nan.data(), nan.size());
        QVERIFY(!e.ok);
        QVERIFY(!e.error.empty());
        QVERIFY(!zscale(nullptr, 0).ok);
    }

    void stretchesAtKnownPoints() {
        for (StretchKind k : {StretchKind::Linear, StretchKind::Sqrt, StretchKind::Log, StretchKind::Asinh}) {
            QCOMPARE(applyStretch(k, 0), 0.0);
            QVERIFY(std::fabs(applyStretch(k, 1) - 1) < 1e-12);
            QCOMPARE(applyStretch(k, -3), 0.0);  // clamped
            QVERIFY(std::fabs(applyStretch(k, 7) - 1) < 1e-12);
            double prev = -1;
            for (int i = 0; i <= 100; ++i) {  // monotonic, and the inverse undoes it
                const double x = i / 100.0, y = applyStretch(k, x);
                QVERIFY(y > prev);
                prev = y;
                QVERIFY2(std::fabs(invertStretch(k, y) - x) < 1e-9, stretchKindName(k));
            }
        }
        QCOMPARE(applyStretch(StretchKind::Linear, 0.25), 0.25);
        QCOMPARE(applyStretch(StretchKind::Sqrt, 0.25), 0.5);
        // log(a x + 1) / log(a + 1) with a = 99, x = 1/11: log(10) / log(100) = 1/2.
        StretchParams sp;
        sp.logExponent = 99;
        QVERIFY(std::fabs(applyStretch(StretchKind::Log, 1.0 / 11, sp) - 0.5) < 1e-12);
        // asinh(10 x) / asinh(10) at x = 0.1: asinh(1) = 0.881373587019543, asinh(10) = 2.99822295029797.
        QVERIFY(std::fabs(applyStretch(StretchKind::Asinh, 0.1) - 0.881373587019543 / 2.99822295029797) < 1e-12);
        // The bright end is compressed: log and asinh lift faint values above linear.
        QVERIFY(applyStretch(StretchKind::Log, 0.01) > 0.3);
        QVERIFY(applyStretch(StretchKind::Asinh, 0.01) > 0.03);
    }

    void limitsAndHistogram() {
        std::vector<float> v;
        for (int i = 0; i <= 100; ++i) v.push_back(float(i));
        v.push_back(NAN);
        const DisplayLimits mm = minMaxLimits(v.data(), v.size());
        QVERIFY(mm.ok);
        QCOMPARE(mm.lo, 0.0);
        QCOMPARE(mm.hi, 100.0);
        const DisplayLimits pc = percentileLimits(v.data(), v.size(), 10, 90);
        QVERIFY(pc.ok);
        QCOMPARE(pc.lo, 10.0);
        QCOMPARE(pc.hi, 90.0);
        const auto h = histogram(v.data(), v.size(), 0, 100, 4);  // bins of 25; 100 in the last
        QCOMPARE(int(h.size()), 4);
        QCOMPARE(int(h[0]), 25);
        QCOMPARE(int(h[3]), 26);
        QCOMPARE(int(h[0] + h[1] + h[2] + h[3]), 101);
    }
};

QTEST_MAIN(TestDisplayStretch)
#include "test_display_stretch.moc"
