#include "core/radiometry/gcp.hpp"
#include "core/radiometry/mosaic.hpp"
#include "core/radiometry/radiometry_params.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/text.hpp"

namespace lwb::core::radiometry {

namespace {
std::string gcpName(const Gcp& g, size_t i) {
    std::string s = "GCP " + (g.id.empty() ? std::to_string(i + 1) : g.id);
    if (g.line > 0) s += " (line " + std::to_string(g.line) + ")";
    return s;
}
// Ratio of the spread across the best-fitting line to the spread along it.
double lineRatio(const std::vector<Eigen::Vector2d>& p) {
    Eigen::Vector2d m = Eigen::Vector2d::Zero();
    for (const auto& v : p) m += v;
    m /= static_cast<double>(p.size());
    Eigen::Matrix2d s = Eigen::Matrix2d::Zero();
    for (const auto& v : p) s += (v - m) * (v - m).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(s);
    const double l1 = std::max(es.eigenvalues()(1), 0.0), l0 = std::max(es.eigenvalues()(0), 0.0);
    return l1 > 0 ? std::sqrt(l0 / l1) : 0.0;
}
}  // namespace

const char* geoModelName(GeoModel m) { return m == GeoModel::Homography ? "homography" : "affine"; }

bool parseGeoModel(const std::string& s, GeoModel* m) {
    const std::string t = toLower(s);
    if (t == "affine") *m = GeoModel::Affine;
    else if (t == "homography" || t == "projective") *m = GeoModel::Homography;
    else return false;
    return true;
}

bool readGcpCsv(const std::string& path, std::vector<Gcp>* out, std::string* error) {
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        *error = csv.error;
        return false;
    }
    const CsvTable& t = csv.table;
    const int cid = t.firstColumn({"id", "name", "marker"});
    const int cx = t.firstColumn({"x", "col", "px"}), cy = t.firstColumn({"y", "row", "py"});
    const int mx = t.firstColumn({"map_x", "mapx", "e", "east"}), my = t.firstColumn({"map_y", "mapy", "n", "north"});
    if (cx < 0 || cy < 0 || mx < 0 || my < 0) {
        *error = path + ":1: header needs x, y (image px) and map_x, map_y (map m)";
        return false;
    }
    std::vector<Gcp> v;
    for (size_t i = 0; i < t.rows.size(); ++i) {
        const auto& row = t.rows[i];
        Gcp g;
        g.line = t.lines[i];
        g.id = cid >= 0 ? std::string(trim(row[cid])) : std::to_string(i + 1);
        if (!parseDouble(row[cx], &g.x) || !parseDouble(row[cy], &g.y) || !parseDouble(row[mx], &g.mapX) ||
            !parseDouble(row[my], &g.mapY)) {
            *error = whereInFile(path, t.lines[i]) + "x, y, map_x, map_y must be finite numbers";
            return false;
        }
        v.push_back(std::move(g));
    }
    if (v.empty()) {
        *error = path + ": no GCP rows";
        return false;
    }
    *out = std::move(v);
    return true;
}

std::string validate(const GcpFitParams& p) {
    RadiometryParams r;  // the ranges of the schema's rows (radiometry_params.cpp)
    r.gcp = p;
    return radiometrySchema().validate(r, "gcp.");
}

