#include "core/radiometry/reflectance.hpp"

#include <algorithm>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/image_codecs.hpp"
#include "core/common/image_header.hpp"
#include "core/common/text.hpp"
#include "core/radiometry/radiometry_params.hpp"

namespace lwb::core::radiometry {

namespace {
std::string regionName(const Region& r, size_t i) {
    std::string s = "region " + (r.name.empty() ? std::to_string(i + 1) : r.name);
    if (r.line > 0) s += " (line " + std::to_string(r.line) + ")";
    return s;
}

// Finite pixels of one rectangle (already checked to lie inside the image): sum, sum of squares,
// count, and how many fall outside [lo, hi]. Only the rectangle is converted to double.
struct RectStats {
    double sum = 0, sum2 = 0;
    int n = 0, outside = 0, finite = 0;  // n: pixels summed
};
// mask: leave the pixels outside [lo, hi] out of the sums (they are still counted in `outside`).
bool rectStats(const cv::Mat& image, const cv::Rect& rect, double lo, double hi, RectStats* st, std::string* error,
               bool mask = false) {
    cv::Mat roi;
    try {
        image(rect).convertTo(roi, CV_64F);
    } catch (const cv::Exception& e) {
        *error = std::string("cannot read the image: ") + e.what();
        return false;
    }
    for (int y = 0; y < roi.rows; ++y) {
        const double* row = roi.ptr<double>(y);
        for (int x = 0; x < roi.cols; ++x) {
            const double v = row[x];
            if (!std::isfinite(v)) continue;
            ++st->finite;
            const bool out = v < lo || v > hi;
            if (out) ++st->outside;
            if (out && mask) continue;
            st->sum += v;
            st->sum2 += v * v;
            ++st->n;
        }
    }
    return true;
}

// Plausible magnitudes of the inputs (see readRegionCsv and readFitCsv).
constexpr double kMaxReflectancePct = 150, kMaxDn = 1e9, kMaxLineCoefficient = 1e6;

std::string extensionOf(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
    return toLower(path.substr(dot + 1));
}
}  // namespace

bool readRegionCsv(const std::string& path, std::vector<Region>* out, std::string* error) {
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        *error = csv.error;
        return false;
    }
    const CsvTable& t = csv.table;
    const int cn = t.firstColumn({"name", "id", "region"});
    const int cr = t.firstColumn({"reflectance", "measured", "reflectance_pct", "measured_pct"});
    const int cd = t.firstColumn({"dn", "mean_dn"}), cs = t.firstColumn({"simulated", "simulated_pct"});
    const int cx = t.column("x"), cy = t.column("y"), cw = t.column("w"), ch = t.column("h");
    const bool rect = cx >= 0 && cy >= 0 && cw >= 0 && ch >= 0;
    if (cr < 0) {
        *error = path + ":1: header needs a reflectance (or measured) column";
        return false;
    }
    if (cd < 0 && cs < 0 && !rect) {
        *error = path + ":1: header needs dn, simulated, or a rectangle x, y, w, h";
        return false;
    }
    std::vector<Region> v;
    for (size_t i = 0; i < t.rows.size(); ++i) {
        const auto& row = t.rows[i];
        const std::string where = whereInFile(path, t.lines[i]);
        Region r;
        r.line = t.lines[i];
        r.name = cn >= 0 ? std::string(trim(row[cn])) : std::to_string(i + 1);
        if (!parseDouble(row[cr], &r.reflectance)) {
            *error = where + "reflectance must be a finite number, not \"" + printableExcerpt(row[cr]) + "\"";
            return false;
        }
        auto opt = [&](int c, double* dst) {
            if (c < 0 || trim(row[c]).empty()) return true;
            if (!parseDouble(row[c], dst)) {
                *error = where + t.header[c] + " must be a finite number, not \"" + printableExcerpt(row[c]) + "\"";
                return false;
            }
            return true;
        };
        if (!opt(cd, &r.dn) || !opt(cs, &r.simulated)) return false;
        // Magnitudes a measurement can have: reflectance in percent, DN of a camera. Anything
        // else is a damaged field (1e308 would overflow the fit's sums).
        if (r.reflectance < 0 || r.reflectance > kMaxReflectancePct) {
            *error = where + "reflectance " + formatShortest(r.reflectance) + " is not a plausible reflectance in percent (0..150)";
            return false;
        }
        if (std::isfinite(r.simulated) && (r.simulated < -kMaxReflectancePct || r.simulated > kMaxReflectancePct)) {
            *error = where + "simulated reflectance " + formatShortest(r.simulated) + " % is not plausible (|value| <= 150)";
            return false;
        }
        if (std::isfinite(r.dn) && std::fabs(r.dn) > kMaxDn) {
            *error = where + "dn " + formatShortest(r.dn) + " is not a plausible digital number (|dn| <= 1e9)";
            return false;
        }
        if (rect && !trim(row[cx]).empty()) {
            long long x = 0, y = 0, w = 0, h = 0;
            if (!parseLong(row[cx], &x) || !parseLong(row[cy], &y) || !parseLong(row[cw], &w) || !parseLong(row[ch], &h) ||
                w < 1 || h < 1 || x < 0 || y < 0 || x > 1000000 || y > 1000000 || w > 1000000 || h > 1000000) {
                *error = where + "x, y, w, h must be whole numbers (x, y >= 0; w, h >= 1)";
                return false;
            }
            r.rect = cv::Rect(static_cast<int>(x), static_cast<int>(y), static_cast<int>(w), static_cast<int>(h));
        }
        v.push_back(std::move(r));
    }
    if (v.empty()) {
        *error = path + ": no region rows";
        return false;
    }
    *out = std::move(v);
    return true;
}

