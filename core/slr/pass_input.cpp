#include "core/slr/pass_input.hpp"

#include "core/common/folder.hpp"

#include "core/slr/ilrs_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sys/stat.h>

#include "core/common/atomic_file.hpp"
#include "core/common/text.hpp"
#include "core/slr/cpf.hpp"
#include "core/slr/ilrs_tables.hpp"
#include "core/slr/oc_csv.hpp"
#include "core/slr/sinex.hpp"
#include "core/slr/slr_time.hpp"

namespace lwb::core::slr {

namespace {
constexpr double kEarthRadiusKm = 6371.0;

std::string extension(const std::string& path) { return inputExtension(path); }

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
    s.end = q.endYear == kCrdAbsent ? std::string("(end not given)")
                                    : timeText(q.endYear, q.endMonth, q.endDay, q.endHour, q.endMinute, q.endSecond);
    s.ranges = p.ranges.size();
    s.normalPoints = p.normalPoints.size();
    s.dataType = q.dataType;
    s.problem = p.problem;
    return s;
}

/// `error` followed by the first readers' warnings (the damaged lines that may explain it).
std::string withWarnings(std::string error, const std::vector<std::string>& first,
                         const std::vector<std::string>& second = {}) {
    constexpr size_t kShown = 5;
    const size_t n = first.size() + second.size();
    if (n == 0) return error;
    error += "\n  the reader's warnings" + (n > kShown ? " (first " + std::to_string(kShown) + " of " + std::to_string(n) + ")"
                                                       : std::string()) + ":";
    for (size_t i = 0; i < n && i < kShown; ++i) error += "\n  " + (i < first.size() ? first[i] : second[i - first.size()]);
    return error;
}

/// An id of a CRD H3 or CPF H2 that is given: not empty, "na" or -1.
bool idGiven(const std::string& id) {
    const std::string l = toLower(trim(id));
    return !l.empty() && l != "na" && l != "-1";
}

/// ILRS ids compared as numbers when both are ("0904907" is "904907"), else as text.
bool sameIlrsId(const std::string& a, const std::string& b) {
    long long x = 0, y = 0;
    if (parseLong(a, &x) && parseLong(b, &y)) return x == y;
    return toLower(trim(a)) == toLower(trim(b));
}

std::string idList(const std::string& name, const std::string& ilrs, long norad, long sic) {
    std::string s = name.empty() ? std::string("?") : name;
    s += ": ILRS id " + (idGiven(ilrs) ? ilrs : std::string("not given"));
    s += ", NORAD " + (norad > 0 ? std::to_string(norad) : std::string("not given"));
    s += ", SIC " + (sic > 0 ? std::to_string(sic) : std::string("not given"));
    return s;
}

/// The prediction must be for the pass's satellite. Compares the ids both files give (ILRS id,
/// NORAD number, SIC): an error when every one of them differs, a warning when some differ or
/// none can be compared. O-C against another satellite's orbit is kilometres of nonsense.
bool checkCpfTarget(const CpfFile& cpf, const CrdPass& pass, const std::string& crdPath, std::string* error,
                    std::vector<std::string>* warnings) {
    const CpfHeader& h = cpf.header;
    const CrdTarget& t = pass.target;
    const std::string cpfName = cpf.path.empty() ? std::string("cpf") : cpf.path;
    int compared = 0;
    std::vector<std::string> differ;
    if (idGiven(h.ilrsId) && idGiven(t.ilrsId)) {
        ++compared;
        if (!sameIlrsId(h.ilrsId, t.ilrsId)) differ.push_back("ILRS id");
    }
    if (h.norad > 0 && t.norad > 0) {
        ++compared;
        if (h.norad != t.norad) differ.push_back("NORAD number");
    }
    if (h.sic > 0 && t.sic > 0) {
        ++compared;
        if (h.sic != t.sic) differ.push_back("SIC");
    }
    const std::string both = "the CPF H2 gives " + idList(h.targetName, h.ilrsId, h.norad, h.sic) + "; the pass's H3 (" + crdPath + ":" +
                             std::to_string(t.line) + ") gives " + idList(t.name, t.ilrsId, t.norad, t.sic);
    if (compared == 0) {
        warnings->push_back(cpfName + ": cannot check that the prediction is for the pass's satellite (no id that both "
                                      "files give): " + both);
        return true;
    }
    if (differ.size() == size_t(compared)) {
        *error = cpfName + ": the prediction is for another satellite: " + both +
                 ". Give the CPF of the pass's satellite.";
        return false;
    }
    if (!differ.empty()) {
        std::string which;
        for (const auto& d : differ) which += (which.empty() ? "" : " and ") + d;
        warnings->push_back(cpfName + ": the " + which + " of the prediction and the pass differ (the other ids agree): " +
                            both);
    }
    return true;
}

/// The first damaged record of the pass with its warning, or "" when none.
std::string damagedRecords(const CrdPass& pass, const std::string& path, const std::vector<std::string>& warnings) {
    if (pass.skippedLines.empty()) return {};
    // The reader lists the skipped lines whether or not its warning list is full.
    const std::string at = path + ":" + std::to_string(pass.skippedLines.front()) + ":";
    std::string why = at + " a damaged record";
    for (const auto& w : warnings)  // (the same line may also end the file: "file ends without H8")
        if (w.rfind(at, 0) == 0 && w.find(" record skipped: ") != std::string::npos) {
            why = w;
            break;
        }
    return why + " (" + std::to_string(pass.skippedLines.size()) +
           " damaged record(s) in the pass to screen: repair or remove them before writing results)";
}
}  // namespace

