// The footprint shot list's filter expression, the column plot and the trend layout (issue 30):
// the filter narrows the table, the contact sheet, the trend's input and the plot; an invalid
// expression keeps the filter in force and says why; the session keeps the filter; X / Y columns
// plot one point per shot with both values; the trend plots keep their labels and ticks apart at
// 1024x700.
#include <QApplication>
#include <QComboBox>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTableView>
#include <QtTest>
#include <cmath>
#include <qcustomplot.h>

#include "test_support.hpp"
#include "ui/footprint/column_plot.hpp"
#include "ui/footprint/contact_sheet.hpp"
#include "ui/footprint/filter_field.hpp"
#include "ui/footprint/footprint_workspace.hpp"
#include "ui/shell/main_window.hpp"
#include "ui/footprint/shot_columns.hpp"
#include "ui/footprint/shot_table_model.hpp"

using namespace lwb::ui;

namespace {
bool showDemo(MainWindow& w, QSize size = {1400, 900}) {
    if (!w.openDemo() || !w.workspace<lwb::ui::FootprintWorkspace>()->controller()->waitIdle(60000)) return false;
    w.resize(size);
    w.show();
    w.activateWindow();
    return QTest::qWaitForWindowExposed(&w);
}

int currentSource(FootprintWorkspace* fw) {
    const QModelIndex i = fw->table()->currentIndex();
    return i.isValid() ? fw->proxy()->mapToSource(i).row() : -1;
}

// Good shots with a fit, a time and a beam among the rows for which `pick` holds: the trend's input.
template <class F>
int trendInput(const FootprintController* c, F pick) {
    int n = 0;
    for (int i = 0; i < c->count(); ++i) {
        const Shot& s = *c->shot(i);
        n += pick(s) && s.effectiveVerdict() == Verdict::Good && s.fit.ok && !s.time.isEmpty() && !s.beam.isEmpty();
    }
    return n;
}

// Shot points on the trend's X plot (the shot graphs: even indices).
int trendShotPoints(FootprintWorkspace* fw) {
    QCustomPlot* p = fw->trendPlots().at(0);
    int n = 0;
    for (int g = 0; g < p->graphCount(); g += 2) n += p->graph(g)->dataCount();
    return n;
}

void click(QWidget* w, QPoint at) {
    QMouseEvent press(QEvent::MouseButtonPress, at, w->mapToGlobal(at), Qt::LeftButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(w, &press);
    QMouseEvent release(QEvent::MouseButtonRelease, at, w->mapToGlobal(at), Qt::LeftButton, Qt::NoButton, Qt::NoModifier);
    QApplication::sendEvent(w, &release);
}
}  // namespace

class TestFootprintFilter : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void filterNarrowsTableSheetTrendAndPlot() {
        MainWindow w;
        QVERIFY(showDemo(w));
        FootprintWorkspace* fw = w.workspace<lwb::ui::FootprintWorkspace>();
        const FootprintController* c = fw->controller();
        const int all = c->count();
        QVERIFY(all > 100);
        QCOMPARE(fw->proxy()->rowCount(), all);
        QCOMPARE(fw->contactSheet()->model()->rowCount(), all);
        const int trendAll = trendShotPoints(fw);
        QCOMPARE(trendAll, trendInput(c, [](const Shot&) { return true; }));
        QCOMPARE(fw->trendPlots().at(2)->graphCount(), 2);  // both beams
        QVERIFY(!fw->trendSummary()->text().contains("Filter applied"));

        fw->whereField()->setText("beam == 2");
        int beam2 = 0;
        for (const Shot& s : c->shots()) beam2 += s.beam == "2";
        QVERIFY(beam2 > 10 && beam2 < all);
        QCOMPARE(fw->proxy()->rowCount(), beam2);
        QCOMPARE(fw->contactSheet()->model()->rowCount(), beam2);
        QCOMPARE(fw->trendPlots().at(2)->graphCount(), 1);  // one beam's pointing
        QCOMPARE(trendShotPoints(fw), trendInput(c, [](const Shot& s) { return s.beam == "2"; }));
        QVERIFY2(fw->trendSummary()->text().contains(QString("Filter applied: the trend of the %1 of %2 shots").arg(beam2).arg(all)),
                 qPrintable(fw->trendSummary()->text()));

        // Combined with the verdict choice: doubtful shots of beam 2 only.
        fw->filterBox()->setCurrentIndex(ShotFilterProxy::DoubtfulOnly);
        int doubtful2 = 0;
        for (const Shot& s : c->shots()) doubtful2 += s.beam == "2" && s.effectiveVerdict() == Verdict::Doubtful && s.loadError.isEmpty();
        QVERIFY(doubtful2 > 0);
        QCOMPARE(fw->proxy()->rowCount(), doubtful2);
        QCOMPARE(fw->contactSheet()->model()->rowCount(), doubtful2);
        fw->filterBox()->setCurrentIndex(ShotFilterProxy::All);