std::string validate(const ReflectanceFitParams& p) {
    // The ranges of the schema's rows (radiometry_params.cpp: dn_min, dn_max, vm_pct,
    // min_region_*), the other fields at their defaults; then the rule between two of them.
    RadiometryParams r;
    r.fit = p;
    if (std::string e = radiometrySchema().validate(r); !e.empty()) return e;
    if (!(p.dnMin < p.dnMax)) return "the DN range needs min < max";
    return {};
}

bool measureRegionDn(const cv::Mat& image, const ReflectanceFitParams& params, std::vector<Region>* regions,
                     std::string* error) {
    if (image.empty() || image.channels() != 1) {
        *error = "the region image must be a non-empty single-channel image";
        return false;
    }
    const cv::Rect bounds(0, 0, image.cols, image.rows);
    for (size_t i = 0; i < regions->size(); ++i) {
        Region& r = (*regions)[i];
        if (r.rect.empty()) continue;
        if ((r.rect & bounds) != r.rect) {
            *error = regionName(r, i) + ": rectangle " + std::to_string(r.rect.x) + "," + std::to_string(r.rect.y) + " " +
                     std::to_string(r.rect.width) + "x" + std::to_string(r.rect.height) + " leaves the " +
                     std::to_string(image.cols) + "x" + std::to_string(image.rows) + " image";
            return false;
        }
        RectStats st;
        if (!rectStats(image, r.rect, params.dnMin, params.dnMax, &st, error, params.maskOutOfRangePixels)) return false;
        if (st.finite == 0) {
            *error = regionName(r, i) + ": no finite pixels inside the rectangle";
            return false;
        }
        r.dn = st.n > 0 ? st.sum / st.n : NAN;
        r.dnStd = st.n > 1 ? sqrtVariance((st.sum2 - st.sum * st.sum / st.n) / (st.n - 1)) : st.n == 1 ? 0 : NAN;
        r.pixels = st.n;
        r.pixelsOutOfRange = st.outside;
        r.pixelsTotal = st.finite;
    }
    return true;
}

double paperUncertaintyPct(double vm, double kSd, double bSd) { return std::sqrt(vm * vm + kSd * kSd + bSd * bSd); }

double predictionUncertaintyPct(const ReflectanceFit& fit, double dn) {
    const double var = fit.kSd * fit.kSd * dn * dn + 2 * dn * fit.covKB + fit.bSd * fit.bSd;
    return std::sqrt(fit.spectrometerPct * fit.spectrometerPct + std::max(0.0, var));
}

