#pragma once
// Batch processing of many frames on all cores, results in input order, with progress,
// cancellation and a per-item callback as results arrive; and the CSV report.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/common/task.hpp"
#include "core/footprint/image_io.hpp"
#include "core/footprint/pipeline.hpp"
#include "core/footprint/shot_list.hpp"

namespace lwb::core::footprint {

struct BatchParams {
    FootprintParams footprint;
    ImageReadParams read;
    std::vector<cv::Point2d> centres;  ///< nominal centres (full-image px); empty: search / whole ROI
                                       ///< (a shot with a centre of its own uses that one alone)
    int threads = 0;                   ///< worker threads; 0 = all cores
};

/// The analyst's review of one ROI (the workbench's review table; the CLI has none).
struct RoiReview {
    bool overridden = false;            ///< a manual verdict replaces the computed one
    Verdict verdict = Verdict::Good;    ///< the manual verdict (when overridden)
    std::string note;
};

struct BatchItem {
    std::string file;
    std::string time, beam, camera;     ///< the shot's, from a shot list or frame metadata ("" unknown)
    double seconds = 0;                 ///< reading and processing time (run summaries; not in the report)
    std::string readError;              ///< the frame could not be read (then rois is empty)
    std::vector<FrameRoiResult> rois;   ///< one per centre (or one)
    std::vector<RoiReview> reviews;     ///< review tables only: one per ROI (one when unreadable)
};

/// What a footprint report holds beyond the CLI's columns.
struct FootprintCsvOptions {
    /// Adds auto_verdict,override,note; `verdict` is then the effective one (the manual verdict
    /// where there is one) and auto_verdict the computed one.
    bool review = false;
    bool acceptedOnly = false;          ///< only rows whose (effective) verdict is good, with a fit
};

struct BatchResult {
    bool cancelled = false;
    std::vector<BatchItem> items;       ///< input order
    size_t readErrors = 0;              ///< items with readError set
};

/// Called once per finished item, serialised (never two at once), in completion order.
using BatchItemFn = std::function<void(size_t index, const BatchItem& item)>;

/// Reads and processes every file. Long runs poll fb for cancellation and report progress.
BatchResult runFootprintBatch(const std::vector<std::string>& files, const BatchParams& params,
                              Feedback* fb = nullptr, const BatchItemFn& onItem = {});
/// The same over shots (core/footprint/shot_list.hpp): each item carries its shot's time, beam
/// and camera, and a shot with a centre of its own is cut there (one ROI) instead of at
/// params.centres.
BatchResult runFootprintBatch(const std::vector<ShotSpec>& shots, const BatchParams& params, Feedback* fb = nullptr,
                              const BatchItemFn& onItem = {});

/// Frames already in memory (CV_32FC1, DN; e.g. numpy arrays viewed by the Python module), each
/// named for the report's file column: the stage runFootprintBatch runs after reading a file
/// (processFrame with params.centres), so the same frames give the same report.
BatchResult runFootprintFrames(const std::vector<cv::Mat>& frames, const std::vector<std::string>& names,
                               const BatchParams& params, Feedback* fb = nullptr, const BatchItemFn& onItem = {});

/// The footprint shots task (core/common/task.hpp): every shot's ROI through processRoi on all
/// cores (the per-ROI stage of runFootprintBatch, which reads the frames and cuts the ROIs
/// itself), results in input order. The workbench's shot list runs it live
/// (TaskJob<ShotsTask>).
struct ShotsTask {
    static constexpr const char* kName = "footprint shots";
    using Params = FootprintParams;
    static const Schema<FootprintParams>& schema() { return footprintSchema(); }
    struct Inputs {
        std::vector<cv::Mat> rois;  ///< one per shot; empty = unreadable (its result stays empty)
    };
    /// Fits made under parameters that differ only in kStageVerdict rows: judged again with
    /// the verdict of now, not fitted again.
    struct Reuse {
        std::shared_ptr<const std::vector<FootprintResult>> fits;
    };
    using Outputs = std::vector<FootprintResult>;
    static Outputs run(const Inputs& in, const FootprintParams& params, const Reuse& reuse, Feedback* fb);
};

struct ReportRow;
/// The report's rows of an item (core/footprint/report_columns.hpp): one per ROI, or one for an
/// unreadable frame. They point into `item`, which must outlive them.
std::vector<ReportRow> reportRows(const BatchItem& item, Method method, bool review = false);

/// The CSV header of footprint reports: the names of core/footprint/report_columns.hpp
/// (file,x,y,verdict,...,time,beam,camera), then the review's columns when asked.
std::string footprintCsvHeader(const FootprintCsvOptions& options = {});
/// One CSV row per ROI of the item (coordinates in full-image px), each ending in '\n'; adds the
/// number of rows to *rows when given.
std::string footprintCsvRows(const BatchItem& item, Method method, const FootprintCsvOptions& options = {},
                             size_t* rows = nullptr);
/// Writes a whole report atomically. False with *error on failure; *rows (when given) is the
/// number of data rows written.
bool writeFootprintCsv(const std::string& path, const std::vector<BatchItem>& items, Method method,
                       std::string* error, const FootprintCsvOptions& options = {}, size_t* rows = nullptr);

}  // namespace lwb::core::footprint
