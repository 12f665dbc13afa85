#include "ui/footprint/footprint_params_panel.hpp"

#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QVBoxLayout>

#include "core/common/atomic_file.hpp"
#include "core/common/json.hpp"

namespace lwb::ui {

using namespace core::footprint;

QString FootprintParamsPanel::userPresetDir() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/footprint-presets";
}

FootprintParamsPanel::~FootprintParamsPanel() = default;

FootprintParamsPanel::FootprintParamsPanel(QWidget* parent)
    : QWidget(parent), m_form(std::make_unique<SchemaForm<FootprintParams>>(footprintSchema(), this)) {
    SchemaForm<FootprintParams>& form = *m_form;
    auto* top = new QVBoxLayout(this);
    auto* head = new QFormLayout;
    head->addRow(tr("Method"), form.add("method", tr("Method"),
                                        {tr("Gray centroid (baseline)"), tr("TEFM (threshold + ellipse)"),
                                         tr("Gaussian fit (Wu + Guo + LM)")}));
    auto* presetRow = new QHBoxLayout;
    m_preset = new QComboBox(this);
    m_preset->setToolTip(tr("Verdict criteria of a paper (wu2021, yao2021), or a saved preset (every parameter)"));
    m_savePreset = new QPushButton(tr("Save…"), this);
    m_savePreset->setToolTip(tr("Save the current parameters as a preset (the CLI reads it with --config)"));
    presetRow->addWidget(m_preset, 1);
    presetRow->addWidget(m_savePreset);
    head->addRow(tr("Preset"), presetRow);
    top->addLayout(head);

    auto group = [this, top](const QString& title) {
        auto* g = new QGroupBox(title, this);
        top->addWidget(g);
        return new QFormLayout(g);
    };
    QFormLayout* seg = group(tr("Spot domain"));
    form.place(seg, "segment.threshold_factor", tr("Threshold factor"));
    form.place(seg, "segment.min_peak_snr", tr("Min. peak SNR"));
    QFormLayout* tefm = group(tr("TEFM"));
    form.place(tefm, "tefm.background_offset", tr("Background offset"));
    form.place(tefm, "tefm.threshold_factor", tr("Threshold factor"));
    form.place(tefm, "tefm.erosion_size", tr("Erosion size"));
    QFormLayout* ver = group(tr("Verdict criteria"));
    form.place(ver, "verdict.axis_ratio", tr("Axis ratio C = σx/σy"));
    form.place(ver, "verdict.major_axis_px", tr("Major axis L_A"));
    form.place(ver, "verdict.tilt_deg", tr("Tilt θ"));
    form.place(ver, "verdict.eccentricity", tr("Eccentricity"));
    form.place(ver, "verdict.mse_max", tr("MSE below"));
    form.place(ver, "verdict.max_uncertainty_px", tr("Uncertainty at most"));
    form.place(ver, "verdict.check_edge", tr("Spot must not touch the ROI edge"));
    form.place(ver, "verdict.check_saturation", tr("No saturated pixels"));
    form.place(ver, "verdict.check_second_spot", tr("No second spot above"));
    form.place(ver, "verdict.second_spot_fraction", tr("  of main peak"));
    // Every other row of the table, so no parameter is out of reach. "preset" is the combo above.
    m_advanced = new CollapsibleSection(tr("Advanced (every other parameter)"), this);
    form.addRemaining(m_advanced->form(), {"preset"});
    top->addWidget(m_advanced);
    m_message = form.addMessageLabel([this] { emit paramsChanged(m_form->params()); });
    top->addWidget(m_message);
    top->addStretch(1);

    connect(m_preset, &QComboBox::activated, this, [this](int i) {
        QString err;
        if (!loadPreset(m_preset->itemData(i).toString(), &err)) QMessageBox::warning(this, tr("Preset"), err);
    });
    connect(m_savePreset, &QPushButton::clicked, this, &FootprintParamsPanel::askAndSavePreset);
    rebuildPresetList();
    setParams(FootprintParams{});
}

