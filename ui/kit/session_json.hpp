#pragma once
// Sessions are Qt JSON objects per workspace; the parameter sections in them are the schemas'
// JSON (core::Json). These convert between the two (through text: numbers keep every digit)
// and check a workspace's state for keys it does not know.
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <string>
#include <vector>

#include "core/common/json.hpp"

namespace lwb::ui {

QJsonObject toQtJson(const core::Json& j);
core::Json fromQtJson(const QJsonValue& v);

/// False with *error naming the first key of `state` that is not in `known` ("SOURCE:LINE:COL: "
/// first when `doc`, the parsed session, is given; `at` is the state's path in it).
bool checkSessionKeys(const QJsonObject& state, const std::vector<std::string>& known, const QString& workspace,
                      QString* error, const core::JsonParseResult* doc, const std::vector<std::string>& at);

}  // namespace lwb::ui
