#include "ui/kit/save_path.hpp"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSettings>

namespace lwb::ui {

namespace {
// The suffixes of a filter's patterns: "CRD (*.npt *.np2 *.crd)" → npt, np2, crd (every type's,
// for a filter list "PNG (*.png);;SVG (*.svg)").
QStringList suffixesOf(const QString& filter) {
    QStringList suffixes;
    const QRegularExpression pattern(QStringLiteral("\\*\\.([A-Za-z0-9_.]+)"));
    for (auto it = pattern.globalMatch(filter); it.hasNext();) suffixes << it.next().captured(1).toLower();
    return suffixes;
}
bool endsWithOneOf(const QString& name, const QStringList& suffixes) {
    for (const QString& s : suffixes)
        if (name.endsWith("." + s)) return true;
    return false;
}
}  // namespace

QString withFilterSuffix(const QString& path, const QString& filter, const QString& allFilters) {
    if (path.isEmpty()) return path;
    const QStringList suffixes = suffixesOf(filter);
    if (suffixes.isEmpty()) return path;
    const QString name = QFileInfo(path).fileName().toLower();
    // A name that says the chosen type, or another type of the dialog ("x.svg" with the PNG type
    // chosen wrote "x.svg.png", issue 42): the name's type is written.
    if (endsWithOneOf(name, suffixes) || endsWithOneOf(name, suffixesOf(allFilters))) return path;
    return path + "." + suffixes.first();
}

QString askSavePath(QWidget* parent, const QString& title, const QString& settingsKey, const QString& suggestedName,
                    const QString& filter) {
    QSettings st;
    const QString dir = st.value(settingsKey).toString();
    QString selected;
    const QString path = QFileDialog::getSaveFileName(parent, title, suggestedName.isEmpty() ? dir : QDir(dir).filePath(suggestedName),
                                                      filter, &selected);
    if (path.isEmpty()) return path;
    st.setValue(settingsKey, QFileInfo(path).absolutePath());
    return withFilterSuffix(path, selected.isEmpty() ? filter : selected, filter);
}

}  // namespace lwb::ui
