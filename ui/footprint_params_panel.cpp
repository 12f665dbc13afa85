#include "ui/footprint_params_panel.hpp"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QComboBox>
#include <QDir>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardPaths>
#include <QVBoxLayout>
#include <QFileInfo>
#include <QRegularExpression>
#include <cmath>

#include "core/common/atomic_file.hpp"
#include "core/common/json.hpp"
#include "ui/param_slider.hpp"

namespace lwb::ui {

using namespace core::footprint;

QString FootprintParamsPanel::userPresetDir() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + "/footprint-presets";
}

FootprintParamsPanel::RangeRow FootprintParamsPanel::addRange(QFormLayout* form, const QString& name, double lo,
                                                              double hi, int decimals, const QString& unit) {
    RangeRow r;
    r.on = new QCheckBox(name, this);
    r.lo = new ParamSlider(tr("  min"), lo, hi, lo, decimals, false, unit, this);
    r.hi = new ParamSlider(tr("  max"), lo, hi, hi, decimals, false, unit, this);
    form->addRow(r.on);
    form->addRow(r.lo);
    form->addRow(r.hi);
    connect(r.on, &QCheckBox::toggled, this, [this, r](bool on) {
        r.lo->setEnabled(on);
        r.hi->setEnabled(on);
        fromWidgets();
    });
    connect(r.lo, &ParamSlider::valueChanged, this, [this] { fromWidgets(); });
    connect(r.hi, &ParamSlider::valueChanged, this, [this] { fromWidgets(); });
    return r;
}

FootprintParamsPanel::FootprintParamsPanel(QWidget* parent) : QWidget(parent) {
    auto* top = new QVBoxLayout(this);
    auto* head = new QFormLayout;
    m_method = new QComboBox(this);
    m_method->addItem(tr("Gaussian fit (Wu + Guo + LM)"), "gauss");
    m_method->addItem(tr("TEFM (threshold + ellipse)"), "tefm");
    m_method->addItem(tr("Gray centroid (baseline)"), "gcm");
    head->addRow(tr("Method"), m_method);
    auto* presetRow = new QHBoxLayout;
    m_preset = new QComboBox(this);
    m_savePreset = new QPushButton(tr("Save…"), this);
    m_savePreset->setToolTip(tr("Save the current parameters as a preset (the CLI reads it with --config)"));
    presetRow->addWidget(m_preset, 1);
    presetRow->addWidget(m_savePreset);
    head->addRow(tr("Preset"), presetRow);
    top->addLayout(head);

    auto* seg = new QGroupBox(tr("Spot domain"), this);
    auto* segForm = new QFormLayout(seg);
    m_threshold = new ParamSlider(tr("Threshold factor"), 0.02, 0.6, m_params.segment.thresholdFactor, 3, false, {}, this);
    m_threshold->setToolTipText(tr("Domain threshold = background + factor × (peak − background); 1/e² = 0.135"));
    m_minSnr = new ParamSlider(tr("Min. peak SNR"), 1, 30, m_params.segment.minPeakSnr, 1, false, {}, this);
    segForm->addRow(m_threshold);
    segForm->addRow(m_minSnr);
    top->addWidget(seg);

    auto* tefm = new QGroupBox(tr("TEFM"), this);
    auto* tefmForm = new QFormLayout(tefm);
    m_offsetEstimated = new QCheckBox(tr("Background offset from the estimate"), this);
    m_offsetEstimated->setChecked(true);
    m_offset = new ParamSlider(tr("Background offset"), 0, 12000, 2000, 0, false, "DN", this);
    m_offset->setEnabled(false);
    m_erosion = new ParamSlider(tr("Erosion size"), 1, 9, m_params.tefm.erosionSize, 0, false, "px", this);
    m_erosion->field()->setSingleStep(2);
    tefmForm->addRow(m_offsetEstimated);
    tefmForm->addRow(m_offset);
    tefmForm->addRow(m_erosion);
    top->addWidget(tefm);

    auto* ver = new QGroupBox(tr("Verdict criteria"), this);
    auto* verForm = new QFormLayout(ver);
    m_ratio = addRange(verForm, tr("Axis ratio C = σx/σy"), 0.3, 3.0, 2, {});
    m_ratioMax = m_ratio.hi;
    m_length = addRange(verForm, tr("Major axis L_A"), 0, 40, 1, "px");
    m_tilt = addRange(verForm, tr("Tilt θ"), -90, 90, 1, "°");
    m_ecc = addRange(verForm, tr("Eccentricity"), 0, 1, 2, {});
    m_mseOn = new QCheckBox(tr("MSE below"), this);
    m_mseMax = new ParamSlider(tr("  max"), 1e-8, 1e-2, 1e-5, 8, true, {}, this);
    verForm->addRow(m_mseOn);
    verForm->addRow(m_mseMax);
    m_edgeOn = new QCheckBox(tr("Spot must not touch the ROI edge"), this);
    m_satOn = new QCheckBox(tr("No saturated pixels"), this);
    m_secondOn = new QCheckBox(tr("No second spot above"), this);
    m_secondSpot = new ParamSlider(tr("  of main peak"), 0.05, 1.5, 0.35, 2, false, {}, this);
    verForm->addRow(m_edgeOn);
    verForm->addRow(m_satOn);
    verForm->addRow(m_secondOn);
    verForm->addRow(m_secondSpot);
    top->addWidget(ver);
    top->addStretch(1);

    for (ParamSlider* s : {m_threshold, m_minSnr, m_offset, m_erosion, m_mseMax, m_secondSpot})
        connect(s, &ParamSlider::valueChanged, this, [this] { fromWidgets(); });
    for (QCheckBox* c : {m_offsetEstimated, m_mseOn, m_edgeOn, m_satOn, m_secondOn})
        connect(c, &QCheckBox::toggled, this, [this] { fromWidgets(); });
    connect(m_method, &QComboBox::currentIndexChanged, this, [this] { fromWidgets(); });
    connect(m_preset, &QComboBox::activated, this, [this](int i) { applyPreset(m_preset->itemData(i).toString()); });
    connect(m_savePreset, &QPushButton::clicked, this, &FootprintParamsPanel::saveUserPreset);
    rebuildPresetList();
    setParams(m_params);
}

