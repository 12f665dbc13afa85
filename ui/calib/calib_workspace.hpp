#pragma once
// The altimeter calibration workspace (paper 002): the ground detector array's energies as a
// colour map with the fitted footprint and its centre's uncertainty ellipse, the convergence of
// the pointing & range calibration and of the detector fit, the labelled validation statistics
// of the elevation differences, the calibrated parameters, and the waveform match (two-peak
// decomposition, candidate features ranked by Δh).
//
// Errors of the open buttons and exports are shown in a dialog here (a warning on the
// offscreen platform), with the file and line from the core's message.
#include <QJsonObject>
#include <QWidget>

#include "ui/calib/calib_controller.hpp"
#include "ui/kit/workspace.hpp"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QTabWidget;
class QTableWidget;
class QCustomPlot;
class QCPColorMap;
class QCPColorScale;
class QCPCurve;
class QCPGraph;

class QHBoxLayout;

class QCPColorGradient;

namespace lwb::ui {

class CalibParamsPanel;

class CalibWorkspace : public Workspace {
    Q_OBJECT
public:
    explicit CalibWorkspace(QWidget* parent = nullptr);
    CalibController* controller() const { return m_controller; }

    /// Every input from the simulators: detector array, 4 calibration passes of both beams, 22
    /// independent check passes, a double-peak waveform over six candidate features.
    void openDemo() override;
    QJsonObject saveState() const override;

    // Workspace
    QString key() const override { return QStringLiteral("calibration"); }
    QString title() const override { return tr("Altimeter calibration"); }
    QString demoSummary() const override { return tr("a simulated calibration"); }
    bool waitIdle(int timeoutMs) override { return m_controller->waitIdle(timeoutMs); }
    void dropPrepared() override { m_preparedInputs.reset(); }
    /// Nothing from the window: its inputs (array, passes, waveform) are chosen by its own buttons.
    QString claim(const InputProbe&, bool) const override { return QString(); }
    OpenOutcome openInputs(const QMap<QString, QStringList>&, int) override { return {}; }
    /// "detector" (array, pointing, statistics) or "waveform".
    void showTab(const QString& name) override;

    // For tests and screenshots.
    QDoubleSpinBox* triggerField() const;
    QDoubleSpinBox* thresholdField() const;
    QComboBox* pointingModelBox() const;
    CalibParamsPanel* paramsPanel() const { return m_params; }
    QCustomPlot* energyPlot() const { return m_energyPlot; }
    QCustomPlot* centrePlot() const { return m_centrePlot; }
    QCustomPlot* pointingConvergencePlot() const { return m_convPlot; }
    QCustomPlot* detectorConvergencePlot() const { return m_detConvPlot; }
    QCustomPlot* waveformPlot() const { return m_wavePlot; }
    /// Under the plots: validation statistics, calibrated parameters, convergence plots.
    QTabWidget* resultTabs() const { return m_bottomTabs; }
    QTableWidget* statsTable() const { return m_statsTable; }
    QTableWidget* paramTable() const { return m_paramTable; }
    QTableWidget* rankingTable() const { return m_rankTable; }
    QLabel* detectorSummary() const { return m_detSummary; }

private:
    // The constructor's parts.
    QHBoxLayout* buildInputRow();
    QWidget* buildArrayTab();
    QWidget* buildWaveformTab();
    void drawEnergyMap(const CalibRun& run, bool truth, QCPColorGradient grad);
    void drawCentrePlot(const CalibRun& run, bool truth);
    void drawDetectorConvergence(const CalibRun& run);
    QString detectorSummary(const CalibRun& run, bool truth) const;

    void buildPanel(QWidget* panel);
    void showRun(const CalibRun& run);
    void showDetector(const CalibRun& run);
    void showPointing(const CalibRun& run);
    void showStats(const CalibRun& run);
    void showWaveform(const CalibRun& run);
    void showInputs();
    void widgetsFromParams();
    void showError(const QString& title, const QString& message);
    QString openFile(const QString& title, const QString& filter);
    void exportWith(const QString& title, const QString& filter,
                    bool (CalibController::*fn)(const QString&, QString*) const);

    CalibController* m_controller;
    std::shared_ptr<const CalibData> m_preparedInputs;  ///< what a session's prepareState read, for its restore
    QTabWidget* m_tabs;
    QTabWidget* m_bottomTabs = nullptr;  ///< validation statistics, calibrated parameters, convergence
    QLabel *m_inputs, *m_detSummary, *m_statsSource, *m_waveSummary, *m_pointingSummary;
    QCustomPlot *m_energyPlot, *m_centrePlot, *m_convPlot, *m_detConvPlot, *m_wavePlot;
    QCPColorMap* m_energyMap;
    QCPColorScale* m_energyScale;
    QTableWidget *m_statsTable, *m_paramTable, *m_rankTable;
    // Parameters.
    CalibParamsPanel* m_params;
    QComboBox* m_colorMap;
    QCheckBox* m_showTruth;
    bool m_fresh = true;  // the next detector result rescales the views

protected:
    /// restoreState, checkState and prepareState (Workspace) read the session state here:
    /// Validates everything first; on error (*error says what, with the session's file:line:col
    /// when `doc`, the parsed session, is given; `at`: this state's path in it) the previous
    /// state stays.
    bool readState(const QJsonObject& state, QString* error, const core::JsonParseResult* doc,
                   const std::vector<std::string>& at, StatePhase phase) override;
};

}  // namespace lwb::ui
