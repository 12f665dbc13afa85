#include "ui/kit/display_controls.hpp"

#include "ui/kit/workspace_layout.hpp"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <algorithm>
#include <cmath>

namespace lwb::ui {

using core::StretchKind;

namespace {
const float* values(const cv::Mat& img) { return img.isContinuous() ? img.ptr<float>() : nullptr; }

// "Nice" tick step (1, 2 or 5 × 10^k) for about `count` ticks over span.
double niceStep(double span, int count) {
    const double raw = span / std::max(1, count);
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * p >= raw) return m * p;
    return 10 * p;
}
}  // namespace

core::DisplayLimits displayLimits(const cv::Mat& img, const DisplaySettings& s) {
    core::DisplayLimits l;
    cv::Mat c = img.isContinuous() ? img : img.clone();
    const size_t n = c.total();
    switch (s.limits) {
        case LimitsMode::MinMax: l = core::minMaxLimits(values(c), n); break;
        case LimitsMode::Percentile: l = core::percentileLimits(values(c), n, 0.5, 99.5); break;
        case LimitsMode::ZScale: {
            const core::ZScaleResult z = core::zscale(values(c), n);
            l.ok = z.ok;
            l.lo = z.z1;
            l.hi = z.z2;
            break;
        }
        case LimitsMode::Manual:
            l.ok = true;
            l.lo = s.manualLo;
            l.hi = s.manualHi;
            break;
    }
    if (!l.ok) l = {true, 0, 1};
    if (!(l.hi > l.lo)) l.hi = l.lo + 1;
    return l;
}

QImage renderStretched(const cv::Mat& img, ColorMap map, StretchKind k, double lo, double hi) {
    QImage out(img.cols, img.rows, QImage::Format_ARGB32);
    if (img.empty()) return out;
    QRgb lut[1024];
    for (int i = 0; i < 1024; ++i) lut[i] = mapColor(map, core::applyStretch(k, i / 1023.0));
    const double scale = hi > lo ? 1.0 / (hi - lo) : 1.0;
    for (int y = 0; y < img.rows; ++y) {
        const float* src = img.ptr<float>(y);
        auto* dst = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < img.cols; ++x) {
            const double t = std::isfinite(src[x]) ? std::clamp((src[x] - lo) * scale, 0.0, 1.0) : 0.0;
            dst[x] = lut[static_cast<int>(t * 1023 + 0.5)];
        }
    }
    return out;
}

core::DisplayLimits contrastBiasLimits(double lo, double hi, double dxFraction, double dyFraction) {
    const double bias = 0.5 + dxFraction;
    const double contrast = std::pow(10.0, std::clamp(dyFraction, -4.0, 4.0));
    const double centre = lo + bias * (hi - lo), half = (hi - lo) / contrast / 2;
    return {true, centre - half, centre + half};
}

DisplayControls::DisplayControls(QWidget* parent) : QWidget(parent) {
    auto* lay = new QHBoxLayout;  // becomes a wrapping row below (the window stays usable at 1024 px)
    m_limits = new QComboBox(this);
    m_limits->addItems({tr("Min–max"), tr("ZScale"), tr("99.5 %"), tr("Manual")});
    m_limits->setToolTip(tr("Display limits: the ROI's min and max, IRAF zscale (as DS9), the 0.5–99.5 "
                            "percentiles, or the low and high values typed here"));
    m_stretch = new QComboBox(this);
    for (StretchKind k : {StretchKind::Linear, StretchKind::Sqrt, StretchKind::Log, StretchKind::Asinh})
        m_stretch->addItem(QString::fromLatin1(core::stretchKindName(k)));
    m_stretch->setToolTip(tr("Stretch between the limits: linear, sqrt, log (a = 1000) or asinh (as DS9)"));
    m_lo = new QDoubleSpinBox(this);
    m_hi = new QDoubleSpinBox(this);
    for (QDoubleSpinBox* b : {m_lo, m_hi}) {
        b->setRange(-1e9, 1e9);
        b->setDecimals(0);
        b->setSuffix(tr(" DN"));
        b->setKeyboardTracking(false);
    }
    m_lo->setToolTip(tr("Low display limit (DN); editable in manual mode"));
    m_hi->setToolTip(tr("High display limit (DN); editable in manual mode"));
    lay->addWidget(m_limits);
    lay->addWidget(m_stretch);
    lay->addWidget(m_lo);
    lay->addWidget(new QLabel(QStringLiteral("–"), this));
    lay->addWidget(m_hi);
    setLayout(wrapRow(lay));
    m_limits->setCurrentIndex(int(DisplaySettings{}.limits));
    auto sync = [this] {
        const bool manual = m_limits->currentIndex() == int(LimitsMode::Manual);
        m_lo->setReadOnly(!manual);
        m_hi->setReadOnly(!manual);
    };
    sync();
    connect(m_limits, &QComboBox::currentIndexChanged, this, [this, sync] {
        sync();
        if (m_limits->currentIndex() == int(LimitsMode::Manual)) keepManual();  // (the limits shown become the analyst's)
        m_cbBaseSet = false;  // limits chosen by hand: a reset has nothing to go back to
        emit changed();
    });
    connect(m_stretch, &QComboBox::currentIndexChanged, this, &DisplayControls::changed);
    for (QDoubleSpinBox* b : {m_lo, m_hi})
        connect(b, &QDoubleSpinBox::valueChanged, this, [this] {
            if (m_limits->currentIndex() != int(LimitsMode::Manual)) return;
            keepManual();
            m_cbBaseSet = false;
            emit changed();
        });
}

