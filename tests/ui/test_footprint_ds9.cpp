// DS9-grade image review in the footprint workspace (issue 30): contrast / bias by a drag on the
// ROI view, the frame view and the colour bar; box and circle regions with their statistics;
// blink and tile of several shots with zoom and display locked; the view exported with its
// overlays.
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QInputDialog>
#include <QItemSelectionModel>
#include <QLabel>
#include <QMenu>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QTimer>
#include <QtTest>
#include <cmath>

#include "core/common/region_stats.hpp"
#include "test_support.hpp"
#include "ui_support.hpp"
#include "ui/footprint/blink_view.hpp"
#include "ui/kit/display_controls.hpp"
#include "ui/footprint/footprint_workspace.hpp"
#include "ui/kit/image_view.hpp"
#include "ui/shell/main_window.hpp"
#include "ui/footprint/shot_table_model.hpp"

using namespace lwb::ui;

namespace {
bool loadAndWait(FootprintController* c, const QStringList& inputs) {
    QSignalSpy finished(c, &FootprintController::loadFinished);
    c->open(inputs);
    return finished.wait(30000) && c->waitIdle(30000);
}

bool showShot(FootprintWorkspace* fw, int row) {
    QSignalSpy detail(fw->controller(), &FootprintController::currentDetailReady);
    fw->selectRow(row);
    if (fw->controller()->current() != row) return false;
    fw->controller()->setCurrent(row);
    return !detail.isEmpty() || detail.wait(10000);
}

// (the shared drag helper: tests/ui_support.hpp)
void drag(QWidget* w, Qt::MouseButton button, Qt::KeyboardModifiers mods, QPointF from, QPointF to) {
    lwbtest::mouseDrag(w, button, mods, from, to);
}

int countColour(const QImage& img, QColor c, int tol) {
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x) {
            const QColor p = img.pixelColor(x, y);
            n += std::abs(p.red() - c.red()) <= tol && std::abs(p.green() - c.green()) <= tol && std::abs(p.blue() - c.blue()) <= tol;
        }
    return n;
}

// The statistics of the pixels (x0..x1, y0..y1) of a float image, by a plain loop.
struct Plain {
    int n = 0;
    double sum = 0, min = 1e300, max = -1e300, sx = 0, sy = 0;
};
Plain plainStats(const cv::Mat& m, int x0, int x1, int y0, int y1) {
    Plain s;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double v = m.at<float>(y, x);
            ++s.n;
            s.sum += v;
            s.min = std::min(s.min, v);
            s.max = std::max(s.max, v);
            s.sx += v * x;
            s.sy += v * y;
        }
    return s;
}
}  // namespace

