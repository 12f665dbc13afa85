#include "ui/radiometry/radiometry_workspace.hpp"

#include <QApplication>
#include <QButtonGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QRadioButton>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <qcustomplot.h>

#include <QUndoStack>
#include <QUndoCommand>
#include <QPointer>
#include <functional>
#include "ui/kit/save_path.hpp"
#include "ui/kit/app_undo.hpp"
#include "ui/calib/calib_params_panel.hpp"
#include "ui/kit/color_maps.hpp"
#include "ui/kit/plot_kit.hpp"
#include "ui/kit/session_json.hpp"
#include "ui/kit/workspace_layout.hpp"

namespace lwb::ui {

using namespace core::radiometry;

namespace {

const QColor kFitColor(0, 215, 255), kCheckColor(255, 140, 0), kBlue(31, 119, 180), kGrey(150, 150, 150),
    kRed(214, 39, 40), kGreenText(30, 120, 50);
constexpr int kMaxDisplayCells = 2400;  // per axis: larger images are shown area-averaged

// Fills a colour map from a CV_32F image (NaN where mask is 0), area-averaged when large.
void fillMap(QCPColorMap* map, const cv::Mat& img, const cv::Mat& mask) {
    if (img.empty()) {
        map->data()->clear();
        return;
    }
    cv::Mat show = img.clone();
    if (!mask.empty())
        for (int y = 0; y < show.rows; ++y) {
            float* r = show.ptr<float>(y);
            const uchar* m = mask.ptr<uchar>(y);
            for (int x = 0; x < show.cols; ++x)
                if (!m[x]) r[x] = NAN;
        }
    const int f = std::max(1, int(std::ceil(std::max(img.cols, img.rows) / double(kMaxDisplayCells))));
    if (f > 1) cv::resize(show, show, cv::Size(img.cols / f, img.rows / f), 0, 0, cv::INTER_AREA);
    map->data()->setSize(show.cols, show.rows);
    // Cell centres: pixel (x, y) of the image is at coordinate (x, y).
    map->data()->setRange(QCPRange(0.5 * (f - 1), 0.5 * (f - 1) + (show.cols - 1) * f),
                          QCPRange(0.5 * (f - 1), 0.5 * (f - 1) + (show.rows - 1) * f));
    for (int y = 0; y < show.rows; ++y) {
        const float* r = show.ptr<float>(y);
        for (int x = 0; x < show.cols; ++x) map->data()->setCell(x, y, r[x]);
    }
}

// 0.5–99.5 % of the finite pixels where mask is set.
QCPRange robustRange(const cv::Mat& img, const cv::Mat& mask) {
    std::vector<float> v;
    v.reserve(img.total());
    const int step = std::max(1, int(img.total() / 2000000));
    size_t k = 0;
    for (int y = 0; y < img.rows; ++y) {
        const float* r = img.ptr<float>(y);
        const uchar* m = mask.empty() ? nullptr : mask.ptr<uchar>(y);
        for (int x = 0; x < img.cols; ++x, ++k)
            if (k % step == 0 && std::isfinite(r[x]) && (!m || m[x])) v.push_back(r[x]);
    }
    if (v.empty()) return QCPRange(0, 1);
    const size_t lo = size_t(0.005 * (v.size() - 1)), hi = size_t(0.995 * (v.size() - 1));
    std::nth_element(v.begin(), v.begin() + lo, v.end());
    const double a = v[lo];
    std::nth_element(v.begin(), v.begin() + hi, v.end());
    const double b = v[hi];
    return b > a ? QCPRange(a, b) : QCPRange(a, a + 1);
}

QString num(double v, int decimals) { return std::isfinite(v) ? QString::number(v, 'f', decimals) : QString(); }

QTableWidgetItem* cell(const QString& text, bool editable = false, Qt::Alignment align = Qt::AlignRight | Qt::AlignVCenter) {
    auto* it = new QTableWidgetItem(text);
    it->setTextAlignment(align);
    Qt::ItemFlags f = Qt::ItemIsSelectable | Qt::ItemIsEnabled;
    if (editable) f |= Qt::ItemIsEditable;
    it->setFlags(f);
    return it;
}

// Refits an image plot to its window when resized (unless the analyst zoomed in); the fit is
// also the plot kit's home view.
class ImageFit : public QObject {
public:
    ImageFit(QCustomPlot* plot, std::function<void()> fit) : QObject(plot), m_plot(plot), m_fit(std::move(fit)) {
        plot->installEventFilter(this);
        PlotKitOptions o;
        o.home = [plot, f = m_fit] {
            plot->setProperty("zoomed", false);
            f();
        };
        installPlotKit(plot, o);
    }

protected:
    bool eventFilter(QObject* o, QEvent* e) override {
        if (o == m_plot && e->type() == QEvent::Resize)
            QMetaObject::invokeMethod(m_plot, [f = m_fit] { f(); }, Qt::QueuedConnection);
        if (o == m_plot && (e->type() == QEvent::Wheel || e->type() == QEvent::MouseMove)) {
            if (e->type() == QEvent::Wheel || (static_cast<QMouseEvent*>(e)->buttons() & Qt::LeftButton))
                if (m_plot->selectionRectMode() == QCP::srmNone) m_plot->setProperty("zoomed", true);
        }
        return false;
    }

private:
    QCustomPlot* m_plot;
    std::function<void()> m_fit;
};

enum RegionCol { ColName, ColRole, ColRefl, ColDn, ColPred, ColResid, ColNote, ColCount };

}  // namespace

RadiometryWorkspace::RadiometryWorkspace(QWidget* parent) : Workspace(parent) {
    m_controller = new RadiometryController(this);
    QHBoxLayout* top = buildInputRow();
    m_info = new QLabel(this);
    m_info->setProperty("showsData", true);  // results: the program's words with the data's and the core's
    m_info->setTextFormat(Qt::RichText);
    m_info->setForegroundRole(QPalette::PlaceholderText);

    buildImages();
    // Fit plot and tables.
    // (Short labels and legend entries: in a 1024 × 700 window the plot is about 240 × 190 px,
    // and the long ones took the axes' room, 1 entry a row.)
    m_fitPlot = newPlot(this, tr("Calibration line (eq. 5)"), tr("Region mean V_DN"), tr("V_REF (%)"));
    m_fitPlot->setToolTip(tr("Paper 003 eq. 5: the measured reflectance V_REF (%) of each region against its mean "
                             "DN V_DN, the fitted line V_REF = K·V_DN + B and its 1σ band"));
    m_fitPlot->setMinimumWidth(240);
    m_fitPlot->legend->setFont(QFont(font().family(), 8));
    m_fitPlot->legend->setIconSize(16, 8);
    m_fitPlot->legend->setRowSpacing(0);
    legendBelow(m_fitPlot, 2);
    m_fitSummary = new QLabel(this);
    m_fitSummary->setProperty("showsData", true);  // results: the program's words with the data's and the core's
    m_fitSummary->setWordWrap(true);
    m_fitSummary->setTextFormat(Qt::RichText);
    m_fitSummary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QWidget* regCol = buildRegionTable();
    QWidget* errCol = buildErrorColumn();

    auto* bottom = new QSplitter(Qt::Horizontal, this);
    bottom->addWidget(m_fitPlot);
    bottom->addWidget(regCol);
    bottom->addWidget(errCol);
    bottom->setStretchFactor(0, 4);
    bottom->setStretchFactor(1, 5);
    bottom->setStretchFactor(2, 4);
    bottom->setSizes({340, 450, 330});

    auto* images = new QWidget(this);
    auto* imgLay = new QVBoxLayout(images);
    imgLay->setContentsMargins(0, 0, 0, 0);
    imgLay->setSpacing(2);
    imgLay->addWidget(m_dnPlot, 1);
    imgLay->addWidget(m_reflPlot, 1);
    imgLay->addWidget(m_readout);
    auto* vsplit = new QSplitter(Qt::Vertical, this);
    vsplit->addWidget(images);
    vsplit->addWidget(bottom);
    vsplit->setStretchFactor(0, 3);
    vsplit->setStretchFactor(1, 2);
    vsplit->setSizes({520, 290});

    // Right: parameters.
    auto* panel = new QWidget(this);
    buildPanel(panel);
    layoutWorkspace(this, QStringLiteral("radiometry"), top, m_info, vsplit, panel, 300, 1150);

    // Wiring.
    connect(m_controller, &RadiometryController::imageChanged, this, &RadiometryWorkspace::showImage);
    // New data: the undo history refers to the image it was made on (the other workspaces' stay).
    connect(m_controller, &RadiometryController::imageChanged, this, [this] { undoStackOf(this).clear(); });
    // An undo or redo changes the work a session saves.
    connect(&undoStackOf(this), &QUndoStack::indexChanged, this, [this] {
        if (undoStackOf(this).count() > 0) emit modified();
    });
    connect(m_controller, &RadiometryController::regionsChanged, this, [this] {
        refreshRegionTable();
        showOverlays();
    });
    connect(m_controller, &RadiometryController::runReady, this, &RadiometryWorkspace::showRun);
    connect(m_controller, &RadiometryController::status, this, &RadiometryWorkspace::status);
    connect(m_controller, &RadiometryController::mosaicFailed, this,
            [this](const QString& m) { showError(tr("Cannot mosaic the frames"), m); });
    connect(m_controller, &RadiometryController::mosaicProgress, this,
            [this](double f) { emit status(tr("Mosaicking… %1 %").arg(int(100 * f))); });
    widgetsFromParams();
    showImage();
}

// Top: inputs, picking mode, exports.
QHBoxLayout* RadiometryWorkspace::buildInputRow() {
    auto* top = new QHBoxLayout;
    auto* demo = new QPushButton(tr("Demo"), this);
    demo->setToolTip(tr("A simulated field: six overlapping frames mosaicked, six grey panels, four check surfaces"));
    auto* openImg = new QPushButton(tr("DN image…"), this);
    openImg->setToolTip(tr("A single-channel DN image or mosaic (TIFF, PNG, PGM; any depth)"));
    auto* openFrames = new QPushButton(tr("Mosaic frames…"), this);
    openFrames->setToolTip(tr("The overlapping frames of one row, in scan order: stitched as radiometry mosaic does"));
    auto* openRegions = new QPushButton(tr("Regions…"), this);
    openRegions->setToolTip(tr("Fit regions CSV: name, reflectance (%), x, y, w, h (or dn) [, role fit/check]"));
    auto* openChecks = new QPushButton(tr("Check regions…"), this);
    openChecks->setToolTip(tr("Check regions CSV: name, reflectance (%), x, y, w, h"));
    m_modePan = new QRadioButton(tr("Pan / zoom"), this);
    m_modeFit = new QRadioButton(tr("Draw fit region"), this);
    m_modeCheck = new QRadioButton(tr("Draw check region"), this);
    m_modePan->setChecked(true);
    auto* modes = new QButtonGroup(this);
    for (QRadioButton* b : {m_modePan, m_modeFit, m_modeCheck}) modes->addButton(b);
    m_modeFit->setToolTip(tr("Drag a rectangle on the DN image over a grey panel, then type its measured reflectance"));
    m_modeCheck->setToolTip(tr("Drag a rectangle over a check surface, then type its measured reflectance"));
    auto* exportBtn = new QToolButton(this);
    exportBtn->setText(tr("Export"));
    exportBtn->setPopupMode(QToolButton::InstantPopup);
    auto* exportMenu = new QMenu(exportBtn);
    exportBtn->setMenu(exportMenu);
    for (QWidget* w : std::initializer_list<QWidget*>{demo, openImg, openFrames, openRegions, openChecks}) top->addWidget(w);
    top->addSpacing(16);
    for (QWidget* w : std::initializer_list<QWidget*>{m_modePan, m_modeFit, m_modeCheck}) top->addWidget(w);
    top->addStretch(1);
    top->addWidget(exportBtn);
    for (QRadioButton* b : {m_modePan, m_modeFit, m_modeCheck})
        connect(b, &QRadioButton::toggled, this, [this] {
            const bool draw = !m_modePan->isChecked();
            m_dnPlot->setSelectionRectMode(draw ? QCP::srmCustom : QCP::srmNone);
            const QColor c = m_modeCheck->isChecked() ? kCheckColor : kFitColor;
            m_dnPlot->selectionRect()->setPen(QPen(c, 1.5, Qt::DashLine));
            m_dnPlot->selectionRect()->setBrush(QColor(c.red(), c.green(), c.blue(), 40));
            m_dnPlot->setCursor(draw ? Qt::CrossCursor : Qt::ArrowCursor);
        });
    connect(demo, &QPushButton::clicked, this, [this] {
        openDemo();
        emit modified();
    });
    auto pick = [this](const QString& title, const QString& filter, bool many) {
        QSettings st;
        const QString dir = st.value("paths/radiometry").toString();
        QStringList paths = many ? QFileDialog::getOpenFileNames(this, title, dir, filter)
                                 : QStringList{QFileDialog::getOpenFileName(this, title, dir, filter)};
        paths.removeAll(QString());
        if (!paths.isEmpty()) st.setValue("paths/radiometry", QFileInfo(paths.first()).absolutePath());
        return paths;
    };
    const QString imageFilter = tr("Images (*.tif *.tiff *.png *.pgm);;All files (*)");
    const QString csv = tr("CSV (*.csv *.txt);;All files (*)");
    connect(openImg, &QPushButton::clicked, this, [=] {
        const QStringList p = pick(tr("Open a DN image"), imageFilter, false);
        if (p.isEmpty()) return;
        QString err;
        if (!m_controller->openImage(p.first(), &err)) showError(tr("Cannot open the image"), err);
        else emit modified();
    });
    connect(openFrames, &QPushButton::clicked, this, [=] {
        QStringList p = pick(tr("Frames of one row (in scan order)"), imageFilter, true);
        if (p.isEmpty()) return;
        std::sort(p.begin(), p.end());  // file names carry the scan order
        QString err;
        if (!m_controller->openFrames(p, &err)) showError(tr("Cannot mosaic the frames"), err);
        else emit modified();
    });
    connect(openRegions, &QPushButton::clicked, this, [=] {
        const QStringList p = pick(tr("Open fit regions"), csv, false);
        if (p.isEmpty()) return;
        QString err;
        bool ok = true;
        editRegions(tr("Open regions"), [&] { ok = m_controller->openRegions(p.first(), RegionRole::Fit, &err); });
        if (!ok) showError(tr("Cannot open the regions"), err);
        else emit modified();
    });
    connect(openChecks, &QPushButton::clicked, this, [=] {
        const QStringList p = pick(tr("Open check regions"), csv, false);
        if (p.isEmpty()) return;
        QString err;
        bool ok = true;
        editRegions(tr("Open check regions"), [&] { ok = m_controller->openRegions(p.first(), RegionRole::Check, &err); });
        if (!ok) showError(tr("Cannot open the check regions"), err);
        else emit modified();
    });
    const QString csvOut = tr("CSV (*.csv)"), tiff = tr("32-bit float TIFF (*.tif *.tiff)");
    exportMenu->addAction(tr("Reflectance image (TIFF)…"), this,
                          [=] { exportWith(tr("Export reflectance image"), tiff, &RadiometryController::exportReflectance); });
    exportMenu->addAction(tr("Uncertainty image (TIFF)…"), this,
                          [=] { exportWith(tr("Export uncertainty image"), tiff, &RadiometryController::exportUncertainty); });
    exportMenu->addAction(tr("Fit K, B (CSV)…"), this, [=] { exportWith(tr("Export fit"), csvOut, &RadiometryController::exportFit); });
    exportMenu->addAction(tr("Regions with results (CSV)…"), this,
                          [=] { exportWith(tr("Export regions"), csvOut, &RadiometryController::exportRegions); });
    exportMenu->addAction(tr("Relative errors (CSV)…"), this,
                          [=] { exportWith(tr("Export relative errors"), csvOut, &RadiometryController::exportRelativeErrors); });
    return top;
}

// The DN and reflectance images, their linked views, the region drawn with the mouse and the
// pixel readout.
void RadiometryWorkspace::buildImages() {
    m_dnPlot = newPlot(this, tr("DN image with the picked regions"), tr("Column (px)"), tr("Row (px)"));
    const ImageMap dn = addImageMap(m_dnPlot, tr("DN"), true);
    m_dnMap = dn.map;
    m_dnScale = dn.scale;
    m_dnMap->setName(tr("DN"));
    m_reflPlot = newPlot(this, tr("Reflectance image V_REF = K·V_DN + B"), tr("Column (px)"), tr("Row (px)"));
    const ImageMap refl = addImageMap(m_reflPlot, tr("Reflectance (%)"), true);
    m_reflMap = refl.map;
    m_reflScale = refl.scale;
    for (QCustomPlot* p : {m_dnPlot, m_reflPlot}) {
        p->setMinimumHeight(170);
        p->selectionRect()->setPen(QPen(kFitColor, 1.5, Qt::DashLine));
        p->selectionRect()->setBrush(QColor(0, 215, 255, 40));
        new ImageFit(p, [this, p] { fitImage(p); });
    }
    m_readout = new QLabel(readoutPrompt(), this);
    m_readout->setObjectName("readout");

    connect(m_dnPlot->selectionRect(), &QCPSelectionRect::accepted, this, [this](const QRect& r, QMouseEvent*) {
        const double x0 = m_dnPlot->xAxis->pixelToCoord(r.left()), x1 = m_dnPlot->xAxis->pixelToCoord(r.right());
        const double y0 = m_dnPlot->yAxis->pixelToCoord(r.top()), y1 = m_dnPlot->yAxis->pixelToCoord(r.bottom());
        regionDrawn(QRectF(QPointF(std::min(x0, x1), std::min(y0, y1)), QPointF(std::max(x0, x1), std::max(y0, y1))),
                    m_modeCheck->isChecked() ? RegionRole::Check : RegionRole::Fit);
    });
    // Both images show the same pixels: their x ranges follow each other.
    auto link = [this](QCustomPlot* from, QCustomPlot* to) {
        connect(from->xAxis, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, [this, from, to](const QCPRange& r) {
            if (m_linking) return;
            m_linking = true;
            to->xAxis->setRange(r);
            to->yAxis->setRange(from->yAxis->range().center(), to->yAxis->range().size(), Qt::AlignCenter);
            to->yAxis->setScaleRatio(to->xAxis, 1.0);
            to->setProperty("zoomed", from->property("zoomed"));
            to->replot(QCustomPlot::rpQueuedReplot);
            m_linking = false;
        });
    };
    link(m_dnPlot, m_reflPlot);
    link(m_reflPlot, m_dnPlot);
    for (QCustomPlot* p : {m_dnPlot, m_reflPlot})
        connect(p, &QCustomPlot::mouseMove, this, [this, p](QMouseEvent* e) {
            if (!m_controller->hasImage()) return;
            const int x = int(std::lround(p->xAxis->pixelToCoord(e->position().x())));
            const int y = int(std::lround(p->yAxis->pixelToCoord(e->position().y())));
            const cv::Mat& d = m_controller->image().display;
            if (x < 0 || y < 0 || x >= d.cols || y >= d.rows) return;
            QString t = tr("Pixel (%1, %2): %3 DN").arg(x).arg(y).arg(d.at<float>(y, x), 0, 'f', 0);
            if (const GeoReference& geo = m_controller->image().geo; geo.valid) {
                const cv::Point2d g = pixelCentreToMap(geo, x, y);
                t += tr(" · ground E %1 m, N %2 m").arg(g.x, 0, 'f', 3).arg(g.y, 0, 'f', 3);
            }
            const ApplyResult& a = m_controller->run().apply;
            if (a.ok && a.reflectance.size() == d.size()) {
                t += tr(" · reflectance %1 %").arg(a.reflectance.at<float>(y, x), 0, 'f', 3);
                if (!a.uncertainty.empty()) t += tr(" ± %1 %").arg(a.uncertainty.at<float>(y, x), 0, 'f', 3);
            }
            m_readout->setText(t);
        });
}

// The regions: their table (name, role, reflectance typed in, mean DN, line, residual), remove
// and fit ↔ check.
QWidget* RadiometryWorkspace::buildRegionTable() {
    auto* regCol = new QWidget(this);
    auto* regLay = new QVBoxLayout(regCol);
    regLay->setContentsMargins(0, 0, 0, 0);
    auto* regTitle = new QLabel(tr("<b>Regions</b> — type the spectrometer reflectance; drag on the DN image to add"), regCol);
    regTitle->setWordWrap(true);
    m_regionTable = new QTableWidget(regCol);
    m_regionTable->setColumnCount(ColCount);
    m_regionTable->setHorizontalHeaderLabels({tr("Name"), tr("Role"), tr("Refl. %"), tr("Mean DN"), tr("Line %"),
                                              tr("Resid. %"), tr("Note")});
    m_regionTable->verticalHeader()->hide();
    m_regionTable->verticalHeader()->setDefaultSectionSize(20);
    m_regionTable->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_regionTable->setSelectionMode(QAbstractItemView::SingleSelection);
    m_regionTable->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                                   QAbstractItemView::AnyKeyPressed);
    m_regionTable->horizontalHeader()->setMinimumSectionSize(36);
    const int widths[] = {80, 46, 58, 56, 56, 58};
    for (int c = 0; c < ColNote; ++c) m_regionTable->setColumnWidth(c, widths[c]);
    m_regionTable->horizontalHeader()->setSectionResizeMode(ColNote, QHeaderView::Stretch);
    m_regionTable->horizontalHeaderItem(ColRefl)->setToolTip(tr("Measured by the spectrometer (350–900 nm mean), %"));
    m_regionTable->horizontalHeaderItem(ColDn)->setToolTip(tr("Mean DN over the rectangle (V_DN); hover for its σ"));
    m_regionTable->horizontalHeaderItem(ColPred)->setToolTip(tr("The fitted line at the region's mean DN: K·V_DN + B (%)"));
    m_regionTable->horizontalHeaderItem(ColResid)->setToolTip(tr("Measured − line (%), fit regions"));
    m_regionTable->horizontalHeaderItem(ColName)->setToolTip(tr("Hover a name for its rectangle (image pixels)"));
    auto* regButtons = new QHBoxLayout;
    auto* remove = new QPushButton(tr("Remove region"), regCol);
    auto* toggleRole = new QPushButton(tr("Fit ↔ check"), regCol);
    regButtons->addWidget(remove);
    regButtons->addWidget(toggleRole);
    regButtons->addStretch(1);
    regLay->addWidget(regTitle);
    regLay->addWidget(m_regionTable, 1);
    regLay->addLayout(regButtons);

