#include "core/slr/oc.hpp"

#include "core/slr/slr_params.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numeric>

#include "core/common/golden.hpp"
#include "core/common/text.hpp"
#include "core/slr/ilrs_tables.hpp"
#include "core/slr/orbit_fit.hpp"
#include "core/slr/refraction.hpp"
#include "core/slr/slr_time.hpp"

namespace lwb::core::slr {

namespace {

/// Station position in the inertial frame that coincides with ITRF at the bounce time, at a
/// time `dt` seconds from the bounce (negative: before): the Earth-fixed point rotated by ω·dt.
Eigen::Vector3d rotated(const Eigen::Vector3d& s, double dt) {
    const double a = kEarthRotationRate * dt;
    const double c = std::cos(a), sn = std::sin(a);
    return Eigen::Vector3d(c * s.x() - sn * s.y(), sn * s.x() + c * s.y(), s.z());
}

/// Relativistic (Shapiro) one-way delay (m) of the Earth's field between two points.
double shapiroM(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const double r1 = a.norm(), r2 = b.norm(), rho = (a - b).norm();
    const double den = r1 + r2 - rho;
    if (den <= 0) return 0;
    return 2.0 * kEarthGm / (kSpeedOfLight * kSpeedOfLight) * std::log((r1 + r2 + rho) / den);
}

/// Met values interpolated linearly in time (clamped at the ends).
struct MetSeries {
    std::vector<double> t, p, temp, h;
    bool empty() const { return t.empty(); }
    void at(double x, double* P, double* T, double* H) const {
        if (x <= t.front()) {
            *P = p.front(), *T = temp.front(), *H = h.front();
            return;
        }
        if (x >= t.back()) {
            *P = p.back(), *T = temp.back(), *H = h.back();
            return;
        }
        const size_t k = static_cast<size_t>(std::upper_bound(t.begin(), t.end(), x) - t.begin());
        const double u = (x - t[k - 1]) / (t[k] - t[k - 1]);
        *P = p[k - 1] + u * (p[k] - p[k - 1]);
        *T = temp[k - 1] + u * (temp[k] - temp[k - 1]);
        *H = h[k - 1] + u * (h[k] - h[k - 1]);
    }
};

MetSeries metSeries(const CrdPass& pass, std::vector<std::string>* warnings, const std::string& where) {
    std::vector<std::pair<double, const CrdMeteo*>> v;
    size_t bad = 0;
    for (const auto& m : pass.meteo) {
        if (!(m.pressureMbar >= 400 && m.pressureMbar <= 1100 && m.temperatureK >= 200 && m.temperatureK <= 340 &&
              m.humidityPct >= 0 && m.humidityPct <= 100.5)) {
            if (bad++ < 5)
                warnings->push_back(where + ":" + std::to_string(m.line) +
                                    ": implausible met record (pressure 400..1100 mbar, temperature 200..340 K, humidity "
                                    "0..100 %); not used");
            continue;
        }
        v.emplace_back(pass.passSeconds(m.secOfDay), &m);
    }
    std::stable_sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    MetSeries s;
    for (const auto& [t, m] : v) {
        if (!s.t.empty() && t <= s.t.back()) continue;  // duplicate epoch: first wins
        s.t.push_back(t);
        s.p.push_back(m->pressureMbar);
        s.temp.push_back(m->temperatureK);
        s.h.push_back(std::min(100.0, m->humidityPct));
    }
    return s;
}

std::string passName(const CrdPass& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%s %04d-%02d-%02d %02d:%02d", p.station.name.c_str(), p.session.startYear,
                  p.session.startMonth, p.session.startDay, p.session.startHour, p.session.startMinute);
    return buf;
}

}  // namespace

// The O-C parameters' ranges are their schema rows' (core/slr/slr_params.cpp, oc.*).
std::string validate(const OcParams& p) {
    SlrParams sp;
    sp.oc = p;
    return slrSchema().validate(sp, "oc.");
}

std::string validate(const TrendOcParams& p) {
    SlrParams sp;
    sp.ownTrend = p;
    return slrSchema().validate(sp, "oc.");
}