ReflectanceFitResult fitReflectance(const std::vector<Region>& regions, const ReflectanceFitParams& params) {
    ReflectanceFitResult res;
    if (const std::string e = validate(params); !e.empty()) {
        res.error = e;
        return res;
    }
    res.regions.resize(regions.size());
    std::vector<size_t> use;
    for (size_t i = 0; i < regions.size(); ++i) {
        const Region& r = regions[i];
        RegionOutcome& o = res.regions[i];
        if (!std::isfinite(r.reflectance)) {
            res.error = regionName(r, i) + ": the measured reflectance is not a finite number";
            return res;
        }
        const bool measured = r.pixelsTotal > 0;
        if (measured && params.maskOutOfRangePixels) {
            res.pixelsMasked += r.pixelsOutOfRange;
            const int needed = std::max(params.minRegionPixels,
                                        static_cast<int>(std::ceil(params.minRegionFraction * r.pixelsTotal)));
            if (r.pixels < needed) {
                o.used = false;
                o.note = "only " + std::to_string(r.pixels) + " of " + std::to_string(r.pixelsTotal) +
                         " pixels inside the camera's linear range " + formatDouble(params.dnMin, 6) + ".." +
                         formatDouble(params.dnMax, 6) + " (needs " + std::to_string(needed) + ")";
                res.warnings.push_back(regionName(r, i) + ": " + o.note + ", left out of the fit");
                ++res.regionsExcluded;
                continue;
            }
            if (r.pixelsOutOfRange > 0) {
                o.note = std::to_string(r.pixelsOutOfRange) + " of " + std::to_string(r.pixelsTotal) +
                         " pixels outside the linear range masked";
                res.warnings.push_back(regionName(r, i) + ": " + o.note);
            }
            use.push_back(i);
            continue;
        }
        if (!std::isfinite(r.dn)) {
            res.error = regionName(r, i) + ": no mean DN (give dn, or a rectangle and the image)";
            return res;
        }
        const bool outside = r.dn < params.dnMin || r.dn > params.dnMax;
        if (outside) {
            o.note = "mean DN " + formatDouble(r.dn, 6) + " outside the camera's linear range " +
                     formatDouble(params.dnMin, 6) + ".." + formatDouble(params.dnMax, 6);
            if (params.excludeOutOfRange) {
                o.used = false;
                ++res.regionsExcluded;
                res.warnings.push_back(regionName(r, i) + ": " + o.note + ", left out of the fit");
            } else {
                res.warnings.push_back(regionName(r, i) + ": " + o.note);
            }
        } else if (r.pixelsOutOfRange > 0) {
            o.note = std::to_string(r.pixelsOutOfRange) + " of " + std::to_string(r.pixels) +
                     " pixels outside the linear range";
            res.warnings.push_back(regionName(r, i) + ": " + o.note);
        }
        if (o.used) use.push_back(i);
    }
    const int n = static_cast<int>(use.size());
    if (n < 3) {
        res.error = "only " + std::to_string(n) + " usable region" + (n == 1 ? "" : "s") +
                    ": the line needs at least 3 (two fix it, the third measures its error)";
        return res;
    }
    double xm = 0, ym = 0;
    for (size_t i : use) {
        xm += regions[i].dn;
        ym += regions[i].reflectance;
    }
    xm /= n;
    ym /= n;
    double sxx = 0, sxy = 0, syy = 0;
    for (size_t i : use) {
        const double dx = regions[i].dn - xm, dy = regions[i].reflectance - ym;
        sxx += dx * dx;
        sxy += dx * dy;
        syy += dy * dy;
    }
    if (!(sxx > 1e-12 * std::max(1.0, xm * xm) * n)) {
        res.error = "every usable region has the same mean DN: the slope K is undetermined";
        return res;
    }
    ReflectanceFit& f = res.fit;
    f.n = n;
    f.k = sxy / sxx;
    f.b = ym - f.k * xm;
    double sse = 0;
    for (size_t i = 0; i < regions.size(); ++i) {
        RegionOutcome& o = res.regions[i];
        o.predicted = f.k * regions[i].dn + f.b;
        o.residual = regions[i].reflectance - o.predicted;
        if (o.used) sse += o.residual * o.residual;
    }
    const double s2 = sse / (n - 2);
    f.residualSd = std::sqrt(s2);
    f.kSd = std::sqrt(s2 / sxx);
    f.bSd = std::sqrt(s2 * (1.0 / n + xm * xm / sxx));
    f.covKB = -xm * s2 / sxx;
    f.r2 = syy > 0 ? 1 - sse / syy : NAN;
    f.meanDn = xm;
    f.spectrometerPct = params.spectrometerPct;
    f.paperUncertaintyPct = paperUncertaintyPct(params.spectrometerPct, f.kSd, f.bSd);
    f.uncertaintyAtMeanPct = predictionUncertaintyPct(f, xm);
    if (!std::isfinite(f.k) || !std::isfinite(f.b) || !std::isfinite(f.kSd) || !std::isfinite(f.bSd)) {
        res.error = "the fit gave a non-finite K, B or standard error (the region values overflow double precision)";
        return res;
    }
    if (f.k <= 0) res.warnings.push_back("the fitted slope K is not positive: reflectance falls as DN rises");
    res.ok = true;
    return res;
}

