#include "core/radiometry/mosaic.hpp"
#include "core/radiometry/radiometry_params.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <unistd.h>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/atomic_file.hpp"
#include "core/common/image_header.hpp"
#include "core/common/text.hpp"

namespace lwb::core::radiometry {

const char* featureTypeName(FeatureType f) { return f == FeatureType::Akaze ? "akaze" : "orb"; }
const char* motionModelName(MotionModel m) {
    switch (m) {
        case MotionModel::Translation: return "translation";
        case MotionModel::Similarity: return "similarity";
        case MotionModel::Affine: return "affine";
        case MotionModel::Homography: return "homography";
    }
    return "?";
}
const char* blendModeName(BlendMode b) {
    return b == BlendMode::Feather ? "feather" : b == BlendMode::Average ? "average" : "first";
}
bool parseFeatureType(const std::string& s, FeatureType* f) {
    const std::string t = toLower(s);
    if (t == "orb") *f = FeatureType::Orb;
    else if (t == "akaze") *f = FeatureType::Akaze;
    else return false;
    return true;
}
bool parseMotionModel(const std::string& s, MotionModel* m) {
    const std::string t = toLower(s);
    if (t == "translation") *m = MotionModel::Translation;
    else if (t == "similarity") *m = MotionModel::Similarity;
    else if (t == "affine") *m = MotionModel::Affine;
    else if (t == "homography") *m = MotionModel::Homography;
    else return false;
    return true;
}
bool parseBlendMode(const std::string& s, BlendMode* b) {
    const std::string t = toLower(s);
    if (t == "feather") *b = BlendMode::Feather;
    else if (t == "average") *b = BlendMode::Average;
    else if (t == "first") *b = BlendMode::First;
    else return false;
    return true;
}

std::string validate(const MosaicParams& p) {
    RadiometryParams r;  // the ranges of the schema's rows (radiometry_params.cpp)
    r.mosaic = p;
    return radiometrySchema().validate(r, "mosaic.");
}

namespace {

// 8-bit views for the detectors with one contrast stretch (0.5–99.5 % percentiles) for every
// frame (same scene, same exposure): the detectors' thresholds assume a full 0..255 range, and a
// dull 8-bit frame left as it is yields few keypoints.
std::vector<cv::Mat> to8bit(const std::vector<cv::Mat>& frames) {
    std::vector<cv::Mat> out;
    std::vector<float> sample;
    for (const auto& f : frames) {
        cv::Mat g;
        f.convertTo(g, CV_32F);
        const int step = std::max(1, static_cast<int>(std::sqrt(g.total() / 20000.0)));
        for (int y = 0; y < g.rows; y += step)
            for (int x = 0; x < g.cols; x += step)
                if (std::isfinite(g.at<float>(y, x))) sample.push_back(g.at<float>(y, x));
    }
    double lo = 0, hi = 1;
    if (!sample.empty()) {
        std::sort(sample.begin(), sample.end());
        lo = sample[sample.size() / 200];
        hi = sample[sample.size() - 1 - sample.size() / 200];
        if (!(hi > lo)) hi = lo + 1;
    }
    for (const auto& f : frames) {
        cv::Mat g;
        f.convertTo(g, CV_8U, 255.0 / (hi - lo), -lo * 255.0 / (hi - lo));
        out.push_back(g);
    }
    return out;
}

// ---- the stages of mosaicRow ----------------------------------------------------------------

// The frames: at least two, single-channel, one depth, at least 16x16. "" when fine.
std::string checkFrames(const std::vector<cv::Mat>& frames) {
    if (frames.size() < 2) return "a row mosaic needs at least two frames";
    const int depth = frames[0].depth();
    for (size_t i = 0; i < frames.size(); ++i) {
        const cv::Mat& f = frames[i];
        if (f.empty() || f.channels() != 1) return "frame " + std::to_string(i + 1) + " is empty or not single-channel";
        if (f.depth() != depth || (depth != CV_8U && depth != CV_16U && depth != CV_32F))
            return "frame " + std::to_string(i + 1) + ": every frame must share one depth (8-bit, 16-bit or 32-bit float)";
        if (f.cols < 16 || f.rows < 16) return "frame " + std::to_string(i + 1) + " is smaller than 16x16";
    }
    return {};
}

// Keypoints and descriptors of every frame (progress 0..0.5). False when cancelled.
bool detectFeatures(const std::vector<cv::Mat>& frames, const MosaicParams& params, const Feedback* fb,
                    std::vector<std::vector<cv::KeyPoint>>* kps, std::vector<cv::Mat>* desc) {
    const std::vector<cv::Mat> g8 = to8bit(frames);
    cv::Ptr<cv::Feature2D> det;
    if (params.features == FeatureType::Orb)
        det = cv::ORB::create(params.maxFeatures);
    else
        det = cv::AKAZE::create();
    kps->assign(frames.size(), {});
    desc->assign(frames.size(), cv::Mat());
    for (size_t i = 0; i < frames.size(); ++i) {
        if (cancelled(fb)) return false;
        det->detectAndCompute(g8[i], cv::noArray(), (*kps)[i], (*desc)[i]);
        if (fb) fb->setProgress(0.5 * (i + 1) / frames.size());
    }
    return true;
}

// Translation: exhaustive consensus over (up to 500) single-match hypotheses (deterministic),
// refined three times over its inliers.
cv::Matx33d translationConsensus(const std::vector<cv::Point2f>& pTo, const std::vector<cv::Point2f>& pFrom, double thr,
                                 std::vector<uchar>* inl) {
    const size_t n = pTo.size(), stride = std::max<size_t>(1, n / 500);
    size_t bestCount = 0;
    cv::Point2d best;
    for (size_t k = 0; k < n; k += stride) {
        const cv::Point2d s = cv::Point2d(pFrom[k]) - cv::Point2d(pTo[k]);
        size_t c = 0;
        for (size_t j = 0; j < n; ++j)
            if (cv::norm(cv::Point2d(pFrom[j]) - cv::Point2d(pTo[j]) - s) < thr) ++c;
        if (c > bestCount) {
            bestCount = c;
            best = s;
        }
    }
    for (int pass = 0; pass < 3; ++pass) {
        cv::Point2d m(0, 0);
        int c = 0;
        inl->assign(n, 0);
        for (size_t j = 0; j < n; ++j)
            if (cv::norm(cv::Point2d(pFrom[j]) - cv::Point2d(pTo[j]) - best) < thr) {
                (*inl)[j] = 1;
                m += cv::Point2d(pFrom[j]) - cv::Point2d(pTo[j]);
                ++c;
            }
        if (c) best = m / c;
    }
    return cv::Matx33d(1, 0, best.x, 0, 1, best.y, 0, 0, 1);
}

// Frame i onto frame i - 1: ratio-tested matches, the model's robust fit, its inliers, RMS,
// shift, rotation and scale. "" when fine, else why (warnings go to *warnings).
std::string registerPair(size_t i, const std::vector<std::vector<cv::KeyPoint>>& kps, const std::vector<cv::Mat>& desc,
                         const MosaicParams& params, PairRegistration* out, std::vector<std::string>* warnings) {
    PairRegistration pr;
    pr.from = i - 1;
    pr.to = i;
    pr.keypointsFrom = static_cast<int>(kps[i - 1].size());
    pr.keypointsTo = static_cast<int>(kps[i].size());
    std::vector<cv::Point2f> pTo, pFrom;
    if (!desc[i].empty() && !desc[i - 1].empty()) {
        cv::BFMatcher matcher(cv::NORM_HAMMING);
        std::vector<std::vector<cv::DMatch>> knn;
        matcher.knnMatch(desc[i], desc[i - 1], knn, 2);
        for (const auto& m : knn) {
            if (m.size() < 2 || m[0].distance >= params.ratioTest * m[1].distance) continue;
            pTo.push_back(kps[i][m[0].queryIdx].pt);
            pFrom.push_back(kps[i - 1][m[0].trainIdx].pt);
        }
    }
    pr.matches = static_cast<int>(pTo.size());
    const std::string pairName = "frames " + std::to_string(i) + " and " + std::to_string(i + 1);
    if (pr.matches < params.minInliers)
        return pairName + ": only " + std::to_string(pr.matches) + " distinctive matches (need " +
               std::to_string(params.minInliers) + "): too little overlap or texture, or frames out of order?";
    cv::Matx33d h = cv::Matx33d::eye();
    std::vector<uchar> inl;
    const double thr = params.ransacThresholdPx;
    if (params.model == MotionModel::Translation) {
        h = translationConsensus(pTo, pFrom, thr, &inl);
    } else if (params.model == MotionModel::Homography) {
        const cv::Mat H = cv::findHomography(pTo, pFrom, cv::RANSAC, thr, inl, 2000, 0.995);
        if (H.empty()) return pairName + ": no homography found";
        h = cv::Matx33d(H);
    } else {
        const cv::Mat A = params.model == MotionModel::Similarity
                              ? cv::estimateAffinePartial2D(pTo, pFrom, inl, cv::RANSAC, thr, 2000, 0.995, 10)
                              : cv::estimateAffine2D(pTo, pFrom, inl, cv::RANSAC, thr, 2000, 0.995, 10);
        if (A.empty()) return pairName + ": no " + motionModelName(params.model) + " transform found";
        const cv::Mat_<double> a(A);
        h = cv::Matx33d(a(0, 0), a(0, 1), a(0, 2), a(1, 0), a(1, 1), a(1, 2), 0, 0, 1);
    }
    double ss = 0;
    int ni = 0;
    for (size_t j = 0; j < inl.size(); ++j)
        if (inl[j]) {
            const cv::Point2d q = applyHomography(h, pTo[j].x, pTo[j].y);
            ss += std::pow(cv::norm(q - cv::Point2d(pFrom[j])), 2);
            ++ni;
        }
    pr.inliers = ni;
    pr.rmsPx = ni ? std::sqrt(ss / ni) : NAN;
    pr.transform = h;
    const cv::Point2d o = applyHomography(h, 0, 0);
    pr.shiftX = o.x;
    pr.shiftY = o.y;
    pr.scale = std::sqrt(std::fabs(h(0, 0) * h(1, 1) - h(0, 1) * h(1, 0)));
    pr.rotationDeg = std::atan2(h(1, 0), h(0, 0)) * 180 / M_PI;
    if (ni < params.minInliers)
        return pairName + ": only " + std::to_string(ni) + " consistent matches (need " + std::to_string(params.minInliers) + ")";
    if (std::fabs(pr.rotationDeg) > params.maxRotationDeg)
        warnings->push_back(pairName + ": rotated by " + formatFixed(pr.rotationDeg, 2) + " degrees");
    if (std::fabs(pr.scale - 1) > params.maxScaleChange)
        warnings->push_back(pairName + ": scale changes by " + formatFixed(100 * (pr.scale - 1), 1) + " %");
    *out = pr;
    return {};
}

// The bounding box of frame `f` under transform m (pixel edges, not centres).
void frameBounds(const cv::Mat& f, const cv::Matx33d& m, double* x0, double* y0, double* x1, double* y1) {
    const double w = f.cols - 0.5, hh = f.rows - 0.5;
    for (const cv::Point2d c : {cv::Point2d(-0.5, -0.5), cv::Point2d(w, -0.5), cv::Point2d(-0.5, hh), cv::Point2d(w, hh)}) {
        const cv::Point2d p = applyHomography(m, c.x, c.y);
        *x0 = std::min(*x0, p.x);
        *y0 = std::min(*y0, p.y);
        *x1 = std::max(*x1, p.x);
        *y1 = std::max(*y1, p.y);
    }
}

// Adds frame f, warped by m, into the canvas sums inside box (feathered, averaged or first-wins).
void blendFrame(const cv::Mat& frame, const cv::Matx33d& m, const cv::Rect& box, BlendMode blend, cv::Mat& sum, cv::Mat& wsum) {
    const cv::Matx33d local = cv::Matx33d(1, 0, -box.x, 0, 1, -box.y, 0, 0, 1) * m;
    cv::Mat f, warped, mask, weight;
    frame.convertTo(f, CV_32F);
    cv::warpPerspective(f, warped, cv::Mat(local), box.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    cv::Mat ones(f.size(), CV_32F, cv::Scalar(1));
    cv::warpPerspective(ones, mask, cv::Mat(local), box.size(), cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar(0));
    cv::Mat valid = mask > 0.999f;
    if (blend == BlendMode::Feather) {
        cv::Mat pad(f.rows + 2, f.cols + 2, CV_8U, cv::Scalar(0)), dist;
        pad(cv::Rect(1, 1, f.cols, f.rows)).setTo(255);
        cv::distanceTransform(pad, dist, cv::DIST_L2, 3);
        cv::warpPerspective(dist(cv::Rect(1, 1, f.cols, f.rows)), weight, cv::Mat(local), box.size(), cv::INTER_LINEAR,
                            cv::BORDER_CONSTANT, cv::Scalar(0));
    } else {
        weight = cv::Mat(box.size(), CV_32F, cv::Scalar(1));
    }
    cv::Mat zero = weight.clone();
    zero.setTo(0, ~valid);
    weight = zero;
    cv::Mat s = sum(box), ws = wsum(box);
    if (blend == BlendMode::First) {
        cv::Mat empty = ws == 0;
        cv::Mat take = valid & empty;
        warped.copyTo(s, take);
        ws.setTo(1, take);
    } else {
        s += warped.mul(weight);
        ws += weight;
    }
}

// The canvas holding every registered frame and the blend into it (progress 0.5..1): fills
// res.image, res.coverage and shifts res.frameToMosaic onto the canvas. "" when fine.
std::string composeCanvas(const std::vector<cv::Mat>& frames, const MosaicParams& params, const Feedback* fb, MosaicResult& res) {
    double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
    for (size_t i = 0; i < frames.size(); ++i) frameBounds(frames[i], res.frameToMosaic[i], &minX, &minY, &maxX, &maxY);
    const double cw = std::ceil(maxX - minX), ch = std::ceil(maxY - minY);
    if (!std::isfinite(cw) || !std::isfinite(ch) || cw > 32000 || ch > 32000 || cw * ch > params.maxCanvasPixels)
        return "the mosaic would be " + formatFixed(cw, 0) + "x" + formatFixed(ch, 0) +
               " pixels: too large (a registration went wrong, or raise the limit)";
    const double ox = std::floor(minX + 0.5), oy = std::floor(minY + 0.5);  // frame 0 stays on the pixel grid
    const cv::Matx33d shift(1, 0, -ox, 0, 1, -oy, 0, 0, 1);
    const cv::Size canvas(static_cast<int>(std::ceil(maxX - ox + 0.5)), static_cast<int>(std::ceil(maxY - oy + 0.5)));
    cv::Mat sum(canvas, CV_32F, cv::Scalar(0)), wsum(canvas, CV_32F, cv::Scalar(0));
    for (size_t i = 0; i < frames.size(); ++i) {
        if (cancelled(fb)) return "cancelled";
        res.frameToMosaic[i] = shift * res.frameToMosaic[i];
        const cv::Matx33d& m = res.frameToMosaic[i];
        double bx0 = INFINITY, by0 = INFINITY, bx1 = -INFINITY, by1 = -INFINITY;
        frameBounds(frames[i], m, &bx0, &by0, &bx1, &by1);
        const cv::Rect box = cv::Rect(cv::Point(static_cast<int>(std::floor(bx0)), static_cast<int>(std::floor(by0))),
                                      cv::Point(static_cast<int>(std::ceil(bx1)) + 1, static_cast<int>(std::ceil(by1)) + 1)) &
                             cv::Rect(0, 0, canvas.width, canvas.height);
        if (box.empty()) continue;
        blendFrame(frames[i], m, box, params.blend, sum, wsum);
        if (fb) fb->setProgress(0.5 + 0.5 * (i + 1) / frames.size());
    }
    res.coverage = wsum > 0;
    cv::Mat avg;
    cv::divide(sum, cv::max(wsum, 1e-12f), avg);
    avg.setTo(0, ~res.coverage);
    avg.convertTo(res.image, frames[0].depth());
    return {};
}

}  // namespace

// Stages: checkFrames -> detectFeatures -> registerPair (each neighbour pair, chained to frame 0)
// -> composeCanvas (canvas, blend).
MosaicResult mosaicRow(const std::vector<cv::Mat>& frames, const MosaicParams& params, const Feedback* fb) {
    MosaicResult res;
    if (const std::string e = validate(params); !e.empty()) {
        res.error = e;
        return res;
    }
    if (const std::string e = checkFrames(frames); !e.empty()) {
        res.error = e;
        return res;
    }
    try {
        std::vector<std::vector<cv::KeyPoint>> kps;
        std::vector<cv::Mat> desc;
        if (!detectFeatures(frames, params, fb, &kps, &desc)) {
            res.error = "cancelled";
            return res;
        }
        res.frameToMosaic.assign(frames.size(), cv::Matx33d::eye());
        for (size_t i = 1; i < frames.size(); ++i) {
            if (cancelled(fb)) {
                res.error = "cancelled";
                return res;
            }
            PairRegistration pr;
            if (std::string e = registerPair(i, kps, desc, params, &pr, &res.warnings); !e.empty()) {
                res.error = e;
                return res;
            }
            res.frameToMosaic[i] = res.frameToMosaic[i - 1] * pr.transform;
            res.pairs.push_back(pr);
        }
        if (std::string e = composeCanvas(frames, params, fb, res); !e.empty()) {
            res.error = e;
            return res;
        }
    } catch (const cv::Exception& e) {
        res.error = std::string("mosaic failed: ") + e.what();
        return res;
    }
    res.ok = true;
    return res;
}

bool writePairCsv(const std::string& path, const MosaicResult& r, std::string* error) {
    std::string s = "from,to,keypoints_from,keypoints_to,matches,inliers,rms_px,shift_x,shift_y,rotation_deg,scale\n";
    for (const auto& p : r.pairs)
        s += std::to_string(p.from + 1) + "," + std::to_string(p.to + 1) + "," + std::to_string(p.keypointsFrom) + "," +
             std::to_string(p.keypointsTo) + "," + std::to_string(p.matches) + "," + std::to_string(p.inliers) + "," +
             formatFixed(p.rmsPx, 4) + "," + formatFixed(p.shiftX, 3) + "," + formatFixed(p.shiftY, 3) + "," +
             formatFixed(p.rotationDeg, 4) + "," + formatFixed(p.scale, 6) + "\n";
    return writeFileAtomic(path, s, error);
}

double mosaicPeakBytes(const std::vector<long long>& framePixels) {
    double total = 0, pair = 0;
    for (size_t i = 0; i < framePixels.size(); ++i) {
        total += double(framePixels[i]);
        if (i > 0) pair = std::max(pair, double(framePixels[i - 1]) + double(framePixels[i]));
    }
    if (framePixels.size() == 1) pair = double(framePixels[0]);
    return 70e6 + 64 * pair + 8 * total;
}

double memoryBudgetBytes() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), size = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && size > 0 ? 0.75 * double(pages) * double(size) : 8e9;
}