    connect(m_regionTable, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* it) {
        if (m_tableUpdating) return;
        const int row = it->row();
        if (it->column() == ColName) {
            const QString name = it->text().trimmed();
            editRegions(tr("Rename region"), [this, row, name] { m_controller->setRegionName(row, name); });
            emit modified();
        } else if (it->column() == ColRefl) {
            const QString t = it->text().trimmed().remove('%').trimmed();
            bool ok = false;
            const double v = t.isEmpty() ? NAN : QLocale().toDouble(t, &ok);
            const double v2 = ok || t.isEmpty() ? v : t.toDouble(&ok);
            if (!t.isEmpty() && (!ok || !std::isfinite(v2))) {
                emit status(tr("Reflectance of %1: \"%2\" is not a number").arg(m_controller->regions()[size_t(row)].name, t));
                refreshRegionTable();
                return;
            }
            editRegions(tr("Change reflectance"), [this, row, v2] { m_controller->setRegionReflectance(row, v2); });
            emit modified();
        }
    });
    connect(m_regionTable, &QTableWidget::itemSelectionChanged, this, [this] { showOverlays(); });
    connect(remove, &QPushButton::clicked, this, [this] {
        const int i = selectedRegion();
        if (i < 0) return;
        editRegions(tr("Remove region"), [this, i] { m_controller->removeRegion(i); });
        emit modified();
    });
    connect(toggleRole, &QPushButton::clicked, this, [this] {
        const int i = selectedRegion();
        if (i < 0) return;
        const RegionRole r = m_controller->regions()[size_t(i)].role;
        editRegions(tr("Change region role"),
                    [this, i, r] { m_controller->setRegionRole(i, r == RegionRole::Fit ? RegionRole::Check : RegionRole::Fit); });
        m_regionTable->selectRow(i);
        emit modified();
    });
    return regCol;
}