std::string validate(const ApplyParams& p) {
    ReflectanceFitParams f;  // (the DN range's rows; apply shares them with the fit)
    f.dnMin = p.dnMin;
    f.dnMax = p.dnMax;
    return validate(f);
}

ApplyResult applyReflectance(const cv::Mat& dn, const ReflectanceFit& fit, const ApplyParams& params) {
    ApplyResult res;
    if (dn.empty() || dn.channels() != 1) {
        res.error = "the DN image must be a non-empty single-channel image";
        return res;
    }
    if (!std::isfinite(fit.k) || !std::isfinite(fit.b)) {
        res.error = "the calibration line (K, B) is not finite";
        return res;
    }
    if (const std::string e = validate(params); !e.empty()) {
        res.error = e;
        return res;
    }
    const bool unc = params.uncertaintyImage;
    if (unc && !(std::isfinite(fit.kSd) && std::isfinite(fit.bSd) && std::isfinite(fit.covKB))) {
        res.error = "the per-pixel uncertainty needs the standard errors of K and B";
        return res;
    }
    // One row in double at a time (a whole-image double copy was 8 bytes a pixel: 2 GiB of the
    // 4.8 GB a 16384^2 image took); the output and the input are the only images held.
    cv::Mat f;
    try {
        res.reflectance.create(dn.size(), CV_32FC1);
        if (unc) res.uncertainty.create(dn.size(), CV_32FC1);
    } catch (const cv::Exception& e) {
        res.error = std::string("cannot allocate the reflectance image: ") + e.what();
        return res;
    }
    for (int y = 0; y < dn.rows; ++y) {
        dn.row(y).convertTo(f, CV_64F);
        const double* in = f.ptr<double>(0);
        float* out = res.reflectance.ptr<float>(y);
        float* uo = unc ? res.uncertainty.ptr<float>(y) : nullptr;
        for (int x = 0; x < f.cols; ++x) {
            const double v = in[x];
            const bool below = v < params.dnMin, above = v > params.dnMax;
            res.belowRange += below;
            res.aboveRange += above;
            if (!std::isfinite(v) || ((below || above) && params.outOfRangeToNan)) {
                out[x] = NAN;
                if (uo) uo[x] = NAN;
                continue;
            }
            const double refl = fit.k * v + fit.b;
            // In double and checked before the float cast: K and B of any size reach here from
            // the command line, and a value beyond float range would be undefined, not inf.
            if (!(std::fabs(refl) <= 1e6)) {
                res.error = "K = " + formatShortest(fit.k) + ", B = " + formatShortest(fit.b) + " give a reflectance of " +
                            formatShortest(refl) + " % at DN " + formatShortest(v) + " (pixel " + std::to_string(x) + ", " +
                            std::to_string(y) + "): not plausible (|reflectance| <= 1e6 %)";
                res.reflectance.release();
                res.uncertainty.release();
                return res;
            }
            out[x] = static_cast<float>(refl);
            if (uo) {
                const double u = predictionUncertaintyPct(fit, v);
                uo[x] = std::fabs(u) <= 1e30 ? static_cast<float>(u) : NAN;
            }
        }
    }
    const size_t total = dn.total();
    if (res.belowRange || res.aboveRange)
        res.warnings.push_back(std::to_string(res.belowRange) + " pixels below and " + std::to_string(res.aboveRange) +
                               " above the linear range " + formatDouble(params.dnMin, 6) + ".." +
                               formatDouble(params.dnMax, 6) + " (of " + std::to_string(total) + ")" +
                               (params.outOfRangeToNan ? ", set to NaN" : ""));
    res.ok = true;
    return res;
}

