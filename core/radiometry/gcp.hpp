#pragma once
// Geometric correction of a row image by ground control points (paper 003 §3.1: ENVI's
// "image to map" correction with the markers laid every 1 m on both sides of the field). An
// affine or a projective transform from image pixels to map metres is fitted by least squares;
// every GCP's residual is reported, and the image is resampled onto a north-up map grid.
// Conventions: image x = column, y = row, pixel centres at integers; map X to the right (east),
// Y up (north); map grid pixel (c, r) has its centre at (X0 + c·s, Y0 − r·s).
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace lwb::core::radiometry {

struct Gcp {
    std::string id;
    double x = 0, y = 0;        ///< image position (px)
    double mapX = 0, mapY = 0;  ///< map position (m)
    long line = 0;              ///< source line (for messages)
};

/// Reads GCPs: header id (optional), x, y (or col, row) and map_x, map_y (or X, Y / e, n).
/// Errors name the file and line.
bool readGcpCsv(const std::string& path, std::vector<Gcp>* out, std::string* error);

enum class GeoModel {
    Affine,      ///< 6 parameters, ≥ 3 GCPs not on one line
    Homography,  ///< 8 parameters, ≥ 4 GCPs, no three of four on one line
};
const char* geoModelName(GeoModel m);
bool parseGeoModel(const std::string& s, GeoModel* m);

struct GcpFitParams {
    GeoModel model = GeoModel::Affine;
    double collinearTolerance = 1e-3;  ///< GCPs count as collinear when the spread across their best line
                                       ///< is below this fraction of the spread along it (0..0.5)
    /// Chance that a sound GCP is named an outlier (each GCP; in (0, 0.5)): the transform of the
    /// others misses it by z standard deviations, z² following an F(2, ν) distribution (ν: the
    /// others' degrees of freedom), and it is an outlier when P(F > z²) < this and the miss > 0.5 px.
    double outlierProbability = 1e-3;
    bool leaveOneOut = true;           ///< judge each GCP against the fit of the others (internal: off
                                       ///< for those fits)
};
std::string validate(const GcpFitParams& p);

struct GcpResidual {
    std::string id;
    double dMapX = 0, dMapY = 0;       ///< model(image) − map (m)
    double dx = 0, dy = 0;             ///< model⁻¹(map) − image (px)
    double mapNorm = 0, pxNorm = 0;
};

struct GcpFitResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    GeoModel model = GeoModel::Affine;
    cv::Matx33d imageToMap = cv::Matx33d::eye();
    cv::Matx33d mapToImage = cv::Matx33d::eye();
    std::vector<GcpResidual> residuals;  ///< per GCP, input order
    double rmsMap = NAN, rmsPx = NAN;    ///< √(mean squared residual norm) (m, px)
    int dof = 0;                         ///< 2·GCPs − parameters
    double metresPerPixel = NAN;         ///< √|det| of the linear part at the image centre
    /// GCPs (input order) that the transform of the others misses by far more than those fit
    /// each other (leave one out: an outlier pulls a least-squares fit towards itself, so its own
    /// residual hides it — one mark 1 km off left a residual of 2.2 x RMS among six). Named in
    /// `warnings`; the result is doubtful.
    std::vector<size_t> outliers;
};

/// Fits image → map with the chosen model. Errors: too few GCPs, collinear or repeated GCPs,
/// non-finite coordinates, a degenerate homography.
GcpFitResult fitGcpTransform(const std::vector<Gcp>& gcps, const GcpFitParams& params = {});

struct MapGrid {
    double originX = 0, originY = 0;   ///< map position of the centre of pixel (0, 0) (m)
    double pixelSize = 0.01;           ///< m per pixel (> 0)
    int width = 0, height = 0;
};

/// The smallest north-up grid with the given pixel size that holds the whole image.
MapGrid gridCovering(const GcpFitResult& fit, cv::Size imageSize, double pixelSize);

struct WarpResult {
    bool ok = false;
    std::string error;
    cv::Mat image;                     ///< same depth as the input
    cv::Mat valid;                     ///< CV_8U: 255 where the map pixel came from inside the image
};

/// Resamples the image onto the grid (bilinear). Errors: grid too large, singular transform.
WarpResult warpToMap(const cv::Mat& image, const GcpFitResult& fit, const MapGrid& grid);

/// Averages map images on the same grid where they are valid (the row images into one mosaic).
WarpResult mergeOnGrid(const std::vector<cv::Mat>& images, const std::vector<cv::Mat>& valid);

/// Writes the residual table (id, x, y, map_x, map_y, d_map_x, d_map_y, d_px_x, d_px_y), atomically.
bool writeGcpResidualCsv(const std::string& path, const std::vector<Gcp>& gcps, const GcpFitResult& fit,
                         std::string* error);

}  // namespace lwb::core::radiometry
