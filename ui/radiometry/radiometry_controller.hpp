#pragma once
// The radiometry workspace's controller (paper 003): the DN image (one file, a row mosaicked
// from frames, or the built-in simulated field with grey panels), the regions picked on it
// (rectangles with the spectrometer's reflectance; "fit" regions define V_REF = K·V_DN + B,
// "check" regions measure the relative error of the reflectance image), and the parameters.
// Widgets never call the core: the mosaic and the chain measure → fit → apply → check run on
// the thread pool, tagged with generation numbers; stale results are dropped.
#include <QJsonObject>
#include <QObject>
#include <QRect>
#include <QString>
#include <QStringList>
#include <memory>
#include <opencv2/core.hpp>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/radiometry/geotiff.hpp"
#include "core/radiometry/mosaic.hpp"
#include "core/radiometry/radiometry_params.hpp"
#include "core/radiometry/radiometry_run.hpp"
#include "core/radiometry/reflectance.hpp"

#include "ui/kit/task_job.hpp"

namespace lwb::ui {

enum class RegionRole { Fit, Check };
const char* regionRoleName(RegionRole r);
bool parseRegionRole(const QString& s, RegionRole* r);

/// A region as the analyst defined it.
struct PickedRegion {
    QString name;
    RegionRole role = RegionRole::Fit;
    QRect rect;                  ///< image pixels (x = column, y = row); empty when dn is given
    double reflectance = NAN;    ///< spectrometer reflectance (%); NaN = not entered yet
    double dn = NAN;             ///< mean DN given in a regions file without a rectangle
};

/// The parameters: one schema table (core::radiometry::radiometrySchema()).
using RadiometryParams = core::radiometry::RadiometryParams;
QString validateRadiometryParams(const RadiometryParams& p);
/// The session's parameter block: the schema's JSON (every field, always written).
QJsonObject radiometryParamsToJson(const RadiometryParams& p);
/// Through the schema: unknown keys, wrong types and invalid values are errors naming the key;
/// missing keys keep their defaults. With `doc` (the parsed session) a message starts with the
/// value's file:line:col; `at` is the block's path in the session.
bool radiometryParamsFromJson(const QJsonObject& o, RadiometryParams* p, QString* error, const core::JsonParseResult* doc = nullptr,
        const std::vector<std::string>& at = {});

/// The DN image and where it came from.
struct RadiometryImage {
    QString source;              ///< "demo", a file path, or empty
    QStringList frames;          ///< the frames of a mosaic (empty otherwise)
    cv::Mat dn;                  ///< as read / mosaicked (8U, 16U, 32F...)
    cv::Mat display;             ///< CV_32F copy for views and readouts
    cv::Mat coverage;            ///< CV_8U, 255 where the image has data
    std::vector<core::radiometry::PairRegistration> pairs;  ///< mosaic pairs (when mosaicked)
    std::vector<std::string> warnings;
    double demoK = NAN, demoB = NAN;  ///< demo: the simulated line V_REF = K·V_DN + B
    core::radiometry::GeoReference geo;  ///< a GeoTIFF's georeferencing (ground coordinates, m)
};

/// A DN image or a row's frames, read and not yet shown (RadiometryController::readInput).
struct RadiometryInput {
    std::shared_ptr<RadiometryImage> image;  ///< a DN image read, or
    std::vector<cv::Mat> frames;             ///< the frames of a row, read, to mosaic
    QStringList framePaths;
};

/// One run of measure → fit → apply → check.
struct RadiometryRun {
    quint64 generation = 0;
    std::vector<PickedRegion> regions;           ///< as used by this run
    std::vector<core::radiometry::Region> measured;  ///< same order: mean DN, σ, pixels
    std::vector<int> fitIndex;                   ///< region index of each fit input
    core::radiometry::ReflectanceFitResult fit;  ///< regions in fitIndex order
    QString error;                               ///< why there is no fit (or no image)
    core::radiometry::ApplyResult apply;         ///< reflectance (and uncertainty) image
    std::vector<int> checkIndex;                 ///< region index of each check row
    core::radiometry::RelativeErrorResult check;
    QString checkError;
    std::vector<QString> notes;                  ///< per region: why it is not in the fit, or doubts
    double latencyMs = 0;
};

class RadiometryController : public QObject {
    Q_OBJECT
public:
    explicit RadiometryController(QObject* parent = nullptr);
    ~RadiometryController() override;

