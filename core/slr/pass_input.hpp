#pragma once
// From files to a pass ready for screening, and back: the layer the `slr` command and the SLR
// workspace share. A CRD full-rate pass gets its O-C from the CPF prediction and the SINEX
// station coordinates when both are given, else from a robust trend of its own time of flight
// (a warning says so); a plain O-C table (CSV, header epoch_s,oc_s) is used as it is. After
// screening the pass is written back as CRD full rate with filter flags, its normal points as a
// CRD normal-point file, and the per-point result as CSV.
#include <string>
#include <vector>

#include "core/common/feedback.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/oc.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/screen.hpp"

namespace lwb::core::slr {

struct PassInputParams {
    std::string cpfPath;      ///< CPF prediction; with sinexPath, O-C from the prediction
    std::string sinexPath;    ///< SINEX station coordinates
    OcParams oc;              ///< light time, refraction (default Mendes–Pavlis from the met records)
    TrendOcParams trend;      ///< the fallback without a prediction
};

struct PassSummary {
    int index = 0;                 ///< pass number in the file (0-based)
    std::string satellite, ilrsId, station;
    std::string start, end;        ///< H4 UTC, "YYYY-MM-DD hh:mm:ss"
    size_t ranges = 0;             ///< type-10 records
    size_t normalPoints = 0;       ///< type-11 records
    int dataType = 0;              ///< 0 full rate, 1 normal points
};

struct PassData {
    std::string source;            ///< file the pass came from
    int passIndex = 0;
    std::string satellite, ilrsId, station;
    int cdpPad = -1;
    std::string ocOrigin;          ///< "CPF prediction", "fitted TOF trend (no prediction)" or "O-C table"
    std::vector<double> t;         ///< epoch (s since 0h UTC of the pass day for CRD input)
    std::vector<double> oc;        ///< O-C (s, two-way)
    std::vector<double> tof;       ///< observed two-way TOF (s); empty for O-C tables
    std::vector<int> stationFlag;  ///< the station's filter flag per point (CRD), empty otherwise
    std::vector<size_t> rangeIndex;///< CrdPass::ranges index per point (CRD)
    double altitudeKm = 0;         ///< satellite altitude estimate for the normal-point bin (0 = unknown)
    bool hasCrd = false;
    CrdFile crd;                   ///< the file as read (for writing back)
};

struct PassInputResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    std::vector<PassSummary> passes;  ///< every pass of the file (one entry for an O-C table)
    PassData pass;                    ///< the loaded pass
};

/// True for the CRD endings (frd fr2 npt np2 crd, any case).
bool isCrdPath(const std::string& path);

/// Loads pass `passIndex` (0-based; -1 = the first full-rate pass) of a CRD file, or an O-C CSV.
PassInputResult loadPass(const std::string& path, int passIndex, const PassInputParams& params,
                         const Feedback* fb = nullptr);

/// Per-point result as CSV: index,epoch_s,oc_s,class,region,residual_s,kept,station_flag, one
/// row per point in pass order; index = the point's type-10 record in the CRD pass (0-based;
/// pass.rangeIndex), or its row in an O-C table. `post` may be null. Atomic.
bool writeScreenCsv(const std::string& path, const PassData& pass, const ScreenResult& screen,
                    const std::vector<uint8_t>& accepted, const PostfitResult* post, std::string* error);
/// The pass as CRD full rate with filter flags 2 (accepted) / 1 (noise) on the screened records;
/// records without an O-C keep their flag; other passes unchanged.
bool writeScreenedCrd(const std::string& path, const PassData& pass, const std::vector<uint8_t>& accepted,
                      std::string* error);
/// The normal points as a CRD normal-point file (headers of the pass, data type 1).
bool writeNormalPointCrd(const std::string& path, const PassData& pass, const std::vector<NormalPoint>& nps,
                         std::string* error);

}  // namespace lwb::core::slr
