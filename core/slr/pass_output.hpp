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
/// pass.rangeIndex), or its row in an O-C table. `post` may be null. Atomic. Refuses a pass
/// with damaged records (PassData::damaged).
bool writeScreenCsv(const std::string& path, const PassData& pass, const ScreenResult& screen,
                    const std::vector<uint8_t>& accepted, const PostfitResult* post, std::string* error);
/// The pass as CRD full rate with filter flags 2 (accepted) / 1 (noise) on the screened records;
/// records without an O-C keep their flag; other passes unchanged.
bool writeScreenedCrd(const std::string& path, const PassData& pass, const std::vector<uint8_t>& accepted,
                      std::string* error);
/// The normal points as a CRD normal-point file (headers of the pass, data type 1). With none
/// (no signal, no bin full enough, a doubtful pass), `noneReason` is written in their place as
/// a "00" comment record: "00 no normal points: REASON".
bool writeNormalPointCrd(const std::string& path, const PassData& pass, const std::vector<NormalPoint>& nps,
                         std::string* error, const std::string& noneReason = {});

/// The normal-point block of writeNormalPointCrd, to be written with others (a station's
/// normal-point file of a day: writeNormalPointFile).
bool normalPointPass(const PassData& pass, const std::vector<NormalPoint>& nps, const std::string& noneReason, CrdPass* out,
                     std::string* error);
/// Normal-point blocks as one CRD file (line ends and trailer like `like`, the file they came from).
bool writeNormalPointFile(const std::string& path, std::vector<CrdPass> passes, const CrdFile& like, std::string* error);

}  // namespace lwb::core::slr
