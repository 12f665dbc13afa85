#include "core/slr/cpf.hpp"

#include <functional>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "core/common/atomic_file.hpp"
#include "core/common/text.hpp"
#include "core/slr/slr_time.hpp"

namespace lwb::core::slr {

namespace {

bool toInt(std::string_view s, long* out) {
    long long v = 0;
    if (parseLong(s, &v) && v > -2000000000LL && v < 2000000000LL) {
        *out = static_cast<long>(v);
        return true;
    }
    double d = 0;
    if (parseFortranDouble(s, &d) && d == std::floor(d) && std::fabs(d) < 2e9) {
        *out = static_cast<long>(d);
        return true;
    }
    return false;
}

std::string fmtSeconds(double s) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f", s);
    return buf;
}

}  // namespace

namespace {

using Warn = std::function<void(std::string)>;

// H1: "CPF <version> <source> <date> <hour> <sequence> [<sub-daily>] <target> ...". False with
// *error for a file that is no CPF (or a CRD).
bool parseCpfH1(const std::vector<std::string_view>& f, long lineNo, const std::string& src, CpfHeader& h,
                std::string* error) {
    if (f.size() < 3 || toLower(f[1]) != "cpf") {
        *error = whereInFile(src, lineNo) + "H1 must start with \"CPF <version>\"" +
                 (f.size() >= 2 && toLower(f[1]) == "crd" ? std::string(": this H1 names CRD ranging data, not a CPF prediction")
                                                          : std::string());
        return false;
    }
    long v = 0;
    if (!toInt(f[2], &v) || v < 1 || v > 9) {
        *error = whereInFile(src, lineNo) + "H1 format version is not 1 or 2: \"" + printableExcerpt(f[2]) + "\"";
        return false;
    }
    h.version = static_cast<int>(v);
    if (f.size() > 3) h.source = std::string(f[3]);
    long y = 0, m = 0, d = 0, hh = 0;
    if (f.size() > 7 && toInt(f[4], &y) && toInt(f[5], &m) && toInt(f[6], &d) && toInt(f[7], &hh)) {
        h.year = static_cast<int>(y), h.month = static_cast<int>(m), h.day = static_cast<int>(d),
        h.hour = static_cast<int>(hh);
    }
    size_t k = 8;
    if (f.size() > k) h.sequence = std::string(f[k++]);
    if (h.version >= 2 && f.size() > k) h.sequence += " " + std::string(f[k++]);
    if (f.size() > k) h.targetName = std::string(f[k++]);
    for (; k < f.size(); ++k) h.notes += (h.notes.empty() ? "" : " ") + std::string(f[k]);
    return true;
}

// H2: ids, the prediction's span and step, target type, frame, centre of mass.
void parseCpfH2(const std::vector<std::string_view>& f, long lineNo, const std::string& src, CpfHeader& h, const Warn& warn) {
    if (f.size() < 17) {
        warn(whereInFile(src, lineNo) + "H2 has " + std::to_string(f.size() - 1) + " fields (expected >= 16); ignored");
        return;
    }
    h.ilrsId = std::string(f[1]);
    long v[15];
    bool good = true;
    for (int i = 0; i < 15 && good; ++i) good = toInt(f[static_cast<size_t>(i + 2)], &v[i]);
    if (!good || !validDate(static_cast<int>(v[2]), static_cast<int>(v[3]), static_cast<int>(v[4])) ||
        !validDate(static_cast<int>(v[8]), static_cast<int>(v[9]), static_cast<int>(v[10]))) {
        warn(whereInFile(src, lineNo) + "H2 ids, span or step unreadable; ignored");
        return;
    }
    h.sic = v[0], h.norad = v[1];
    h.startMjd = mjdFromDate(static_cast<int>(v[2]), static_cast<int>(v[3]), static_cast<int>(v[4]));
    h.startSod = v[5] * 3600.0 + v[6] * 60.0 + v[7];
    h.endMjd = mjdFromDate(static_cast<int>(v[8]), static_cast<int>(v[9]), static_cast<int>(v[10]));
    h.endSod = v[11] * 3600.0 + v[12] * 60.0 + v[13];
    h.stepS = static_cast<double>(v[14]);
    long x = 0;
    if (f.size() > 18 && toInt(f[18], &x)) h.targetType = static_cast<int>(x);
    if (f.size() > 19 && toInt(f[19], &x)) h.referenceFrame = static_cast<int>(x);
    if (f.size() > 21 && toInt(f[21], &x)) h.comApplied = static_cast<int>(x);
}

// Type 10: one position (direction, MJD, seconds of day, leap flag, X Y Z). False (a warning
// said why) when the record cannot be used.
bool parseCpfPosition(const std::vector<std::string_view>& f, long lineNo, const std::string& src, const Warn& warn,
                      CpfPosition* out) {
    CpfPosition p;
    p.line = lineNo;
    long dir = 0, mjd = 0, leap = 0;
    double sod = 0, xyz[3];
    std::string why;
    if (f.size() < 8) why = "has " + std::to_string(f.size() - 1) + " fields (expected 7)";
    else if (!toInt(f[1], &dir) || dir < 0 || dir > 2) why = "direction flag is not 0, 1 or 2";
    else if (!toInt(f[2], &mjd) || mjd < 15000 || mjd > 100000) why = "MJD is not a day number in 15000..100000";
    else if (!parseFortranDouble(f[3], &sod) || sod < 0 || sod >= 86401) why = "seconds of day not in 0..86400";
    else if (!toInt(f[4], &leap)) why = "leap-second flag is not an integer";
    else if (!parseFortranDouble(f[5], &xyz[0]) || !parseFortranDouble(f[6], &xyz[1]) || !parseFortranDouble(f[7], &xyz[2]))
        why = "X, Y, Z must be finite numbers";
    else if (std::fabs(xyz[0]) > 1e12 || std::fabs(xyz[1]) > 1e12 || std::fabs(xyz[2]) > 1e12)
        why = "position beyond 1e12 m";
    if (!why.empty()) {
        warn(whereInFile(src, lineNo) + "type 10 record skipped: " + why);
        return false;
    }
    p.direction = static_cast<int>(dir);
    p.mjd = mjd;
    p.sod = sod;
    p.leapSecond = static_cast<int>(leap);
    p.position = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
    if (p.leapSecond != 0)
        warn(whereInFile(src, lineNo) + "leap-second flag set: interpolation across the leap second is not corrected");
    *out = p;
    return true;
}

// Epochs must increase within each direction: a record repeating the previous epoch is skipped;
// one going back in time means the file is out of order (sorted by something else, joined from
// pieces, shuffled), which no interpolation can use: an error.
bool keepTimeOrder(const std::string& src, CpfReadResult& res) {
    std::vector<CpfPosition> kept;
    kept.reserve(res.file.positions.size());
    double last[3] = {-1e300, -1e300, -1e300};
    long lastLine[3] = {0, 0, 0};
    size_t bad = 0;
    for (const auto& p : res.file.positions) {
        const double t = static_cast<double>(p.mjd) * kSecondsPerDay + p.sod;
        if (t < last[p.direction]) {
            res.error = whereInFile(src, p.line) + "position record out of time order (MJD " + std::to_string(p.mjd) + " " +
                        formatFixed(p.sod, 3) + " s comes after the record of line " + std::to_string(lastLine[p.direction]) +
                        ", " + formatFixed(last[p.direction] - t, 0) +
                        " s later): a prediction's records run forward in time; is the file sorted or joined?";
            res.file.positions.clear();
            return false;
        }
        if (t == last[p.direction]) {
            if (bad++ < 20) res.warnings.push_back(whereInFile(src, p.line) + "epoch repeats the previous record's; skipped");
            continue;
        }
        last[p.direction] = t;
        lastLine[p.direction] = p.line;
        kept.push_back(p);
    }
    res.file.positions = std::move(kept);
    return true;
}

}  // namespace