RelativeErrorResult relativeErrors(const std::vector<Region>& regions, const cv::Mat* image, double limitPct) {
    RelativeErrorResult res;
    if (!(limitPct > 0 && std::isfinite(limitPct))) {
        res.error = "the relative-error limit must be > 0 %";
        return res;
    }
    if (regions.empty()) {
        res.error = "no check regions";
        return res;
    }
    if (image && (image->empty() || image->channels() != 1)) {
        res.error = "the reflectance image must be a non-empty single-channel image";
        return res;
    }
    double sum = 0, mx = 0;
    for (size_t i = 0; i < regions.size(); ++i) {
        const Region& r = regions[i];
        RelativeErrorRow row;
        row.name = r.name.empty() ? std::to_string(i + 1) : r.name;
        row.measured = r.reflectance;
        if (!(std::isfinite(r.reflectance) && r.reflectance > 0)) {
            res.error = regionName(r, i) + ": the measured reflectance must be a number > 0";
            return res;
        }
        if (image && !r.rect.empty()) {
            const cv::Rect bounds(0, 0, image->cols, image->rows);
            if ((r.rect & bounds) != r.rect) {
                res.error = regionName(r, i) + ": the rectangle leaves the image";
                return res;
            }
            RectStats st;
            if (!rectStats(*image, r.rect, -INFINITY, INFINITY, &st, &res.error)) return res;
            if (st.n == 0) {
                res.error = regionName(r, i) + ": no finite reflectance inside the rectangle";
                return res;
            }
            row.simulated = st.sum / st.n;
        } else {
            row.simulated = r.simulated;
        }
        if (!std::isfinite(row.simulated)) {
            res.error = regionName(r, i) + ": no simulated reflectance (give simulated, or a rectangle and the image)";
            return res;
        }
        row.relativeErrorPct = std::fabs(row.simulated - row.measured) / row.measured * 100;
        row.withinLimit = row.relativeErrorPct < limitPct;
        if (!row.withinLimit)
            res.warnings.push_back(regionName(r, i) + ": relative error " + formatFixed(row.relativeErrorPct, 3) +
                                   " % exceeds " + formatDouble(limitPct, 4) + " %");
        sum += row.relativeErrorPct;
        mx = std::max(mx, row.relativeErrorPct);
        res.rows.push_back(row);
    }
    res.maxPct = mx;
    res.meanPct = sum / res.rows.size();
    res.allWithinLimit = std::all_of(res.rows.begin(), res.rows.end(), [](const RelativeErrorRow& r) { return r.withinLimit; });
    res.ok = true;
    return res;
}

bool writeFitCsv(const std::string& path, const ReflectanceFit& f, std::string* error) {
    // Shortest text that reads back to the same double: `radiometry apply --fit` then converts
    // with exactly the line the fit found, as the workbench does with the fit in memory (12
    // digits moved the last bits of the reflectance image; issue 28).
    auto g = [](double v) { return std::isfinite(v) ? formatShortest(v) : std::string(); };
    const std::string s =
        "k,b,k_sd,b_sd,cov_kb,n,residual_sd,r2,mean_dn,vm_pct,paper_uncertainty_pct,uncertainty_at_mean_pct\n" + g(f.k) +
        "," + g(f.b) + "," + g(f.kSd) + "," + g(f.bSd) + "," + g(f.covKB) + "," + std::to_string(f.n) + "," +
        g(f.residualSd) + "," + g(f.r2) + "," + g(f.meanDn) + "," + g(f.spectrometerPct) + "," + g(f.paperUncertaintyPct) +
        "," + g(f.uncertaintyAtMeanPct) + "\n";
    return writeFileAtomic(path, s, error);
}

