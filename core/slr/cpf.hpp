#pragma once
// CPF (ILRS Consolidated Prediction Format, v1.01 and v2.00; Ricklefs) reader and Lagrange
// interpolation of the predicted target position.
//
// Read: H1 (version, source, production date, sequence, target name), H2 (ids, span, step,
// target type, frame, centre-of-mass flag), H5 (centre-of-mass to reflector offset), H9;
// type 10 position records (direction flag, MJD, seconds of day, leap-second flag, X Y Z in
// metres, body-fixed ITRF, UTC epochs), type 20 velocity records (m/s, following their 10),
// 99 end. Other records (H3 H4, 30 40 50 60 70, 00 comments) are kept in `otherLines` only.
// Case-insensitive record ids, free format.
#include <Eigen/Core>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace lwb::core::slr {

struct CpfHeader {
    int version = 1;              ///< CPF format version
    std::string source;           ///< ephemeris source (e.g. "HTS")
    int year = 0, month = 0, day = 0, hour = 0;  ///< production date (UTC)
    std::string sequence;         ///< ephemeris sequence number (and v2 sub-daily number, blank-joined)
    std::string targetName;
    std::string notes;
    std::string ilrsId;           ///< H2 ILRS id as written
    long sic = -1, norad = -1;
    long startMjd = 0;  double startSod = 0;  ///< H2 span start (UTC); 0 when no H2
    long endMjd = 0;    double endSod = 0;    ///< H2 span end (UTC)
    double stepS = NAN;           ///< time between table entries (s)
    int targetType = -1;          ///< 1 passive retro-reflector, 2 synchronous transponder, ...
    int referenceFrame = -1;      ///< 0 geocentric true body-fixed (ITRF), 1 ICRF, 2 J2000
    int comApplied = -1;          ///< 1: positions are for the retro-reflector (CofM correction applied)
    double comOffsetM = NAN;      ///< H5 centre-of-mass to reflector offset (m), NaN when absent
};

/// One type-10 record, with the velocity of the following type-20 record when present.
struct CpfPosition {
    int direction = 0;            ///< 0 common epoch (instantaneous), 1 transmit, 2 receive
    long mjd = 0;                 ///< Modified Julian Date (UTC)
    double sod = 0;               ///< seconds of day (UTC)
    int leapSecond = 0;           ///< leap-second flag (0 none; +1/-1 on a leap-second day)
    Eigen::Vector3d position{0, 0, 0};   ///< m, ITRF
    bool hasVelocity = false;
    Eigen::Vector3d velocity{0, 0, 0};   ///< m/s, ITRF
    long line = 0;                ///< source line
};

struct CpfFile {
    std::string path;
    CpfHeader header;
    std::vector<CpfPosition> positions;  ///< in file order (strictly increasing epochs per direction)
    std::vector<std::string> otherLines; ///< records kept but not interpreted (H3, H4, 30, 40, ...)
};

struct CpfReadResult {
    bool ok = false;
    std::string error;            ///< "FILE:LINE: what is wrong"
    std::vector<std::string> warnings;
    CpfFile file;
};

/// Whether the positions can be the orbit of a satellite: "" when they can, else what is wrong,
/// naming the record's line. Checked: every position at least 6 300 km from the Earth's centre
/// (a record at (0, 0, 0) or below the surface is damaged), and every record on the smooth orbit
/// through its six nearest neighbours of the same direction (Lagrange interpolation, which
/// follows an orbit sampled at 1-5 min to metres): a record more than 1 km and more than 20 times
/// the median of these residuals off is damaged. Records next to a gap wider than twice the
/// usual step are not judged.
std::string cpfPlausibilityProblem(const CpfFile& cpf);

/// Parses CPF text; `source` names it in messages. Never throws.
CpfReadResult parseCpf(std::string_view text, const std::string& source);
/// Reads and parses a CPF file.
CpfReadResult readCpf(const std::string& path);

struct CpfInterpParams {
    int points = 10;              ///< Lagrange nodes (2..20); ILRS practice: 8-10 for LEO at 1-5 min steps
    int direction = 0;            ///< which position records to use (0 common epoch; 1 or 2 for files that have them)
};
std::string validate(const CpfInterpParams& p);

struct CpfState {
    bool ok = false;
    std::string error;            ///< e.g. "epoch is 125.0 s after the last prediction record"
    Eigen::Vector3d position{0, 0, 0};  ///< m, ITRF (body-fixed), at the epoch
    Eigen::Vector3d velocity{0, 0, 0};  ///< m/s: derivative of the interpolating polynomial
};

/// Interpolator over the records of one direction flag, prepared once and used many times.
/// Epochs are MJD + seconds of day (UTC). Re-entrant (const after construction).
class CpfInterpolator {
public:
    explicit CpfInterpolator(const CpfFile& cpf, const CpfInterpParams& params = {});
    bool ok() const { return m_error.empty(); }
    const std::string& error() const { return m_error; }

    /// Lagrange interpolation with `points` nodes centred on the epoch (shifted inwards at the
    /// ends of the table). Error when the epoch lies outside the table, saying by how much.
    /// The table must not have a gap (step > 2.5 x the median step) around the epoch.
    /// withVelocity=false skips the derivative (faster).
    CpfState at(long mjd, double sod, bool withVelocity = true) const;
    /// Same with the epoch as seconds since 0h UTC of `refMjd`.
    CpfState atSeconds(long refMjd, double seconds, bool withVelocity = true) const;

    long referenceMjd() const { return m_refMjd; }
    double firstSeconds() const { return m_t.empty() ? 0 : m_t.front(); }  ///< since 0h of referenceMjd()
    double lastSeconds() const { return m_t.empty() ? 0 : m_t.back(); }
    size_t size() const { return m_t.size(); }

private:
    std::string m_error;
    int m_points = 10;
    long m_refMjd = 0;
    std::vector<double> m_t;                 ///< s since 0h of m_refMjd
    std::vector<Eigen::Vector3d> m_pos;
    double m_medianStep = 0;
};

/// One-off interpolation (builds a CpfInterpolator).
CpfState interpolateCpf(const CpfFile& cpf, long mjd, double sod, const CpfInterpParams& params = {});

}  // namespace lwb::core::slr
