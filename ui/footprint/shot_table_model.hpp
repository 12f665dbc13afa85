#pragma once
// Table model of the footprint shot list (reads the controller's shots) and a proxy that
// filters by verdict and by an expression over the columns (core/common/row_filter), and sorts
// numerically.
#include <QAbstractTableModel>
#include <QSortFilterProxyModel>
#include <memory>

#include "core/common/row_filter.hpp"

#include "ui/footprint/footprint_controller.hpp"

namespace lwb::ui {

class ShotTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { File, Time, Beam, X, Y, VerdictCol, Reasons, NoiseClass, Note, ColumnCount };
    /// VerdictRole: the effective Verdict (int) of a readable shot, -1 for an unreadable one.
    /// StateRole: the ShotState (int).
    enum Roles { SortRole = Qt::UserRole + 1, VerdictRole, StateRole };
    explicit ShotTableModel(FootprintController* c, QObject* parent = nullptr);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation o, int role) const override;
    FootprintController* controller() const { return m_c; }

private:
    FootprintController* m_c;
};

class ShotFilterProxy : public QSortFilterProxyModel {
    Q_OBJECT
public:
    enum Filter { All, GoodOnly, DoubtfulOnly, RejectedOnly, UnreadableOnly, OverriddenOnly };
    /// Names for the session file (index = Filter).
    static QStringList filterKeys();
    using QSortFilterProxyModel::QSortFilterProxyModel;
    void setVerdictFilter(Filter f);
    Filter verdictFilter() const { return m_filter; }
    /// The expression filter (shot_columns.hpp names the columns). A blank text shows every
    /// shot. An invalid text leaves the filter as it was: false with *error (position and what
    /// was expected).
    bool setExpression(const QString& text, QString* error);
    /// The expression in force (the last valid one).
    QString expression() const { return m_expression; }
    /// True when a verdict choice or an expression hides shots.
    bool isFiltered() const { return m_filter != All || m_where; }
    /// Whether a source row passes both filters (the trend and the column plot use the view's shots).
    bool acceptsSourceRow(int row) const { return filterAcceptsRow(row, {}); }

protected:
    bool filterAcceptsRow(int row, const QModelIndex& parent) const override;

private:
    bool verdictAccepts(int row, const QModelIndex& parent) const;
    Filter m_filter = All;
    QString m_expression;
    std::shared_ptr<const core::RowFilter> m_where;
};

QString verdictLabel(Verdict v);
QColor verdictColor(Verdict v);

/// What the review shows for a shot: its effective verdict, or that it could not be read, or
/// that it has not been judged yet.
enum class ShotState { Good, Doubtful, Rejected, Unreadable, Pending };
ShotState shotState(const Shot& s);
QString shotStateLabel(ShotState s);
/// The state as the interface shows it (translated; shotStateLabel is the value filters and files use).
QString shotStateText(ShotState s);
QColor shotStateColor(ShotState s);

}  // namespace lwb::ui
