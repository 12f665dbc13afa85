#pragma once
// CRD (ILRS Consolidated laser Ranging Data format, v1.01 and v2.01; Ricklefs & Moore) reader
// and writer for full-rate (.frd .fr2), normal-point (.npt .np2) and sampled (.qlk) files.
//
// What it accepts: upper- or lower-case record ids, free format (fields separated by blanks),
// several passes per file (H4 ... H8 blocks; H1/H2/H3 may repeat or be inherited by the next
// H4), "na" fields (v2: not available -> NaN or -1), 00 comments and 9x user records (kept,
// not interpreted), v1 files that omit trailing fields (e.g. MLRS "version 0" files).
// Every line is kept verbatim in its pass, so writing a file back reproduces it record for
// record (line ends become the file's own: LF, or CRLF when the first line ended so).
//
// Parsed: H1 H2 H3 H4 (H5 kept), C0, 10 (full rate), 11 (normal point), 12, 20 (met),
// 30 (pointing), 40/41 (calibration). Others (21, 42, 50, 60, C1..C7, 9x) are kept verbatim.
//
// Errors vs warnings: a record that cannot be read inside an otherwise sound pass is skipped
// with a warning "FILE:LINE: ..." (the line is still kept for writing). A block that cannot be
// a pass (H4 without a valid data type or start date-time, no readable 10/11 record) is kept
// with CrdPass::problem set and a warning, so that the other passes of the file are still read;
// an H4 end date-time written as unknown (-1 or na in all six fields) is accepted with a note.
// H4 flags outside their ranges (range type 0..4, ...) are warned about and read as unknown.
// A file that has no H1/H4 before its data, whose H1 names another format (CPF), whose every
// pass is unusable, binary data or an empty file stop the read with an error naming file and
// line.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/feedback.hpp"

