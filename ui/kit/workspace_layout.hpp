#pragma once
// The layout the SLR, calibration and radiometry workspaces share: a centre column (a row of
// inputs, an information line, the body) and the parameter panel on the right in a scroll area,
// in a dock beside it (dockPanels).
//
// Dockable panels (every workspace): each workspace is an inner main window ("dockHost") whose
// centre is its views and whose panels (parameters; the footprint's shot list) are docks — moved
// to another side, floated as their own window, closed and brought back from View ▸ Panels. The
// arrangement is saved per workspace when the program closes and restored when it starts
// (saveDockLayouts / restoreDockLayouts); View ▸ Reset panel layout puts every panel back.
//
// Small windows (1024×700, or 150 % scaling on 1920×1080): the row of inputs wraps onto more
// lines instead of widening the window (FlowLayout); the parameter panel scrolls vertically, is
// as wide as its widest row (never cut off, never scrolled sideways), and can be collapsed by
// closing its dock or with View ▸ Parameter panels (the scroll area is named "parameterPanel").
#include <QLayout>
#include <QList>
#include <QString>
#include <vector>
#include <QMargins>
#include <QRect>

class QDockWidget;
class QMainWindow;
class QScrollArea;
class QWidget;

namespace lwb::ui {

/// `name`: the workspace's key for its saved panel layout ("slr", "calibration", …).
void layoutWorkspace(QWidget* workspace, const QString& name, QLayout* top, QWidget* info, QWidget* body,
                     QWidget* panel, int panelMinWidth, int centreWidth);

/// A panel of a workspace, docked at `area` (Qt::LeftDockWidgetArea or Qt::RightDockWidgetArea)
/// `width` px wide at first; `id` names the dock in the saved layout ("parameters", "shots").
struct DockPanel {
    QWidget* widget = nullptr;
    QString id, title;
    int area = 0x2;  ///< Qt::RightDockWidgetArea
    int width = 340;
};
/// Fills `workspace` with an inner main window: `centre` in the middle, each panel in a dock.
/// The dock of panel `id` is named "<name>.<id>".
QMainWindow* dockPanels(QWidget* workspace, const QString& name, QWidget* centre, const std::vector<DockPanel>& panels);
/// Every workspace's dock arrangement under `root`, to the settings (layout/<name>) and back;
/// resetDockLayouts puts every panel back where dockPanels first put it.
void saveDockLayouts(QWidget* root);
void restoreDockLayouts(QWidget* root);
void resetDockLayouts(QWidget* root);
/// The docks under `root` (in workspace order).
QList<QDockWidget*> workspaceDocks(QWidget* root);

/// `text` (a label of messages) in a scroll area as tall as the text up to `lines` lines, then
/// scrolling (layoutWorkspace puts the information line in one).
QWidget* boundedText(QWidget* text, int lines);

/// A row of controls (a QHBoxLayout not yet installed) as a FlowLayout that wraps: the same
/// widgets in the same order; spacers and stretches are dropped. `row` is deleted.
QLayout* wrapRow(QLayout* row);
/// Keeps a parameter panel's scroll area as wide as the panel's widest row plus the scroll bar
/// (nothing cut off, no sideways scrolling), following the panel as it changes.
void fitPanelWidth(QScrollArea* scroll);

/// Where a top-level window goes on a screen: `wanted` (a saved geometry, or the default size
/// at the origin) shrunk to the screen's available area `available` (never below `minimum`,
/// the window's own least size) and moved into it, so that the title bar, the parameter panel
/// and the status bar are on the screen. A frame of `frame` pixels (title bar, borders) is kept
/// for the window manager's decoration.
QRect fitWindowToScreen(const QRect& wanted, const QSize& minimum, const QRect& available, const QMargins& frame);

/// Gives a top-level window (a dialog, the blink window) the size `wanted`, fitted to the
/// available area of its screen (its parent's, else the primary) with a title bar's room, and
/// centred over its parent where that fits (issue 42: the blink window opened 700 px tall at
/// y = 40 on a 700 px screen, its controls under the task bar).
void placeOnScreen(QWidget* window, const QSize& wanted);

/// Lays its widgets out left to right and wraps onto the next line when the width runs out.
class FlowLayout : public QLayout {
public:
    explicit FlowLayout(QWidget* parent = nullptr, int spacing = 6);
    ~FlowLayout() override;
    void addItem(QLayoutItem* item) override;
    int count() const override { return int(m_items.size()); }
    QLayoutItem* itemAt(int i) const override { return m_items.value(i); }
    QLayoutItem* takeAt(int i) override;
    Qt::Orientations expandingDirections() const override { return {}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override { return place(QRect(0, 0, width, 0), false); }
    void setGeometry(const QRect& rect) override;
    QSize sizeHint() const override;
    QSize minimumSize() const override;

private:
    int place(const QRect& rect, bool apply) const;
    QList<QLayoutItem*> m_items;
};

}  // namespace lwb::ui
