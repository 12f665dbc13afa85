#include "ui/kit/workspace_layout.hpp"

#include <QGuiApplication>
#include <QScreen>

#include <algorithm>
#include <QFrame>

#include <QDockWidget>
#include <QEvent>
#include <QHBoxLayout>
#include <QMainWindow>
#include <QSettings>
#include <QScrollArea>
#include <QScrollBar>
#include <QSplitter>
#include <QStyle>
#include <QVBoxLayout>
#include <QWidget>
#include <functional>

namespace lwb::ui {

namespace {

// Keeps a scroll area as wide as its panel needs (plus the vertical scroll bar), following the
// panel's layout as it changes, so that nothing in the panel is cut off and it never scrolls
// sideways.
class PanelWidth : public QObject {
public:
    explicit PanelWidth(QScrollArea* scroll) : QObject(scroll), m_scroll(scroll) {
        scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        if (scroll->widget()) scroll->widget()->installEventFilter(this);
        update();
    }
    void update() {
        const QWidget* w = m_scroll->widget();
        if (!w) return;
        const int bar = m_scroll->style()->pixelMetric(QStyle::PM_ScrollBarExtent, nullptr, m_scroll);
        m_scroll->setMinimumWidth(w->minimumSizeHint().width() + bar + 2 * m_scroll->frameWidth() + 2);
    }

protected:
    bool eventFilter(QObject*, QEvent* e) override {
        if (e->type() == QEvent::LayoutRequest || e->type() == QEvent::Show) update();
        return false;
    }

private:
    QScrollArea* m_scroll;
};

}  // namespace

namespace {

// A scroll area as tall as its text up to `lines` lines, then scrolling: a message above the
// plots (a pass's warnings: seven lines on a BLITS pass with a CPF and a SINEX) must not squeeze
// them (the O-C plot was left 25 px tall in a 1024 × 700 window).
class BoundedText : public QScrollArea {
public:
    BoundedText(QWidget* text, int lines, QWidget* parent) : QScrollArea(parent), m_lines(lines) {
        setWidget(text);
        setWidgetResizable(true);
        setFrameShape(QFrame::NoFrame);
        setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
        viewport()->installEventFilter(this);
        setObjectName("boundedText");
    }
    QSize sizeHint() const override {
        const QWidget* w = widget();
        const int width = viewport()->width() > 50 ? viewport()->width() : w->sizeHint().width();
        const int h = w->hasHeightForWidth() ? w->heightForWidth(width) : w->sizeHint().height();
        return {QScrollArea::sizeHint().width(), std::min(h, maxHeight())};
    }
    QSize minimumSizeHint() const override { return {0, std::min(sizeHint().height(), fontMetrics().lineSpacing() + 4)}; }

protected:
    bool eventFilter(QObject* o, QEvent* e) override {
        // The text changed (its label asks its parent, the viewport, for a new layout) or the
        // width did: a new height.
        if (o == viewport() && (e->type() == QEvent::LayoutRequest || e->type() == QEvent::Resize)) updateGeometry();
        return QScrollArea::eventFilter(o, e);
    }

private:
    // (half a line more: the lines of rich text are a little taller than the font's spacing,
    // and a cut line shows there is more to scroll to)
    int maxHeight() const { return (2 * m_lines + 1) * fontMetrics().lineSpacing() / 2 + 6; }
    int m_lines;
};

}  // namespace

QWidget* boundedText(QWidget* text, int lines) { return new BoundedText(text, lines, text->parentWidget()); }

void layoutWorkspace(QWidget* workspace, const QString& name, QLayout* top, QWidget* info, QWidget* body,
                     QWidget* panel, int panelMinWidth, int centreWidth) {
    auto* scroll = new QScrollArea(workspace);
    scroll->setObjectName("parameterPanel");
    scroll->setWidget(panel);
    scroll->setWidgetResizable(true);
    fitPanelWidth(scroll);
    auto* centre = new QWidget(workspace);
    auto* cl = new QVBoxLayout(centre);
    cl->setContentsMargins(0, 0, 0, 0);
    cl->addLayout(wrapRow(top));
    cl->addWidget(boundedText(info, 3));
    cl->addWidget(body, 1);
    (void)centreWidth;  // (the centre takes what the docks leave)
    DockPanel p;
    p.widget = scroll;
    p.id = "parameters";
    p.title = QObject::tr("Parameters");
    p.area = Qt::RightDockWidgetArea;
    p.width = std::max(panelMinWidth, scroll->minimumSizeHint().width()) + 10;
    dockPanels(workspace, name, centre, {p});
}

namespace {

// The first time the host is shown: the docks at their first widths (resizeDocks needs the
// host laid out), unless a saved layout was restored.
class DockFirstShow : public QObject {
public:
    explicit DockFirstShow(QMainWindow* host) : QObject(host), m_host(host) { host->installEventFilter(this); }

protected:
    bool eventFilter(QObject* o, QEvent* e) override {
        if (o == m_host && e->type() == QEvent::Show && !m_done) {
            m_done = true;
            if (!m_host->property("lwbRestored").toBool()) applyWidths(m_host);
        }
        return false;
    }

public:
    static void applyWidths(QMainWindow* host) {
        QList<QDockWidget*> docks;
        QList<int> widths;
        for (QDockWidget* d : host->findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly)) {
            docks << d;
            widths << d->property("lwbWidth").toInt();
        }
        if (!docks.isEmpty()) host->resizeDocks(docks, widths, Qt::Horizontal);
    }

private:
    QMainWindow* m_host;
    bool m_done = false;
};

QList<QMainWindow*> dockHosts(QWidget* root) {
    QList<QMainWindow*> out;
    for (QMainWindow* h : root->findChildren<QMainWindow*>("dockHost"))
        if (!h->property("lwbWorkspace").toString().isEmpty()) out << h;
    return out;
}

constexpr int kDockLayoutVersion = 1;

}  // namespace