namespace lwb::core::slr {

/// Value of an absent integer field ("na" in v2, or missing trailing field).
constexpr int kCrdAbsent = -1;

/// One line of the file, verbatim.
/// A record's id held in 8 bytes (issue 44: a std::string was 32 bytes of every record): up to
/// 7 characters exactly. A longer first field (no CRD record's) keeps its first 7 and equals
/// no id of 7 characters or fewer.
class CrdRecordId {
public:
    CrdRecordId() = default;
    CrdRecordId(std::string_view s) {
        m_n = static_cast<unsigned char>(s.size() > kMax ? kLong : s.size());
        std::memcpy(m_c, s.data(), std::min(s.size(), kMax));
    }
    CrdRecordId(const char* s) : CrdRecordId(std::string_view(s)) {}
    CrdRecordId(const std::string& s) : CrdRecordId(std::string_view(s)) {}
    size_t size() const { return m_n == kLong ? kMax : m_n; }
    bool empty() const { return m_n == 0; }
    char operator[](size_t i) const { return m_c[i]; }
    std::string_view view() const { return {m_c, size()}; }
    std::string str() const { return std::string(view()); }
    operator std::string() const { return str(); }
    friend bool operator==(const CrdRecordId& a, const CrdRecordId& b) { return a.m_n == b.m_n && a.view() == b.view(); }
    friend bool operator!=(const CrdRecordId& a, const CrdRecordId& b) { return !(a == b); }

private:
    static constexpr size_t kMax = 7;
    static constexpr unsigned char kLong = 255;
    char m_c[kMax] = {};
    unsigned char m_n = 0;
};

struct CrdRecord {
    std::string text;  ///< the line without its line end (trailing CRs removed)
    CrdRecordId id;    ///< lower-case record id: "h1".."h9", "c0".."c7", "10", "11", "00", "93", ...; "" for a blank line
    long line = 0;     ///< 1-based line in the source (0 for records added by a helper)
};

/// H1 format header.
struct CrdFormatHeader {
    int version = 1;           ///< CRD format version (0 and 1 are both read as v1)
    int year = 0, month = 0, day = 0, hour = 0;  ///< production date (UTC)
    std::string text;          ///< the record itself
    long line = 0;
};

/// H2 station header.
struct CrdStation {
    std::string name;          ///< station name (e.g. "MATM")
    int cdpPadId = kCrdAbsent; ///< 4-digit CDP pad id (the SLRF/SINEX site code), e.g. 7941
    int cdpSystem = kCrdAbsent;     ///< CDP system number
    int cdpOccupancy = kCrdAbsent;  ///< CDP occupancy sequence number
    int timeScale = kCrdAbsent;     ///< station epoch time scale (3 UTC(USNO), 4 UTC(GPS), 7 UTC(BIH/BIPM))
    std::string network;       ///< v2: station network ("ILRS", "EUROLAS", "NASA", ...)
    std::string text;
    long line = 0;
};

/// H3 target header.
struct CrdTarget {
    std::string name;          ///< target name (e.g. "blits")
    std::string ilrsId;        ///< ILRS (COSPAR-based) id as written, e.g. "0904907"
    long sic = kCrdAbsent;     ///< Goddard satellite id code
    long norad = kCrdAbsent;   ///< NORAD catalogue number
    int timeScale = kCrdAbsent;     ///< spacecraft epoch time scale (transponders)
    int targetType = kCrdAbsent;    ///< 0 none/passive (v1), 1 passive retro-reflector, 2 synchronous transponder, ...
    int targetClass = kCrdAbsent;   ///< v2 target class
    int targetLocation = kCrdAbsent;///< v2 location/dynamics
    std::string text;
    long line = 0;
};

/// H4 session (pass) header.
struct CrdSession {
    int dataType = 0;          ///< 0 full rate, 1 normal point, 2 sampled engineering
    int startYear = 0, startMonth = 0, startDay = 0, startHour = 0, startMinute = 0, startSecond = 0;  ///< UTC
    /// UTC; all kCrdAbsent when the H4 gives the end as unknown (-1 or na)
    int endYear = 0, endMonth = 0, endDay = 0, endHour = 0, endMinute = 0, endSecond = 0;
    int releaseFlag = kCrdAbsent;        ///< data release (0 first release, ...)
    int refractionApplied = kCrdAbsent;  ///< 1: tropospheric refraction already applied to the ranges
    int comApplied = kCrdAbsent;         ///< 1: centre-of-mass correction applied
    int receiveAmpApplied = kCrdAbsent;  ///< 1: receive amplitude correction applied
    int stationDelayApplied = kCrdAbsent;///< 1: station system delay (calibration) applied
    int spacecraftDelayApplied = kCrdAbsent;  ///< 1: spacecraft system delay applied
    int rangeType = kCrdAbsent;          ///< 0 no ranges, 1 one-way, 2 two-way, 3 received only, 4 mixed
    int qualityAlert = kCrdAbsent;       ///< 0 good, 1 suspect, 2 poor
    // (a flag outside its range is read as kCrdAbsent, with a warning)
    std::string text;
    long line = 0;
};

/// C0 system configuration.
struct CrdSystemConfig {
    int detailType = 0;
    double wavelengthNm = NAN;           ///< transmit wavelength (nm)
    std::string systemId;                ///< the id type-10/11 records refer to
    std::vector<std::string> componentIds;
    size_t record = 0;                   ///< index into CrdPass::records
    long line = 0;
};

/// Type 10: one full-rate range.
struct CrdRange {
    double secOfDay = 0;     ///< s of day (UTC) of the epoch named by epochEvent
    double tofS = 0;         ///< two-way time of flight (s), corrected for system delay per H4
    std::string configId;    ///< system configuration id (C0)
    int epochEvent = 2;      ///< 0 ground receive, 1 spacecraft bounce, 2 ground transmit (two-way); 3..6 one-way
    int filterFlag = 0;      ///< 0 unknown, 1 noise, 2 data
    int detectorChannel = kCrdAbsent;
    int stopNumber = kCrdAbsent;
    double receiveAmplitude = NAN;   ///< receive amplitude (mV or linear count), NaN when absent
    double transmitAmplitude = NAN;  ///< v2 transmit amplitude, NaN when absent
    size_t record = 0;       ///< index into CrdPass::rangeLines (its line's text)
    long line = 0;           ///< source line
};

/// A column of a pass's type-10 records that is often the same in every record (a detector
/// channel, "na" amplitudes): one value until a record differs, then one per record.
template <class T>
class CrdLazyColumn {
public:
    T at(size_t i) const { return m_values.empty() ? m_first : m_values[i]; }
    void push(T v, size_t count) {  // count: the records before this one
        if (m_values.empty()) {
            if (count == 0) m_first = v;
            if (same(v, m_first)) return;
            m_values.assign(count, m_first);
        }
        m_values.push_back(v);
    }
    void set(size_t i, T v, size_t count) {
        if (m_values.empty()) {
            if (same(v, m_first)) return;
            m_values.assign(count, m_first);
        }
        m_values[i] = v;
    }
    void erase(size_t i) {
        if (!m_values.empty()) m_values.erase(m_values.begin() + static_cast<std::ptrdiff_t>(i));
    }
    void clear() {
        m_values.clear();
        m_values.shrink_to_fit();
    }
    size_t bytes() const { return m_values.capacity() * sizeof(T); }

private:
    static bool same(T a, T b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }  // (NaN is NaN)
    T m_first{};
    std::vector<T> m_values;
};

/// A column of a pass's type-10 records whose value mostly rises by one from record to record
/// (a record's index among the pass's lines, its line in the file): kept as runs, each its
/// first record and value, until the runs would outweigh a value per record (every other line
/// a meteorological record, say), then one value per record. A raw kHz pass's type-10 lines
/// follow one another: one run (issue 44: 8 of its 26 bytes a record). Also a CRD pass's
/// record index per point (PassData::rangeIndex).
template <class T>
class CrdStepColumn {
public:
    static CrdStepColumn of(const std::vector<T>& values) {
        CrdStepColumn c;
        for (T v : values) c.push(v);
        return c;
    }
    CrdStepColumn() = default;
    CrdStepColumn(const CrdStepColumn&) = default;
    CrdStepColumn& operator=(const CrdStepColumn&) = default;
    // (moved from: empty, as a moved-from vector is; the defaults kept its size)
    CrdStepColumn(CrdStepColumn&& o) noexcept { swap(o); }
    CrdStepColumn& operator=(CrdStepColumn&& o) noexcept {
        CrdStepColumn(std::move(o)).swap(*this);
        return *this;
    }
    void swap(CrdStepColumn& o) noexcept {
        m_runs.swap(o.m_runs);
        m_values.swap(o.m_values);
        std::swap(m_size, o.m_size);
        std::swap(m_last, o.m_last);
        std::swap(m_asRuns, o.m_asRuns);
    }
    size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    T at(size_t i) const {
        if (!m_asRuns) return m_values[i];
        const auto r = std::upper_bound(m_runs.begin(), m_runs.end(), i,
                                        [](size_t k, const Run& run) { return k < run.first; }) - 1;
        return static_cast<T>(r->value + static_cast<T>(i - r->first));
    }
    void push(T v) {
        if (m_asRuns) {
            if (m_runs.empty() || v != static_cast<T>(m_last + 1)) {
                if ((m_runs.size() + 1) * sizeof(Run) > (m_size + 16) * sizeof(T)) {
                    toValues();  // (the runs would outweigh the values)
                } else {
                    m_runs.push_back({m_size, v});
                }
            }
        }
        if (!m_asRuns) m_values.push_back(v);
        m_last = v;
        ++m_size;
    }
    // (kept again as runs where they fit: a pass with one leap-second record erased (noLeap)
    // is still one or two runs)
    void erase(size_t i) {
        CrdStepColumn rest;
        for (size_t k = 0; k < m_size; ++k)
            if (k != i) rest.push(at(k));
        swap(rest);
    }
    size_t bytes() const { return m_values.capacity() * sizeof(T) + m_runs.capacity() * sizeof(Run); }

private:
    struct Run {
        size_t first;  // its first record
        T value;       // that record's value
    };
    void toValues() {
        if (!m_asRuns) return;
        std::vector<T> v;
        v.reserve(m_size + 1);
        for (size_t i = 0; i < m_size; ++i) v.push_back(at(i));
        m_values.swap(v);
        m_runs = std::vector<Run>();
        m_asRuns = false;
    }
    std::vector<Run> m_runs;
    std::vector<T> m_values;
    size_t m_size = 0;
    T m_last{};
    bool m_asRuns = true;
};

/// The type-10 records of a pass by column (issue 44): 18 bytes a record where a CrdRange is
/// 96 (epoch and TOF 8 each, epoch event and flag 1 each; the record index and line as runs),
/// its configuration id a small number into the pass's ids, the columns that
/// do not change (channel, stop, amplitudes "na") one value. Read a record with [] (a CrdRange
/// by value) or a column; records are added with push_back and changed with setFilterFlag.
class CrdRanges {
public:
    size_t size() const { return m_sod.size(); }
    bool empty() const { return m_sod.empty(); }
    void reserve(size_t n);
    void clear();
    CrdRange operator[](size_t i) const;
    CrdRange front() const { return (*this)[0]; }
    CrdRange back() const { return (*this)[size() - 1]; }
    void push_back(const CrdRange& r);
    void erase(size_t i);
    void setFilterFlag(size_t i, int flag) { m_flag[i] = static_cast<int8_t>(flag); }
    void setEpochEvent(size_t i, int event) { m_event[i] = static_cast<int8_t>(event); }

