#pragma once
// The SLR workspace: the O-C scatter beside its binary image (axes linked), the residual
// histogram, the parameter panel (ui/slr_params_panel.hpp), box edits, presets and exports.
#include <QJsonArray>
#include <QJsonObject>
#include <QPointer>
#include <QSet>
#include <QWidget>
#include <optional>

#include "ui/kit/elided_label.hpp"
#include "core/common/json.hpp"
#include "core/sim/slr_sim.hpp"

#include "ui/kit/workspace.hpp"
#include "ui/slr/slr_controller.hpp"

class QComboBox;
class QToolButton;
class QCheckBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QCustomPlot;
class QCPRange;
class QCPColorMap;
class QCPItemText;

class QHBoxLayout;
class QTabWidget;

namespace lwb::ui {

class ParamSlider;
class SlrParamsPanel;
class SlrAllPassesDialog;
class SlrFileCheckDialog;
class SlrStationNpPanel;
class SlrStrips;

class SlrWorkspace : public Workspace {
    Q_OBJECT
public:
    explicit SlrWorkspace(QWidget* parent = nullptr);
    SlrController* controller() const { return m_controller; }
    SlrParamsPanel* paramsPanel() const { return m_params; }
    ParamSlider* cosineSlider() const;
    ParamSlider* magOcSlider() const;
    ParamSlider* areaSlider() const;
    QCheckBox* autoCheck() const;
    QCustomPlot* ocPlot() const { return m_ocPlot; }
    QCustomPlot* imagePlot() const { return m_imagePlot; }
    QLabel* infoLabel() const { return m_info; }  ///< the pass line and the readers' warnings
    QComboBox* passCombo() const { return m_passCombo; }  ///< every pass, by time; item data = pass index
    QCustomPlot* histPlot() const { return m_histPlot; }
    QLabel* statsLabel() const { return m_stats; }  ///< the run's summary beside the histogram
    QLabel* hoverLabel() const { return m_hover; }
    /// The station's normal points beside ours: the table under the plots (a tab beside the
    /// histogram) and the overlay on the main plot.
    SlrStationNpPanel* stationNpPanel() const { return m_stationNps; }
    /// Opens a station's CRD normal-point file to compare with; "" stops comparing. False with
    /// *error (the file in use kept).
    bool setStationNormalPoints(const QString& path, QString* error);

    /// What a box drawn on the main plot does.
    enum class BoxMode { Pan, Zoom, ForceIn, ForceOut };
    void setBoxMode(BoxMode mode);
    /// The main plot: O-C (ns) or the residual view (O-C less the post-fit trend, ps two-way on
    /// the left axis, mm one-way on the right).
    void setResidualView(bool on);
    bool residualView() const { return m_residual; }
    /// Time axis in seconds of day instead of UTC hh:mm:ss.
    void setSecondsOfDay(bool on);
    /// Home: every plot fitted to its data again.
    void resetView();
    /// The hover readout for a pixel of the main plot ("" when no point is near).
    QString readoutAt(const QPointF& pixel) const;
    /// The point nearest a pixel of the main plot (`m_ocPlot`) or of the binary image, within
    /// 10 px; -1 when none.
    int pointNear(const QCustomPlot* plot, const QPointF& pixel) const;
    /// The one time cursor of the pass (the mouse over `source`, at `pixel`): a line at the
    /// hovered epoch on the O-C plot and the image, the hovered point ringed in each, its
    /// residual marked on the histogram, the readout in the hover line. clearTimeCursor hides it.
    void showTimeCursor(QCustomPlot* source, const QPointF& coords, const QPoint& pixel);
    void clearTimeCursor();
    /// The hover line's text for point k.
    QString pointText(int k) const;
    /// New CPF (a file or a folder) or SINEX; "" clears it. The open pass is read again.
    bool setCpf(const QString& path, QString* error);
    bool setSinex(const QString& path, QString* error);
    QString cpfPath() const { return m_cpfPath; }
    QString sinexPath() const { return m_snxPath; }
    /// Exports the pass as CRD full rate with the screening's flags: `wholeFile` = every pass of
    /// the file with this pass's flags set, else this pass alone. *message says what was written.
    bool exportCrd(const QString& path, bool wholeFile, QString* message);
    /// Opens the "all passes" table of the open CRD file (screened in the background).
    SlrAllPassesDialog* screenAllPasses();
    /// Checks the open CRD file against the format (core checkCrd, as laserwb-cli crd check)
    /// with progress and Cancel, and lists its problems; null when no CRD file is open or it
    /// was cancelled.
    SlrFileCheckDialog* checkFile();
    /// "Tune from this file's passes" (issue 45): the satellite's screening and post-fit
    /// parameters chosen from the station's own filter flags (2 data, 1 noise) over every pass of
    /// the open CRD file, as laserwb-cli slr tune chooses them (core tuneSlr; the starting point
    /// the command's defaults or the satellite's entry of the workbench's presets), with progress
    /// and Cancel. A dialog shows the choice, F1 before, after and held out per pass; *Apply to
    /// this pass* sets it as one undoable step, nothing is changed otherwise. Null when there is
    /// nothing to tune on (said) or it was cancelled.
    QDialog* tuneFromFile();
    /// The same over every pass of the open pass's satellite in the CRD files of a folder (a
    /// station's archive; asked for when `folder` is empty), as laserwb-cli slr tune FOLDER: a
    /// file or pass there that cannot be tuned on is left out with its reason (in the dialog).
    QDialog* tuneFromFolder(QString folder = {});
    QList<QAction*> fileOpenActions() override;
    /// The strips beside the sliders (ui/slr/slr_strips.hpp).
    SlrStrips* strips() const { return m_strips; }

