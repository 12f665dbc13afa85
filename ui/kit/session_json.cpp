#include "ui/kit/session_json.hpp"

#include <QJsonArray>
#include <QJsonDocument>
#include <QObject>
#include <algorithm>

namespace lwb::ui {

QJsonObject toQtJson(const core::Json& j) {
    return QJsonDocument::fromJson(QByteArray::fromStdString(core::dumpJson(j, -1))).object();
}

core::Json fromQtJson(const QJsonValue& v) {
    // Wrapped in an array, so any value (not only an object) goes through the document.
    const QByteArray text = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    const core::JsonParseResult r = core::parseJson(text.toStdString(), "session");
    return r.ok && r.value.is_array() && !r.value.empty() ? r.value[0] : core::Json();
}

bool checkSessionKeys(const QJsonObject& state, const std::vector<std::string>& known, const QString& workspace,
                      QString* error, const core::JsonParseResult* doc, const std::vector<std::string>& at) {
    for (auto it = state.begin(); it != state.end(); ++it) {
        const std::string key = it.key().toStdString();
        if (std::find(known.begin(), known.end(), key) != known.end()) continue;
        std::vector<std::string> path = at;
        path.push_back(key);
        *error = QString::fromStdString(doc ? doc->where(path) : std::string()) +
                 QObject::tr("unknown key \"%1\" in the %2 session state").arg(it.key(), workspace);
        return false;
    }
    return true;
}

}  // namespace lwb::ui