    /// The columns a pass's O-C and screening read without building records.
    double secOfDay(size_t i) const { return m_sod[i]; }
    double tofS(size_t i) const { return m_tof[i]; }
    int filterFlag(size_t i) const { return m_flag[i]; }
    int epochEvent(size_t i) const { return m_event[i]; }
    size_t record(size_t i) const { return m_record.at(i); }
    long line(size_t i) const { return static_cast<long>(m_line.at(i)); }
    const std::string& configId(size_t i) const { return m_configIds[m_config.at(i)]; }
    /// Bytes held (the benchmark's accounting).
    size_t bytes() const;

    class const_iterator {
    public:
        using iterator_category = std::forward_iterator_tag;
        using value_type = CrdRange;
        using difference_type = std::ptrdiff_t;
        using pointer = void;
        using reference = CrdRange;
        const_iterator(const CrdRanges* r, size_t i) : m_r(r), m_i(i) {}
        CrdRange operator*() const { return (*m_r)[m_i]; }
        const_iterator& operator++() {
            ++m_i;
            return *this;
        }
        bool operator==(const const_iterator& o) const { return m_i == o.m_i; }
        bool operator!=(const const_iterator& o) const { return m_i != o.m_i; }

    private:
        const CrdRanges* m_r;
        size_t m_i;
    };
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size()}; }

