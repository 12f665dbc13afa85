#pragma once
// The footprint run from its sources: a front end (the CLI's `footprint`, the workbench's shot
// list, Python's fit_batch) gathers what the analyst gave — frames, folders, shot lists, frame
// metadata, a config, a preset, settings — and the core resolves them here into the shots and
// the parameters, in one order, with one set of messages. Reading a shot's frame and cutting its
// ROIs is here too, for the batch (runFootprintBatch) and the workbench's loader alike.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/common/json.hpp"
#include "core/common/schema.hpp"
#include "core/footprint/batch.hpp"

namespace lwb::core::footprint {

struct FootprintSources {
    std::vector<std::string> inputs;   ///< frames, folders and shot lists, in the order given
    std::string metadata;              ///< a frame-metadata table (core/footprint/shot_list.hpp); "" none
    /// The workbench's file dialog: a file that is neither a frame nor a shot list — and a .csv
    /// picked together with frames (a folder's truth.csv) — is set aside and listed instead of
    /// read; so are a folder's files that are not frames. Otherwise (the CLI, Python) a named
    /// file is read as a frame and a .csv is always a shot list.
    bool setAsideOthers = false;
    /// --keep-going: a frame named but missing is kept as a shot, and reported as a rejected row
    /// like any frame that cannot be read (a folder or shot list that is missing still stops the run).
    bool keepGoing = false;
    // ---- the parameters, applied in this order over the defaults ----
    std::string configFile;            ///< a JSON config (the footprint block of a session); "" none
    Json config;                       ///< parameters given as JSON (Python's FootprintParams, the
                                       ///< workbench's panel); null none. Applied after configFile.
    std::string preset;                ///< wu2021 | yao2021 ("" none)
    std::vector<ParamSetting> set;     ///< --method, --roi, --set, a Python dict: in order
    // ---- how the frames are read and cut ----
    std::vector<cv::Point2d> centres;  ///< nominal centres (--center); a shot's own centre wins
    ImageReadParams read;
    int threads = 0;                   ///< worker threads; 0 = every core
};

struct FootprintError {
    std::string message;
    bool usage = false;                ///< a bad option (exit 2) rather than a bad file (exit 1)
};

struct FootprintSetup {
    BatchParams params;                ///< resolved and validated
    std::vector<ShotSpec> shots;       ///< every shot, in input order (before any shard)
    std::vector<std::string> setAside; ///< files left out (FootprintSources::setAsideOthers)
    size_t unmatched = 0;              ///< shots the frame metadata has no row for
};

/// The parameters alone: defaults → config file → config → preset → settings (a setting of
/// roi.size makes the size explicit: a smaller frame is then an error) → the family's rules.
bool resolveFootprintParams(const FootprintSources& sources, FootprintParams* out, FootprintError* error);

/// resolveFootprintParams, and how the frames are read and cut (centres, read, threads): all
/// a run over frames in memory needs.
bool resolveBatchParams(const FootprintSources& sources, BatchParams* out, FootprintError* error);

/// The shots alone (frames, folders, shot lists expanded; the frame metadata applied) into
/// out->shots, out->setAside and out->unmatched. Refuses inputs that hold no frame. Reads no frame.
bool gatherShots(const FootprintSources& sources, FootprintSetup* out, FootprintError* error);

/// The parameters, then the shots (frames, folders, shot lists expanded; the frame metadata
/// applied). Refuses inputs that hold no frame. Reads no frame.
bool setUpFootprintRun(const FootprintSources& sources, FootprintSetup* out, FootprintError* error);

/// One ROI of a shot cut from its frame: where it sits in the frame, and why not when it could
/// not be cut.
struct ShotRoi {
    std::string error;                 ///< "" when cut
    cv::Mat roi;                       ///< CV_32FC1, DN
    int originX = 0, originY = 0;      ///< the ROI's top-left pixel in the frame
    bool wholeImage = false;           ///< the frame was the ROI itself
    std::vector<std::string> warnings;
};

/// The ROIs of a shot in a frame already read: at the shot's own centre when it has one, else
/// one per params.centres, else one found by params.footprint.roi.
std::vector<ShotRoi> cutShotRois(const cv::Mat& frame, const ShotSpec& shot, const BatchParams& params);

/// Each ROI cut fitted and judged (processRoi); a ROI that could not be cut is a result with
/// ok=false and the cut's error.
std::vector<FrameRoiResult> processShotRois(const std::vector<ShotRoi>& rois, const FootprintParams& params);

/// Cuts one ROI per centre (or one searched / whole ROI when centres is empty) and processes
/// each: cutShotRois then processShotRois.
std::vector<FrameRoiResult> processFrame(const cv::Mat& image, const FootprintParams& params,
                                         const std::vector<cv::Point2d>& centres);

/// Reads the shot's frame (params.read) and cuts its ROIs. False with *readError when the frame
/// cannot be read.
bool loadShotRois(const ShotSpec& shot, const BatchParams& params, std::vector<ShotRoi>* rois, std::string* readError);

/// The shot's whole frame, read as loadShotRois reads it (the workbench's frame view).
ImageReadResult readShotFrame(const ShotSpec& shot, const BatchParams& params);

}  // namespace lwb::core::footprint
