#pragma once
// The footprint parameter panel: method, presets (built-in and user-saved) and the thresholds,
// every widget generated from a row of footprintSchema() (ui/schema_form.hpp); the rows not
// placed in the main groups are in the "Advanced" section, so every parameter can be reached.
// Each widget changes only its own parameter; paramsChanged is emitted on every accepted edit.
#include <QWidget>
#include <memory>

#include "core/footprint/pipeline.hpp"
#include "ui/kit/schema_form.hpp"

class QComboBox;
class QLabel;
class QPushButton;

namespace lwb::ui {

class ParamSlider;
class CollapsibleSection;

class FootprintParamsPanel : public QWidget {
    Q_OBJECT
public:
    explicit FootprintParamsPanel(QWidget* parent = nullptr);
    ~FootprintParamsPanel() override;
    const core::footprint::FootprintParams& params() const { return m_form->params(); }
    /// The label of a parameter's row as the panel shows it ("Axis ratio C = σx/σy"); the key when
    /// it has none.
    QString rowLabel(const std::string& key) const;
    /// Shows p without emitting paramsChanged.
    void setParams(const core::footprint::FootprintParams& p);
    /// Folder of user presets (JSON files in the CLI's --config format).
    static QString userPresetDir();
    /// Applies a built-in preset ("wu2021") or a preset / config file (a path ending in .json)
    /// and emits paramsChanged. False with *error (file:line:col) when the file is refused.
    bool loadPreset(const QString& nameOrPath, QString* error);
    /// Writes the current parameters as the user preset `name` (every field, the --config
    /// format) and returns its path; empty with *error on failure.
    QString saveUserPreset(const QString& name, QString* error);

    /// The schema-bound widgets (tests, the latency benchmark).
    SchemaForm<core::footprint::FootprintParams>& form() { return *m_form; }
    ParamSlider* thresholdSlider() const;
    ParamSlider* axisRatioMaxSlider() const;
    QComboBox* methodCombo() const;
    CollapsibleSection* advanced() const { return m_advanced; }
    /// Why the last edit was refused (empty when it was accepted).
    QLabel* messageLabel() const { return m_message; }

signals:
    void paramsChanged(const core::footprint::FootprintParams& p);

private:
    void rebuildPresetList();
    void askAndSavePreset();

    std::unique_ptr<SchemaForm<core::footprint::FootprintParams>> m_form;
    QComboBox* m_preset;
    QPushButton* m_savePreset;
    QLabel* m_message;
    CollapsibleSection* m_advanced;
};

}  // namespace lwb::ui