CpfReadResult parseCpf(std::string_view given, const std::string& source) {
    CpfReadResult res;
    std::string storage;
    const std::string_view text = plainText(given, &storage);
    const std::string src = source.empty() ? "cpf" : source;
    try {
        res.file.path = source;
        if (std::string e = textFileProblem(text, src, "CPF"); !e.empty()) {
            res.error = std::move(e);
            return res;
        }
        CpfHeader& h = res.file.header;
        bool haveH1 = false, ended = false;
        size_t dropped = 0;
        auto warn = [&](std::string w) {
            if (res.warnings.size() < 500) res.warnings.push_back(std::move(w));
            else ++dropped;
        };
        size_t pos = 0;
        long lineNo = 0;
        while (pos < text.size()) {
            size_t end = text.find('\n', pos);
            if (end == std::string_view::npos) end = text.size();
            std::string_view line = text.substr(pos, end - pos);
            pos = end + 1;
            ++lineNo;
            const std::vector<std::string_view> f = splitBlanks(line);
            if (f.empty()) continue;
            const std::string id = toLower(f[0]);
            if (!haveH1) {
                if (id == "00") continue;
                if (id != "h1") {
                    res.error = whereInFile(src, lineNo) + "not a CPF file: first record is \"" + printableExcerpt(line) + "\" (expected H1)";
                    return res;
                }
            }
            if (ended) {
                warn(whereInFile(src, lineNo) + "record after the 99 end-of-ephemeris record; ignored");
                continue;
            }
            if (id == "h1") {
                if (haveH1) {
                    warn(whereInFile(src, lineNo) + "second H1; ignored");
                    continue;
                }
                std::string err;
                if (!parseCpfH1(f, lineNo, src, h, &err)) {
                    res.error = err;
                    return res;
                }
                haveH1 = true;
            } else if (id == "h2") {
                parseCpfH2(f, lineNo, src, h, warn);
            } else if (id == "h5") {
                double off = 0;
                if (f.size() > 1 && parseFortranDouble(f[1], &off)) h.comOffsetM = off;
                else warn(whereInFile(src, lineNo) + "H5 centre-of-mass offset unreadable; ignored");
            } else if (id == "h9") {
                continue;
            } else if (id == "10") {
                CpfPosition p;
                if (parseCpfPosition(f, lineNo, src, warn, &p)) res.file.positions.push_back(p);
            } else if (id == "20") {
                double v[3];
                long dir = 0;
                if (f.size() < 5 || !toInt(f[1], &dir) || !parseFortranDouble(f[2], &v[0]) || !parseFortranDouble(f[3], &v[1]) ||
                    !parseFortranDouble(f[4], &v[2])) {
                    warn(whereInFile(src, lineNo) + "type 20 velocity record unreadable; skipped");
                    continue;
                }
                if (res.file.positions.empty() || res.file.positions.back().hasVelocity ||
                    res.file.positions.back().direction != dir) {
                    warn(whereInFile(src, lineNo) + "type 20 velocity record without a preceding type 10; skipped");
                    continue;
                }
                res.file.positions.back().hasVelocity = true;
                res.file.positions.back().velocity = Eigen::Vector3d(v[0], v[1], v[2]);
            } else if (id == "99") {
                ended = true;
            } else if (id == "00") {
                continue;
            } else {
                if (res.file.otherLines.size() < 100000) res.file.otherLines.emplace_back(line);
            }
        }
        // The format closes every file with a 99 record: without it the file was probably cut short.
        if (!ended && haveH1)
            warn(whereInFile(src, lineNo) + "the file ends without the 99 end-of-ephemeris record: truncated? (its last " +
                 "prediction records may be missing)");
        if (dropped) res.warnings.push_back("... and " + std::to_string(dropped) + " more warnings");
        if (res.file.positions.empty()) {
            res.error = src + ": no readable type 10 position record";
            return res;
        }
        if (!keepTimeOrder(src, res)) return res;
        res.ok = true;
    } catch (const std::exception& e) {
        res = CpfReadResult();
        res.error = src + ": internal error: " + e.what();
    }
    return res;
}