bool isCrdFile(const std::string& path) {
    const std::string e = extension(path);
    const bool crdName = e == "frd" || e == "fr2" || e == "npt" || e == "np2" || e == "crd";
    // Only a regular file (or standard input) is looked into (a FIFO would block); the reader
    // reports the others. A gzip-compressed file is looked into decompressed.
    if (!isStandardStream(path)) {
        struct stat st {};
        if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return crdName;
    }
    std::string head, why;
    if (!readFileHead(path, 65536, &head, &why)) return crdName;
    if (head.size() >= 3 && head.compare(0, 3, "\xEF\xBB\xBF") == 0) head.erase(0, 3);
    size_t pos = 0;
    while (pos < head.size()) {
        size_t end = head.find('\n', pos);
        if (end == std::string::npos) end = head.size();
        const std::string_view line = std::string_view(head).substr(pos, end - pos);
        pos = end + 1;
        const std::vector<std::string_view> f = splitBlanks(line);
        std::string first = f.empty() ? std::string() : toLower(f[0]);
        while (!first.empty() && first.back() == '\r') first.pop_back();
        if (first.empty() || first == "00") continue;  // blank line or CRD comment
        if (first == "h1") return true;
        if (first[0] == '#' || line.find(',') != std::string_view::npos) return false;  // CSV comment or header
        return crdName;
    }
    return crdName;
}

namespace {

// Time span of a prediction (MJD + s): its positions' first and last epochs.
bool cpfSpan(const CpfFile& cpf, double* first, double* last) {
    if (cpf.positions.empty()) return false;
    *first = INFINITY;
    *last = -INFINITY;
    for (const auto& p : cpf.positions) {
        const double t = double(p.mjd) * 86400.0 + p.sod;
        *first = std::min(*first, t);
        *last = std::max(*last, t);
    }
    return true;
}

// Start and end of a pass (MJD·86400 + s) from its range epochs and H4 date.
bool passSpan(const CrdPass& pass, double* first, double* last) {
    const CrdSession& q = pass.session;
    if (pass.ranges.empty() || q.startYear <= 0) return false;
    const double day0 = double(mjdFromDate(q.startYear, q.startMonth, q.startDay)) * 86400.0;
    *first = INFINITY;
    *last = -INFINITY;
    for (const auto& r : pass.ranges) {
        // Epochs are seconds of the H4 start day; a pass over midnight has them past 86400 or wraps.
        double t = r.secOfDay;
        if (t + 43200 < (q.startHour * 3600.0 + q.startMinute * 60.0 + q.startSecond)) t += 86400;
        *first = std::min(*first, day0 + t);
        *last = std::max(*last, day0 + t);
    }
    return std::isfinite(*first);
}

// Does the prediction fit the pass: the same satellite (no id that differs everywhere) and a time
// span covering the pass with a margin for the interpolation window? "" when it fits, else why not.
std::string cpfMismatch(const CpfFile& cpf, const CrdPass& pass, const std::string& crdPath, std::vector<std::string>* warnings) {
    std::string err;
    if (!checkCpfTarget(cpf, pass, crdPath, &err, warnings)) return err;
    double cf = 0, cl = 0, pf = 0, pl = 0;
    if (cpfSpan(cpf, &cf, &cl) && passSpan(pass, &pf, &pl) && (pf < cf || pl > cl)) {
        int y = 0, mo = 0, d = 0;
        dateFromMjd(long(cf / 86400), &y, &mo, &d);
        char a[32], b[32];
        std::snprintf(a, sizeof a, "%04d-%02d-%02d", y, mo, d);
        dateFromMjd(long(cl / 86400), &y, &mo, &d);
        std::snprintf(b, sizeof b, "%04d-%02d-%02d", y, mo, d);
        return (cpf.path.empty() ? std::string("cpf") : cpf.path) + ": the prediction covers " + a + " to " + b +
               ", not the pass (" + timeText(pass.session.startYear, pass.session.startMonth, pass.session.startDay,
                                              pass.session.startHour, pass.session.startMinute, pass.session.startSecond) +
               ")";
    }
    return {};
}

}  // namespace

