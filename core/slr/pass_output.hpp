#pragma once
// The outputs of a screened pass: the per-point CSV, the CRD full rate with the screening's
// filter flags, and the normal points as a CRD normal-point file. The CLI and the workbench's
// export both call these, so both write the same bytes.

#include <cstdint>
#include <string>
#include <vector>

#include "core/slr/pass_input.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/screen.hpp"

namespace lwb::core::slr {

/// Per-point result as CSV: index,epoch_s,oc_s,class,region,residual_s,kept,station_flag, one
/// row per point in pass order; index = the point's type-10 record in the CRD pass (0-based;
/// pass.rangeIndex), or its row in an O-C table; class the run's (PassRunResult::classes:
/// signal, recovered, band or noise), region the screening's. `post` may be null. Atomic.
/// Refuses a pass with damaged records (PassData::damaged).
bool writeScreenCsv(const std::string& path, const PassData& pass, const ScreenResult& screen,
                    const std::vector<PointClass>& classes, const PostfitResult* post, std::string* error);
/// The pass as CRD full rate with filter flags 2 (accepted) / 1 (noise) on the screened records;
/// records without an O-C keep their flag; other passes unchanged (alone: the pass alone, as
/// passAlone gives it).
bool writeScreenedCrd(const std::string& path, const PassData& pass, const std::vector<uint8_t>& accepted,
                      std::string* error, bool alone = false);
/// What a normal-point file of ours says beyond its records (crd.hpp NormalPointProduct): why
/// there are none ("" when there are), the post-fit's session statistics (record 50; quality 1
/// when at most 10 % of the points are noise, else 2), the H1's production date
/// (SOURCE_DATE_EPOCH when set, else now, UTC) and this program's C5 software record (v2).
NormalPointProduct normalPointProduct(const PostfitResult* post, const ScreenResult* screen, const std::string& noneReason);

/// The normal points as a CRD normal-point file (headers of the pass, data type 1), with
/// `product`'s records. With none (no signal, no bin full enough, a doubtful pass), its
/// noneReason is written in their place as a "00" comment record: "00 no normal points: REASON".
bool writeNormalPointCrd(const std::string& path, const PassData& pass, const std::vector<NormalPoint>& nps,
                         std::string* error, const NormalPointProduct& product = {});

/// The normal-point block of writeNormalPointCrd, to be written with others (a station's
/// normal-point file of a day: writeNormalPointFile).
bool normalPointPass(const PassData& pass, const std::vector<NormalPoint>& nps, const NormalPointProduct& product, CrdPass* out,
                     std::string* error);
/// Normal-point blocks as one CRD file, with the line ends and the H9 of the first block as
/// passAlone writes them (crd.hpp): the same bytes whether the pass was read whole or streamed.
bool writeNormalPointFile(const std::string& path, std::vector<CrdPass> passes, std::string* error);

}  // namespace lwb::core::slr
