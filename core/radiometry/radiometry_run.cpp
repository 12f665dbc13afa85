#include "core/radiometry/radiometry_run.hpp"

#include <cmath>

#include "core/common/csv.hpp"
#include "core/common/text.hpp"

namespace lwb::core::radiometry {

namespace {
std::string gx(double v) { return std::isfinite(v) ? formatDouble(v, 10) : std::string(); }

// Measures every rectangle that lies inside the image in one pass; notes the others.
void measureStage(const cv::Mat& dn, const std::vector<RegionPick>& regions, const RadiometryParams& p, RadiometryRunResult& run) {
    const bool haveImage = !dn.empty();
    const cv::Rect bounds = haveImage ? cv::Rect(0, 0, dn.cols, dn.rows) : cv::Rect();
    std::vector<Region> toMeasure;
    std::vector<size_t> measuredIndex;
    for (size_t i = 0; i < regions.size(); ++i) {
        const RegionPick& pr = regions[i];
        Region& r = run.measured[i];
        r.name = pr.name;
        r.reflectance = pr.reflectance;
        r.dn = pr.dn;
        if (pr.rect.empty()) {
            if (!std::isfinite(pr.dn)) run.notes[i] = "no rectangle and no DN";
            continue;
        }
        r.rect = pr.rect;
        r.dn = NAN;
        if (!haveImage) {
            run.notes[i] = "no image to measure on";
            continue;
        }
        if ((r.rect & bounds) != r.rect) {
            run.notes[i] = "rectangle leaves the " + std::to_string(bounds.width) + "×" + std::to_string(bounds.height) + " image";
            continue;
        }
        toMeasure.push_back(r);
        measuredIndex.push_back(i);
    }
    if (toMeasure.empty()) return;
    std::string err;
    if (measureRegionDn(dn, p.fit, &toMeasure, &err)) {
        for (size_t j = 0; j < toMeasure.size(); ++j) run.measured[measuredIndex[j]] = toMeasure[j];
    } else {
        run.error = err;
    }
}

// The fit over the fit regions that have a reflectance and a DN.
void fitStage(const std::vector<RegionPick>& regions, const RadiometryParams& p, RadiometryRunResult& run) {
    std::vector<Region> fitRegions;
    for (size_t i = 0; i < regions.size(); ++i) {
        if (regions[i].check) continue;
        const Region& r = run.measured[i];
        if (!std::isfinite(r.reflectance)) {
            if (run.notes[i].empty()) run.notes[i] = "enter the measured reflectance";
            continue;
        }
        if (!std::isfinite(r.dn)) continue;
        fitRegions.push_back(r);
        run.fitIndex.push_back(int(i));
    }
    if (!run.error.empty()) return;
    run.fit = fitReflectance(fitRegions, p.fit);
    if (!run.fit.ok) run.error = run.fit.error;
    for (size_t j = 0; j < run.fit.regions.size() && j < run.fitIndex.size(); ++j)
        if (!run.fit.regions[j].note.empty()) run.notes[size_t(run.fitIndex[j])] = run.fit.regions[j].note;
}

// Relative errors of the check regions: over their rectangle on the reflectance image, or
// K DN + B for regions given by their DN alone.
void checkStage(const std::vector<RegionPick>& regions, const RadiometryParams& p, RadiometryRunResult& run) {
    std::vector<Region> checks;
    for (size_t i = 0; i < regions.size(); ++i) {
        if (!regions[i].check) continue;
        Region r = run.measured[i];
        if (!(std::isfinite(r.reflectance) && r.reflectance > 0)) {
            if (run.notes[i].empty()) run.notes[i] = "enter the measured reflectance (> 0 %)";
            continue;
        }
        if (!r.rect.empty() && !std::isfinite(r.dn)) continue;  // outside the image: noted above
        if (r.rect.empty() || !run.apply.ok) {
            if (!std::isfinite(r.dn)) continue;
            r.rect = cv::Rect();
            r.simulated = run.fit.fit.k * r.dn + run.fit.fit.b;
        }
        checks.push_back(r);
        run.checkIndex.push_back(int(i));
    }
    if (checks.empty()) {
        run.checkError = "no check regions with a measured reflectance";
    } else {
        run.check = relativeErrors(checks, run.apply.ok ? &run.apply.reflectance : nullptr, p.limitPct);
        if (!run.check.ok) run.checkError = run.check.error;
    }
}

}  // namespace

RadiometryRunResult RadiometryTask::run(const Inputs& in, const RadiometryParams& p, const NoReuse&, Feedback*) {
    const cv::Mat& dn = in.dn;
    const std::vector<RegionPick>& regions = in.regions;
    RadiometryRunResult run;
    run.notes.assign(regions.size(), std::string());
    run.measured.resize(regions.size());
    measureStage(dn, regions, p, run);
    fitStage(regions, p, run);
    if (!run.fit.ok) return run;
    if (!dn.empty()) {
        run.apply = applyReflectance(dn, run.fit.fit, applyParamsOf(p));
        if (!run.apply.ok) run.error = run.apply.error;
    }
    checkStage(regions, p, run);
    return run;
}

std::string regionResultsCsv(const std::vector<RegionPick>& regions, const RadiometryRunResult& r) {
    std::string s = "name,role,reflectance,x,y,w,h,dn,dn_sd,pixels,predicted,residual,used,note\n";
    for (size_t i = 0; i < regions.size() && i < r.measured.size(); ++i) {
        const RegionPick& p = regions[i];
        const Region& m = r.measured[i];
        double predicted = NAN, residual = NAN;
        bool used = false;
        for (size_t j = 0; j < r.fitIndex.size(); ++j)
            if (r.fitIndex[j] == int(i) && r.fit.ok) {
                predicted = r.fit.regions[j].predicted;
                residual = r.fit.regions[j].residual;
                used = r.fit.regions[j].used;
            }
        if (p.check && r.fit.ok && std::isfinite(m.dn)) predicted = r.fit.fit.k * m.dn + r.fit.fit.b;
        const bool rect = !p.rect.empty();
        s += csvEscape(p.name) + "," + (p.check ? "check" : "fit") + "," + gx(p.reflectance) + "," +
             (rect ? std::to_string(p.rect.x) + "," + std::to_string(p.rect.y) + "," + std::to_string(p.rect.width) + "," +
                         std::to_string(p.rect.height)
                   : std::string(",,,")) +
             "," + gx(m.dn) + "," + gx(m.dnStd) + "," + (m.pixels ? std::to_string(m.pixels) : std::string()) + "," +
             gx(predicted) + "," + gx(residual) + "," + (used ? "1" : "0") + "," +
             csvEscape(i < r.notes.size() ? r.notes[i] : std::string()) + "\n";
    }
    return s;
}

}  // namespace lwb::core::radiometry
