// GeoTIFF through GDAL (issue 12): the GCP-corrected mosaic and the reflectance image carry the
// markers' ground coordinates (metres) as their geotransform; written and read back with GDAL,
// every marker's map position lands on the pixel that holds the marker's image content; a
// georeferenced DN mosaic gives a georeferenced reflectance; plain TIFF/PNG stay available.
#include <QtTest>
#include <opencv2/imgcodecs.hpp>

#include "core/radiometry/gcp.hpp"
#include "core/radiometry/geotiff.hpp"
#include "test_support.hpp"

using namespace lwb::core::radiometry;
using namespace lwbtest;

class TestRadiometryGeotiff : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString path(const QString& n) const { return m_dir.path() + "/" + n; }

private slots:
    void writeAndReadBackKeepsPixelsAndGeotransform() {
        cv::Mat img(37, 53, CV_16UC1);
        for (int y = 0; y < img.rows; ++y)
            for (int x = 0; x < img.cols; ++x) img.at<uint16_t>(y, x) = static_cast<uint16_t>(1000 * y + x);
        MapGrid g;
        g.originX = 500123.25;
        g.originY = 4321987.5;
        g.pixelSize = 0.02;
        g.width = img.cols;
        g.height = img.rows;
        const GeoReference geo = geoReferenceOf(g);
        // GDAL's corner convention: the top-left corner is half a pixel up-left of pixel (0, 0)'s centre.
        QCOMPARE(geo.transform[0], 500123.24);
        QCOMPARE(geo.transform[3], 4321987.51);
        const cv::Point2d c = pixelCentreToMap(geo, 10, 20);
        QVERIFY(std::fabs(c.x - (g.originX + 10 * 0.02)) < 1e-9 && std::fabs(c.y - (g.originY - 20 * 0.02)) < 1e-9);
        std::string err;
        const std::string p = path("a.tif").toStdString();
        QVERIFY2(writeGeoTiff(p, img, geo, &err), err.c_str());
        QCOMPARE(filesIn(m_dir.path()), QStringList{"a.tif"});  // no side file, no temporary left
        cv::Mat back;
        GeoReference bg;
        QVERIFY2(readGeoTiff(p, &back, &bg, &err), err.c_str());
        QVERIFY(bg.valid);
        QCOMPARE(back.type(), CV_16UC1);
        QCOMPARE(cv::norm(back, img, cv::NORM_INF), 0.0);
        for (int i = 0; i < 6; ++i) QVERIFY(std::fabs(bg.transform[i] - geo.transform[i]) < 1e-9);
        QVERIFY2(bg.crsWkt.find("metre") != std::string::npos, bg.crsWkt.c_str());  // local frame in metres
        // OpenCV reads the same file as a plain TIFF (pixel data unchanged).
        const cv::Mat cvRead = cv::imread(p, cv::IMREAD_UNCHANGED);
        QCOMPARE(cv::norm(cvRead, img, cv::NORM_INF), 0.0);
        // A float image with NaN and a projected CRS.
        cv::Mat f(5, 6, CV_32FC1, cv::Scalar(12.5f));
        f.at<float>(2, 3) = NAN;
        GeoReference utm = geo;
        QVERIFY2(crsFromUserInput("EPSG:32650", &utm.crsWkt, &err), err.c_str());
        QVERIFY2(writeGeoTiff(path("f.tif").toStdString(), f, utm, &err, true, NAN), err.c_str());
        QVERIFY2(readGeoTiff(path("f.tif").toStdString(), &back, &bg, &err), err.c_str());
        QCOMPARE(back.type(), CV_32FC1);
        QVERIFY(std::isnan(back.at<float>(2, 3)) && back.at<float>(0, 0) == 12.5f);
        QVERIFY2(bg.crsWkt.find("32650") != std::string::npos, bg.crsWkt.c_str());
        // Without a georeference: a plain TIFF, read back as such.
        QVERIFY2(writeGeoTiff(path("plain.tif").toStdString(), img, GeoReference{}, &err), err.c_str());
        QVERIFY2(readGeoReference(path("plain.tif").toStdString(), &bg, &err), err.c_str());
        QVERIFY(!bg.valid);
        // Bad inputs fail with the file named.
        QVERIFY(!crsFromUserInput("EPSG:nonsense", &utm.crsWkt, &err));
        QVERIFY2(err.find("nonsense") != std::string::npos, err.c_str());
        QVERIFY(lwbtest::writeText(path("junk.tif"), "not a tiff at all"));
        QVERIFY(!readGeoReference(path("junk.tif").toStdString(), &bg, &err));
        QVERIFY2(err.find("junk.tif") != std::string::npos, err.c_str());
        QVERIFY(!writeGeoTiff(path("bad.tif").toStdString(), cv::Mat(4, 4, CV_64FC1, cv::Scalar(1)), geo, &err));
        QVERIFY(!QFile::exists(path("bad.tif")));
    }

    // CLI: the GCP-corrected image as a GeoTIFF whose geotransform puts every marker where its
    // image content is; apply on that georeferenced DN image writes a georeferenced reflectance.
    void gcpMapAndReflectanceAreGeoreferenced() {
        cv::Mat img(120, 300, CV_16UC1);
        for (int y = 0; y < img.rows; ++y)
            for (int x = 0; x < img.cols; ++x) img.at<uint16_t>(y, x) = static_cast<uint16_t>(200 + 20 * x + y);
        QVERIFY(cv::imwrite(path("row16.png").toStdString(), img));
        // Markers in a local field frame (metres, Y up): map = (100 + 0.01·x, 51.2 − 0.01·y).
        struct Marker {
            const char* id;
            int x, y;
        } markers[] = {{"M1", 0, 0}, {"M2", 299, 0}, {"M3", 0, 119}, {"M4", 299, 119}, {"M5", 150, 60}, {"M6", 100, 0}};
        QByteArray gcps = "id,x,y,map_x,map_y\n";
        for (const Marker& m : markers)
            gcps += QByteArray(m.id) + "," + QByteArray::number(m.x) + "," + QByteArray::number(m.y) + "," +
                    QByteArray::number(100 + 0.01 * m.x, 'f', 4) + "," + QByteArray::number(51.2 - 0.01 * m.y, 'f', 4) + "\n";
        QVERIFY(writeText(path("gcps.csv"), gcps));
        const CliRun r = runCli({"radiometry", "gcp", path("row16.png"), "--gcps", path("gcps.csv"), "-o", path("map.tif"),
                                 "--pixel-size", "0.01", "--valid", path("valid.tif")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains("GeoTIFF"), qPrintable(r.err));
        cv::Mat map;
        GeoReference geo;
        std::string err;
        QVERIFY2(readGeoTiff(path("map.tif").toStdString(), &map, &geo, &err), err.c_str());
        QVERIFY(geo.valid);
        QCOMPARE(geo.transform[1], 0.01);
        QCOMPARE(geo.transform[5], -0.01);
        QCOMPARE(geo.transform[2], 0.0);
        QCOMPARE(geo.transform[4], 0.0);
        for (const Marker& m : markers) {
            const double mx = 100 + 0.01 * m.x, my = 51.2 - 0.01 * m.y;
            // Map → pixel centre through the geotransform read back from the file.
            const double col = (mx - geo.transform[0]) / geo.transform[1] - 0.5;
            const double row = (my - geo.transform[3]) / geo.transform[5] - 0.5;
            const int c = static_cast<int>(std::lround(col)), rr = static_cast<int>(std::lround(row));
            QVERIFY2(std::fabs(col - c) < 1e-6 && std::fabs(row - rr) < 1e-6, m.id);  // on a pixel centre
            QVERIFY(c >= 0 && rr >= 0 && c < map.cols && rr < map.rows);
            QCOMPARE(map.at<uint16_t>(rr, c), img.at<uint16_t>(m.y, m.x));
        }
        GeoReference vg;
        QVERIFY2(readGeoReference(path("valid.tif").toStdString(), &vg, &err), err.c_str());
        QVERIFY(vg.valid && vg.transform[0] == geo.transform[0] && vg.transform[3] == geo.transform[3]);
        // The reflectance of the georeferenced DN mosaic keeps the georeferencing.
        const CliRun a = runCli({"radiometry", "apply", path("map.tif"), "--k", "0.001", "--b", "1", "-o", path("refl.tif")});
        QVERIFY2(a.exitCode == 0, qPrintable(a.err));
        cv::Mat refl;
        GeoReference rg;
        QVERIFY2(readGeoTiff(path("refl.tif").toStdString(), &refl, &rg, &err), err.c_str());
        QVERIFY(rg.valid);
        for (int i = 0; i < 6; ++i) QCOMPARE(rg.transform[i], geo.transform[i]);
        QCOMPARE(rg.crsWkt, geo.crsWkt);
        QCOMPARE(refl.type(), CV_32FC1);
        QVERIFY(std::fabs(refl.at<float>(10, 20) - (0.001 * map.at<uint16_t>(10, 20) + 1)) < 1e-4);
        // Plain TIFF on request, and PNG by extension: no georeferencing.
        QCOMPARE(runCli({"radiometry", "apply", path("map.tif"), "--k", "0.001", "--b", "1", "-o", path("plain.tif"),
                         "--plain-tiff"})
                     .exitCode,
                 0);
        QVERIFY2(readGeoReference(path("plain.tif").toStdString(), &rg, &err), err.c_str());
        QVERIFY(!rg.valid);
        QCOMPARE(runCli({"radiometry", "gcp", path("row16.png"), "--gcps", path("gcps.csv"), "-o", path("map.png"),
                         "--pixel-size", "0.01"})
                     .exitCode,
                 0);
        QVERIFY2(readGeoReference(path("map.png").toStdString(), &rg, &err), err.c_str());
        QVERIFY(!rg.valid);
        // A CRS for the markers' coordinates, and a bad one (usage error, nothing written).
        QCOMPARE(runCli({"radiometry", "gcp", path("row16.png"), "--gcps", path("gcps.csv"), "-o", path("utm.tif"),
                         "--pixel-size", "0.01", "--crs", "EPSG:32650"})
                     .exitCode,
                 0);
        QVERIFY2(readGeoReference(path("utm.tif").toStdString(), &rg, &err), err.c_str());
        QVERIFY(rg.crsWkt.find("32650") != std::string::npos);
        const CliRun bad = runCli({"radiometry", "gcp", path("row16.png"), "--gcps", path("gcps.csv"), "-o", path("never.tif"),
                                   "--crs", "EPSG:nonsense"});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY(!QFile::exists(path("never.tif")));
    }
};

QTEST_GUILESS_MAIN(TestRadiometryGeotiff)
#include "test_radiometry_geotiff.moc"