// The fit's summary and the relative errors of the check regions.
QWidget* RadiometryWorkspace::buildErrorColumn() {
    auto* errCol = new QWidget(this);
    auto* errLay = new QVBoxLayout(errCol);
    errLay->setContentsMargins(0, 0, 0, 0);
    auto* errTitle = new QLabel(tr("<b>Relative error of the check regions</b> (tables 5–7)"), errCol);
    errTitle->setWordWrap(true);
    m_errorTable = new QTableWidget(errCol);
    m_errorTable->setColumnCount(5);
    m_errorTable->setHorizontalHeaderLabels({tr("Region"), tr("Meas. %"), tr("Image %"), tr("Error %"), tr("OK")});
    m_errorTable->horizontalHeaderItem(1)->setToolTip(tr("Measured by the spectrometer (%)"));
    m_errorTable->horizontalHeaderItem(2)->setToolTip(tr("Mean of the reflectance image over the region (%)"));
    m_errorTable->horizontalHeaderItem(3)->setToolTip(tr("|image − measured| / measured × 100"));
    m_errorTable->horizontalHeaderItem(4)->setToolTip(tr("Relative error within the limit"));
    m_errorTable->verticalHeader()->hide();
    m_errorTable->verticalHeader()->setDefaultSectionSize(20);
    m_errorTable->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_errorTable->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_errorTable->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_errorSummary = new QLabel(errCol);
    m_errorSummary->setProperty("showsData", true);  // results: the program's words with the data's and the core's
    m_errorSummary->setWordWrap(true);
    m_errorSummary->setTextFormat(Qt::RichText);
    errLay->addWidget(m_fitSummary);
    errLay->addSpacing(4);
    errLay->addWidget(errTitle);
    errLay->addWidget(m_errorTable, 1);
    errLay->addWidget(m_errorSummary);

    return errCol;
}

