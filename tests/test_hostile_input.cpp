// Hostile input (issue 8): special files, huge images from small files, numbers that are not
// numbers or not plausible, and messages that must say what and where. Each row once crashed,
// hung, exhausted memory, or exited 0 with garbage.
#include <QElapsedTimer>
#include <QtTest>
#include <fcntl.h>
#include <opencv2/imgcodecs.hpp>
#include <sys/stat.h>
#include <unistd.h>

#include "core/common/atomic_file.hpp"
#include "core/common/image_header.hpp"
#include "core/common/text.hpp"
#include "core/footprint/background.hpp"
#include "core/footprint/image_io.hpp"
#include "core/radiometry/mosaic.hpp"
#include "test_support.hpp"

using namespace lwbtest;
using namespace lwb::core;

namespace {
// A 16-bit PNG whose IHDR says width x height, made from a real 8x8 PNG by patching the header
// (the refusal must come from the header, before any decoding).
QByteArray pngClaiming(quint32 width, quint32 height) {
    std::vector<uchar> buf;
    cv::imencode(".png", cv::Mat(8, 8, CV_16UC1, cv::Scalar(100)), buf);
    QByteArray b(reinterpret_cast<const char*>(buf.data()), int(buf.size()));
    for (int k = 0; k < 4; ++k) {
        b[16 + k] = char((width >> (24 - 8 * k)) & 0xFF);
        b[20 + k] = char((height >> (24 - 8 * k)) & 0xFF);
    }
    return b;
}
}  // namespace

