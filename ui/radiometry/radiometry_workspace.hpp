#pragma once
// The radiometry workspace (paper 003): the DN image or row mosaic with the picked regions,
// region picking (drag a rectangle, type the spectrometer's reflectance in the table), the
// V_REF = K·V_DN + B fit with K, B, their standard errors and the uncertainty, the reflectance
// image with its colour bar, and the relative errors of the check regions.

#include <QJsonObject>
#include <QWidget>
#include <functional>
#include <optional>

#include "ui/radiometry/radiometry_controller.hpp"
#include "ui/kit/workspace.hpp"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QRadioButton;
class QTableWidget;
class QCustomPlot;
class QFormLayout;
class QCPColorMap;
class QCPColorScale;

class QHBoxLayout;

namespace lwb::ui {

class RadiometryParamsPanel;

class RadiometryWorkspace : public Workspace {
    Q_OBJECT
public:
    explicit RadiometryWorkspace(QWidget* parent = nullptr);
    RadiometryController* controller() const { return m_controller; }

    /// The simulated field (six frames mosaicked in the background, grey panels, check surfaces).
    void openDemo() override;
    QJsonObject saveState() const override;

    // Workspace
    QString key() const override { return QStringLiteral("radiometry"); }
    QString title() const override { return tr("Radiometry"); }
    QString demoSummary() const override { return tr("a synthetic radiometric scene"); }
    bool waitIdle(int timeoutMs) override { return m_controller->waitIdle(timeoutMs); }
    void dropPrepared() override { m_preparedInput.reset(); }
    /// Images (PNG, TIFF, PGM) while it is in front: one image, or frames to mosaic.
    QString claim(const InputProbe& probe, bool current) const override;
    OpenOutcome openInputs(const QMap<QString, QStringList>& byRole, int pass) override;

    /// Adds a region drawn over `imageRect` (image pixels) as if the analyst had dragged it:
    /// the new row is selected and its reflectance cell opened for typing. Returns its index.
    int regionDrawn(const QRectF& imageRect, RegionRole role);

    // For tests and screenshots.
    QCustomPlot* dnPlot() const { return m_dnPlot; }
    QCustomPlot* reflectancePlot() const { return m_reflPlot; }
    QCustomPlot* fitPlot() const { return m_fitPlot; }
    QTableWidget* regionTable() const { return m_regionTable; }
    QTableWidget* errorTable() const { return m_errorTable; }
    QLabel* fitSummary() const { return m_fitSummary; }
    QDoubleSpinBox* vmField() const;
    RadiometryParamsPanel* paramsPanel() const { return m_params; }
    QRadioButton* drawFitButton() const { return m_modeFit; }
    QRadioButton* drawCheckButton() const { return m_modeCheck; }

private:
    /// Runs a region edit and makes it a step of the undo history (nothing when it changed nothing).
    void editRegions(const QString& what, const std::function<void()>& edit);
    // The constructor's parts.
    QHBoxLayout* buildInputRow();
    void buildImages();
    QWidget* buildRegionTable();
    QWidget* buildErrorColumn();

    void buildPanel(QWidget* panel);
    void showImage();
    QString readoutPrompt() const;
    void showRun(const RadiometryRun& run);
    void showOverlays();
    void refreshRegionTable();
    void showFit(const RadiometryRun& run);
    void showErrors(const RadiometryRun& run);
    void showReflectance(const RadiometryRun& run);
    void fitImage(QCustomPlot* plot);
    void alignImagePlots();
    void widgetsFromParams();
    void showError(const QString& title, const QString& message);
    void exportWith(const QString& title, const QString& filter,
                    bool (RadiometryController::*fn)(const QString&, QString*) const);
    int selectedRegion() const;

    RadiometryController* m_controller;
    std::optional<RadiometryInput> m_preparedInput;  ///< what a session's prepareState read, for its restore
    QCustomPlot *m_dnPlot, *m_reflPlot, *m_fitPlot;
    QCPColorMap *m_dnMap, *m_reflMap;
    QCPColorScale *m_dnScale, *m_reflScale;
    QTableWidget *m_regionTable, *m_errorTable;
    QLabel *m_info, *m_readout, *m_fitSummary, *m_errorSummary, *m_mosaicInfo;
    QRadioButton *m_modePan, *m_modeFit, *m_modeCheck;
    QComboBox *m_dnColors, *m_reflColors;
    RadiometryParamsPanel* m_params;
    bool m_tableUpdating = false;
    bool m_linking = false;

protected:
    /// restoreState, checkState and prepareState (Workspace) read the session state here:
    /// Validates everything first; on error (*error says what) the previous state stays.
    /// With `doc` (the parsed session) each message starts with the value's file:line:col; `at`
    /// is this state's path in it.
    bool readState(const QJsonObject& state, QString* error, const core::JsonParseResult* doc,
                   const std::vector<std::string>& at, StatePhase phase) override;
};

}  // namespace lwb::ui