bool readPassSources(const PassInputParams& params, PassSources* out, std::string* error) {
    *out = PassSources();
    if (!params.cpfPath.empty()) {
        out->cpfFolder = isFolder(params.cpfPath);
        std::vector<std::string> files;
        if (out->cpfFolder) {
            if (!listFolder(params.cpfPath, &files, error)) return false;
        } else {
            files.push_back(params.cpfPath);
        }
        for (const auto& f : files) {
            CpfReadResult cpf = readCpf(f);
            // A damaged prediction (a record inside the Earth, or off the orbit) is refused before
            // any pass is screened with it; in a folder it is set aside with the reason.
            if (cpf.ok)
                if (std::string bad = cpfPlausibilityProblem(cpf.file); !bad.empty()) {
                    cpf.ok = false;
                    cpf.error = bad;
                }
            if (!cpf.ok) {
                if (!out->cpfFolder) {
                    *error = withWarnings(cpf.error, cpf.warnings);
                    return false;
                }
                out->skipped.push_back(f + ": not used: " + cpf.error);
                continue;
            }
            out->cpfs.push_back(std::move(cpf));
        }
        if (out->cpfFolder && out->cpfs.empty()) {
            *error = params.cpfPath + ": the folder holds no readable CPF file";
            return false;
        }
    }
    if (!params.sinexPath.empty()) {
        const SinexReadResult snx = readSinex(params.sinexPath);
        if (!snx.ok) {
            *error = snx.error;
            return false;
        }
        out->stations = snx.file;
        out->stationWarnings = snx.warnings;
        out->haveStations = true;
    }
    return true;
}

PassInputResult loadPass(const std::string& path, int passIndex, const PassInputParams& params, const Feedback* fb) {
    PassInputResult r;
    r.pass.source = path;
    if (!isCrdFile(path)) return passFromOcTable(path);
    const auto crd = std::make_shared<const CrdReadResult>(readCrd(path, {}, fb));
    if (!crd->ok) {
        r.error = withWarnings(crd->error, crd->warnings);
        return r;
    }
    PassSources sources;
    if (!params.cpfPath.empty() && !params.sinexPath.empty() && !readPassSources(params, &sources, &r.error)) {
        r.passes = summarisePasses(crd->file);
        return r;
    }
    PassInputResult p = passFromCrd(crd, path, passIndex, params, sources, fb);
    if (p.passes.empty()) p.passes = summarisePasses(crd->file);
    return p;
}

