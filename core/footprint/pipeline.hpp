#pragma once
// The footprint pipeline for one ROI (background → domain → method → verdict → CRLB) and for
// a frame with one or more nominal centres, with every parameter in one struct.
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/json.hpp"
#include "core/common/schema.hpp"
#include "core/footprint/background.hpp"
#include "core/footprint/gauss_fit.hpp"
#include "core/footprint/gcm.hpp"
#include "core/footprint/roi.hpp"
#include "core/footprint/segment.hpp"
#include "core/footprint/tefm.hpp"
#include "core/footprint/verdict.hpp"

namespace lwb::core::footprint {

enum class Method { Gcm, Tefm, Gauss };
const char* methodName(Method m);
bool parseMethod(const std::string& s, Method* m);

struct FootprintParams {
    Method method = Method::Gauss;   ///< default: the full Gaussian (Wu + xy + Guo + LM)
    std::string preset = "wu2021";   ///< name of the verdict criteria (informational once loaded)
    RoiParams roi;
    BackgroundParams background;
    SegmentParams segment;
    GcmParams gcm;
    TefmParams tefm;
    GaussParams gauss;
    VerdictParams verdict;
    CameraParams camera;
};

/// The parameter table (core/common/schema.hpp): every field's key, unit, range, UI range and
/// doc, declared once. JSON configs, sessions, the CLI's --set and the GUI panel use it.
const Schema<FootprintParams>& footprintSchema();

/// The stages of a shot's run that the schema rows are tagged with (FieldInfo::stage): the fit
/// (ROI, background, segmentation, centre method, camera) and the verdict on the fit.
enum FootprintStage : int { kStageFit = 0, kStageVerdict = 1 };

/// Empty when every parameter is valid, else what is wrong.
std::string validate(const FootprintParams& p);
/// Loads the named verdict preset into p (and records the name). False when unknown.
bool applyPreset(const std::string& name, FootprintParams* p);

/// Reads a JSON config over p (missing keys keep their values; a "preset" is applied before the
/// verdict values). False with *error naming the key, and its line and column when `doc` is
/// given, when anything is unknown, malformed, non-finite or out of range.
bool footprintParamsFromJson(const Json& j, FootprintParams* p, std::string* error, const JsonParseResult* doc = nullptr);
Json footprintParamsToJson(const FootprintParams& p);

struct FootprintResult {
    bool ok = false;            ///< false: the inputs or params were unusable (see error)
    std::string error;
    Method method = Method::Gauss;
    BackgroundResult background;
    SpotDomain domain;
    SpotFit fit;                ///< ROI coordinates
    GaussModel gaussModel;      ///< when method == Gauss and the fit succeeded
    std::string gaussStage;     ///< "wu", "guo" or "lm"
    TefmResult tefm;            ///< when method == Tefm (ellipse + constrained image)
    Verdict verdict = Verdict::Rejected;
    std::vector<std::string> reasons;
    double crlbPx = NAN;        ///< Cramér–Rao bound on the radial error (closed form, fitted spot)
    std::string startNote;      ///< the Gaussian fit started from moments (why): the verdict stage keeps it doubtful
};

/// Runs the whole pipeline on a CV_32FC1 ROI. Never throws.
FootprintResult processRoi(const cv::Mat& roi, const FootprintParams& params);

/// The verdict stage of processRoi on its own: judges r's fit and domain again with other
/// criteria, no refit (roiWidth / roiHeight: the ROI's size, for the edge check). A result that
/// is not ok (unusable input or params) is left as it is.
void judgeResult(FootprintResult* r, int roiWidth, int roiHeight, const VerdictParams& verdict);
/// What the verdict stage reads of r (its fit, domain and start note; roiWidth / roiHeight: the
/// ROI's size): judgeResult is checkVerdict of these under the criteria.
VerdictMeasures measureResult(const FootprintResult& r, int roiWidth, int roiHeight);
/// True when results under `a` hold under `b` but for the verdict: only verdict criteria (and
/// the informational preset name) differ, so judgeResult() replaces processRoi(). The stages
/// come from the schema rows' tags (FootprintStage).
bool onlyVerdictDiffers(const FootprintParams& a, const FootprintParams& b);

struct FrameRoiResult {
    FootprintResult result;     ///< fit in ROI coordinates
    int originX = 0, originY = 0;  ///< add to ROI coordinates for full-image ones
    std::vector<std::string> warnings;
};

// (processFrame, which cuts a frame's ROIs and processes each: core/footprint/footprint_run.hpp)

}  // namespace lwb::core::footprint
