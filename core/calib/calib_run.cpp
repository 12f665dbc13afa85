#include "core/calib/calib_run.hpp"

#include <cmath>

#include "core/calib/detector_array.hpp"
#include "core/calib/pointing.hpp"
#include "core/calib/validation_stats.hpp"
#include "core/calib/waveform.hpp"

namespace lwb::core::calib {

namespace {

std::string fileName(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

void addGroup(CalibRunResult& run, const std::string& name, const std::string& group, std::vector<double> d) {
    StatsGroup g;
    g.name = name;
    g.group = group;
    g.d = std::move(d);
    g.stats = elevationStats(g.d);
    if (!g.stats.ok && run.statsError.empty()) run.statsError = name + ": " + g.stats.error;
    run.stats.push_back(std::move(g));
}

// The validation statistics (see CalibTask).
void computeStats(const CalibInputData& d, CalibRunResult& run) {
    if (!d.differences.empty()) {
        run.statsSource = "Elevation differences from " + fileName(d.differencesName);
        for (const auto& g : d.differences)
            addGroup(run, g.group.empty() ? std::string("all") : (d.groupColumn.empty() ? "" : d.groupColumn + " ") + g.group,
                     g.group, g.d);
        return;
    }
    if (!run.hasPointing || !run.pointing.ok) {
        if (!d.checkPoints.empty() || !d.points.empty()) run.statsError = "no statistics: the pointing calibration did not succeed";
        return;
    }
    if (!d.checkPoints.empty()) {
        run.check = checkCalibration(d.beams, run.pointing, d.checkPoints);
        run.hasCheck = true;
        if (!run.check.ok) {
            run.statsError = "check points: " + run.check.error;
            return;
        }
        run.statsSource = "Height differences laser − control at " + std::to_string(run.check.points.size()) +
                          " independent check points, calibrated";
        for (const auto& b : d.beams) {
            std::vector<double> v = heightDifferences(run.check, b.id);
            if (!v.empty()) addGroup(run, "beam " + std::to_string(b.id), std::to_string(b.id), std::move(v));
        }
        return;
    }
    run.statsSource = "Height residuals of the " + std::to_string(run.pointing.residuals.size()) +
                      " control points after calibration (not independent)";
    for (const auto& b : d.beams) {
        std::vector<double> v;
        for (const auto& r : run.pointing.residuals)
            if (r.beam == b.id) v.push_back(r.after.u);
        if (!v.empty()) addGroup(run, "beam " + std::to_string(b.id), std::to_string(b.id), std::move(v));
    }
}

}  // namespace

CalibRunResult CalibTask::run(const CalibInputData& d, const CalibParams& p, const NoReuse&, Feedback*) {
    CalibRunResult run;
    if (!d.array.detectors.empty()) {
        run.hasDetector = true;
        run.detector = fitDetectorArray(d.array, p.detector);
    }
    if (!d.points.empty()) {
        run.hasPointing = true;
        run.pointing = calibratePointing(d.beams, d.points, p.pointing);
    }
    computeStats(d, run);
    double height = d.givenHeightM;
    if (!d.waveform.amplitude.empty()) {
        run.hasWaveform = true;
        run.waveformRun = withSampleInterval(d.waveform, p.waveform.sampleIntervalNs);
        run.waveform = decomposeWaveform(run.waveformRun, p.waveform);
        height = run.waveform.ok ? run.waveform.heightM : NAN;
    }
    if (std::isfinite(height) && !d.features.empty()) {
        run.hasMatch = true;
        run.match = matchFeature(d.features, height, p.match);
    }
    return run;
}

bool loadCalibPart(CalibPart part, const CalibSources& src, CalibInputData* d, std::string* error) {
    switch (part) {
        case CalibPart::Detectors:
            d->array = {};
            d->hasDetectorTruth = false;
            return src.detectors.empty() || readDetectorCsv(src.detectors, &d->array, error);
        case CalibPart::ControlPoints:
            d->points.clear();
            d->beams.clear();
            d->hasPointingTruth = false;
            if (src.controlPoints.empty()) return true;
            if (src.beams.empty() && src.givenBeams.empty()) {
                *error = src.controlPoints + ": the control points need beam designs (a beams JSON)";
                return false;
            }
            d->beams = src.givenBeams;
            if ((!src.beams.empty() && !readBeamsJson(src.beams, &d->beams, error)) ||
                !readControlPointCsv(src.controlPoints, &d->points, error)) {
                d->points.clear();
                d->beams.clear();
                return false;
            }
            if (d->points.empty()) {
                *error = src.controlPoints + ": no control points";
                return false;
            }
            return true;
        case CalibPart::CheckPoints:
            d->checkPoints.clear();
            return src.checkPoints.empty() || readControlPointCsv(src.checkPoints, &d->checkPoints, error);
        case CalibPart::Differences:
            d->differences.clear();
            d->differencesName = src.differences;
            d->groupColumn = src.groupColumn;
            return src.differences.empty() || readDifferencesCsv(src.differences, src.groupColumn, &d->differences, error);
        case CalibPart::Waveform:
            d->waveform = {};
            d->trueHeightM = NAN;
            d->givenHeightM = src.givenHeightM;
            return src.waveform.empty() || readWaveformCsv(src.waveform, 1.0, &d->waveform, error);
        case CalibPart::Features:
            d->features.clear();
            return src.features.empty() || readFeatureCsv(src.features, &d->features, error);
    }
    return true;
}

bool loadCalibInputs(const CalibSources& src, CalibInputData* in, std::string* error) {
    CalibInputData d;
    for (CalibPart part : {CalibPart::Detectors, CalibPart::ControlPoints, CalibPart::CheckPoints, CalibPart::Differences,
                           CalibPart::Waveform, CalibPart::Features})
        if (!loadCalibPart(part, src, &d, error)) return false;
    *in = std::move(d);
    return true;
}

std::vector<std::pair<std::string, ElevationStats>> statsRows(const std::vector<StatsGroup>& groups) {
    std::vector<std::pair<std::string, ElevationStats>> rows;
    for (const auto& g : groups)
        if (g.stats.ok) rows.emplace_back(g.group, g.stats.stats);
    return rows;
}

}  // namespace lwb::core::calib
