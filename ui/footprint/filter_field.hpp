#pragma once
// The shot list's filter field: a line edit for a row filter expression (core/common/row_filter)
// that completes the word under the cursor from the column names, lists the language and the
// columns in its tooltip, and shows an error (red border, the error first in the tooltip) while
// the text is invalid.
#include <QCompleter>
#include <QLineEdit>

namespace lwb::ui {

/// Completes the last word of a line edit's text (QCompleter completes the whole text).
class WordCompleter : public QCompleter {
    Q_OBJECT
public:
    WordCompleter(const QStringList& words, QObject* parent);
    QStringList splitPath(const QString& path) const override;
    QString pathFromIndex(const QModelIndex& index) const override;

private:
    QLineEdit* edit() const;
};

class FilterField : public QLineEdit {
    Q_OBJECT
public:
    /// help: the tooltip (rich text); words: what the completer offers.
    FilterField(const QString& help, const QStringList& words, QWidget* parent = nullptr);
    /// Marks the text invalid with `error` (empty: valid again).
    void setError(const QString& error);
    QString error() const { return m_error; }
    bool hasError() const { return !m_error.isEmpty(); }

private:
    QString m_help, m_error;
};

}  // namespace lwb::ui