private:
    std::vector<double> m_sod, m_tof;
    CrdLazyColumn<uint32_t> m_config;       ///< index into m_configIds (one value throughout: no column)
    std::vector<std::string> m_configIds;
    uint32_t m_lastConfig = 0;              ///< the last record's (the likeliest for the next one)
    std::vector<int8_t> m_event, m_flag;
    CrdStepColumn<uint32_t> m_record, m_line;
    CrdLazyColumn<int32_t> m_channel, m_stop;
    CrdLazyColumn<double> m_rxAmp, m_txAmp;
};

/// Type 11: one normal point (also what a helper writes).
struct CrdNormalPoint {
    double secOfDay = 0;      ///< s of day (UTC)
    double tofS = 0;          ///< two-way time of flight (s)
    std::string configId = "std";  ///< system configuration id
    int epochEvent = 2;       ///< as in CrdRange
    double windowS = NAN;     ///< normal point window length (s)
    int numRanges = 0;        ///< number of raw ranges after editing
    double binRmsPs = NAN;    ///< bin RMS of the accepted raw time-of-flight residuals from the trend (ps, two-way)
    double skew = NAN;        ///< bin skew
    double kurtosis = NAN;    ///< bin kurtosis
    double peakMinusMeanPs = NAN;  ///< bin peak minus mean (ps)
    double returnRatePct = NAN;    ///< return rate (%)
    int detectorChannel = 0;  ///< 0 for all channels / not applicable
    double snr = NAN;         ///< v2 signal to noise ratio
    size_t record = 0;        ///< index into CrdPass::records (set by the reader)
    long line = 0;
};