namespace {

// The GCPs' image and map positions: finite, no position repeated, not collinear. False with
// res->error.
bool gcpPositions(const std::vector<Gcp>& gcps, const GcpFitParams& params, std::vector<Eigen::Vector2d>& img,
                  std::vector<Eigen::Vector2d>& map, GcpFitResult* res) {
    const int n = static_cast<int>(gcps.size());
    for (int i = 0; i < n; ++i) {
        const Gcp& g = gcps[i];
        if (!std::isfinite(g.x) || !std::isfinite(g.y) || !std::isfinite(g.mapX) || !std::isfinite(g.mapY)) {
            res->error = gcpName(g, i) + ": non-finite coordinates";
            return false;
        }
        for (int j = 0; j < i; ++j) {
            if (gcps[j].x == g.x && gcps[j].y == g.y) {
                res->error = gcpName(g, i) + " repeats the image position of " + gcpName(gcps[j], j);
                return false;
            }
            if (gcps[j].mapX == g.mapX && gcps[j].mapY == g.mapY) {
                res->error = gcpName(g, i) + " repeats the map position of " + gcpName(gcps[j], j);
                return false;
            }
        }
        img.emplace_back(g.x, g.y);
        map.emplace_back(g.mapX, g.mapY);
    }
    const double ri = lineRatio(img), rm = lineRatio(map);
    if (ri <= params.collinearTolerance || rm <= params.collinearTolerance) {
        res->error = "the " + std::to_string(n) + " GCPs are collinear (" + (ri <= params.collinearTolerance ? "image" : "map") +
                     " spread across their line is " + formatDouble(100 * std::min(ri, rm), 3) +
                     " % of the spread along it): the transform is undetermined across the line";
        return false;
    }
    return true;
}

// A homography needs four GCPs no three of which are on a line (when only four are given), and
// a normalised DLT system of rank 8. False with res->error.
bool homographyDetermined(const std::vector<Eigen::Vector2d>& img, const std::vector<Eigen::Vector2d>& map,
                          const GcpFitParams& params, GcpFitResult* res) {
    const int n = static_cast<int>(img.size());
    // No three of any four on a line when only four are given; the general case is caught by
    // the rank of the normalised DLT system.
    if (n == 4) {
        for (int a = 0; a < 4; ++a) {
            std::vector<Eigen::Vector2d> tri, trm;
            for (int k = 0; k < 4; ++k)
                if (k != a) {
                    tri.push_back(img[k]);
                    trm.push_back(map[k]);
                }
            if (lineRatio(tri) <= params.collinearTolerance || lineRatio(trm) <= params.collinearTolerance) {
                res->error = "three of the four GCPs lie on one line: the homography is degenerate";
                return false;
            }
        }
    }
    auto normaliser = [](const std::vector<Eigen::Vector2d>& p) {
        Eigen::Vector2d m = Eigen::Vector2d::Zero();
        for (const auto& v : p) m += v;
        m /= static_cast<double>(p.size());
        double d = 0;
        for (const auto& v : p) d += (v - m).norm();
        const double s = std::sqrt(2.0) / std::max(d / p.size(), 1e-300);
        Eigen::Matrix3d t;
        t << s, 0, -s * m.x(), 0, s, -s * m.y(), 0, 0, 1;
        return t;
    };
    const Eigen::Matrix3d ti = normaliser(img), tm = normaliser(map);
    Eigen::MatrixXd A(2 * n, 9);
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d p = ti * Eigen::Vector3d(img[i].x(), img[i].y(), 1);
        const Eigen::Vector3d q = tm * Eigen::Vector3d(map[i].x(), map[i].y(), 1);
        A.row(2 * i) << p.x(), p.y(), 1, 0, 0, 0, -q.x() * p.x(), -q.x() * p.y(), -q.x();
        A.row(2 * i + 1) << 0, 0, 0, p.x(), p.y(), 1, -q.y() * p.x(), -q.y() * p.y(), -q.y();
    }
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
    const Eigen::VectorXd s = svd.singularValues();
    if (s.size() < 9 || !(s(7) > 1e-8 * s(0))) {
        res->error = "the GCPs do not determine a homography (degenerate configuration)";
        return false;
    }
    return true;
}

// The least-squares transform image → map: a homography (OpenCV), or an affine in centred
// coordinates. False with res->error.
bool fitTransform(const std::vector<Eigen::Vector2d>& img, const std::vector<Eigen::Vector2d>& map, bool homog,
                  cv::Matx33d* out, GcpFitResult* res) {
    const int n = static_cast<int>(img.size());
    cv::Matx33d h = cv::Matx33d::eye();
    try {
        std::vector<cv::Point2d> src, dst;
        for (int i = 0; i < n; ++i) {
            src.emplace_back(img[i].x(), img[i].y());
            dst.emplace_back(map[i].x(), map[i].y());
        }
        if (homog) {
            const cv::Mat H = cv::findHomography(src, dst, 0);
            if (H.empty()) {
                res->error = "the homography fit failed (degenerate GCPs)";
                return false;
            }
            h = cv::Matx33d(H);
        } else {
            // Least squares in centred coordinates: [X Y] = [x−mx, y−my, 1]·P.
            Eigen::Vector2d m = Eigen::Vector2d::Zero();
            for (const auto& v : img) m += v;
            m /= n;
            Eigen::MatrixXd M(n, 3), Y(n, 2);
            for (int i = 0; i < n; ++i) {
                M.row(i) << img[i].x() - m.x(), img[i].y() - m.y(), 1;
                Y.row(i) << map[i].x(), map[i].y();
            }
            const Eigen::MatrixXd P = M.colPivHouseholderQr().solve(Y);
            h = cv::Matx33d(P(0, 0), P(1, 0), P(2, 0) - P(0, 0) * m.x() - P(1, 0) * m.y(),  //
                            P(0, 1), P(1, 1), P(2, 1) - P(0, 1) * m.x() - P(1, 1) * m.y(),  //
                            0, 0, 1);
        }
    } catch (const cv::Exception& e) {
        res->error = std::string("the transform fit failed: ") + e.what();
        return false;
    }
    *out = h;
    return true;
}

