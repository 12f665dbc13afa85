#pragma once
// The CSV outputs of the calibration steps (the formats of `laserwb-cli calib ...`), beside the
// results: the CLI and the workbench's exports write the same text through these. Each
// *Csv function returns the whole file; writeTextOutput writes it atomically.
#include <string>
#include <utility>
#include <vector>

#include "core/calib/pointing.hpp"
#include "core/calib/validation_stats.hpp"
#include "core/calib/waveform.hpp"

namespace lwb::core::calib {

/// calib pointing -o: per beam, the corrections, their sigmas and the three-axis angles.
std::string pointingBeamsCsv(const PointingCalibResult& r);
/// calib pointing --params: the solved parameters with sigmas.
std::string pointingParamsCsv(const PointingCalibResult& r);
/// calib pointing --residuals: per control point, E/N/U and along/across before and after.
std::string pointingResidualsCsv(const PointingCalibResult& r);
/// calib pointing --iterations: per iteration, chi2, RMS and the parameters.
std::string pointingIterationsCsv(const PointingCalibResult& r);
/// The beam designs with the calibrated alpha and beta (calib pointing --beams-out).
std::vector<BeamDesign> calibratedBeams(const std::vector<BeamDesign>& design, const PointingCalibResult& r);

/// calib stats -o: one row per named group.
std::string statsCsv(const std::vector<std::pair<std::string, ElevationStats>>& groups);
/// calib waveform -o: the candidates ranked.
std::string rankingCsv(const std::vector<FeatureCandidate>& candidates, const FeatureMatchResult& r);
/// calib waveform --model: the waveform and the fitted model.
std::string waveformModelCsv(const Waveform& w, const WaveformResult& r);

/// Writes text atomically (temporary + rename); false with *error.
bool writeTextOutput(const std::string& path, const std::string& text, std::string* error);

}  // namespace lwb::core::calib
