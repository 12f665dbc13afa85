#pragma once
// The footprint workspace's "Plot" tab: any column of the shot list against any other (residual
// against elevation, SNR against time, dx against dy), over the shots of the table's view (its
// verdict choice and filter expression), each point coloured by its verdict. A click on a point
// makes that shot current in the table. Built on the plot kit (export, box zoom, theme; a UTC
// time axis for the time column).
#include <QPoint>
#include <QWidget>
#include <vector>

class QComboBox;
class QCustomPlot;
class QLabel;
class QTimer;

namespace lwb::ui {

class FootprintController;
class ShotFilterProxy;

class ColumnPlot : public QWidget {
    Q_OBJECT
public:
    ColumnPlot(FootprintController* c, ShotFilterProxy* view, QWidget* parent = nullptr);
    QComboBox* xBox() const { return m_x; }
    QComboBox* yBox() const { return m_y; }
    QCustomPlot* plot() const { return m_plot; }
    QLabel* info() const { return m_info; }
    /// Chooses the columns by name (shot_columns.hpp); false when one is not plottable.
    bool setColumns(const QString& x, const QString& y);
    QString xColumn() const;
    QString yColumn() const;
    /// Points drawn (shots of the view with both values).
    int pointCount() const { return int(m_points.size()); }
    /// Redraws from the view now (changes of the view are otherwise gathered and redrawn soon).
    void refresh();
    /// Ring on the current shot (-1: none).
    void setCurrentRow(int sourceRow);
    /// Source row of the point nearest a widget pixel of the plot (within 8 px), or -1.
    int rowAt(const QPoint& plotPixel) const;
    /// The plot pixel of a shot's point (tests), or (-1, -1) when it is not drawn.
    QPoint pixelOf(int sourceRow) const;

signals:
    void shotClicked(int sourceRow);
    void columnsChanged();

private:
    struct Point {
        double x, y;
        int row;
    };
    void scheduleRefresh();
    void showCurrent();
    FootprintController* m_c;
    ShotFilterProxy* m_view;
    QComboBox *m_x, *m_y;
    QCustomPlot* m_plot;
    QLabel* m_info;
    QTimer* m_timer = nullptr;
    std::vector<Point> m_points;
    int m_current = -1;
    double m_xOffset = 0;  // seconds subtracted from a time shown as seconds of day
    QPoint m_press;
};

}  // namespace lwb::ui