// Each GCP's residual in map units and in pixels, and their RMS.
void gcpResiduals(const std::vector<Gcp>& gcps, const std::vector<Eigen::Vector2d>& img,
                  const std::vector<Eigen::Vector2d>& map, GcpFitResult* res) {
    const int n = static_cast<int>(gcps.size());
    double sm = 0, sp = 0;
    for (int i = 0; i < n; ++i) {
        GcpResidual r;
        r.id = gcps[i].id.empty() ? std::to_string(i + 1) : gcps[i].id;
        const cv::Point2d pm = applyHomography(res->imageToMap, img[i].x(), img[i].y());
        const cv::Point2d pi = applyHomography(res->mapToImage, map[i].x(), map[i].y());
        r.dMapX = pm.x - map[i].x();
        r.dMapY = pm.y - map[i].y();
        r.dx = pi.x - img[i].x();
        r.dy = pi.y - img[i].y();
        r.mapNorm = std::hypot(r.dMapX, r.dMapY);
        r.pxNorm = std::hypot(r.dx, r.dy);
        sm += r.mapNorm * r.mapNorm;
        sp += r.pxNorm * r.pxNorm;
        res->residuals.push_back(r);
    }
    res->rmsMap = std::sqrt(sm / n);
    res->rmsPx = std::sqrt(sp / n);
}

// The ground size of an image pixel at the GCPs' centre (the Jacobian's determinant).
double metresPerPixelAt(const std::vector<Eigen::Vector2d>& img, const cv::Matx33d& imageToMap) {
    const int n = static_cast<int>(img.size());
    Eigen::Vector2d m = Eigen::Vector2d::Zero();
    for (const auto& v : img) m += v;
    m /= n;
    const double e = 1e-3;
    const cv::Point2d a = applyHomography(imageToMap, m.x(), m.y()), bx = applyHomography(imageToMap, m.x() + e, m.y()),
                      by = applyHomography(imageToMap, m.x(), m.y() + e);
    const double det = ((bx.x - a.x) * (by.y - a.y) - (by.x - a.x) * (bx.y - a.y)) / (e * e);
    return std::sqrt(std::fabs(det));
}

}  // namespace