void RadiometryWorkspace::buildPanel(QWidget* panel) {
    auto* pl = new QVBoxLayout(panel);
    pl->setContentsMargins(4, 4, 4, 4);
    m_params = new RadiometryParamsPanel(panel);
    pl->addWidget(m_params);
    m_mosaicInfo = new QLabel(panel);
    m_mosaicInfo->setWordWrap(true);
    m_mosaicInfo->setTextFormat(Qt::RichText);
    m_params->mosaicGroup()->addRow(m_mosaicInfo);
    bindParamsPanel(m_params, m_controller, this, tr("radiometry parameters"));
    auto* vg = new QGroupBox(tr("View"), panel);
    auto* vf = new QFormLayout(vg);
    m_dnColors = new QComboBox(vg);
    m_dnColors->addItems(colorMapNames());
    m_dnColors->setCurrentIndex(int(ColorMap::Gray));
    m_reflColors = new QComboBox(vg);
    m_reflColors->addItems(colorMapNames());
    m_reflColors->setCurrentIndex(int(ColorMap::Viridis));
    vf->addRow(tr("DN colours"), m_dnColors);
    vf->addRow(tr("Reflectance colours"), m_reflColors);
    auto* hint = new QLabel(tr("Wheel: zoom (Shift: x, Ctrl: y) · drag: pan · right-drag: box zoom · double-click: "
                               "whole image · right-click: export"),
                            vg);
    hint->setWordWrap(true);
    hint->setForegroundRole(QPalette::PlaceholderText);
    vf->addRow(hint);
    pl->addWidget(vg);
    pl->addStretch(1);

    connect(m_dnColors, &QComboBox::currentIndexChanged, this, [this] {
        showImage();
        emit modified();
    });
    connect(m_reflColors, &QComboBox::currentIndexChanged, this, [this] {
        if (m_controller->hasRun()) showReflectance(m_controller->run());
        emit modified();
    });
}

void RadiometryWorkspace::widgetsFromParams() { m_params->setParams(m_controller->params()); }

QDoubleSpinBox* RadiometryWorkspace::vmField() const { return m_params->field("vm_pct"); }

void RadiometryWorkspace::showError(const QString& title, const QString& message) {
    emit status(title + ": " + message);
    if (qApp->platformName() == "offscreen") {
        qWarning("%s: %s", qPrintable(title), qPrintable(message));
        return;
    }
    QMessageBox::warning(this, title, message);
}

void RadiometryWorkspace::exportWith(const QString& title, const QString& filter,
                                     bool (RadiometryController::*fn)(const QString&, QString*) const) {
    const QString path = askSavePath(this, title, "paths/radiometryExport", QString(), filter);
    if (path.isEmpty()) return;
    QString err;
    if (!(m_controller->*fn)(path, &err)) showError(title, err);
    else emit status(tr("Wrote %1").arg(path));
}

void RadiometryWorkspace::openDemo() { m_controller->openDemo(); }

int RadiometryWorkspace::selectedRegion() const {
    const auto rows = m_regionTable->selectionModel()->selectedRows();
    return rows.isEmpty() ? -1 : rows.first().row();
}

