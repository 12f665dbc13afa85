#pragma once
// SLR O-C residuals as a sparse binary image (paper 004 §3.1–3.2, steps 1–2): each point
// (t, O-C) maps to the pixel (round(t·mag_T), round(O-C·mag_OC)); the coordinates are shifted
// to start at 0; every pixel keeps ALL the indices of the points that fall on it (the paper's
// "index matrix"); occupied pixels are labelled into 4- or 8-connected regions.
//
// The image is never allocated: a 3000 s pass at mag_T 10 and a 1 µs gate at mag_OC 1e10 is a
// 30 000 × 10 000 image, but only the occupied pixels (at most one per point) are stored,
// sorted by (row, col), and labelled with a union-find over that sorted list, so time is
// O(n log n) and memory O(n) in the number of points, whatever the magnification.
//
// Orientation follows the paper: row = time (t·mag_T), col = O-C (O-C·mag_OC). The paper's
// example (478.64358053542 s, 7.986e-8 s) at mag_T 1, mag_OC 1e7 is pixel (479, 1) before the shift.
#include <cstdint>
#include <string>
#include <vector>

#include "core/common/feedback.hpp"

namespace lwb::core::slr {

struct MappingParams {
    double magT = 10;      ///< pixels per second of epoch, (0, 1e15]; paper table 1: 10 conventional, 1 diffuse
    double magOc = 1e10;   ///< pixels per second of O-C (two-way), (0, 1e18]; paper: 1e10 conventional, 1e7 diffuse
    int connectivity = 8;  ///< 4 or 8 (paper §3.2.1: high echo rate → 4, low → 8)
};

/// Empty when the parameters are usable, else what is wrong (NaN, ≤ 0, absurd, connectivity not 4/8).
std::string validate(const MappingParams& p);

/// One connected region of occupied pixels (paper §3.2.1: area and centroid; plus box and points).
struct Region {
    int64_t area = 0;          ///< pixels
    int64_t points = 0;        ///< points on those pixels (≥ area: several points may share a pixel)
    double row = 0, col = 0;   ///< centroid of the region's pixels (unweighted, shifted pixel units)
    int64_t rowMin = 0, rowMax = 0, colMin = 0, colMax = 0;  ///< bounding box (inclusive)
};

/// Pixel coordinates after the shift (never negative): 32-bit when every one fits, else 64-bit
/// (absurd magnifications). A kHz pass's image has about one pixel an event: the two 64-bit
/// columns were 16 of its bytes an event (issue 44).
class PixelCoords {
public:
    void reset(size_t capacity, bool wide) {
        m_wide = wide;
        m_narrow = {};
        m_wideValues = {};
        if (wide) m_wideValues.reserve(capacity);
        else m_narrow.reserve(capacity);
    }
    void push_back(int64_t v) {
        if (m_wide) m_wideValues.push_back(v);
        else m_narrow.push_back(static_cast<uint32_t>(v));
    }
    int64_t operator[](size_t i) const { return m_wide ? m_wideValues[i] : static_cast<int64_t>(m_narrow[i]); }
    size_t size() const { return m_wide ? m_wideValues.size() : m_narrow.size(); }
    bool empty() const { return size() == 0; }
    bool wide() const { return m_wide; }
    const uint32_t* narrowData() const { return m_narrow.data(); }
    const int64_t* wideData() const { return m_wideValues.data(); }
    bool operator==(const PixelCoords& o) const {
        if (size() != o.size()) return false;
        for (size_t i = 0; i < size(); ++i)
            if ((*this)[i] != o[i]) return false;
        return true;
    }

private:
    bool m_wide = false;
    std::vector<uint32_t> m_narrow;
    std::vector<int64_t> m_wideValues;
};

/// The regions of an image, in label order, kept small: at 64 bytes a Region they were 38 bytes
/// an event of a raw kHz pass's screening, its largest block (issue 44). A region of one pixel
/// holding at most 255 points is its pixel and its point count (13 bytes, 21 with 64-bit
/// coordinates); any other is a whole region of 32-bit fields (40 bytes; a Region of 64 where
/// the coordinates need 64 bits). operator[] gives the same Region either way.
class RegionList {
public:
    RegionList() = default;
    /// Any regions (tests, synthetic input).
    RegionList(const std::vector<Region>& regions);  // NOLINT: implicit, as the vector it replaced

    size_t size() const { return m_slot.size(); }
    bool empty() const { return m_slot.empty(); }
    Region operator[](size_t i) const;
    int64_t area(size_t i) const;
    int64_t rowMin(size_t i) const;