// computeOc in named stages: check the inputs, the centre-of-mass offset, the refraction set-up,
// then per range the light times, the wavelength and the computed two-way time of flight.
namespace {

std::string checkStation(const Eigen::Vector3d& stationEcef) {
    if (!stationEcef.allFinite() || stationEcef.norm() < 6.3e6 || stationEcef.norm() > 6.4e6)
        return "station position is not on the Earth's surface (|r| must be 6300..6400 km)";
    return {};
}

// The target's centre-of-mass offset (m): given, else the CPF's when it has not applied it, else 0.
double comOffsetM(const OcParams& params, const CpfFile& cpf) {
    if (!std::isnan(params.targetComOffsetM)) return params.targetComOffsetM;
    return cpf.header.comApplied == 0 && std::isfinite(cpf.header.comOffsetM) ? cpf.header.comOffsetM : 0.0;
}

// Whether refraction is added (Mendes–Pavlis asked, the ranges not already corrected, met records
// usable), with the met series; says why not in the warnings.
bool setUpRefraction(const CrdPass& pass, const OcParams& params, const std::string& name, MetSeries* met,
                     std::vector<std::string>* warnings) {
    if (params.refraction != RefractionModel::MendesPavlis) return false;
    if (pass.session.refractionApplied == 1) {
        warnings->push_back(name + ": H4 says the ranges are already corrected for refraction; no correction added");
        return false;
    }
    *met = metSeries(pass, warnings, pass.station.name);
    if (met->empty()) {
        warnings->push_back(name + ": no usable met (type 20) record: no refraction correction");
        return false;
    }
    return true;
}

// One leg's light time (s) with the satellite fixed at `sat`, iterated from `leg`: dir = −1 for the
// uplink (station at tb − up), +1 for the downlink (station at tb + down).
double legTime(const Eigen::Vector3d& sat, const Eigen::Vector3d& station, int dir, double leg, const OcParams& params) {
    for (int k = 0; k < params.maxIterations; ++k) {
        const double next = (sat - rotated(station, dir * leg)).norm() / kSpeedOfLight;
        const bool done = std::fabs(next - leg) < params.convergenceS;
        leg = next;
        if (done) break;
    }
    return leg;
}

// Light times of one range and the satellite at the bounce.
struct LightTime {
    bool ok = false;  // false: the prediction does not cover the bounce (spanError says why)
    double up = 0, down = 0;
    Eigen::Vector3d sat = Eigen::Vector3d::Zero();
};

// The observed time of flight only seeds the iteration. Epoch event 2 (ground transmit): bounce
// = t + up, iterated with the uplink; 0 (ground receive): bounce = t − down, with the downlink;
// else the epoch is the bounce.
LightTime lightTime(const CpfInterpolator& interp, double startMjd, const Eigen::Vector3d& station, const OcParams& params,
                    const CrdRange& r, double t, std::string* spanError) {
    LightTime lt;
    lt.up = lt.down = r.tofS / 2;
    auto satAt = [&](double tt) {
        const CpfState s = interp.atSeconds(startMjd, tt, false);
        if (!s.ok) {
            if (spanError->empty()) *spanError = s.error;
            return false;
        }
        lt.sat = s.position;
        return true;
    };
    if (r.epochEvent == 2 || r.epochEvent == 0) {
        const bool transmit = r.epochEvent == 2;
        double& leg = transmit ? lt.up : lt.down;
        const int dir = transmit ? -1 : 1;
        auto bounce = [&] { return transmit ? t + leg : t - leg; };
        for (int k = 0; k < params.maxIterations; ++k) {
            if (!satAt(bounce())) return lt;
            const double next = (lt.sat - rotated(station, dir * leg)).norm() / kSpeedOfLight;
            const bool done = std::fabs(next - leg) < params.convergenceS;
            leg = next;
            if (done) break;
        }
        if (!satAt(bounce())) return lt;
    } else if (!satAt(t)) {
        return lt;
    }
    lt.up = legTime(lt.sat, station, -1, lt.up, params);
    lt.down = legTime(lt.sat, station, 1, lt.down, params);
    lt.ok = true;
    return lt;
}

// The wavelength (nm) for a range's refraction: given, else its configuration's C0 record, else
// 532 nm with one warning per pass.
double rangeWavelengthNm(const CrdPass& pass, const CrdRange& r, const OcParams& params, const std::string& name, bool* warned,
                         std::vector<std::string>* warnings) {
    if (!std::isnan(params.wavelengthNm)) return params.wavelengthNm;
    const CrdSystemConfig* cfg = pass.config(r.configId);
    if (!cfg && !pass.configs.empty()) cfg = &pass.configs.front();
    const double lambda = cfg ? cfg->wavelengthNm : NAN;
    if (lambda >= 300 && lambda <= 2000) return lambda;
    if (!*warned)
        warnings->push_back(name + ": no usable wavelength in the C0 record for configuration \"" + r.configId +
                            "\"; 532 nm assumed");
    *warned = true;
    return 532.0;
}

void appendPassWarnings(const std::string& name, size_t skippedEvent, size_t skippedSpan, const std::string& spanError,
                        OcResult* res) {
    if (skippedEvent)
        res->warnings.push_back(name + ": " + std::to_string(skippedEvent) +
                                " records with a one-way epoch event (3..6) skipped: only two-way ranging is computed");
    if (skippedSpan)
        res->warnings.push_back(name + ": " + std::to_string(skippedSpan) + " records outside the prediction skipped (" +
                                spanError + ")");
}

}  // namespace

OcResult computeOc(const CrdPass& pass, const CpfFile& cpf, const Eigen::Vector3d& stationEcef, const OcParams& params,
                   const Feedback* feedback) {
    OcResult res;
    res.method = OcMethod::Prediction;
    try {
        std::string e = validate(params);
        if (e.empty()) e = checkStation(stationEcef);
        if (!e.empty()) {
            res.error = e;
            return res;
        }
        const std::string name = passName(pass);
        const CpfInterpolator interp(cpf, params.interpolation);
        if (!interp.ok()) {
            res.error = interp.error();
            return res;
        }
        res.startMjd = pass.startMjd();
        res.stationEcef = stationEcef;
        const Geodetic geo = geodeticFromEcef(stationEcef);
        res.comOffsetM = comOffsetM(params, cpf);
        MetSeries met;
        res.refractionApplied = setUpRefraction(pass, params, name, &met, &res.warnings);

        bool warnedWavelength = false;
        size_t skippedEvent = 0, skippedSpan = 0;
        std::string spanError;
        const size_t n = pass.ranges.size();
        const double c = kSpeedOfLight;
        for (auto* v : {&res.epoch_s, &res.oc_s, &res.tof_s, &res.elevation_rad, &res.azimuth_rad, &res.refraction_s}) v->reserve(n);
        res.range_index.reserve(n), res.line.reserve(n), res.filter_flag.reserve(n);
        for (size_t i = 0; i < n; ++i) {
            if ((i & 0xfff) == 0 && feedback) {
                if (feedback->isCancelled()) {
                    res = OcResult();
                    res.error = "cancelled";
                    return res;
                }
                feedback->setProgress(static_cast<double>(i) / static_cast<double>(n));
            }
            const CrdRange& r = pass.ranges[i];
            if (r.epochEvent > 2) {
                ++skippedEvent;
                continue;
            }
            const double t = pass.passSeconds(r.secOfDay);
            const LightTime lt = lightTime(interp, res.startMjd, stationEcef, params, r, t, &spanError);
            if (!lt.ok) {
                ++skippedSpan;
                continue;
            }
            double computed = lt.up + lt.down;
            // Centre-of-mass offset: the reflection happens that much nearer the station, both legs.
            computed -= 2.0 * res.comOffsetM / c;
            if (params.shapiro)
                computed += (shapiroM(rotated(stationEcef, -lt.up), lt.sat) + shapiroM(lt.sat, rotated(stationEcef, lt.down))) / c;
            double az = 0, el = 0;
            azimuthElevation(stationEcef, geo, lt.sat, &az, &el);
            double refrS = 0;
            if (res.refractionApplied) {
                const double lambda = rangeWavelengthNm(pass, r, params, name, &warnedWavelength, &res.warnings);
                if (std::isnan(res.wavelengthNm)) res.wavelengthNm = lambda;
                double P = 0, T = 0, H = 0;
                met.at(t, &P, &T, &H);
                // Both legs at the same elevation (the satellite moves < 0.01° during the flight).
                refrS = 2.0 * mendesPavlisDelayM(geo, P, T, H, lambda / 1000.0, std::max(el, 1.0 * M_PI / 180)) / c;
                computed += refrS;
            }
            res.epoch_s.push_back(t);
            res.oc_s.push_back(r.tofS - computed);
            res.tof_s.push_back(r.tofS);
            res.elevation_rad.push_back(el);
            res.azimuth_rad.push_back(az);
            res.refraction_s.push_back(refrS);
            res.range_index.push_back(static_cast<uint32_t>(i));
            res.line.push_back(r.line);
            res.filter_flag.push_back(static_cast<int8_t>(r.filterFlag));
        }
        appendPassWarnings(name, skippedEvent, skippedSpan, spanError, &res);
        if (res.oc_s.empty()) {
            res.error = name + ": no O-C computed" + (spanError.empty() ? std::string() : ": " + spanError);
            return res;
        }
        if (std::any_of(res.elevation_rad.begin(), res.elevation_rad.end(), [](double el) { return el < 0; }))
            res.warnings.push_back(name + ": the predicted target is below the horizon at some epochs: wrong station, "
                                          "prediction or time?");
        if (feedback) feedback->setProgress(1.0);
        res.ok = true;
    } catch (const std::exception& e) {
        res = OcResult();
        res.error = std::string("internal error: ") + e.what();
    }
    return res;
}