std::string cpfPlausibilityProblem(const CpfFile& cpf) {
    const std::string src = cpf.path.empty() ? std::string("cpf") : cpf.path;
    constexpr double kMinRadiusM = 6.3e6;
    for (const auto& p : cpf.positions)
        if (!(p.position.norm() >= kMinRadiusM))
            return whereInFile(src, p.line) + "position (" + formatShortest(p.position.x()) + ", " + formatShortest(p.position.y()) +
                   ", " + formatShortest(p.position.z()) + ") m is " + formatFixed(p.position.norm() / 1000, 1) +
                   " km from the Earth's centre, inside the Earth: a damaged prediction";
    for (int dir = 0; dir <= 2; ++dir) {
        std::vector<const CpfPosition*> r;
        for (const auto& p : cpf.positions)
            if (p.direction == dir) r.push_back(&p);
        const size_t n = r.size();
        if (n < 8) continue;
        std::vector<double> t(n), steps;
        for (size_t i = 0; i < n; ++i) t[i] = static_cast<double>(r[i]->mjd) * kSecondsPerDay + r[i]->sod;
        for (size_t i = 1; i < n; ++i) steps.push_back(t[i] - t[i - 1]);
        std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
        const double step = steps[steps.size() / 2];
        std::vector<double> res(n, NAN);
        for (size_t i = 0; i < n; ++i) {
            // The 6 nearest records (3 each side, shifted at the ends), none across a gap.
            size_t lo = i >= 3 ? i - 3 : 0;
            if (lo + 6 >= n) lo = n - 7;
            bool gap = false;
            for (size_t k = lo + 1; k <= lo + 6; ++k) gap = gap || t[k] - t[k - 1] > 2 * step;
            if (gap) continue;
            Eigen::Vector3d est = Eigen::Vector3d::Zero();
            for (size_t k = lo; k <= lo + 6; ++k) {
                if (k == i) continue;
                double w = 1;
                for (size_t m = lo; m <= lo + 6; ++m)
                    if (m != i && m != k) w *= (t[i] - t[m]) / (t[k] - t[m]);
                est += w * r[k]->position;
            }
            res[i] = (r[i]->position - est).norm();
        }
        std::vector<double> finite;
        for (double v : res)
            if (std::isfinite(v)) finite.push_back(v);
        if (finite.size() < 4) continue;
        std::nth_element(finite.begin(), finite.begin() + finite.size() / 2, finite.end());
        const double median = finite[finite.size() / 2];
        size_t worst = n;
        for (size_t i = 0; i < n; ++i)
            if (std::isfinite(res[i]) && (worst == n || res[i] > res[worst])) worst = i;
        if (worst < n && res[worst] > 1000 && res[worst] > 20 * median)
            return whereInFile(src, r[worst]->line) + "position record " + formatFixed(res[worst] / 1000, 1) +
                   " km off the orbit through its neighbours (the records' median: " + formatFixed(median, 1) +
                   " m): a damaged record; repair or remove it";
    }
    return {};
}