double DisplayControls::low() const { return m_lo->value(); }
double DisplayControls::high() const { return m_hi->value(); }

void DisplayControls::beginContrastBias() {
    if (!m_cbBaseSet) {
        m_cbBase = settings();
        m_cbBaseSet = true;
    }
    m_cbLo = m_lo->value();
    m_cbHi = m_hi->value();
}

void DisplayControls::dragContrastBias(double dxFraction, double dyFraction) {
    const core::DisplayLimits l = contrastBiasLimits(m_cbLo, m_cbHi, dxFraction, dyFraction);
    const QSignalBlocker b1(m_limits), b2(m_lo), b3(m_hi);
    m_limits->setCurrentIndex(int(LimitsMode::Manual));
    m_lo->setReadOnly(false);
    m_hi->setReadOnly(false);
    m_lo->setValue(l.lo);
    m_hi->setValue(std::max(l.hi, m_lo->value() + 1));  // the fields keep whole DN: never an empty window
    keepManual();
    emit changed();
}

void DisplayControls::resetContrastBias() {
    if (!m_cbBaseSet) return;
    const DisplaySettings base = m_cbBase;
    m_cbBaseSet = false;
    setSettings(base);
}

DisplaySettings DisplayControls::settings() const {
    DisplaySettings s;
    s.limits = LimitsMode(m_limits->currentIndex());
    s.stretch = StretchKind(m_stretch->currentIndex());
    const bool manual = s.limits == LimitsMode::Manual;
    s.manualLo = manual ? m_lo->value() : m_manualLo;
    s.manualHi = manual ? m_hi->value() : m_manualHi;
    return s;
}

void DisplayControls::keepManual() {
    m_manualLo = m_lo->value();
    m_manualHi = m_hi->value();
}

void DisplayControls::setSettings(const DisplaySettings& s) {
    const QSignalBlocker b1(m_limits), b2(m_stretch), b3(m_lo), b4(m_hi);
    m_lo->setValue(s.manualLo);
    m_hi->setValue(s.manualHi);
    keepManual();
    m_stretch->setCurrentIndex(int(s.stretch));
    m_limits->setCurrentIndex(int(s.limits));
    m_lo->setReadOnly(s.limits != LimitsMode::Manual);
    m_hi->setReadOnly(s.limits != LimitsMode::Manual);
    emit changed();
}

void DisplayControls::showLimits(double lo, double hi) {
    if (m_limits->currentIndex() == int(LimitsMode::Manual)) return;
    const QSignalBlocker b1(m_lo), b2(m_hi);
    m_lo->setValue(lo);
    m_hi->setValue(hi);
}

HistogramView::HistogramView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(140, 56);
    setToolTip(tr("Histogram of the ROI (log counts) with the display limits"));
}

void HistogramView::setData(const cv::Mat& img, double lo, double hi) {
    cv::Mat c = img.isContinuous() ? img : img.clone();
    const core::DisplayLimits r = core::minMaxLimits(values(c), c.total());
    m_min = r.ok ? std::min(r.lo, lo) : lo;
    m_max = r.ok ? std::max(r.hi, hi) : hi;
    if (!(m_max > m_min)) m_max = m_min + 1;
    m_bins = core::histogram(values(c), c.total(), m_min, m_max, 64);
    m_lo = lo;
    m_hi = hi;
    update();
}

void HistogramView::clear() {
    m_bins.clear();
    update();
}

double HistogramView::xOf(double dn) const {
    const double left = 4, right = width() - 4;
    return left + (dn - m_min) / (m_max - m_min) * (right - left);
}

