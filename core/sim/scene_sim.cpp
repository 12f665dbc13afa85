#include "core/sim/scene_sim.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/rng.hpp"

namespace lwb::core::sim {

cv::Mat simulateScene(const SceneSimParams& p, uint64_t seed) {
    Rng rng(seed);
    cv::Mat img(p.height, p.width, CV_32F, cv::Scalar(p.meanDn));
    for (int i = 0; i < p.features; ++i) {
        const double level = p.meanDn + rng.uniform(-1, 1) * p.contrastDn;
        // Draws as named values (a constructor's arguments are evaluated in an unspecified order:
        // GCC right to left, clang left to right); the order is the one GCC builds always had.
        const double cy = rng.uniform(0, p.height), cx = rng.uniform(0, p.width);
        const cv::Point c(static_cast<int>(cx), static_cast<int>(cy));
        const int kind = static_cast<int>(rng.uniform(0, 3));
        if (kind == 0) {  // slab
            const double sh = rng.uniform(8, 80), sw = rng.uniform(8, 80);
            const cv::Size s(static_cast<int>(sw), static_cast<int>(sh));
            const cv::RotatedRect r(c, s, static_cast<float>(rng.uniform(0, 180)));
            cv::Point2f v[4];
            r.points(v);
            std::vector<cv::Point> poly(v, v + 4);
            cv::fillConvexPoly(img, poly, cv::Scalar(level), cv::LINE_AA);
        } else if (kind == 1) {  // blob
            const double angle = rng.uniform(0, 180), ah = rng.uniform(3, 30), aw = rng.uniform(3, 30);
            cv::ellipse(img, c, cv::Size(static_cast<int>(aw), static_cast<int>(ah)), angle, 0, 360, cv::Scalar(level),
                        cv::FILLED, cv::LINE_AA);
        } else {  // joint / crack
            const double dy = rng.uniform(-120, 120), dx = rng.uniform(-120, 120);
            const cv::Point d(static_cast<int>(dx), static_cast<int>(dy));
            cv::line(img, c, c + d, cv::Scalar(level), static_cast<int>(rng.uniform(1, 4)), cv::LINE_AA);
        }
    }
    cv::Mat grain(p.height, p.width, CV_32F);
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) grain.at<float>(y, x) = static_cast<float>(rng.normal());
    cv::GaussianBlur(grain, grain, cv::Size(0, 0), p.grainSigmaPx);
    cv::Scalar m, s;
    cv::meanStdDev(grain, m, s);
    img += grain * (p.grainDn / std::max(s[0], 1e-9));
    return img;
}

RowFrames simulateRowFrames(const RowFramesParams& p, const SceneSimParams& sceneParams, uint64_t seed) {
    RowFrames out;
    Rng rng(Rng::mix(seed, 1));
    const int step = static_cast<int>(std::lround(p.frameWidth * (1 - p.overlap)));
    const int margin = p.jitterPx + 2;
    SceneSimParams sp = sceneParams;
    sp.width = (p.frames - 1) * step + p.frameWidth + 2 * margin;
    sp.height = p.frameHeight + 2 * margin;
    out.scene = simulateScene(sp, seed);
    for (int k = 0; k < p.frames; ++k) {
        const int jx = static_cast<int>(std::lround(rng.uniform(-p.jitterPx, p.jitterPx)));
        const int jy = static_cast<int>(std::lround(rng.uniform(-p.jitterPx, p.jitterPx)));
        const cv::Point o(margin + k * step + jx, margin + jy);
        cv::Mat f = out.scene(cv::Rect(o, cv::Size(p.frameWidth, p.frameHeight))).clone();
        for (int y = 0; y < f.rows; ++y)
            for (int x = 0; x < f.cols; ++x) f.at<float>(y, x) += static_cast<float>(rng.normal(0, p.noiseDn));
        cv::Mat g;
        f.convertTo(g, p.depth, p.depth == CV_8U ? 1.0 / 256 : 1.0);
        out.frames.push_back(g);
        out.offsets.push_back(o);
    }
    return out;
}

}  // namespace lwb::core::sim