    /// Opens a CRD or O-C CSV with the CPF/SINEX chosen in the workspace; errors in a dialog.
    bool openPath(const QString& path, int passIndex, QString* error);
    /// Opens pass `index` of the open file (the pass list, Screen all passes) with progress and
    /// Cancel; false when it cannot be opened (shown in place) or was cancelled.
    bool switchToPass(int index);
    /// A simulated kHz pass of about `points` points (the demo, the latency benchmark).
    void openDemo(int points);
    static constexpr int kDemoPoints = 20000;  ///< the built-in demo's

    // Workspace
    QString key() const override { return QStringLiteral("slr"); }
    QString title() const override { return tr("SLR pass screening"); }
    void openDemo() override { openDemo(kDemoPoints); }
    void dropPrepared() override;
    QString demoSummary() const override { return tr("a simulated kHz pass"); }
    bool waitIdle(int timeoutMs) override { return m_controller->waitIdle(timeoutMs); }
    /// "slr" a pass (CRD, O-C table), "slr-cpf" a prediction, "slr-sinex" station coordinates,
    /// "slr-npt" a station's normal points (compared with the open pass).
    QString claim(const InputProbe& probe, bool current) const override;
    OpenOutcome openInputs(const QMap<QString, QStringList>& byRole, int pass) override;
    QList<QAction*> openActions() override;
    QStringList shortcutNotes() const override;
    /// laserwb-cli slr with the pass, the prediction, the station file and the last run's
    /// parameters (core slrCommandArgs); the box edits are not in it (*note says how many).
    QString commandLine(QString* note) const override;
    QString pythonScript(QString* note) const override;
    QString reportName() const override;
    bool writeReport(const QString& path, QString* error) const override;
    QString editsNote() const;  ///< what the command and the script cannot carry ("" when nothing)

    /// Session state: inputs, edits, and the parameters as slrSchema()'s JSON ("screen" and
    /// "postfit", every field).
    QJsonObject saveState() const override;

private:
    /// The Open button: a pass file chosen, opened through the window (openRequested).
    void choosePass();
    /// The prediction's and station file's names beside the Open buttons (m_cpfPath, m_snxPath).
    void showSourceNames();
    // The constructor's parts.
    QHBoxLayout* buildInputRow();
    void buildPlots();
    QWidget* buildPlotArea();
    QWidget* buildPanel();
    void wireController();

