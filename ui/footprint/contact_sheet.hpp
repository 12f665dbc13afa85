#pragma once
// Contact sheet of the footprint review: a grid of ROI thumbnails of the current view (the shot
// table's filter and sort), each with its verdict badge ("manual" marked), keyboard navigable;
// a click or Enter opens the shot in the review.
#include <QHash>
#include <QImage>
#include <QListView>
#include <QStyledItemDelegate>

#include "ui/kit/color_maps.hpp"

class QSortFilterProxyModel;

namespace lwb::ui {

class FootprintController;

class ContactSheet : public QListView {
    Q_OBJECT
public:
    /// view: the shot table's proxy (filter and sort shared with the table).
    ContactSheet(FootprintController* c, QSortFilterProxyModel* view, QWidget* parent = nullptr);
    void setColorMap(ColorMap map);
    /// Source row of the current thumbnail (-1: none).
    int currentSourceRow() const;
    /// Makes the thumbnail of a source row current (when it is in the view).
    void setCurrentSourceRow(int row);
    /// Thumbnail of a source row (rendered on first use, then cached until the list changes).
    QImage thumbnail(int sourceRow) const;
    static constexpr int kThumb = 96;

signals:
    void openShot(int sourceRow);

private:
    FootprintController* m_c;
    QSortFilterProxyModel* m_view;
    ColorMap m_map = ColorMap::Viridis;
    mutable QHash<int, QImage> m_cache;
};

}  // namespace lwb::ui
