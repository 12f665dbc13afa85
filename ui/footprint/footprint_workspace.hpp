#pragma once
// The footprint review workspace: shot table, ROI and frame views with the fits drawn over
// them (DS9-like limits, stretch, histogram and colour bar), a contact sheet of the current
// view, the parameter panel, and the trend plots. The review loop: filter, then A / R / N
// (accept, reject, next unreviewed) and E (note) by keyboard; every verdict and note is an
// undoable command on the workspace's undo stack (undoStackOf).
#include <QHash>
#include <QJsonObject>
#include <QWidget>

#include "core/common/json.hpp"
#include "core/footprint/tune.hpp"
#include "ui/footprint/footprint_controller.hpp"
#include "ui/footprint/shot_table_model.hpp"
#include "ui/kit/task_job.hpp"
#include "ui/kit/workspace.hpp"

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
class FootprintParamsPanel;
class ContactSheet;
class DisplayControls;
class HistogramView;
class ColorBar;
class FilterField;
class ColumnPlot;

class FootprintWorkspace : public Workspace {
    Q_OBJECT
signals:
    /// The strips beside the verdict sliders were drawn (refreshStrips).
    void stripsReady();

public:
public:
    explicit FootprintWorkspace(QWidget* parent = nullptr);
    FootprintController* controller() const { return m_controller; }
    FootprintParamsPanel* paramsPanel() const { return m_panel; }
    QTableView* table() const { return m_table; }
    ShotFilterProxy* proxy() const { return m_proxy; }
    ImageView* roiView() const { return m_roiView; }
    /// The full frame around the ROI (shown for shots cut from a full frame).
    ImageView* frameView() const { return m_frameView; }
    ContactSheet* contactSheet() const { return m_sheet; }
    DisplayControls* displayControls() const { return m_display; }
    HistogramView* histogram() const { return m_histogram; }
    ColorBar* colorBar() const { return m_colorBar; }
    QComboBox* filterBox() const { return m_filter; }
    /// The filter expression field (shot_columns.hpp: the columns; core/common/row_filter: the language).
    FilterField* whereField() const { return m_where; }
    /// The "Plot" tab: any column against any other over the view's shots.
    ColumnPlot* columnPlot() const { return m_columnPlot; }
    /// The trend plots (x, y, pointing) and their summary line.
    QList<QCustomPlot*> trendPlots() const;
    QLabel* trendSummary() const { return m_trendSummary; }
    QLineEdit* noteField() const { return m_note; }
    QLabel* readout() const { return m_readout; }
    /// "reviewed 12 of 30 doubtful": shots judged doubtful by the pipeline that have a manual verdict.
    QLabel* reviewedLabel() const { return m_reviewed; }

    /// Session state: inputs, parameters, overrides and notes (keyed by file and ROI centre),
    /// the filter and the current shot.
    QJsonObject saveState() const override;

    // Workspace
    QString key() const override { return QStringLiteral("footprint"); }
    QString title() const override { return tr("Footprint review"); }
    /// The built-in demo's shots (ui/footprint/demo.cpp) with the panel's parameters.
    void openDemo() override;
    QString demoSummary() const override;
    bool waitIdle(int timeoutMs) override { return m_controller->waitIdle(timeoutMs); }
    /// Folders, frames (PNG, TIFF, PGM, raw) and shot lists (a CSV whose first column is "file").
    QString claim(const InputProbe& probe, bool current) const override;
    OpenOutcome openInputs(const QMap<QString, QStringList>& byRole, int pass) override;
    QList<QAction*> openActions() override;
    QList<QAction*> exportActions() override;
    QList<QAction*> fileOpenActions() override;
    QList<QAction*> fileExportActions() override;
    QStringList shortcutNotes() const override;
    void cancelWork() override;
    /// Asks for frames or a shot list, or a folder, and opens them through the window.
    void chooseInputs();
    void chooseFolder();
    /// Asks for a file and writes the accepted shots (the CLI's accepted-shots CSV).
    void exportAcceptedShots();

    /// "review", "sheet" (contact sheet), "trend" or "plot".
    void showTab(const QString& name) override;
    void acceptCurrent();
    void rejectCurrent();
    /// The next shot of the view after the current one (wrapping) without a manual verdict.
    void nextUnreviewed();
    void selectRow(int sourceRow);

