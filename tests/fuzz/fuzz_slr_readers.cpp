// libFuzzer target for the SLR readers: the same bytes go to the CRD, CPF, SINEX and O-C CSV
// parsers (from memory). Beyond "no crash, no leak, no hang" it checks invariants and trap()s
// when one breaks:
//   - CRD: a file that reads is written back and read again with the same records;
//   - O-C CSV: a table that reads is written and read back to the same doubles;
//   - CPF / SINEX: the interpolator and the station lookup run on whatever was read.
// An input holding a line "====" is also split there: CRD before it, CPF after it, and the
// O-C of every pass is computed against that prediction (fixed station: MLRO, Matera).
// Build: make fuzz (clang, -fsanitize=fuzzer,address). See docs/fuzzing.md.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/slr/cpf.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/oc.hpp"
#include "core/slr/oc_csv.hpp"
#include "core/slr/sinex.hpp"

using namespace lwb::core::slr;

namespace {

void check(bool condition) {
    if (!condition) __builtin_trap();
}

void fuzzCrd(std::string_view text, CrdReadResult* out) {
    CrdReadResult r = parseCrd(text, "fuzz");
    check(r.ok || !r.error.empty());
    if (!r.ok) return;
    const std::string written = formatCrd(r.file);
    const CrdReadResult again = parseCrd(written, "fuzz");
    check(again.ok);
    check(again.file.passes.size() == r.file.passes.size());
    for (size_t k = 0; k < r.file.passes.size(); ++k) {
        const CrdPass &a = r.file.passes[k], &b = again.file.passes[k];
        check(a.records.size() == b.records.size());
        for (size_t i = 0; i < a.records.size(); ++i) check(a.records[i].text == b.records[i].text);
        check(a.ranges.size() == b.ranges.size());
        check(a.normalPoints.size() == b.normalPoints.size());
    }
    check(formatCrd(again.file) == written);
    for (CrdPass p : r.file.passes) {
        std::string err;
        check(setFilterFlags(&p, std::vector<int>(p.ranges.size(), 2), &err));
        for (const auto& x : p.ranges) check(x.filterFlag == 2);
        if (p.ranges.size() <= 4000) {
            const OcResult oc = computeTrendOc(p, TrendOcParams());
            check(oc.ok || !oc.error.empty());
            if (oc.ok) check(oc.oc_s.size() == p.ranges.size());
        }
        if (!p.ranges.empty() && p.normalPoints.size() < 1000) {
            std::vector<CrdNormalPoint> nps;
            CrdNormalPoint n;
            n.secOfDay = p.ranges.front().secOfDay;
            n.tofS = p.ranges.front().tofS;
            n.numRanges = 1;
            nps.push_back(n);
            CrdPass np;
            if (makeNormalPointPass(p, nps, &np, &err)) check(np.normalPoints.size() == 1);
            CrdPass q = p;
            if (setNormalPoints(&q, nps, NormalPointMode::Append, &err))
                check(q.normalPoints.size() == p.normalPoints.size() + 1);
        }
    }
    if (out) *out = std::move(r);
}

void fuzzCpf(std::string_view text, CpfReadResult* out) {
    CpfReadResult r = parseCpf(text, "fuzz");
    check(r.ok || !r.error.empty());
    if (!r.ok) return;
    const CpfInterpolator ip(r.file);
    if (ip.ok() && ip.size() > 0) {
        const long ref = ip.referenceMjd();
        for (double t : {ip.firstSeconds(), 0.5 * (ip.firstSeconds() + ip.lastSeconds()), ip.lastSeconds(),
                         ip.lastSeconds() + 1.0, ip.firstSeconds() - 1.0}) {
            const CpfState s = ip.atSeconds(ref, t);
            check(s.ok || !s.error.empty());
        }
    }
    if (out) *out = std::move(r);
}

void fuzzSinex(std::string_view text) {
    const SinexReadResult r = parseSinex(text, "fuzz");
    check(r.ok || !r.error.empty());
    if (!r.ok) return;
    size_t n = 0;
    for (const auto& s : r.file.solutions) {
        if (++n > 20) break;
        const StationPositionResult p = stationPosition(r.file, s.code, 56000, 0.0);
        check(p.ok || !p.error.empty());
    }
    (void)stationPositionByPad(r.file, 7941, 56000, 0.0);
}

void fuzzCsv(std::string_view text) {
    const OcCsvReadResult r = parseOcCsv(text, "fuzz");
    check(r.ok || !r.error.empty());
    if (!r.ok) return;
    const OcCsvReadResult back = parseOcCsv(formatOcCsv(r.table), "fuzz");
    check(back.ok);
    check(back.table.epoch_s == r.table.epoch_s);
    check(back.table.oc_s == r.table.oc_s);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    fuzzCrd(text, nullptr);
    fuzzCpf(text, nullptr);
    fuzzSinex(text);
    fuzzCsv(text);
    const size_t cut = text.find("\n====\n");
    if (cut != std::string_view::npos) {
        CrdReadResult crd;
        CpfReadResult cpf;
        fuzzCrd(text.substr(0, cut + 1), &crd);
        fuzzCpf(text.substr(cut + 6), &cpf);
        if (crd.ok && cpf.ok) {
            const Eigen::Vector3d mlro(4641978.617, 1393067.723, 4133249.623);
            for (const CrdPass& p : crd.file.passes) {
                if (p.ranges.size() > 4000) continue;
                const OcResult oc = computeOc(p, cpf.file, mlro, OcParams());
                check(oc.ok || !oc.error.empty());
                if (oc.ok) check(oc.oc_s.size() <= p.ranges.size() && oc.oc_s.size() == oc.epoch_s.size());
            }
        }
    }
    return 0;
}