bool readFitCsv(const std::string& path, ReflectanceFit* fit, std::string* error) {
    const CsvReadResult csv = readCsv(path);
    if (!csv.ok) {
        *error = csv.error;
        return false;
    }
    const CsvTable& t = csv.table;
    if (t.rows.size() != 1 || t.column("k") < 0 || t.column("b") < 0) {
        *error = path + ": a fit file has the columns k, b (and k_sd, b_sd, cov_kb, ...) and one data row";
        return false;
    }
    ReflectanceFit f;
    const auto& row = t.rows[0];
    const std::string where = whereInFile(path, t.lines[0]);
    struct Field {
        const char* name;
        double* dst;
        bool required;
    } fields[] = {{"k", &f.k, true},           {"b", &f.b, true},
                  {"k_sd", &f.kSd, false},     {"b_sd", &f.bSd, false},
                  {"cov_kb", &f.covKB, false}, {"residual_sd", &f.residualSd, false},
                  {"r2", &f.r2, false},        {"mean_dn", &f.meanDn, false},
                  {"vm_pct", &f.spectrometerPct, false}, {"paper_uncertainty_pct", &f.paperUncertaintyPct, false},
                  {"uncertainty_at_mean_pct", &f.uncertaintyAtMeanPct, false}};
    for (const Field& fd : fields) {
        const int c = t.column(fd.name);
        if (c < 0 || (!fd.required && trim(row[c]).empty())) continue;
        if (!parseDouble(row[c], fd.dst)) {
            *error = where + fd.name + " must be a finite number, not \"" + printableExcerpt(row[c]) + "\"";
            return false;
        }
    }
    if (std::fabs(f.k) > kMaxLineCoefficient || std::fabs(f.b) > kMaxLineCoefficient) {
        *error = where + "k = " + formatShortest(f.k) + ", b = " + formatShortest(f.b) +
                 " is not a plausible calibration line (|k|, |b| <= 1e6 % per DN and %)";
        return false;
    }
    if (const int c = t.column("n"); c >= 0 && !trim(row[c]).empty()) {
        long long n = 0;
        if (!parseLong(row[c], &n) || n < 0 || n > std::numeric_limits<int>::max()) {
            *error = where + "n must be a whole number from 0 to " + std::to_string(std::numeric_limits<int>::max()) +
                     ", not \"" + printableExcerpt(row[c]) + "\"";
            return false;
        }
        f.n = static_cast<int>(n);
    }
    *fit = f;
    return true;
}

bool writeRegionFitCsv(const std::string& path, const std::vector<Region>& regions, const ReflectanceFitResult& r,
                       std::string* error) {
    std::string s = "name,dn,reflectance,predicted,residual,used,pixels,pixels_masked,note\n";
    auto g = [](double v) { return std::isfinite(v) ? formatDouble(v, 10) : std::string(); };
    for (size_t i = 0; i < regions.size() && i < r.regions.size(); ++i) {
        const Region& rg = regions[i];
        const bool measured = rg.pixelsTotal > 0;
        s += csvEscape(rg.name) + "," + g(rg.dn) + "," + g(rg.reflectance) + "," + g(r.regions[i].predicted) + "," +
             g(r.regions[i].residual) + "," + (r.regions[i].used ? "1" : "0") + "," +
             (measured ? std::to_string(rg.pixels) : std::string()) + "," +
             (measured ? std::to_string(rg.pixelsOutOfRange) : std::string()) + "," + csvEscape(r.regions[i].note) + "\n";
    }
    return writeFileAtomic(path, s, error);
}

bool writeRelativeErrorCsv(const std::string& path, const RelativeErrorResult& r, std::string* error) {
    std::string s = "name,measured,simulated,relative_error_pct,within_limit\n";
    for (const auto& row : r.rows)
        s += csvEscape(row.name) + "," + formatDouble(row.measured, 10) + "," + formatDouble(row.simulated, 10) + "," +
             formatFixed(row.relativeErrorPct, 6) + "," + (row.withinLimit ? "1" : "0") + "\n";
    return writeFileAtomic(path, s, error);
}