/// Type 12: range supplement.
struct CrdRangeSupplement {
    double secOfDay = 0;
    std::string configId;
    double refractionPs = NAN;     ///< tropospheric refraction correction (ps, one-way)
    double comCorrectionM = NAN;   ///< target centre-of-mass correction (m, one-way)
    double ndValue = NAN;          ///< neutral density filter value
    double timeBiasS = NAN;        ///< time bias applied (s)
    double rangeRate = NAN;        ///< v2 range rate (m/s)
    size_t record = 0;
    long line = 0;
};

/// Type 20: meteorological record.
struct CrdMeteo {
    double secOfDay = 0;
    double pressureMbar = NAN;     ///< surface pressure (mbar = hPa)
    double temperatureK = NAN;     ///< surface temperature (K)
    double humidityPct = NAN;      ///< relative humidity (%)
    int origin = kCrdAbsent;       ///< 0 measured at the epoch, 1 interpolated
    size_t record = 0;
    long line = 0;
};

/// Type 30: pointing angles.
struct CrdPointing {
    double secOfDay = 0;
    double azimuthDeg = NAN;
    double elevationDeg = NAN;
    int directionFlag = kCrdAbsent;  ///< 0 transmit and receive, 1 transmit, 2 receive
    int angleOrigin = kCrdAbsent;    ///< 0 unknown, 1 computed, 2 commanded, 3 measured
    int refractionCorrected = kCrdAbsent;
    double azimuthRate = NAN, elevationRate = NAN;  ///< v2 (deg/s)
    size_t record = 0;
    long line = 0;
};

/// Types 40 (calibration) and 41 (calibration detail, v2).
struct CrdCalibration {
    bool detail = false;             ///< true for a type-41 record
    double secOfDay = 0;
    int dataType = kCrdAbsent;       ///< 0 station combined, 1 transmit, 2 receive
    std::string configId;
    long pointsRecorded = kCrdAbsent, pointsUsed = kCrdAbsent;
    double targetDistanceM = NAN;    ///< one-way target distance (m)
    double systemDelayPs = NAN;      ///< calibration system delay (ps)
    double delayShiftPs = NAN;       ///< delay shift (ps)
    double rmsPs = NAN;
    double skew = NAN, kurtosis = NAN;
    double peakMinusMeanPs = NAN;
    int calType = kCrdAbsent, shiftType = kCrdAbsent, detectorChannel = kCrdAbsent;
    int span = kCrdAbsent;           ///< v2 calibration span
    double returnRatePct = NAN;      ///< v2
    size_t record = 0;
    long line = 0;
};

/// The file a reader read, as it was then (its lines are re-read from it by offset).
struct CrdFileOrigin {
    std::string path;      ///< as given (for messages)
    std::string openPath;  ///< absolute, to open it again
    long long size = -1;
    long long mtimeNs = 0;
    unsigned long long inode = 0, device = 0;
};