class TestFootprintDs9 : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        const auto sim = lwbtest::runCli({"simulate", "footprint", "--count", "3", "--seed", "7", "--full-frame", "-q", m_dir.path() + "/frames"});
        QVERIFY2(sim.exitCode == 0, qPrintable(sim.err));
    }

    // Middle-drag and Ctrl+drag on the ROI view, a drag on the frame view and on the colour
    // bar: bias to the right moves the window of DN up, a drag down narrows it; the low and high
    // fields (Manual) follow; a double-click on the colour bar goes back to min–max.
    void contrastBiasDragMovesTheLimits() {
        MainWindow w;
        FootprintWorkspace* fw = w.workspace<lwb::ui::FootprintWorkspace>();
        QVERIFY(loadAndWait(fw->controller(), {m_dir.path() + "/frames"}));
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(showShot(fw, 0));
        DisplayControls* dc = fw->displayControls();
        ImageView* roi = fw->roiView();
        QCOMPARE(dc->limitsBox()->currentIndex(), int(LimitsMode::MinMax));
        const double lo0 = fw->histogram()->limitLo(), hi0 = fw->histogram()->limitHi(), w0 = hi0 - lo0;
        QVERIFY(w0 > 100);
        // Bias: a quarter of the view's width to the right moves the middle up by a quarter of the window.
        const QPointF c = roi->rect().center();
        drag(roi, Qt::MiddleButton, {}, c, c + QPointF(roi->width() / 4.0, 0));
        QCOMPARE(dc->limitsBox()->currentIndex(), int(LimitsMode::Manual));
        QVERIFY2(std::abs(dc->low() - (lo0 + w0 / 4)) <= 1 && std::abs(dc->high() - (hi0 + w0 / 4)) <= 1,
                 qPrintable(QString("%1..%2 -> %3..%4").arg(lo0).arg(hi0).arg(dc->low()).arg(dc->high())));
        QCOMPARE(fw->histogram()->limitLo(), dc->low());  // drawn with the new limits
        QCOMPARE(fw->colorBar()->hi(), dc->high());
        // Contrast: Ctrl+right-drag down half the height narrows the window by √10 about its middle.
        const double mid = (dc->low() + dc->high()) / 2, width1 = dc->high() - dc->low();
        drag(roi, Qt::RightButton, Qt::ControlModifier, c, c + QPointF(0, roi->height() / 2.0));
        QVERIFY2(std::abs((dc->high() - dc->low()) - width1 / std::sqrt(10.0)) <= 2,
                 qPrintable(QString("width %1 -> %2").arg(width1).arg(dc->high() - dc->low())));
        QVERIFY(std::abs((dc->low() + dc->high()) / 2 - mid) <= 1);
        QVERIFY2(std::abs(roi->zoom() - roi->fitZoom()) < 1e-9, "a contrast drag neither pans nor zooms");
        // Up widens it again.
        const double narrow = dc->high() - dc->low();
        drag(roi, Qt::LeftButton, Qt::ControlModifier, c, c - QPointF(0, roi->height() / 4.0));
        QVERIFY(dc->high() - dc->low() > 1.5 * narrow);
        // The frame view too: bias to the left moves the window down.
        ImageView* frame = fw->frameView();
        QVERIFY(frame->isVisible() && frame->hasImage());
        const double before = dc->low();
        drag(frame, Qt::MiddleButton, {}, frame->rect().center(), frame->rect().center() - QPointF(frame->width() / 5.0, 0));
        QVERIFY2(dc->low() < before - 10, qPrintable(QString("%1 -> %2").arg(before).arg(dc->low())));
        // The colour bar: a drag to the right raises the limits.
        const double beforeBar = dc->low();
        ColorBar* bar = fw->colorBar();
        drag(bar, Qt::LeftButton, {}, bar->barRect().center(), bar->barRect().center() + QPointF(bar->barRect().width() / 4.0, 0));
        QVERIFY2(dc->low() > beforeBar + 10, qPrintable(QString("%1 -> %2").arg(beforeBar).arg(dc->low())));
        // Double-click on the bar: the settings before the first drag (min–max).
        QTest::mouseDClick(bar, Qt::LeftButton, {}, bar->barRect().center());
        QCOMPARE(dc->limitsBox()->currentIndex(), int(LimitsMode::MinMax));
        QCOMPARE(fw->histogram()->limitLo(), lo0);
        QCOMPARE(fw->histogram()->limitHi(), hi0);
        // The views' menu offers the reset too.
        drag(roi, Qt::MiddleButton, {}, c, c + QPointF(30, 0));
        QCOMPARE(dc->limitsBox()->currentIndex(), int(LimitsMode::Manual));
        QSignalSpy reset(roi, &ImageView::contrastBiasResetRequested);
        QTimer::singleShot(100, [] {
            auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
            if (!menu) return;
            for (QAction* a : menu->actions())
                if (a->text().startsWith("Reset contrast")) a->trigger();
            menu->close();
        });
        QTest::mouseClick(roi, Qt::RightButton, {}, c.toPoint());
        QCOMPARE(reset.count(), 1);
        QCOMPARE(dc->limitsBox()->currentIndex(), int(LimitsMode::MinMax));
        QCOMPARE(fw->histogram()->limitHi(), hi0);
    }

    // A box drawn corner to corner, moved, a circle, one partly outside the ROI: the statistics
    // under the views are those of the pixels inside, in full-frame coordinates.
    void regionsShowTheirStatistics() {
        MainWindow w;
        FootprintWorkspace* fw = w.workspace<lwb::ui::FootprintWorkspace>();
        QVERIFY(loadAndWait(fw->controller(), {m_dir.path() + "/frames"}));
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(showShot(fw, 1));
        ImageView* roi = fw->roiView();
        const cv::Mat data = fw->controller()->shot(1)->roi;
        const QPointF origin = roi->origin();
        QVERIFY(origin.x() > 0 && origin.y() > 0);  // a ROI cut from a full frame
        // Pan mode: a drag pans and draws nothing.
        drag(roi, Qt::LeftButton, {}, roi->toWidget({9.6, 10.6}), roi->toWidget({17.6, 16.6}));
        QVERIFY(roi->regions().isEmpty());
        roi->fitToWindow();
        roi->setMouseMode(ImageView::MouseMode::BoxRegion);
        // A click draws nothing either.
        QTest::mouseClick(roi, Qt::LeftButton, {}, roi->toWidget({5, 5}).toPoint());
        QVERIFY(roi->regions().isEmpty());
        // x in [9.6, 17.6) → columns 10..17, y in [10.6, 16.6) → rows 11..16: 48 pixels.
        drag(roi, Qt::LeftButton, {}, roi->toWidget({9.6, 10.6}), roi->toWidget({17.6, 16.6}));
        QCOMPARE(roi->regions().size(), 1);
        lwb::core::RegionStatsResult s = roi->regionStats().first();
        Plain want = plainStats(data, 10, 17, 11, 16);
        QVERIFY(s.ok);
        QCOMPARE(s.count, size_t(48));
        QVERIFY2(std::abs(s.sum - want.sum) < 1e-6 * want.sum,
                 qPrintable(QString("sum %1, loop %2; centre %3,%4 size %5x%6; data %7x%8 same as shot: %9")
                                .arg(s.sum).arg(want.sum).arg(roi->regions()[0].centerX).arg(roi->regions()[0].centerY)
                                .arg(roi->regions()[0].width).arg(roi->regions()[0].height).arg(data.cols).arg(data.rows)
                                .arg(cv::norm(data, fw->controller()->shot(fw->controller()->current())->roi) == 0)));
        QCOMPARE(s.min, want.min);
        QCOMPARE(s.max, want.max);
        QVERIFY(std::abs(s.centroidX - want.sx / want.sum) < 1e-9);
        QLabel* label = fw->regionStatsLabel();
        QVERIFY(label->isVisible());
        QVERIFY2(label->text().contains("ROI Box 1") && label->text().contains("n 48"), qPrintable(label->text()));
        auto fmt = [](double v) { return QString::number(v, 'f', std::abs(v) >= 100 ? 1 : 2); };
        const QString centroid =
            QString("centroid (%1, %2)").arg(fmt(want.sx / want.sum + origin.x()), fmt(want.sy / want.sum + origin.y()));
        QVERIFY2(label->text().contains(centroid), qPrintable(label->text() + " / " + centroid));
        // Drag the box 2 px right: columns 12..19.
        drag(roi, Qt::LeftButton, {}, roi->toWidget({13, 13}), roi->toWidget({15, 13}));
        QCOMPARE(roi->regions().size(), 1);
        s = roi->regionStats().first();
        want = plainStats(data, 12, 19, 11, 16);
        QCOMPARE(s.count, size_t(48));
        QVERIFY(std::abs(s.sum - want.sum) < 1e-6 * want.sum);
        // A circle from the centre (5, 5) out to radius 3: 29 pixel centres.
        roi->setMouseMode(ImageView::MouseMode::CircleRegion);
        drag(roi, Qt::LeftButton, {}, roi->toWidget({5, 5}), roi->toWidget({8, 5}));
        QCOMPARE(roi->regions().size(), 2);
        QCOMPARE(roi->regionStats()[1].count, size_t(29));
        // About the ROI's corner pixel: the part outside the image counted apart.
        drag(roi, Qt::LeftButton, {}, roi->toWidget({0, 0}), roi->toWidget({0, 2.5}));
        const lwb::core::RegionStatsResult corner = roi->regionStats()[2];
        want = plainStats(data, 0, 2, 0, 2);
        want.sum -= data.at<float>(2, 2);  // (2, 2) is 2.83 px away
        QCOMPARE(corner.count, size_t(8));
        QCOMPARE(corner.outside, size_t(21 - 8));  // 21 centres within 2.5 px of (0, 0)
        QVERIFY(std::abs(corner.sum - want.sum) < 1e-6 * want.sum);
        QVERIFY(label->text().contains("13 px outside the image"));
        // Regions stay with the next shot and are measured on it.
        QVERIFY(showShot(fw, 2));
        QCOMPARE(roi->regions().size(), 3);
        const Plain next = plainStats(fw->controller()->shot(2)->roi, 12, 19, 11, 16);
        QVERIFY(std::abs(roi->regionStats().first().sum - next.sum) < 1e-6 * next.sum);
        // Delete removes the selected region (the last drawn).
        roi->setFocus();
        QTest::keyClick(roi, Qt::Key_Delete);
        QCOMPARE(roi->regions().size(), 2);
        QVERIFY(!label->text().contains("Circle 3"));
    }

    // Three shots tiled: a zoom step or a pan on one tile moves every tile; a contrast drag on
    // one sets the limits of all; blinking cycles them at the interval.
    void blinkAndTileLockZoomAndDisplay() {
        MainWindow w;
        FootprintWorkspace* fw = w.workspace<lwb::ui::FootprintWorkspace>();
        QVERIFY(loadAndWait(fw->controller(), {m_dir.path() + "/frames"}));
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(showShot(fw, 0));
        QItemSelectionModel* sel = fw->table()->selectionModel();
        sel->select(QItemSelection(fw->proxy()->index(0, 0), fw->proxy()->index(2, 0)),
                    QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        QCOMPARE(sel->selectedRows().size(), 3);
        fw->table()->setFocus();
        QTest::keyClick(fw->table(), Qt::Key_B);  // B opens it
        const QList<BlinkView*> opened = fw->findChildren<BlinkView*>();
        QCOMPARE(opened.size(), 1);
        BlinkView* bv = opened.first();
        QVERIFY(QTest::qWaitForWindowExposed(bv));
        QCOMPARE(bv->frameCount(), 3);
        QCOMPARE(bv->mode(), BlinkView::Mode::Tile);
        for (int i = 0; i < 3; ++i) QVERIFY(bv->tile(i)->isVisible() && bv->tile(i)->hasImage());
        // Zoom on tile 0: the others follow, relative to their fits, about the same point.
        bv->tile(0)->setZoomStep(4);
        for (int i = 1; i < 3; ++i) {
            QVERIFY2(std::abs(bv->tile(i)->viewState().magnification - 4) < 1e-9,
                     qPrintable(QString::number(bv->tile(i)->viewState().magnification)));
            QVERIFY((bv->tile(i)->viewState().centre - bv->tile(0)->viewState().centre).manhattanLength() < 1e-6);
        }
        // A pan on tile 2 moves tiles 0 and 1.
        const QPointF before = bv->tile(0)->viewState().centre;
        ImageView* t2 = bv->tile(2);
        drag(t2, Qt::LeftButton, {}, t2->rect().center(), t2->rect().center() + QPointF(40, 0));
        QVERIFY(bv->tile(0)->viewState().centre.x() < before.x() - 0.5);
        QVERIFY((bv->tile(0)->viewState().centre - t2->viewState().centre).manhattanLength() < 1e-6);
        QVERIFY((bv->tile(1)->viewState().centre - t2->viewState().centre).manhattanLength() < 1e-6);
        // The wheel on tile 1 too.
        const QPointF under = bv->tile(1)->rect().center();
        QWheelEvent wheel(under, bv->tile(1)->mapToGlobal(under), QPoint(), QPoint(0, 240), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(bv->tile(1), &wheel);
        QVERIFY(bv->tile(0)->viewState().magnification > 4.5);
        QVERIFY(std::abs(bv->tile(0)->viewState().magnification - bv->tile(1)->viewState().magnification) < 1e-9);
        // One set of limits for all: the front shot's min–max at first.
        const lwb::core::DisplayLimits l0 = bv->limits();
        double mn = 0, mx = 0;
        cv::minMaxLoc(fw->controller()->shot(fw->proxy()->mapToSource(fw->proxy()->index(0, 0)).row())->roi, &mn, &mx);
        QCOMPARE(l0.lo, mn);
        QCOMPARE(l0.hi, mx);
        // A contrast drag on tile 1: every tile's limits change together (bias right: up).
        drag(bv->tile(1), Qt::MiddleButton, {}, under, under + QPointF(bv->tile(1)->width() / 4.0, 0));
        QCOMPARE(bv->displayControls()->limitsBox()->currentIndex(), int(LimitsMode::Manual));
        QVERIFY(bv->limits().lo > l0.lo + 10);
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(bv->tileLimits(i).lo, bv->limits().lo);
            QCOMPARE(bv->tileLimits(i).hi, bv->limits().hi);
        }
        // Blink: one tile shown at a time, cycled at the interval, still zoomed as locked.
        bv->setInterval(60);
        bv->setMode(BlinkView::Mode::Blink);
        QVERIFY(bv->playing());
        int shown = 0;
        for (int i = 0; i < 3; ++i) shown += bv->tile(i)->isVisible();
        QCOMPARE(shown, 1);
        QSet<int> seen;
        QElapsedTimer t;
        t.start();
        while (seen.size() < 3 && t.elapsed() < 5000) {
            seen.insert(bv->currentFrame());
            QTest::qWait(20);
        }
        QCOMPARE(seen.size(), 3);
        bv->setPlaying(false);
        QTest::qWait(50);
        const int front = bv->currentFrame();
        QVERIFY(bv->tile(front)->isVisible());
        QVERIFY2(std::abs(bv->tile(front)->viewState().magnification - bv->tile(0)->viewState().magnification) < 1e-6 ||
                     front == 0,
                 qPrintable(QString("the blinking tile keeps the locked zoom: front %1 at %2, tile 0 at %3")
                                .arg(front).arg(bv->tile(front)->viewState().magnification).arg(bv->tile(0)->viewState().magnification)));
        // Back in an automatic mode, the limits are the front shot's, for every tile.
        bv->displayControls()->limitsBox()->setCurrentIndex(int(LimitsMode::MinMax));
        bv->setCurrentFrame(2);
        cv::minMaxLoc(fw->controller()->shot(fw->proxy()->mapToSource(fw->proxy()->index(2, 0)).row())->roi, &mn, &mx);
        QCOMPARE(bv->limits().lo, mn);
        QCOMPARE(bv->tileLimits(0).hi, mx);
        bv->close();
    }

    // The ROI view with its fits, centres, a region and the badge, to PNG at a chosen width (and
    // SVG, PDF); without the overlays the same export has none of their colours.
    void exportTheViewWithItsOverlays() {
        MainWindow w;
        FootprintWorkspace* fw = w.workspace<lwb::ui::FootprintWorkspace>();
        QVERIFY(loadAndWait(fw->controller(), {m_dir.path() + "/frames"}));
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        int row = -1;  // a shot with a Gaussian fit
        for (int i = 0; i < fw->controller()->count() && row < 0; ++i)
            if (fw->controller()->shot(i)->fit.ok) row = i;
        QVERIFY(row >= 0);
        QVERIFY(showShot(fw, row));
        ImageView* roi = fw->roiView();
        lwb::core::RegionStatsParams box;
        box.centerX = 6;
        box.centerY = 6;
        box.width = box.height = 6;
        roi->setRegions({box});
        const QString png = m_dir.path() + "/view.png";
        QString err;
        QVERIFY2(roi->exportView(png, 900, &err), qPrintable(err));
        QImage img(png);
        QCOMPARE(img.width(), 900);
        QCOMPARE(img.height(), roi->exportHeight(900));
        QVERIFY(img.height() > 800);  // a square ROI
        const QColor gauss(0, 220, 255), green(0, 255, 0);
        const int gaussPx = countColour(img, gauss, 40), greenPx = countColour(img, green, 40);
        QVERIFY2(gaussPx > 200 && greenPx > 200, qPrintable(QString("fit %1 px, region %2 px").arg(gaussPx).arg(greenPx)));
        // The badge: the verdict's colour, behind white text, in a corner.
        const Shot* s = fw->controller()->shot(row);
        const QColor badge = verdictColor(s->effectiveVerdict());
        QVERIFY2(countColour(img, badge, 45) > 300, qPrintable(QString::number(countColour(img, badge, 45))));
        // Without the overlays and the region, none of their colours.
        for (QCheckBox* b : fw->findChildren<QCheckBox*>()) b->setChecked(false);
        roi->setRegions({});
        QVERIFY(roi->exportView(m_dir.path() + "/bare.png", 900, &err));
        const QImage bare(m_dir.path() + "/bare.png");
        QVERIFY2(countColour(bare, gauss, 40) < gaussPx / 10 && countColour(bare, green, 40) < greenPx / 10,
                 qPrintable(QString("%1 %2").arg(countColour(bare, gauss, 40)).arg(countColour(bare, green, 40))));
        for (QCheckBox* b : fw->findChildren<QCheckBox*>()) b->setChecked(true);
        // SVG and PDF.
        QVERIFY2(roi->exportView(m_dir.path() + "/view.svg", 600, &err), qPrintable(err));
        QFile svg(m_dir.path() + "/view.svg");
        QVERIFY(svg.open(QIODevice::ReadOnly));
        const QByteArray svgText = svg.readAll();
        QVERIFY(svgText.contains("<svg") && svgText.contains("<image"));
        QVERIFY2(roi->exportView(m_dir.path() + "/view.pdf", 600, &err), qPrintable(err));
        QFile pdf(m_dir.path() + "/view.pdf");
        QVERIFY(pdf.open(QIODevice::ReadOnly));
        QVERIFY(pdf.read(5) == "%PDF-");
        // The dialogs: a width, then the file, offered as the shot's stem with _roi.
        QString offered;

        QTimer::singleShot(200, [&] {
            auto* in = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
            if (!in) return;
            in->setIntValue(640);
            in->accept();
            QTimer::singleShot(200, [&] {
                auto* fd = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
                if (!fd) return;
                offered = fd->selectedFiles().value(0);
                fd->setDirectory(m_dir.path());
                fd->selectFile(QFileInfo(offered).fileName());
                QMetaObject::invokeMethod(fd, "accept");
            });
        });
        QVERIFY(roi->exportDialog());
        QVERIFY2(offered.endsWith(QFileInfo(s->file).completeBaseName() + "_roi.png"), qPrintable(offered));
        const QImage viaDialog(m_dir.path() + "/" + QFileInfo(offered).fileName());
        QCOMPARE(viaDialog.width(), 640);
    }
};

QTEST_MAIN(TestFootprintDs9)
#include "test_footprint_ds9.moc"
