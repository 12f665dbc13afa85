#include "ui/footprint/shot_table_model.hpp"

#include <QCoreApplication>

#include <QColor>
#include <QFileInfo>
#include <cmath>

#include "ui/footprint/shot_columns.hpp"

namespace lwb::ui {

QString verdictLabel(Verdict v) { return QString::fromLatin1(core::footprint::verdictName(v)); }

QColor verdictColor(Verdict v) {
    switch (v) {
        case Verdict::Good: return QColor(46, 139, 87);
        case Verdict::Doubtful: return QColor(214, 137, 16);
        case Verdict::Rejected: return QColor(192, 57, 43);
    }
    return Qt::gray;
}

ShotState shotState(const Shot& s) {
    if (!s.loadError.isEmpty()) return ShotState::Unreadable;
    if (!s.processed) return ShotState::Pending;
    return ShotState(int(s.effectiveVerdict()));  // Good, Doubtful, Rejected share the values
}

QString shotStateLabel(ShotState s) {
    switch (s) {
        case ShotState::Unreadable: return QObject::tr("unreadable");
        case ShotState::Pending: return QObject::tr("…");
        default: return verdictLabel(Verdict(int(s)));
    }
}

QString shotStateText(ShotState s) {
    switch (s) {
        case ShotState::Good: return QCoreApplication::translate("lwb::ui::ShotTableModel", "good");
        case ShotState::Doubtful: return QCoreApplication::translate("lwb::ui::ShotTableModel", "doubtful");
        case ShotState::Rejected: return QCoreApplication::translate("lwb::ui::ShotTableModel", "rejected");
        default: return shotStateLabel(s);
    }
}

QColor shotStateColor(ShotState s) {
    switch (s) {
        case ShotState::Unreadable: return QColor(110, 110, 120);
        case ShotState::Pending: return QColor(128, 128, 128);
        default: return verdictColor(Verdict(int(s)));
    }
}

QStringList ShotFilterProxy::filterKeys() { return {"all", "good", "doubtful", "rejected", "unreadable", "manual"}; }

ShotTableModel::ShotTableModel(FootprintController* c, QObject* parent) : QAbstractTableModel(parent), m_c(c) {
    connect(c, &FootprintController::shotsAboutToReset, this, [this]() { beginResetModel(); });
    connect(c, &FootprintController::shotsReset, this, [this]() { endResetModel(); });
    connect(c, &FootprintController::shotsAboutToAppend, this,
            [this](int first, int last) { beginInsertRows({}, first, last); });
    connect(c, &FootprintController::shotsAppended, this, [this](int, int) { endInsertRows(); });
    connect(c, &FootprintController::shotsChanged, this, [this](int first, int last) {
        emit dataChanged(index(first, 0), index(last, ColumnCount - 1));
    });
}

int ShotTableModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : m_c->count(); }
int ShotTableModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant ShotTableModel::headerData(int section, Qt::Orientation o, int role) const {
    if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
    static const char* names[] = {QT_TR_NOOP("File"),    QT_TR_NOOP("Time"),    QT_TR_NOOP("Beam"),
                                  QT_TR_NOOP("X (px)"),  QT_TR_NOOP("Y (px)"),  QT_TR_NOOP("Verdict"),
                                  QT_TR_NOOP("Failed criteria"), QT_TR_NOOP("Noise"), QT_TR_NOOP("Note")};
    return section >= 0 && section < ColumnCount ? tr(names[section]) : QVariant();
}

QVariant ShotTableModel::data(const QModelIndex& index, int role) const {
    const Shot* s = m_c->shot(index.row());
    if (!s) return {};
    const bool failed = !s->loadError.isEmpty();
    const Verdict v = failed ? Verdict::Rejected : s->effectiveVerdict();
    const ShotState state = shotState(*s);
    if (role == VerdictRole) return failed ? -1 : int(v);
    if (role == StateRole) return int(state);
    if (role == Qt::ToolTipRole) {
        if (failed) return s->loadError;
        if (index.column() == Reasons || index.column() == VerdictCol) return s->reasons.join("\n");
        if (index.column() == Time) return s->time;
        return s->file;
    }
    if (role == Qt::ForegroundRole && index.column() == VerdictCol) return shotStateColor(state);
    if (role == Qt::TextAlignmentRole && (index.column() == X || index.column() == Y))
        return int(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != SortRole) return {};
    const bool sort = role == SortRole;
    switch (index.column()) {
        case File: return sort ? s->file : QFileInfo(s->file).fileName();
        case Time: return sort ? s->time : s->time.left(10);  // the date; the full time is in the tooltip
        case Beam: return s->beam;
        case X: {
            const double x = s->fullX();
            return std::isfinite(x) && v != Verdict::Rejected ? (sort ? QVariant(x) : QString::number(x, 'f', 3)) : QVariant();
        }
        case Y: {
            const double y = s->fullY();
            return std::isfinite(y) && v != Verdict::Rejected ? (sort ? QVariant(y) : QString::number(y, 'f', 3)) : QVariant();
        }
        case VerdictCol:
            if (sort) return int(state) * 2 + (s->overridden ? 1 : 0);
            return s->overridden && !failed ? shotStateText(state) + tr(" (manual)") : shotStateText(state);
        case Reasons: return failed ? s->loadError : s->reasons.join("; ");
        case NoiseClass: return s->noiseClass;
        case Note: return s->note;
    }
    return {};
}

void ShotFilterProxy::setVerdictFilter(Filter f) {
    m_filter = f;
    invalidateFilter();
}

bool ShotFilterProxy::setExpression(const QString& text, QString* error) {
    core::RowFilterParams p;
    p.text = text.toStdString();
    p.columns = shotColumnNames();
    const core::RowFilterResult r = core::compileRowFilter(p);
    if (!r.ok) {
        if (error) *error = QString::fromStdString(r.error);
        return false;
    }
    m_where = r.filter;
    m_expression = r.empty ? QString() : text.trimmed();
    invalidateFilter();
    return true;
}

bool ShotFilterProxy::filterAcceptsRow(int row, const QModelIndex& parent) const {
    if (!verdictAccepts(row, parent)) return false;
    if (!m_where) return true;
    const auto* model = qobject_cast<const ShotTableModel*>(sourceModel());
    const Shot* s = model ? model->controller()->shot(row) : nullptr;
    if (!s) return false;
    const int roi = shotRoiIndex(*model->controller(), row);
    std::vector<core::FilterCell> cells(shotColumnNames().size());
    for (int c : m_where->usedColumns()) cells[size_t(c)] = shotCell(*s, roi, c);
    return m_where->matches(cells);
}

bool ShotFilterProxy::verdictAccepts(int row, const QModelIndex& parent) const {
    if (m_filter == All) return true;
    const QModelIndex i = sourceModel()->index(row, 0, parent);
    const ShotState s = ShotState(sourceModel()->data(i, ShotTableModel::StateRole).toInt());
    switch (m_filter) {
        case GoodOnly: return s == ShotState::Good;
        case DoubtfulOnly: return s == ShotState::Doubtful;
        case RejectedOnly: return s == ShotState::Rejected;
        case UnreadableOnly: return s == ShotState::Unreadable;
        case OverriddenOnly:
            // (the sort key: state · 2 + overridden; the shown text is translated)
            return sourceModel()->data(sourceModel()->index(row, ShotTableModel::VerdictCol, parent), ShotTableModel::SortRole).toInt() % 2 == 1;
        default: return true;
    }
}

}  // namespace lwb::ui