/// A pass's type-10 lines, held apart from its other records (issue 44: a CrdRecord a line was
/// 112 bytes of every event). While a pass is read, their texts lie one after another in one
/// buffer, a 4-byte offset a line. A pass read from a plain file (not compressed, not the
/// standard input) then keeps no text at all: each run of consecutive lines knows its span in
/// the file, and the lines are read again from there when they are written (a file changed
/// since is refused, not written from). Runs also give each line its place among the records
/// (its slot: the run is written before records[slot]) and its source line. Lines the reader
/// could not parse are kept too (written back as they were).
class CrdRangeLines {
public:
    size_t size() const { return m_size; }
    bool empty() const { return m_size == 0; }
    /// Line k's text: only while the texts are in memory (inMemory()).
    std::string_view text(size_t k) const;
    bool inMemory() const { return !m_origin; }
    long line(size_t k) const;
    size_t slot(size_t k) const;
    /// Adds a line after the others (slot: the number of records before it; fileOffset: where
    /// the line starts in its file, -1 when it did not come from a plain file).
    void add(std::string_view text, long line, size_t slot, long long fileOffset = -1);
    void reserve(size_t lines, size_t bytes);
    /// Before any line is added: the lines to come are `origin`'s own bytes at the offsets given
    /// to add(), so only their places are kept: the reader parses them from the file's text it
    /// holds until then (Reader's fileBytes), and a writer reads them back from the file in
    /// blocks. A raw kHz pass's type-10 texts were copied beside the file's text they were read
    /// from: 54 of a 10⁶-event pass's 113 MB at its read (issue 44). A line added with no place
    /// (fileOffset −1) brings the earlier ones back into memory and the texts are kept from there.
    void placesOnly(const std::shared_ptr<const CrdFileOrigin>& origin);
    /// Drops the texts when every line has its place in `origin`'s file (else keeps them).
    void keepInFile(const std::shared_ptr<const CrdFileOrigin>& origin);
    /// Reads the texts back into memory (a no-op when they are). False with *error when the file
    /// changed since it was read.
    bool load(std::string* error);
    /// Replaces field `field` (0-based, blank-separated) of every line k with value(k) (a
    /// nullopt keeps it). False (*error) when a line has no such field or the texts cannot be
    /// read back (nothing is changed then).
    bool replaceField(size_t field, const std::function<std::optional<std::string>(size_t k)>& value, std::string* error);
    size_t bytes() const;
    /// The lines' text bytes (without line ends), in memory or in the file.
    size_t textBytes() const;
    void clear() { *this = CrdRangeLines(); }

    /// The lines in order, from memory or from the file (in blocks).
    class Reader {
    public:
        /// fileBytes: the whole file's bytes as they were read (lines kept by place are taken
        /// from there, not read again from the file); empty: from the file.
        explicit Reader(const CrdRangeLines& lines, std::string_view fileBytes = {});
        ~Reader();
        Reader(const Reader&) = delete;
        Reader& operator=(const Reader&) = delete;
        /// The next line's text (valid until the next call); false at the end or on an error.
        bool next(std::string_view* text);
        const std::string& error() const { return m_error; }

    private:
        bool fill();
        const CrdRangeLines& m_lines;
        size_t m_k = 0, m_run = 0, m_inRun = 0;
        struct File;
        std::unique_ptr<File> m_file;
        std::string m_error;
    };

private:
    struct Run {
        size_t first = 0;      // its first line's index
        size_t slot = 0;
        long firstLine = 0;
        size_t base = 0;       // the offset its lines' starts are counted from (in m_text)
        long long fileBegin = -1, fileEnd = -1;  // its lines' span in the file (the last one's text ends at fileEnd)
    };
    size_t runOf(size_t k) const;
    size_t runSize(size_t r) const { return (r + 1 < m_runs.size() ? m_runs[r + 1].first : m_size) - m_runs[r].first; }
    std::string m_text;
    std::vector<uint32_t> m_start;  // each line's start, from its run's base (in memory only)
    std::vector<Run> m_runs;
    size_t m_size = 0;
    bool m_allInFile = true;
    std::shared_ptr<const CrdFileOrigin> m_origin;  // set when the texts are in the file only
};

/// One pass: an H4 ... H8 block with the lines that precede it.
struct CrdPass {
    CrdFormatHeader format;          ///< from this block's H1 or the last one before it
    CrdStation station;
    CrdTarget target;
    CrdSession session;
    std::string predictionHeader;    ///< H5 text (v2), empty when absent
    bool inheritsHeaders = false;    ///< true when H1/H2/H3 came from an earlier block of the file
    bool endedWithH8 = false;        ///< false when the block was closed by a new H1/H4 or the end of file
    size_t ordinal = 0;              ///< its place among the file's passes, 1-based (0: made, not read)
    bool crlf = false;               ///< its file used CRLF line ends (a pass written alone keeps them)