CpfReadResult readCpf(const std::string& path) {
    std::string text, err;
    if (!readFileText(path, &text, &err)) {
        CpfReadResult r;
        r.error = err;
        return r;
    }
    return parseCpf(text, path);
}

std::string validate(const CpfInterpParams& p) {
    if (p.points < 2 || p.points > 20) return "Lagrange points must be in 2..20";
    if (p.direction < 0 || p.direction > 2) return "direction flag must be 0, 1 or 2";
    return {};
}

CpfInterpolator::CpfInterpolator(const CpfFile& cpf, const CpfInterpParams& params) {
    if (const std::string e = validate(params); !e.empty()) {
        m_error = e;
        return;
    }
    m_points = params.points;
    for (const auto& p : cpf.positions) {
        if (p.direction != params.direction) continue;
        if (m_t.empty()) m_refMjd = p.mjd;
        m_t.push_back(static_cast<double>(p.mjd - m_refMjd) * kSecondsPerDay + p.sod);
        m_pos.push_back(p.position);
    }
    if (m_t.size() < static_cast<size_t>(m_points)) {
        m_error = (cpf.path.empty() ? std::string("cpf") : cpf.path) + ": " + std::to_string(m_t.size()) +
                  " position records with direction flag " + std::to_string(params.direction) + ", " +
                  std::to_string(m_points) + " needed for the interpolation";
        m_t.clear();
        m_pos.clear();
        return;
    }
    std::vector<double> steps(m_t.size() - 1);
    for (size_t i = 1; i < m_t.size(); ++i) steps[i - 1] = m_t[i] - m_t[i - 1];
    std::nth_element(steps.begin(), steps.begin() + static_cast<long>(steps.size() / 2), steps.end());
    m_medianStep = steps[steps.size() / 2];
}