    /// n regions of which `whole` are more than one pixel (capacity hints); wide: coordinates
    /// may need 64 bits (as the image's PixelCoords).
    void reserve(size_t n, size_t whole, bool wide);
    /// A new region of the one pixel (row, col) holding `points` points.
    void addPixel(int64_t row, int64_t col, int64_t points);
    /// The pixel (row, col) holding `points` points joins region i (its centroid a sum until finish()).
    void addToRegion(size_t i, int64_t row, int64_t col, int64_t points);
    /// Once every pixel is added: the centroids from their sums.
    void finish();
    void push_back(const Region& r);

    class const_iterator {
    public:
        const_iterator(const RegionList* l, size_t i) : m_l(l), m_i(i) {}
        Region operator*() const { return (*m_l)[m_i]; }
        const_iterator& operator++() {
            ++m_i;
            return *this;
        }
        bool operator!=(const const_iterator& o) const { return m_i != o.m_i; }
        bool operator==(const const_iterator& o) const { return m_i == o.m_i; }

    private:
        const RegionList* m_l;
        size_t m_i;
    };
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size()}; }

private:
    struct Whole32 {
        double row = 0, col = 0;
        uint32_t area = 0, points = 0;
        uint32_t rowMin = 0, rowMax = 0, colMin = 0, colMax = 0;
    };
    static constexpr uint32_t kPixel = UINT32_MAX;
    void makeWhole(size_t i, const Region& r);
    void widen();
    std::vector<uint32_t> m_slot;   ///< per region: index of its whole region, or kPixel
    PixelCoords m_row, m_col;       ///< per region: its pixel when it is one (else unused)
    std::vector<uint8_t> m_points;  ///< per region: its points when it is one pixel
    std::vector<Whole32> m_whole32; ///< whole regions of a 32-bit list
    std::vector<Region> m_whole64;  ///< whole regions of a 64-bit list
};

struct BinaryImage {
    bool ok = false;
    std::string error;
    std::vector<std::string> warnings;
    MappingParams params;      ///< the mapping and connectivity used
    int64_t rowOffset = 0;     ///< unshifted row of shifted row 0 (= min round(t·mag_T))
    int64_t colOffset = 0;     ///< unshifted col of shifted col 0 (= min round(O-C·mag_OC))
    int64_t rows = 0, cols = 0;  ///< extent of the (never allocated) image after the shift
    // Occupied pixels, sorted by (row, col); shifted coordinates.
    PixelCoords pixelRow, pixelCol;
    std::vector<uint32_t> pixelRegion;      ///< region label of each pixel (index into regions)
    std::vector<uint32_t> pixelPointStart;  ///< CSR: points of pixel p are pixelPoints[start[p] .. start[p+1])
    std::vector<uint32_t> pixelPoints;      ///< point indices grouped by pixel (the paper's index matrix)
    RegionList regions;                     ///< labelled in order of their first pixel in (row, col) order

    size_t pixelCount() const { return pixelRow.size(); }
};

/// The pixel of each point (the index matrix inverted), made on demand: nothing in the
/// screening needs it, and kept in the image it was 4 bytes an event of a kHz pass's peak.
std::vector<uint32_t> pointPixels(const BinaryImage& img);

/// Step 1 for one point: the unshifted pixel (row = round(t·mag_T), col = round(O-C·mag_OC)).
/// False when a product is not finite or exceeds ±2^61 (the caller reports it).
bool mapPoint(double t, double oc, double magT, double magOc, int64_t* row, int64_t* col);

/// Steps 1–2: maps the points (epochs t and O-C in seconds, same length), shifts to 0, keeps
/// the index matrix and labels the regions. Errors (ok = false): lengths differ, a non-finite
/// value (names the point), invalid params, more than 2^32 − 2 points, or a magnification whose
/// pixel coordinates overflow ±2^61 (it fails at once, before any allocation). Zero points give
/// an empty, valid image. Polls fb (cancel → ok = false, error "cancelled").
BinaryImage buildBinaryImage(const std::vector<double>& t, const std::vector<double>& oc, const MappingParams& params,
                             const Feedback* fb = nullptr);

/// The areas (pixels) of the regions buildBinaryImage() would find, in no particular order, and
/// nothing else: the same pixels and links at a fraction of the cost (no index matrix, no
/// region statistics, no 64-bit sort when the points come in time order). Empty when the
/// parameters are invalid, a point is not finite or maps beyond 2^61, or there are no points.
std::vector<int64_t> regionAreas(const std::vector<double>& t, const std::vector<double>& oc, const MappingParams& params);

}  // namespace lwb::core::slr
