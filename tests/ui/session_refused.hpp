#pragma once
// Shared by the calibration and radiometry workspace tests: a session the workspace must refuse
// with the file, line and column of the bad value.
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QtTest>

#include "core/common/json.hpp"

namespace lwbtest {

// Restores `block` of the session `text` (as the main window does: parsed by the core's JSON
// reader as "s.json") into a fresh Workspace and checks it is refused with a message that starts
// with `where` ("s.json:LINE:") and names `what`.
template <class Workspace>
void expectSessionRefused(const QString& text, const char* block, const QString& where, const QString& what) {
    const lwb::core::JsonParseResult doc = lwb::core::parseJson(text.toStdString(), "s.json");
    QVERIFY2(doc.ok, doc.error.c_str());
    Workspace w;
    QString err;
    QVERIFY(!w.restoreState(QJsonDocument::fromJson(text.toUtf8()).object()[block].toObject(), &err, &doc));
    QVERIFY2(err.startsWith(where) && err.contains(what), qPrintable(err));
}

}  // namespace lwbtest