    /// The review table (every shot; acceptedOnly: the accepted ones) through the CLI's report
    /// writer with the review columns. Atomic. False with *error.
    bool exportTable(const QString& path, bool acceptedOnly, QString* error, int* rows = nullptr);
    /// Asks for a file and exports (status message or error).
    void exportDialog(bool acceptedOnly);
    /// Blink / tile window of the shots selected in the table (two or more with an image; the
    /// current view's first shots when fewer are selected). Null when there are not two.
    class BlinkView* openBlinkView();
    /// "Suggest thresholds from my verdicts": the verdict criteria tuned (core VerdictTuneTask, in
    /// the background with the window's progress and Cancel) on the shots that have a manual
    /// verdict; the outcome in a dialog, applied (one undoable step) only when the analyst
    /// accepts (the verdict criteria alone, over the parameters of then). False when the shots are
    /// still being processed (said through failed()); too few manual verdicts are said when the
    /// task ends.
    bool suggestThresholds();
    /// The strips beside the verdict sliders (issue 45): for each verdict threshold switched on,
    /// the shots whose verdict would change (filled) and, where shots have a manual verdict,
    /// the disagreements with them (a line) along the slider's track, computed in the background
    /// (core sweepCriterion) after every rejudge or verdict edit. Returns at once; stripsReady()
    /// when they are drawn.
    void refreshStrips();
    /// The last suggestion's dialog (null before one), for tests: Apply and Close.
    class QDialog* suggestionDialog() const { return m_suggestion; }
    /// The line under the views with the regions' statistics.
    QLabel* regionStatsLabel() const { return m_regionStats; }

private:
    // The constructor's parts.
    QWidget* buildShotList();
    void buildCentre();
    void wireController();
    void wireZoomKeys();
    void setRoiOverlay();

    void showDetail(const ShotDetail& d);
    void updateCounts();
    void refreshTrend();
    void applyWhere();
    void viewChanged();
    QWidget* buildTrendTab();
    void currentRowChanged();
    int currentSourceRow() const;
    /// After the view changed: `sourceRow` current again if it is in the view, else the first row.
    void selectInView(int sourceRow);
    void judgeCurrent(bool overridden, Verdict v);
    /// New parameters from the panel or a suggestion: the controller reruns, one undoable step.
    void changeParams(const core::footprint::FootprintParams& p, const QString& what);
    void showSuggestion(const core::footprint::VerdictTuneResult& r, int labelled);
    void commitNote();

public:
    /// Applies session overrides (and the session's current shot) to the rows first..last that
    /// have arrived (last -1: every row; called as rows arrive, for the rows that arrived).
    void applyPendingOverrides(int first = 0, int last = -1);

private:
    FootprintController* m_controller;
    ShotTableModel* m_model;
    ShotFilterProxy* m_proxy;
    QTableView* m_table;
    QComboBox *m_filter, *m_colorMap;
    DisplayControls* m_display;
    HistogramView* m_histogram;
    ColorBar* m_colorBar;
    QLabel *m_counts, *m_reviewed, *m_readout, *m_details;
    QLabel* m_regionStats = nullptr;
    QCheckBox *m_showGauss, *m_showTefm, *m_showDomain, *m_showCentres;
    ImageView *m_roiView, *m_frameView;
    ContactSheet* m_sheet;
    QLineEdit* m_note;
    FootprintParamsPanel* m_panel;
    QTabWidget* m_tabs;
    QWidget *m_reviewTab, *m_trendTab;
    FilterField* m_where;
    ColumnPlot* m_columnPlot;
    QCustomPlot *m_plotX, *m_plotY, *m_plotPointing;
    QLabel* m_trendSummary;
    ShotDetail m_detail;
    QHash<QString, QJsonObject> m_pendingOverrides;  // from a session (by shot key), applied when rows arrive
    QString m_pendingCurrent;        // from a session: key of the shot to make current
    cv::Mat m_frame;                 // full frame of the current shot (when it is one)
    QString m_frameFile;
    TaskJob<core::footprint::VerdictTuneTask>* m_tuneJob = nullptr;
    std::shared_ptr<const core::footprint::VerdictTuneTask::Inputs> m_tuneInputs;  // the next suggestion's shots
    QDialog* m_suggestion = nullptr;
    class QTimer* m_stripTimer = nullptr;
    std::shared_ptr<core::Feedback> m_stripWork;  // the strips being computed (cancelled by the next)

protected:
    /// restoreState, checkState and prepareState (Workspace) read the session state here:
    /// Restores a session; loading of the inputs runs in the background, overrides (and the
    /// current shot) are applied as rows arrive. The parameters start from the defaults and every field given is read
    /// (footprintSchema().fromJson: unknown keys are errors naming the key, with the line and
    /// column when `doc`, the parsed session file, is given; `at`: this state's path in it).
    /// False with *error when the state is malformed.
    bool readState(const QJsonObject& state, QString* error, const core::JsonParseResult* doc,
                   const std::vector<std::string>& at, StatePhase phase) override;
};

}  // namespace lwb::ui
