#pragma once
// Table model of the footprint shot list (reads the controller's shots) and a proxy that
// filters by verdict and sorts numerically.
#include <QAbstractTableModel>
#include <QSortFilterProxyModel>

#include "ui/footprint_controller.hpp"

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

protected:
    bool filterAcceptsRow(int row, const QModelIndex& parent) const override;

private:
    Filter m_filter = All;
};

QString verdictLabel(Verdict v);
QColor verdictColor(Verdict v);

/// What the review shows for a shot: its effective verdict, or that it could not be read, or
/// that it has not been judged yet.
enum class ShotState { Good, Doubtful, Rejected, Unreadable, Pending };
ShotState shotState(const Shot& s);
QString shotStateLabel(ShotState s);
QColor shotStateColor(ShotState s);

}  // namespace lwb::ui