int RadiometryWorkspace::regionDrawn(const QRectF& r, RegionRole role) {
    // Pixel (x, y) covers x − 0.5 .. x + 0.5: the pixels whose centres the rectangle encloses.
    const int x0 = int(std::ceil(r.left() - 1e-9)), y0 = int(std::ceil(r.top() - 1e-9));
    const int x1 = int(std::floor(r.right() + 1e-9)), y1 = int(std::floor(r.bottom() + 1e-9));
    if (x1 < x0 || y1 < y0) {
        emit status(tr("The rectangle holds no pixel centre: drag a larger one"));
        return -1;
    }
    int i = -1;
    editRegions(tr("Add region"), [&] { i = m_controller->addRegion(QString(), QRect(QPoint(x0, y0), QPoint(x1, y1)), NAN, role); });
    if (i < 0) {
        emit status(tr("The rectangle misses the image"));
        return -1;
    }
    emit modified();
    m_regionTable->selectRow(i);
    if (QTableWidgetItem* it = m_regionTable->item(i, ColRefl)) {
        m_regionTable->setCurrentItem(it);
        m_regionTable->editItem(it);
    }
    emit status(tr("%1 added: type its measured reflectance (%)").arg(m_controller->regions()[size_t(i)].name));
    return i;
}

// ---------------------------------------------------------------------------------------------

void RadiometryWorkspace::alignImagePlots() {
    // The colour scales' tick labels differ in width ("25000" against "30"): widen the narrower
    // scale so both axis rects have the same width and the stacked images the same x scale.
    m_dnScale->setMinimumMargins(QMargins());
    m_reflScale->setMinimumMargins(QMargins());
    m_dnPlot->replot();
    m_reflPlot->replot();
    const int a = m_dnScale->outerRect().width(), b = m_reflScale->outerRect().width();
    if (a == b) return;
    QCPColorScale* narrow = a < b ? m_dnScale : m_reflScale;
    const int target = std::max(a, b);
    int extra = narrow->margins().right() + target - narrow->outerRect().width();
    for (int k = 0; k < 4; ++k) {  // the auto margin reacts to its floor: converge in a few steps
        narrow->setMinimumMargins(QMargins(0, 0, extra, 0));
        narrow->parentPlot()->replot();
        const int d = target - narrow->outerRect().width();
        if (d == 0) break;
        extra += d;
    }
}

void RadiometryWorkspace::fitImage(QCustomPlot* p) {
    const cv::Mat& d = m_controller->image().display;
    if (d.empty()) return;
    if (p->property("zoomed").toBool()) {
        p->yAxis->setScaleRatio(p->xAxis, 1.0);
        p->replot(QCustomPlot::rpQueuedReplot);
        return;
    }
    // The whole image in both views at one scale (one image pixel as wide as tall on screen),
    // so the DN and reflectance images stay aligned pixel for pixel.
    double s = 0;
    for (QCustomPlot* q : {m_dnPlot, m_reflPlot}) {
        q->replot();  // lays out the axes and the colour scale: the axis rect has its final size
        const QRect ar = q->axisRect()->rect();
        if (ar.width() < 10 || ar.height() < 10) return;
        s = std::max(s, std::max(d.cols / double(ar.width()), d.rows / double(ar.height())));
    }
    const double cx = 0.5 * (d.cols - 1), cy = 0.5 * (d.rows - 1);
    m_linking = true;
    for (QCustomPlot* q : {m_dnPlot, m_reflPlot}) {
        const QRect ar = q->axisRect()->rect();
        q->xAxis->setRange(cx - 0.5 * s * ar.width(), cx + 0.5 * s * ar.width());
        q->yAxis->setRange(cy - 0.5 * s * ar.height(), cy + 0.5 * s * ar.height());
        q->setProperty("zoomed", false);
        q->replot(QCustomPlot::rpQueuedReplot);
    }
    m_linking = false;
}

QString RadiometryWorkspace::readoutPrompt() const { return tr("Move the cursor over an image for its DN and reflectance"); }

void RadiometryWorkspace::showImage() {
    const RadiometryImage& img = m_controller->image();
    m_dnMap->setGradient(gradientFor(colorMapFromIndex(m_dnColors->currentIndex())));
    m_dnScale->setGradient(m_dnMap->gradient());
    fillMap(m_dnMap, img.display, img.coverage);
    if (!img.display.empty()) {
        const QCPRange r = robustRange(img.display, img.coverage);
        m_dnMap->setDataRange(r);
        m_dnScale->setDataRange(r);
    }
    QString src;
    if (img.source == "demo") src = tr("simulated field, mosaic of %1 frames").arg(img.pairs.size() + 1);
    else if (!img.frames.isEmpty()) src = tr("mosaic of %1 frames (%2 … %3)").arg(img.frames.size()).arg(QFileInfo(img.frames.first()).fileName(), QFileInfo(img.frames.last()).fileName());
    else if (!img.source.isEmpty()) src = QFileInfo(img.source).fileName();
    m_info->setText(img.dn.empty() ? tr("No image: open a DN image, mosaic frames, or the demo.")
                                   : tr("<b>Image</b> %1 · %2×%3 px, %4-bit%5")
                                         .arg(src.toHtmlEscaped())
                                         .arg(img.dn.cols)
                                         .arg(img.dn.rows)
                                         .arg(img.dn.depth() == CV_8U ? 8 : img.dn.depth() == CV_16U ? 16 : 32)
                                         .arg(std::isfinite(img.demoK)
                                                  ? tr(" · simulated line K = %1 %/DN, B = %2 %").arg(img.demoK).arg(img.demoB)
                                                  : QString()));
    if (img.geo.valid && !img.dn.empty()) {
        // Ground coordinates of the georeferenced image (GeoTIFF): its corners' pixel centres.
        const cv::Point2d tl = pixelCentreToMap(img.geo, 0, 0), br = pixelCentreToMap(img.geo, img.dn.cols - 1, img.dn.rows - 1);
        m_readout->setText(tr("Georeferenced: pixel %1 m; top-left pixel at E %2, N %3 m; bottom-right at E %4, N %5 m")
                               .arg(std::hypot(img.geo.transform[1], img.geo.transform[4]), 0, 'g', 4)
                               .arg(tl.x, 0, 'f', 3)
                               .arg(tl.y, 0, 'f', 3)
                               .arg(br.x, 0, 'f', 3)
                               .arg(br.y, 0, 'f', 3));
    } else {
        m_readout->setText(readoutPrompt());  // not the last image's pixel (it may not exist in this one)
    }
    QString mi;
    for (const auto& pr : img.pairs)
        mi += tr("frames %1–%2: %3/%4 inliers, RMS %5 px<br>")
                  .arg(pr.from + 1)
                  .arg(pr.to + 1)
                  .arg(pr.inliers)
                  .arg(pr.matches)
                  .arg(pr.rmsPx, 0, 'f', 2);
    for (const auto& w : img.warnings) mi += "<i>" + QString::fromStdString(w).toHtmlEscaped() + "</i><br>";
    m_mosaicInfo->setText(mi.isEmpty() ? tr("<i>no mosaic</i>") : mi);
    m_dnPlot->setProperty("zoomed", false);
    m_reflPlot->setProperty("zoomed", false);
    alignImagePlots();
    fitImage(m_dnPlot);
    showOverlays();
}

