#include "core/footprint/roi.hpp"

#include "core/footprint/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace lwb::core::footprint {

std::string validate(const RoiParams& p) {
    FootprintParams f;  // the ranges are the footprint schema's roi rows
    f.roi = p;
    if (std::string e = footprintSchema().validate(f, "roi."); !e.empty()) return e;
    if (p.hasCenter && (!std::isfinite(p.centerX) || !std::isfinite(p.centerY))) return "ROI centre must be finite numbers";
    return {};
}

cv::Point findBrightestBlob(const cv::Mat& image, double sigma) {
    cv::Mat small, large;
    cv::GaussianBlur(image, small, cv::Size(), sigma, sigma, cv::BORDER_REPLICATE);
    cv::GaussianBlur(image, large, cv::Size(), 3 * sigma, 3 * sigma, cv::BORDER_REPLICATE);
    cv::Mat dog = small - large;
    cv::Point best;
    cv::minMaxLoc(dog, nullptr, nullptr, nullptr, &best);
    return best;
}

RoiResult extractRoi(const cv::Mat& image, const RoiParams& p) {
    RoiResult r;
    if (image.empty() || image.type() != CV_32FC1) {
        r.error = "ROI: image must be a non-empty CV_32FC1 frame";
        return r;
    }
    if (const std::string e = validate(p); !e.empty()) {
        r.error = e;
        return r;
    }
    const int n = p.size;
    const int w = image.cols, h = image.rows;
    if (n > w || n > h) {
        if (p.sizeExplicit || p.hasCenter) {
            r.error = "ROI " + std::to_string(n) + "x" + std::to_string(n) + " is larger than the image " +
                      std::to_string(w) + "x" + std::to_string(h);
            return r;
        }
        // A ready ROI smaller than the default size: take it whole.
        r.roi = image.clone();
        r.wholeImage = true;
        r.ok = true;
        return r;
    }
    if (!p.hasCenter && w == n && h == n) {
        r.roi = image.clone();
        r.wholeImage = true;
        r.ok = true;
        return r;
    }
    double cx = p.centerX, cy = p.centerY;
    if (p.hasCenter) {
        if (cx < -0.5 || cy < -0.5 || cx > w - 0.5 || cy > h - 0.5) {
            r.error = "ROI centre (" + std::to_string(cx) + ", " + std::to_string(cy) +
                      ") lies outside the image " + std::to_string(w) + "x" + std::to_string(h);
            return r;
        }
    } else {
        const cv::Point b = findBrightestBlob(image, p.blobSigma);
        cx = b.x;
        cy = b.y;
        r.searched = true;
    }
    // The ROI's centre pixel is N/2 (for even N the centre falls between N/2-1 and N/2).
    int x0 = static_cast<int>(std::lround(cx)) - n / 2;
    int y0 = static_cast<int>(std::lround(cy)) - n / 2;
    const int sx = std::clamp(x0, 0, w - n), sy = std::clamp(y0, 0, h - n);
    if (sx != x0 || sy != y0)
        r.warnings.push_back("ROI shifted by (" + std::to_string(sx - x0) + ", " + std::to_string(sy - y0) +
                             ") px to stay inside the image");
    r.originX = sx;
    r.originY = sy;
    r.roi = image(cv::Rect(sx, sy, n, n)).clone();
    r.ok = true;
    return r;
}

}  // namespace lwb::core::footprint
