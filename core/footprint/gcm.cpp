#include "core/footprint/gcm.hpp"

#include <cmath>

namespace lwb::core::footprint {

SpotFit weightedCentroid(const cv::Mat& w, double noise) {
    SpotFit f;
    double s = 0, sx = 0, sy = 0;
    for (int y = 0; y < w.rows; ++y) {
        const float* row = w.ptr<float>(y);
        for (int x = 0; x < w.cols; ++x) {
            const double v = row[x];
            s += v;
            sx += v * x;
            sy += v * y;
        }
    }
    if (!(s > 0)) {
        f.error = "centroid: no positive weight in the ROI";
        return f;
    }
    f.x = sx / s;
    f.y = sy / s;
    double mxx = 0, mxy = 0, myy = 0, r2 = 0;
    int count = 0;
    for (int y = 0; y < w.rows; ++y) {
        const float* row = w.ptr<float>(y);
        for (int x = 0; x < w.cols; ++x) {
            const double v = row[x];
            const double dx = x - f.x, dy = y - f.y;
            if (v > 0) {
                r2 += dx * dx + dy * dy;
                ++count;
            }
            mxx += v * dx * dx;
            mxy += v * dx * dy;
            myy += v * dy * dy;
        }
    }
    setShapeFromCovariance(mxx / s, mxy / s, myy / s, 4.0, &f);
    f.areaPx = count;
    // δX = Σ (x_i − X) δI_i / Σ I  →  var X + var Y = σ² Σ r_i² / (Σ I)²
    f.uncertaintyPx = noise * std::sqrt(r2) / s;
    f.mse = NAN;  // no model, no fit residual
    f.ok = true;
    return f;
}

SpotFit fitGcm(const cv::Mat& roi, double background, double noise, const GcmParams& params) {
    cv::Mat w;
    if (params.subtractBackground)
        cv::max(roi - background, 0.0, w);
    else
        w = roi;
    SpotFit f = weightedCentroid(w, noise);
    double mx = 0;
    cv::minMaxLoc(roi, nullptr, &mx);
    f.background = background;
    f.amplitude = mx - background;
    f.snr = f.amplitude / std::max(noise, 1e-9);
    return f;
}

}  // namespace lwb::core::footprint
