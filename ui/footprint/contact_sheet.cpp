#include "ui/footprint/contact_sheet.hpp"

#include <QFileInfo>
#include <QPainter>
#include <QSortFilterProxyModel>

#include "ui/kit/display_controls.hpp"
#include "ui/footprint/footprint_controller.hpp"
#include "ui/kit/image_view.hpp"
#include "ui/footprint/shot_table_model.hpp"

namespace lwb::ui {

namespace {
class ThumbDelegate : public QStyledItemDelegate {
public:
    ThumbDelegate(const ContactSheet* sheet, FootprintController* c, QSortFilterProxyModel* view)
        : QStyledItemDelegate(const_cast<ContactSheet*>(sheet)), m_sheet(sheet), m_c(c), m_view(view) {}

    QSize sizeHint(const QStyleOptionViewItem& o, const QModelIndex&) const override {
        return {ContactSheet::kThumb + 12, ContactSheet::kThumb + o.fontMetrics.height() + 14};
    }

    void paint(QPainter* p, const QStyleOptionViewItem& o, const QModelIndex& index) const override {
        const int row = m_view->mapToSource(index).row();
        const Shot* s = m_c->shot(row);
        if (!s) return;
        p->save();
        const QRect r = o.rect.adjusted(2, 2, -2, -2);
        const bool selected = o.state & QStyle::State_Selected;
        p->fillRect(r, selected ? o.palette.color(QPalette::Highlight) : o.palette.color(QPalette::Base));
        const QRect img(r.left() + 4, r.top() + 4, ContactSheet::kThumb, ContactSheet::kThumb);
        const QImage thumb = m_sheet->thumbnail(row);
        if (thumb.isNull()) {
            p->fillRect(img, QColor(40, 40, 40));
            p->setPen(Qt::white);
            p->drawText(img, Qt::AlignCenter | Qt::TextWordWrap, s->loadError.isEmpty() ? QObject::tr("…") : QObject::tr("unreadable"));
        } else {
            p->drawImage(img, thumb);
        }
        // Verdict badge: computed or manual (marked), unreadable apart.
        const QVariant stateRole = index.model()->data(index, ShotTableModel::StateRole);
        const ShotState st = ShotState(stateRole.toInt());
        const QColor colour = shotStateColor(st);
        QFont f = o.font;
        f.setBold(true);
        f.setPointSizeF(std::max(6.0, f.pointSizeF() * 0.85));
        p->setFont(f);
        const QString badge = shotStateText(st) + (s->overridden ? QObject::tr(" ✎") : QString());
        const QSize badgeSize(p->fontMetrics().horizontalAdvance(badge) + 8, p->fontMetrics().height() + 2);
        // In a corner that leaves the spot's centre in view (in the top left one it hid a spot
        // near the ROI's top edge, issue 30); the thumbnail is the ROI stretched over `img`.
        QVector<QPointF> spot;
        if (s->fit.ok && !s->roi.empty())
            spot << QPointF(img.left() + (s->fit.x + 0.5) * img.width() / s->roi.cols,
                            img.top() + (s->fit.y + 0.5) * img.height() / s->roi.rows);
        QRect badgeRect = placeBadge(img, badgeSize, 2, spot, 4);
        if (badgeRect.isEmpty()) badgeRect = QRect(img.topLeft() + QPoint(2, 2), badgeSize);
        p->setPen(Qt::NoPen);
        p->setBrush(QColor(colour.red(), colour.green(), colour.blue(), 225));
        p->drawRoundedRect(badgeRect, 3, 3);
        p->setPen(Qt::white);
        p->drawText(badgeRect, Qt::AlignCenter, badge);
        p->setFont(o.font);
        p->setPen(selected ? o.palette.color(QPalette::HighlightedText) : o.palette.color(QPalette::Text));
        const QRect text(r.left() + 2, img.bottom() + 3, r.width() - 4, o.fontMetrics.height());
        // The end of a name tells shots apart (shot_000123.png, demo:b1_2020-04_02).
        p->drawText(text, Qt::AlignCenter, o.fontMetrics.elidedText(QFileInfo(s->file).fileName(), Qt::ElideLeft, text.width()));
        if (o.state & QStyle::State_HasFocus) {
            p->setPen(QPen(o.palette.color(QPalette::Highlight).lighter(130), 2));
            p->setBrush(Qt::NoBrush);
            p->drawRect(r.adjusted(1, 1, -1, -1));
        }
        p->restore();
    }

private:
    const ContactSheet* m_sheet;
    FootprintController* m_c;
    QSortFilterProxyModel* m_view;
};
}  // namespace

ContactSheet::ContactSheet(FootprintController* c, QSortFilterProxyModel* view, QWidget* parent)
    : QListView(parent), m_c(c), m_view(view) {
    setViewMode(QListView::IconMode);
    setResizeMode(QListView::Adjust);
    setMovement(QListView::Static);
    setUniformItemSizes(true);
    setWrapping(true);
    setSpacing(2);
    setSelectionMode(QAbstractItemView::SingleSelection);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setItemDelegate(new ThumbDelegate(this, c, view));
    setModel(view);
    setToolTip(tr("Arrow keys move; Enter or a click opens the shot in the review"));
    connect(c, &FootprintController::shotsAboutToReset, this, [this] { m_cache.clear(); });
    connect(this, &QAbstractItemView::clicked, this, [this](const QModelIndex& i) { emit openShot(m_view->mapToSource(i).row()); });
    connect(this, &QAbstractItemView::activated, this, [this](const QModelIndex& i) { emit openShot(m_view->mapToSource(i).row()); });
}

void ContactSheet::setColorMap(ColorMap map) {
    if (map == m_map) return;
    m_map = map;
    m_cache.clear();
    viewport()->update();
}

int ContactSheet::currentSourceRow() const {
    const QModelIndex i = currentIndex();
    return i.isValid() ? m_view->mapToSource(i).row() : -1;
}

void ContactSheet::setCurrentSourceRow(int row) {
    const QModelIndex src = m_view->sourceModel()->index(row, 0);
    const QModelIndex i = m_view->mapFromSource(src);
    if (!i.isValid()) return;
    setCurrentIndex(i);
    scrollTo(i);
}

QImage ContactSheet::thumbnail(int sourceRow) const {
    if (m_cache.contains(sourceRow)) return m_cache[sourceRow];
    const Shot* s = m_c->shot(sourceRow);
    if (!s || s->roi.empty()) return {};
    DisplaySettings ds;  // min–max, linear: the spot's shape, as the review shows it by default
    const core::DisplayLimits l = displayLimits(s->roi, ds);
    const QImage img = renderStretched(s->roi, m_map, ds.stretch, l.lo, l.hi)
                           .scaled(kThumb, kThumb, Qt::KeepAspectRatio, Qt::FastTransformation);
    m_cache.insert(sourceRow, img);
    return img;
}

}  // namespace lwb::ui
