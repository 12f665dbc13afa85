#include "core/slr/pass_output.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include "core/common/atomic_file.hpp"
#include "core/common/output_set.hpp"
#include "core/common/parallel.hpp"
#include "core/common/text.hpp"
#include "lwb_version.hpp"

// The writers of a screened pass, beside the outputs they write (the loaders are in
// pass_input.cpp): the per-point CSV, the CRD full rate with filter flags, the normal points.

namespace lwb::core::slr {

namespace {
// A pass is written only whole (no damaged records) and never over the file it was read from.
bool writablePassOutput(const std::string& path, const PassData& pass, std::string* error) {
    if (!pass.damaged.empty()) {
        *error = pass.damaged;
        return false;
    }
    if (!pass.source.empty() && sameFile(path, pass.source)) {
        *error = path + ": is the file this pass was read from; choose another name (the input is kept as it is)";
        return false;
    }
    return true;
}
}  // namespace

bool writeScreenCsv(const std::string& path, const PassData& pass, const ScreenResult& screen,
                    const std::vector<PointClass>& classes, const PostfitResult* post, std::string* error) {
    if (!writablePassOutput(path, pass, error)) return false;
    const size_t n = pass.t.size();
    if (screen.pointClass.size() != n || classes.size() != n) {
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
    // Rows [from, to) as text appended to block; the first row with a value that does not fit
    // the buffer (an epoch of 1e300 in fixed notation) is returned, or `to`: refused, never
    // written as whatever the buffer held. std::to_chars instead of printf: a 10⁶-point pass is
    // written in a fraction of the time.
    auto formatRows = [&](size_t from, size_t to, std::string& block) -> size_t {
        char num[64];
        bool fits = true;
        auto put = [&](double value, std::chars_format fmt, int precision) {
            const auto res = std::to_chars(num, num + sizeof num, value, fmt, precision);
            if (res.ec != std::errc()) fits = false;
            else block.append(num, res.ptr);
        };
        auto putInt = [&](unsigned long long value) {
            const auto res = std::to_chars(num, num + sizeof num, value);
            if (res.ec != std::errc()) fits = false;
            else block.append(num, res.ptr);
        };
        for (size_t i = from; i < to; ++i) {
            const PointClass c = classes[i];
            const double res = post && post->ok ? post->residuals[i] : NAN;
            const int kept = post && post->ok ? post->kept[i] : c != PointClass::Noise;
            // index: the type-10 record of the CRD pass (a record without an O-C, e.g. a one-way
            // epoch event, has no row), else the row of the O-C table.
            const size_t index = i < pass.rangeIndex.size() ? pass.rangeIndex.at(i) : i;
            putInt(index);
            block += ',';
            put(pass.t[i], std::chars_format::fixed, 9);
            block += ',';
            put(pass.oc[i], std::chars_format::scientific, 6);
            block += ',';
            block += pointClassName(c);
            block += ',';
            putInt(screen.pointRegion.empty() ? 0u : unsigned(screen.pointRegion[i]));
            block += ',';
            if (std::isfinite(res)) put(res, std::chars_format::scientific, 6);
            block += ',';
            putInt(unsigned(kept));
            block += ',';
            if (!pass.stationFlag.empty()) putInt(unsigned(std::max(0, int(pass.stationFlag[i]))));
            block += '\n';
            if (!fits) return i;
        }
        return to;
    };
    // Blocks of 8192 rows (about 0.5 MB; a stream write per line was a third of the time),
    // formatted up to 16 at a time on the cores and written in order: a 10⁵-point pass is
    // written in about half the time on two cores. At most 16 blocks are held (8 MB).
    constexpr size_t kRows = 8192, kBatch = 16;
    struct alignas(64) Block {  // a line of its own: appends of one thread never touch another's
        std::string text;
        size_t bad = 0;  // first row that did not fit, or the block's end
    };
    std::vector<Block> blocks(kBatch);
    for (size_t b0 = 0; b0 < n; b0 += kRows * kBatch) {
        const size_t count = std::min(kBatch, (n - b0 + kRows - 1) / kRows);
        parallelFor(count, coresFor(0), [&](size_t k) {
            const size_t from = b0 + k * kRows, to = std::min(n, from + kRows);
            blocks[k].text.clear();
            blocks[k].bad = formatRows(from, to, blocks[k].text);
        });
        for (size_t k = 0; k < count; ++k) {
            const size_t bad = blocks[k].bad;
            if (bad < std::min(n, b0 + (k + 1) * kRows)) {
                *error = "point " + std::to_string(bad) + " (epoch_s " + formatDouble(pass.t[bad], 6) + ", oc_s " +
                         formatDouble(pass.oc[bad], 6) + "): a value too large to write";
                return false;  // the AtomicFile removes its temporary
            }
            o.write(blocks[k].text.data(), std::streamsize(blocks[k].text.size()));
        }
    }
    if (!f.commit()) {
        *error = f.error();
        return false;
    }
    return true;
}

bool writeScreenedCrd(const std::string& path, const PassData& pass, const std::vector<uint8_t>& accepted,
                      std::string* error, bool alone) {
    if (!pass.hasCrd) {
        *error = "the pass did not come from a CRD file; there is nothing to write flags into";
        return false;
    }
    if (!writablePassOutput(path, pass, error)) return false;
    const CrdPass& p = pass.crd->passes[size_t(pass.passIndex)];
    // Records that were not screened (no O-C: outside the prediction, one-way events) keep the
    // station's own flag; only the screened ones get 2 (accepted) or 1 (noise).
    std::vector<int> flags(p.ranges.size());
    for (size_t k = 0; k < p.ranges.size(); ++k) flags[k] = p.ranges.filterFlag(k);
    for (size_t i = 0; i < pass.rangeIndex.size() && i < accepted.size(); ++i)
        flags[pass.rangeIndex.at(i)] = accepted[i] ? 2 : 1;
    return writeCrdWithFlags(path, *pass.crd, size_t(pass.passIndex), flags, alone, error);
}

NormalPointProduct normalPointProduct(const PostfitResult* post, const ScreenResult* screen, const std::string& noneReason) {
    NormalPointProduct p;
    p.noneReason = noneReason;
    if (post && post->ok && post->stats.n > 1) {
        p.session = true;
        p.rmsPs = post->stats.rms * 1e12;
        p.skew = post->stats.skew;
        p.kurtosis = post->stats.kurtosis;
        p.peakMinusMeanPs = post->stats.peakMinusMean * 1e12;
        const size_t all = screen ? screen->pointClass.size() : 0;
        // 1: clear, little noise (at most 10 % of the points); 2: clear, much noise.
        p.quality = all == 0 ? 0 : screen->noisePoints * 10 <= all ? 1 : 2;
    }
    // The production date: SOURCE_DATE_EPOCH when set (a reproducible file, the reproducible-
    // builds convention), else now; UTC.
    std::time_t now = std::time(nullptr);
    if (const char* e = std::getenv("SOURCE_DATE_EPOCH")) {
        long long v = 0;
        if (parseLong(e, &v) && v >= 0) now = static_cast<std::time_t>(v);
    }
    std::tm tm{};
    if (gmtime_r(&now, &tm)) {
        p.year = tm.tm_year + 1900;
        p.month = tm.tm_mon + 1;
        p.day = tm.tm_mday;
        p.hour = tm.tm_hour;
    }
    p.softwareVersion = LWB_VERSION;
    return p;
}

bool normalPointPass(const PassData& pass, const std::vector<NormalPoint>& nps, const NormalPointProduct& product, CrdPass* out,
                     std::string* error) {
    if (!pass.hasCrd) {
        *error = "normal points as CRD need the pass's CRD headers (open the CRD file, not an O-C table)";
        return false;
    }
    const CrdPass& full = pass.crd->passes[size_t(pass.passIndex)];
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
            const CrdRange& src = full.ranges[pass.rangeIndex.at(np.pointIndex)];
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
    if (!makeNormalPointPass(full, recs, out, error, product)) return false;
    if (out) out->crlf = full.crlf;
    return true;
}

bool writeNormalPointCrd(const std::string& path, const PassData& pass, const std::vector<NormalPoint>& nps,
                         std::string* error, const NormalPointProduct& product) {
    if (!pass.hasCrd) return normalPointPass(pass, nps, product, nullptr, error);  // (says why)
    if (!writablePassOutput(path, pass, error)) return false;
    CrdPass np;
    if (!normalPointPass(pass, nps, product, &np, error)) return false;
    return writeNormalPointFile(path, {std::move(np)}, error);
}

bool writeNormalPointFile(const std::string& path, std::vector<CrdPass> passes, std::string* error) {
    if (passes.empty()) {
        *error = path + ": no normal-point block to write";
        return false;
    }
    CrdFile out;
    out.path = path;
    out.crlf = passes.front().crlf;
    out.trailer.push_back(trailerFor(passes.front()));
    out.passes = std::move(passes);
    return writeCrd(path, out, error);
}

}  // namespace lwb::core::slr
