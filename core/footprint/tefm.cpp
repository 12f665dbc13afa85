#include "core/footprint/tefm.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "core/footprint/gcm.hpp"

namespace lwb::core::footprint {

TefmResult fitTefm(const cv::Mat& roi, double background, double noise, const TefmParams& params) {
    TefmResult r;
    const double offset = std::isnan(params.backgroundOffset) ? background : params.backgroundOffset;
    // Step 1: remove the ground.
    cv::Mat g;
    cv::max(roi - offset, 0.0, g);
    // Step 2: first constraint, T = max/e².
    double mx = 0;
    cv::minMaxLoc(g, nullptr, &mx);
    if (!(mx > 0)) {
        r.fit.error = "TEFM: nothing above the ground offset";
        return r;
    }
    const double t = params.thresholdFactor * mx;
    cv::Mat th;
    cv::threshold(g, th, t, 0, cv::THRESH_TOZERO);
    // Step 3: second constraint, erosion (local minimum over D1).
    cv::Mat er;
    if (params.erosionSize > 1)
        cv::erode(th, er, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(params.erosionSize, params.erosionSize)),
                  cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
    else
        er = th;
    // Step 4: third constraint, ellipse fit to the boundary of the region around the maximum.
    cv::Mat bin = er > 0;
    cv::Point maxP;
    double emax = 0;
    cv::minMaxLoc(er, nullptr, &emax, nullptr, &maxP);
    if (!(emax > 0)) {
        r.fit.error = "TEFM: erosion removed the whole spot";
        return r;
    }
    cv::Mat labels;
    cv::connectedComponents(bin, labels, 8, CV_32S);
    const int keep = labels.at<int>(maxP);
    std::vector<cv::Point2f> boundary;
    const int w = roi.cols, h = roi.rows;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (labels.at<int>(y, x) != keep) continue;
            const bool edge = x == 0 || y == 0 || x == w - 1 || y == h - 1 || labels.at<int>(y, x - 1) != keep ||
                              labels.at<int>(y, x + 1) != keep || labels.at<int>(y - 1, x) != keep ||
                              labels.at<int>(y + 1, x) != keep;
            if (edge) boundary.emplace_back(static_cast<float>(x), static_cast<float>(y));
        }
    if (boundary.size() < 5) {
        r.fit.error = "TEFM: spot boundary has fewer than 5 pixels, no ellipse";
        return r;
    }
    cv::RotatedRect e;
    try {
        e = cv::fitEllipse(boundary);
    } catch (const cv::Exception& ex) {
        r.fit.error = std::string("TEFM: ellipse fit failed: ") + ex.what();
        return r;
    }
    double a = e.size.width / 2.0, b = e.size.height / 2.0;
    double ang = e.angle * M_PI / 180.0;  // angle of the width axis
    if (b > a) {
        std::swap(a, b);
        ang += M_PI / 2;
    }
    if (!(std::isfinite(a) && std::isfinite(b) && a > 0 && b > 0) || a > 4.0 * std::max(w, h)) {
        r.fit.error = "TEFM: degenerate ellipse";
        return r;
    }
    r.ellipseX = e.center.x;
    r.ellipseY = e.center.y;
    r.ellipseA = a;
    r.ellipseB = b;
    r.ellipseAngleRad = std::remainder(ang, M_PI);
    // Pixels outside the ellipse are set to 0.
    const cv::Mat& src = params.centroidOnEroded ? er : th;
    r.constrained = cv::Mat::zeros(roi.size(), CV_32F);
    const double c = std::cos(ang), s = std::sin(ang);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double dx = x - e.center.x, dy = y - e.center.y;
            const double u = (dx * c + dy * s) / a, v = (-dx * s + dy * c) / b;
            if (u * u + v * v <= 1.0) r.constrained.at<float>(y, x) = src.at<float>(y, x);
        }
    // Step 5: gray centroid of the constrained image.
    SpotFit f = weightedCentroid(r.constrained, noise);
    if (!f.ok) {
        r.fit.error = "TEFM: " + f.error;
        return r;
    }
    // Shape from the ellipse (semi-axes in sigmaX/sigmaY, full axes in major/minor).
    const double cov_xx = a * a * c * c + b * b * s * s;
    const double cov_yy = a * a * s * s + b * b * c * c;
    const double cov_xy = (a * a - b * b) * c * s;
    const double area = f.areaPx;
    setShapeFromCovariance(cov_xx, cov_xy, cov_yy, 2.0, &f);
    f.areaPx = area;
    f.background = offset;
    f.amplitude = mx;
    f.snr = mx / std::max(noise, 1e-9);
    r.fit = f;
    return r;
}

}  // namespace lwb::core::footprint