PassInputResult passFromOcTable(const std::string& path) {
    PassInputResult r;
    PassData& d = r.pass;
    d.source = path;
    // A station_flag column (the CLI's own -o writes one): the station's filter flags, as a CRD's.
    OcCsvParams params;
    params.optionalColumns = {"station_flag"};
    OcCsvReadResult csv = readOcCsv(path, params);
    if (!csv.ok) {
        r.error = csv.error;
        return r;
    }
    std::vector<int8_t> flags;
    if (!csv.table.extra.empty()) {
        const std::vector<double>& f = csv.table.extra.front();
        flags.resize(f.size());
        bool any = false;
        for (size_t i = 0; i < f.size(); ++i) {
            if (std::isnan(f[i])) continue;  // (empty: unknown, 0)
            if (f[i] != 0 && f[i] != 1 && f[i] != 2) {
                r.error = path + ":" + std::to_string(csv.table.line[i]) + ": station_flag " + formatShortest(f[i]) +
                          " is not a CRD filter flag (0 unknown, 1 noise, 2 data)";
                return r;
            }
            flags[i] = static_cast<int8_t>(f[i]);
            any = any || flags[i] != 0;
        }
        if (!any) flags.clear();  // (a column of blanks or zeros says nothing)
    }
    PassInputResult p = passFromOc(std::move(csv.table.epoch_s), std::move(csv.table.oc_s), path);
    p.warnings.insert(p.warnings.begin(), csv.warnings.begin(), csv.warnings.end());
    if (p.ok) p.pass.stationFlag = std::move(flags);
    return p;
}

PassInputResult passFromOc(std::vector<double> t, std::vector<double> oc, const std::string& source) {
    PassInputResult r;
    PassData& d = r.pass;
    d.source = source;
    if (t.size() != oc.size()) {
        r.error = source + ": " + std::to_string(t.size()) + " epochs and " + std::to_string(oc.size()) + " O-C values";
        return r;
    }
    for (size_t i = 0; i < t.size(); ++i)
        if (!std::isfinite(t[i]) || !std::isfinite(oc[i])) {
            r.error = source + ": point " + std::to_string(i) + " is not finite";
            return r;
        }
    d.t = std::move(t);
    d.oc = std::move(oc);
    d.ocOrigin = "O-C table";
    PassSummary s;
    s.ranges = d.t.size();
    r.passes.push_back(s);
    if (d.t.size() < kMinPassPoints) {
        r.error = source + ": the O-C table holds " + std::to_string(d.t.size()) + " points; a pass needs at least " +
                  std::to_string(kMinPassPoints);
        return r;
    }
    r.ok = true;
    return r;
}

BlockStatus blockStatus(const PassSummary& s) {
    // By the records first: a block of type-10 records only is full rate even when its H4 says
    // data type 1 (the shared beaconc_20070511.frd: three such blocks of the station's own
    // full-rate data).
    if (s.normalPoints > 0 && (s.dataType == 1 || s.ranges == 0))
        return {"station normal points", std::to_string(s.normalPoints) + " normal-point records of the station's own"};
    if (s.dataType == 2) return {"skipped", "sampled engineering data (H4 data type 2)"};
    if (s.problem.empty() && s.ranges < kMinPassPoints)
        return {"skipped", std::to_string(s.ranges) + " full-rate records; a pass needs at least " + std::to_string(kMinPassPoints)};
    return {};
}

std::vector<PassSummary> summarisePasses(const CrdFile& file) {
    std::vector<PassSummary> v;
    for (size_t i = 0; i < file.passes.size(); ++i) v.push_back(summarise(file.passes[i], int(i)));
    return v;
}