CpfState CpfInterpolator::atSeconds(long refMjd, double seconds, bool withVelocity) const {
    CpfState s;
    if (!ok()) {
        s.error = m_error;
        return s;
    }
    if (!std::isfinite(seconds)) {
        s.error = "epoch is not a finite number";
        return s;
    }
    const double t = static_cast<double>(refMjd - m_refMjd) * kSecondsPerDay + seconds;
    if (t < m_t.front()) {
        s.error = "epoch is " + fmtSeconds(m_t.front() - t) + " s before the first prediction record";
        return s;
    }
    if (t > m_t.back()) {
        s.error = "epoch is " + fmtSeconds(t - m_t.back()) + " s after the last prediction record";
        return s;
    }
    const size_t n = m_t.size(), np = static_cast<size_t>(m_points);
    size_t k = static_cast<size_t>(std::upper_bound(m_t.begin(), m_t.end(), t) - m_t.begin());
    k = k == 0 ? 0 : k - 1;  // m_t[k] <= t
    if (k + 1 < n && m_t[k + 1] - m_t[k] > 2.5 * m_medianStep) {
        s.error = "epoch falls in a " + fmtSeconds(m_t[k + 1] - m_t[k]) + " s gap of the prediction table (step " +
                  fmtSeconds(m_medianStep) + " s)";
        return s;
    }
    long start = static_cast<long>(k) - static_cast<long>(np / 2 - 1);
    start = std::max(0L, std::min(start, static_cast<long>(n - np)));
    const size_t s0 = static_cast<size_t>(start);
    const double tc = m_t[s0 + np / 2];  // centre the time axis for conditioning
    double x[20];
    for (size_t j = 0; j < np; ++j) x[j] = m_t[s0 + j] - tc;
    const double u = t - tc;
    Eigen::Vector3d pos(0, 0, 0), vel(0, 0, 0);
    for (size_t j = 0; j < np; ++j) {
        double l = 1;
        for (size_t m = 0; m < np; ++m)
            if (m != j) l *= (u - x[m]) / (x[j] - x[m]);
        pos += l * m_pos[s0 + j];
        if (withVelocity) {
            double dl = 0;
            for (size_t i = 0; i < np; ++i) {
                if (i == j) continue;
                double prod = 1 / (x[j] - x[i]);
                for (size_t m = 0; m < np; ++m)
                    if (m != j && m != i) prod *= (u - x[m]) / (x[j] - x[m]);
                dl += prod;
            }
            vel += dl * m_pos[s0 + j];
        }
    }
    s.position = pos;
    s.velocity = vel;
    s.ok = true;
    return s;
}

CpfState CpfInterpolator::at(long mjd, double sod, bool withVelocity) const { return atSeconds(mjd, sod, withVelocity); }

CpfState interpolateCpf(const CpfFile& cpf, long mjd, double sod, const CpfInterpParams& params) {
    try {
        return CpfInterpolator(cpf, params).at(mjd, sod);
    } catch (const std::exception& e) {
        CpfState s;
        s.error = std::string("internal error: ") + e.what();
        return s;
    }
}

}  // namespace lwb::core::slr