QMainWindow* dockPanels(QWidget* workspace, const QString& name, QWidget* centre, const std::vector<DockPanel>& panels) {
    auto* host = new QMainWindow(workspace);
    host->setWindowFlags(Qt::Widget);  // (QMainWindow makes itself a window whatever the flags given)
    host->setObjectName("dockHost");
    host->setProperty("lwbWorkspace", name);
    host->setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    centre->setParent(host);
    host->setCentralWidget(centre);
    for (const DockPanel& p : panels) {
        auto* dock = new QDockWidget(p.title, host);
        dock->setObjectName(name + "." + p.id);
        dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable | QDockWidget::DockWidgetClosable);
        dock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
        dock->setWidget(p.widget);
        dock->setProperty("lwbArea", p.area);
        dock->setProperty("lwbWidth", p.width);
        host->addDockWidget(Qt::DockWidgetArea(p.area), dock);
    }
    new DockFirstShow(host);
    auto* lay = new QHBoxLayout(workspace);
    lay->setContentsMargins(4, 4, 4, 4);
    lay->addWidget(host);
    return host;
}

void saveDockLayouts(QWidget* root) {
    QSettings st;
    for (QMainWindow* h : dockHosts(root))
        st.setValue("layout/" + h->property("lwbWorkspace").toString(), h->saveState(kDockLayoutVersion));
}

void restoreDockLayouts(QWidget* root) {
    QSettings st;
    for (QMainWindow* h : dockHosts(root)) {
        const QByteArray state = st.value("layout/" + h->property("lwbWorkspace").toString()).toByteArray();
        if (!state.isEmpty() && h->restoreState(state, kDockLayoutVersion)) h->setProperty("lwbRestored", true);
    }
}

void resetDockLayouts(QWidget* root) {
    for (QMainWindow* h : dockHosts(root)) {
        for (QDockWidget* d : h->findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly)) {
            d->setFloating(false);
            h->addDockWidget(Qt::DockWidgetArea(d->property("lwbArea").toInt()), d);
            d->show();
        }
        DockFirstShow::applyWidths(h);
    }
}

QList<QDockWidget*> workspaceDocks(QWidget* root) {
    QList<QDockWidget*> out;
    for (QMainWindow* h : dockHosts(root)) out += h->findChildren<QDockWidget*>(QString(), Qt::FindDirectChildrenOnly);
    return out;
}

void fitPanelWidth(QScrollArea* scroll) { new PanelWidth(scroll); }

QLayout* wrapRow(QLayout* row) {
    auto* flow = new FlowLayout(nullptr, row->spacing() >= 0 ? row->spacing() : 6);
    std::function<void(QLayout*)> move = [&](QLayout* from) {
        while (QLayoutItem* it = from->takeAt(0)) {
            if (QWidget* w = it->widget()) flow->addWidget(w);
            else if (QLayout* inner = it->layout()) move(inner);
            delete it;  // a nested layout once emptied; spacers and stretches mean nothing in a flow
        }
    };
    move(row);
    delete row;
    return flow;
}