bool writeImage(const std::string& path, const cv::Mat& image, std::string* error) {
    const std::string ext = extensionOf(path);
    if (image.empty()) {
        *error = path + ": empty image";
        return false;
    }
    const int depth = image.depth();
    if (ext == "png" && depth != CV_8U && depth != CV_16U) {
        *error = path + ": PNG holds 8- or 16-bit images only (use .tif for 32-bit float)";
        return false;
    }
    if ((ext == "tif" || ext == "tiff") && depth != CV_8U && depth != CV_16U && depth != CV_32F) {
        *error = path + ": TIFF output takes 8-bit, 16-bit or 32-bit float images";
        return false;
    }
    if (ext != "png" && ext != "tif" && ext != "tiff" && ext != "pgm") {
        *error = path + ": unsupported image extension (png, tif, tiff, pgm)";
        return false;
    }
    std::vector<uchar> buf;
    try {
        if (!imageEncode("." + ext, image, buf)) {
            *error = path + ": cannot encode as ." + ext;
            return false;
        }
    } catch (const cv::Exception& e) {
        *error = path + ": cannot encode: " + e.what();
        return false;
    }
    // Written from the encoder's buffer (a string copy of it was a third image-sized block).
    AtomicFile f(path);
    if (f.ok()) f.stream().write(reinterpret_cast<const char*>(buf.data()), static_cast<std::streamsize>(buf.size()));
    if (!f.ok() || !f.commit()) {
        *error = f.error();
        return false;
    }
    return true;
}

bool writeFloatTiff(const std::string& path, const cv::Mat& image, std::string* error) {
    if (image.type() != CV_32FC1) {
        *error = path + ": a float TIFF needs a single-channel 32-bit float image";
        return false;
    }
    const std::string ext = extensionOf(path);
    if (ext != "tif" && ext != "tiff") {
        *error = path + ": the reflectance image is written as TIFF (.tif or .tiff)";
        return false;
    }
    return writeImage(path, image, error);
}

bool readImageAnyDepth(const std::string& path, cv::Mat* out, std::string* error, long long maxPixels) {
    // Larger than an image within the pixel limit could be (8 bytes a pixel and a megabyte of
    // header): refused from its size, before it is read (a sparse file was read whole first).
    long long size = 0;
    if (!isStandardStream(path) && !regularFileProblem(path, nullptr, &size) && maxPixels > 0 &&
        size > maxPixels * 8 + (1LL << 20)) {
        *error = path + ": " + std::to_string(size) + " bytes: larger than an image of at most " + std::to_string(maxPixels) +
                 " pixels can be (raise the limit with --max-pixels)";
        return false;
    }
    std::string bytes;
    if (!readFileBytes(path, &bytes, error)) return false;
    if (const std::string why = imageSizeProblem(bytes, path, maxPixels); !why.empty()) {
        *error = why;
        return false;
    }
    cv::Mat img;
    try {
        const cv::Mat buf(1, static_cast<int>(std::min<size_t>(bytes.size(), INT32_MAX)), CV_8U, bytes.data());
        img = imageDecode(buf, cv::IMREAD_UNCHANGED);
        if (!img.empty() && img.channels() == 3) cv::cvtColor(img, img, cv::COLOR_BGR2GRAY);
        if (!img.empty() && img.channels() == 4) cv::cvtColor(img, img, cv::COLOR_BGRA2GRAY);
    } catch (const cv::Exception& e) {
        *error = path + ": cannot decode the image: " + e.what();
        return false;
    } catch (const std::bad_alloc&) {
        *error = path + ": out of memory decoding the image";
        return false;
    }
    if (img.empty()) {
        *error = path + ": not a readable image (PNG, TIFF, PGM, JPEG)";
        return false;
    }
    if (img.channels() != 1) {
        *error = path + ": unsupported channel count " + std::to_string(img.channels());
        return false;
    }
    *out = img;
    return true;
}

}  // namespace lwb::core::radiometry