        // A number column: the SNR below its median leaves about half of the fitted shots.
        std::vector<double> snr;
        for (const Shot& s : c->shots())
            if (s.fit.ok) snr.push_back(s.fit.snr);
        std::sort(snr.begin(), snr.end());
        const double median = snr[snr.size() / 2];
        fw->whereField()->setText(QString("snr < %1").arg(median, 0, 'g', 17));
        int below = 0;
        for (const Shot& s : c->shots()) below += s.fit.ok && s.fit.snr < median;
        QCOMPARE(fw->proxy()->rowCount(), below);
        QCOMPARE(fw->columnPlot()->pointCount() <= below, true);

        fw->whereField()->clear();
        QCOMPARE(fw->proxy()->rowCount(), all);
        QCOMPARE(trendShotPoints(fw), trendAll);
        QVERIFY(!fw->trendSummary()->text().contains("Filter applied"));
    }

    void invalidExpressionKeepsThePreviousFilter() {
        MainWindow w;
        QVERIFY(showDemo(w));
        FootprintWorkspace* fw = w.workspace<lwb::ui::FootprintWorkspace>();
        fw->whereField()->setText("beam == 1");
        const int beam1 = fw->proxy()->rowCount();
        QVERIFY(beam1 > 0 && beam1 < fw->controller()->count());
        QVERIFY(!fw->whereField()->hasError());
        QSignalSpy status(fw, &FootprintWorkspace::status);
        fw->whereField()->setText("snrr < 3");
        QCOMPARE(fw->proxy()->rowCount(), beam1);  // the filter in force stays
        QCOMPARE(fw->proxy()->expression(), QString("beam == 1"));
        QVERIFY(fw->whereField()->hasError());
        QVERIFY2(fw->whereField()->error().startsWith("column 'snrr' unknown at 1; columns: file, time, beam"),
                 qPrintable(fw->whereField()->error()));
        QVERIFY(fw->whereField()->styleSheet().contains("#c0392b"));
        QVERIFY(fw->whereField()->toolTip().contains("column 'snrr' unknown at 1"));
        QVERIFY(!status.isEmpty());
        QVERIFY(status.last().at(0).toString().contains("column 'snrr' unknown at 1"));
        fw->whereField()->setText("snr < 3 and");
        QVERIFY(fw->whereField()->error().contains("at 12"));
        QCOMPARE(fw->proxy()->rowCount(), beam1);
        // Valid again: applied, the mark gone, the tooltip back to the help.
        fw->whereField()->setText("beam == 1 and verdict == \"good\"");
        QVERIFY(!fw->whereField()->hasError());
        QVERIFY(fw->whereField()->styleSheet().isEmpty());
        QVERIFY(!fw->whereField()->toolTip().contains("snrr"));
        QVERIFY(fw->whereField()->toolTip().contains("amplitude_dn"));
        QVERIFY(fw->proxy()->rowCount() < beam1);
    }

    void sessionRoundTripsTheFilterAndThePlot() {
        const QString session = m_dir.path() + "/where.lwb.json";
        const QString expr = "snr < 40 or verdict == \"doubtful\"";
        int rows = 0;
        {
            MainWindow w;
            QVERIFY(showDemo(w));
            FootprintWorkspace* fw = w.workspace<lwb::ui::FootprintWorkspace>();
            fw->whereField()->setText(expr);
            rows = fw->proxy()->rowCount();
            QVERIFY(rows > 0 && rows < fw->controller()->count());
            QVERIFY(fw->columnPlot()->setColumns("time", "snr"));
            QString err;
            QVERIFY2(w.saveSession(session, &err), qPrintable(err));
        }
        MainWindow w2;
        QString err;
        QVERIFY2(w2.openSession(session, true, &err), qPrintable(err));
        QVERIFY(w2.workspace<lwb::ui::FootprintWorkspace>()->controller()->waitIdle(60000));
        FootprintWorkspace* fw = w2.workspace<lwb::ui::FootprintWorkspace>();
        QCOMPARE(fw->whereField()->text(), expr);
        QCOMPARE(fw->proxy()->expression(), expr);
        QCOMPARE(fw->proxy()->rowCount(), rows);
        QCOMPARE(fw->columnPlot()->xColumn(), QString("time"));
        QCOMPARE(fw->columnPlot()->yColumn(), QString("snr"));
    }

