// Footprint input: every file format, ROI extraction, and the bad inputs that must fail clearly.
#include <QtTest>
#include <sys/resource.h>
#include <unistd.h>
#include <opencv2/imgcodecs.hpp>

#include "core/footprint/image_io.hpp"
#include "core/footprint/footprint_run.hpp"
#include "core/footprint/pipeline.hpp"
#include "core/footprint/roi.hpp"
#include "core/sim/footprint_sim.hpp"
#include "test_support.hpp"

using namespace lwb::core;
using namespace lwb::core::footprint;

namespace {
cv::Mat shotImage(uint64_t seed, int size = 32, sim::Scene scene = sim::Scene::Weak, sim::FootprintSimTruth* t = nullptr) {
    sim::FootprintSimParams p;
    p.width = p.height = size;
    p.scene = scene;
    const auto s = sim::simulateFootprint(p, seed);
    if (t) *t = s.truth;
    return s.image;
}
}  // namespace

class TestFootprintIo : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.path() + "/" + name; }

private slots:
    // Issue 41: 2 GiB sparse inputs were read whole before their header said no. A frame file
    // larger than any frame within the pixel limit could be (8 bytes a pixel and 1 MB) is
    // refused from its size; a raw frame whose size is not its pixels' likewise, unread.
    void oversizedFrameFilesRefusedUnread() {
        const std::string big = lwbtest::str(path("sparse.png"));
        QVERIFY(lwbtest::writeText(path("sparse.png"), QByteArray("\x89PNG\r\n\x1a\n", 8)));
        QCOMPARE(::truncate(big.c_str(), 2LL << 30), 0);
        struct rusage before {}, after {};
        getrusage(RUSAGE_SELF, &before);
        ImageReadParams p;
        const ImageReadResult r = readFrame(big, p);
        getrusage(RUSAGE_SELF, &after);
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("2147483648 bytes: larger than a frame of at most 16777216 pixels") != std::string::npos,
                 r.error.c_str());
        QVERIFY2(after.ru_maxrss - before.ru_maxrss < 16 * 1024, "the file was read");
        const std::string raw = lwbtest::str(path("sparse.raw"));
        QVERIFY(lwbtest::writeText(path("sparse.raw"), QByteArray(10, '\x01')));
        QCOMPARE(::truncate(raw.c_str(), 1LL << 24), 0);
        p.rawWidth = p.rawHeight = 550;
        const ImageReadResult rr = readFrame(raw, p);
        QVERIFY(!rr.ok);
        QVERIFY2(rr.error.find("raw file holds 16777216 bytes, but 550x550 16-bit pixels need 605000") != std::string::npos,
                 rr.error.c_str());
        QFile::remove(path("sparse.png"));
        QFile::remove(path("sparse.raw"));
    }

    void everyFormatReadsTheSamePixels_data() {
        QTest::addColumn<QString>("ext");
        QTest::newRow("png") << "png";
        QTest::newRow("tif") << "tif";
        QTest::newRow("tiff") << "tiff";
        QTest::newRow("pgm") << "pgm";
        QTest::newRow("raw") << "raw";
    }
    void everyFormatReadsTheSamePixels() {
        QFETCH(QString, ext);
        const cv::Mat img = shotImage(5);
        const std::string file = path("frame." + ext).toStdString();
        std::string err;
        QVERIFY2(writeFrame16(file, img, &err), err.c_str());
        ImageReadParams rp;
        rp.rawWidth = rp.rawHeight = 32;
        const ImageReadResult r = readFrame(file, rp);
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.image.type(), CV_32FC1);
        cv::Mat back;
        r.image.convertTo(back, CV_16U);
        QCOMPARE(cv::countNonZero(back != img), 0);  // bit-exact in every format
        QVERIFY(r.maxValue <= 16383);                 // 14-bit data kept as it is, not rescaled
    }

    void fourteenBitValuesAreNotRescaled() {
        cv::Mat img(8, 8, CV_16UC1, cv::Scalar(100));
        img.at<uint16_t>(3, 4) = 16383;
        std::string err;
        QVERIFY(writeFrame16(path("fourteen.png").toStdString(), img, &err));
        const ImageReadResult r = readFrame(path("fourteen.png").toStdString());
        QVERIFY(r.ok);
        QCOMPARE(r.image.at<float>(3, 4), 16383.0f);
        QCOMPARE(r.image.at<float>(0, 0), 100.0f);
    }

    void badInputsFailWithTheReason_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("expect");
        QTest::newRow("missing") << "nothere.png" << "no such file";
        QTest::newRow("8-bit") << "eight.png" << "8-bit";
        QTest::newRow("rgb") << "rgb.png" << "3-channel";
        QTest::newRow("all zero") << "zero.png" << "all zero";
        // (said as truncated, where it ends, before the decoder sees it: issue 42)
        QTest::newRow("truncated png") << "trunc.png" << "truncated PNG: the file ends inside its IDAT chunk";
        QTest::newRow("text as png") << "text.png" << "not a readable image";
        QTest::newRow("empty") << "empty.png" << "empty file";
        QTest::newRow("raw wrong size") << "short.raw" << "bytes";
        QTest::newRow("folder") << "." << "folder";
    }
    void badInputsFailWithTheReason() {
        QFETCH(QString, name);
        QFETCH(QString, expect);
        cv::imwrite(path("eight.png").toStdString(), cv::Mat(16, 16, CV_8UC1, cv::Scalar(90)));
        cv::imwrite(path("rgb.png").toStdString(), cv::Mat(16, 16, CV_16UC3, cv::Scalar(900, 800, 700)));
        cv::imwrite(path("zero.png").toStdString(), cv::Mat::zeros(16, 16, CV_16UC1));
        std::vector<uchar> png;
        cv::imencode(".png", shotImage(3), png);
        lwbtest::writeText(path("trunc.png"), QByteArray(reinterpret_cast<const char*>(png.data()), int(png.size() / 2)));
        lwbtest::writeText(path("text.png"), "this is not an image\n");
        lwbtest::writeText(path("empty.png"), "");
        lwbtest::writeText(path("short.raw"), QByteArray(100, '\1'));
        ImageReadParams rp;
        rp.rawWidth = rp.rawHeight = 32;
        const std::string file = name == "." ? m_dir.path().toStdString() : path(name).toStdString();
        const ImageReadResult r = readFrame(file, rp);
        QVERIFY(!r.ok);
        QVERIFY2(QString::fromStdString(r.error).contains(expect), r.error.c_str());
        QVERIFY2(QString::fromStdString(r.error).startsWith(QString::fromStdString(file)), r.error.c_str());
    }

    void rawNeedsItsSize() {
        std::string err;
        QVERIFY(writeFrame16(path("noSize.raw").toStdString(), shotImage(4), &err));
        const ImageReadResult r = readFrame(path("noSize.raw").toStdString());
        QVERIFY(!r.ok);
        QVERIFY(QString::fromStdString(r.error).contains("--raw-size"));
    }

    void roiAroundNominalCentre() {
        sim::FootprintSimTruth t;
        sim::FootprintSimParams p;
        p.width = p.height = 550;
        p.hasCenter = true;
        p.centerX = 122;
        p.centerY = 262;
        const auto shot = sim::simulateFootprint(p, 17);
        cv::Mat f;
        shot.image.convertTo(f, CV_32F);
        RoiParams rp;
        rp.hasCenter = true;
        rp.centerX = 122;
        rp.centerY = 262;
        const RoiResult r = extractRoi(f, rp);
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.roi.cols, 32);
        QCOMPARE(r.originX, 122 - 16);
        QCOMPARE(r.originY, 262 - 16);
        // The blob search finds the spot on a textured 550×550 frame without a centre.
        RoiParams search;
        const RoiResult s = extractRoi(f, search);
        QVERIFY(s.ok && s.searched);
        const double cx = s.originX + 15.5, cy = s.originY + 15.5;
        QVERIFY2(std::hypot(cx - shot.truth.x, cy - shot.truth.y) < 4.0, "blob search missed the spot");
    }

    void floatTiffFrames() {
        // 32-bit float TIFF is accepted; a ROI whose values spread over less than one DN (a
        // calibrated product, say) once overran the background histogram (review finding).
        cv::Mat flat(32, 32, CV_32F);
        cv::randu(flat, cv::Scalar(100.0), cv::Scalar(100.7));
        QVERIFY(cv::imwrite(path("flat.tif").toStdString(), flat));
        ImageReadResult r = readFrame(path("flat.tif").toStdString());
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.storedBits, 32);
        const FootprintResult fr = processRoi(r.image, FootprintParams{});
        QVERIFY(fr.ok);
        QVERIFY(fr.background.level >= 100 && fr.background.level <= 100.7);
        QCOMPARE(fr.verdict, Verdict::Rejected);  // no spot in flat noise
        // A float frame with a spot: the same centre as the 16-bit one.
        sim::FootprintSimTruth t;
        cv::Mat spot16 = shotImage(21, 32, sim::Scene::Night, &t), spotF;
        spot16.convertTo(spotF, CV_32F);
        QVERIFY(cv::imwrite(path("spot.tif").toStdString(), spotF));
        r = readFrame(path("spot.tif").toStdString());
        QVERIFY2(r.ok, r.error.c_str());
        const FootprintResult sr = processRoi(r.image, FootprintParams{});
        QVERIFY(sr.fit.ok);
        QVERIFY(std::hypot(sr.fit.x - t.x, sr.fit.y - t.y) < 0.3);
    }

    void roiEdgeCases() {
        cv::Mat f;
        shotImage(8).convertTo(f, CV_32F);
        RoiParams big;
        big.size = 64;
        big.sizeExplicit = true;
        RoiResult r = extractRoi(f, big);
        QVERIFY(!r.ok);
        QVERIFY2(QString::fromStdString(r.error).contains("larger than the image"), r.error.c_str());
        // Default size on a smaller ready ROI: taken whole.
        cv::Mat small = f(cv::Rect(4, 4, 24, 24)).clone();
        r = extractRoi(small, RoiParams{});
        QVERIFY(r.ok && r.wholeImage);
        // A centre near the frame edge shifts the ROI inside, with a warning.
        cv::Mat frame(100, 100, CV_32F, cv::Scalar(500));
        RoiParams edge;
        edge.hasCenter = true;
        edge.centerX = 3;
        edge.centerY = 50;
        r = extractRoi(frame, edge);
        QVERIFY(r.ok);
        QCOMPARE(r.originX, 0);
        QCOMPARE(r.warnings.size(), size_t(1));
        edge.centerX = 150;  // outside
        QVERIFY(!extractRoi(frame, edge).ok);
    }

    void processFrameGivesFullImageCoordinates() {
        sim::FootprintSimParams p;
        p.width = p.height = 550;
        p.hasCenter = true;
        p.centerX = 300.4;
        p.centerY = 140.7;
        const auto shot = sim::simulateFootprint(p, 23);
        cv::Mat f;
        shot.image.convertTo(f, CV_32F);
        const auto res = processFrame(f, FootprintParams{}, {cv::Point2d(300, 141)});
        QCOMPARE(res.size(), size_t(1));
        QVERIFY(res[0].result.ok && res[0].result.fit.ok);
        const double x = res[0].result.fit.x + res[0].originX, y = res[0].result.fit.y + res[0].originY;
        QVERIFY2(std::hypot(x - shot.truth.x, y - shot.truth.y) < 0.5, "full-image centre off by more than 0.5 px");
    }
};

QTEST_GUILESS_MAIN(TestFootprintIo)
#include "test_footprint_io.moc"