void FootprintParamsPanel::rebuildPresetList() {
    m_preset->clear();
    for (const auto& n : verdictPresetNames()) m_preset->addItem(QString::fromStdString(n), QString::fromStdString(n));
    const QDir dir(userPresetDir());
    for (const QString& f : dir.entryList({"*.json"}, QDir::Files, QDir::Name))
        m_preset->addItem(tr("%1 (saved)").arg(QFileInfo(f).completeBaseName()), dir.filePath(f));
}

void FootprintParamsPanel::applyPreset(const QString& name) {
    FootprintParams p = m_params;
    if (name.endsWith(".json")) {
        const core::JsonParseResult j = core::readJsonFile(name.toStdString());
        std::string err;
        if (!j.ok || !footprintParamsFromJson(j.value, &p, &err)) {
            QMessageBox::warning(this, tr("Preset"), QString::fromStdString(j.ok ? err : j.error));
            return;
        }
    } else if (!core::footprint::applyPreset(name.toStdString(), &p)) {
        return;
    }
    setParams(p);
    emit paramsChanged(m_params);
}

void FootprintParamsPanel::saveUserPreset() {
    bool ok = false;
    const QString name = QInputDialog::getText(this, tr("Save preset"), tr("Preset name:"), QLineEdit::Normal, {}, &ok).trimmed();
    if (!ok || name.isEmpty()) return;
    QString safe = name;
    safe.replace(QRegularExpression("[^A-Za-z0-9_.-]"), "_");
    QDir().mkpath(userPresetDir());
    std::string err;
    if (!core::writeFileAtomic((userPresetDir() + "/" + safe + ".json").toStdString(),
                               footprintParamsToJson(m_params).dump(), &err)) {
        QMessageBox::warning(this, tr("Save preset"), QString::fromStdString(err));
        return;
    }
    rebuildPresetList();
    m_preset->setCurrentIndex(m_preset->findData(userPresetDir() + "/" + safe + ".json"));
}

