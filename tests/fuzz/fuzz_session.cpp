// libFuzzer target: the parts of a GUI session file (*.lwb.json) that are read without widgets:
// Qt's JSON parser (QJsonDocument::fromJson, as MainWindow::openSession calls it) and the three
// parameter blocks the workspaces restore: "calibration"."params" (calibParamsFromJson),
// "radiometry"."params" (radiometryParamsFromJson) and "footprint"."params" (turned back into
// text and read by core::parseJson + footprintParamsFromJson, as FootprintWorkspace does).
// A parameter block that reads is written (…ToJson) and read again to the same JSON. The rest
// of a session (input files, regions, overrides, the window) is restored by the workspace
// widgets and is not reached here.
#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

#include "core/footprint/pipeline.hpp"
#include "tests/fuzz/fuzz_support.hpp"
#include "ui/calib/calib_controller.hpp"
#include "ui/radiometry/radiometry_controller.hpp"

using namespace lwb;
using lwb::fuzz::check;

namespace {

QByteArray text(const QJsonObject& o) { return QJsonDocument(o).toJson(QJsonDocument::Compact); }

template <class Params, class From, class To>
void roundTrip(const QJsonObject& block, From from, To to) {
    Params p;
    QString err;
    if (!from(block, &p, &err)) {
        check(!err.isEmpty());
        return;
    }
    const QByteArray written = text(to(p));
    Params q;
    check(from(QJsonDocument::fromJson(written).object(), &q, &err));
    check(text(to(q)) == written);
}

void footprintParams(const QJsonObject& block) {
    const core::JsonParseResult j = core::parseJson(QJsonDocument(block).toJson().toStdString(), "session params");
    check(j.ok);  // Qt wrote it
    core::footprint::FootprintParams p;
    std::string err;
    lwb::fuzz::checkReported(core::footprint::footprintParamsFromJson(j.value, &p, &err), err);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    QJsonParseError pe;
    const QJsonDocument doc =
        QJsonDocument::fromJson(QByteArray(reinterpret_cast<const char*>(data), int(size)), &pe);
    if (pe.error != QJsonParseError::NoError) {
        check(!pe.errorString().isEmpty());
        return 0;
    }
    const QJsonObject o = doc.object();
    roundTrip<ui::CalibParams>(
        o["calibration"].toObject()["params"].toObject(),
        [](const QJsonObject& b, ui::CalibParams* p, QString* e) { return ui::calibParamsFromJson(b, p, e); },
        ui::calibParamsToJson);
    roundTrip<ui::RadiometryParams>(
        o["radiometry"].toObject()["params"].toObject(),
        [](const QJsonObject& b, ui::RadiometryParams* p, QString* e) { return ui::radiometryParamsFromJson(b, p, e); },
        ui::radiometryParamsToJson);
    footprintParams(o["footprint"].toObject()["params"].toObject());
    return 0;
}