    void showRun(const SlrRun& run);
    void drawMainPlot(const SlrRun& run, bool residual);
    void drawImage(const SlrRun& run);
    void drawHistogram(const SlrRun& run);
    QString summaryHtml(const SlrRun& run) const;
    void showPass();
    QString passFileStem() const;
    void fillPassList();
    void applyTimeAxis();
    void fitMainPlot();
    void fitImagePlot();
    void pushForced(const std::vector<int8_t>& after, const QString& text);
    void linkRanges(QCustomPlot* from, QCustomPlot* to);
    void boxSelected(const QRect& rect);
    /// tuneFromFile and tuneFromFolder: core tuneSlr on `input` (a file or a folder), its dialog.
    QDialog* tuneOn(const QString& input, const QString& title);

    SlrController* m_controller;
    QCustomPlot *m_ocPlot, *m_imagePlot, *m_histPlot;
    QCPColorMap* m_imageMap;
    QCPItemText* m_histEmpty = nullptr;  ///< the histogram's "nothing kept" line
    QCPColorMap* m_imageBand;  ///< the track's band of O-C pixels unpooled, over m_imageMap (showRun)
    QComboBox* m_passCombo;
    SlrParamsPanel* m_params;
    QRadioButton *m_modeZoom, *m_modeIn, *m_modeOut;
    QPushButton *m_undo, *m_clearEdits;
    QLabel *m_info, *m_stats;
    ElidedLabel *m_cpfLabel, *m_snxLabel;
    QString m_path, m_cpfPath, m_snxPath;
    bool m_loading = false;
    bool m_openCancelled = false;  ///< the last pass read (readPass) was cancelled by the analyst
    std::optional<SlrOpening> m_preparedOpening;  ///< the pass a session's prepareState read, for its restore
    bool m_linking = false;
    bool m_imageFlattened = false;  ///< the binary image is of the flattened O-C (refinement)
    bool m_residual = false, m_secondsOfDay = false, m_applyingParams = false;
    QRadioButton* m_modeBoxZoom;
    QComboBox* m_viewCombo;
    QCheckBox* m_sodCheck;
    QToolButton *m_cpfClear, *m_snxClear;
    QLabel* m_hover;
    QVector<double> m_y;           ///< per point: the main plot's value (ns, or ps in the residual view)
    QVector<const char*> m_class;  ///< per point: its class in the last run
    /// The binary image drawn: its magnifications (a point's pixel centre is computed from them,
    /// imagePixelOf; two columns of them were 16 bytes an event of a kHz pass). 0: none drawn.
    double m_imgMagT = 0, m_imgMagOc = 0;
    QPointF imagePixelOf(size_t i) const;
    QPointer<SlrAllPassesDialog> m_all;
    SlrStationNpPanel* m_stationNps;
    QTabWidget* m_bottomTabs;
    SlrStrips* m_strips = nullptr;

    /// Reads `path` (block `passIndex`, -1 the first to screen) with the given prediction and
    /// station files, its O-C made with `params`' oc.* rows, on a worker with progress and
    /// Cancel; nothing shown changes. False with *error (the reader's, or cancelled).
    bool readPass(const QString& path, int passIndex, const QString& cpf, const QString& sinex, const core::slr::SlrParams& params,
                  SlrOpening* out, QString* error);
    /// prepareState's reading of a session's inputs (`params`: the session's): the pass (kept in
    /// m_preparedOpening), the manual edits against its points, the station's normal points.
    bool prepareInputs(const QJsonObject& state, const core::slr::SlrParams& params, QString* error);
    /// A session's manual edits ([point, 1 kept / 0 rejected], …) of a pass of `points` points;
    /// false with *error for a point beyond it.
    static bool readForcedEdits(const QJsonArray& forced, size_t points, std::vector<uint32_t>* in, std::vector<uint32_t>* out,
                                QString* error);
    struct SimulatedDemo {
        core::sim::SlrSimPass pass;
        double altitudeKm = 0;
    };
    static SimulatedDemo simulatedDemo(int points);

protected:
    /// restoreState, checkState and prepareState (Workspace) read the session state here:
    /// Restores a session. The parameters start from the defaults and every field given is read
    /// (Schema::fromJson: unknown keys and invalid values are errors naming the key, with the
    /// line and column when `doc`, the parsed session file, is given; `at` is this state's path
    /// in it). False with *error, nothing changed.
    bool readState(const QJsonObject& state, QString* error, const core::JsonParseResult* doc,
                   const std::vector<std::string>& at, StatePhase phase) override;
};

}  // namespace lwb::ui