void FootprintParamsPanel::setParams(const FootprintParams& p) {
    m_loading = true;
    m_params = p;
    m_method->setCurrentIndex(m_method->findData(QString(methodName(p.method))));
    const int pi = m_preset->findData(QString::fromStdString(p.preset));
    if (pi >= 0) m_preset->setCurrentIndex(pi);
    m_threshold->setValue(p.segment.thresholdFactor);
    m_minSnr->setValue(p.segment.minPeakSnr);
    m_offsetEstimated->setChecked(std::isnan(p.tefm.backgroundOffset));
    m_offset->setEnabled(!std::isnan(p.tefm.backgroundOffset));
    if (!std::isnan(p.tefm.backgroundOffset)) m_offset->setValue(p.tefm.backgroundOffset);
    m_erosion->setValue(p.tefm.erosionSize);
    auto setRange = [](RangeRow& row, const Range& r) {
        row.on->setChecked(r.enabled);
        row.lo->setEnabled(r.enabled);
        row.hi->setEnabled(r.enabled);
        if (r.enabled) {
            row.lo->setValue(r.lo);
            row.hi->setValue(r.hi);
        }
    };
    setRange(m_ratio, p.verdict.axisRatio);
    setRange(m_length, p.verdict.majorAxisPx);
    setRange(m_tilt, p.verdict.tiltDeg);
    setRange(m_ecc, p.verdict.eccentricity);
    m_mseOn->setChecked(p.verdict.mseEnabled);
    m_mseMax->setEnabled(p.verdict.mseEnabled);
    m_mseMax->setValue(p.verdict.mseMax);
    m_edgeOn->setChecked(p.verdict.checkEdge);
    m_satOn->setChecked(p.verdict.checkSaturation);
    m_secondOn->setChecked(p.verdict.checkSecondSpot);
    m_secondSpot->setValue(p.verdict.secondSpotFraction);
    m_loading = false;
}

void FootprintParamsPanel::fromWidgets() {
    if (m_loading) return;
    FootprintParams p = m_params;
    parseMethod(m_method->currentData().toString().toStdString(), &p.method);
    p.segment.thresholdFactor = m_threshold->value();
    p.tefm.thresholdFactor = m_threshold->value();
    p.segment.minPeakSnr = m_minSnr->value();
    m_offset->setEnabled(!m_offsetEstimated->isChecked());
    p.tefm.backgroundOffset = m_offsetEstimated->isChecked() ? NAN : m_offset->value();
    int e = static_cast<int>(std::lround(m_erosion->value()));
    if (e % 2 == 0) e += 1;
    p.tefm.erosionSize = std::clamp(e, 1, 9);
    auto getRange = [](const RangeRow& row) {
        Range r;
        r.enabled = row.on->isChecked();
        r.lo = std::min(row.lo->value(), row.hi->value());
        r.hi = std::max(row.lo->value(), row.hi->value());
        return r;
    };
    p.verdict.axisRatio = getRange(m_ratio);
    p.verdict.majorAxisPx = getRange(m_length);
    p.verdict.tiltDeg = getRange(m_tilt);
    p.verdict.eccentricity = getRange(m_ecc);
    p.verdict.mseEnabled = m_mseOn->isChecked();
    m_mseMax->setEnabled(p.verdict.mseEnabled);
    p.verdict.mseMax = m_mseMax->value();
    p.verdict.checkEdge = m_edgeOn->isChecked();
    p.verdict.checkSaturation = m_satOn->isChecked();
    p.verdict.checkSecondSpot = m_secondOn->isChecked();
    p.verdict.secondSpotFraction = m_secondSpot->value();
    if (!validate(p).empty()) return;  // e.g. a transient min > max while dragging
    m_params = p;
    emit paramsChanged(m_params);
}

}  // namespace lwb::ui
