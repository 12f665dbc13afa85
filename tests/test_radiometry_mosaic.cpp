// Row mosaic and GCP geometric correction (paper 003 §3.1): a textured synthetic scene cut into
// overlapping frames with exact offsets is mosaicked back and compared with the scene; affine and
// projective GCP fits recover known transforms; collinear / too few GCPs fail clearly.
#include <QtTest>
#include <algorithm>

#include "core/radiometry/gcp.hpp"
#include "core/radiometry/mosaic.hpp"
#include "core/common/rng.hpp"
#include "core/sim/scene_sim.hpp"
#include "test_support.hpp"

using namespace lwb::core;
using namespace lwb::core::radiometry;

namespace {
cv::Point2d apply(const cv::Matx33d& h, double x, double y) {
    const double w = h(2, 0) * x + h(2, 1) * y + h(2, 2);
    return {(h(0, 0) * x + h(0, 1) * y + h(0, 2)) / w, (h(1, 0) * x + h(1, 1) * y + h(1, 2)) / w};
}
std::vector<Gcp> gcpsFrom(const cv::Matx33d& imageToMap, const std::vector<cv::Point2d>& mapPts, double noisePx, uint64_t seed) {
    const cv::Matx33d inv = imageToMap.inv();
    sim::Rng rng(seed);
    std::vector<Gcp> g;
    for (size_t i = 0; i < mapPts.size(); ++i) {
        const cv::Point2d p = apply(inv, mapPts[i].x, mapPts[i].y);
        Gcp c;
        c.id = "M" + std::to_string(i + 1);
        c.x = p.x + rng.normal(0, noisePx);
        c.y = p.y + rng.normal(0, noisePx);
        c.mapX = mapPts[i].x;
        c.mapY = mapPts[i].y;
        g.push_back(c);
    }
    return g;
}
// Markers every 1 m on both sides of a 4 m long, 1.2 m wide strip (the rig's layout).
std::vector<cv::Point2d> markerLayout() {
    std::vector<cv::Point2d> m;
    for (int i = 0; i <= 4; ++i) {
        m.emplace_back(i, 0.0);
        m.emplace_back(i, 1.2);
    }
    return m;
}
}  // namespace