ParamSlider* FootprintParamsPanel::thresholdSlider() const {
    return qobject_cast<ParamSlider*>(m_form->widget("segment.threshold_factor"));
}

ParamSlider* FootprintParamsPanel::axisRatioMaxSlider() const {
    auto* r = qobject_cast<RangeEdit*>(m_form->widget("verdict.axis_ratio"));
    return r ? r->hiSlider() : nullptr;
}

QComboBox* FootprintParamsPanel::methodCombo() const { return qobject_cast<QComboBox*>(m_form->widget("method")); }

void FootprintParamsPanel::rebuildPresetList() {
    m_preset->clear();
    for (const auto& n : verdictPresetNames()) m_preset->addItem(QString::fromStdString(n), QString::fromStdString(n));
    const QDir dir(userPresetDir());
    for (const QString& f : dir.entryList({"*.json"}, QDir::Files, QDir::Name))
        m_preset->addItem(tr("%1 (saved)").arg(QFileInfo(f).completeBaseName()), dir.filePath(f));
}

bool FootprintParamsPanel::loadPreset(const QString& name, QString* error) {
    FootprintParams p = params();
    if (name.endsWith(".json")) {
        // A preset file is a config: what it does not give takes the default, as with --config.
        p = FootprintParams{};
        const core::JsonParseResult j = core::readJsonFile(name.toStdString());
        std::string err;
        if (!j.ok || !footprintParamsFromJson(j.value, &p, &err, &j)) {
            *error = QString::fromStdString(j.ok ? err : j.error);
            return false;
        }
    } else if (!core::footprint::applyPreset(name.toStdString(), &p)) {
        *error = tr("unknown preset \"%1\"").arg(name);
        return false;
    }
    setParams(p);
    const int i = m_preset->findData(name);
    if (i >= 0) m_preset->setCurrentIndex(i);
    emit paramsChanged(params());
    return true;
}

QString FootprintParamsPanel::saveUserPreset(const QString& name, QString* error) {
    QString safe = name.trimmed();
    safe.replace(QRegularExpression("[^A-Za-z0-9_.-]"), "_");
    QDir().mkpath(userPresetDir());
    const QString path = userPresetDir() + "/" + safe + ".json";
    std::string err;
    if (!core::writeFileAtomic(path.toStdString(), core::dumpJson(footprintParamsToJson(params())), &err)) {
        *error = QString::fromStdString(err);
        return {};
    }
    rebuildPresetList();
    m_preset->setCurrentIndex(m_preset->findData(path));
    return path;
}

void FootprintParamsPanel::askAndSavePreset() {
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Save preset"), tr("Preset name:"), QLineEdit::Normal, {}, &ok).trimmed();
    if (!ok || name.isEmpty()) return;
    QString err;
    if (saveUserPreset(name, &err).isEmpty()) QMessageBox::warning(this, tr("Save preset"), err);
}

void FootprintParamsPanel::setParams(const FootprintParams& p) {
    m_form->setParams(p);
    const int i = m_preset->findData(QString::fromStdString(p.preset));
    if (i >= 0) m_preset->setCurrentIndex(i);
    m_message->hide();
}

QString FootprintParamsPanel::rowLabel(const std::string& key) const {
    const QString l = m_form->label(key);
    if (l.isEmpty()) return QString::fromStdString(key);
    if (!l.startsWith(QLatin1String("  "))) return l;
    // A row that continues the one above it ("  of main peak" under "No second spot above").
    const std::vector<std::string> keys = m_form->boundKeys();
    const auto it = std::find(keys.begin(), keys.end(), key);
    return it == keys.begin() || it == keys.end() ? l.trimmed() : m_form->label(*(it - 1)) + " " + l.trimmed();
}

}  // namespace lwb::ui