GcpFitResult fitGcpTransform(const std::vector<Gcp>& gcps, const GcpFitParams& params) {
    GcpFitResult res;
    res.model = params.model;
    if (const std::string e = validate(params); !e.empty()) {
        res.error = e;
        return res;
    }
    const int n = static_cast<int>(gcps.size());
    const bool homog = params.model == GeoModel::Homography;
    const int np = homog ? 8 : 6;
    const int need = homog ? 4 : 3;
    if (n < need) {
        res.error = "only " + std::to_string(n) + " GCP" + (n == 1 ? "" : "s") + ": the " + geoModelName(params.model) +
                    " model needs at least " + std::to_string(need);
        return res;
    }
    std::vector<Eigen::Vector2d> img, map;
    if (!gcpPositions(gcps, params, img, map, &res)) return res;
    if (homog && !homographyDetermined(img, map, params, &res)) return res;
    cv::Matx33d h = cv::Matx33d::eye();
    if (!fitTransform(img, map, homog, &h, &res)) return res;
    bool invertible = false;
    const cv::Matx33d inv = h.inv(cv::DECOMP_LU, &invertible);
    if (!invertible || std::fabs(cv::determinant(h)) < 1e-300) {
        res.error = "the fitted transform is singular";
        return res;
    }
    res.imageToMap = h * (1.0 / h(2, 2));
    res.mapToImage = inv * (1.0 / inv(2, 2));
    gcpResiduals(gcps, img, map, &res);
    res.dof = 2 * n - np;
    if (res.dof == 0)
        res.warnings.push_back("as many equations as parameters: the GCP residuals are zero and do not measure accuracy");
    // Each GCP against the transform of the others (when they still over-determine it): the
    // miss of the left-out GCP, in standard deviations of such a miss. Its variance is the others'
    // residual variance (per coordinate, over their degrees of freedom) over 1 - h_ii, the GCP's
    // leverage among the GCPs judged (of the affine design [x y 1]; for a homography an
    // approximation): a corner GCP is predicted by extrapolation and may miss by more. The worst
    // GCP beyond the limit is named and set aside, and the rest judged again without it (an
    // outlier among the others would make a sound GCP look wrong).
    std::vector<int> active(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) active[static_cast<size_t>(i)] = i;
    GcpFitParams inner = params;
    inner.leaveOneOut = false;
    while (params.leaveOneOut && 2 * (static_cast<int>(active.size()) - 1) - np >= 2) {
        const int m = static_cast<int>(active.size());
        Eigen::MatrixXd X(m, 3);
        for (int a = 0; a < m; ++a) X.row(a) << img[active[a]].x(), img[active[a]].y(), 1.0;
        const Eigen::Matrix3d XtXi = (X.transpose() * X).inverse();
        int worst = -1;
        double worstRatio = 1, worstMiss = 0, worstZ = 0, worstRms = 0, worstMapMiss = 0;
        for (int a = 0; a < m; ++a) {
            const int i = active[a];
            std::vector<Gcp> others;
            for (int k : active)
                if (k != i) others.push_back(gcps[static_cast<size_t>(k)]);
            const GcpFitResult o = fitGcpTransform(others, inner);
            if (!o.ok || !(o.dof > 0)) continue;
            const cv::Point2d pi = applyHomography(o.mapToImage, map[i].x(), map[i].y());
            const double miss = std::hypot(pi.x - img[i].x(), pi.y - img[i].y());
            const double h = std::min(0.999, double(X.row(a) * XtXi * X.row(a).transpose()));
            const double sigma = o.rmsPx * std::sqrt((m - 1.0) / o.dof);  // per coordinate
            const double z = miss * std::sqrt(1 - h) / (std::sqrt(2.0) * std::max(sigma, 1e-12));
            // P(F(2, nu) > f) = (1 + 2 f / nu)^(-nu / 2): the z that a sound GCP exceeds with the
            // chosen probability (7.8 for nu = 4, 3.5 for nu = 20, at 0.001).
            const double nu = o.dof;
            const double zLimit = std::sqrt(nu / 2 * (std::pow(params.outlierProbability, -2 / nu) - 1));
            if (miss > 0.5 && z / zLimit > worstRatio) {
                const cv::Point2d pm = applyHomography(o.imageToMap, img[i].x(), img[i].y());
                worst = i, worstRatio = z / zLimit, worstMiss = miss, worstZ = z, worstRms = o.rmsPx;
                worstMapMiss = std::hypot(pm.x - map[i].x(), pm.y - map[i].y());
            }
        }
        if (worst < 0) break;
        res.outliers.push_back(static_cast<size_t>(worst));
        res.warnings.push_back(gcpName(gcps[static_cast<size_t>(worst)], static_cast<size_t>(worst)) +
                               ": the transform of the other GCPs puts it " + formatFixed(worstMapMiss, 3) + " m (" +
                               formatFixed(worstMiss, 2) + " px) away, " + formatFixed(worstZ, 1) +
                               " standard deviations of such a miss (they fit each other within " + formatFixed(worstRms, 3) +
                               " px RMS): a misplaced marker or a wrong coordinate?");
        active.erase(std::find(active.begin(), active.end(), worst));
    }
    std::sort(res.outliers.begin(), res.outliers.end());
    res.metresPerPixel = metresPerPixelAt(img, res.imageToMap);
    res.ok = true;
    return res;
}

MapGrid gridCovering(const GcpFitResult& fit, cv::Size size, double pixelSize) {
    MapGrid g;
    g.pixelSize = pixelSize;
    double minX = INFINITY, maxX = -INFINITY, minY = INFINITY, maxY = -INFINITY;
    const int steps = 32;
    for (int k = 0; k <= steps; ++k) {
        const double fx = -0.5 + (size.width) * double(k) / steps, fy = -0.5 + (size.height) * double(k) / steps;
        const cv::Point2d pts[4] = {applyHomography(fit.imageToMap, fx, -0.5), applyHomography(fit.imageToMap, fx, size.height - 0.5),
                                    applyHomography(fit.imageToMap, -0.5, fy), applyHomography(fit.imageToMap, size.width - 0.5, fy)};
        for (const auto& p : pts) {
            minX = std::min(minX, p.x);
            maxX = std::max(maxX, p.x);
            minY = std::min(minY, p.y);
            maxY = std::max(maxY, p.y);
        }
    }
    if (!(pixelSize > 0) || !std::isfinite(minX) || !std::isfinite(maxY)) return g;
    g.originX = minX + pixelSize / 2;
    g.originY = maxY - pixelSize / 2;
    g.width = static_cast<int>(std::min(1e9, std::ceil((maxX - minX) / pixelSize - 1e-6)));
    g.height = static_cast<int>(std::min(1e9, std::ceil((maxY - minY) / pixelSize - 1e-6)));
    return g;
}

