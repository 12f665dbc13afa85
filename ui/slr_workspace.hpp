#pragma once
// The SLR workspace: the O-C scatter beside its binary image (axes linked), the residual
// histogram, sliders for the screening parameters, box edits, presets and exports.
#include <QJsonObject>
#include <QWidget>

#include "ui/slr_controller.hpp"

class QComboBox;
class QCheckBox;
class QLabel;
class QPushButton;
class QRadioButton;
class QCustomPlot;
class QCPRange;
class QCPColorMap;

namespace lwb::ui {

class ParamSlider;

class SlrWorkspace : public QWidget {
    Q_OBJECT
public:
    explicit SlrWorkspace(QWidget* parent = nullptr);
    SlrController* controller() const { return m_controller; }
    ParamSlider* cosineSlider() const { return m_cosine; }
    ParamSlider* magOcSlider() const { return m_magOc; }
    ParamSlider* areaSlider() const { return m_area; }
    QCheckBox* autoCheck() const { return m_auto; }
    QCustomPlot* ocPlot() const { return m_ocPlot; }
    QCustomPlot* imagePlot() const { return m_imagePlot; }
    QLabel* infoLabel() const { return m_info; }  ///< the pass line and the readers' warnings

    /// Opens a CRD or O-C CSV with the CPF/SINEX chosen in the workspace; errors in a dialog.
    bool openPath(const QString& path, int passIndex, QString* error);
    /// A simulated kHz pass of about `points` points (the demo, the latency benchmark).
    void openDemo(int points = 20000);

    QJsonObject saveState() const;
    bool restoreState(const QJsonObject& state, QString* error);

signals:
    void modified();
    void status(const QString& message);

private:
    void showRun(const SlrRun& run);
    void paramsFromWidgets();
    void widgetsFromParams();
    void linkRanges(QCustomPlot* from, QCustomPlot* to);
    void boxSelected(const QRect& rect);
    void pickFile(QString* target, QLabel* label, const QString& title, const QString& filter);

    SlrController* m_controller;
    QCustomPlot *m_ocPlot, *m_imagePlot, *m_histPlot;
    QCPColorMap* m_imageMap;
    QComboBox *m_passCombo, *m_connectivity, *m_reject;
    QCheckBox* m_auto;
    ParamSlider *m_magT, *m_magOc, *m_area, *m_cosine, *m_degree;
    QRadioButton *m_modeZoom, *m_modeIn, *m_modeOut;
    QPushButton *m_undo, *m_clearEdits;
    QLabel *m_info, *m_stats, *m_cpfLabel, *m_snxLabel;
    QString m_path, m_cpfPath, m_snxPath;
    bool m_loading = false;
    bool m_linking = false;
    bool m_imageFlattened = false;  ///< the binary image is of the flattened O-C (refinement)
};

}  // namespace lwb::ui
