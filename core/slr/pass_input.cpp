#include "core/slr/pass_input.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/common/atomic_file.hpp"
#include "core/common/text.hpp"
#include "core/slr/cpf.hpp"
#include "core/slr/oc_csv.hpp"
#include "core/slr/sinex.hpp"

namespace lwb::core::slr {

namespace {
constexpr double kLight = 299792458.0;
constexpr double kEarthRadiusKm = 6371.0;

std::string extension(const std::string& path) {
    const size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
    return toLower(path.substr(dot + 1));
}

std::string timeText(int y, int mo, int d, int h, int mi, int s) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02d %02d:%02d:%02d", y, mo, d, h, mi, s);
    return buf;
}

PassSummary summarise(const CrdPass& p, int index) {
    PassSummary s;
    s.index = index;
    s.satellite = p.target.name;
    s.ilrsId = p.target.ilrsId;
    s.station = p.station.name;
    const CrdSession& q = p.session;
    s.start = timeText(q.startYear, q.startMonth, q.startDay, q.startHour, q.startMinute, q.startSecond);
    s.end = timeText(q.endYear, q.endMonth, q.endDay, q.endHour, q.endMinute, q.endSecond);
    s.ranges = p.ranges.size();
    s.normalPoints = p.normalPoints.size();
    s.dataType = q.dataType;
    return s;
}
}  // namespace

bool isCrdPath(const std::string& path) {
    const std::string e = extension(path);
    return e == "frd" || e == "fr2" || e == "npt" || e == "np2" || e == "crd";
}

PassInputResult loadPass(const std::string& path, int passIndex, const PassInputParams& params, const Feedback* fb) {
    PassInputResult r;
    PassData& d = r.pass;
    d.source = path;
    if (!isCrdPath(path)) {
        const OcCsvReadResult csv = readOcCsv(path);
        if (!csv.ok) {
            r.error = csv.error;
            return r;
        }
        r.warnings = csv.warnings;
        d.t = csv.table.epoch_s;
        d.oc = csv.table.oc_s;
        d.ocOrigin = "O-C table";
        PassSummary s;
        s.ranges = d.t.size();
        r.passes.push_back(s);
        if (d.t.size() < 3) {
            r.error = path + ": the O-C table holds " + std::to_string(d.t.size()) + " points; screening needs at least 3";
            return r;
        }
        r.ok = true;
        return r;
    }
    CrdReadResult crd = readCrd(path, {}, fb);
    if (!crd.ok) {
        r.error = crd.error;
        return r;
    }
    r.warnings = crd.warnings;
    for (size_t i = 0; i < crd.file.passes.size(); ++i) r.passes.push_back(summarise(crd.file.passes[i], int(i)));
    if (passIndex < 0) {
        for (size_t i = 0; i < crd.file.passes.size() && passIndex < 0; ++i)
            if (!crd.file.passes[i].ranges.empty()) passIndex = int(i);
        if (passIndex < 0) {
            r.error = path + ": no full-rate pass (no type-10 records) to screen";
            return r;
        }
    }
    if (passIndex >= int(crd.file.passes.size())) {
        r.error = path + ": pass " + std::to_string(passIndex + 1) + " asked for, the file holds " +
                  std::to_string(crd.file.passes.size());
        return r;
    }
    const CrdPass& pass = crd.file.passes[size_t(passIndex)];
    if (pass.ranges.size() < 3) {
        r.error = path + ": pass " + std::to_string(passIndex + 1) + " holds " + std::to_string(pass.ranges.size()) +
                  " full-rate records; screening needs at least 3";
        return r;
    }
    d.passIndex = passIndex;
    d.satellite = pass.target.name;
    d.ilrsId = pass.target.ilrsId;
    d.station = pass.station.name;
    d.cdpPad = pass.station.cdpPadId;
    OcResult oc;
    const bool predicted = !params.cpfPath.empty() && !params.sinexPath.empty();
    if (!params.cpfPath.empty() != !params.sinexPath.empty())
        r.warnings.push_back("O-C from a prediction needs both the CPF and the SINEX file; using the fitted TOF trend");
    double altitudeKm = 0;
    if (predicted) {
        const CpfReadResult cpf = readCpf(params.cpfPath);
        if (!cpf.ok) {
            r.error = cpf.error;
            return r;
        }
        const SinexReadResult snx = readSinex(params.sinexPath);
        if (!snx.ok) {
            r.error = snx.error;
            return r;
        }
        oc = computeOc(pass, cpf.file, snx.file, params.oc, fb);
        d.ocOrigin = "CPF prediction";
        double rmin = INFINITY;
        for (const auto& p : cpf.file.positions) rmin = std::min(rmin, p.position.norm());
        if (std::isfinite(rmin)) altitudeKm = rmin / 1000.0 - kEarthRadiusKm;
        for (const auto& w : cpf.warnings) r.warnings.push_back(w);
    } else {
        oc = computeTrendOc(pass, params.trend, fb);
        d.ocOrigin = "fitted TOF trend (no prediction)";
    }
    if (!oc.ok) {
        r.error = oc.error;
        return r;
    }
    for (const auto& w : oc.warnings) r.warnings.push_back(w);
    d.t = oc.epoch_s;
    d.oc = oc.oc_s;
    d.tof = oc.tof_s;
    d.stationFlag = oc.filter_flag;
    d.rangeIndex = oc.range_index;
    if (!(altitudeKm > 0)) {
        // No prediction: the shortest one-way range of the pass bounds the altitude from above.
        double tmin = INFINITY;
        for (double v : d.tof) tmin = std::min(tmin, v);
        if (std::isfinite(tmin)) altitudeKm = 0.5 * tmin * kLight / 1000.0;
        r.warnings.push_back("satellite altitude estimated from the shortest range of the pass (" +
                             formatFixed(altitudeKm, 0) + " km) for the normal-point bin");
    }
    d.altitudeKm = altitudeKm;
    d.hasCrd = true;
    d.crd = std::move(crd.file);
    r.ok = true;
    return r;
}