    /// Every line of the block in order but its type-10 ones: comments and H1..H3 before the
    /// H4, the H4, configs, other data, 9x user records, the H8. With rangeLines in their slots
    /// (allRecords) writing them back reproduces the block.
    std::vector<CrdRecord> records;
    /// The block's type-10 lines, each with its place among `records`.
    CrdRangeLines rangeLines;

    std::vector<CrdSystemConfig> configs;
    CrdRanges ranges;                           ///< type 10, in file order
    std::vector<CrdNormalPoint> normalPoints;   ///< type 11
    std::vector<CrdRangeSupplement> supplements;///< type 12
    std::vector<CrdMeteo> meteo;                ///< type 20
    std::vector<CrdPointing> pointing;          ///< type 30
    std::vector<CrdCalibration> calibrations;   ///< types 40 and 41
    /// Source lines of data records (types 10, 11, 12, 20, 30, 40, 41, C0) that could not be
    /// parsed and were left out of the lists above (each also has a warning, while the warning
    /// list is not full).
    std::vector<long> skippedLines;
    /// Non-empty when the block cannot be used as a pass ("FILE:LINE: why": an H4 without a valid
    /// start date-time or data type, or no readable range record). Its lines are kept for writing
    /// back, its parsed lists are empty; the reader warns about it and reads the other passes.
    std::string problem;

    /// MJD of the H4 start date (0h UTC): epochs are measured from it.
    long startMjd() const;
    /// Seconds since 0h UTC of the H4 start day for a record's seconds-of-day: adds 86 400 s
    /// when the pass crossed midnight (secOfDay more than 12 h before the H4 start time).
    double passSeconds(double secOfDay) const;
    /// C0 record for a system configuration id, or nullptr (ids compare case-insensitively).
    const CrdSystemConfig* config(const std::string& systemId) const;
};

/// Every line of a pass in its order (records and rangeLines merged), as records. Empty, with
/// *error, when its type-10 lines cannot be read back from their file.
std::vector<CrdRecord> allRecords(const CrdPass& pass, std::string* error = nullptr);
/// The pass's lines from `lines` (every line in order, as allRecords gives them): type-10 ones
/// into rangeLines, the others into records.
void setAllRecords(CrdPass* pass, std::vector<CrdRecord> lines);

struct CrdFile {
    std::string path;                ///< as given to the reader ("" for text)
    std::vector<CrdPass> passes;
    std::vector<CrdRecord> trailer;  ///< lines after the last pass (H9, comments)
    bool crlf = false;               ///< the source used CRLF line ends
};

struct CrdReadParams {
    size_t maxWarnings = 500;        ///< further warnings are counted in one closing line (>= 1)
};

struct CrdReadResult {
    bool ok = false;
    std::string error;               ///< "FILE:LINE: what is wrong"
    std::vector<std::string> warnings;
    CrdFile file;
};

std::string validate(const CrdReadParams& p);

/// A CRD field that says "not available": "na" in any case, signed or not.
bool isCrdNa(std::string_view field);

/// Parses CRD text; `source` names it in messages. Never throws.
CrdReadResult parseCrd(std::string_view text, const std::string& source, const CrdReadParams& params = {},
                       const Feedback* feedback = nullptr);
/// A CRD file read pass by pass (streamCrd): what is known of the whole file at the end.
struct CrdStreamResult {
    bool ok = false;                 ///< the file was read to its end (some passes may have problems)
    std::string error;               ///< "FILE:LINE: what is wrong", as readCrd's
    std::vector<std::string> warnings;  ///< the reader's, for the whole file (passes' included)
    size_t passes = 0;               ///< passes handed out
};

/// Reads a CRD file pass by pass, holding one pass at a time (the memory of the largest pass,
/// not of the file: a station's daily or monthly file of many passes). First one read through
/// the file counts its passes (H4 records) and calls begin(count); then each pass, parsed as
/// readCrd parses it (its `problem` set when it cannot be used, `ordinal` its place), is moved
/// to onPass as soon as it closes and dropped after. begin or onPass returning false stops the
/// read (error "cancelled"). Gzip and "-" as readCrd (the standard input is held whole). Never
/// throws.
CrdStreamResult streamCrd(const std::string& path, const CrdReadParams& params, const Feedback* feedback,
                          const std::function<bool(size_t passCount)>& begin,
                          const std::function<bool(CrdPass&& pass)>& onPass);