void RadiometryWorkspace::showOverlays() {
    const int sel = selectedRegion();
    const auto& regions = m_controller->regions();
    for (QCustomPlot* p : {m_dnPlot, m_reflPlot}) {
        p->clearItems();
        for (size_t i = 0; i < regions.size(); ++i) {
            const PickedRegion& r = regions[i];
            if (r.rect.isEmpty()) continue;
            const QColor c = r.role == RegionRole::Fit ? kFitColor : kCheckColor;
            const bool selected = int(i) == sel;
            auto* item = new QCPItemRect(p);
            item->topLeft->setCoords(r.rect.x() - 0.5, r.rect.y() - 0.5);
            item->bottomRight->setCoords(r.rect.x() + r.rect.width() - 0.5, r.rect.y() + r.rect.height() - 0.5);
            item->setPen(QPen(selected ? Qt::white : c, selected ? 2.6 : 1.6));
            item->setBrush(Qt::NoBrush);
            auto* label = new QCPItemText(p);
            label->position->setCoords(r.rect.x() - 0.5, r.rect.y() - 1.5);
            label->setPositionAlignment(Qt::AlignLeft | Qt::AlignBottom);
            label->setText(r.name);
            label->setColor(Qt::black);
            label->setBrush(QColor(c.red(), c.green(), c.blue(), selected ? 255 : 200));
            label->setPadding(QMargins(2, 0, 2, 0));
            QFont f = label->font();
            f.setPointSizeF(7.5);
            label->setFont(f);
            label->setClipToAxisRect(true);
        }
        p->replot(QCustomPlot::rpQueuedReplot);
    }
}

void RadiometryWorkspace::refreshRegionTable() {
    m_tableUpdating = true;
    const int sel = selectedRegion();
    const auto& regions = m_controller->regions();
    const RadiometryRun& run = m_controller->run();
    const bool runMatches = run.regions.size() == regions.size();
    m_regionTable->setRowCount(int(regions.size()));
    for (int i = 0; i < int(regions.size()); ++i) {
        const PickedRegion& r = regions[size_t(i)];
        // Items are updated in place (never replaced): this runs inside itemChanged of the cell
        // the analyst just edited.
        auto set = [&](int col, QTableWidgetItem* it) {
            QTableWidgetItem* old = m_regionTable->item(i, col);
            if (!old) {
                m_regionTable->setItem(i, col, it);
                return;
            }
            if (old->text() != it->text()) old->setText(it->text());
            if (old->flags() != it->flags()) old->setFlags(it->flags());
            if (old->toolTip() != it->toolTip()) old->setToolTip(it->toolTip());
            if (old->foreground() != it->foreground()) old->setForeground(it->foreground());
            if (old->textAlignment() != it->textAlignment()) old->setTextAlignment(Qt::Alignment(it->textAlignment()));
            delete it;
        };
        auto* name = cell(r.name, true, Qt::AlignLeft | Qt::AlignVCenter);
        name->setToolTip(r.rect.isEmpty() ? tr("mean DN given: %1").arg(r.dn)
                                          : tr("x %1, y %2, %3 × %4 px").arg(r.rect.x()).arg(r.rect.y()).arg(r.rect.width()).arg(r.rect.height()));
        set(ColName, name);
        auto* role = cell(r.role == RegionRole::Fit ? tr("fit") : tr("check"), false, Qt::AlignCenter);
        role->setForeground(r.role == RegionRole::Fit ? QColor(0, 120, 160) : QColor(190, 100, 0));
        set(ColRole, role);
        auto* refl = cell(std::isfinite(r.reflectance) ? QString::number(r.reflectance, 'g', 6) : QString(), true);
        if (!std::isfinite(r.reflectance)) refl->setToolTip(tr("Type the measured reflectance (%)"));
        set(ColRefl, refl);
        const Region* m = runMatches ? &run.measured[size_t(i)] : nullptr;
        auto* dn = cell(m ? num(m->dn, 0) : QString());
        if (m && std::isfinite(m->dnStd))
            dn->setToolTip(tr("σ %1 DN over %2 pixels%3")
                               .arg(m->dnStd, 0, 'f', 1)
                               .arg(m->pixels)
                               .arg(m->pixelsOutOfRange ? tr(", %1 outside the linear range").arg(m->pixelsOutOfRange) : QString()));
        set(ColDn, dn);
        double pred = NAN, resid = NAN;
        if (runMatches && run.fit.ok) {
            for (size_t j = 0; j < run.fitIndex.size(); ++j)
                if (run.fitIndex[j] == i) {
                    pred = run.fit.regions[j].predicted;
                    resid = run.fit.regions[j].residual;
                }
            if (r.role == RegionRole::Check && m && std::isfinite(m->dn)) pred = run.fit.fit.k * m->dn + run.fit.fit.b;
        }
        set(ColPred, cell(num(pred, 3)));
        set(ColResid, cell(num(resid, 3)));
        QString note = runMatches && size_t(i) < run.notes.size() ? run.notes[size_t(i)] : QString();
        auto* ni = cell(note, false, Qt::AlignLeft | Qt::AlignVCenter);
        ni->setToolTip(note);
        if (!note.isEmpty()) ni->setForeground(QColor(170, 90, 0));
        set(ColNote, ni);
    }
    if (sel >= 0 && sel < int(regions.size())) m_regionTable->selectRow(sel);
    m_tableUpdating = false;
}

void RadiometryWorkspace::showRun(const RadiometryRun& run) {
    refreshRegionTable();
    showFit(run);
    showErrors(run);
    showReflectance(run);
}