void HistogramView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().color(QPalette::Base));
    if (m_bins.empty()) return;
    const int textH = p.fontMetrics().height();
    const double top = 4, bottom = height() - textH - 2;
    size_t peak = 1;
    for (size_t b : m_bins) peak = std::max(peak, b);
    const double lpeak = std::log10(1.0 + double(peak));
    const double bw = (width() - 8) / double(m_bins.size());
    p.setPen(Qt::NoPen);
    p.setBrush(palette().color(QPalette::Text).lighter(140));
    for (size_t i = 0; i < m_bins.size(); ++i) {
        if (!m_bins[i]) continue;
        const double h = std::log10(1.0 + double(m_bins[i])) / lpeak * (bottom - top);
        p.drawRect(QRectF(4 + i * bw, bottom - h, std::max(1.0, bw - 0.5), h));
    }
    const QColor loC(0, 160, 255), hiC(230, 60, 40);
    p.setPen(QPen(loC, 2));
    p.drawLine(QPointF(xOf(m_lo), top), QPointF(xOf(m_lo), bottom));
    p.setPen(QPen(hiC, 2));
    p.drawLine(QPointF(xOf(m_hi), top), QPointF(xOf(m_hi), bottom));
    p.setPen(palette().color(QPalette::Text));
    p.drawText(QRectF(4, bottom + 1, width() - 8, textH), Qt::AlignLeft, QString::number(m_min, 'f', 0));
    p.drawText(QRectF(4, bottom + 1, width() - 8, textH), Qt::AlignRight, tr("%1 DN").arg(m_max, 0, 'f', 0));
}

ColorBar::ColorBar(QWidget* parent) : QWidget(parent) {
    setMinimumSize(140, 38);
    setToolTip(tr("Colour scale between the display limits (DN). Drag: bias (left/right) and contrast (up/down), "
                  "as DS9; double-click: reset"));
    setCursor(Qt::SizeAllCursor);
}

void ColorBar::setScale(ColorMap map, StretchKind k, double lo, double hi) {
    m_map = map;
    m_stretch = k;
    m_lo = lo;
    m_hi = hi > lo ? hi : lo + 1;
    m_valid = true;
    update();
}

void ColorBar::clear() {
    m_valid = false;
    update();
}

std::vector<double> ColorBar::ticks() const {
    std::vector<double> t;
    if (!m_valid) return t;
    const double step = niceStep(m_hi - m_lo, 4);
    for (double v = std::ceil(m_lo / step) * step; v <= m_hi + 1e-9 * step; v += step) t.push_back(v);
    return t;
}

// The unit sits beside the bar's right end, level with it: drawn inside the bar (on a dark
// box) it hid the top of the scale and read as part of it (issue 30). The bar gives up the
// unit's width; the tick labels stay under the bar.
QRect ColorBar::barRect() const {
    const QFontMetrics fm = fontMetrics();
    const int unitW = fm.horizontalAdvance(tr("DN"));
    return QRect(4, 2, std::max(8, width() - 8 - unitW - 6), std::max(8, height() - fm.height() - 6));
}

QRect ColorBar::unitRect() const {
    const QRect bar = barRect();
    return QRect(bar.right() + 7, bar.top(), fontMetrics().horizontalAdvance(tr("DN")), bar.height());
}

void ColorBar::mousePressEvent(QMouseEvent* e) {
    if (!m_valid) return;
    m_dragging = true;
    m_dragStart = e->position();
    emit contrastBiasStarted();
}

void ColorBar::mouseMoveEvent(QMouseEvent* e) {
    if (!m_dragging) return;
    const QPointF d = e->position() - m_dragStart;
    emit contrastBiasDragged(d.x() / std::max(1, barRect().width()), d.y() / 150.0);
}

void ColorBar::mouseReleaseEvent(QMouseEvent*) { m_dragging = false; }

void ColorBar::mouseDoubleClickEvent(QMouseEvent*) {
    m_dragging = false;
    emit contrastBiasResetRequested();
}

void ColorBar::paintEvent(QPaintEvent*) {
    QPainter p(this);
    if (!m_valid) return;
    const int textH = p.fontMetrics().height();
    const QRect bar = barRect();
    const int left = bar.left(), right = bar.right() + 1, barH = bar.height() - 1;
    for (int x = left; x < right; ++x) {
        const double t = double(x - left) / std::max(1, right - left - 1);
        p.setPen(QColor::fromRgb(mapColor(m_map, core::applyStretch(m_stretch, t))));
        p.drawLine(x, bar.top(), x, bar.top() + barH);
    }
    p.setPen(palette().color(QPalette::Text));
    p.drawRect(left, bar.top(), right - left - 1, barH);
    const std::vector<double> ts = ticks();
    const double step = ts.size() > 1 ? ts[1] - ts[0] : 1;
    const int decimals = step >= 1 ? 0 : int(std::ceil(-std::log10(step)));
    for (double v : ts) {
        const double x = left + (v - m_lo) / (m_hi - m_lo) * (right - left - 1);
        p.drawLine(QPointF(x, 2 + barH), QPointF(x, 5 + barH));
        const QString label = QString::number(v, 'f', decimals);
        const double w = p.fontMetrics().horizontalAdvance(label);
        const double lx = std::clamp(x - w / 2, double(left), double(width() - 4) - w);
        p.drawText(QPointF(lx, 4 + barH + textH - p.fontMetrics().descent()), label);
    }
    p.drawText(unitRect(), Qt::AlignLeft | Qt::AlignVCenter, tr("DN"));
}

}  // namespace lwb::ui
