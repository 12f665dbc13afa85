#pragma once
// A one-line label that never asks for its text's width: text wider than the label is drawn
// elided ("…") and shown whole in the tooltip (issue 42: the SINEX file's name and the SLR hover
// line were clipped mid-letter at 1024 px, and a long line widened its window).
#include <QLabel>

namespace lwb::ui {

class ElidedLabel : public QLabel {
    Q_OBJECT
public:
    explicit ElidedLabel(const QString& text = {}, QWidget* parent = nullptr, Qt::TextElideMode mode = Qt::ElideMiddle);
    /// The whole text (QLabel::text() is that too; only the painting elides).
    void setFullText(const QString& text);
    /// A tooltip shown when the text fits (when it does not, the tooltip is the whole text).
    void setPlainToolTip(const QString& tip);
    /// Whether the text is drawn elided at the current width.
    bool isElided() const;
    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

protected:
    void paintEvent(QPaintEvent*) override;
    void resizeEvent(QResizeEvent* e) override;

private:
    void updateTip();
    Qt::TextElideMode m_mode;
    QString m_tip;
};

}  // namespace lwb::ui
