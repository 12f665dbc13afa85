// The radiometry workspace under the offscreen platform: the demo field's fit against the
// simulated line, region picking and editing reaching K and B, exports read back (the
// reflectance TIFF with OpenCV), corrupt inputs that leave the state alone, sessions.
#include <QApplication>
#include <QDoubleSpinBox>
#include <QJsonArray>
#include <QJsonDocument>
#include <QLabel>
#include <QStandardPaths>
#include <QTableWidget>
#include <QtTest>
#include <opencv2/imgcodecs.hpp>
#include <qcustomplot.h>

#include "core/common/csv.hpp"
#include "core/radiometry/reflectance.hpp"
#include "session_refused.hpp"
#include "test_support.hpp"
#include "ui/radiometry/radiometry_workspace.hpp"

using namespace lwb::ui;
using namespace lwb::core::radiometry;

namespace {
int countRole(const std::vector<PickedRegion>& r, RegionRole role) {
    int n = 0;
    for (const auto& x : r) n += x.role == role;
    return n;
}
int regionIndex(const RadiometryController* c, const QString& name) {
    for (size_t i = 0; i < c->regions().size(); ++i)
        if (c->regions()[i].name == name) return int(i);
    return -1;
}
}  // namespace

class TestRadiometryWorkspace : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString path(const QString& f) const { return m_dir.path() + "/" + f; }

    // The workspace shown in a window, with the demo opened and screened.
    static bool showDemo(RadiometryWorkspace& w) {
        w.resize(1200, 800);
        w.show();
        if (!QTest::qWaitForWindowExposed(&w)) return false;
        w.openDemo();
        return w.controller()->waitIdle(60000);
    }

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    // Issue 28, GUI = CLI: the workbench's radiometry of simulated frames writes the files
    // laserwb-cli writes for the same inputs and defaults, byte for byte: the fit (radiometry fit
    // on the CLI's mosaic), the reflectance image (radiometry apply) and the check table
    // (radiometry check on that image).
    void workbenchAndCliWriteTheSameFiles() {
        const QString sim = path("same-sim"), out = path("same");
        QVERIFY(QDir().mkpath(out));
        auto cli = [](const QStringList& args) {
            const auto r = lwbtest::runCli(args + QStringList{"-q"});
            QVERIFY2(r.exitCode == 0, qPrintable(args.join(' ') + ": " + r.err));
        };
        cli({"simulate", "radiometry", sim});
        QStringList frames;
        for (int i = 1; i <= 6; ++i) frames << sim + QString("/frame_%1.png").arg(i);
        cli(QStringList{"radiometry", "mosaic"} + frames + QStringList{"-o", out + "/row.tif"});
        cli({"radiometry", "fit", sim + "/regions.csv", "--image", out + "/row.tif", "-o", out + "/fit_cli.csv"});
        cli({"radiometry", "apply", out + "/row.tif", "--fit", out + "/fit_cli.csv", "-o", out + "/refl_cli.tif"});
        cli({"radiometry", "check", sim + "/check.csv", "--image", out + "/refl_cli.tif", "-o", out + "/check_cli.csv"});

        RadiometryWorkspace w;
        RadiometryController* c = w.controller();
        QString err;
        QVERIFY2(c->openFrames(frames, &err), qPrintable(err));
        QVERIFY(c->waitIdle(60000));
        QVERIFY2(c->openRegions(sim + "/regions.csv", RegionRole::Fit, &err), qPrintable(err));
        QVERIFY2(c->openRegions(sim + "/check.csv", RegionRole::Check, &err), qPrintable(err));
        QVERIFY(c->waitIdle(60000));
        QVERIFY2(c->exportFit(out + "/fit_gui.csv", &err), qPrintable(err));
        QVERIFY2(c->exportReflectance(out + "/refl_gui.tif", &err), qPrintable(err));
        QVERIFY2(c->exportRelativeErrors(out + "/check_gui.csv", &err), qPrintable(err));
        for (const char* f : {"fit_%1.csv", "refl_%1.tif", "check_%1.csv"}) {
            const QByteArray gui = lwbtest::readAll(out + "/" + QString(f).arg("gui")), cliFile = lwbtest::readAll(out + "/" + QString(f).arg("cli"));
            QVERIFY2(!gui.isEmpty(), f);
            QVERIFY2(gui == cliFile, qPrintable(QString("%1: the workbench's export differs from laserwb-cli's (%2 vs %3 bytes):\n%4\n---\n%5")
                                                    .arg(QString(f).arg("*")).arg(gui.size()).arg(cliFile.size())
                                                    .arg(QString::fromUtf8(gui.left(300)), QString::fromUtf8(cliFile.left(300)))));
        }
    }

    void demoFitsTheSimulatedLine() {
        RadiometryWorkspace w;
        RadiometryController* c = w.controller();
        w.openDemo();
        QVERIFY(c->waitIdle(60000));
        QVERIFY(c->hasImage());
        const RadiometryImage& img = c->image();
        QCOMPARE(img.source, QString("demo"));
        QCOMPARE(int(img.pairs.size()), 5);  // six frames mosaicked
        QCOMPARE(countRole(c->regions(), RegionRole::Fit), 6);
        QCOMPARE(countRole(c->regions(), RegionRole::Check), 4);
        const RadiometryRun& run = c->run();
        QVERIFY2(run.fit.ok, qPrintable(run.error));
        const ReflectanceFit& f = run.fit.fit;
        QCOMPARE(f.n, 6);
        // The simulated line within 3σ of the fit.
        QVERIFY2(std::fabs(f.k - img.demoK) < 3 * f.kSd, qPrintable(QString("K %1 ± %2 vs %3").arg(f.k).arg(f.kSd).arg(img.demoK)));
        QVERIFY2(std::fabs(f.b - img.demoB) < 3 * f.bSd, qPrintable(QString("B %1 ± %2 vs %3").arg(f.b).arg(f.bSd).arg(img.demoB)));
        QVERIFY(f.r2 > 0.999);
        // The reflectance image and the check regions (measured to ±1 %: well within 5 %).
        QVERIFY(run.apply.ok);
        QCOMPARE(run.apply.reflectance.size(), img.dn.size());
        QVERIFY(run.check.ok);
        QCOMPARE(int(run.check.rows.size()), 4);
        QVERIFY(run.check.allWithinLimit);
        QVERIFY(run.check.maxPct < 5);
        // What is shown.
        QCOMPARE(w.regionTable()->rowCount(), 10);
        QCOMPARE(w.errorTable()->rowCount(), 4);
        QCOMPARE(w.errorTable()->item(0, 0)->text(), QString("cement 1"));
        QVERIFY(w.fitSummary()->text().contains(QString::number(f.k, 'g', 6)));
        QCPColorMap* refl = nullptr;
        for (int i = 0; i < w.reflectancePlot()->plottableCount(); ++i)
            if (auto* m = qobject_cast<QCPColorMap*>(w.reflectancePlot()->plottable(i))) refl = m;
        QVERIFY(refl);
        QCOMPARE(refl->data()->keySize(), img.dn.cols);
        QCOMPARE(refl->data()->valueSize(), img.dn.rows);
        // A covered pixel shows K·DN + B.
        const int x = img.dn.cols / 2, y = img.dn.rows / 2;
        QVERIFY(img.coverage.at<uchar>(y, x));
        QVERIFY(std::fabs(refl->data()->cell(x, y) - (f.k * img.display.at<float>(y, x) + f.b)) < 1e-3);
    }

    void pickingAndEditingRegionsChangesTheFit() {
        RadiometryWorkspace w;
        RadiometryController* c = w.controller();
        w.openDemo();
        QVERIFY(c->waitIdle(60000));
        const ReflectanceFit before = c->run().fit.fit;
        QCOMPARE(before.n, 6);
        // Drag a rectangle over the lawn (as the mouse does): a fit region without a reflectance
        // yet, noted and left out.
        const int lawn = regionIndex(c, "lawn");
        QVERIFY(lawn >= 0);
        const QRect lr = c->regions()[size_t(lawn)].rect;
        const int added = w.regionDrawn(QRectF(lr.x() + 5.2, lr.y() + 5.2, 30, 20), RegionRole::Fit);
        QVERIFY(added >= 0);
        QCOMPARE(c->regions()[size_t(added)].rect, QRect(lr.x() + 6, lr.y() + 6, 30, 20));
        QVERIFY(std::isnan(c->regions()[size_t(added)].reflectance));
        QVERIFY(c->waitIdle(30000));
        QCOMPARE(c->run().fit.fit.n, 6);
        QCOMPARE(c->run().fit.fit.k, before.k);
        QVERIFY(c->run().notes[size_t(added)].contains("reflectance"));
        QCOMPARE(w.regionTable()->rowCount(), 11);
        // Type its reflectance in the table: a 7th point, and K, B move.
        QTableWidgetItem* cell = w.regionTable()->item(added, 2);
        QVERIFY(cell && (cell->flags() & Qt::ItemIsEditable));
        cell->setText("8.60 %");  // re-shown as 8.6 while its own itemChanged is running
        QCOMPARE(c->regions()[size_t(added)].reflectance, 8.6);
        QCOMPARE(w.regionTable()->item(added, 2)->text(), QString("8.6"));
        QVERIFY(c->waitIdle(30000));
        const ReflectanceFit with = c->run().fit.fit;
        QCOMPARE(with.n, 7);
        QVERIFY(with.k != before.k && with.b != before.b);
        // A wrong reflectance pulls the line further: the residual of the region shows it.
        c->setRegionReflectance(added, 20.0);
        QVERIFY(c->waitIdle(30000));
        QVERIFY(std::fabs(c->run().fit.fit.b - before.b) > std::fabs(with.b - before.b));
        double resid = NAN;
        for (size_t j = 0; j < c->run().fitIndex.size(); ++j)
            if (c->run().fitIndex[j] == added) resid = c->run().fit.regions[j].residual;
        QVERIFY2(resid > 5, qPrintable(QString::number(resid)));
        // Removing it restores the six-panel fit exactly.
        c->removeRegion(added);
        QVERIFY(c->waitIdle(30000));
        QCOMPARE(c->run().fit.fit.n, 6);
        QCOMPARE(c->run().fit.fit.k, before.k);
        QCOMPARE(w.regionTable()->rowCount(), 10);
        // Removing a panel leaves five: K changes, its σ grows.
        c->removeRegion(regionIndex(c, "panel 62 %"));
        QVERIFY(c->waitIdle(30000));
        QCOMPARE(c->run().fit.fit.n, 5);
        QVERIFY(c->run().fit.fit.k != before.k);
        // A panel's reflectance edited through the API changes the fit.
        c->setRegionReflectance(regionIndex(c, "panel 30 %"), 33.0);
        QVERIFY(c->waitIdle(30000));
        QVERIFY(c->run().fit.fit.residualSd > before.residualSd * 2);
        // A check region turned into a fit region joins the fit.
        c->setRegionRole(regionIndex(c, "cement 1"), RegionRole::Fit);
        QVERIFY(c->waitIdle(30000));
        QCOMPARE(c->run().fit.fit.n, 6);
        QCOMPARE(int(c->run().check.rows.size()), 3);
        QCOMPARE(w.errorTable()->rowCount(), 3);
    }

    void draggingOnTheImageAddsARegion() {
        RadiometryWorkspace w;
        RadiometryController* c = w.controller();
        QVERIFY(showDemo(w));
        const size_t before = c->regions().size();
        w.drawCheckButton()->setChecked(true);
        QCustomPlot* p = w.dnPlot();
        // From pixel (300, 120) to (340, 150) of the image, in widget coordinates.
        const QPoint a(int(p->xAxis->coordToPixel(300)), int(p->yAxis->coordToPixel(120)));
        const QPoint b(int(p->xAxis->coordToPixel(340)), int(p->yAxis->coordToPixel(150)));
        QTest::mousePress(p, Qt::LeftButton, Qt::NoModifier, a);
        QTest::mouseMove(p, (a + b) / 2);
        QTest::mouseMove(p, b);
        QTest::mouseRelease(p, Qt::LeftButton, Qt::NoModifier, b);
        QCOMPARE(c->regions().size(), before + 1);
        const PickedRegion& r = c->regions().back();
        QCOMPARE(r.role, RegionRole::Check);
        QVERIFY2(std::abs(r.rect.left() - 300) <= 2 && std::abs(r.rect.right() - 340) <= 2 && std::abs(r.rect.top() - 120) <= 2 &&
                     std::abs(r.rect.bottom() - 150) <= 2,
                 qPrintable(QString("%1,%2 %3x%4").arg(r.rect.x()).arg(r.rect.y()).arg(r.rect.width()).arg(r.rect.height())));
        QCOMPARE(w.regionTable()->rowCount(), int(before + 1));
        QCOMPARE(w.regionTable()->currentRow(), int(before));  // selected, its reflectance cell open for typing
    }

    // Seen in a real window: after opening a 32×32 image the pixel readout still showed the
    // demo's "Pixel (1430, 347): 25293 DN · reflectance 27.487 %", a pixel the new image
    // does not have.
    void openingAnImageClearsThePixelReadout() {
        RadiometryWorkspace w;
        RadiometryController* c = w.controller();
        QVERIFY(showDemo(w));
        auto* readout = w.findChild<QLabel*>("readout");
        QVERIFY(readout);
        QCustomPlot* p = w.dnPlot();
        QTest::mouseMove(p, QPoint(int(p->xAxis->coordToPixel(300)), int(p->yAxis->coordToPixel(120))));
        QVERIFY2(readout->text().startsWith("Pixel ("), qPrintable(readout->text()));  // (the pixel under the pointer, ±2)
        cv::Mat small(32, 32, CV_16U, cv::Scalar(5000));
        std::string e;
        QVERIFY(writeImage(path("small.png").toStdString(), small, &e));
        QString err;
        QVERIFY2(c->openImage(path("small.png"), &err), qPrintable(err));
        QVERIFY2(!readout->text().contains("Pixel ("), qPrintable(readout->text()));
    }

    void exportsReadBack() {
        RadiometryWorkspace w;
        RadiometryController* c = w.controller();
        w.openDemo();
        QVERIFY(c->waitIdle(60000));
        const ReflectanceFit f = c->run().fit.fit;
        QString err;
        QVERIFY2(c->exportReflectance(path("refl.tif"), &err), qPrintable(err));
        const cv::Mat t = cv::imread(path("refl.tif").toStdString(), cv::IMREAD_UNCHANGED);
        QVERIFY(!t.empty());
        QCOMPARE(t.type(), CV_32FC1);
        QCOMPARE(t.cols, c->image().dn.cols);
        QCOMPARE(t.rows, c->image().dn.rows);
        const cv::Mat& dn = c->image().display;
        for (const cv::Point p : {cv::Point(10, 10), cv::Point(dn.cols / 2, dn.rows / 2), cv::Point(dn.cols - 20, dn.rows - 30)}) {
            const double expect = f.k * dn.at<float>(p) + f.b;
            QVERIFY2(std::fabs(t.at<float>(p) - expect) < 1e-4 * std::max(1.0, std::fabs(expect)),
                     qPrintable(QString("%1 vs %2").arg(t.at<float>(p)).arg(expect)));
        }
        QVERIFY2(c->exportUncertainty(path("unc.tif"), &err), qPrintable(err));
        const cv::Mat u = cv::imread(path("unc.tif").toStdString(), cv::IMREAD_UNCHANGED);
        QVERIFY(!u.empty() && u.type() == CV_32FC1);
        QVERIFY(u.at<float>(dn.rows / 2, dn.cols / 2) >= float(f.spectrometerPct));
        QVERIFY2(c->exportFit(path("fit.csv"), &err), qPrintable(err));
        ReflectanceFit back;
        std::string e;
        QVERIFY(readFitCsv(path("fit.csv").toStdString(), &back, &e));
        QVERIFY(std::fabs(back.k - f.k) <= 1e-9 * std::fabs(f.k));
        QVERIFY(std::fabs(back.b - f.b) <= 1e-9 * std::fabs(f.b));
        QVERIFY2(c->exportRelativeErrors(path("check.csv"), &err), qPrintable(err));
        const auto chk = lwb::core::readCsv(path("check.csv").toStdString());
        QVERIFY(chk.ok);
        QCOMPARE(chk.table.rows.size(), size_t(4));
        QCOMPARE(chk.table.rows[1][size_t(chk.table.column("name"))], std::string("lawn"));
        // The region table is re-readable by the CLI's reader, and reloading it reproduces the fit.
        QVERIFY2(c->exportRegions(path("regions.csv"), &err), qPrintable(err));
        std::vector<Region> regions;
        QVERIFY2(readRegionCsv(path("regions.csv").toStdString(), &regions, &e), e.c_str());
        QCOMPARE(regions.size(), size_t(10));
        RadiometryWorkspace w2;
        RadiometryController* c2 = w2.controller();
        QVERIFY2(c2->setRegions({}, &err), qPrintable(err));
        QVERIFY2(writeImage(path("dn.tif").toStdString(), c->image().dn, &e), e.c_str());
        QVERIFY2(c2->openImage(path("dn.tif"), &err), qPrintable(err));
        QVERIFY2(c2->openRegions(path("regions.csv"), RegionRole::Fit, &err), qPrintable(err));
        QCOMPARE(countRole(c2->regions(), RegionRole::Check), 4);  // from the role column
        QVERIFY(c2->waitIdle(30000));
        QVERIFY(c2->run().fit.ok);
        QCOMPARE(c2->run().fit.fit.k, f.k);
        QCOMPARE(c2->run().fit.fit.b, f.b);
        // The CLI on the same image and regions gives the same line.
        // (the fit regions only: the CLI has no role column)
        std::string fitOnly = "name,reflectance,x,y,w,h\n";
        for (const auto& r : c->regions())
            if (r.role == RegionRole::Fit)
                fitOnly += r.name.toStdString() + "," + QString::number(r.reflectance, 'g', 17).toStdString() + "," +
                           std::to_string(r.rect.x()) + "," + std::to_string(r.rect.y()) + "," + std::to_string(r.rect.width()) + "," +
                           std::to_string(r.rect.height()) + "\n";
        QVERIFY(lwbtest::writeText(path("regions_fit.csv"), QByteArray::fromStdString(fitOnly)));
        const auto cli2 = lwbtest::runCli({"radiometry", "fit", path("regions_fit.csv"), "--image", path("dn.tif"), "-o", path("fit_cli.csv"), "-q"});
        QVERIFY2(cli2.exitCode == 0, qPrintable(cli2.err));
        ReflectanceFit cliFit;
        QVERIFY(readFitCsv(path("fit_cli.csv").toStdString(), &cliFit, &e));
        QVERIFY(std::fabs(cliFit.k - f.k) <= 1e-9 * std::fabs(f.k));
        QVERIFY(std::fabs(cliFit.b - f.b) <= 1e-9 * std::fabs(f.b));
    }

    void corruptInputsKeepThePreviousState() {
        RadiometryWorkspace w;
        RadiometryController* c = w.controller();
        w.openDemo();
        QVERIFY(c->waitIdle(60000));
        const cv::Size size = c->image().dn.size();
        const size_t regions = c->regions().size();
        const double k = c->run().fit.fit.k;
        QString err;
        QVERIFY(lwbtest::writeText(path("bad_regions.csv"), "name,reflectance,x,y,w,h\np1,12,1,1,5,5\np2,abc,1,1,5,5\n"));
        QVERIFY(!c->openRegions(path("bad_regions.csv"), RegionRole::Fit, &err));
        QVERIFY2(err.contains("bad_regions.csv:3"), qPrintable(err));
        QCOMPARE(c->regions().size(), regions);
        QVERIFY(lwbtest::writeText(path("bad_role.csv"), "name,reflectance,x,y,w,h,role\np1,12,1,1,5,5,fit\np2,13,1,1,5,5,calib\n"));
        QVERIFY(!c->openRegions(path("bad_role.csv"), RegionRole::Fit, &err));
        QVERIFY2(err.contains("bad_role.csv:3") && err.contains("calib"), qPrintable(err));
        QCOMPARE(c->regions().size(), regions);
        QVERIFY(lwbtest::writeText(path("not_an_image.tif"), "this is not a TIFF"));
        QVERIFY(!c->openImage(path("not_an_image.tif"), &err));
        QVERIFY2(err.contains("not_an_image.tif"), qPrintable(err));
        QVERIFY(!c->openFrames({path("not_an_image.tif"), path("not_an_image.tif")}, &err));
        QVERIFY(!c->openFrames({path("dn_only_one.tif")}, &err));
        QVERIFY(!c->busy());
        QCOMPARE(c->image().dn.size(), size);
        QCOMPARE(c->image().source, QString("demo"));
        QCOMPARE(c->run().fit.fit.k, k);
        // Frames that cannot be registered: the mosaic fails in the background, the image stays.
        cv::Mat flat(200, 200, CV_16U, cv::Scalar(1000));
        std::string e;
        QVERIFY(writeImage(path("flat1.tif").toStdString(), flat, &e));
        QVERIFY(writeImage(path("flat2.tif").toStdString(), flat, &e));
        QSignalSpy failed(c, &RadiometryController::mosaicFailed);
        QVERIFY2(c->openFrames({path("flat1.tif"), path("flat2.tif")}, &err), qPrintable(err));
        QVERIFY(c->waitIdle(30000));
        QCOMPARE(failed.count(), 1);
        QVERIFY(failed.first().at(0).toString().contains("flat1.tif"));
        QCOMPARE(c->image().dn.size(), size);
        QCOMPARE(c->run().fit.fit.k, k);
        // A region off the image is noted, not fatal.
        const int off = c->addRegion("edge", QRect(size.width - 10, 5, 40, 8), 20.0);
        QVERIFY(off >= 0);
        QCOMPARE(c->regions()[size_t(off)].rect.width(), 10);  // clipped to the image
        QVERIFY(c->waitIdle(30000));
        QVERIFY(c->run().fit.ok);
    }

    // Session parameters the fuzzer produced (fuzz_session, docs/fuzzing.md): a min_inliers of
    // 2e58 was converted to int (undefined behaviour; INT_MIN in practice, then refused without
    // naming the key) and 12.5 silently became 12. Both are refused naming the key.
    void sessionParamsFuzzRegressions_data() {
        QTest::addColumn<QByteArray>("params");
        QTest::newRow("min_inliers 2e58") << QByteArray(R"({"mosaic": {"min_inliers": 2e58}})");
        QTest::newRow("min_inliers 12.5") << QByteArray(R"({"mosaic": {"min_inliers": 12.5}})");
    }
    void sessionParamsFuzzRegressions() {
        QFETCH(QByteArray, params);
        RadiometryParams p;
        QString err;
        QVERIFY(!radiometryParamsFromJson(QJsonDocument::fromJson(params).object(), &p, &err));
        // Refused naming the key: 12.5 as not a whole number, 2e58 as outside the valid range
        // (the schema checks the range before any conversion to int).
        QVERIFY2(err.contains("min_inliers") && (err.contains("whole number") || err.contains("must be in")), qPrintable(err));
    }

    // A bad value in a session file is named with the file, line and column (issue 9).
    void sessionErrorsNameLineAndColumn_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("where");
        QTest::addColumn<QString>("what");
        QTest::newRow("limit_pct -1") << "{\"radiometry\": {\n \"params\":\n  {\"limit_pct\": -1}}}" << "s.json:3:"
                                      << "limit_pct";
        QTest::newRow("unknown key") << "{\"radiometry\": {\n \"params\": {},\n \"regoins\": []}}" << "s.json:3:"
                                     << "regoins";
        QTest::newRow("region role") << "{\"radiometry\": {\"regions\": [\n {\"name\": \"a\", \"role\": \"fit\", \"dn\": 5},\n "
                                        "{\"name\": \"b\",\n  \"role\": \"both\", \"dn\": 5}]}}"
                                     << "s.json:4:" << "role";
    }
    void sessionErrorsNameLineAndColumn() {
        QFETCH(QString, text);
        QFETCH(QString, where);
        QFETCH(QString, what);
        lwbtest::expectSessionRefused<RadiometryWorkspace>(text, "radiometry", where, what);
    }

    void sessionRoundTrip() {
        QJsonObject state;
        double k = 0, b = 0;
        std::vector<PickedRegion> regions;
        {
            RadiometryWorkspace a;
            RadiometryController* c = a.controller();
            a.openDemo();
            QVERIFY(c->waitIdle(60000));
            c->setRegionReflectance(regionIndex(c, "panel 20 %"), 19.9);
            c->addRegion("extra", QRect(100, 150, 20, 20), NAN, RegionRole::Check);
            a.vmField()->setValue(0.3);
            QVERIFY(c->waitIdle(30000));
            k = c->run().fit.fit.k;
            b = c->run().fit.fit.b;
            regions = c->regions();
            QCOMPARE(c->run().fit.fit.spectrometerPct, 0.3);
            state = QJsonDocument::fromJson(QJsonDocument(a.saveState()).toJson()).object();
        }
        RadiometryWorkspace r;
        RadiometryController* c = r.controller();
        QString err;
        QVERIFY2(r.restoreState(state, &err), qPrintable(err));
        QVERIFY(c->waitIdle(60000));
        QCOMPARE(c->image().source, QString("demo"));
        QCOMPARE(c->regions().size(), regions.size());  // the session's regions, not the demo's
        for (size_t i = 0; i < regions.size(); ++i) {
            QCOMPARE(c->regions()[i].name, regions[i].name);
            QCOMPARE(c->regions()[i].rect, regions[i].rect);
            QCOMPARE(c->regions()[i].role, regions[i].role);
            QVERIFY(c->regions()[i].reflectance == regions[i].reflectance ||
                    (std::isnan(c->regions()[i].reflectance) && std::isnan(regions[i].reflectance)));
        }
        QCOMPARE(c->params().fit.spectrometerPct, 0.3);
        QCOMPARE(r.vmField()->value(), 0.3);
        QCOMPARE(c->run().fit.fit.k, k);
        QCOMPARE(c->run().fit.fit.b, b);
        // A malformed session is refused and changes nothing.
        QJsonObject bad = state;
        QJsonArray ra = bad["regions"].toArray();
        QJsonObject r0 = ra[0].toObject();
        r0["role"] = "calibration";
        ra[0] = r0;
        bad["regions"] = ra;
        QVERIFY(!r.restoreState(bad, &err));
        QVERIFY2(err.contains("role"), qPrintable(err));
        bad = state;
        QJsonObject p = bad["params"].toObject();
        p["dn_min"] = 70000;  // above dn_max
        bad["params"] = p;
        QVERIFY(!r.restoreState(bad, &err));
        QVERIFY2(err.contains("range"), qPrintable(err));
        bad = state;
        bad["demo"] = false;
        bad["image"] = path("missing.tif");
        QVERIFY(!r.restoreState(bad, &err));
        QVERIFY2(err.contains("missing.tif"), qPrintable(err));
        QVERIFY(c->waitIdle(30000));
        QCOMPARE(c->image().source, QString("demo"));
        QCOMPARE(c->regions().size(), regions.size());
        QCOMPARE(c->params().fit.spectrometerPct, 0.3);
        QCOMPARE(c->run().fit.fit.k, k);
    }
};

QTEST_MAIN(TestRadiometryWorkspace)
#include "test_radiometry_workspace.moc"