namespace {

// The pass to read: the one asked for, or the first pass to screen (isPassToScreen: the one
// rule every front end and batch shares). -1 with r->error (and r->passes listing the file)
// when there is none, or when the one asked for cannot be used or is not a pass (r->notAPass).
int choosePass(const CrdReadResult& crd, const std::string& path, int passIndex, PassInputResult* r) {
    PassInputResult& res = *r;
    if (passIndex < 0) {
        for (size_t i = 0; i < crd.file.passes.size() && passIndex < 0; ++i)
            if (isPassToScreen(summarise(crd.file.passes[i], int(i)))) passIndex = int(i);
        if (passIndex < 0) {
            // Say what the file does hold, block by block.
            std::string held;
            for (size_t i = 0; i < crd.file.passes.size(); ++i) {
                const CrdPass& q = crd.file.passes[i];
                const size_t number = q.ordinal ? q.ordinal : i + 1;
                const BlockStatus b = blockStatus(summarise(q, int(i)));
                held += "\n  pass " + std::to_string(number) +
                        (!q.problem.empty() ? " cannot be used: " + q.problem : ": " + b.status + " (" + b.reason + ")");
            }
            res.error = path + ": no full-rate pass to screen in the file:" + held;
            res.error = withWarnings(res.error, res.warnings);
            res.passes = summarisePasses(crd.file);
            return -1;
        }
    }
    if (passIndex >= int(crd.file.passes.size())) {
        res.passes = summarisePasses(crd.file);
        res.error = path + ": pass " + std::to_string(passIndex + 1) + " asked for, the file holds " +
                    std::to_string(crd.file.passes.size());
        return -1;
    }
    const CrdPass& pass = crd.file.passes[size_t(passIndex)];
    // (its place in the file it was read from: a pass read alone, by streamCrd, is index 0 here)
    const size_t number = pass.ordinal ? pass.ordinal : size_t(passIndex) + 1;
    if (!pass.problem.empty()) {
        res.error = withWarnings(path + ": pass " + std::to_string(number) + " cannot be used: " + pass.problem,
                                 res.warnings);
        return -1;
    }
    if (const BlockStatus b = blockStatus(summarise(pass, passIndex)); !b.status.empty()) {
        res.notAPass = true;
        res.passes = summarisePasses(crd.file);
        res.error = path + ": pass " + std::to_string(number) + " is not a pass to screen: " + b.status + " (" + b.reason + ")";
        return -1;
    }
    return passIndex;
}

// The prediction for this pass: the given CPF, or the one of a folder whose satellite and time
// span fit, checked against the ranges (a median |O-C| above 100 us is another satellite, a
// wrong epoch or a damaged file). Null with *why when none is used (the pass's own TOF trend
// then); false with r->error when the run must stop.
bool predictionFor(const CrdPass& pass, const std::string& path, const PassInputParams& params, const PassSources& sources,
                   const Feedback* fb, const CpfFile** cpfOut, OcResult* oc, std::vector<std::string>* cpfWarnings,
                   std::string* whyOut, PassInputResult* r) {
    const CpfFile*& cpf = *cpfOut;
    std::string& why = *whyOut;
    // The prediction for this pass: the given CPF, or the one of a folder whose satellite and
    // time span fit. When none fits: an error, or with cpfFallback (and always for a folder) the
    // pass's own TOF trend with a note saying why.
    if (!sources.cpfs.empty() && sources.haveStations) {
        for (const auto& c : sources.cpfs) {
            std::vector<std::string> w = c.warnings;
            const std::string m = cpfMismatch(c.file, pass, path, &w);
            if (m.empty()) {
                cpf = &c.file;
                *cpfWarnings = w;
                break;
            }
            if (why.empty() || !sources.cpfFolder) why = m;
        }
        if (!cpf && sources.cpfFolder)
            why = params.cpfPath + ": no prediction in the folder fits the pass (satellite " + pass.target.name +
                  (idGiven(pass.target.ilrsId) ? ", ILRS id " + pass.target.ilrsId : std::string()) + ")" +
                  (why.empty() ? std::string() : "; e.g. " + why);
        if (!cpf && !sources.cpfFolder && !params.cpfFallback) {
            r->error = withWarnings(why, sources.cpfs.front().warnings);
            return false;
        }
    }
    if (cpf) {
        *oc = computeOc(pass, *cpf, sources.stations, params.oc, fb);
        // The prediction must describe the ranges: a usable prediction leaves O-C of nanoseconds
        // to microseconds (a time bias of 10 ms on a LEO pass: 0.5 us); a median |O-C| above
        // 100 us (15 km one-way) is another satellite, a wrong epoch or a damaged file.
        if (oc->ok && !oc->oc_s.empty()) {
            std::vector<double> a;
            a.reserve(oc->oc_s.size());
            for (double v : oc->oc_s) a.push_back(std::fabs(v));
            std::nth_element(a.begin(), a.begin() + static_cast<long>(a.size() / 2), a.end());
            const double median = a[a.size() / 2];
            if (!(median <= 1e-4)) {
                const std::string bad = (cpf->path.empty() ? std::string("cpf") : cpf->path) +
                                        ": the prediction does not describe this pass: its O-C is " +
                                        formatFixed(median * 1e3, 3) + " ms (median |O-C|, " +
                                        formatFixed(median * kSpeedOfLight / 2000, 0) +
                                        " km one-way; a usable prediction leaves microseconds). Another satellite, a wrong "
                                        "epoch or a damaged file?";
                if (!params.cpfFallback && !sources.cpfFolder) {
                    r->error = bad;
                    return false;
                }
                cpf = nullptr;
                why = bad;
            }
        }
    }
    return true;
}

}  // namespace

