#include "core/slr/np_compare.hpp"
#include "core/slr/oc.hpp"
#include "core/slr/slr_time.hpp"

#include <cstdio>

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "core/common/text.hpp"

namespace lwb::core::slr {

namespace {

std::string withoutLeadingZeros(const std::string& id) {
    const size_t k = id.find_first_not_of("0 ");
    return k == std::string::npos ? std::string() : id.substr(k);
}

bool sameSatellite(const PassData& pass, const CrdTarget& target) {
    const std::string a = withoutLeadingZeros(pass.ilrsId), b = withoutLeadingZeros(target.ilrsId);
    if (!a.empty() && !b.empty()) return a == b;
    if (!pass.satellite.empty() && !target.name.empty()) return toLower(pass.satellite) == toLower(target.name);
    return true;  // (nothing to tell them apart by)
}

// The computed TOF (TOF − O-C of the pass's points: the prediction, or the fitted TOF trend) at
// t: a polynomial through the 12 points nearest in time (degree up to 5; the computed TOF is
// smooth, and a straight line between 10 Hz points is off by 0.4 ns on a LEO pass). NaN when t
// is farther than `reach` outside the points.
double computedTofAt(const PassData& pass, double t, double reach) {
    const size_t n = pass.t.size();
    if (n < 2 || pass.tof.size() != n || t < pass.t.front() - reach || t > pass.t.back() + reach) return NAN;
    size_t hi = static_cast<size_t>(std::lower_bound(pass.t.begin(), pass.t.end(), t) - pass.t.begin());
    size_t lo = hi;
    constexpr size_t kPoints = 12;
    while (hi - lo < kPoints && (lo > 0 || hi < n)) {
        if (lo == 0) ++hi;
        else if (hi == n) --lo;
        else if (t - pass.t[lo - 1] <= pass.t[hi] - t) --lo;
        else ++hi;
    }
    const size_t m = hi - lo;
    double h = 0;
    for (size_t k = lo; k < hi; ++k) h = std::max(h, std::fabs(pass.t[k] - t));
    if (m < 2 || h <= 0) return NAN;
    const double ref = pass.tof[lo] - pass.oc[lo];
    const int degree = static_cast<int>(std::min<size_t>(5, m - 1));
    Eigen::MatrixXd A(static_cast<Eigen::Index>(m), degree + 1);
    Eigen::VectorXd b(static_cast<Eigen::Index>(m));
    for (size_t k = 0; k < m; ++k) {
        const double u = (pass.t[lo + k] - t) / h;
        double p = 1;
        for (int d = 0; d <= degree; ++d, p *= u) A(static_cast<Eigen::Index>(k), d) = p;
        b(static_cast<Eigen::Index>(k)) = (pass.tof[lo + k] - pass.oc[lo + k]) - ref;
    }
    return ref + A.colPivHouseholderQr().solve(b)(0);
}

// The station block to compare with: the pass's satellite, the most normal points within the
// pass's span. -1 when none.
int pickBlock(const PassData& pass, long passMjd, const CrdFile& station, double reach) {
    int best = -1;
    size_t bestCount = 0;
    for (size_t k = 0; k < station.passes.size(); ++k) {
        const CrdPass& b = station.passes[k];
        if (b.normalPoints.empty() || !b.problem.empty() || !sameSatellite(pass, b.target)) continue;
        const double offset = static_cast<double>(b.startMjd() - passMjd) * 86400.0;
        size_t count = 0;
        for (const CrdNormalPoint& np : b.normalPoints) {
            const double t = offset + b.passSeconds(np.secOfDay);
            count += t >= pass.t.front() - reach && t <= pass.t.back() + reach;
        }
        if (count > bestCount) {
            bestCount = count;
            best = static_cast<int>(k);
        }
    }
    return best;
}

}  // namespace

std::string NpComparison::describe() const {
    if (!ok) return error;
    const size_t station = matched + stationOnly, ours = matched + oursOnly;
    std::string s = std::to_string(station) + " station normal point" + (station == 1 ? "" : "s") + ", " + std::to_string(ours) +
                    " ours (bins of " + formatFixed(binLengthS, 0) + " s): " + std::to_string(matched) + " in the same bins";
    if (matched)
        s += ", ours − station " + formatFixed(meanMm, 2) + " mm mean, " + formatFixed(meanAbsMm, 2) + " mm mean |Δ|, " +
             formatFixed(rmsMm, 2) + " mm RMS (one-way)";
    if (stationOnly) s += "; " + std::to_string(stationOnly) + " only the station's";
    if (oursOnly) s += "; " + std::to_string(oursOnly) + " only ours";
    return s;
}

std::string npComparisonCsv(const NpComparison& c) {
    auto num = [](double v, int decimals) {
        if (!std::isfinite(v)) return std::string();
        char b[64];
        std::snprintf(b, sizeof b, "%.*f", decimals, v);
        return std::string(b);
    };
    auto count = [](int n) { return n > 0 ? std::to_string(n) : std::string(); };
    auto iso = [&c](double t) {
        if (!std::isfinite(t)) return std::string();
        const long long ms = std::llround(t * 1000.0);
        const long long dayMs = 86400000LL;
        const long long days = ms >= 0 ? ms / dayMs : -((-ms + dayMs - 1) / dayMs);  // (a bin before 0h: the day before)
        const long long of = ms - days * dayMs;
        int y = 0, mo = 0, d = 0;
        dateFromMjd(c.dayMjd + static_cast<long>(days), &y, &mo, &d);
        char b[48];
        std::snprintf(b, sizeof b, "%04d-%02d-%02dT%02lld:%02lld:%02lld.%03lldZ", y, mo, d, of / 3600000, of / 60000 % 60,
                      of / 1000 % 60, of % 1000);
        return std::string(b);
    };
    std::string out = "utc,epoch_s,match,delta_mm,station_ranges,our_ranges,station_rms_ps,our_rms_ps,station_oc_s,station_residual_s\n";
    for (const NpDifference& d : c.rows) {
        const char* match = d.match == NpDifference::Match::Both          ? "both"
                            : d.match == NpDifference::Match::StationOnly ? "station_only"
                                                                          : "ours_only";
        out += iso(d.t) + "," + num(d.t, 3) + "," + match + "," + num(d.deltaMm, 2) + "," + count(d.stationRanges) + "," +
               count(d.ourRanges) + "," + num(d.stationRmsPs, 1) + "," + num(d.ourRmsPs, 1) + "," + num(d.stationOcS, 12) +
               "," + num(d.stationResidualS, 12) + "\n";
    }
    return out;
}

NpComparison compareWithStation(const PassData& pass, const PostfitResult& post, const CrdFile& station,
                                const std::string& stationPath) {
    NpComparison c;
    const std::string where = stationPath.empty() ? std::string("the station's normal points") : stationPath;
    if (!pass.hasCrd || !pass.crd || pass.passIndex < 0 || static_cast<size_t>(pass.passIndex) >= pass.crd->passes.size() ||
        pass.t.empty() || pass.tof.size() != pass.t.size()) {
        c.error = where + ": the open pass is not from a CRD file (no date to put the station's epochs on)";
        return c;
    }
    if (!post.ok) {
        c.error = where + ": the pass has no post-fit, so no normal points of ours to compare (" + post.error + ")";
        return c;
    }
    const CrdPass& mine = pass.crd->passes[static_cast<size_t>(pass.passIndex)];
    const long mjd = mine.startMjd();
    c.dayMjd = mjd;
    double L = post.binLengthS > 0 ? post.binLengthS : 30;
    const int k = pickBlock(pass, mjd, station, L);
    if (k < 0) {
        size_t withNps = 0;
        for (const CrdPass& b : station.passes) withNps += !b.normalPoints.empty();
        c.error = where + ": no normal points of " + (pass.satellite.empty() ? pass.ilrsId : pass.satellite) + " between " +
                  hmsRounded(pass.t.front()) + " and " + hmsRounded(pass.t.back()) + " UTC (the file holds " + std::to_string(withNps) +
                  " block" + (withNps == 1 ? "" : "s") + " of normal points; none of this satellite overlaps the pass)";
        return c;
    }
    const CrdPass& block = station.passes[static_cast<size_t>(k)];
    c.block = static_cast<size_t>(k);
    c.stationName = block.station.name;
    c.satellite = block.target.name;
    for (const CrdNormalPoint& np : block.normalPoints)
        if (std::isfinite(np.windowS) && np.windowS > 0) {
            L = np.windowS;
            break;
        }
    c.binLengthS = L;
    const double offset = static_cast<double>(block.startMjd() - mjd) * 86400.0;
    auto bin = [L](double t) { return static_cast<long long>(std::floor(t / L + 1e-9)); };
    std::vector<const NormalPoint*> ours;
    for (const NormalPoint& np : post.normalPoints) ours.push_back(&np);
    std::vector<bool> used(ours.size(), false);
    for (const CrdNormalPoint& s : block.normalPoints) {
        NpDifference d;
        d.stationT = d.t = offset + block.passSeconds(s.secOfDay);
        d.stationRanges = s.numRanges;
        d.stationRmsPs = s.binRmsPs;
        const double computed = computedTofAt(pass, d.stationT, L);
        if (std::isfinite(computed)) {
            d.stationOcS = s.tofS - computed;
            d.stationResidualS = d.stationOcS - evaluateTrend(post, d.stationT);
        }
        d.match = NpDifference::Match::StationOnly;
        for (size_t j = 0; j < ours.size(); ++j)
            if (!used[j] && bin(ours[j]->epochS) == bin(d.stationT)) {
                used[j] = true;
                d.match = NpDifference::Match::Both;
                d.ourT = ours[j]->epochS;
                d.ourRanges = ours[j]->points;
                d.ourRmsPs = ours[j]->rmsPs;
                if (std::isfinite(d.stationOcS))
                    d.deltaMm = (evaluateTrend(post, d.stationT) + ours[j]->meanResidualS - d.stationOcS) * 0.5 * kSpeedOfLight * 1e3;
                break;
            }
        c.rows.push_back(d);
    }
    for (size_t j = 0; j < ours.size(); ++j)
        if (!used[j]) {
            NpDifference d;
            d.match = NpDifference::Match::OursOnly;
            d.t = d.ourT = ours[j]->epochS;
            d.ourRanges = ours[j]->points;
            d.ourRmsPs = ours[j]->rmsPs;
            c.rows.push_back(d);
        }
    std::stable_sort(c.rows.begin(), c.rows.end(), [](const NpDifference& a, const NpDifference& b) { return a.t < b.t; });
    double sum = 0, sumAbs = 0, sum2 = 0;
    size_t withDelta = 0;
    for (const NpDifference& d : c.rows) {
        if (d.match == NpDifference::Match::Both) ++c.matched;
        else ++(d.match == NpDifference::Match::StationOnly ? c.stationOnly : c.oursOnly);
        if (!std::isfinite(d.deltaMm)) continue;
        ++withDelta;
        sum += d.deltaMm;
        sumAbs += std::fabs(d.deltaMm);
        sum2 += d.deltaMm * d.deltaMm;
    }
    if (withDelta) {
        const double n = static_cast<double>(withDelta);
        c.meanMm = sum / n;
        c.meanAbsMm = sumAbs / n;
        c.rmsMm = std::sqrt(sum2 / n);
    }
    c.ok = true;
    return c;
}

bool loadStationNormalPoints(const std::string& path, CrdFile* out, std::string* error) {
    CrdReadResult r = readCrd(path);
    if (!r.ok) {
        *error = r.error;
        return false;
    }
    size_t nps = 0;
    for (const CrdPass& p : r.file.passes) nps += p.normalPoints.size();
    if (nps == 0) {
        *error = path + ": no normal-point records (type 11): not a normal-point file";
        return false;
    }
    *out = std::move(r.file);
    return true;
}

}  // namespace lwb::core::slr
