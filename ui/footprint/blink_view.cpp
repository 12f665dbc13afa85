#include "ui/footprint/blink_view.hpp"

#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QShortcut>
#include <QSpinBox>
#include <QEvent>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include "ui/kit/contrast_bias.hpp"
#include "ui/kit/workspace_layout.hpp"

namespace lwb::ui {

BlinkView::BlinkView(std::vector<BlinkFrame> frames, ColorMap map, const DisplaySettings& display, QWidget* parent)
    : QWidget(parent, Qt::Window), m_frames(std::move(frames)), m_map(map) {
    setWindowTitle(tr("Blink / tile: %n shots", nullptr, int(m_frames.size())));
    setAttribute(Qt::WA_DeleteOnClose);
    auto* lay = new QVBoxLayout(this);
    lay->addWidget(buildControls());
    m_display = new DisplayControls(this);
    m_display->setSettings(display);
    lay->addWidget(m_display);
    auto* gridHost = new QWidget(this);
    m_grid = new QGridLayout(gridHost);
    m_grid->setContentsMargins(0, 0, 0, 0);
    m_grid->setSpacing(4);
    const int n = int(m_frames.size());
    const int cols = std::max(1, int(std::ceil(std::sqrt(double(n)))));
    for (int i = 0; i < n; ++i) {
        auto* cell = new QWidget(gridHost);
        auto* cellLay = new QVBoxLayout(cell);
        cellLay->setContentsMargins(0, 0, 0, 0);
        cellLay->setSpacing(1);
        auto* view = new ImageView(cell);
        view->setMinimumSize(120, 120);
        auto* caption = new QLabel(m_frames[size_t(i)].name, cell);
        caption->setAlignment(Qt::AlignCenter);
        cellLay->addWidget(view, 1);
        cellLay->addWidget(caption);
        m_grid->addWidget(cell, i / cols, i % cols);
        m_cells << cell;
        m_tiles << view;
        m_tileLimits << core::DisplayLimits{};
        const BlinkFrame& f = m_frames[size_t(i)];
        if (f.hasCentre)
            view->setOverlay([c = f.centre](QPainter& p, double scale) {
                p.setPen(QPen(QColor(0, 220, 255), 1.6 / scale));
                const double s = 0.6;
                p.drawLine(c + QPointF(-s, -s), c + QPointF(s, s));
                p.drawLine(c + QPointF(-s, s), c + QPointF(s, -s));
            });
        connect(view, &ImageView::viewChanged, this, [this, i] { syncViews(i); });
        view->installEventFilter(this);
    }
    lay->addWidget(gridHost, 1);
    m_bar = new ColorBar(this);
    m_bar->setFixedHeight(40);
    lay->addWidget(m_bar);
    wireContrastBias(m_display, m_tiles, m_bar);
    connect(m_display, &DisplayControls::changed, this, &BlinkView::render);
    m_timer = new QTimer(this);
    connect(m_timer, &QTimer::timeout, this, [this] { step(1); });
    auto key = [this](const QKeySequence& k, auto fn) {
        auto* sc = new QShortcut(k, this, nullptr, nullptr, Qt::WidgetWithChildrenShortcut);
        connect(sc, &QShortcut::activated, this, fn);
    };
    key(QKeySequence(Qt::Key_Space), [this] { setPlaying(!playing()); });
    key(QKeySequence(Qt::Key_Right), [this] { step(1); });
    key(QKeySequence(Qt::Key_Left), [this] { step(-1); });
    key(QKeySequence(Qt::Key_T), [this] { setMode(Mode::Tile); });
    key(QKeySequence(Qt::Key_B), [this] { setMode(Mode::Blink); });
    render();
    applyMode();
    placeOnScreen(this, QSize(900, 700));
}

QWidget* BlinkView::buildControls() {
    auto* row = new QWidget(this);
    auto* lay = new QHBoxLayout;
    m_modeBox = new QComboBox(row);
    m_modeBox->addItems({tr("Tile"), tr("Blink")});
    m_modeBox->setToolTip(tr("Tile: every shot in a grid (T) · Blink: one at a time, cycled at the interval (B)"));
    m_interval = new QSpinBox(row);
    m_interval->setRange(50, 10000);
    m_interval->setSingleStep(100);
    m_interval->setValue(500);
    m_interval->setSuffix(tr(" ms"));
    m_interval->setToolTip(tr("Time each shot is shown when blinking"));
    m_play = new QPushButton(tr("Pause"), row);
    m_play->setToolTip(tr("Start or stop the blinking (Space); ← / → step by hand"));
    m_frameLabel = new QLabel(row);
    lay->addWidget(new QLabel(tr("Show:"), row));
    lay->addWidget(m_modeBox);
    lay->addWidget(new QLabel(tr("Every"), row));
    lay->addWidget(m_interval);
    lay->addWidget(m_play);
    lay->addWidget(m_frameLabel, 1);
    row->setLayout(wrapRow(lay));
    connect(m_modeBox, &QComboBox::currentIndexChanged, this, [this](int i) { setMode(Mode(i)); });
    connect(m_interval, &QSpinBox::valueChanged, this, [this](int ms) { m_timer->setInterval(ms); });
    connect(m_play, &QPushButton::clicked, this, [this] { setPlaying(!playing()); });
    return row;
}

void BlinkView::setMode(Mode m) {
    m_mode = m;
    if (m_modeBox->currentIndex() != int(m)) {
        const QSignalBlocker b(m_modeBox);
        m_modeBox->setCurrentIndex(int(m));
    }
    applyMode();
}

void BlinkView::applyMode() {
    if (m_frames.empty()) return;
    const bool blink = m_mode == Mode::Blink;
    for (int i = 0; i < m_cells.size(); ++i) m_cells[i]->setVisible(!blink || i == m_current);
    m_interval->setEnabled(blink);
    m_play->setEnabled(blink);
    setPlaying(blink);
    // The tiles changed size: each takes the locked zoom and centre again, relative to its fit.
    QTimer::singleShot(0, this, [this] {
        m_syncing = true;
        for (ImageView* v : m_tiles) v->setViewState(m_state);
        m_syncing = false;
    });
    m_frameLabel->setText(tr("%1 / %2: %3").arg(m_current + 1).arg(frameCount()).arg(m_frames[size_t(m_current)].name));
}

void BlinkView::setCurrentFrame(int i) {
    if (i < 0 || i >= frameCount()) return;
    m_current = i;
    if (m_mode == Mode::Blink)
        for (int k = 0; k < m_cells.size(); ++k) m_cells[k]->setVisible(k == i);
    m_frameLabel->setText(tr("%1 / %2: %3").arg(i + 1).arg(frameCount()).arg(m_frames[size_t(i)].name));
    if (m_display->settings().limits != LimitsMode::Manual) render();  // the front shot's limits for all
}

void BlinkView::step(int delta) {
    const int n = frameCount();
    if (n > 0) setCurrentFrame(((m_current + delta) % n + n) % n);
}

void BlinkView::setInterval(int ms) { m_interval->setValue(ms); }
int BlinkView::interval() const { return m_interval->value(); }

void BlinkView::setPlaying(bool on) {
    on = on && m_mode == Mode::Blink && frameCount() > 1;
    if (on) m_timer->start(m_interval->value());
    else m_timer->stop();
    m_play->setText(on ? tr("Pause") : tr("Play"));
}

bool BlinkView::playing() const { return m_timer->isActive(); }

// One set of limits for every tile: the front shot's under the automatic modes, the fields' in Manual.
void BlinkView::render() {
    if (m_frames.empty()) return;
    const DisplaySettings ds = m_display->settings();
    m_limits = displayLimits(m_frames[size_t(m_current)].data, ds);
    m_display->showLimits(m_limits.lo, m_limits.hi);
    for (int i = 0; i < m_tiles.size(); ++i) {
        const BlinkFrame& f = m_frames[size_t(i)];
        m_tiles[i]->setImage(f.data, renderStretched(f.data, m_map, ds.stretch, m_limits.lo, m_limits.hi), f.origin);
        m_tileLimits[i] = m_limits;
    }
    m_bar->setScale(m_map, ds.stretch, m_limits.lo, m_limits.hi);
}

// A tile shown alone (Blink) or back in the grid changes size: it takes the locked state again,
// relative to its new fit (a hidden widget's resize comes at show time, with no usable old size).
bool BlinkView::eventFilter(QObject* o, QEvent* e) {
    if (e->type() == QEvent::Resize || e->type() == QEvent::Show) {
        auto* v = qobject_cast<ImageView*>(o);
        if (v && m_tiles.contains(v))
            QTimer::singleShot(0, v, [this, v] {
                const bool was = m_syncing;
                m_syncing = true;
                v->setViewState(m_state);
                m_syncing = was;
            });
    }
    return QWidget::eventFilter(o, e);
}

void BlinkView::syncViews(int from) {
    if (m_syncing) return;
    m_syncing = true;
    m_state = m_tiles[from]->viewState();
    for (int i = 0; i < m_tiles.size(); ++i)
        if (i != from) m_tiles[i]->setViewState(m_state);
    m_syncing = false;
}

}  // namespace lwb::ui