void RadiometryWorkspace::showFit(const RadiometryRun& run) {
    QCustomPlot* p = m_fitPlot;
    p->clearPlottables();
    const ReflectanceFitResult& f = run.fit;
    QVector<double> ux, uy, usd, ox, oy, cx, cy;
    double dnMax = 0;
    for (size_t j = 0; j < run.fitIndex.size(); ++j) {
        const Region& r = run.measured[size_t(run.fitIndex[j])];
        const bool used = !f.ok || j >= f.regions.size() || f.regions[j].used;
        (used ? ux : ox) << r.dn;
        (used ? uy : oy) << r.reflectance;
        if (used) usd << (std::isfinite(r.dnStd) ? r.dnStd : 0);
        dnMax = std::max(dnMax, r.dn);
    }
    for (size_t i = 0; i < run.regions.size(); ++i) {
        const Region& r = run.measured[i];
        if (run.regions[i].role != RegionRole::Check || !std::isfinite(r.dn) || !std::isfinite(r.reflectance)) continue;
        cx << r.dn;
        cy << r.reflectance;
        dnMax = std::max(dnMax, r.dn);
    }
    if (f.ok) {
        const ReflectanceFit& fit = f.fit;
        QVector<double> lx, ly, hi, lo;
        const double x1 = std::max(dnMax * 1.08, 1.0);
        for (int k = 0; k <= 60; ++k) {
            const double x = x1 * k / 60;
            const double y = fit.k * x + fit.b, u = predictionUncertaintyPct(fit, x);
            lx << x;
            ly << y;
            hi << y + u;
            lo << y - u;
        }
        QCPGraph* band = p->addGraph();
        band->setName(tr("±1σ (incl. V_M)"));
        band->setPen(QPen(QColor(120, 120, 120), 1, Qt::DashLine));
        band->setData(lx, hi);
        QCPGraph* band2 = p->addGraph();
        band2->setPen(QPen(QColor(120, 120, 120), 1, Qt::DashLine));
        band2->setData(lx, lo);
        band2->removeFromLegend();
        band->setBrush(QColor(120, 120, 120, 35));
        band->setChannelFillGraph(band2);
        QCPGraph* line = p->addGraph();
        line->setName(tr("K·V_DN + B"));
        line->setPen(QPen(Qt::black, 1.6));
        line->setData(lx, ly);
    }
    QCPGraph* used = p->addGraph();
    used->setName(tr("fit regions (%1)").arg(ux.size()));
    used->setLineStyle(QCPGraph::lsNone);
    used->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, kBlue, kBlue, 7));
    used->setData(ux, uy);
    if (!usd.isEmpty()) {
        auto* eb = new QCPErrorBars(p->xAxis, p->yAxis);
        eb->setDataPlottable(used);
        eb->setErrorType(QCPErrorBars::etKeyError);
        eb->setData(usd);
        eb->setPen(QPen(kBlue, 1));
        eb->removeFromLegend();
    }
    if (!ox.isEmpty()) {
        QCPGraph* out = p->addGraph();
        out->setName(tr("left out (range)"));
        out->setLineStyle(QCPGraph::lsNone);
        out->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(kRed, 1.5), Qt::NoBrush, 8));
        out->setData(ox, oy);
    }
    if (!cx.isEmpty()) {
        QCPGraph* chk = p->addGraph();
        chk->setName(tr("check (not fitted)"));
        chk->setLineStyle(QCPGraph::lsNone);
        chk->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDiamond, QPen(kCheckColor.darker(115), 1.6), Qt::NoBrush, 9));
        chk->setData(cx, cy);
    }
    p->rescaleAxes();
    p->xAxis->setRangeLower(0);
    p->xAxis->setRangeUpper(std::max(dnMax * 1.08, 1.0));
    const QCPRange yr = p->yAxis->range();
    p->yAxis->setRange(std::min(0.0, yr.lower - 0.05 * yr.size()), yr.upper + 0.08 * yr.size());
    p->replot(QCustomPlot::rpQueuedReplot);

    QString html;
    if (f.ok) {
        const ReflectanceFit& fit = f.fit;
        html = tr("<b>K</b> = %1 ± %2 %/DN<br><b>B</b> = %3 ± %4 %<br>"
                  "%5 regions · R² %6 · s %7 % · cov(K,B) %8<br>"
                  "<b>Uncertainty</b> (eq. 6) %9 % · at the mean DN %10: %11 %")
                   .arg(QString::number(fit.k, 'g', 6), QString::number(fit.kSd, 'g', 3), QString::number(fit.b, 'f', 4),
                        QString::number(fit.bSd, 'f', 4))
                   .arg(fit.n)
                   .arg(QString::number(fit.r2, 'f', 6), QString::number(fit.residualSd, 'f', 3), QString::number(fit.covKB, 'g', 2),
                        QString::number(fit.paperUncertaintyPct, 'f', 4), QString::number(fit.meanDn, 'f', 0),
                        QString::number(fit.uncertaintyAtMeanPct, 'f', 4));
        const RadiometryImage& img = m_controller->image();
        if (std::isfinite(img.demoK) && fit.kSd > 0)
            html += tr("<br><span style='color:#2c8c2c'>Simulated line: K %1 (fit − sim %2σ), B %3 (%4σ)</span>")
                        .arg(img.demoK)
                        .arg((fit.k - img.demoK) / fit.kSd, 0, 'f', 2)
                        .arg(img.demoB)
                        .arg((fit.b - img.demoB) / fit.bSd, 0, 'f', 2);
        for (const auto& w : f.warnings) html += "<br><i>" + QString::fromStdString(w).toHtmlEscaped() + "</i>";
    } else {
        html = tr("<span style='color:#c0392b'><b>No fit:</b> %1</span>").arg(run.error.toHtmlEscaped());
    }
    m_fitSummary->setText(html);
}

void RadiometryWorkspace::showErrors(const RadiometryRun& run) {
    m_errorTable->setRowCount(0);
    const RelativeErrorResult& c = run.check;
    if (!c.ok) {
        m_errorSummary->setText(run.checkError.isEmpty() ? QString()
                                                         : tr("<span style='color:#666'>%1</span>").arg(run.checkError.toHtmlEscaped()));
        return;
    }
    m_errorTable->setRowCount(int(c.rows.size()));
    for (int i = 0; i < int(c.rows.size()); ++i) {
        const RelativeErrorRow& r = c.rows[size_t(i)];
        m_errorTable->setItem(i, 0, cell(QString::fromStdString(r.name), false, Qt::AlignLeft | Qt::AlignVCenter));
        m_errorTable->setItem(i, 1, cell(num(r.measured, 3)));
        m_errorTable->setItem(i, 2, cell(num(r.simulated, 3)));
        m_errorTable->setItem(i, 3, cell(num(r.relativeErrorPct, 3)));
        auto* ok = cell(r.withinLimit ? tr("yes") : tr("NO"), false, Qt::AlignCenter);
        ok->setForeground(r.withinLimit ? kGreenText : kRed);
        m_errorTable->setItem(i, 4, ok);
    }
    QString html = tr("max %1 %, mean %2 % (limit %3 %): %4")
                       .arg(num(c.maxPct, 3), num(c.meanPct, 3), num(m_controller->params().limitPct, 2))
                       .arg(c.allWithinLimit ? tr("<span style='color:#1e7832'><b>all within</b></span>")
                                             : tr("<span style='color:#c0392b'><b>limit exceeded</b></span>"));
    for (const auto& w : c.warnings) html += "<br><i>" + QString::fromStdString(w).toHtmlEscaped() + "</i>";
    m_errorSummary->setText(html);
}

void RadiometryWorkspace::showReflectance(const RadiometryRun& run) {
    m_reflMap->setGradient(gradientFor(colorMapFromIndex(m_reflColors->currentIndex())));
    m_reflScale->setGradient(m_reflMap->gradient());
    const RadiometryImage& img = m_controller->image();
    if (run.apply.ok && run.apply.reflectance.size() == img.display.size()) {
        fillMap(m_reflMap, run.apply.reflectance, img.coverage);
        const QCPRange r = robustRange(run.apply.reflectance, img.coverage);
        m_reflMap->setDataRange(r);
        m_reflScale->setDataRange(r);
    } else {
        m_reflMap->data()->clear();
    }
    alignImagePlots();
    fitImage(m_dnPlot);
}

// ---------------------------------------------------------------------------------------------

QJsonObject RadiometryWorkspace::saveState() const {
    const RadiometryImage& img = m_controller->image();
    QJsonObject o;
    o["demo"] = img.source == "demo";
    o["image"] = img.frames.isEmpty() && img.source != "demo" ? img.source : QString();
    QJsonArray frames;
    for (const QString& f : img.frames) frames.append(f);
    o["frames"] = frames;
    QJsonArray regions;
    for (const PickedRegion& r : m_controller->regions()) {
        QJsonObject j;
        j["name"] = r.name;
        j["role"] = regionRoleName(r.role);
        j["reflectance"] = std::isfinite(r.reflectance) ? QJsonValue(r.reflectance) : QJsonValue();
        if (!r.rect.isEmpty()) j["rect"] = QJsonArray{r.rect.x(), r.rect.y(), r.rect.width(), r.rect.height()};
        else j["dn"] = r.dn;
        regions.append(j);
    }
    o["regions"] = regions;
    o["params"] = radiometryParamsToJson(m_controller->params());
    QJsonObject v;
    v["dn_colors"] = m_dnColors->currentIndex();
    v["reflectance_colors"] = m_reflColors->currentIndex();
    o["view"] = v;
    return o;
}

