#include "ui/footprint/filter_field.hpp"

#include <QAbstractItemView>
#include <QStringListModel>

namespace lwb::ui {

namespace {
// Start of the word that ends at `end` (letters, digits and '_').
int wordStart(const QString& t, int end) {
    int i = end;
    while (i > 0 && (t[i - 1].isLetterOrNumber() || t[i - 1] == '_')) --i;
    return i;
}
}  // namespace

WordCompleter::WordCompleter(const QStringList& words, QObject* parent) : QCompleter(parent) {
    setModel(new QStringListModel(words, this));
    setCaseSensitivity(Qt::CaseInsensitive);
    setCompletionMode(QCompleter::PopupCompletion);
    setModelSorting(QCompleter::UnsortedModel);
}

QLineEdit* WordCompleter::edit() const { return qobject_cast<QLineEdit*>(widget()); }

QStringList WordCompleter::splitPath(const QString& path) const {
    // The word the cursor ends (the whole text is `path`): an empty prefix completes nothing.
    const int end = edit() ? std::min<int>(edit()->cursorPosition(), path.size()) : path.size();
    const QString word = path.mid(wordStart(path, end), end - wordStart(path, end));
    return {word.isEmpty() ? QStringLiteral("\x01") : word};
}

QString WordCompleter::pathFromIndex(const QModelIndex& index) const {
    const QString word = QCompleter::pathFromIndex(index);
    QLineEdit* e = edit();
    if (!e) return word;
    const QString t = e->text();
    const int end = std::min<int>(e->cursorPosition(), t.size());
    return t.left(wordStart(t, end)) + word + t.mid(end);
}

FilterField::FilterField(const QString& help, const QStringList& words, QWidget* parent)
    : QLineEdit(parent), m_help(help) {
    setClearButtonEnabled(true);
    setToolTip(help);
    setCompleter(new WordCompleter(words, this));
}

void FilterField::setError(const QString& error) {
    m_error = error;
    if (error.isEmpty()) {
        setStyleSheet(QString());
        setToolTip(m_help);
        return;
    }
    setStyleSheet("QLineEdit { border: 2px solid #c0392b; border-radius: 2px; }");
    setToolTip(tr("<p style='color:#c0392b'><b>%1</b></p><p>The filter shown is still the last valid one.</p>")
                   .arg(error.toHtmlEscaped()) +
               m_help);
}

}  // namespace lwb::ui
