#pragma once
// Validation of a solved pointing and range calibration on independent check points (paper 002
// §3.3): every check shot is geolocated with the calibrated pointing angles and range bias of
// its beam (eq. 2), and the result is compared with the surveyed footprint position. The height
// component of laser − control is the "elevation difference" whose statistics
// (validation_stats.hpp) the paper tabulates.
#include <cmath>
#include <string>
#include <vector>

#include "core/calib/pointing.hpp"

namespace lwb::core::calib {

struct CheckPointDifference {
    std::string id;             ///< as in the input (row number when it has none)
    int beam = 0;
    double e = 0, n = 0, u = 0; ///< laser − control in the control point's local ENU frame (m)
    double plan = 0;            ///< √(e² + n²) (m)
    long line = 0;              ///< source line (for messages)
};

struct CalibrationCheckParams {
    /// true: use the calibrated angles and range biases; false: the design values (the
    /// differences before calibration, for comparison).
    bool applyCalibration = true;
};

struct CalibrationCheckResult {
    bool ok = false;
    std::string error;
    std::vector<CheckPointDifference> points;  ///< same order as the input
};

/// Geolocates the check points with the calibration `calib` (solved for `beams`, in design
/// order) and returns laser − control per point. Errors: a calibration that is not ok or does
/// not match the beams, a point of an unknown or unsolved beam (naming the point and its line),
/// non-finite inputs, no points.
CalibrationCheckResult checkCalibration(const std::vector<BeamDesign>& beams, const PointingCalibResult& calib,
                                        const std::vector<ControlPoint>& points, const CalibrationCheckParams& params = {});

/// The height differences (u) of the points of one beam (every beam when beam is 0).
std::vector<double> heightDifferences(const CalibrationCheckResult& r, int beam = 0);

}  // namespace lwb::core::calib