std::string mosaicMemoryProblem(const std::vector<std::string>& paths, double budgetBytes) {
    std::vector<long long> px;
    for (const std::string& p : paths) {
        // The first 64 KiB hold the size of a PNG, PGM or JPEG and of most TIFFs; a TIFF whose
        // first directory lies further on is read whole (the frames are read again to decode).
        std::string bytes, err;
        if (!readFileHead(p, 1 << 16, &bytes, &err)) return {};  // the decoder says why
        ImageHeader h = readImageHeader(bytes);
        if (!h.complete && bytes.size() == (1u << 16)) {
            if (!readFileBytes(p, &bytes, &err)) return {};
            h = readImageHeader(bytes);
        }
        if (!h.complete) return {};
        px.push_back(h.width * h.height);
    }
    const double peak = mosaicPeakBytes(px);
    if (peak <= budgetBytes) return {};
    double total = 0;
    for (long long n : px) total += double(n);
    return "the " + std::to_string(paths.size()) + " frames (" + formatFixed(total / 1e6, 1) +
           " Mpx together) would take about " + formatFixed(peak / 1e9, 1) + " GB to mosaic, more than this machine's budget of " +
           formatFixed(budgetBytes / 1e9, 1) + " GB (3/4 of its memory): mosaic smaller or downsampled frames, or fewer at a time";
}

}  // namespace lwb::core::radiometry
