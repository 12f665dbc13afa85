#pragma once
// The layout the SLR, calibration and radiometry workspaces share: a centre column (a row of
// inputs, an information line, the body) and the parameter panel on the right in a scroll area,
// side by side in a splitter.
//
// Small windows (1024×700, or 150 % scaling on 1920×1080): the row of inputs wraps onto more
// lines instead of widening the window (FlowLayout); the parameter panel scrolls vertically, is
// as wide as its widest row (never cut off, never scrolled sideways), and can be collapsed by
// dragging the splitter or with View ▸ Parameter panels (the scroll area is named
// "parameterPanel").
#include <QLayout>
#include <QList>
#include <QMargins>
#include <QRect>

class QScrollArea;
class QWidget;

namespace lwb::ui {

void layoutWorkspace(QWidget* workspace, QLayout* top, QWidget* info, QWidget* body, QWidget* panel,
                     int panelMinWidth, int centreWidth);

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
