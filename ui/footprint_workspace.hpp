#pragma once
// The footprint review workspace: shot table, ROI and frame views with the fits drawn over
// them, the parameter panel, and the trend plots.
#include <QJsonObject>
#include <QWidget>

#include "core/common/json.hpp"
#include "ui/footprint_controller.hpp"

class QTableView;
class QComboBox;
class QLabel;
class QLineEdit;
class QTabWidget;
class QCheckBox;
class QCustomPlot;
class QTextBrowser;

namespace lwb::ui {

class ImageView;
class ShotTableModel;
class ShotFilterProxy;
class FootprintParamsPanel;

class FootprintWorkspace : public QWidget {
    Q_OBJECT
public:
    explicit FootprintWorkspace(QWidget* parent = nullptr);
    FootprintController* controller() const { return m_controller; }
    FootprintParamsPanel* paramsPanel() const { return m_panel; }
    QTableView* table() const { return m_table; }
    ShotFilterProxy* proxy() const { return m_proxy; }
    ImageView* roiView() const { return m_roiView; }

    /// Session state: inputs, parameters, overrides and notes (keyed by file and ROI centre).
    QJsonObject saveState() const;
    /// Restores a session; loading of the inputs runs in the background, overrides are applied
    /// as rows arrive. The parameters start from the defaults and every field given is read
    /// (footprintSchema().fromJson: unknown keys are errors naming the key, with the line and
    /// column when `doc`, the parsed session file, is given; `at`: this state's path in it).
    /// False with *error when the state is malformed.
    bool restoreState(const QJsonObject& state, QString* error, const core::JsonParseResult* doc = nullptr,
                      const std::vector<std::string>& at = {"footprint"});

    /// "review" or "trend".
    void showTab(const QString& name);
    void acceptCurrent();
    void rejectCurrent();
    void selectRow(int sourceRow);

signals:
    void modified();               ///< something a session would save changed
    void status(const QString& message);

private:
    void showDetail(const ShotDetail& d);
    void updateCounts();
    void refreshTrend();
    void currentRowChanged();
    int currentSourceRow() const;

public:
    /// Applies session overrides to the rows that have arrived (called as rows arrive).
    void applyPendingOverrides();

private:

    FootprintController* m_controller;
    ShotTableModel* m_model;
    ShotFilterProxy* m_proxy;
    QTableView* m_table;
    QComboBox *m_filter, *m_colorMap, *m_stretch;
    QLabel *m_counts, *m_readout, *m_details;
    QCheckBox *m_showGauss, *m_showTefm, *m_showDomain, *m_showCentres;
    ImageView *m_roiView, *m_frameView;
    QLineEdit* m_note;
    FootprintParamsPanel* m_panel;
    QTabWidget* m_tabs;
    QCustomPlot *m_plotX, *m_plotY, *m_plotPointing;
    QLabel* m_trendSummary;
    ShotDetail m_detail;
    QJsonObject m_pendingOverrides;  // from a session, applied when rows arrive
    cv::Mat m_frame;                 // full frame of the current shot (when it is one)
    QString m_frameFile;
};

}  // namespace lwb::ui
