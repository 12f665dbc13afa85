#pragma once
// The footprint parameter panel: method, presets (built-in and user-saved) and a slider with
// a numeric field for every threshold. Emits paramsChanged on every edit.
#include <QWidget>

#include "core/footprint/pipeline.hpp"

class QComboBox;
class QCheckBox;
class QPushButton;
class QFormLayout;

namespace lwb::ui {

class ParamSlider;

class FootprintParamsPanel : public QWidget {
    Q_OBJECT
public:
    explicit FootprintParamsPanel(QWidget* parent = nullptr);
    core::footprint::FootprintParams params() const { return m_params; }
    /// Shows p without emitting paramsChanged.
    void setParams(const core::footprint::FootprintParams& p);
    /// Folder of user presets (JSON files in the CLI's --config format).
    static QString userPresetDir();

    // For tests and the latency benchmark.
    ParamSlider* thresholdSlider() const { return m_threshold; }
    ParamSlider* axisRatioMaxSlider() const { return m_ratioMax; }
    QComboBox* methodCombo() const { return m_method; }

signals:
    void paramsChanged(const core::footprint::FootprintParams& p);

private:
    void rebuildPresetList();
    void applyPreset(const QString& name);
    void saveUserPreset();
    void fromWidgets();
    struct RangeRow {
        QCheckBox* on;
        ParamSlider *lo, *hi;
    };
    RangeRow addRange(QFormLayout* form, const QString& name, double lo, double hi, int decimals, const QString& unit);

    core::footprint::FootprintParams m_params;
    bool m_loading = false;
    QComboBox *m_method, *m_preset;
    QPushButton *m_savePreset;
    ParamSlider *m_threshold, *m_offset, *m_erosion, *m_mseMax, *m_secondSpot, *m_minSnr;
    QCheckBox *m_offsetEstimated, *m_mseOn, *m_edgeOn, *m_satOn, *m_secondOn;
    RangeRow m_ratio, m_length, m_tilt, m_ecc;
    ParamSlider *m_ratioMax;
};

}  // namespace lwb::ui