OcResult computeOc(const CrdPass& pass, const CpfFile& cpf, const SinexFile& sinex, const OcParams& params,
                   const Feedback* feedback) {
    try {
        if (pass.ranges.empty()) {
            OcResult r;
            r.error = passName(pass) + ": no full-rate (type 10) records";
            return r;
        }
        const double sod = pass.passSeconds(pass.ranges.front().secOfDay);
        const StationPositionResult st = stationPositionByPad(sinex, pass.station.cdpPadId, pass.startMjd(), sod);
        if (!st.ok) {
            OcResult r;
            r.error = passName(pass) + ": " + st.error;
            return r;
        }
        OcResult r = computeOc(pass, cpf, st.position, params, feedback);
        r.stationCode = st.code;
        r.warnings.insert(r.warnings.begin(), st.warnings.begin(), st.warnings.end());
        return r;
    } catch (const std::exception& e) {
        OcResult r;
        r.error = std::string("internal error: ") + e.what();
        return r;
    }
}

// ---- fallback: robust trend of the time of flight ---------------------------------------------

namespace {

/// Legendre design matrix on x in [-1, 1].
Eigen::MatrixXd legendre(const std::vector<double>& x, int degree) {
    Eigen::MatrixXd a(static_cast<Eigen::Index>(x.size()), degree + 1);
    for (size_t i = 0; i < x.size(); ++i) {
        const Eigen::Index r = static_cast<Eigen::Index>(i);
        a(r, 0) = 1;
        if (degree >= 1) a(r, 1) = x[i];
        for (int k = 1; k < degree; ++k) a(r, k + 1) = ((2 * k + 1) * x[i] * a(r, k) - k * a(r, k - 1)) / (k + 1);
    }
    return a;
}

double medianOf(std::vector<double> v) {
    if (v.empty()) return NAN;
    const size_t m = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + static_cast<long>(m), v.end());
    double med = v[m];
    if (v.size() % 2 == 0) med = 0.5 * (med + *std::max_element(v.begin(), v.begin() + static_cast<long>(m)));
    return med;
}

// (TrendOcParams::fitMaxPoints, 20 000, is above every shared real pass, BLITS's longest having
// 7 920 records: their trends are the whole pass's fit.)
// Indices 0, k, 2k, ... of n records, k the least step that keeps at most `most` of them.
std::vector<size_t> evenlyTaken(size_t n, size_t most) {
    most = std::max<size_t>(most, 1);
    const size_t every = std::max<size_t>(1, (n + most - 1) / most);
    std::vector<size_t> at;
    for (size_t i = 0; i < n; i += every) at.push_back(i);
    return at;
}

Eigen::VectorXd takeAt(const Eigen::VectorXd& v, const std::vector<size_t>& at) {
    Eigen::VectorXd out(static_cast<Eigen::Index>(at.size()));
    for (size_t k = 0; k < at.size(); ++k) out(static_cast<Eigen::Index>(k)) = v(static_cast<Eigen::Index>(at[k]));
    return out;
}

// The TOF residuals (ms) of every record from a squared-TOF fit's coefficients, its design made
// for a block of rows at a time (`design(begin, end)`), so that no n-row matrix is built. False
// when the squared trend is not positive somewhere.
template <class Design>
bool residualsOfAll(size_t n, const Design& design, const Eigen::VectorXd& coef, const Eigen::VectorXd& tofMs,
                    Eigen::VectorXd* resid) {
    resid->resize(static_cast<Eigen::Index>(n));
    constexpr size_t kBlock = 1 << 14;
    for (size_t b = 0; b < n; b += kBlock) {
        const size_t e = std::min(n, b + kBlock);
        const Eigen::VectorXd fit = design(b, e) * coef;
        for (size_t i = b; i < e; ++i) {
            const double f = fit(static_cast<Eigen::Index>(i - b));
            if (!(f > 0)) return false;
            (*resid)(static_cast<Eigen::Index>(i)) = tofMs(static_cast<Eigen::Index>(i)) - std::sqrt(f);
        }
    }
    return true;
}

// A pass's epochs t (s) and what the trends take of them: the normalised time x in [-1, 1] and s
// = t - t_mid, computed where they are needed (for a kHz pass each as a whole column was 8 bytes
// an event more at the trend's peak, issue 44); the same expressions, so the same values.
struct Epochs {
    const std::vector<double>& t;
    double t0, t1, tm;
    size_t size() const { return t.size(); }
    double x(size_t i) const { return 2 * (t[i] - t0) / (t1 - t0) - 1; }
    double s(size_t i) const { return t[i] - tm; }
    std::vector<double> xs(size_t b, size_t e) const {
        std::vector<double> v(e - b);
        for (size_t i = b; i < e; ++i) v[i - b] = x(i);
        return v;
    }
    std::vector<double> ss(size_t b, size_t e) const {
        std::vector<double> v(e - b);
        for (size_t i = b; i < e; ++i) v[i - b] = s(i);
        return v;
    }
    std::vector<double> xsAt(const std::vector<size_t>& at) const {
        std::vector<double> v(at.size());
        for (size_t k = 0; k < at.size(); ++k) v[k] = x(at[k]);
        return v;
    }
    std::vector<double> ssAt(const std::vector<size_t>& at) const {
        std::vector<double> v(at.size());
        for (size_t k = 0; k < at.size(); ++k) v[k] = s(at[k]);
        return v;
    }
};