bool RadiometryWorkspace::readState(const QJsonObject& o, QString* error, const core::JsonParseResult* doc,
                                    const std::vector<std::string>& at, StatePhase phase) {
    // Each message starts with the session's file:line:col of the value when `doc` is given.
    auto where = [&](std::vector<std::string> rel) {
        rel.insert(rel.begin(), at.begin(), at.end());
        return QString::fromStdString(doc ? doc->where(rel) : std::string());
    };
    auto whereRegion = [&](int i, const char* key) {
        std::vector<std::string> rel = {"regions", "[" + std::to_string(i) + "]"};
        if (key) rel.push_back(key);
        return where(rel);
    };
    if (!checkSessionKeys(o, {"demo", "image", "frames", "regions", "params", "view"}, "radiometry", error, doc, at))
        return false;
    RadiometryParams p;
    QString err;
    std::vector<std::string> paramsAt = at;
    paramsAt.push_back("params");
    if (!radiometryParamsFromJson(o["params"].toObject(), &p, &err, doc, paramsAt)) {
        *error = err;
        return false;
    }
    std::vector<PickedRegion> regions;
    const QJsonArray ra = o["regions"].toArray();
    for (int i = 0; i < ra.size(); ++i) {
        const QJsonObject j = ra[i].toObject();
        PickedRegion r;
        r.name = j["name"].toString();
        if (!parseRegionRole(j["role"].toString(), &r.role)) {
            *error = whereRegion(i, "role") +
                     tr("radiometry region %1: role must be fit or check, not \"%2\"").arg(i + 1).arg(j["role"].toString());
            return false;
        }
        const QJsonValue refl = j["reflectance"];
        if (!refl.isNull() && !refl.isUndefined() && !refl.isDouble()) {
            *error = whereRegion(i, "reflectance") +
                     tr("radiometry region %1 (%2): reflectance must be a number or null").arg(i + 1).arg(r.name);
            return false;
        }
        r.reflectance = refl.isDouble() ? refl.toDouble() : NAN;
        if (j.contains("rect")) {
            const QJsonArray a = j["rect"].toArray();
            // Each a whole number up to a million pixels, so that x + w cannot overflow an int.
            auto coord = [&](int k, int lo) {
                const double v = a[k].toDouble(-1);
                return a[k].isDouble() && v == std::floor(v) && v >= lo && v <= 1e6;
            };
            if (a.size() != 4 || !coord(0, 0) || !coord(1, 0) || !coord(2, 1) || !coord(3, 1)) {
                *error = whereRegion(i, "rect") +
                         tr("radiometry region %1 (%2): rect must be [x, y, w, h], whole numbers with 0 ≤ x, y ≤ 1000000 "
                            "and 1 ≤ w, h ≤ 1000000")
                             .arg(i + 1)
                             .arg(r.name);
                return false;
            }
            r.rect = QRect(a[0].toInt(), a[1].toInt(), a[2].toInt(), a[3].toInt());
        } else if (j["dn"].isDouble()) {
            r.dn = j["dn"].toDouble();
        } else {
            *error = whereRegion(i, nullptr) +
                     tr("radiometry region %1 (%2): needs a rect or a dn").arg(i + 1).arg(r.name);
            return false;
        }
        regions.push_back(r);
    }
    const QJsonObject v = o["view"].toObject();
    const int dnc = v["dn_colors"].toInt(int(ColorMap::Gray)), rc = v["reflectance_colors"].toInt(int(ColorMap::Viridis));
    if (dnc < 0 || dnc >= m_dnColors->count() || rc < 0 || rc >= m_reflColors->count()) {
        *error = where({"view"}) + tr("radiometry view: colour map out of range");
        return false;
    }
    QStringList frames;
    for (const auto& f : o["frames"].toArray()) frames << f.toString();
    const QString image = o["image"].toString();
    const bool demo = o["demo"].toBool();
    if (frames.size() == 1) {
        *error = where({"frames"}) + tr("radiometry frames: a mosaic needs at least two frames");
        return false;
    }
    if (phase == StatePhase::Check) return true;  // (nothing above changes the workspace)
    // The image or the frames: read when prepared (and kept for the restore), else now.
    const bool readsInput = !image.isEmpty() || frames.size() >= 2;
    auto preparedIsThis = [&] {
        return m_preparedInput && (m_preparedInput->image ? m_preparedInput->image->source == image
                                                        : image.isEmpty() && m_preparedInput->framePaths == frames);
    };
    if (readsInput && (phase == StatePhase::Prepare || !preparedIsThis())) {
        RadiometryInput read;
        if (!RadiometryController::readInput(image, frames, &read, error)) return false;
        m_preparedInput = std::move(read);
    }
    if (phase == StatePhase::Prepare) return true;
    // A mosaic runs in the background with the restored mosaic parameters.
    m_controller->setParams(p);
    if (readsInput) {
        m_controller->adoptInput(std::move(*m_preparedInput));
        m_preparedInput.reset();
    } else if (!demo) {
        m_controller->clearImage();
    }
    m_controller->setRegions(regions, &err);
    if (demo) {
        m_controller->keepRegionsForNextDemo();
        m_controller->openDemo();
    }
    widgetsFromParams();
    m_dnColors->setCurrentIndex(dnc);
    m_reflColors->setCurrentIndex(rc);
    return true;
}

namespace {
bool sameRegions(const std::vector<PickedRegion>& a, const std::vector<PickedRegion>& b) {
    auto same = [](double x, double y) { return (std::isnan(x) && std::isnan(y)) || x == y; };
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].name != b[i].name || a[i].role != b[i].role || a[i].rect != b[i].rect ||
            !same(a[i].reflectance, b[i].reflectance) || !same(a[i].dn, b[i].dn))
            return false;
    return true;
}

// One region edit (drawn, removed, renamed, its reflectance or role changed, a regions file read)
// as a step of the workspace's undo history: the regions before and after it.
class RegionsCommand : public QUndoCommand {
public:
    RegionsCommand(RadiometryController* c, std::vector<PickedRegion> before, std::vector<PickedRegion> after, const QString& what)
        : QUndoCommand(what), m_c(c), m_before(std::move(before)), m_after(std::move(after)) {}
    void undo() override { put(m_before); }
    void redo() override {
        if (m_first) m_first = false;  // (the edit itself was the first redo)
        else put(m_after);
    }

private:
    void put(const std::vector<PickedRegion>& r) {
        QString ignored;
        if (m_c) m_c->setRegions(r, &ignored);
    }
    QPointer<RadiometryController> m_c;
    std::vector<PickedRegion> m_before, m_after;
    bool m_first = true;
};
}  // namespace

void RadiometryWorkspace::editRegions(const QString& what, const std::function<void()>& edit) {
    const std::vector<PickedRegion> before = m_controller->regions();
    edit();
    if (sameRegions(before, m_controller->regions())) return;
    undoStackOf(this).push(new RegionsCommand(m_controller, before, m_controller->regions(), what));
    emit modified();
}

QString RadiometryWorkspace::claim(const InputProbe& probe, bool current) const {
    static const QStringList images = {"png", "tif", "tiff", "pgm"};
    return current && !probe.isDir && !probe.gz && images.contains(probe.suffix) ? key() : QString();
}

OpenOutcome RadiometryWorkspace::openInputs(const QMap<QString, QStringList>& byRole, int) {
    OpenOutcome out;
    QStringList images = byRole.value(key());
    if (images.isEmpty()) return out;
    std::sort(images.begin(), images.end());  // file names carry the scan order
    QString err;
    if (images.size() == 1 && QFileInfo(images.first()).isDir()) {  // a recent entry of several frames
        out.problems << tr("%1: a folder of frames; open them with Mosaic frames…").arg(images.first());
        return out;
    }
    const bool ok = images.size() == 1 ? m_controller->openImage(images.first(), &err) : m_controller->openFrames(images, &err);
    if (!ok) {
        out.problems << err;
        return out;
    }
    out.opened = out.replaced = true;
    out.recentPath = images.size() == 1 ? images.first() : QFileInfo(images.first()).absolutePath();
    return out;
}

}  // namespace lwb::ui