// ---------------------------------------------------------------------------------------------

FlowLayout::FlowLayout(QWidget* parent, int spacing) : QLayout(parent) {
    setSpacing(spacing);
    setContentsMargins(0, 0, 0, 0);
}

FlowLayout::~FlowLayout() {
    while (QLayoutItem* it = takeAt(0)) delete it;
}

void FlowLayout::addItem(QLayoutItem* item) { m_items.append(item); }

QLayoutItem* FlowLayout::takeAt(int i) { return i >= 0 && i < m_items.size() ? m_items.takeAt(i) : nullptr; }

void FlowLayout::setGeometry(const QRect& rect) {
    QLayout::setGeometry(rect);
    place(rect, true);
}

QSize FlowLayout::sizeHint() const {
    // One line when there is room for it.
    int w = 0, h = 0;
    for (QLayoutItem* it : m_items) {
        if (it->isEmpty()) continue;
        const QSize s = it->sizeHint();
        w += s.width() + (w > 0 ? spacing() : 0);
        h = std::max(h, s.height());
    }
    const QMargins m = contentsMargins();
    return QSize(w + m.left() + m.right(), h + m.top() + m.bottom());
}

QSize FlowLayout::minimumSize() const {
    QSize s;
    for (QLayoutItem* it : m_items)
        if (!it->isEmpty()) s = s.expandedTo(it->minimumSize());
    const QMargins m = contentsMargins();
    return s + QSize(m.left() + m.right(), m.top() + m.bottom());
}

int FlowLayout::place(const QRect& rect, bool apply) const {
    const QMargins m = contentsMargins();
    const QRect r = rect.adjusted(m.left(), m.top(), -m.right(), -m.bottom());
    int x = r.x(), y = r.y(), line = 0;
    for (QLayoutItem* it : m_items) {
        if (it->isEmpty()) continue;
        const QSize s = it->sizeHint();
        if (x > r.x() && x + s.width() > r.right() + 1) {  // wrap
            x = r.x();
            y += line + spacing();
            line = 0;
        }
        if (apply) it->setGeometry(QRect(QPoint(x, y), s));
        x += s.width() + spacing();
        line = std::max(line, s.height());
    }
    return y + line - rect.y() + m.bottom();
}

QRect fitWindowToScreen(const QRect& wanted, const QSize& minimum, const QRect& available, const QMargins& frame) {
    const QRect inside = available.marginsRemoved(frame);
    const QSize size = wanted.size().boundedTo(inside.size()).expandedTo(minimum);
    // Keep the top-left corner when the window fits where it was, else slide it in (a window
    // larger than the screen even at its least size starts at the top left, its title bar shown).
    QPoint at = wanted.topLeft();
    at.setX(std::max(inside.left(), std::min(at.x(), inside.right() + 1 - size.width())));
    at.setY(std::max(inside.top(), std::min(at.y(), inside.bottom() + 1 - size.height())));
    return QRect(at, size);
}

void placeOnScreen(QWidget* window, const QSize& wanted) {
    QWidget* parent = window->parentWidget() ? window->parentWidget()->window() : nullptr;
    const QScreen* sc = parent && parent->screen() ? parent->screen() : QGuiApplication::primaryScreen();
    if (!sc) {
        window->resize(wanted);
        return;
    }
    QRect want(QPoint(0, 0), wanted);
    if (parent) want.moveCenter(parent->frameGeometry().center());
    else want.moveCenter(sc->availableGeometry().center());
    // The window manager's frame as the parent has it (borders too: 2 px a side left a dialog
    // 4 px beyond an 800 px screen, issue 42), at least a title bar of 30 px.
    QMargins frame(0, 30, 0, 0);
    if (parent) {
        const QRect f = parent->frameGeometry(), g = parent->geometry();
        frame = QMargins(std::max(0, g.left() - f.left()), std::max(30, g.top() - f.top()), std::max(0, f.right() - g.right()),
                         std::max(0, f.bottom() - g.bottom()));
    }
    window->setGeometry(fitWindowToScreen(want, window->minimumSizeHint(), sc->availableGeometry(), frame));
}

}  // namespace lwb::ui
