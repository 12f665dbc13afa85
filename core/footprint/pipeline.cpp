#include "core/footprint/pipeline.hpp"

#include <cmath>

#include "core/common/schema.hpp"
#include "core/common/text.hpp"
#include "core/footprint/crlb.hpp"

namespace lwb::core::footprint {

namespace {
// Every pixel of a CV_32FC1 image finite: x − x is 0 for a finite x and NaN otherwise, a test
// without branches that vectorises (cv::checkRange took 1 % of a shot).
bool allFinite(const cv::Mat& img) {
    int ok = 1;
    for (int y = 0; y < img.rows; ++y) {
        const float* row = img.ptr<float>(y);
        for (int x = 0; x < img.cols; ++x) ok &= row[x] - row[x] == 0.0f;
    }
    return ok != 0;
}
}  // namespace

FootprintResult processRoi(const cv::Mat& roi, const FootprintParams& params) {
    FootprintResult r;
    r.method = params.method;
    if (roi.empty() || roi.type() != CV_32FC1) {
        r.error = "ROI must be a non-empty single-channel float image";
        return r;
    }
    if (roi.cols < 5 || roi.rows < 5) {
        r.error = "ROI is only " + std::to_string(roi.cols) + "x" + std::to_string(roi.rows) + " px";
        return r;
    }
    if (const std::string e = validate(params); !e.empty()) {
        r.error = e;
        return r;
    }
    if (!allFinite(roi)) {
        r.error = "ROI holds NaN or infinite pixels";
        return r;
    }
    r.background = estimateBackground(roi, params.background);
    if (!r.background.ok) {
        r.error = r.background.error;
        return r;
    }
    const double bg = r.background.level, noise = r.background.noise;
    r.domain = segmentSpot(roi, bg, noise, params.camera.saturationDn, params.segment);
    r.ok = true;
    if (r.domain.found) {
        switch (params.method) {
            case Method::Gcm: r.fit = fitGcm(roi, bg, noise, params.gcm); break;
            case Method::Tefm:
                r.tefm = fitTefm(roi, bg, noise, params.tefm);
                r.fit = r.tefm.fit;
                break;
            case Method::Gauss: {
                GaussResult g = fitGauss(roi, r.domain, bg, noise, params.gauss, params.camera);
                r.fit = g.fit;
                r.gaussModel = g.model;
                r.gaussStage = g.stage;
                r.startNote = g.fallbackStart || g.coreStart ? g.note : std::string();
                break;
            }
        }
        if (r.fit.ok) {
            r.fit.areaPx = params.method == Method::Gauss ? r.domain.pixels.size() : r.fit.areaPx;
            const double big = std::max(r.fit.sigmaX, r.fit.sigmaY), small = std::min(r.fit.sigmaX, r.fit.sigmaY);
            // For TEFM/GCM the "σ" are ellipse semi-axes / moments: scale to Gaussian σ.
            const double toSigma = params.method == Method::Tefm ? 0.5 : 1.0;
            const CrlbResult c = crlbClosedForm(r.fit.amplitude, big * toSigma, small * toSigma,
                                                r.fit.background, params.camera, false);
            if (c.ok) r.crlbPx = c.radialPx;
        }
    }
    judgeResult(&r, roi.cols, roi.rows, params.verdict);
    return r;
}

VerdictMeasures measureResult(const FootprintResult& r, int roiWidth, int roiHeight) {
    VerdictMeasures m = measureVerdict(r.fit, r.domain, roiWidth, roiHeight);
    m.startNote = r.startNote;
    return m;
}

void judgeResult(FootprintResult* r, int roiWidth, int roiHeight, const VerdictParams& verdict) {
    if (!r->ok) return;
    r->reasons.clear();
    r->verdict = checkVerdict(measureResult(*r, roiWidth, roiHeight), verdict, &r->reasons);
}

bool onlyVerdictDiffers(const FootprintParams& a, const FootprintParams& b) {
    return footprintSchema().firstChangedStage(a, b) != kStageFit;
}

}  // namespace lwb::core::footprint