class TestRadiometryMosaic : public QObject {
    Q_OBJECT

private slots:
    void mosaicMatchesTheScene_data() {
        QTest::addColumn<int>("features");
        QTest::addColumn<int>("model");
        QTest::addColumn<int>("depth");
        QTest::addColumn<double>("offsetTolPx");
        QTest::addColumn<double>("maeTolDn");
        // Frames carry 30 DN of noise (16-bit); AKAZE keypoints localise to ~0.03 px, ORB's to
        // ~0.5 px (pyramid levels), so ORB gets a looser offset tolerance and the resampling blur
        // of a half-pixel error (~80 DN on this texture) in its pixel tolerance.
        QTest::newRow("akaze, similarity, 16-bit") << int(FeatureType::Akaze) << int(MotionModel::Similarity) << CV_16U << 0.25 << 40.0;
        QTest::newRow("akaze, translation, 8-bit") << int(FeatureType::Akaze) << int(MotionModel::Translation) << CV_8U << 0.25 << 1.0;
        QTest::newRow("orb, translation, 16-bit") << int(FeatureType::Orb) << int(MotionModel::Translation) << CV_16U << 1.0 << 150.0;
    }
    void mosaicMatchesTheScene() {
        QFETCH(int, features);
        QFETCH(int, model);
        QFETCH(int, depth);
        QFETCH(double, offsetTolPx);
        QFETCH(double, maeTolDn);
        sim::RowFramesParams rp;  // 6 frames of 400×360 px, 25 % overlap, ±4 px jitter
        rp.depth = depth;
        const sim::RowFrames rf = sim::simulateRowFrames(rp, {}, 11);
        MosaicParams mp;
        mp.features = FeatureType(features);
        mp.model = MotionModel(model);
        const MosaicResult r = mosaicRow(rf.frames, mp);
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.pairs.size(), rf.frames.size() - 1);
        QCOMPARE(r.image.depth(), depth);
        // Every frame's origin lands where the scene says, relative to frame 0.
        const cv::Point2d o0 = apply(r.frameToMosaic[0], 0, 0);
        double worst = 0;
        for (size_t k = 0; k < rf.frames.size(); ++k) {
            const cv::Point2d ok = apply(r.frameToMosaic[k], 0, 0) - o0;
            const cv::Point2d truth = rf.offsets[k] - rf.offsets[0];
            worst = std::max(worst, cv::norm(ok - truth));
        }
        qInfo("worst frame offset error %.3f px", worst);
        QVERIFY2(worst <= offsetTolPx, qPrintable(QString::number(worst)));
        // Frame 0 is placed on the pixel grid: mosaic (x, y) = scene (x − o0 + offset0).
        QCOMPARE(o0.x, std::round(o0.x));
        QCOMPARE(o0.y, std::round(o0.y));
        const double scale = depth == CV_8U ? 1.0 / 256 : 1.0;
        std::vector<double> diffs;
        cv::Mat m;
        r.image.convertTo(m, CV_64F);
        for (int y = 0; y < m.rows; ++y)
            for (int x = 0; x < m.cols; ++x) {
                if (!r.coverage.at<uchar>(y, x)) continue;
                const int sx = x - static_cast<int>(o0.x) + rf.offsets[0].x, sy = y - static_cast<int>(o0.y) + rf.offsets[0].y;
                if (sx < 0 || sy < 0 || sx >= rf.scene.cols || sy >= rf.scene.rows) continue;
                diffs.push_back(std::fabs(m.at<double>(y, x) - scale * rf.scene.at<float>(sy, sx)));
            }
        // Nearly all of the mosaic is covered and compared.
        const double union_ = rf.offsets.back().x - rf.offsets.front().x + rp.frameWidth;
        QVERIFY(diffs.size() > 0.9 * union_ * rp.frameHeight);
        double mae = 0;
        for (double d : diffs) mae += d;
        mae /= diffs.size();
        qInfo("mean |mosaic - scene| %.2f (frame noise %.2f)", mae, rp.noiseDn * scale);
        QVERIFY2(mae <= maeTolDn, qPrintable(QString::number(mae)));
    }

    void blendModesAgree() {
        const sim::RowFrames rf = sim::simulateRowFrames({}, {}, 12);
        MosaicParams mp;
        mp.blend = BlendMode::First;
        const MosaicResult a = mosaicRow(rf.frames, mp);
        mp.blend = BlendMode::Average;
        const MosaicResult b = mosaicRow(rf.frames, mp);
        QVERIFY(a.ok && b.ok);
        QCOMPARE(a.image.size(), b.image.size());
        cv::Mat d;
        cv::absdiff(a.image, b.image, d);
        // Only the overlaps differ, by about the frame noise (30 DN): mean well below 30.
        QVERIFY(cv::mean(d, a.coverage)[0] < 30);
        QCOMPARE(cv::countNonZero(a.coverage != b.coverage), 0);
    }

    void framesWithoutOverlapFailClearly() {
        const sim::RowFrames rf = sim::simulateRowFrames({}, {}, 13);
        std::vector<cv::Mat> frames = {rf.frames[0], rf.frames[3]};  // 900 px apart: nothing shared
        const MosaicResult r = mosaicRow(frames, {});
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("frames 1 and 2") != std::string::npos, r.error.c_str());
        QVERIFY(!mosaicRow({rf.frames[0]}, {}).ok);
        cv::Mat f8;
        rf.frames[1].convertTo(f8, CV_8U, 1.0 / 256);
        const MosaicResult mixed = mosaicRow({rf.frames[0], f8}, {});
        QVERIFY(!mixed.ok);
        QVERIFY2(mixed.error.find("depth") != std::string::npos, mixed.error.c_str());
    }

    void affineGcpsRecoverTheTransform() {
        // 3 mm/px, rotated 1.5°, slight shear; the marker layout; 0.3 px of GCP noise.
        const double s = 0.003, th = 1.5 * M_PI / 180;
        const cv::Matx33d truth(s * std::cos(th), -s * std::sin(th) + 0.00002, 0.5, -s * std::sin(th), -s * std::cos(th), 2.0,
                                0, 0, 1);
        const auto gcps = gcpsFrom(truth, markerLayout(), 0.3, 3);
        const GcpFitResult r = fitGcpTransform(gcps, {});
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.residuals.size(), gcps.size());
        QCOMPARE(r.dof, 2 * 10 - 6);
        // RMS residual ≈ noise · √(dof / 2n) = 0.3 · √(14/20) = 0.25 px; accept 0.1..0.5 px.
        QVERIFY2(r.rmsPx > 0.1 && r.rmsPx < 0.5, qPrintable(QString::number(r.rmsPx)));
        QVERIFY(std::fabs(r.rmsMap / r.rmsPx - s) < 0.1 * s);  // the same residuals in metres
        // The fitted transform agrees with the truth within 1 px anywhere on a 1500 x 450 px row.
        for (double x : {0.0, 750.0, 1500.0})
            for (double y : {0.0, 450.0}) {
                const cv::Point2d a = apply(r.imageToMap, x, y), b = apply(truth, x, y);
                QVERIFY(cv::norm(a - b) < s);
            }
        QVERIFY(std::fabs(r.metresPerPixel - s) < 0.01 * s);
    }

    // GCP outliers by leave-one-out (issue 27: one mark 1 km off among six went unnamed: its own
    // residual was 2.2 x RMS). 2000 sets of 6 marks on a 1600 x 300 px field, picked to 0.3 px
    // (Gaussian, each axis): flagged at most 1 % of the sets (gcp.outlier_p 0.001 per mark: 0.6 %
    // expected); with one mark moved by 20 px (67 sigma), that mark found in at least 95 % of the
    // sets and another flagged in at most 3 %. (Six marks leave the others 4 degrees of freedom:
    // a 5 px error is found in about 63 % of the sets, printed, not asserted.)
    void gcpOutliersByLeaveOneOut() {
        sim::Rng rng(27);
        int falseSets = 0, found = 0, wrong = 0, found5 = 0;
        const int sets = 2000;
        for (int s = 0; s < sets; ++s) {
            std::vector<Gcp> g;
            for (int k = 0; k < 6; ++k) {
                Gcp p;
                p.id = "G" + std::to_string(k + 1);
                const double x = rng.uniform(20, 1600), y = rng.uniform(20, 330);
                p.x = x + 0.3 * rng.normal();
                p.y = y + 0.3 * rng.normal();
                p.mapX = 0.01 * x + 0.0002 * y + 3;
                p.mapY = -0.01 * y + 0.0001 * x + 5;
                g.push_back(p);
            }
            const GcpFitResult clean = fitGcpTransform(g);
            QVERIFY(clean.ok);
            falseSets += !clean.outliers.empty();
            const int bad = static_cast<int>(rng.uniform(0, 6));
            std::vector<Gcp> g5 = g;
            g5[bad].x += 5 * std::cos(s * 0.7);
            g5[bad].y += 5 * std::sin(s * 0.7);
            const GcpFitResult off5 = fitGcpTransform(g5);
            found5 += std::count(off5.outliers.begin(), off5.outliers.end(), size_t(bad)) > 0;
            g[bad].x += 20 * std::cos(s * 0.7);
            g[bad].y += 20 * std::sin(s * 0.7);
            const GcpFitResult off = fitGcpTransform(g);
            QVERIFY(off.ok);
            found += std::count(off.outliers.begin(), off.outliers.end(), size_t(bad)) > 0;
            wrong += static_cast<int>(off.outliers.size()) - (std::count(off.outliers.begin(), off.outliers.end(), size_t(bad)) > 0);
        }
        qInfo("GCP outliers: clean sets flagged %.2f %%; a 20 px mark found in %.1f %% (other marks flagged %.2f %%); "
              "a 5 px mark found in %.1f %%",
              100.0 * falseSets / sets, 100.0 * found / sets, 100.0 * wrong / sets, 100.0 * found5 / sets);
        QVERIFY(falseSets <= sets / 100);
        QVERIFY(found >= sets * 95 / 100);
        QVERIFY(wrong <= sets * 3 / 100);
    }

    void homographyGcpsRecoverAPerspective() {
        const cv::Matx33d truth(0.003, 0.0001, 0.2, 0.00005, -0.0031, 1.8, 2e-5, 1e-5, 1);  // ~3 % scale change across the row
        const auto gcps = gcpsFrom(truth, markerLayout(), 0.0, 1);
        GcpFitParams p;
        p.model = GeoModel::Homography;
        const GcpFitResult r = fitGcpTransform(gcps, p);
        QVERIFY2(r.ok, r.error.c_str());
        // Exact data: residuals at the precision of OpenCV's solver (1.5e-5 px seen), far below 1e-3 px.
        QVERIFY2(r.rmsPx < 1e-3, qPrintable(QString::number(r.rmsPx)));
        // The affine model cannot follow the perspective: clearly larger residuals.
        const GcpFitResult a = fitGcpTransform(gcps, {});
        QVERIFY(a.ok);
        QVERIFY(a.rmsPx > 1);
    }

    void collinearAndTooFewGcpsFailClearly() {
        const cv::Matx33d truth(0.003, 0, 0, 0, -0.003, 2, 0, 0, 1);
        std::vector<cv::Point2d> line;
        for (int i = 0; i < 6; ++i) line.emplace_back(i, 0.0);  // one side of the field only
        const GcpFitResult c = fitGcpTransform(gcpsFrom(truth, line, 0.0, 1), {});
        QVERIFY(!c.ok);
        QVERIFY2(c.error.find("collinear") != std::string::npos, c.error.c_str());
        const GcpFitResult few = fitGcpTransform(gcpsFrom(truth, {{0, 0}, {1, 1}}, 0, 1), {});
        QVERIFY(!few.ok);
        QVERIFY2(few.error.find("at least 3") != std::string::npos, few.error.c_str());
        GcpFitParams h;
        h.model = GeoModel::Homography;
        const GcpFitResult three = fitGcpTransform(gcpsFrom(truth, {{0, 0}, {1, 0}, {2, 0}, {1, 1}}, 0, 1), h);
        QVERIFY(!three.ok);
        QVERIFY2(three.error.find("three of the four") != std::string::npos || three.error.find("collinear") != std::string::npos,
                 three.error.c_str());
        auto dup = gcpsFrom(truth, markerLayout(), 0, 1);
        dup[4].x = dup[2].x;
        dup[4].y = dup[2].y;
        const GcpFitResult d = fitGcpTransform(dup, {});
        QVERIFY(!d.ok);
        QVERIFY2(d.error.find("repeats") != std::string::npos, d.error.c_str());
        auto nan = gcpsFrom(truth, markerLayout(), 0, 1);
        nan[1].mapY = NAN;
        QVERIFY(!fitGcpTransform(nan, {}).ok);
    }

    void warpFollowsTheMapConventions() {
        // map X = 0.01·x + 2, map Y = 5 − 0.01·y (north up): on a 0.01 m grid the image comes
        // back pixel for pixel.
        const cv::Mat img = [] {
            cv::Mat m(40, 60, CV_16UC1);
            for (int y = 0; y < m.rows; ++y)
                for (int x = 0; x < m.cols; ++x) m.at<uint16_t>(y, x) = static_cast<uint16_t>(100 * x + y);
            return m;
        }();
        std::vector<Gcp> g;
        for (auto [x, y] : {std::pair{0, 0}, {59, 0}, {0, 39}, {59, 39}, {30, 20}}) {
            Gcp c;
            c.x = x;
            c.y = y;
            c.mapX = 0.01 * x + 2;
            c.mapY = 5 - 0.01 * y;
            g.push_back(c);
        }
        const GcpFitResult fit = fitGcpTransform(g, {});
        QVERIFY2(fit.ok, fit.error.c_str());
        const MapGrid grid = gridCovering(fit, img.size(), 0.01);
        QCOMPARE(grid.width, 60);
        QCOMPARE(grid.height, 40);
        QVERIFY(std::fabs(grid.originX - 2) < 1e-9 && std::fabs(grid.originY - 5) < 1e-9);
        const WarpResult w = warpToMap(img, fit, grid);
        QVERIFY2(w.ok, w.error.c_str());
        QCOMPARE(w.image.type(), CV_16UC1);
        QCOMPARE(cv::countNonZero(w.valid), 60 * 40);
        QCOMPARE(cv::norm(w.image, img, cv::NORM_INF), 0.0);
        // Two halves merge back into the whole.
        cv::Mat left = w.valid.clone(), right = w.valid.clone();
        left(cv::Rect(30, 0, 30, 40)).setTo(0);
        right(cv::Rect(0, 0, 30, 40)).setTo(0);
        const WarpResult merged = mergeOnGrid({w.image, w.image}, {left, right});
        QVERIFY(merged.ok);
        QCOMPARE(cv::norm(merged.image, img, cv::NORM_INF), 0.0);
        MapGrid huge = grid;
        huge.width = huge.height = 100000;
        QVERIFY(!warpToMap(img, fit, huge).ok);
    }
};

QTEST_GUILESS_MAIN(TestRadiometryMosaic)
#include "test_radiometry_mosaic.moc"