PassInputResult passFromCrd(const std::shared_ptr<const CrdReadResult>& shared, const std::string& path, int passIndex,
                            const PassInputParams& params, const PassSources& sources, const Feedback* fb) {
    PassInputResult r;
    PassData& d = r.pass;
    d.source = path;
    const CrdReadResult& crd = *shared;
    r.warnings = crd.warnings;
    passIndex = choosePass(crd, path, passIndex, &r);
    if (passIndex < 0) return r;
    const CrdPass& pass = crd.file.passes[size_t(passIndex)];
    d.passIndex = passIndex;
    d.satellite = pass.target.name;
    d.ilrsId = pass.target.ilrsId;
    d.station = pass.station.name;
    d.cdpPad = pass.station.cdpPadId;
    d.damaged = damagedRecords(pass, path, r.warnings);
    OcResult oc;
    // (a SINEX file alone is no half of anything: it gives the station for day or night)
    if (!params.cpfPath.empty() && params.sinexPath.empty())
        r.warnings.push_back("O-C from a prediction needs the SINEX file too (the station's position); using the fitted TOF trend");
    double altitudeKm = 0;
    std::vector<std::string> cpfWarnings;
    const CpfFile* cpf = nullptr;
    std::string why;
    if (!predictionFor(pass, path, params, sources, fb, &cpf, &oc, &cpfWarnings, &why, &r)) return r;
    if (cpf) {
        d.ocOrigin = "CPF prediction" + (sources.cpfFolder ? " " + cpf->path : std::string());
        double rmin = INFINITY;
        for (const auto& p : cpf->positions) rmin = std::min(rmin, p.position.norm());
        if (std::isfinite(rmin)) altitudeKm = rmin / 1000.0 - kEarthRadiusKm;
        for (const auto& w : cpfWarnings) r.warnings.push_back(w);
    } else {
        if (!why.empty()) {
            d.ocNote = why + "; O-C against the pass's own TOF trend";
            r.warnings.push_back(d.ocNote);
        }
        oc = computeTrendOc(pass, params.trend, fb);
        d.ocOrigin = "fitted TOF trend (no prediction)";
        d.orbitTrend = oc.trendOrbit;
        d.trendHat = std::move(oc.trendHat);
    }
    if (!oc.ok) {
        // The prediction's warnings first: a damaged or missing position record explains most
        // interpolation failures.
        r.error = withWarnings(oc.error, cpfWarnings, crd.warnings);
        return r;
    }
    for (const auto& w : oc.warnings) r.warnings.push_back(w);
    r.notes = oc.notes;
    d.ocComputed = true;
    d.ocParams = params.oc;
    d.ownTrendParams = params.trend;
    d.t = std::move(oc.epoch_s);  // (moved: copies held 36 bytes an event twice, issue 44)
    d.oc = std::move(oc.oc_s);
    d.tof = std::move(oc.tof_s);
    d.stationFlag = std::move(oc.filter_flag);
    d.rangeIndex = CrdStepColumn<uint32_t>::of(oc.range_index);
    std::vector<uint32_t>().swap(oc.range_index);
    if (!(altitudeKm > 0)) {
        // No prediction: the shortest one-way range of the pass bounds the altitude from above.
        double tmin = INFINITY;
        for (double v : d.tof) tmin = std::min(tmin, v);
        if (std::isfinite(tmin)) altitudeKm = 0.5 * tmin * kSpeedOfLight / 1000.0;
        // (said only when it matters: the missions table's bin wins for a satellite it lists)
        if (!findMission(pass.target))
            r.warnings.push_back("satellite altitude estimated from the shortest range of the pass (" +
                             formatFixed(altitudeKm, 0) + " km), for the normal-point bin of a satellite the ILRS "
                             "missions table does not list");
    }
    d.altitudeKm = altitudeKm;
    d.hasCrd = true;
    d.startMjd = pass.startMjd();
    d.crd = std::shared_ptr<const CrdFile>(shared, &shared->file);
    r.ok = true;
    return r;
}

}  // namespace lwb::core::slr
