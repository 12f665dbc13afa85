#pragma once
// The calibration parameters an analyst sets (paper 002): the detector-array fit, the pointing
// calibration, the waveform decomposition and the feature match, declared once in one schema
// table (core/common/schema.hpp). The CLI's calib commands (--config / --print-config / --set /
// --help-params, and their named options as aliases) and the workbench's session read and write
// them through it.
#include "core/calib/detector_array.hpp"
#include "core/calib/pointing.hpp"
#include "core/calib/waveform.hpp"
#include "core/common/schema.hpp"

namespace lwb::core::calib {

struct CalibParams {
    DetectorFitParams detector;
    PointingCalibParams pointing;
    WaveformParams waveform;
    FeatureMatchParams match;
};

/// Keys "detector.trigger", "pointing.sigma_h", "waveform.thred_h", ...; messages name them
/// "calib.detector.trigger".
const Schema<CalibParams>& calibSchema();

/// "" when every field and rule holds, else the first problem (the schema's message).
std::string validate(const CalibParams& p);

}  // namespace lwb::core::calib
