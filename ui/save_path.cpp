#include "ui/save_path.hpp"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QRegularExpression>
#include <QSettings>

namespace lwb::ui {

QString withFilterSuffix(const QString& path, const QString& filter) {
    if (path.isEmpty()) return path;
    // The suffixes of the filter's patterns: "CRD (*.npt *.np2 *.crd)" → npt, np2, crd.
    QStringList suffixes;
    const QRegularExpression pattern(QStringLiteral("\\*\\.([A-Za-z0-9_.]+)"));
    for (auto it = pattern.globalMatch(filter); it.hasNext();) suffixes << it.next().captured(1).toLower();
    if (suffixes.isEmpty()) return path;
    const QString name = QFileInfo(path).fileName().toLower();
    for (const QString& s : suffixes)
        if (name.endsWith("." + s)) return path;
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
    return withFilterSuffix(path, selected.isEmpty() ? filter : selected);
}

}  // namespace lwb::ui
