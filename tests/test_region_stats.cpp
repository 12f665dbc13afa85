// Region statistics (core/common/region_stats): box and circle regions on a 6 × 5 ramp
// v(x, y) = 10 y + x, whose answers follow by hand; a region partly or wholly outside the image,
// NaN pixels, edges, and the pixel types.
#include <QtTest>
#include <cmath>
#include <limits>

#include "core/common/region_stats.hpp"

using namespace lwb::core;

namespace {
cv::Mat ramp() {
    cv::Mat m(5, 6, CV_32FC1);
    for (int y = 0; y < m.rows; ++y)
        for (int x = 0; x < m.cols; ++x) m.at<float>(y, x) = float(10 * y + x);
    return m;
}

RegionStatsParams box(double cx, double cy, double w, double h) {
    RegionStatsParams p;
    p.shape = RegionShape::Box;
    p.centerX = cx;
    p.centerY = cy;
    p.width = w;
    p.height = h;
    return p;
}

RegionStatsParams circle(double cx, double cy, double r) {
    RegionStatsParams p;
    p.shape = RegionShape::Circle;
    p.centerX = cx;
    p.centerY = cy;
    p.radius = r;
    return p;
}

bool near(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)); }
}  // namespace

class TestRegionStats : public QObject {
    Q_OBJECT
private slots:
    void boxInside() {
        // x in [0.5, 4.5) -> 1..4, y in [0.5, 2.5) -> 1, 2: 11..14 and 21..24.
        const RegionStatsResult r = regionStats(ramp(), box(2.5, 1.5, 4, 2));
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.count, size_t(8));
        QCOMPARE(r.outside, size_t(0));
        QCOMPARE(r.nonFinite, size_t(0));
        QCOMPARE(r.sum, 140.0);
        QCOMPARE(r.mean, 17.5);
        QCOMPARE(r.median, 17.5);  // (14 + 21) / 2
        QCOMPARE(r.min, 11.0);
        QCOMPARE(r.max, 24.0);
        QVERIFY(near(r.stddev, std::sqrt(30.0)));  // squares 2 (6.5² + 5.5² + 4.5² + 3.5²) = 210, / 7
        QVERIFY(r.centroidOk);
        QVERIFY(near(r.centroidX, 360.0 / 140));  // (130 + 230) / 140
        QVERIFY(near(r.centroidY, 230.0 / 140));  // (50·1 + 90·2) / 140
    }

    void boxOfIntegerSizeTakesThatManyPixelsAnywhere() {
        for (double dx : {0.0, 0.1, 0.25, 0.5, 0.75, 0.99})
            for (double dy : {0.0, 0.3, 0.5, 0.8}) {
                const RegionStatsResult r = regionStats(ramp(), box(2.5 + dx, 2 + dy, 3, 2));
                QVERIFY(r.ok);
                QCOMPARE(r.count + r.outside, size_t(6));
            }
        // A box whose edges fall on pixel centres: the low edge is in, the high edge out.
        const RegionStatsResult r = regionStats(ramp(), box(2, 2, 2, 2));  // x, y in [1, 3)
        QCOMPARE(r.count, size_t(4));
        QCOMPARE(r.sum, 11.0 + 12 + 21 + 22);
    }

    void boxPartlyOutside() {
        // x in [3, 7) -> 3..6, y in [2, 6) -> 2..5; the image has x <= 5, y <= 4: 9 inside, 7 outside.
        const RegionStatsResult r = regionStats(ramp(), box(5, 4, 4, 4));
        QVERIFY(r.ok);
        QCOMPARE(r.count, size_t(9));
        QCOMPARE(r.outside, size_t(7));
        QCOMPARE(r.sum, 306.0);
        QCOMPARE(r.mean, 34.0);
        QCOMPARE(r.median, 34.0);
        QCOMPARE(r.min, 23.0);
        QCOMPARE(r.max, 45.0);
        QVERIFY(near(r.stddev, std::sqrt(606.0 / 8)));
        QVERIFY(near(r.centroidX, 1230.0 / 306));
        QVERIFY(near(r.centroidY, 978.0 / 306));
    }

    void circleInsideAndOnItsEdge() {
        // Radius 1 about (2, 2): the centre and its four neighbours, 22 21 23 12 32.
        RegionStatsResult r = regionStats(ramp(), circle(2, 2, 1));
        QVERIFY(r.ok);
        QCOMPARE(r.count, size_t(5));
        QCOMPARE(r.sum, 110.0);
        QCOMPARE(r.median, 22.0);
        QCOMPARE(r.min, 12.0);
        QCOMPARE(r.max, 32.0);
        QVERIFY(near(r.stddev, std::sqrt(202.0 / 4)));
        QVERIFY(near(r.centroidX, 222.0 / 110));
        QVERIFY(near(r.centroidY, 240.0 / 110));
        // Radius √2: the diagonal neighbours lie on the edge and are in (the 3 × 3 block).
        r = regionStats(ramp(), circle(2, 2, std::sqrt(2.0)));
        QCOMPARE(r.count, size_t(9));
        QCOMPARE(r.sum, 198.0);
        QCOMPARE(r.mean, 22.0);
        r = regionStats(ramp(), circle(2, 2, 1.4));
        QCOMPARE(r.count, size_t(5));
    }

    void circlePartlyOutside() {
        // About the top-left pixel with radius 1: (0,0), (1,0), (0,1) inside; (−1,0), (0,−1) outside.
        const RegionStatsResult r = regionStats(ramp(), circle(0, 0, 1));
        QVERIFY(r.ok);
        QCOMPARE(r.count, size_t(3));
        QCOMPARE(r.outside, size_t(2));
        QCOMPARE(r.sum, 11.0);
        QCOMPARE(r.min, 0.0);
        QCOMPARE(r.median, 1.0);
        QVERIFY(near(r.centroidX, 1.0 / 11));
        QVERIFY(near(r.centroidY, 10.0 / 11));
    }

    void nanPixelsAreLeftOutAndCounted() {
        cv::Mat m = ramp();
        m.at<float>(1, 2) = std::numeric_limits<float>::quiet_NaN();  // x = 2, y = 1: the 12
        m.at<float>(2, 4) = std::numeric_limits<float>::infinity();   // x = 4, y = 2: the 24
        const RegionStatsResult r = regionStats(m, box(2.5, 1.5, 4, 2));
        QVERIFY(r.ok);
        QCOMPARE(r.count, size_t(6));
        QCOMPARE(r.nonFinite, size_t(2));
        QCOMPARE(r.sum, 104.0);  // 140 − 12 − 24
        QCOMPARE(r.min, 11.0);
        QCOMPARE(r.max, 23.0);
        QCOMPARE(r.median, (14.0 + 21) / 2);  // 11 13 14 21 22 23
        QVERIFY(std::isfinite(r.stddev) && std::isfinite(r.centroidX));
        // Only NaN inside: not ok, and says so.
        cv::Mat n(3, 3, CV_32FC1, cv::Scalar(std::numeric_limits<float>::quiet_NaN()));
        const RegionStatsResult all = regionStats(n, box(1, 1, 3, 3));
        QVERIFY(!all.ok);
        QCOMPARE(all.nonFinite, size_t(9));
        QVERIFY(all.error.find("NaN") != std::string::npos);
    }

    void outsideBadInputAndNoCentroid() {
        const RegionStatsResult out = regionStats(ramp(), box(20, 20, 2, 3));
        QVERIFY(!out.ok);
        QCOMPARE(out.count, size_t(0));
        QCOMPARE(out.outside, size_t(6));
        QVERIFY(!regionStats(cv::Mat(), box(1, 1, 1, 1)).ok);
        QVERIFY(!regionStats(ramp(), box(1, 1, -1, 1)).ok);
        QVERIFY(!regionStats(ramp(), circle(std::nan(""), 1, 1)).ok);
        QVERIFY(!regionStats(cv::Mat(3, 3, CV_8UC3), box(1, 1, 1, 1)).ok);
        QVERIFY(!regionStats(ramp(), box(1, 1, 1e12, 1)).ok);
        // A zero-size box holds no pixel centre.
        QVERIFY(!regionStats(ramp(), box(2, 2, 0, 0)).ok);
        // Values summing to zero or less: no value-weighted centroid, the rest as usual.
        const cv::Mat neg = ramp() - 30;
        const RegionStatsResult r = regionStats(neg, box(2.5, 1.5, 4, 2));
        QVERIFY(r.ok);
        QVERIFY(!r.centroidOk);
        QCOMPARE(r.mean, 17.5 - 30);
    }

    void pixelTypesGiveTheSameAnswer() {
        const cv::Mat f = ramp();
        for (int type : {CV_8UC1, CV_16UC1, CV_16SC1, CV_32SC1, CV_64FC1}) {
            cv::Mat m;
            f.convertTo(m, type);
            const RegionStatsResult r = regionStats(m, box(2.5, 1.5, 4, 2));
            QVERIFY(r.ok);
            QCOMPARE(r.sum, 140.0);
            QCOMPARE(r.median, 17.5);
        }
    }
};

QTEST_MAIN(TestRegionStats)
#include "test_region_stats.moc"
