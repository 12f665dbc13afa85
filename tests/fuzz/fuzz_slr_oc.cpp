// libFuzzer target: O-C from a prediction. The input is split at a line "====": CRD before it,
// CPF after it (inputs without one are skipped). When both read, the O-C of every pass is
// computed against that prediction (station fixed at MLRO, Matera): it succeeds or says why,
// and gives at most one value per range, with an epoch for each. The readers alone are
// fuzz_crd and fuzz_cpf.
#include <Eigen/Core>
#include <string_view>

#include "core/slr/cpf.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/oc.hpp"
#include "tests/fuzz/fuzz_support.hpp"

using namespace lwb::core::slr;
using lwb::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text = lwb::fuzz::asText(data, size);
    const size_t cut = text.find("\n====\n");
    if (cut == std::string_view::npos) return 0;
    const CrdReadResult crd = parseCrd(text.substr(0, cut + 1), "fuzz");
    const CpfReadResult cpf = parseCpf(text.substr(cut + 6), "fuzz");
    lwb::fuzz::checkReported(crd.ok, crd.error);
    lwb::fuzz::checkReported(cpf.ok, cpf.error);
    if (!crd.ok || !cpf.ok) return 0;
    const Eigen::Vector3d mlro(4641978.617, 1393067.723, 4133249.623);
    for (const CrdPass& p : crd.file.passes) {
        const OcResult oc = computeOc(p, cpf.file, mlro, OcParams());
        lwb::fuzz::checkReported(oc.ok, oc.error);
        if (oc.ok) check(oc.oc_s.size() <= p.ranges.size() && oc.oc_s.size() == oc.epoch_s.size());
    }
    return 0;
}
