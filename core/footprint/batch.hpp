#pragma once
// Batch processing of many frames on all cores, results in input order, with progress,
// cancellation and a per-item callback as results arrive; and the CSV report.
#include <functional>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/footprint/image_io.hpp"
#include "core/footprint/pipeline.hpp"

namespace lwb::core::footprint {

struct BatchParams {
    FootprintParams footprint;
    ImageReadParams read;
    std::vector<cv::Point2d> centres;  ///< nominal centres (full-image px); empty: search / whole ROI
    int threads = 0;                   ///< worker threads; 0 = all cores
};

struct BatchItem {
    std::string file;
    std::string readError;              ///< the frame could not be read (then rois is empty)
    std::vector<FrameRoiResult> rois;   ///< one per centre (or one)
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

/// The CSV header of footprint reports, with `extra` column names appended.
std::string footprintCsvHeader(const std::vector<std::string>& extra = {});
/// One CSV row per ROI of the item (coordinates in full-image px), each ending in '\n', with
/// the `extra` values (CSV-escaped here) appended to every row.
std::string footprintCsvRows(const BatchItem& item, Method method, const std::vector<std::string>& extra = {});

/// Columns a caller appends to the report (the workbench adds time, beam, camera, override and
/// note): the names, and per item one value per name.
struct FootprintCsvExtra {
    std::vector<std::string> names;
    std::vector<std::vector<std::string>> values;  ///< values[item][column]
};

/// Writes a whole report atomically (the `footprint` command's and the workbench's export).
/// False with *error on failure.
bool writeFootprintCsv(const std::string& path, const std::vector<BatchItem>& items, Method method,
                       std::string* error, const FootprintCsvExtra* extra = nullptr);

}  // namespace lwb::core::footprint