    const RadiometryImage& image() const { return *m_image; }
    bool hasImage() const { return !m_image->dn.empty(); }
    const std::vector<PickedRegion>& regions() const { return m_regions; }
    const RadiometryParams& params() const { return m_params; }
    const RadiometryRun& run() const { return m_run; }
    bool hasRun() const { return m_run.generation != 0; }
    bool busy() const { return m_mosaicRunning || m_job.busy(); }

    /// The simulated field: six frames of a row with grey panels and check surfaces, mosaicked
    /// in the background; its panels and check regions become the regions.
    void openDemo();
    /// A DN image (PNG, TIFF, PGM; any depth). On error (naming the file) the image stays.
    bool openImage(const QString& path, QString* error);
    /// Frames of a row, in scan order: read at once (errors name the file), mosaicked in the
    /// background (a mosaic error is reported by mosaicFailed; the previous image stays).
    bool openFrames(const QStringList& paths, QString* error);
    /// openImage (`image` given) or openFrames (`frames`) in two steps: the files read and
    /// checked, nothing changed (false with *error naming the file); then shown, or mosaicked.
    static bool readInput(const QString& image, const QStringList& frames, RadiometryInput* out, QString* error);
    void adoptInput(RadiometryInput in);
    void cancelMosaic();
    /// No image (the regions stay).
    void clearImage();

    /// Regions from a CSV (calib fit/check format: name, reflectance, x, y, w, h or dn, and an
    /// optional role column fit/check). The file's regions replace those of `role` (or, with a
    /// role column, all regions). On error (file:line) the regions stay.
    bool openRegions(const QString& path, RegionRole role, QString* error);
    /// Replaces every region (sessions); false when one is invalid (the regions stay).
    bool setRegions(const std::vector<PickedRegion>& regions, QString* error);

    /// Adds a region; the rectangle is clipped to the image. Returns its index (−1 when the
    /// rectangle misses the image).
    int addRegion(const QString& name, const QRect& rect, double reflectance, RegionRole role = RegionRole::Fit);
    void removeRegion(int index);
    void setRegionReflectance(int index, double reflectance);
    void setRegionName(int index, const QString& name);
    void setRegionRole(int index, RegionRole role);
    void setRegionRect(int index, const QRect& rect);
    /// A name not used yet ("panel 7", "check 3").
    QString nextRegionName(RegionRole role) const;

    bool setParams(const RadiometryParams& p, QString* error = nullptr);

    // Exports (atomic). False with *error.
    bool exportFit(const QString& path, QString* error) const;              ///< radiometry fit -o
    bool exportRegions(const QString& path, QString* error) const;          ///< regions + results, re-readable
    bool exportRelativeErrors(const QString& path, QString* error) const;   ///< radiometry check -o
    bool exportReflectance(const QString& path, QString* error) const;      ///< 32-bit float TIFF
    bool exportUncertainty(const QString& path, QString* error) const;      ///< 32-bit float TIFF

    bool waitIdle(int timeoutMs);

signals:
    void imageChanged();
    void regionsChanged();
    void runReady(const lwb::ui::RadiometryRun& run);
    void mosaicProgress(double fraction);
    void mosaicFailed(const QString& message);
    void status(const QString& message);

private:
    void schedule() { m_job.schedule(); }
    void startMosaic(std::vector<cv::Mat> frames, const QStringList& paths, bool demo);
    void setImage(std::shared_ptr<const RadiometryImage> img);

    std::shared_ptr<const RadiometryImage> m_image;
    std::vector<PickedRegion> m_regions;
    RadiometryParams m_params;
    RadiometryRun m_run;
    TaskJob<core::radiometry::RadiometryTask> m_job;  // the live rerun of the core task (debounce, cancel, generation tag)
    std::vector<PickedRegion> m_runRegions;            // the regions of the run last started
    quint64 m_imageGeneration = 0;
    std::shared_ptr<core::Feedback> m_mosaicFeedback;
    bool m_mosaicRunning = false;
    bool m_keepRegionsOnDemo = false;  // a session restores its own regions over the demo's

public:
    /// For session restore: the next demo image keeps the current regions instead of its own.
    void keepRegionsForNextDemo() { m_keepRegionsOnDemo = true; }
};

}  // namespace lwb::ui

Q_DECLARE_METATYPE(lwb::ui::RadiometryRun)