    void columnPlotPointsAndClick() {
        MainWindow w;
        QVERIFY(showDemo(w));
        FootprintWorkspace* fw = w.workspace<lwb::ui::FootprintWorkspace>();
        const FootprintController* c = fw->controller();
        fw->showTab("plot");
        ColumnPlot* cp = fw->columnPlot();
        QVERIFY(cp->setColumns("snr", "amplitude_dn"));
        int fitted = 0, goodFitted = 0, shown = 0;
        for (const Shot& s : c->shots()) {
            fitted += s.fit.ok && std::isfinite(s.fit.snr) && std::isfinite(s.fit.amplitude);
            goodFitted += s.fit.ok && s.effectiveVerdict() == Verdict::Good;
            shown += s.fit.ok && s.effectiveVerdict() != Verdict::Rejected;  // x is empty when rejected
        }
        QCOMPARE(cp->pointCount(), fitted);
        int drawn = 0;
        for (int g = 0; g < cp->plot()->graphCount(); ++g) drawn += cp->plot()->graph(g)->dataCount();
        QCOMPARE(drawn, fitted + 1);  // + the ring on the current shot
        QCOMPARE(cp->plot()->xAxis->label(), QString("snr"));
        QCOMPARE(cp->plot()->yAxis->label(), QString("amplitude_dn (DN)"));
        // dx against dy: no point for a rejected shot (its position is empty, as in the table).
        QVERIFY(cp->setColumns("dx", "dy"));
        QCOMPARE(cp->pointCount(), shown);
        // The filter applies.
        fw->whereField()->setText("verdict == \"good\"");
        cp->refresh();
        QCOMPARE(cp->pointCount(), goodFitted);
        // Time along x: dates in UTC.
        QVERIFY(cp->setColumns("time", "snr"));
        QVERIFY(cp->plot()->xAxis->ticker().dynamicCast<QCPAxisTickerDateTime>());
        QCOMPARE(cp->pointCount(), goodFitted);
        // A click on a point makes its shot current in the table.
        cp->plot()->replot();
        int target = -1;
        for (int i = c->count() - 1; i >= 0 && target < 0; --i)
            if (c->shot(i)->fit.ok && c->shot(i)->effectiveVerdict() == Verdict::Good && i != currentSource(fw)) target = i;
        QVERIFY(target >= 0);
        const QPoint at = cp->pixelOf(target);
        QVERIFY(cp->plot()->axisRect()->rect().contains(at));
        const int hit = cp->rowAt(at);
        QVERIFY(hit >= 0);  // the target or a point drawn on top of it
        click(cp->plot(), at);
        QCOMPARE(currentSource(fw), hit);
        QCOMPARE(c->current(), hit);
    }

    // The analyst's report at 1024x700: tick labels overlapped, the "Pointing change (arc…" label
    // was clipped, titles collided.
    void trendPlotsAt1024x700() {
        MainWindow w;
        QVERIFY(showDemo(w, {1024, 700}));
        FootprintWorkspace* fw = w.workspace<lwb::ui::FootprintWorkspace>();
        fw->showTab("trend");
        QTest::qWait(50);
        const QList<QCustomPlot*> plots = fw->trendPlots();
        QCOMPARE(plots.size(), 3);
        for (QCustomPlot* p : plots) {
            p->replot();
            const QRect ar = p->axisRect()->rect();
            QVERIFY2(ar.height() >= 60, qPrintable(QString("axis rect %1 px high").arg(ar.height())));
            // The y label is drawn along the axis rect: it must fit its height.
            const QFontMetrics fm(p->yAxis->labelFont());
            QVERIFY2(fm.horizontalAdvance(p->yAxis->label()) <= ar.height(),
                     qPrintable(QString("'%1' is %2 px, the axis %3 px").arg(p->yAxis->label()).arg(fm.horizontalAdvance(p->yAxis->label())).arg(ar.height())));
            QVERIFY(p->rect().contains(ar));
            QVERIFY2(!p->legend->visible() || !p->legend->outerRect().intersects(ar), "the legend covers the data");
            // Tick labels apart: on x, each label's width fits between its ticks; on y, the font's height.
            for (QCPAxis* a : {p->xAxis, p->yAxis}) {
                const QFontMetrics tf(a->tickLabelFont());
                const QVector<double> ticks = a->tickVector();
                const QVector<QString> labels = a->tickVectorLabels();
                QVERIFY(ticks.size() >= 2);
                for (int i = 1; i < ticks.size(); ++i) {
                    const double gap = std::abs(a->coordToPixel(ticks[i]) - a->coordToPixel(ticks[i - 1]));
                    const double need = a->orientation() == Qt::Horizontal
                                            ? (tf.horizontalAdvance(labels[i]) + tf.horizontalAdvance(labels[i - 1])) / 2.0 + 4
                                            : tf.height();
                    QVERIFY2(gap >= need, qPrintable(QString("%1 and %2: %3 px apart, %4 needed")
                                                         .arg(labels[i - 1], labels[i]).arg(gap).arg(need)));
                }
            }
        }
        // The plots do not overlap one another.
        for (int i = 1; i < plots.size(); ++i)
            QVERIFY(!plots[i]->geometry().intersects(plots[i - 1]->geometry()));
        w.grab().save(m_dir.path() + "/trend_1024x700.png");
    }
};

QTEST_MAIN(TestFootprintFilter)
#include "test_footprint_filter.moc"
