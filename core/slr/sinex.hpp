#pragma once
// SINEX (Solution INdependent EXchange format, v2.01/2.02) station coordinates: SITE/ID,
// SOLUTION/EPOCHS and SOLUTION/ESTIMATE (STAX STAY STAZ in m, VELX VELY VELZ in m/y with their
// REF_EPOCH "YY:DOY:SSSSS"). Other blocks are skipped. Station position at an epoch =
// position + velocity * (epoch - REF_EPOCH) in years of 365.25 days, using the solution
// (SOLN) whose SOLUTION/EPOCHS validity interval holds the epoch.
//
// SLR files (ILRS SLRF2014 and later) key their sites by the 4-digit CDP pad id, the number in
// CRD H2 (e.g. 7941 Matera MLRO); SITE/ID then ends with the 8-digit CDP-SOD (pad, system,
// occupancy). Post-seismic (PSD) corrections that some sites need are not applied.
#include <Eigen/Core>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace lwb::core::slr {

struct SinexSite {
    std::string code;         ///< 4-character site code (for SLR files: the CDP pad id)
    std::string point;        ///< point code ("A")
    std::string domes;        ///< DOMES number
    std::string description;  ///< free text (SITE/ID columns 22-43)
    std::string cdpSod;       ///< trailing 8-digit CDP-SOD when present (SLRF files), else ""
    long line = 0;
};

/// One site solution: position and velocity at the reference epoch, and where it is valid.
struct SinexSolution {
    std::string code, point;
    std::string soln;                     ///< SOLN field as written ("1", "2", ...)
    long refMjd = 0;  double refSod = 0;  ///< REF_EPOCH of the estimates
    Eigen::Vector3d position{0, 0, 0};    ///< m (ITRF of the file)
    Eigen::Vector3d velocity{0, 0, 0};    ///< m/y
    Eigen::Vector3d positionSigma{NAN, NAN, NAN}, velocitySigma{NAN, NAN, NAN};
    int haveMask = 0;                     ///< bits 0..2 STAX/Y/Z, 3..5 VELX/Y/Z
    bool hasValidity = false;             ///< SOLUTION/EPOCHS gave the interval
    double validFromMjd = NAN, validToMjd = NAN;  ///< days (fractional MJD); "00:000:00000" end = open
    long line = 0;                        ///< line of its first estimate
};

struct SinexFile {
    std::string path;
    std::vector<SinexSite> sites;
    std::vector<SinexSolution> solutions;  ///< in file order
};

struct SinexReadResult {
    bool ok = false;
    std::string error;                    ///< "FILE:LINE: what is wrong"
    std::vector<std::string> warnings;
    SinexFile file;
};

/// Parses SINEX text; `source` names it in messages. Never throws.
SinexReadResult parseSinex(std::string_view text, const std::string& source);
/// Reads and parses a SINEX file.
SinexReadResult readSinex(const std::string& path);

struct StationPositionResult {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;    ///< e.g. epoch outside every validity interval
    Eigen::Vector3d position{0, 0, 0};    ///< m, at the epoch
    Eigen::Vector3d velocity{0, 0, 0};    ///< m/y
    std::string code, soln, description;
};

/// Position of a site (by SINEX site code, e.g. "7941") at MJD + seconds of day (UTC).
/// Picks the solution whose validity interval holds the epoch; else the nearest one, with a
/// warning. Errors when the site is absent or lacks STAX/STAY/STAZ. Missing velocities count
/// as zero with a warning.
StationPositionResult stationPosition(const SinexFile& sinex, const std::string& siteCode, long mjd, double sod);

/// Same for a CRD H2 CDP pad id: the site code is the 4-digit pad id; SITE/ID CDP-SOD entries
/// whose first 4 digits match are used when the code itself is absent.
StationPositionResult stationPositionByPad(const SinexFile& sinex, int cdpPadId, long mjd, double sod);

}  // namespace lwb::core::slr