WarpResult warpToMap(const cv::Mat& image, const GcpFitResult& fit, const MapGrid& grid) {
    WarpResult res;
    if (image.empty() || image.channels() != 1) {
        res.error = "the image must be a non-empty single-channel image";
        return res;
    }
    if (!(grid.pixelSize > 0) || grid.width < 1 || grid.height < 1) {
        res.error = "the map grid needs a pixel size > 0 and a size of at least 1x1";
        return res;
    }
    if (grid.width > 40000 || grid.height > 40000 || double(grid.width) * grid.height > 4e8) {
        res.error = "the map grid " + std::to_string(grid.width) + "x" + std::to_string(grid.height) +
                    " is too large (choose a coarser pixel size)";
        return res;
    }
    const cv::Matx33d g(grid.pixelSize, 0, grid.originX, 0, -grid.pixelSize, grid.originY, 0, 0, 1);
    const cv::Matx33d m = fit.mapToImage * g;  // map-grid pixel → image pixel
    try {
        cv::warpPerspective(image, res.image, cv::Mat(m), cv::Size(grid.width, grid.height),
                            cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_CONSTANT, cv::Scalar(0));
        cv::Mat ones(image.size(), CV_32F, cv::Scalar(1)), w;
        cv::warpPerspective(ones, w, cv::Mat(m), cv::Size(grid.width, grid.height), cv::INTER_LINEAR | cv::WARP_INVERSE_MAP,
                            cv::BORDER_CONSTANT, cv::Scalar(0));
        res.valid = w > 0.999f;
    } catch (const cv::Exception& e) {
        res.error = std::string("resampling failed: ") + e.what();
        return res;
    }
    res.ok = true;
    return res;
}

WarpResult mergeOnGrid(const std::vector<cv::Mat>& images, const std::vector<cv::Mat>& valid) {
    WarpResult res;
    if (images.empty() || images.size() != valid.size()) {
        res.error = "merge needs one validity mask per image";
        return res;
    }
    const cv::Size size = images[0].size();
    const int depth = images[0].depth();
    try {
        cv::Mat sum(size, CV_64F, cv::Scalar(0)), cnt(size, CV_64F, cv::Scalar(0));
        for (size_t i = 0; i < images.size(); ++i) {
            if (images[i].size() != size || valid[i].size() != size || images[i].channels() != 1 ||
                images[i].depth() != depth || valid[i].type() != CV_8UC1) {
                res.error = "map image " + std::to_string(i + 1) + " differs in size, depth or mask from the first";
                return res;
            }
            cv::Mat f;
            images[i].convertTo(f, CV_64F);
            cv::add(sum, f, sum, valid[i]);
            cv::add(cnt, cv::Scalar(1), cnt, valid[i]);
        }
        cv::Mat avg;
        cv::divide(sum, cv::max(cnt, 1.0), avg);
        avg.convertTo(res.image, depth);
        res.valid = cnt > 0;
    } catch (const cv::Exception& e) {
        res.error = std::string("merge failed: ") + e.what();
        return res;
    }
    res.ok = true;
    return res;
}

bool writeGcpResidualCsv(const std::string& path, const std::vector<Gcp>& gcps, const GcpFitResult& fit,
                         std::string* error) {
    std::string s = "id,x,y,map_x,map_y,d_map_x,d_map_y,d_map,d_px_x,d_px_y,d_px,outlier\n";
    for (size_t i = 0; i < gcps.size() && i < fit.residuals.size(); ++i) {
        const bool outlier = std::find(fit.outliers.begin(), fit.outliers.end(), i) != fit.outliers.end();
        const Gcp& g = gcps[i];
        const GcpResidual& r = fit.residuals[i];
        s += csvEscape(g.id) + "," + formatDouble(g.x, 10) + "," + formatDouble(g.y, 10) + "," + formatDouble(g.mapX, 10) +
             "," + formatDouble(g.mapY, 10) + "," + formatFixed(r.dMapX, 5) + "," + formatFixed(r.dMapY, 5) + "," +
             formatFixed(r.mapNorm, 5) + "," + formatFixed(r.dx, 4) + "," + formatFixed(r.dy, 4) + "," +
             formatFixed(r.pxNorm, 4) + "," + (outlier ? "1" : "0") + "\n";
    }
    return writeFileAtomic(path, s, error);
}

}  // namespace lwb::core::radiometry
