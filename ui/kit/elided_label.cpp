#include "ui/kit/elided_label.hpp"

#include <QPainter>
#include <QResizeEvent>
#include <QStyle>

namespace lwb::ui {

ElidedLabel::ElidedLabel(const QString& text, QWidget* parent, Qt::TextElideMode mode) : QLabel(text, parent), m_mode(mode) {
    setTextFormat(Qt::PlainText);
    setWordWrap(false);
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    updateTip();
}

void ElidedLabel::setFullText(const QString& text) {
    setText(text);
    updateTip();
}

void ElidedLabel::setPlainToolTip(const QString& tip) {
    m_tip = tip;
    updateTip();
}

bool ElidedLabel::isElided() const {
    const QRect r = contentsRect();
    return fontMetrics().horizontalAdvance(text()) > r.width();
}

QSize ElidedLabel::minimumSizeHint() const {
    return QSize(fontMetrics().horizontalAdvance(QStringLiteral("M…M")), fontMetrics().height() + 2);
}

QSize ElidedLabel::sizeHint() const {
    return QSize(fontMetrics().horizontalAdvance(text()) + 4, fontMetrics().height() + 2);
}

void ElidedLabel::paintEvent(QPaintEvent*) {
    QPainter p(this);
    const QRect r = contentsRect();
    const QString shown = fontMetrics().elidedText(text(), m_mode, r.width());
    style()->drawItemText(&p, r, int(alignment()) | Qt::TextSingleLine, palette(), isEnabled(), shown, foregroundRole());
}

void ElidedLabel::resizeEvent(QResizeEvent* e) {
    QLabel::resizeEvent(e);
    updateTip();
}

void ElidedLabel::updateTip() {
    const bool elided = isElided();
    setToolTip(elided ? (m_tip.isEmpty() ? text() : text() + "\n\n" + m_tip) : m_tip);
}

}  // namespace lwb::ui