class TestHostileInput : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString p(const QString& n) const { return m_dir.path() + "/" + n; }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // ------------------------------------------------------------------ numbers
    void strictDecimalSyntax_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("ok");
        QTest::addColumn<double>("value");
        QTest::newRow("plain") << "261.5" << true << 261.5;
        QTest::newRow("exponent") << "+1.5e-3" << true << 1.5e-3;
        QTest::newRow("leading point") << "-.5" << true << -0.5;
        QTest::newRow("blanks") << "  42 " << true << 42.0;
        QTest::newRow("underflow") << "1e-400" << true << 0.0;
        QTest::newRow("cut fraction") << "261." << false << 0.0;
        QTest::newRow("cut exponent") << "1e" << false << 0.0;
        QTest::newRow("cut exponent sign") << "1e+" << false << 0.0;
        QTest::newRow("hex float") << "0x1p3" << false << 0.0;
        QTest::newRow("overflow") << "1e400" << false << 0.0;
        QTest::newRow("inf") << "inf" << false << 0.0;
        QTest::newRow("nan") << "nan" << false << 0.0;
        QTest::newRow("two points") << "1.2.3" << false << 0.0;
        QTest::newRow("comma") << "1,5" << false << 0.0;
        QTest::newRow("sign only") << "-" << false << 0.0;
    }
    void strictDecimalSyntax() {
        QFETCH(QString, text);
        QFETCH(bool, ok);
        QFETCH(double, value);
        double v = -99;
        QCOMPARE(parseDouble(text.toStdString(), &v), ok);
        if (ok) QCOMPARE(v, value);
        // The ILRS files' FORTRAN format writes "26." and must still read.
        double f = 0;
        QVERIFY(parseFortranDouble("26.", &f) && f == 26);
        QVERIFY(!parseFortranDouble("0x1p3", &f));
    }

    // A CSV cut inside its last number, a hex float, and implausible magnitudes: exit 1 with
    // FILE:LINE, nothing written.
    void badNumbersInFiles_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("file");
        QTest::addColumn<QByteArray>("content");
        QTest::addColumn<QString>("message");
        const QString trendHead = "time,beam,x,y\n2020-03-01,1,120.8,263.7\n";
        QTest::newRow("trend cut number") << QStringList{"trend", "@in.csv", "-o", "@out.csv"} << "in.csv"
                                          << (trendHead + "2020-04-01,1,120.5,261.").toUtf8() << "in.csv:3:";
        QTest::newRow("trend hex float") << QStringList{"trend", "@in.csv", "-o", "@out.csv"} << "in.csv"
                                         << (trendHead + "2020-04-01,1,0x1p3,261\n").toUtf8() << "in.csv:3:";
        QTest::newRow("trend x 1e308") << QStringList{"trend", "@in.csv", "-o", "@out.csv"} << "in.csv"
                                       << (trendHead + "2020-04-01,1,1e308,261\n").toUtf8() << "not a plausible spot centroid";
        QTest::newRow("stats 1e308") << QStringList{"calib", "stats", "@in.csv", "-o", "@out.csv"} << "in.csv"
                                     << QByteArray("d\n0.1\n1e308\n0.2\n") << "in.csv:3:";
        QTest::newRow("fit reflectance 1e308") << QStringList{"radiometry", "fit", "@in.csv", "-o", "@out.csv"} << "in.csv"
                                               << QByteArray("name,reflectance,dn\na,10,1000\nb,1e308,2000\nc,30,3000\n")
                                               << "in.csv:3:";
        QTest::newRow("fit k 1e308") << QStringList{"radiometry", "apply", "@img.png", "--fit", "@in.csv", "-o", "@out.tif"}
                                     << "in.csv" << QByteArray("k,b\n1e308,1e308\n") << "in.csv:2:";
        QTest::newRow("unterminated quote") << QStringList{"calib", "stats", "@in.csv", "-o", "@out.csv"} << "in.csv"
                                            << QByteArray("d\n0.1\n\"0.2\n0.3\n") << "in.csv:3: a quoted field";
    }
    void badNumbersInFiles() {
        QFETCH(QStringList, args);
        QFETCH(QString, file);
        QFETCH(QByteArray, content);
        QFETCH(QString, message);
        QVERIFY(writeText(p(file), content));
        QVERIFY(cv::imwrite(p("img.png").toStdString(), cv::Mat(8, 8, CV_16UC1, cv::Scalar(1000))));
        QFile::remove(p("out.csv"));
        QFile::remove(p("out.tif"));
        QStringList full;
        for (const QString& a : args) full << (a.startsWith('@') ? p(a.mid(1)) : a);
        const CliRun r = runCli(full);
        QVERIFY2(r.exitCode == 1, qPrintable(QString::number(r.exitCode) + " " + r.err));
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("out.csv")) && !QFile::exists(p("out.tif")));
    }

    // Command-line K and B too large for a float image: refused, no all-inf TIFF.
    void applyOverflowRefused() {
        QVERIFY(cv::imwrite(p("img.png").toStdString(), cv::Mat(8, 8, CV_16UC1, cv::Scalar(1000))));
        // Beyond the option's range: a usage error.
        CliRun r = runCli({"radiometry", "apply", p("img.png"), "--k", "1e308", "--b", "1e308", "-o", p("inf.tif")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--k"), qPrintable(r.err));
        // Within it, but overflowing a float image: refused by the core with the pixel named.
        r = runCli({"radiometry", "apply", p("img.png"), "--k", "1e300", "--b", "1e300", "-o", p("inf.tif")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("not plausible") && r.err.contains("pixel 0, 0"), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("inf.tif")));
    }

    // ------------------------------------------------------------------ special files
    // /dev/zero ran until killed; a FIFO blocked for ever.
    void specialFilesAreNotRead() {
        QFile::remove(p("fifo"));
        QVERIFY(::mkfifo(p("fifo").toLocal8Bit().constData(), 0600) == 0);
        for (const QStringList& args :
             {QStringList{"trend", "/dev/zero", "-o", p("o.csv")}, QStringList{"trend", p("fifo"), "-o", p("o.csv")},
              QStringList{"slr", p("fifo"), "-o", p("o.csv")}, QStringList{"calib", "stats", "/dev/zero"},
              QStringList{"footprint", "/dev/zero", "-o", p("o.csv")}, QStringList{"radiometry", "fit", p("fifo"), "-o", p("o.csv")}}) {
            QElapsedTimer t;
            t.start();
            const CliRun r = runCli(args, 20000);
            QVERIFY2(r.exitCode == 1, qPrintable(args.join(' ') + ": " + QString::number(r.exitCode) + " " + r.err));
            QVERIFY2(r.err.contains("not a regular file"), qPrintable(r.err));
            QVERIFY2(t.elapsed() < 10000, qPrintable(args.join(' ')));
        }
        std::string text, err;
        QVERIFY(!readFileText("/dev/zero", &text, &err));
        // The size limit for text inputs, with the size in the message.
        QVERIFY(writeText(p("big.txt"), QByteArray(5000, 'x')));
        QVERIFY(!readFileText(p("big.txt").toStdString(), &text, &err, 4096));
        QVERIFY2(QString::fromStdString(err).contains("5000 bytes"), err.c_str());
        QVERIFY(readFileText(p("big.txt").toStdString(), &text, &err, 8192));
        QCOMPARE(text.size(), size_t(5000));
    }

    // ------------------------------------------------------------------ images
    // A 0.8 MB PNG of 20000 x 20000 took 6.3 GB and 59 s: refused from its header.
    void hugeImagesRefusedFromTheHeader() {
        QVERIFY(writeText(p("huge.png"), pngClaiming(20000, 20000)));
        QElapsedTimer t;
        t.start();
        CliRun r = runCli({"footprint", p("huge.png"), "-o", p("fp.csv")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("20000 x 20000 = 400000000 pixels"), qPrintable(r.err));
        QVERIFY2(r.err.contains("--max-pixels"), qPrintable(r.err));
        r = runCli({"radiometry", "gcp", p("huge.png"), "--gcps", p("g.csv"), "-o", p("m.tif")});
        QVERIFY(writeText(p("g.csv"), "id,x,y,map_x,map_y\nA,0,0,0,1\nB,5,0,1,1\nC,0,5,0,0\n"));
        r = runCli({"radiometry", "gcp", p("huge.png"), "--gcps", p("g.csv"), "-o", p("m.tif")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("400000000 pixels"), qPrintable(r.err));
        QVERIFY(t.elapsed() < 10000);
        // The limit is a parameter: a 32 x 32 frame passes by default and is refused below 1024.
        QVERIFY(cv::imwrite(p("small.png").toStdString(), cv::Mat(32, 32, CV_16UC1, cv::Scalar(500))));
        footprint::ImageReadParams rp;
        QVERIFY(footprint::readFrame(p("small.png").toStdString(), rp).ok);
        rp.maxPixels = 1023;
        const auto small = footprint::readFrame(p("small.png").toStdString(), rp);
        QVERIFY(!small.ok);
        QVERIFY2(QString::fromStdString(small.error).contains("1024 pixels"), small.error.c_str());
        r = runCli({"footprint", p("small.png"), "--max-pixels", "1000", "-o", p("fp.csv")});
        QCOMPARE(r.exitCode, 1);
        // Issue 27: a 16384 x 16384 frame (0.5 MB as a PNG) took 4.2 GB in footprint; its frames
        // are refused above 4096 x 4096 by default, and --max-pixels takes the limit higher.
        QVERIFY(writeText(p("big.png"), pngClaiming(16384, 16384)));
        r = runCli({"footprint", p("big.png"), "-o", p("fp.csv")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("more than the limit of 16777216 pixels"), qPrintable(r.err));
        QCOMPARE(footprint::ImageReadParams{}.maxPixels, 4096LL * 4096);
        // Issue 27: two 16384 x 16384 frames in `radiometry mosaic` took more than 6 GB (about
        // 64 bytes per pixel of a pair: 34 GB). The mosaic's peak is estimated from the headers
        // and refused above 3/4 of the machine's memory, before any pixel is decoded.
        QVERIFY(writeText(p("big2.png"), pngClaiming(16384, 16384)));
        r = runCli({"radiometry", "mosaic", p("big.png"), p("big2.png"), "-o", p("row.tif")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("to mosaic, more than this machine's budget"), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("row.tif")));
        using radiometry::mosaicMemoryProblem;
        const std::vector<std::string> bigPair = {p("big.png").toStdString(), p("big2.png").toStdString()};
        // (70 MB + 64 B x 537 Mpx + 8 B x 537 Mpx = 38.7 GB)
        QVERIFY(!mosaicMemoryProblem(bigPair, 18e9).empty());  // 3/4 of 24 GB: refused
        QVERIFY(mosaicMemoryProblem(bigPair, 40e9).empty());   // 3/4 of a 54 GB machine: it runs
        QVERIFY(mosaicMemoryProblem({p("small.png").toStdString(), p("small.png").toStdString()}, 1e8).empty());
        QCOMPARE(radiometry::mosaicPeakBytes({1000000, 1000000, 500000}), 70e6 + 64 * 2e6 + 8 * 2.5e6);
    }

    // ------------------------------------------------------------------ tables
    // Issue 27: a CSV of 51 MB of empty fields took 1.65 GB (every field a std::string). Tables
    // of more than kMaxCsvFields fields are refused with the line where the limit was passed.
    void hugeCsvTablesRefused() {
        QByteArray t = "time,beam,x,y\n";
        const QByteArray row = ",,,\n";
        t.reserve(int(t.size() + row.size() * 2500001));
        for (int i = 0; i < 2500001; ++i) t += row;
        QVERIFY(writeText(p("empty.csv"), t));
        const CliRun r = runCli({"trend", p("empty.csv"), "-o", p("t.csv")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("empty.csv:2500002: more than 10000000 fields"), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("t.csv")));
    }

    // Header sizes of every format read, against images written by OpenCV.
    void imageHeaderSizes() {
        const cv::Mat m(37, 53, CV_16UC1, cv::Scalar(7));
        for (const char* ext : {".png", ".tif", ".pgm"}) {
            std::vector<uchar> buf;
            QVERIFY(cv::imencode(ext, m, buf));
            const ImageHeader h = readImageHeader(std::string_view(reinterpret_cast<const char*>(buf.data()), buf.size()));
            QVERIFY2(h.recognised && h.complete, ext);
            QCOMPARE(h.width, 53LL);
            QCOMPARE(h.height, 37LL);
        }
        std::vector<uchar> jpg;
        QVERIFY(cv::imencode(".jpg", cv::Mat(37, 53, CV_8UC1, cv::Scalar(7)), jpg));
        const ImageHeader h = readImageHeader(std::string_view(reinterpret_cast<const char*>(jpg.data()), jpg.size()));
        QVERIFY(h.complete && h.width == 53 && h.height == 37);
        // Cut inside the header: recognised, incomplete, refused with a reason.
        QVERIFY(!readImageHeader(std::string_view("\x89PNG\r\n\x1a\n\0\0", 10)).complete);
        QVERIFY(QString::fromStdString(imageSizeProblem(std::string_view("II*\0\x08\0\0\0", 8), "x.tif", 0)).contains("truncated"));
        // fuzz_frame finding: a classic TIFF whose last IFD entry, ImageWidth, claims type LONG8
        // (8 bytes, BigTIFF only) in a 4-byte value field: its value was read past the entry and
        // the end of the file (ASan: heap-buffer-overflow) and the header taken as complete.
        const char tiff[] = "II*\0\x08\0\0\0\x02\0"
                            "\x01\x01\x03\0\x01\0\0\0\x05\0\0\0"   // ImageLength SHORT 5
                            "\x00\x01\x10\0\x01\0\0\0\x07\0\0\0";  // ImageWidth LONG8
        const std::vector<char> exact(tiff, tiff + sizeof(tiff) - 1);  // no byte after the entry
        QCOMPARE(exact.size(), size_t(34));
        const ImageHeader bad = readImageHeader(std::string_view(exact.data(), exact.size()));
        QVERIFY(bad.recognised && !bad.complete);
        QVERIFY(QString::fromStdString(imageSizeProblem(std::string_view(exact.data(), exact.size()), "x.tif", 0))
                    .contains("damaged"));
    }

    // SIGSEGV: a float TIFF of tiny values (~1e-12) overflowed the histogram clip index.
    void floatTiffOfTinyValuesDoesNotCrash() {
        cv::Mat f(32, 32, CV_32FC1);
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                const double r2 = (x - 15.5) * (x - 15.5) + (y - 16.2) * (y - 16.2);
                f.at<float>(y, x) = float(1e-12 * (1 + 0.01 * ((x * 7 + y * 13) % 5)) + 5e-12 * std::exp(-r2 / 18));
            }
        const footprint::BackgroundResult b = footprint::estimateBackground(f, {});
        QVERIFY(b.ok);
        QVERIFY(std::isfinite(b.level) && b.level >= 0 && b.level < 1e-10);
        QVERIFY(cv::imwrite(p("tiny.tif").toStdString(), f));
        const CliRun r = runCli({"footprint", p("tiny.tif"), "-o", p("tiny.csv"), "--keep-going"});
        QVERIFY2(r.exitCode == 0 || r.exitCode == 1, qPrintable(QString::number(r.exitCode) + r.err));
    }

    // ------------------------------------------------------------------ messages
    void messagesSayWhatAndWhere() {
        // --ransac-px: the CLI and the core agree on the range.
        CliRun r = runCli({"radiometry", "mosaic", "a.png", "b.png", "-o", p("x.tif"), "--ransac-px", "1001"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--ransac-px"), qPrintable(r.err));
        // A duplicate beam id is blamed on the beams file, not on the control points.
        QVERIFY(runCli({"simulate", "calib", p("cal"), "-q"}).exitCode == 0);
        QVERIFY(writeText(p("beams2.json"), "{\"beams\": [{\"id\": 1, \"alpha_deg\": 0.7, \"beta_deg\": 90},\n"
                                            "{\"id\": 1, \"alpha_deg\": 0.7, \"beta_deg\": 270}]}\n"));
        r = runCli({"calib", "pointing", p("cal/control_points.csv"), "--beams", p("beams2.json"), "-o", p("pt.csv")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("beams2.json") && r.err.contains("already used") && !r.err.contains("control_points"),
                 qPrintable(r.err));
        // --config with a misspelt key is an error naming the key.
        QVERIFY(writeText(p("cfg.json"), "{\"gauss\": {\"lm_max_iter\": 5}}"));
        r = runCli({"footprint", "--config", p("cfg.json"), "--print-config"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("gauss.lm_max_iter"), qPrintable(r.err));
        // An unmatched satellite in a big preset file: a short message, not every name.
        const QString slrIn = sharedPath("slr/7080_STELLA_crd_071220_2128_0.frd");
        if (!QFile::exists(slrIn)) QSKIP("shared SLR data absent");
        QByteArray presets = "{\"format\": \"laserwb-slr-presets\", \"version\": 1, \"satellites\": [";
        for (int i = 0; i < 20000; ++i) presets += (i ? "," : "") + QByteArray("{\"name\": \"sat") + QByteArray::number(i) + "\"}";
        presets += "]}";
        QVERIFY(writeText(p("presets.json"), presets));
        r = runCli({"slr", slrIn, "--preset", p("presets.json"), "--satellite", "nosuch", "-o", p("s.csv")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("and 19980 more"), qPrintable(r.err.left(400)));
        QVERIFY2(r.err.size() < 2000, qPrintable(QString::number(r.err.size())));
    }
};

QTEST_GUILESS_MAIN(TestHostileInput)
#include "test_hostile_input.moc"
