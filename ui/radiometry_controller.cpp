#include "ui/radiometry_controller.hpp"

#include <QCoreApplication>
#include <QDateTime>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QPointer>
#include <QThreadPool>
#include <QtConcurrent>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"
#include "core/sim/rng.hpp"
#include "core/sim/scene_sim.hpp"

namespace lwb::ui {

using namespace core::radiometry;
namespace sim = core::sim;

namespace {

bool fail(QString* error, const QString& msg) {
    if (error) *error = msg;
    return false;
}
bool fail(QString* error, const std::string& msg) { return fail(error, QString::fromStdString(msg)); }

std::string gx(double v) { return std::isfinite(v) ? core::formatDouble(v, 10) : std::string(); }

// ---------------------------------------------------------------------------------------------
// The demo field: a textured ground (scene_sim) with six grey panels of known reflectance for
// the fit and four check surfaces, photographed as six overlapping frames of one row.

// Paper 003's line (cement 1 image): V_REF = 0.00126·V_DN − 4.32576, reflectance in %.
constexpr double kDemoK = 0.00126, kDemoB = -4.32576;
constexpr uint64_t kDemoSeed = 20230901;

struct DemoField {
    std::vector<cv::Mat> frames;
    cv::Point frame0;                    ///< scene position of frame 0's pixel (0, 0)
    std::vector<PickedRegion> regions;   ///< rectangles in scene pixels
};

DemoField makeDemoField() {
    DemoField f;
    sim::RowFramesParams rp;             // 6 frames of 400×360 px, 1/4 overlap (paper 003)
    const int step = int(std::lround(rp.frameWidth * (1 - rp.overlap)));
    const int margin = rp.jitterPx + 2;
    sim::SceneSimParams sp;
    sp.width = (rp.frames - 1) * step + rp.frameWidth + 2 * margin;
    sp.height = rp.frameHeight + 2 * margin;
    cv::Mat scene = sim::simulateScene(sp, kDemoSeed);
    sim::Rng rng(sim::Rng::mix(kDemoSeed, 7));
    auto dnOf = [](double reflectance) { return (reflectance - kDemoB) / kDemoK; };
    // Grey panels: uniform to 0.3 %, measured by the spectrometer to ±0.15 % reflectance.
    const double panels[] = {4.8, 10.3, 19.7, 30.4, 44.6, 62.1};
    for (int i = 0; i < 6; ++i) {
        // In the middle of frame i, away from the overlaps the mosaic registers on; small enough
        // (< 0.5 % of the pixels each) not to set the mosaic's 8-bit contrast stretch.
        const cv::Rect r(margin + i * step + 184, margin + 60, 32, 32);
        const double level = dnOf(panels[i]);
        for (int y = r.y; y < r.y + r.height; ++y)
            for (int x = r.x; x < r.x + r.width; ++x) scene.at<float>(y, x) = float(level * (1 + 0.003 * rng.normal()));
        PickedRegion pr;
        pr.name = QString("panel %1 %").arg(panels[i], 0, 'f', 0);
        pr.role = RegionRole::Fit;
        pr.rect = QRect(r.x + 5, r.y + 5, r.width - 10, r.height - 10);
        pr.reflectance = std::round((panels[i] + 0.15 * rng.normal()) * 1000) / 1000;
        f.regions.push_back(pr);
    }
    // Check surfaces: textured (σ 3 % of the level, 2 px grain), measured to ±1 %.
    const struct {
        const char* name;
        double r;
        int frame;
    } checks[] = {{"cement 1", 27.4, 1}, {"lawn", 8.6, 2}, {"cement 2", 31.2, 3}, {"asphalt", 11.9, 4}};
    for (const auto& c : checks) {
        const cv::Rect r(margin + c.frame * step + 140, margin + 200, 120, 90);
        cv::Mat tex(r.size(), CV_32F);
        for (int y = 0; y < tex.rows; ++y)
            for (int x = 0; x < tex.cols; ++x) tex.at<float>(y, x) = float(rng.normal());
        cv::GaussianBlur(tex, tex, cv::Size(0, 0), 2.0);
        cv::Scalar m, s;
        cv::meanStdDev(tex, m, s);
        const double level = dnOf(c.r);
        cv::Mat patch = scene(r);
        for (int y = 0; y < r.height; ++y)
            for (int x = 0; x < r.width; ++x)
                patch.at<float>(y, x) = float(level * (1 + 0.03 * (tex.at<float>(y, x) - m[0]) / std::max(s[0], 1e-9)));
        PickedRegion pr;
        pr.name = c.name;
        pr.role = RegionRole::Check;
        pr.rect = QRect(r.x + 10, r.y + 10, r.width - 20, r.height - 20);
        pr.reflectance = std::round(c.r * (1 + 0.01 * rng.normal()) * 1000) / 1000;
        f.regions.push_back(pr);
    }
    // The frames: jittered offsets along the row, 30 DN of noise each, 16-bit.
    for (int k = 0; k < rp.frames; ++k) {
        const int jx = int(std::lround(rng.uniform(-rp.jitterPx, rp.jitterPx)));
        const int jy = int(std::lround(rng.uniform(-rp.jitterPx, rp.jitterPx)));
        const cv::Point o(margin + k * step + jx, margin + jy);
        if (k == 0) f.frame0 = o;
        cv::Mat fr = scene(cv::Rect(o, cv::Size(rp.frameWidth, rp.frameHeight))).clone();
        for (int y = 0; y < fr.rows; ++y)
            for (int x = 0; x < fr.cols; ++x) fr.at<float>(y, x) += float(rng.normal(0, rp.noiseDn));
        cv::Mat g;
        fr.convertTo(g, CV_16U);
        f.frames.push_back(g);
    }
    return f;
}

std::shared_ptr<RadiometryImage> imageFrom(const cv::Mat& dn, const cv::Mat& coverage) {
    auto img = std::make_shared<RadiometryImage>();
    img->dn = dn;
    dn.convertTo(img->display, CV_32F);
    img->coverage = coverage.empty() ? cv::Mat(dn.size(), CV_8U, cv::Scalar(255)) : coverage;
    return img;
}

// ---------------------------------------------------------------------------------------------
// measure → fit → apply → check

RadiometryRun compute(std::shared_ptr<const RadiometryImage> img, const std::vector<PickedRegion>& regions,
                      const RadiometryParams& p) {
    RadiometryRun run;
    run.regions = regions;
    run.notes.assign(regions.size(), QString());
    run.measured.resize(regions.size());
    const bool haveImage = img && !img->dn.empty();
    const cv::Rect bounds = haveImage ? cv::Rect(0, 0, img->dn.cols, img->dn.rows) : cv::Rect();
    // Measure every rectangle that lies inside the image in one pass.
    std::vector<Region> toMeasure;
    std::vector<size_t> measuredIndex;
    for (size_t i = 0; i < regions.size(); ++i) {
        const PickedRegion& pr = regions[i];
        Region& r = run.measured[i];
        r.name = pr.name.toStdString();
        r.reflectance = pr.reflectance;
        r.dn = pr.dn;
        if (pr.rect.isEmpty()) {
            if (!std::isfinite(pr.dn)) run.notes[i] = QObject::tr("no rectangle and no DN");
            continue;
        }
        r.rect = cv::Rect(pr.rect.x(), pr.rect.y(), pr.rect.width(), pr.rect.height());
        r.dn = NAN;
        if (!haveImage) {
            run.notes[i] = QObject::tr("no image to measure on");
            continue;
        }
        if ((r.rect & bounds) != r.rect) {
            run.notes[i] = QObject::tr("rectangle leaves the %1×%2 image").arg(bounds.width).arg(bounds.height);
            continue;
        }
        toMeasure.push_back(r);
        measuredIndex.push_back(i);
    }
    if (!toMeasure.empty()) {
        std::string err;
        if (measureRegionDn(img->dn, p.fit, &toMeasure, &err)) {
            for (size_t j = 0; j < toMeasure.size(); ++j) run.measured[measuredIndex[j]] = toMeasure[j];
        } else {
            run.error = QString::fromStdString(err);
        }
    }
    // Fit over the fit regions that have a reflectance and a DN.
    std::vector<Region> fitRegions;
    for (size_t i = 0; i < regions.size(); ++i) {
        if (regions[i].role != RegionRole::Fit) continue;
        const Region& r = run.measured[i];
        if (!std::isfinite(r.reflectance)) {
            if (run.notes[i].isEmpty()) run.notes[i] = QObject::tr("enter the measured reflectance");
            continue;
        }
        if (!std::isfinite(r.dn)) continue;
        fitRegions.push_back(r);
        run.fitIndex.push_back(int(i));
    }
    if (run.error.isEmpty()) {
        run.fit = fitReflectance(fitRegions, p.fit);
        if (!run.fit.ok) run.error = QString::fromStdString(run.fit.error);
        for (size_t j = 0; j < run.fit.regions.size() && j < run.fitIndex.size(); ++j)
            if (!run.fit.regions[j].note.empty()) run.notes[size_t(run.fitIndex[j])] = QString::fromStdString(run.fit.regions[j].note);
    }
    if (!run.fit.ok) return run;
    if (haveImage) {
        ApplyParams ap;
        ap.dnMin = p.fit.dnMin;
        ap.dnMax = p.fit.dnMax;
        ap.outOfRangeToNan = p.outOfRangeToNan;
        ap.uncertaintyImage = p.uncertaintyImage;
        run.apply = applyReflectance(img->dn, run.fit.fit, ap);
        if (!run.apply.ok) run.error = QString::fromStdString(run.apply.error);
    }
    // Relative errors of the check regions: over their rectangle on the reflectance image, or
    // K·DN + B for regions given by their DN alone.
    std::vector<Region> checks;
    for (size_t i = 0; i < regions.size(); ++i) {
        if (regions[i].role != RegionRole::Check) continue;
        Region r = run.measured[i];
        if (!(std::isfinite(r.reflectance) && r.reflectance > 0)) {
            if (run.notes[i].isEmpty()) run.notes[i] = QObject::tr("enter the measured reflectance (> 0 %)");
            continue;
        }
        if (!r.rect.empty() && !std::isfinite(r.dn)) continue;  // outside the image: noted above
        if (r.rect.empty() || !run.apply.ok) {
            if (!std::isfinite(r.dn)) continue;
            r.rect = cv::Rect();
            r.simulated = run.fit.fit.k * r.dn + run.fit.fit.b;
        }
        checks.push_back(r);
        run.checkIndex.push_back(int(i));
    }
    if (checks.empty()) {
        run.checkError = QObject::tr("no check regions with a measured reflectance");
    } else {
        run.check = relativeErrors(checks, run.apply.ok ? &run.apply.reflectance : nullptr, p.limitPct);
        if (!run.check.ok) run.checkError = QString::fromStdString(run.check.error);
    }
    return run;
}

}  // namespace

const char* regionRoleName(RegionRole r) { return r == RegionRole::Check ? "check" : "fit"; }

bool parseRegionRole(const QString& s, RegionRole* r) {
    const QString t = s.trimmed().toLower();
    if (t == "fit" || t.isEmpty()) *r = RegionRole::Fit;
    else if (t == "check") *r = RegionRole::Check;
    else return false;
    return true;
}

QString validateRadiometryParams(const RadiometryParams& p) {
    if (std::string e = validate(p.fit); !e.empty()) return QObject::tr("reflectance fit: %1").arg(QString::fromStdString(e));
    if (std::string e = validate(p.mosaic); !e.empty()) return QObject::tr("mosaic: %1").arg(QString::fromStdString(e));
    if (!(p.limitPct > 0 && p.limitPct <= 1000)) return QObject::tr("the relative-error limit must be within 0..1000 %");
    return {};
}

QJsonObject radiometryParamsToJson(const RadiometryParams& p) {
    QJsonObject o;
    o["dn_min"] = p.fit.dnMin;
    o["dn_max"] = p.fit.dnMax;
    o["exclude_out_of_range"] = p.fit.excludeOutOfRange;
    o["vm_pct"] = p.fit.spectrometerPct;
    o["nan_out_of_range"] = p.outOfRangeToNan;
    o["uncertainty_image"] = p.uncertaintyImage;
    o["limit_pct"] = p.limitPct;
    QJsonObject m;
    m["features"] = featureTypeName(p.mosaic.features);
    m["model"] = motionModelName(p.mosaic.model);
    m["blend"] = blendModeName(p.mosaic.blend);
    m["ransac_px"] = p.mosaic.ransacThresholdPx;
    m["min_inliers"] = p.mosaic.minInliers;
    o["mosaic"] = m;
    return o;
}

bool radiometryParamsFromJson(const QJsonObject& o, RadiometryParams* out, QString* error) {
    RadiometryParams p;
    auto num = [&](const QJsonObject& obj, const char* key, double* v) {
        if (!obj.contains(key)) return true;
        if (!obj[key].isDouble()) return fail(error, QObject::tr("radiometry parameter %1 must be a number").arg(key));
        *v = obj[key].toDouble();
        return true;
    };
    auto flag = [&](const QJsonObject& obj, const char* key, bool* v) {
        if (!obj.contains(key)) return true;
        if (!obj[key].isBool()) return fail(error, QObject::tr("radiometry parameter %1 must be true or false").arg(key));
        *v = obj[key].toBool();
        return true;
    };
    const QJsonObject m = o["mosaic"].toObject();
    double minInliers = p.mosaic.minInliers;
    if (!num(o, "dn_min", &p.fit.dnMin) || !num(o, "dn_max", &p.fit.dnMax) ||
        !flag(o, "exclude_out_of_range", &p.fit.excludeOutOfRange) || !num(o, "vm_pct", &p.fit.spectrometerPct) ||
        !flag(o, "nan_out_of_range", &p.outOfRangeToNan) || !flag(o, "uncertainty_image", &p.uncertaintyImage) ||
        !num(o, "limit_pct", &p.limitPct) || !num(m, "ransac_px", &p.mosaic.ransacThresholdPx) ||
        !num(m, "min_inliers", &minInliers))
        return false;
    if (minInliers != std::floor(minInliers) || std::fabs(minInliers) > 1e9)  // before the int conversion
        return fail(error, QObject::tr("radiometry parameter min_inliers must be a whole number, not %1").arg(minInliers));
    p.mosaic.minInliers = int(minInliers);
    if (m.contains("features") && !parseFeatureType(m["features"].toString().toStdString(), &p.mosaic.features))
        return fail(error, QObject::tr("mosaic features must be akaze or orb, not \"%1\"").arg(m["features"].toString()));
    if (m.contains("model") && !parseMotionModel(m["model"].toString().toStdString(), &p.mosaic.model))
        return fail(error, QObject::tr("mosaic model: unknown \"%1\"").arg(m["model"].toString()));
    if (m.contains("blend") && !parseBlendMode(m["blend"].toString().toStdString(), &p.mosaic.blend))
        return fail(error, QObject::tr("mosaic blend: unknown \"%1\"").arg(m["blend"].toString()));
    if (const QString e = validateRadiometryParams(p); !e.isEmpty()) return fail(error, e);
    *out = p;
    return true;
}

// ---------------------------------------------------------------------------------------------

RadiometryController::RadiometryController(QObject* parent)
    : QObject(parent), m_image(std::make_shared<RadiometryImage>()) {
    qRegisterMetaType<lwb::ui::RadiometryRun>();
    m_job.setWork<RadiometryRun>(
        [this]() -> std::function<RadiometryRun(core::Feedback&)> {
            if (m_mosaicRunning) return {};  // the new image schedules a run when it arrives
            const std::shared_ptr<const RadiometryImage> img = m_image;
            const std::vector<PickedRegion> regions = m_regions;
            const RadiometryParams params = m_params;
            return [img, regions, params](core::Feedback&) { return compute(img, regions, params); };
        },
        [this](RadiometryRun run) {
            run.generation = m_job.generation();
            run.latencyMs = double(QDateTime::currentMSecsSinceEpoch() - m_job.changedAt());
            m_run = std::move(run);
            emit runReady(m_run);
        });
}

RadiometryController::~RadiometryController() {
    m_job.cancel();
    ++m_imageGeneration;
    if (m_mosaicFeedback) m_mosaicFeedback->cancel();
    QThreadPool::globalInstance()->waitForDone(10000);
}

void RadiometryController::setImage(std::shared_ptr<const RadiometryImage> img) {
    m_image = std::move(img);
    emit imageChanged();
    schedule();
}

void RadiometryController::openDemo() {
    startMosaic({}, {}, true);
}

void RadiometryController::cancelMosaic() {
    ++m_imageGeneration;
    if (m_mosaicFeedback) m_mosaicFeedback->cancel();
    m_mosaicRunning = false;
}

void RadiometryController::startMosaic(std::vector<cv::Mat> frames, const QStringList& paths, bool demo) {
    cancelMosaic();
    const quint64 gen = ++m_imageGeneration;
    auto fb = std::make_shared<core::Feedback>([self = QPointer<RadiometryController>(this), gen](double f) {
        QMetaObject::invokeMethod(
            qApp,
            [self, gen, f] {
                if (self && gen == self->m_imageGeneration) emit self->mosaicProgress(f);
            },
            Qt::QueuedConnection);
    });
    m_mosaicFeedback = fb;
    m_mosaicRunning = true;
    const MosaicParams mp = m_params.mosaic;
    emit status(demo ? tr("Building the demo field: mosaicking 6 simulated frames…")
                     : tr("Mosaicking %1 frames…").arg(frames.size()));
    QPointer<RadiometryController> self(this);
    (void)QtConcurrent::run([=]() mutable {
        DemoField field;
        if (demo) {
            field = makeDemoField();
            frames = field.frames;
        }
        MosaicResult r = mosaicRow(frames, mp, fb.get());
        if (fb->isCancelled()) return;
        std::shared_ptr<RadiometryImage> img;
        std::vector<PickedRegion> regions;
        if (r.ok) {
            img = imageFrom(r.image, r.coverage);
            img->pairs = r.pairs;
            img->warnings = r.warnings;
            img->frames = paths;
            img->source = demo ? QStringLiteral("demo") : QString();
            if (demo) {
                img->demoK = kDemoK;
                img->demoB = kDemoB;
                // Scene pixels → mosaic pixels through frame 0's transform.
                const cv::Matx33d& t = r.frameToMosaic[0];
                auto map = [&](double x, double y) {
                    const cv::Vec3d v = t * cv::Vec3d(x - field.frame0.x, y - field.frame0.y, 1);
                    return QPointF(v[0] / v[2], v[1] / v[2]);
                };
                for (PickedRegion pr : field.regions) {
                    const QPointF a = map(pr.rect.left(), pr.rect.top());
                    const QPointF b = map(pr.rect.left() + pr.rect.width(), pr.rect.top() + pr.rect.height());
                    pr.rect = QRect(QPoint(int(std::lround(a.x())), int(std::lround(a.y()))),
                                    QPoint(int(std::lround(b.x())) - 1, int(std::lround(b.y())) - 1));
                    regions.push_back(pr);
                }
            }
        }
        QMetaObject::invokeMethod(
            qApp,
            [self, gen, r, img, regions, demo, paths]() {
                if (!self || gen != self->m_imageGeneration) return;
                self->m_mosaicRunning = false;
                if (!r.ok) {
                    const QString msg = demo ? tr("demo mosaic: %1").arg(QString::fromStdString(r.error))
                                             : tr("mosaic of %1 … %2: %3")
                                                   .arg(QFileInfo(paths.value(0)).fileName(), QFileInfo(paths.value(paths.size() - 1)).fileName(),
                                                        QString::fromStdString(r.error));
                    emit self->status(msg);
                    emit self->mosaicFailed(msg);
                    self->schedule();  // so waiters see the controller idle with the old image
                    return;
                }
                if (demo && !self->m_keepRegionsOnDemo) {
                    self->m_regions = regions;
                    emit self->regionsChanged();
                }
                self->m_keepRegionsOnDemo = false;
                for (const auto& w : r.warnings) emit self->status(QString::fromStdString(w));
                emit self->status(demo ? tr("Demo field: %1×%2 px mosaic of 6 frames, 6 grey panels, 4 check surfaces")
                                             .arg(img->dn.cols)
                                             .arg(img->dn.rows)
                                       : tr("Mosaic of %1 frames: %2×%3 px").arg(paths.size()).arg(img->dn.cols).arg(img->dn.rows));
                self->setImage(img);
            },
            Qt::QueuedConnection);
    });
}

void RadiometryController::clearImage() {
    cancelMosaic();
    setImage(std::make_shared<RadiometryImage>());
}

bool RadiometryController::openImage(const QString& path, QString* error) {
    cv::Mat m;
    std::string err;
    if (!readImageAnyDepth(path.toStdString(), &m, &err)) return fail(error, err);
    if (m.channels() != 1) return fail(error, tr("%1: the DN image must have one channel, not %2").arg(path).arg(m.channels()));
    cancelMosaic();
    auto img = imageFrom(m, {});
    img->source = path;
    if (!readGeoReference(path.toStdString(), &img->geo, &err)) img->geo = GeoReference{};  // no georeferencing
    emit status(tr("%1: %2×%3 px%4")
                    .arg(QFileInfo(path).fileName())
                    .arg(m.cols)
                    .arg(m.rows)
                    .arg(img->geo.valid ? tr(", georeferenced") : QString()));
    setImage(img);
    return true;
}

bool RadiometryController::openFrames(const QStringList& paths, QString* error) {
    if (paths.size() < 2) return fail(error, tr("a row mosaic needs at least two frames, in scan order"));
    std::vector<cv::Mat> frames;
    for (const QString& p : paths) {
        cv::Mat m;
        std::string err;
        if (!readImageAnyDepth(p.toStdString(), &m, &err)) return fail(error, err);
        if (m.channels() != 1) return fail(error, tr("%1: frames must have one channel, not %2").arg(p).arg(m.channels()));
        if (!frames.empty() && m.depth() != frames.front().depth())
            return fail(error, tr("%1: every frame must have the depth of the first (%2)").arg(p, paths.first()));
        frames.push_back(m);
    }
    startMosaic(std::move(frames), paths, false);
    return true;
}

bool RadiometryController::openRegions(const QString& path, RegionRole role, QString* error) {
    std::vector<Region> read;
    std::string err;
    if (!readRegionCsv(path.toStdString(), &read, &err)) return fail(error, err);
    // The optional role column (fit / check), aligned by source line.
    const core::CsvReadResult csv = core::readCsv(path.toStdString());
    const int rc = csv.ok ? csv.table.column("role") : -1;
    std::vector<PickedRegion> loaded;
    for (const Region& r : read) {
        PickedRegion p;
        p.name = QString::fromStdString(r.name);
        p.role = role;
        if (rc >= 0)
            for (size_t i = 0; i < csv.table.rows.size(); ++i)
                if (csv.table.lines[i] == r.line &&
                    !parseRegionRole(QString::fromStdString(csv.table.rows[i][size_t(rc)]), &p.role))
                    return fail(error, tr("%1:%2: role must be fit or check, not \"%3\"")
                                           .arg(path)
                                           .arg(r.line)
                                           .arg(QString::fromStdString(csv.table.rows[i][size_t(rc)])));
        p.reflectance = r.reflectance;
        if (!r.rect.empty()) p.rect = QRect(r.rect.x, r.rect.y, r.rect.width, r.rect.height);
        else p.dn = r.dn;
        if (p.rect.isEmpty() && !std::isfinite(p.dn))
            return fail(error, tr("%1:%2: region %3 has neither a rectangle nor a DN").arg(path).arg(r.line).arg(p.name));
        loaded.push_back(p);
    }
    std::vector<PickedRegion> regions;
    if (rc < 0)
        for (const PickedRegion& p : m_regions)
            if (p.role != role) regions.push_back(p);
    regions.insert(regions.end(), loaded.begin(), loaded.end());
    m_regions = regions;
    emit regionsChanged();
    emit status(tr("%1: %2 regions").arg(QFileInfo(path).fileName()).arg(loaded.size()));
    schedule();
    return true;
}

bool RadiometryController::setRegions(const std::vector<PickedRegion>& regions, QString* error) {
    for (size_t i = 0; i < regions.size(); ++i) {
        const PickedRegion& r = regions[i];
        if (r.rect.isEmpty() && !std::isfinite(r.dn))
            return fail(error, tr("region %1 (%2): needs a rectangle or a DN").arg(i + 1).arg(r.name));
        if (!r.rect.isEmpty() && (r.rect.x() < 0 || r.rect.y() < 0))
            return fail(error, tr("region %1 (%2): the rectangle starts outside the image").arg(i + 1).arg(r.name));
        if (std::isinf(r.reflectance))
            return fail(error, tr("region %1 (%2): the reflectance is not a finite number").arg(i + 1).arg(r.name));
    }
    m_regions = regions;
    emit regionsChanged();
    schedule();
    return true;
}

QString RadiometryController::nextRegionName(RegionRole role) const {
    const QString stem = role == RegionRole::Fit ? tr("panel") : tr("check");
    for (int k = 1;; ++k) {
        const QString name = QString("%1 %2").arg(stem).arg(k);
        bool used = false;
        for (const PickedRegion& r : m_regions) used |= r.name == name;
        if (!used) return name;
    }
}

int RadiometryController::addRegion(const QString& name, const QRect& rect, double reflectance, RegionRole role) {
    QRect r = rect.normalized();
    if (hasImage()) r &= QRect(0, 0, m_image->dn.cols, m_image->dn.rows);
    if (r.isEmpty()) return -1;
    PickedRegion p;
    p.name = name.isEmpty() ? nextRegionName(role) : name;
    p.role = role;
    p.rect = r;
    p.reflectance = reflectance;
    m_regions.push_back(p);
    emit regionsChanged();
    schedule();
    return int(m_regions.size()) - 1;
}

void RadiometryController::removeRegion(int index) {
    if (index < 0 || index >= int(m_regions.size())) return;
    m_regions.erase(m_regions.begin() + index);
    emit regionsChanged();
    schedule();
}

void RadiometryController::setRegionReflectance(int index, double reflectance) {
    if (index < 0 || index >= int(m_regions.size()) || std::isinf(reflectance)) return;
    m_regions[size_t(index)].reflectance = reflectance;
    emit regionsChanged();
    schedule();
}

void RadiometryController::setRegionName(int index, const QString& name) {
    if (index < 0 || index >= int(m_regions.size())) return;
    m_regions[size_t(index)].name = name;
    emit regionsChanged();
    schedule();
}

void RadiometryController::setRegionRole(int index, RegionRole role) {
    if (index < 0 || index >= int(m_regions.size())) return;
    m_regions[size_t(index)].role = role;
    emit regionsChanged();
    schedule();
}

void RadiometryController::setRegionRect(int index, const QRect& rect) {
    if (index < 0 || index >= int(m_regions.size())) return;
    QRect r = rect.normalized();
    if (hasImage()) r &= QRect(0, 0, m_image->dn.cols, m_image->dn.rows);
    if (r.isEmpty()) return;
    m_regions[size_t(index)].rect = r;
    m_regions[size_t(index)].dn = NAN;
    emit regionsChanged();
    schedule();
}

bool RadiometryController::setParams(const RadiometryParams& p, QString* error) {
    if (const QString e = validateRadiometryParams(p); !e.isEmpty()) return fail(error, e);
    m_params = p;
    schedule();
    return true;
}

bool RadiometryController::waitIdle(int timeoutMs) {
    return waitUntilIdle([this] { return busy(); }, timeoutMs);
}

// ---------------------------------------------------------------------------------------------
// Exports

bool RadiometryController::exportFit(const QString& path, QString* error) const {
    if (!m_run.fit.ok) return fail(error, tr("no reflectance fit to export"));
    std::string err;
    if (!writeFitCsv(path.toStdString(), m_run.fit.fit, &err)) return fail(error, err);
    return true;
}

bool RadiometryController::exportRegions(const QString& path, QString* error) const {
    const RadiometryRun& r = m_run;
    std::string s = "name,role,reflectance,x,y,w,h,dn,dn_sd,pixels,predicted,residual,used,note\n";
    for (size_t i = 0; i < r.regions.size(); ++i) {
        const PickedRegion& p = r.regions[i];
        const Region& m = r.measured[i];
        double predicted = NAN, residual = NAN;
        bool used = false;
        for (size_t j = 0; j < r.fitIndex.size(); ++j)
            if (r.fitIndex[j] == int(i) && r.fit.ok) {
                predicted = r.fit.regions[j].predicted;
                residual = r.fit.regions[j].residual;
                used = r.fit.regions[j].used;
            }
        if (p.role == RegionRole::Check && r.fit.ok && std::isfinite(m.dn)) predicted = r.fit.fit.k * m.dn + r.fit.fit.b;
        const bool rect = !p.rect.isEmpty();
        s += core::csvEscape(p.name.toStdString()) + "," + regionRoleName(p.role) + "," + gx(p.reflectance) + "," +
             (rect ? std::to_string(p.rect.x()) + "," + std::to_string(p.rect.y()) + "," + std::to_string(p.rect.width()) + "," +
                         std::to_string(p.rect.height())
                   : std::string(",,,")) +
             "," + gx(m.dn) + "," + gx(m.dnStd) + "," + (m.pixels ? std::to_string(m.pixels) : std::string()) + "," +
             gx(predicted) + "," + gx(residual) + "," + (used ? "1" : "0") + "," +
             core::csvEscape(i < r.notes.size() ? r.notes[i].toStdString() : std::string()) + "\n";
    }
    std::string err;
    if (!core::writeFileAtomic(path.toStdString(), s, &err)) return fail(error, err);
    return true;
}

bool RadiometryController::exportRelativeErrors(const QString& path, QString* error) const {
    if (!m_run.check.ok) return fail(error, m_run.checkError.isEmpty() ? tr("no relative errors to export") : m_run.checkError);
    std::string err;
    if (!writeRelativeErrorCsv(path.toStdString(), m_run.check, &err)) return fail(error, err);
    return true;
}

bool RadiometryController::exportReflectance(const QString& path, QString* error) const {
    if (!m_run.apply.ok) return fail(error, tr("no reflectance image to export (fit the line first)"));
    std::string err;
    if (!writeFloatTiff(path.toStdString(), m_run.apply.reflectance, &err)) return fail(error, err);
    return true;
}

bool RadiometryController::exportUncertainty(const QString& path, QString* error) const {
    if (!m_run.apply.ok || m_run.apply.uncertainty.empty()) return fail(error, tr("no uncertainty image to export"));
    std::string err;
    if (!writeFloatTiff(path.toStdString(), m_run.apply.uncertainty, &err)) return fail(error, err);
    return true;
}

}  // namespace lwb::ui