// The squared TOF (ms^2) of the records `at` (or all): tofMs(i) * tofMs(i), as a column only
// where a fit needs it.
Eigen::VectorXd squaredAt(const Eigen::VectorXd& tofMs, const std::vector<size_t>& at) {
    Eigen::VectorXd out(static_cast<Eigen::Index>(at.size()));
    for (size_t k = 0; k < at.size(); ++k) {
        const double v = tofMs(static_cast<Eigen::Index>(at[k]));
        out(static_cast<Eigen::Index>(k)) = v * v;
    }
    return out;
}
Eigen::VectorXd squared(const Eigen::VectorXd& tofMs) {
    Eigen::VectorXd out(tofMs.size());
    for (Eigen::Index i = 0; i < tofMs.size(); ++i) out(i) = tofMs(i) * tofMs(i);
    return out;
}

}  // namespace

namespace {

// The robust (Huber) fit of the squared time of flight by the Legendre basis `a`, iterated until
// the residuals' scale settles: the residuals in ms into *resid, the robust scale (ms) into
// *scale, the robust weights of the fit they come from into *weightsOut (when given). 1 fitted,
// 0 not (degenerate), -1 cancelled.
int robustTofTrend(const Eigen::MatrixXd& a, const Eigen::VectorXd& tofMs, const Eigen::VectorXd& ysq,
                   const TrendOcParams& params, const Feedback* feedback, Eigen::VectorXd* residOut, double* scaleOut,
                   Eigen::VectorXd* coefOut, Eigen::VectorXd* weightsOut = nullptr) {
    const Eigen::Index nn = tofMs.size();
    // Weights in tof^2 space: d(tof^2) = 2 tof d(tof), so 1/(2 tof)^2 makes the fit least squares in tof.
    Eigen::VectorXd base(nn), w = Eigen::VectorXd::Ones(nn), resid = Eigen::VectorXd::Zero(nn);
    for (Eigen::Index i = 0; i < nn; ++i) base(i) = tofMs(i) > 0 ? 1.0 / (4.0 * tofMs(i) * tofMs(i)) : 0.0;
    double scale = NAN;
    bool fitted = false;
    for (int it = 0; it < params.maxIterations; ++it) {
        if (cancelled(feedback)) return -1;
        const Eigen::VectorXd sw = w.cwiseProduct(base).cwiseSqrt();
        const Eigen::MatrixXd aw = sw.asDiagonal() * a;
        const Eigen::VectorXd coef = aw.colPivHouseholderQr().solve(sw.cwiseProduct(ysq));
        if (!coef.allFinite()) break;
        const Eigen::VectorXd fit = a * coef;
        Eigen::VectorXd r(nn);
        bool good = true;
        for (Eigen::Index i = 0; i < nn && good; ++i) {
            good = fit(i) > 0;
            r(i) = good ? tofMs(i) - std::sqrt(fit(i)) : 0;
        }
        if (!good) break;  // a non-positive squared trend: keep the previous fit
        if (coefOut) *coefOut = coef;
        if (weightsOut) *weightsOut = w;
        resid = r;
        fitted = true;
        std::vector<double> absr(static_cast<size_t>(nn));
        for (Eigen::Index i = 0; i < nn; ++i) absr[static_cast<size_t>(i)] = std::fabs(resid(i));
        const double s = 1.4826 * medianOf(absr);
        if (!(s > 0)) {
            scale = 0;
            break;
        }
        Eigen::VectorXd wn(nn);
        for (Eigen::Index i = 0; i < nn; ++i) {
            const double u = std::fabs(resid(i)) / (params.huberK * s);
            wn(i) = u <= 1 ? 1.0 : 1.0 / u;  // Huber weights: bounded influence, not mode-seeking
        }
        const bool converged = std::isfinite(scale) && std::fabs(s - scale) <= 1e-6 * scale;
        scale = s;
        w = wn;
        if (converged) break;
    }
    *residOut = resid;
    *scaleOut = scale;
    return fitted ? 1 : 0;
}

// ---- the orbit arc (issue 43) ------------------------------------------------------------------
//
// TOF^2 (ms^2) = sum_k c_k P_k(x) (k = 0..p) + B cos(w s) + C sin(w s), s = t - t_mid (s), x the
// normalised time: the range of a circular orbit past a station (see oc.hpp), linear for a given
// w. The fit is the polynomial's (Huber IRLS, least squares in the TOF), then for the arc a few
// bisquare steps from the Huber solution (a redescending weight: a noise point microseconds off
// a short pass takes no part in the arc). w is searched on a log grid, then by golden section.

struct ArcFit {
    bool ok = false;
    int degree = 0;          // of the polynomial under the arc
    int rotation = 0;        // the Earth's rotation terms (arcDesign)
    double omega = NAN;      // rad/s
    double scale = NAN;      // robust scale of the TOF residuals (ms)
    double bic = INFINITY;   // n ln(scale^2) + k ln n
    Eigen::VectorXd resid;   // TOF residuals (ms)
    Eigen::VectorXd coef;    // the design's coefficients (ms^2): the polynomial's, then B and C
    Eigen::VectorXd weights; // the robust weights of the final fit (empty when it was fitted on a subsample)
};

// The arc's design: the polynomial's columns, cos(w s), sin(w s) and, for the Earth's rotation
// (`rotation` 1: first order, 2: exact for a circular orbit), the terms of the frequencies w -/+ w_E:
// the station turning at w_E about the pole makes r_sat . r_station a sum of cos and sin at w and
// w -/+ w_E, whose span is that of cos(w s), sin(w s) times sin(w_E s) (1) and cos(w_E s) - 1 (2).
Eigen::MatrixXd arcDesign(const Eigen::MatrixXd& poly, const std::vector<double>& s, double omega, int rotation) {
    const Eigen::Index c0 = poly.cols();
    Eigen::MatrixXd a(poly.rows(), c0 + 2 + 2 * rotation);
    a.leftCols(c0) = poly;
    for (Eigen::Index i = 0; i < poly.rows(); ++i) {
        const double si = s[static_cast<size_t>(i)];
        const double c = std::cos(omega * si), sn = std::sin(omega * si);
        a(i, c0) = c;
        a(i, c0 + 1) = sn;
        if (rotation >= 1) {
            const double e = std::sin(kEarthRotationRate * si);
            a(i, c0 + 2) = c * e;
            a(i, c0 + 3) = sn * e;
        }
        if (rotation >= 2) {
            const double e = std::cos(kEarthRotationRate * si) - 1;
            a(i, c0 + 4) = c * e;
            a(i, c0 + 5) = sn * e;
        }
    }
    return a;
}

// The robust fit of the design `a` to the squared TOF, as robustTofTrend (Huber), then
// `bisquareSteps` Tukey bisquare steps (c = 4.685 robust sigma). Returns the robust scale (ms),
// NaN when degenerate; residuals into *resid, the robust weights of the fit they come from into
// *weightsOut (when given).
double robustArcResiduals(const Eigen::MatrixXd& a, const Eigen::VectorXd& tofMs, const Eigen::VectorXd& ysq, double huberK,
                          int maxIterations, int bisquareSteps, Eigen::VectorXd* resid, Eigen::VectorXd* coefOut,
                          Eigen::VectorXd* weightsOut = nullptr) {
    const Eigen::Index nn = tofMs.size();
    Eigen::VectorXd base(nn), w = Eigen::VectorXd::Ones(nn), r = Eigen::VectorXd::Zero(nn);
    for (Eigen::Index i = 0; i < nn; ++i) base(i) = tofMs(i) > 0 ? 1.0 / (4.0 * tofMs(i) * tofMs(i)) : 0.0;
    double scale = NAN;
    bool fitted = false;
    int bisquare = 0;
    for (int it = 0; it < maxIterations + bisquareSteps; ++it) {
        const Eigen::VectorXd sw = w.cwiseProduct(base).cwiseSqrt();
        const Eigen::VectorXd coef = (sw.asDiagonal() * a).colPivHouseholderQr().solve(sw.cwiseProduct(ysq));
        if (!coef.allFinite()) break;
        const Eigen::VectorXd fit = a * coef;
        Eigen::VectorXd rn(nn);
        bool good = true;
        for (Eigen::Index i = 0; i < nn && good; ++i) {
            good = fit(i) > 0;
            rn(i) = good ? tofMs(i) - std::sqrt(fit(i)) : 0;
        }
        if (!good) break;
        r = rn;
        *coefOut = coef;
        if (weightsOut) *weightsOut = w;
        fitted = true;
        std::vector<double> absr(static_cast<size_t>(nn));
        for (Eigen::Index i = 0; i < nn; ++i) absr[static_cast<size_t>(i)] = std::fabs(r(i));
        const double sc = 1.4826 * medianOf(absr);
        if (!(sc > 0)) {
            scale = 0;
            break;
        }
        const bool converged = std::isfinite(scale) && std::fabs(sc - scale) <= 1e-6 * scale;
        scale = sc;
        const bool tukey = converged || it >= maxIterations;
        if (tukey && ++bisquare > bisquareSteps) break;
        for (Eigen::Index i = 0; i < nn; ++i) {
            if (tukey) {
                const double u = r(i) / (4.685 * sc);
                w(i) = std::fabs(u) < 1 ? (1 - u * u) * (1 - u * u) : 0.0;
            } else {
                const double u = std::fabs(r(i)) / (huberK * sc);
                w(i) = u <= 1 ? 1.0 : 1.0 / u;
            }
        }
        if (tukey && w.sum() < static_cast<double>(a.cols()) + 1) break;  // too few points left to fit
    }
    if (!fitted) return NAN;
    *resid = r;
    return scale;
}

// Whether a fitted arc is a satellite's orbit: the constant A = (2/c)^2 (Re^2 + R^2) of TOF^2 gives
// the orbit's radius R (Re: 6371 km), and the angular rate must be Kepler's for it,
// sqrt(GM/R^3), within the Earth's rotation (1.5 w_E: the pass's apparent rate differs by up to
// w_E cos i) and 10 % (an eccentric orbit's rate varies along it: Beacon-C, e = 0.025, by 5 %).
// Without this a long dense pass's arc, with its rotation terms, can fit the gate's noise with
// any rate. Only for an arc without a polynomial (its constant is then A).
bool arcIsAnOrbit(const Eigen::VectorXd& coef, double omega, int degree) {
    if (degree != 0 || coef.size() < 1) return false;
    constexpr double kRe = 6371e3;
    const double halfC = 0.5 * kSpeedOfLight * 1e-3;  // ms of two-way TOF -> m of range
    const double r2 = coef(0) * halfC * halfC - kRe * kRe;
    if (!(r2 > 0)) return false;
    const double R = std::sqrt(r2);
    if (R < kRe + 150e3) return false;
    const double n = std::sqrt(kEarthGm / (R * R * R));
    return std::fabs(omega - n) <= 1.5 * kEarthRotationRate + 0.1 * n;
}

// The best arc for a polynomial of `degree` under it: w on a log grid over [5e-5, 1.4e-3] rad/s,
// refined by golden section, each w scored by the robust scale of its Huber fit (on at most 600
// points, evenly taken); the final fit at the best w on every point (at most fitMaxPoints).
ArcFit fitArc(const Epochs& ep, const Eigen::VectorXd& tofMs, int degree, int rotation, const TrendOcParams& params) {
    ArcFit best;
    const bool checkOrbit = true;
    const size_t n = ep.size();
    const size_t step = std::max<size_t>(1, (n + 599) / 600);
    std::vector<double> xs, ss;
    std::vector<Eigen::Index> pick;
    for (size_t i = 0; i < n; i += step) {
        xs.push_back(ep.x(i));
        ss.push_back(ep.s(i));
        pick.push_back(static_cast<Eigen::Index>(i));
    }
    Eigen::VectorXd ts(static_cast<Eigen::Index>(pick.size())), ys(ts.size());
    for (Eigen::Index k = 0; k < ts.size(); ++k) {
        const double v = tofMs(pick[static_cast<size_t>(k)]);
        ts(k) = v, ys(k) = v * v;
    }
    const Eigen::MatrixXd polySub = legendre(xs, degree);
    const int iters = std::min(params.maxIterations, 30);
    auto score = [&](double lw) {
        Eigen::VectorXd r, coef;
        const double sc =
            robustArcResiduals(arcDesign(polySub, ss, std::exp(lw), rotation), ts, ys, params.huberK, iters, 0, &r, &coef);
        return std::isfinite(sc) && (!checkOrbit || arcIsAnOrbit(coef, std::exp(lw), degree)) ? sc : INFINITY;
    };
    const double lo = std::log(5e-5), hi = std::log(1.4e-3);
    constexpr int kGrid = 48;
    double bestLw = lo, bestScore = INFINITY;
    std::vector<double> grid(kGrid + 1);
    for (int g = 0; g <= kGrid; ++g) {
        const double lw = lo + (hi - lo) * g / kGrid;
        grid[static_cast<size_t>(g)] = score(lw);
        if (grid[static_cast<size_t>(g)] < bestScore) bestScore = grid[static_cast<size_t>(g)], bestLw = lw;
    }
    if (!std::isfinite(bestScore)) return best;
    // Golden section in the grid cell pair about the best node.
    const double h = (hi - lo) / kGrid;
    double fMin = INFINITY;
    const double lw = goldenSection(std::max(lo, bestLw - h), std::min(hi, bestLw + h), 30, 1e-7, score, &fMin);
    if (fMin <= bestScore) bestLw = lw;
    best.omega = std::exp(bestLw);
    best.degree = degree;
    best.rotation = rotation;
    Eigen::VectorXd coef;
    if (n <= params.fitMaxPoints) {
        const Eigen::MatrixXd a2 = arcDesign(legendre(ep.xs(0, n), degree), ep.ss(0, n), best.omega, rotation);
        best.scale = robustArcResiduals(a2, tofMs, squared(tofMs), params.huberK, params.maxIterations, 3, &best.resid, &coef,
                                        &best.weights);
    } else {  // (a kHz pass: fitted on fitMaxPoints of its records)
        const std::vector<size_t> at = evenlyTaken(n, params.fitMaxPoints);
        Eigen::VectorXd rf;
        best.scale = robustArcResiduals(arcDesign(legendre(ep.xsAt(at), degree), ep.ssAt(at), best.omega, rotation),
                                        takeAt(tofMs, at), squaredAt(tofMs, at), params.huberK, params.maxIterations, 3, &rf, &coef);
        const auto design = [&](size_t b, size_t e) {
            return arcDesign(legendre(ep.xs(b, e), degree), ep.ss(b, e), best.omega, rotation);
        };
        if (std::isfinite(best.scale) && !residualsOfAll(n, design, coef, tofMs, &best.resid)) best.scale = NAN;
    }
    best.coef = coef;
    if (!std::isfinite(best.scale) || (checkOrbit && !arcIsAnOrbit(coef, best.omega, degree))) return best;
    // The scale of the fit: the bisquare's residuals, MAD about zero.
    std::vector<double> absr(n);
    for (size_t i = 0; i < n; ++i) absr[i] = std::fabs(best.resid(static_cast<Eigen::Index>(i)));
    best.scale = 1.4826 * medianOf(absr);
    const double nn = static_cast<double>(n);
    const int k = degree + 1 + 2 + 2 * rotation + 1;  // the polynomial, B and C, the rotation's, and w
    best.bic = nn * std::log(std::max(best.scale, 1e-18) * std::max(best.scale, 1e-18)) + k * std::log(nn);
    best.ok = true;
    return best;
}

// The hat matrix (orbit_fit.hpp leastSquaresHat) of a fit of the squared TOF linear in its
// coefficients, tof_i^2 = a_i . c, with the robust weights w of its last solve: in the TOF its
// Jacobian is a_i / (2 f_i), f the fitted TOF, with a column d f_i / d omega for the arc's rate
// when given (its design's derivative, by central differences, times the coefficients). Empty
// when the weights are not the design's length.
std::vector<double> tofSquaredHat(const Eigen::MatrixXd& a, const Eigen::VectorXd& tofMs, const Eigen::VectorXd& residMs,
                                  const Eigen::VectorXd& w, const std::function<Eigen::MatrixXd(double)>* design,
                                  double omega, const Eigen::VectorXd& coef) {
    const Eigen::Index n = a.rows();
    if (w.size() != n) return {};
    Eigen::MatrixXd J(n, a.cols() + (design ? 1 : 0));
    for (Eigen::Index i = 0; i < n; ++i) J.row(i).head(a.cols()) = a.row(i) / (2 * (tofMs(i) - residMs(i)));
    if (design) {
        const double h = 1e-6 * omega;
        const Eigen::VectorXd dA = ((*design)(omega + h) - (*design)(omega - h)) * coef / (2 * h);
        for (Eigen::Index i = 0; i < n; ++i) J(i, a.cols()) = dA(i) / (2 * (tofMs(i) - residMs(i)));
    }
    return leastSquaresHat(J, w);
}

// The circular orbit's fit (orbit_fit.hpp) on passes under 50 records, the screening's "short
// LEO pass" (the arc's own rule for a short pass): a longer pass has the records to fit the arc's
// free coefficients, and its satellite may be eccentric (Beacon-C, e = 0.025, 96 records of
// which half are noise: its normal points went 3.4 → 11.7 mm from the station's with the circle).
constexpr int kMaxOrbitFitPoints = 49;
// A fitted trend's hat matrix is kept for the short passes (the arc's and the orbit's "short
// LEO pass"): PassTask judges their normal points' precision by it (pass_run.hpp
// kMaxNpTrendErrorMm). On longer passes the estimate was not validated against a truth: on the
// clean lunar simulations (~1000 events) the post-fit alone would put 3-5 mm on normal points
// whose own precision is 3-4 mm (docs/slr-detection.md).
constexpr size_t kMaxTrendHatPoints = kMaxOrbitFitPoints;

// Elevation and azimuth at a pass's epochs, interpolated in its pointing records (type 30);
// NaN without them.
class PointingAngles {
public:
    explicit PointingAngles(const CrdPass& pass) {
        for (const auto& p : pass.pointing) pts.emplace_back(pass.passSeconds(p.secOfDay), &p);
        std::stable_sort(pts.begin(), pts.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
    }
    void at(double tt, double* az, double* el) const {
        *az = *el = NAN;
        if (pts.empty()) return;
        size_t k = static_cast<size_t>(std::upper_bound(pts.begin(), pts.end(), tt,
                                                        [](double v, const auto& p) { return v < p.first; }) -
                                       pts.begin());
        const CrdPointing* a0 = pts[k == 0 ? 0 : k - 1].second;
        const CrdPointing* a1 = pts[k >= pts.size() ? pts.size() - 1 : k].second;
        const double ta = pts[k == 0 ? 0 : k - 1].first, tb = pts[k >= pts.size() ? pts.size() - 1 : k].first;
        const double u = tb > ta ? (tt - ta) / (tb - ta) : 0;
        *el = (a0->elevationDeg + u * (a1->elevationDeg - a0->elevationDeg)) * M_PI / 180;
        double daz = a1->azimuthDeg - a0->azimuthDeg;
        if (daz > 180) daz -= 360;
        if (daz < -180) daz += 360;
        *az = std::fmod(a0->azimuthDeg + u * daz + 360.0, 360.0) * M_PI / 180;
    }

private:
    std::vector<std::pair<double, const CrdPointing*>> pts;
};

}  // namespace

OcResult computeTrendOc(const CrdPass& pass, const TrendOcParams& params, const Feedback* feedback) {
    OcResult res;
    res.method = OcMethod::FittedTrend;
    try {
        if (const std::string e = validate(params); !e.empty()) {
            res.error = e;
            return res;
        }
        const std::string name = passName(pass);
        res.startMjd = pass.startMjd();
        std::vector<double> t;
        std::vector<uint32_t> idx;
        t.reserve(pass.ranges.size()), idx.reserve(pass.ranges.size());
        for (size_t i = 0; i < pass.ranges.size(); ++i) {
            t.push_back(pass.passSeconds(pass.ranges.secOfDay(i)));
            idx.push_back(static_cast<uint32_t>(i));
        }
        if (static_cast<int>(t.size()) < params.minPoints) {
            res.error = name + ": " + std::to_string(t.size()) + " full-rate records; at least " +
                        std::to_string(params.minPoints) + " are needed for a trend";
            return res;
        }
        const auto [tminIt, tmaxIt] = std::minmax_element(t.begin(), t.end());
        const double t0 = *tminIt, t1 = *tmaxIt;
        if (!(t1 - t0 > 0)) {
            res.error = name + ": all records share one epoch; no trend can be fitted";
            return res;
        }
        // (n-1)/4 keeps 4 records per coefficient; a short pass still gets a quadratic (a LEO
        // pass's range is not a line over a minute), with 2 degrees of freedom left at 5 records.
        const int n = static_cast<int>(t.size());
        const int degree = std::max(1, std::min(params.degree, std::max((n - 1) / 4, std::min(2, n - 3))));
        const std::string lowered = degree < params.degree ? name + ": trend degree lowered to " + std::to_string(degree) +
                                                                 " for " + std::to_string(t.size()) + " records"
                                                           : std::string();
        const Epochs ep{t, t0, t1, 0.5 * (t0 + t1)};
        // The polynomial models the squared time of flight (ms^2): a pass's range is close to
        // sqrt(d^2 + v^2 (t - t0)^2), so its square is nearly quadratic in time and a low degree
        // reaches the ranging noise where a polynomial in the range itself needs degree > 12.
        const Eigen::Index nn = static_cast<Eigen::Index>(t.size());
        Eigen::VectorXd tofMs(nn);
        for (Eigen::Index i = 0; i < nn; ++i) tofMs(i) = pass.ranges.tofS(static_cast<size_t>(i)) * 1e3;
        Eigen::VectorXd resid, polyWeights;
        double scale = NAN;
        int fit;
        if (t.size() <= params.fitMaxPoints) {
            fit = robustTofTrend(legendre(ep.xs(0, t.size()), degree), tofMs, squared(tofMs), params, feedback, &resid, &scale,
                                 nullptr, &polyWeights);
        } else {  // (a kHz pass: fitted on fitMaxPoints of its records, the residuals of all)
            const std::vector<size_t> at = evenlyTaken(t.size(), params.fitMaxPoints);
            Eigen::VectorXd coef;
            fit = robustTofTrend(legendre(ep.xsAt(at), degree), takeAt(tofMs, at), squaredAt(tofMs, at), params, feedback,
                                 &resid, &scale, &coef);
            const auto design = [&](size_t b, size_t e) { return legendre(ep.xs(b, e), degree); };
            if (fit > 0 && !residualsOfAll(t.size(), design, coef, tofMs, &resid)) fit = 0;
            if (fit > 0) {
                std::vector<double> absr(t.size());
                for (size_t i = 0; i < t.size(); ++i) absr[i] = std::fabs(resid(static_cast<Eigen::Index>(i)));
                scale = 1.4826 * medianOf(absr);
            }
        }
        if (fit < 0) {
            res = OcResult();
            res.error = "cancelled";
            return res;
        }
        const bool fitted = fit > 0;
        if (!fitted) {
            res.error = name + ": the trend fit failed (degenerate epochs or times of flight)";
            return res;
        }
        res.trendDegree = degree;
        res.trendScaleS = std::isfinite(scale) ? scale * 1e-3 : NAN;
        // The orbit arc (issue 43), when the data say it fits better: at least 8 records (4
        // parameters and as many degrees of freedom), at most half the polynomial's robust
        // scatter, and a lower BIC (n ln(scale^2) + k ln n) than the polynomial's.
        ArcFit arc, start;  // (start: the plain arc, whose rate centres the circular orbit's search)
        if (params.orbitArc && n >= 8 && std::isfinite(scale)) {
            // (polynomial degree, rotation terms): 4 + degree + 2 rotation parameters, each model
            // with 4 records more than parameters.
            for (const auto& [p, rot] : {std::pair{0, 0}, {0, 1}, {0, 2}}) {
                if (4 + p + 2 * rot + 4 > n) continue;
                if (cancelled(feedback)) {
                    res = OcResult();
                    res.error = "cancelled";
                    return res;
                }
                ArcFit f = fitArc(ep, tofMs, p, rot, params);
                if (rot == 0 && f.coef.size() >= 3 && std::isfinite(f.omega)) {
                    start.omega = f.omega;  // (its rate and coefficients: not a copy of its residuals)
                    start.coef = f.coef;
                }
                if (f.ok && f.bic < arc.bic) arc = std::move(f);
            }
            const double nd = static_cast<double>(n);
            const double polyBic = nd * std::log(std::max(scale, 1e-18) * std::max(scale, 1e-18)) + (degree + 1) * std::log(nd);
            // A short pass (under 50 records, the screening's "short LEO pass") takes the arc when
            // it is an orbit (arcIsAnOrbit): too few records to tell the models by their scatter,
            // and the polynomial in TOF^2 is not the geometry. A longer one only when the arc
            // halves the scatter and has the lower BIC (a dense pass's scatter is its gate's
            // noise, which either model follows: the polynomial stays unless the arc is clearly better).
            if (arc.ok && (n < 50 || arc.scale <= 0.5 * scale) && arc.bic < polyBic) {
                resid.swap(arc.resid);
                res.trendDegree = arc.degree;
                res.trendScaleS = arc.scale * 1e-3;
                res.trendArcRateRadS = arc.omega;
            } else {
                arc.ok = false;
            }
        }
        // The circular orbit itself (orbit_fit.hpp) where the ILRS table knows the station: its
        // search about the plain arc's rate, on the points within 5 robust sigma of the trend so
        // far. Taken when its BIC on those points' sums of squares is below the trend's so far (the
        // MAD of 10–30 residuals is too noisy to tell models apart by).
        CircularOrbitResult orbit;
        const IlrsStation* station = findStation(pass.station.cdpPadId);
        if (params.orbitArc && params.circularOrbit && station && start.coef.size() >= 3 && n >= 10 &&
            n <= kMaxOrbitFitPoints) {
            CircularOrbitParams cp;
            cp.arcRate = start.omega;
            cp.stationEcef = ecefFromGeodetic(station->latDeg, station->lonDeg, station->heightM);
            const double lim = 5 * std::max(res.trendScaleS, 1e-12);
            std::vector<double> s(t.size()), w(t.size()), y(t.size());
            double ssRef = 0, m = 0;
            for (size_t i = 0; i < t.size(); ++i) {
                const double r = resid(static_cast<Eigen::Index>(i)) * 1e-3;
                s[i] = ep.s(i);
                y[i] = pass.ranges.tofS(idx[i]);
                w[i] = std::fabs(r) <= lim ? 1.0 : 0.0;
                ssRef += w[i] * r * r;
                m += w[i];
            }
            const int kRef = arc.ok ? arc.degree + 4 + 2 * arc.rotation : degree + 1;
            const double best = m * std::log(std::max(ssRef, 1e-40) / m) + kRef * std::log(m);
            if (cancelled(feedback)) {
                res = OcResult();
                res.error = "cancelled";
                return res;
            }
            CircularOrbitResult f = fitCircularOrbit(s, y, w, cp);
            if (f.ok) {
                double ss = 0;
                for (size_t i = 0; i < t.size(); ++i) ss += w[i] * f.residualS[i] * f.residualS[i];
                const double bic = m * std::log(std::max(ss, 1e-40) / m) + f.parameters * std::log(m);
                if (bic < best) orbit = std::move(f);
            }
            if (orbit.ok) {
                for (size_t i = 0; i < t.size(); ++i) resid(static_cast<Eigen::Index>(i)) = orbit.residualS[i] * 1e3;
                arc.ok = false;
                res.trendDegree = 0;
                res.trendScaleS = orbit.scaleS;
                res.trendArcRateRadS = orbit.meanMotion;
                res.trendOrbit = true;
            }
        }

        // The trend's hat matrix where the pass is short enough to hold it (PassData::trendHat).
        if (t.size() <= kMaxTrendHatPoints && t.size() <= params.fitMaxPoints) {  // (fitted on every record)
            if (orbit.ok) {
                res.trendHat = std::move(orbit.hat);
            } else if (arc.ok) {
                const std::function<Eigen::MatrixXd(double)> design = [&](double om) {
                    return arcDesign(legendre(ep.xs(0, t.size()), arc.degree), ep.ss(0, t.size()), om, arc.rotation);
                };
                res.trendHat = tofSquaredHat(design(arc.omega), tofMs, resid, arc.weights, &design, arc.omega, arc.coef);
            } else {
                res.trendHat = tofSquaredHat(legendre(ep.xs(0, t.size()), degree), tofMs, resid, polyWeights, nullptr, 0.0,
                                             Eigen::VectorXd());
            }
        }
        // The columns, each sized once (a column grown by doubling held up to 1.5 copies of
        // itself), the O-C first so that the fit's columns are freed before the others are made
        // (issue 44: a kHz pass's peak was here). Elevation and azimuth from the pointing records
        // (type 30) when there are some, else no column; no refraction column (none is computed).
        const size_t points = t.size();
        res.oc_s.resize(points);
        for (size_t i = 0; i < points; ++i) res.oc_s[i] = resid(static_cast<Eigen::Index>(i)) * 1e-3;
        resid = Eigen::VectorXd();
        tofMs = Eigen::VectorXd();
        if (!pass.pointing.empty()) {
            const PointingAngles angles(pass);
            res.elevation_rad.resize(points), res.azimuth_rad.resize(points);
            for (size_t i = 0; i < points; ++i) angles.at(t[i], &res.azimuth_rad[i], &res.elevation_rad[i]);
        }
        res.tof_s.resize(points), res.line.resize(points), res.filter_flag.resize(points);
        for (size_t i = 0; i < points; ++i) {
            const size_t k = idx[i];
            res.tof_s[i] = pass.ranges.tofS(k);
            res.line[i] = pass.ranges.line(k);
            res.filter_flag[i] = static_cast<int8_t>(pass.ranges.filterFlag(k));
        }
        res.epoch_s = std::move(t);  // (the epochs and the records' indices as they are)
        res.range_index = std::move(idx);
        if (!arc.ok && !orbit.ok && !lowered.empty()) res.warnings.push_back(lowered);  // (the polynomial's only)
        if (orbit.ok)
            res.notes.push_back(name + ": no prediction: O-C is relative to a robust orbit-arc trend of the time of flight (" +
                                "a circular orbit's range past the station fitted to the pass: radius " +
                                formatFixed(orbit.radiusM / 1e3, 1) + " km, " + formatFixed(orbit.meanMotion * 1e3, 4) +
                                " mrad/s (Kepler's for the radius), the station where the ILRS table puts it; a range "
                                "bias is absorbed)");
        else if (arc.ok)
            res.notes.push_back(name + ": no prediction: O-C is relative to a robust orbit-arc trend of the time of flight (" +
                                "a circular orbit's range past the station, " + formatFixed(arc.omega * 1e3, 4) +
                                " mrad/s, " +
                                (arc.rotation ? std::string("with the Earth's rotation")
                                              : "with a degree-" + std::to_string(arc.degree) + " polynomial") +
                                "; a range bias and smooth drifts are absorbed)");
        else
            res.notes.push_back(name + ": no prediction: O-C is relative to a robust degree-" + std::to_string(degree) +
                                " polynomial trend of the time of flight (a range bias and smooth drifts are absorbed)");
        if (feedback) feedback->setProgress(1.0);
        res.ok = true;
    } catch (const std::exception& e) {
        res = OcResult();
        res.error = std::string("internal error: ") + e.what();
    }
    return res;
}

}  // namespace lwb::core::slr