/// Reads and parses a CRD file.
CrdReadResult readCrd(const std::string& path, const CrdReadParams& params = {}, const Feedback* feedback = nullptr);

/// The file as text: every record of every pass, then the trailer. False (*error) when a
/// pass's type-10 lines cannot be read back from their file (it changed since it was read).
bool formatCrd(const CrdFile& file, std::string* out, std::string* error);
/// formatCrd for a file held in memory (parseCrd's): "" when a pass's lines cannot be read back.
std::string formatCrd(const CrdFile& file);
/// One pass as a file of its own, as every product of a pass is written (the flagged block, its
/// normal points; one pass or a station's file of passes alike): the pass's records, the line
/// ends of the file it came from, and an H9 written in the case of the pass's own H4 ("h4" ->
/// "h9"). Built from the pass alone, so a pass read whole or streamed gives the same bytes.
CrdFile passAlone(const CrdPass& pass);
/// The H9 of passAlone (its case from the pass's H4).
CrdRecord trailerFor(const CrdPass& pass);
/// Writes formatCrd(file) atomically. False with *error on failure.
bool writeCrd(const std::string& path, const CrdFile& file, std::string* error);

/// Writes formatCrd(file) (alone: formatCrd(passAlone(pass))) with the filter flags of pass
/// `passIndex`'s type-10 records set to `flags` as setFilterFlags sets them, streamed to a
/// temporary renamed over `path` when complete: neither the file nor its text is copied (a
/// flagged pass of 10^7 events cost two copies of its lines). False with *error, nothing written.
bool writeCrdWithFlags(const std::string& path, const CrdFile& file, size_t passIndex, const std::vector<int>& flags,
                       bool alone, std::string* error);
/// Sets the filter flag (0 unknown, 1 noise, 2 data) of every type-10 record of the pass, in
/// order; flags.size() must equal pass->ranges.size(). Only the flag field of each line changes.
bool setFilterFlags(CrdPass* pass, const std::vector<int>& flags, std::string* error);

/// A type-11 line for a normal point (CRD v2.01 field order; v1 when version < 2: no SNR, and
/// -1 for absent values since v1 has no "na").
std::string formatNormalPointRecord(const CrdNormalPoint& np, int version = 2);

enum class NormalPointMode { Replace, Append };

/// Replaces the pass's type-11 records with `nps` (at the place of the first old one, else
/// before the H8) or appends them after the last type-11 record. Re-parses the pass.
bool setNormalPoints(CrdPass* pass, const std::vector<CrdNormalPoint>& nps, NormalPointMode mode, std::string* error);

/// A normal-point pass made from a full-rate one: same headers (H4 data type set to 1),
/// configurations, met and calibration records, comments; no 10/12/30/42/9x records; the
/// given normal points before the H8. Inherited H1..H3 are written into the new pass. With no
/// normal points, `product.noneReason` (required then) goes before the H8 as a "00" comment
/// record: a pass that forms none still has its file, saying why.
struct NormalPointProduct {
    std::string noneReason;
    /// A record 50 (session statistics) after the normal points: RMS (ps) of the residuals about
    /// the trend, skew, excess kurtosis, peak - mean (ps), data quality (0 undefined, 1 clear
    /// data with little noise, 2 clear with much noise, 3 unclear).
    bool session = false;
    double rmsPs = NAN, skew = NAN, kurtosis = NAN, peakMinusMeanPs = NAN;
    int quality = 0;
    /// The H1's production date (year > 0): the file is a new product, not the station's.
    int year = 0, month = 0, day = 0, hour = 0;
    /// CRD v2: a C5 software record "C5 0 ID na na laserwb VERSION" after the last C record.
    std::string softwareVersion;
};
bool makeNormalPointPass(const CrdPass& fullRate, const std::vector<CrdNormalPoint>& nps, CrdPass* out,
                         std::string* error, const NormalPointProduct& product = {});

}  // namespace lwb::core::slr
