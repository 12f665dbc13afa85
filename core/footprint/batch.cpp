#include "core/footprint/batch.hpp"

#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/parallel.hpp"
#include "core/common/text.hpp"
#include "core/footprint/footprint_run.hpp"

namespace lwb::core::footprint {

namespace {
// Every shot through `one` (which fills item.rois or item.readError) on all cores, with the
// callback serialised; the stage runFootprintBatch and runFootprintFrames share.
BatchResult runItems(const std::vector<ShotSpec>& shots, int threads, Feedback* fb, const BatchItemFn& onItem,
                     const std::function<void(size_t, BatchItem&)>& one) {
    BatchResult out;
    out.items.resize(shots.size());
    std::mutex cbMutex;
    const size_t total = shots.size();
    const size_t done = parallelForEach(total, threads, fb, [&](size_t i) {
        const auto t0 = std::chrono::steady_clock::now();
        const ShotSpec& shot = shots[i];
        BatchItem& item = out.items[i];
        item.file = shot.file;
        item.time = shot.time;
        item.beam = shot.beam;
        item.camera = shot.camera;
        try {
            one(i, item);
        } catch (const std::exception& e) {  // e.g. out of memory on a huge frame: this item only
            item.rois.clear();
            item.readError = shot.file + ": " + e.what();
        }
        item.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::lock_guard<std::mutex> lock(cbMutex);
        if (onItem) onItem(i, item);
    });
    out.cancelled = cancelled(fb) && done < total;
    if (out.cancelled) out.items.resize(0);
    for (const auto& it : out.items)
        if (!it.readError.empty()) ++out.readErrors;
    return out;
}

std::vector<ShotSpec> shotsOf(const std::vector<std::string>& files) {
    std::vector<ShotSpec> shots(files.size());
    for (size_t i = 0; i < files.size(); ++i) shots[i].file = files[i];
    return shots;
}
}  // namespace

BatchResult runFootprintBatch(const std::vector<std::string>& files, const BatchParams& params, Feedback* fb,
                              const BatchItemFn& onItem) {
    return runFootprintBatch(shotsOf(files), params, fb, onItem);
}

BatchResult runFootprintBatch(const std::vector<ShotSpec>& shots, const BatchParams& params, Feedback* fb,
                              const BatchItemFn& onItem) {
    return runItems(shots, params.threads, fb, onItem, [&](size_t i, BatchItem& item) {
        std::vector<ShotRoi> rois;
        if (loadShotRois(shots[i], params, &rois, &item.readError)) item.rois = processShotRois(rois, params.footprint);
    });
}

BatchResult runFootprintFrames(const std::vector<cv::Mat>& frames, const std::vector<std::string>& names,
                               const BatchParams& params, Feedback* fb, const BatchItemFn& onItem) {
    return runItems(shotsOf(names), params.threads, fb, onItem, [&](size_t i, BatchItem& item) {
        if (i >= frames.size() || frames[i].empty() || frames[i].type() != CV_32FC1)
            item.readError = names[i] + ": not a single-channel float32 frame";
        else
            item.rois = processFrame(frames[i], params.footprint, params.centres);
    });
}

std::vector<FootprintResult> ShotsTask::run(const Inputs& in, const FootprintParams& params, const Reuse& reuse, Feedback* fb) {
    std::vector<FootprintResult> out(in.rois.size());
    const bool judgeOnly = reuse.fits && reuse.fits->size() == in.rois.size();
    parallelForEach(in.rois.size(), 0, fb, [&](size_t i) {
        const cv::Mat& roi = in.rois[i];
        if (roi.empty()) return;  // a shot that could not be read
        if (judgeOnly) {
            out[i] = (*reuse.fits)[i];
            judgeResult(&out[i], roi.cols, roi.rows, params.verdict);
        } else {
            out[i] = processRoi(roi, params);
        }
    });
    return out;
}

std::string footprintCsvHeader(const FootprintCsvOptions& o) {
    std::string h =
        "file,x,y,verdict,reasons,method,noise_class,sigma_x,sigma_y,axis_ratio,tilt_deg,major_axis_px,"
        "mse,snr,crlb_px,roi,uncertainty_px,eccentricity,area_px,amplitude_dn,background_dn,roi_x0,roi_y0,"
        "cov_xx_px2,cov_xy_px2,cov_yy_px2,radius95_px,time,beam,camera";
    if (o.review) h += ",auto_verdict,override,note";
    return h + "\n";
}

namespace {
std::string num(double v, int decimals) { return std::isfinite(v) ? formatFixed(v, decimals) : ""; }
std::string sci(double v) { return std::isfinite(v) ? formatDouble(v, 4) : ""; }
std::string joinReasons(const std::vector<std::string>& r) {
    std::string s;
    for (size_t i = 0; i < r.size(); ++i) s += (i ? "; " : "") + r[i];
    return s;
}
// The shot's columns (time, beam, camera), and the review columns of ROI k (empty fields when
// the item carries no review for it).
std::string shotColumns(const BatchItem& item) {
    return "," + csvEscape(item.time) + "," + csvEscape(item.beam) + "," + csvEscape(item.camera);
}
std::string reviewColumns(const BatchItem& item, size_t k, Verdict computed) {
    const RoiReview rv = k < item.reviews.size() ? item.reviews[k] : RoiReview{};
    return "," + std::string(verdictName(computed)) + "," + (rv.overridden ? "manual" : "") + "," + csvEscape(rv.note);
}
}  // namespace

std::string footprintCsvRows(const BatchItem& item, Method method, const FootprintCsvOptions& o, size_t* rows) {
    std::string out;
    size_t count = 0;
    const std::string file = csvEscape(item.file);
    // Unreadable frames and failed fits are rejected rows, whatever the review says.
    auto failedRow = [&](const std::string& reason, size_t k, const std::string& roi) {
        if (o.acceptedOnly) return;
        // (…, roi_y0, cov_xx/xy/yy_px2, radius95_px empty)
        out += file + ",,,rejected," + csvEscape(reason) + "," + methodName(method) + ",,,,,,,,,," + roi + ",,,,,,,,,,," +
               shotColumns(item);
        if (o.review) out += reviewColumns(item, k, Verdict::Rejected);
        out += "\n";
        ++count;
    };
    if (!item.readError.empty()) {
        failedRow("unreadable: " + item.readError, 0, "0");
        if (rows) *rows += count;
        return out;
    }
    for (size_t k = 0; k < item.rois.size(); ++k) {
        const FrameRoiResult& fr = item.rois[k];
        const FootprintResult& r = fr.result;
        if (!r.ok) {
            failedRow(r.error, k, std::to_string(k));
            continue;
        }
        const SpotFit& f = r.fit;
        Verdict v = r.verdict;
        if (o.review && k < item.reviews.size() && item.reviews[k].overridden) v = item.reviews[k].verdict;
        if (o.acceptedOnly && (v != Verdict::Good || !f.ok)) continue;
        const bool has = f.ok && v != Verdict::Rejected;
        out += file + ",";
        out += (has ? num(f.x + fr.originX, 4) : "") + "," + (has ? num(f.y + fr.originY, 4) : "") + ",";
        out += std::string(verdictName(v)) + "," + csvEscape(joinReasons(r.reasons)) + ",";
        out += std::string(methodName(r.method)) + "," + noiseClassName(r.background.noiseClass) + ",";
        if (f.ok) {
            out += num(f.sigmaX, 4) + "," + num(f.sigmaY, 4) + "," + num(f.axisRatio, 4) + "," +
                   num(f.tiltRad * 180 / M_PI, 3) + "," + num(f.majorAxisPx, 3) + "," + sci(f.mse) + "," +
                   num(f.snr, 2) + "," + num(r.crlbPx, 5) + ",";
        } else {
            out += ",,,,,,,,";
        }
        out += std::to_string(k) + ",";
        if (f.ok)
            out += num(f.uncertaintyPx, 5) + "," + num(f.eccentricity, 4) + "," + num(f.areaPx, 0) + "," +
                   num(f.amplitude, 1) + "," + num(f.background, 1);
        else
            out += ",,,," + num(r.background.level, 1);
        out += "," + std::to_string(fr.originX) + "," + std::to_string(fr.originY);
        // The centre's covariance behind uncertainty_px (the Gaussian fit's; empty for the others).
        out += "," + (has ? sci(f.covXX) : "") + "," + (has ? sci(f.covXY) : "") + "," + (has ? sci(f.covYY) : "") + "," +
               (has ? num(f.radius95Px, 5) : "") + shotColumns(item);
        if (o.review) out += reviewColumns(item, k, r.verdict);
        out += "\n";
        ++count;
    }
    if (rows) *rows += count;
    return out;
}

bool writeFootprintCsv(const std::string& path, const std::vector<BatchItem>& items, Method method,
                       std::string* error, const FootprintCsvOptions& options, size_t* rows) {
    if (rows) *rows = 0;
    AtomicFile f(path);
    if (!f.ok()) {
        *error = f.error();
        return false;
    }
    f.stream() << footprintCsvHeader(options);
    for (const auto& it : items) f.stream() << footprintCsvRows(it, method, options, rows);
    if (!f.commit()) {
        *error = f.error();
        return false;
    }
    return true;
}

}  // namespace lwb::core::footprint