bool writeScreenCsv(const std::string& path, const PassData& pass, const ScreenResult& screen,
                    const std::vector<uint8_t>& accepted, const PostfitResult* post, std::string* error) {
    const size_t n = pass.t.size();
    if (screen.pointClass.size() != n || accepted.size() != n) {
        *error = "screening result does not match the pass (" + std::to_string(screen.pointClass.size()) + " vs " +
                 std::to_string(n) + " points)";
        return false;
    }
    AtomicFile f(path);
    if (!f.ok()) {
        *error = f.error();
        return false;
    }
    std::ostream& o = f.stream();
    o << "index,epoch_s,oc_s,class,region,residual_s,kept,station_flag\n";
    // std::to_chars instead of printf: a 10⁶-point pass is written in a fraction of the time.
    std::string line;
    char num[64];
    auto put = [&](auto value, std::chars_format fmt, int precision) {
        const auto res = std::to_chars(num, num + sizeof num, value, fmt, precision);
        line.append(num, res.ptr);
    };
    auto putInt = [&](unsigned long long value) {
        const auto res = std::to_chars(num, num + sizeof num, value);
        line.append(num, res.ptr);
    };
    for (size_t i = 0; i < n; ++i) {
        // A manual edit can accept a point the screening called noise (or the reverse).
        const PointClass c = accepted[i] ? (screen.pointClass[i] == PointClass::Noise ? PointClass::Signal
                                                                                     : screen.pointClass[i])
                                         : PointClass::Noise;
        const double res = post && post->ok ? post->residuals[i] : NAN;
        const int kept = post && post->ok ? post->kept[i] : accepted[i];
        // index: the type-10 record of the CRD pass (a record without an O-C, e.g. a one-way
        // epoch event, has no row), else the row of the O-C table.
        const size_t index = i < pass.rangeIndex.size() ? pass.rangeIndex[i] : i;
        line.clear();
        putInt(index);
        line += ',';
        put(pass.t[i], std::chars_format::fixed, 9);
        line += ',';
        put(pass.oc[i], std::chars_format::scientific, 6);
        line += ',';
        line += pointClassName(c);
        line += ',';
        putInt(screen.pointRegion.empty() ? 0u : unsigned(screen.pointRegion[i]));
        line += ',';
        if (std::isfinite(res)) put(res, std::chars_format::scientific, 6);
        line += ',';
        putInt(unsigned(kept));
        line += ',';
        if (!pass.stationFlag.empty()) putInt(unsigned(std::max(0, pass.stationFlag[i])));
        line += '\n';
        o.write(line.data(), std::streamsize(line.size()));
    }
    if (!f.commit()) {
        *error = f.error();
        return false;
    }
    return true;
}

bool writeScreenedCrd(const std::string& path, const PassData& pass, const std::vector<uint8_t>& accepted,
                      std::string* error) {
    if (!pass.hasCrd) {
        *error = "the pass did not come from a CRD file; there is nothing to write flags into";
        return false;
    }
    CrdFile out = pass.crd;
    CrdPass& p = out.passes[size_t(pass.passIndex)];
    // Records that were not screened (no O-C: outside the prediction, one-way events) keep the
    // station's own flag; only the screened ones get 2 (accepted) or 1 (noise).
    std::vector<int> flags(p.ranges.size());
    for (size_t k = 0; k < p.ranges.size(); ++k) flags[k] = p.ranges[k].filterFlag;
    for (size_t i = 0; i < pass.rangeIndex.size() && i < accepted.size(); ++i)
        flags[pass.rangeIndex[i]] = accepted[i] ? 2 : 1;
    if (!setFilterFlags(&p, flags, error)) return false;
    return writeCrd(path, out, error);
}

bool writeNormalPointCrd(const std::string& path, const PassData& pass, const std::vector<NormalPoint>& nps,
                         std::string* error) {
    if (!pass.hasCrd) {
        *error = "normal points as CRD need the pass's CRD headers (open the CRD file, not an O-C table)";
        return false;
    }
    const CrdPass& full = pass.crd.passes[size_t(pass.passIndex)];
    std::vector<CrdNormalPoint> recs;
    for (const NormalPoint& np : nps) {
        CrdNormalPoint c;
        c.secOfDay = std::fmod(np.epochS, 86400.0);
        c.tofS = np.tofS;
        if (!std::isfinite(c.tofS)) {
            *error = "normal point at " + formatFixed(np.epochS, 3) + " s has no time of flight";
            return false;
        }
        if (np.pointIndex < pass.rangeIndex.size()) {
            const CrdRange& src = full.ranges[pass.rangeIndex[np.pointIndex]];
            c.configId = src.configId;
            c.epochEvent = src.epochEvent;
        }
        c.windowS = np.windowS;
        c.numRanges = np.points;
        c.binRmsPs = np.rmsPs;
        c.skew = np.skew;
        c.kurtosis = np.kurtosis;
        c.peakMinusMeanPs = np.peakMinusMeanPs;
        c.returnRatePct = np.returnRatePct;
        recs.push_back(c);
    }
    CrdFile out;
    out.path = path;
    out.crlf = pass.crd.crlf;
    CrdPass np;
    if (!makeNormalPointPass(full, recs, &np, error)) return false;
    out.passes.push_back(std::move(np));
    out.trailer = pass.crd.trailer;
    return writeCrd(path, out, error);
}

}  // namespace lwb::core::slr
