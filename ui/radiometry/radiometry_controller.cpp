#include "ui/radiometry/radiometry_controller.hpp"

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
#include "core/sim/demo_data.hpp"
#include "ui/kit/session_json.hpp"

namespace lwb::ui {

using namespace core::radiometry;
namespace sim = core::sim;

namespace {

bool fail(QString* error, const QString& msg) {
    if (error) *error = msg;
    return false;
}
bool fail(QString* error, const std::string& msg) { return fail(error, QString::fromStdString(msg)); }


std::shared_ptr<RadiometryImage> imageFrom(const cv::Mat& dn, const cv::Mat& coverage) {
    auto img = std::make_shared<RadiometryImage>();
    img->dn = dn;
    dn.convertTo(img->display, CV_32F);
    img->coverage = coverage.empty() ? cv::Mat(dn.size(), CV_8U, cv::Scalar(255)) : coverage;
    return img;
}

// ---------------------------------------------------------------------------------------------
// measure → fit → apply → check

std::vector<RegionPick> corePicks(const std::vector<PickedRegion>& regions) {
    std::vector<RegionPick> out;
    for (const PickedRegion& pr : regions) {
        RegionPick r;
        r.name = pr.name.toStdString();
        r.check = pr.role == RegionRole::Check;
        if (!pr.rect.isEmpty()) r.rect = cv::Rect(pr.rect.x(), pr.rect.y(), pr.rect.width(), pr.rect.height());
        r.reflectance = pr.reflectance;
        r.dn = pr.dn;
        out.push_back(r);
    }
    return out;
}

// The part of a run the regions' result table reads, back in core form.
RadiometryRunResult runResultOf(const RadiometryRun& run) {
    RadiometryRunResult r;
    r.measured = run.measured;
    r.fitIndex = run.fitIndex;
    r.fit = run.fit;
    for (const QString& n : run.notes) r.notes.push_back(n.toStdString());
    return r;
}

// The task's outputs with the strings the views show, for the regions they were computed from.
RadiometryRun viewRun(RadiometryRunResult r, const std::vector<PickedRegion>& regions) {
    RadiometryRun run;
    run.regions = regions;
    run.measured = std::move(r.measured);
    run.fitIndex = std::move(r.fitIndex);
    run.fit = std::move(r.fit);
    run.error = QString::fromStdString(r.error);
    run.apply = std::move(r.apply);
    run.checkIndex = std::move(r.checkIndex);
    run.check = std::move(r.check);
    run.checkError = QString::fromStdString(r.checkError);
    for (const auto& n : r.notes) run.notes.push_back(QString::fromStdString(n));
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

QString validateRadiometryParams(const RadiometryParams& p) { return QString::fromStdString(validate(p)); }

QJsonObject radiometryParamsToJson(const RadiometryParams& p) { return toQtJson(radiometrySchema().toJson(p)); }

bool radiometryParamsFromJson(const QJsonObject& o, RadiometryParams* out, QString* error, const core::JsonParseResult* doc,
        const std::vector<std::string>& at) {
    RadiometryParams p;
    std::string err;
    if (!radiometrySchema().fromJson(fromQtJson(o), &p, &err, doc, at)) return fail(error, err);
    if (const std::string e = validate(p); !e.empty()) return fail(error, (doc ? doc->where(at) : std::string()) + e);
    *out = p;
    return true;
}

// ---------------------------------------------------------------------------------------------

RadiometryController::RadiometryController(QObject* parent)
    : QObject(parent), m_image(std::make_shared<RadiometryImage>()) {
    qRegisterMetaType<lwb::ui::RadiometryRun>();
    m_job.bind(
        [this](TaskJob<RadiometryTask>::Run* r) {
            if (m_mosaicRunning) return false;  // the new image schedules a run when it arrives
            auto in = std::make_shared<RadiometryTask::Inputs>();
            if (m_image) in->dn = m_image->dn;  // shared, never written after (RadiometryImage)
            in->regions = corePicks(m_regions);
            r->inputs = std::move(in);
            r->params = m_params;
            m_runRegions = m_regions;  // the latest snapshot is the only run delivered
            return true;
        },
        [this](RadiometryRunResult r) {
            RadiometryRun run = viewRun(std::move(r), m_runRegions);
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
        sim::RadiometryDemoField field;
        if (demo) {
            field = sim::demoRadiometryField();
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
                img->demoK = field.k;
                img->demoB = field.b;
                // Scene pixels → mosaic pixels through frame 0's transform.
                const cv::Matx33d& t = r.frameToMosaic[0];
                auto map = [&](double x, double y) {
                    const cv::Vec3d v = t * cv::Vec3d(x - field.frame0.x, y - field.frame0.y, 1);
                    return QPointF(v[0] / v[2], v[1] / v[2]);
                };
                for (const sim::DemoRegion& dr : field.regions) {
                    PickedRegion pr;
                    pr.name = QString::fromStdString(dr.name);
                    pr.role = dr.check ? RegionRole::Check : RegionRole::Fit;
                    pr.reflectance = dr.reflectance;
                    const QPointF a = map(dr.rect.x, dr.rect.y);
                    const QPointF b = map(dr.rect.x + dr.rect.width, dr.rect.y + dr.rect.height);
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
    RadiometryInput in;
    if (!readInput(path, {}, &in, error)) return false;
    adoptInput(std::move(in));
    return true;
}

bool RadiometryController::openFrames(const QStringList& paths, QString* error) {
    RadiometryInput in;
    if (!readInput(QString(), paths, &in, error)) return false;
    adoptInput(std::move(in));
    return true;
}

bool RadiometryController::readInput(const QString& path, const QStringList& paths, RadiometryInput* out, QString* error) {
    *out = RadiometryInput{};
    if (!path.isEmpty()) {
        cv::Mat m;
        std::string err;
        if (!readImageAnyDepth(path.toStdString(), &m, &err)) return fail(error, err);
        if (m.channels() != 1) return fail(error, tr("%1: the DN image must have one channel, not %2").arg(path).arg(m.channels()));
        out->image = imageFrom(m, {});
        out->image->source = path;
        if (!readGeoReference(path.toStdString(), &out->image->geo, &err)) out->image->geo = GeoReference{};  // no georeferencing
        return true;
    }
    if (paths.size() < 2) return fail(error, tr("a row mosaic needs at least two frames, in scan order"));
    std::vector<std::string> files;
    for (const QString& p : paths) files.push_back(p.toStdString());
    if (const std::string why = mosaicMemoryProblem(files, memoryBudgetBytes()); !why.empty())
        return fail(error, QString::fromStdString(why));
    for (const QString& p : paths) {
        cv::Mat m;
        std::string err;
        if (!readImageAnyDepth(p.toStdString(), &m, &err)) return fail(error, err);
        if (m.channels() != 1) return fail(error, tr("%1: frames must have one channel, not %2").arg(p).arg(m.channels()));
        if (!out->frames.empty() && m.depth() != out->frames.front().depth())
            return fail(error, tr("%1: every frame must have the depth of the first (%2)").arg(p, paths.first()));
        out->frames.push_back(m);
    }
    out->framePaths = paths;
    return true;
}

void RadiometryController::adoptInput(RadiometryInput in) {
    cancelMosaic();
    if (!in.image) {
        startMosaic(std::move(in.frames), in.framePaths, false);
        return;
    }
    emit status(tr("%1: %2×%3 px%4")
                    .arg(QFileInfo(in.image->source).fileName())
                    .arg(in.image->dn.cols)
                    .arg(in.image->dn.rows)
                    .arg(in.image->geo.valid ? tr(", georeferenced") : QString()));
    setImage(std::move(in.image));
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
    std::string err;
    if (!core::writeFileAtomic(path.toStdString(), regionResultsCsv(corePicks(m_run.regions), runResultOf(m_run)), &err))
        return fail(error, err);
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
