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
#include "core/footprint/report_columns.hpp"

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
    std::string h;
    for (const std::string& n : footprintColumnNames(o.review)) h += (h.empty() ? "" : ",") + n;
    return h + "\n";
}

std::vector<ReportRow> reportRows(const BatchItem& item, Method method, bool review) {
    std::vector<ReportRow> rows;
    auto row = [&](size_t k) {
        ReportRow r;
        r.file = item.file;
        r.time = item.time;
        r.beam = item.beam;
        r.camera = item.camera;
        r.method = method;
        r.roi = static_cast<int>(k);
        r.review = review;
        if (k < item.reviews.size()) {
            r.overridden = item.reviews[k].overridden;
            r.manual = item.reviews[k].verdict;
            r.note = item.reviews[k].note;
        }
        return r;
    };
    if (!item.readError.empty()) {
        ReportRow r = row(0);
        r.readError = item.readError;
        rows.push_back(r);
        return rows;
    }
    for (size_t k = 0; k < item.rois.size(); ++k) {
        ReportRow r = row(k);
        r.result = &item.rois[k].result;
        r.originX = item.rois[k].originX;
        r.originY = item.rois[k].originY;
        rows.push_back(r);
    }
    return rows;
}

std::string footprintCsvRows(const BatchItem& item, Method method, const FootprintCsvOptions& o, size_t* rows) {
    std::string out;
    size_t count = 0;
    for (const ReportRow& r : reportRows(item, method, o.review)) {
        // Accepted only: good rows with a fit (unreadable frames and failed fits are rejected rows).
        if (o.acceptedOnly && (r.failed() || r.verdict() != Verdict::Good || !r.result->fit.ok)) continue;
        bool first = true;
        for (const FootprintColumn& c : footprintColumns()) {
            if (c.reviewOnly && !o.review) continue;
            out += (first ? "" : ",") + footprintCsvCell(c, r);
            first = false;
        }
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
