#include "core/footprint/segment.hpp"
#include "core/common/select.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lwb::core::footprint {

namespace {
// Flood fill of the pixels where in[] is nonzero, from the seeds on the stack, into out[]
// (set to 1). Stack entries are packed (y << 16 | x) so no division is needed.
// eight: 8-connectivity (the spot domain) or 4 (its complement, when looking for holes).
void flood(const unsigned char* in, int w, int h, bool eight, std::vector<int>& stack, unsigned char* out,
           std::vector<int>* pixels) {
    while (!stack.empty()) {
        const int packed = stack.back();
        stack.pop_back();
        const int x = packed & 0xFFFF, y = packed >> 16;
        if (pixels) pixels->push_back(y * w + x);
        const int xa = x > 0 ? x - 1 : 0, xb = x < w - 1 ? x + 1 : x, ya = y > 0 ? y - 1 : 0, yb = y < h - 1 ? y + 1 : y;
        for (int ny = ya; ny <= yb; ++ny)
            for (int nx = xa; nx <= xb; ++nx) {
                if (!eight && nx != x && ny != y) continue;
                const int q = ny * w + nx;
                if (in[q] && !out[q]) {
                    out[q] = 1;
                    stack.push_back(ny << 16 | nx);
                }
            }
    }
}

// Square min (erode) or max (dilate) filter of radius r on a 0/1 mask; outside counts as 0.
// ROIs up to 64 px wide hold each row in one 64-bit word (bit x = column x), so a filter pass is
// a few shifts per row; wider ones go pixel by pixel.
using BitRows = std::vector<uint64_t>;

BitRows toBits(const std::vector<unsigned char>& m, int w, int h) {
    BitRows rows(static_cast<size_t>(h));
    for (int y = 0; y < h; ++y) {
        uint64_t bits = 0;
        for (int x = 0; x < w; ++x) bits |= uint64_t(m[size_t(y) * w + x] != 0) << x;
        rows[y] = bits;
    }
    return rows;
}

BitRows morphBits(const BitRows& rows, int w, int h, int r, bool erode) {
    const uint64_t full = w == 64 ? ~uint64_t(0) : (uint64_t(1) << w) - 1;
    BitRows horiz(static_cast<size_t>(h)), out(static_cast<size_t>(h));
    // Shifts of 64 and more are undefined, and a row is at most 64 px: shifts up to 63 reach all of it.
    const int rx = std::min(r, 63);
    for (int y = 0; y < h; ++y) {
        uint64_t v = rows[y];
        for (int k = 1; k <= rx; ++k) {
            const uint64_t left = (rows[y] >> k), right = (rows[y] << k) & full;
            v = erode ? (v & left & right) : (v | left | right);
        }
        horiz[y] = v;
    }
    for (int y = 0; y < h; ++y) {
        uint64_t v = horiz[y];
        for (int k = 1; k <= r; ++k) {
            const uint64_t up = y - k >= 0 ? horiz[y - k] : 0, down = y + k < h ? horiz[y + k] : 0;
            v = erode ? (v & up & down) : (v | up | down);
        }
        out[y] = v;
    }
    return out;
}

std::vector<unsigned char> morph(const std::vector<unsigned char>& m, int w, int h, int r, bool erode) {
    std::vector<unsigned char> rows(m.size()), out(m.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            unsigned char v = erode ? 1 : 0;
            for (int k = -r; k <= r; ++k) {
                const int xx = x + k;
                const unsigned char s = (xx < 0 || xx >= w) ? 0 : m[size_t(y) * w + xx];
                v = erode ? (v & s) : (v | s);
            }
            rows[size_t(y) * w + x] = v;
        }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            unsigned char v = erode ? 1 : 0;
            for (int k = -r; k <= r; ++k) {
                const int yy = y + k;
                const unsigned char s = (yy < 0 || yy >= h) ? 0 : rows[size_t(yy) * w + x];
                v = erode ? (v & s) : (v | s);
            }
            out[size_t(y) * w + x] = v;
        }
    return out;
}

// Cuts thin bright ground features (roads, field edges) that touch the spot out of the
// threshold mask: a morphological opening (erode, then dilate back) keeps only parts at least
// 2r+1 px wide; the pixels of the original mask within r of what survives are kept. If the
// peak itself does not survive (a spot thinner than the opening), the mask is left alone.
void openAroundPeak(std::vector<unsigned char>& above, int w, int h, int r, int px, int py) {
    const bool bits = w <= 64;  // the whole opening on bit rows, converted once each way
    BitRows erodedBits;
    std::vector<unsigned char> eroded;
    if (bits) erodedBits = morphBits(toBits(above, w, h), w, h, r, true);
    else eroded = morph(above, w, h, r, true);
    auto isEroded = [&](int x, int y) {
        return bits ? ((erodedBits[y] >> x) & 1) != 0 : eroded[size_t(y) * w + x] != 0;
    };
    if (!isEroded(px, py)) {
        bool any = false;  // the peak may sit on a 1-px crest of the eroded core: look around it
        for (int dy = -r; dy <= r && !any; ++dy)
            for (int dx = -r; dx <= r && !any; ++dx) {
                const int x = px + dx, y = py + dy;
                any = x >= 0 && y >= 0 && x < w && y < h && isEroded(x, y);
            }
        if (!any) return;
    }
    if (bits) {
        const BitRows kept = morphBits(morphBits(erodedBits, w, h, r, false), w, h, 1, false);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) above[size_t(y) * w + x] &= static_cast<unsigned char>((kept[y] >> x) & 1);
    } else {
        const std::vector<unsigned char> kept = morph(morph(eroded, w, h, r, false), w, h, 1, false);
        for (size_t i = 0; i < above.size(); ++i) above[i] = above[i] && kept[i];
    }
    above[size_t(py) * w + px] = 1;
}

// The peak against a ring r0..r1 px around (px, py): (peak − the ring's median) over the ring's
// robust σ (ring), and over its pixel-scale texture σ — the robust σ of the ring's horizontal
// neighbour differences / √2 (texture) — which large bright and dark areas crossing the ring
// do not inflate. Both 0 when the ring holds too few pixels inside the ROI.
struct RingLook {
    double ring = 0, texture = 0;
};
RingLook ringPeakSnr(const float* img, int w, int h, int px, int py, double peak, double r0, double r1) {
    thread_local std::vector<float> ring, diff;
    ring.clear();
    diff.clear();
    const int R = static_cast<int>(std::ceil(r1));
    const int xa = std::max(0, px - R), xb = std::min(w - 1, px + R);
    for (int y = std::max(0, py - R); y <= std::min(h - 1, py + R); ++y)
        for (int x = xa; x <= xb; ++x) {
            const double r2 = double(x - px) * (x - px) + double(y - py) * (y - py);
            if (r2 < r0 * r0 || r2 > r1 * r1) continue;
            ring.push_back(img[y * w + x]);
            if (x + 1 < w) diff.push_back(std::fabs(img[y * w + x + 1] - img[y * w + x]));
        }
    RingLook out;
    if (ring.size() < 24 || diff.size() < 24) return out;
    const size_t mid = ring.size() / 2;
    const double median = kthSmallest(ring, mid);
    for (float& v : ring) v = static_cast<float>(std::fabs(v - median));
    out.ring = (peak - median) / std::max(1.4826 * kthSmallest(ring, mid), 0.5);
    out.texture = (peak - median) / std::max(1.4826 * kthSmallest(diff, diff.size() / 2) / std::sqrt(2.0), 0.5);
    return out;
}

// std::max_element's index, in two passes without a data-dependent branch in the first (the
// largest value; NaN is never taken, as there) and an early exit in the second.
int firstMaxIndex(const float* v, int n) {
    float m = v[0];
    for (int i = 1; i < n; ++i) m = v[i] > m ? v[i] : m;
    for (int i = 0; i < n; ++i)
        if (v[i] == m) return i;
    return 0;  // v[0] is NaN: max_element keeps the first element
}

// Box mean over (2r+1)² with replicated borders.
void boxSmooth(const float* src, int w, int h, int r, float* dst) {
    std::vector<float> rows(size_t(w) * h);
    // Each sum is taken in the order k = −r..r; the loops over x (inner) vectorise.
    const int xa = std::min(r, w), xb = std::max(xa, w - r);  // interior: x + k inside the row
    for (int y = 0; y < h; ++y) {
        const float* s = src + size_t(y) * w;
        float* o = rows.data() + size_t(y) * w;
        for (int x = 0; x < w; ++x) o[x] = 0;
        for (int k = -r; k <= r; ++k) {
            for (int x = 0; x < xa; ++x) o[x] += s[std::clamp(x + k, 0, w - 1)];
            for (int x = xa; x < xb; ++x) o[x] += s[x + k];
            for (int x = xb; x < w; ++x) o[x] += s[std::clamp(x + k, 0, w - 1)];
        }
    }
    const float norm = 1.0f / float((2 * r + 1) * (2 * r + 1));
    for (int y = 0; y < h; ++y) {
        float* o = dst + size_t(y) * w;
        for (int x = 0; x < w; ++x) o[x] = 0;
        for (int k = -r; k <= r; ++k) {
            const float* s = rows.data() + size_t(std::clamp(y + k, 0, h - 1)) * w;
            for (int x = 0; x < w; ++x) o[x] += s[x];
        }
        for (int x = 0; x < w; ++x) o[x] *= norm;
    }
}
}  // namespace

namespace {

// Holes: non-domain pixels that no 4-connected path of non-domain pixels joins to the outside,
// added to the domain. Only the domain's bounding box (plus a 1 px margin) can hold any.
void fillDomainHoles(int w, int h, std::vector<int>& stack, SpotDomain& d) {
    int bx0 = w, by0 = h, bx1 = -1, by1 = -1;
    for (int p : d.pixels) {
        bx0 = std::min(bx0, p % w);
        bx1 = std::max(bx1, p % w);
        by0 = std::min(by0, p / w);
        by1 = std::max(by1, p / w);
    }
    bx0 = std::max(0, bx0 - 1);
    by0 = std::max(0, by0 - 1);
    bx1 = std::min(w - 1, bx1 + 1);
    by1 = std::min(h - 1, by1 + 1);
    const int bw = bx1 - bx0 + 1, bh = by1 - by0 + 1;
    std::vector<unsigned char> notDomain(size_t(bw) * bh), outside(size_t(bw) * bh, 0);
    for (int y = 0; y < bh; ++y)
        for (int x = 0; x < bw; ++x) notDomain[size_t(y) * bw + x] = !d.mask[size_t(y + by0) * w + x + bx0];
    auto seed = [&](int x, int y) {
        const int q = y * bw + x;
        if (notDomain[q] && !outside[q]) {
            outside[q] = 1;
            stack.push_back(y << 16 | x);
        }
    };
    for (int x = 0; x < bw; ++x) {
        seed(x, 0);
        seed(x, bh - 1);
    }
    for (int y = 0; y < bh; ++y) {
        seed(0, y);
        seed(bw - 1, y);
    }
    flood(notDomain.data(), bw, bh, false, stack, outside.data(), nullptr);
    for (int y = 0; y < bh; ++y)
        for (int x = 0; x < bw; ++x)
            if (notDomain[size_t(y) * bw + x] && !outside[size_t(y) * bw + x]) {
                const int i = (y + by0) * w + x + bx0;
                d.mask[i] = 1;
                d.pixels.push_back(i);
            }
}

// Second spot: a local maximum of the smoothed image, away from the main peak, with a dip
// between the two (a shoulder on the same spot has none). The highest such is kept.
void findSecondSpot(const cv::Mat& smooth, double background, double amp, const SegmentParams& params, SpotDomain& d) {
    const int w = smooth.cols, h = smooth.rows;
    const float* sm = smooth.ptr<float>();
    const double minSep2 = params.secondSpotMinSeparation * params.secondSpotMinSeparation;
    float floorValue = static_cast<float>(background + 0.15 * amp);  // candidates must reach this
    for (int y = 1; y < h - 1; ++y)
        for (int x = 1; x < w - 1; ++x) {
            const float v = sm[y * w + x];
            if (v <= floorValue) continue;
            const double ddx = x - d.peakX, ddy = y - d.peakY;
            if (ddx * ddx + ddy * ddy < minSep2) continue;
            const float* c = sm + y * w + x;
            if (c[-w - 1] > v || c[-w] > v || c[-w + 1] > v || c[-1] > v || c[1] > v || c[w - 1] > v || c[w] > v ||
                c[w + 1] > v)
                continue;  // not a local maximum
            const int steps = static_cast<int>(std::ceil(std::sqrt(ddx * ddx + ddy * ddy)));
            double lowest = v;
            for (int k = 1; k < steps; ++k) {
                const int px = static_cast<int>(std::lround(d.peakX + ddx * k / steps));
                const int py = static_cast<int>(std::lround(d.peakY + ddy * k / steps));
                lowest = std::min<double>(lowest, sm[py * w + px]);
            }
            if (lowest - background > 0.8 * (v - background)) continue;  // no real dip
            d.secondPeakFraction = (v - background) / amp;
            d.secondPeakX = x;
            d.secondPeakY = y;
            floorValue = v;
        }
}

}  // namespace

SpotDomain segmentSpot(const cv::Mat& roi, double background, double noise, double saturationDn,
                       const SegmentParams& params) {
    SpotDomain d;
    const int w = roi.cols, h = roi.rows;
    d.width = w;
    d.height = h;
    // Box-smoothed copy (replicated borders) to take the peak from.
    cv::Mat smooth(h, w, CV_32F);
    if (params.peakSmooth > 1)
        boxSmooth(roi.ptr<float>(), w, h, params.peakSmooth / 2, smooth.ptr<float>());
    else
        roi.copyTo(smooth);
    const float* smp = smooth.ptr<float>();
    const int maxIndex = firstMaxIndex(smp, w * h);
    const double maxV = smp[maxIndex];
    const cv::Point maxP(maxIndex % w, maxIndex / w);
    d.peakX = maxP.x;
    d.peakY = maxP.y;
    d.peak = maxV;
    const double amp = maxV - background;
    d.peakSnr = amp / std::max(noise, 1e-9);
    // On ground with large bright and dark areas (fields, roofs) the ROI-wide σ holds their
    // spread, and a plain spot can sit less than minPeakSnr of it above the median. A peak from
    // localLookFrom·minPeakSnr up gets a second look against a ring around it: it passes when it
    // stands localSnrFloor·minPeakSnr of the ring's robust σ above the ring's median, or — the
    // ring's σ can itself hold a bright field and a dark one — textureSnr σ of the ring's
    // pixel-scale texture. A peak that passes is kept as a faint spot, which the verdict marks
    // doubtful: a visible spot gets a position, an empty ROI is never called good.
    if (amp > 0 && d.peakSnr < params.minPeakSnr && d.peakSnr >= params.localLookFrom * params.minPeakSnr) {
        const RingLook look = ringPeakSnr(roi.ptr<float>(), w, h, maxP.x, maxP.y, maxV, params.ringInnerPx,
                                          params.ringOuterPx);
        d.localPeakSnr = look.ring;
        d.localTextureSnr = look.texture;
        d.faint = look.ring >= params.localSnrFloor * params.minPeakSnr || look.texture >= params.textureSnr;
    }
    if (amp <= 0 || (d.peakSnr < params.minPeakSnr && !d.faint)) {
        d.why = "no spot: peak only " + std::to_string(d.peakSnr).substr(0, 5) + " sigma above the background";
        return d;
    }
    d.threshold = background + params.thresholdFactor * amp;
    const float* img = roi.ptr<float>();
    std::vector<unsigned char> above(size_t(w) * h);
    for (int i = 0; i < w * h; ++i) above[i] = img[i] > d.threshold;
    // The peak of the smoothed image may sit on a raw pixel just under threshold: include it.
    above[d.peakY * w + d.peakX] = 1;
    if (params.openingRadius > 0) openAroundPeak(above, w, h, params.openingRadius, d.peakX, d.peakY);
    d.mask.assign(size_t(w) * h, 0);
    std::vector<int> stack;
    stack.reserve(size_t(w) * h);
    stack.push_back(d.peakY << 16 | d.peakX);
    d.mask[d.peakY * w + d.peakX] = 1;
    d.pixels.reserve(size_t(w) * h / 4);
    flood(above.data(), w, h, true, stack, d.mask.data(), &d.pixels);
    if (params.fillHoles) fillDomainHoles(w, h, stack, d);
    if (static_cast<int>(d.pixels.size()) < params.minPixels) {
        d.why = "no spot: domain of only " + std::to_string(d.pixels.size()) + " px above the threshold";
        return d;
    }
    for (int p : d.pixels) {
        const int x = p % w, y = p / w;
        if (x == 0 || y == 0 || x == w - 1 || y == h - 1) d.touchesBorder = true;
        if (img[p] >= saturationDn) ++d.saturatedPixels;
    }
    findSecondSpot(smooth, background, amp, params, d);
    d.found = true;
    return d;
}

}  // namespace lwb::core::footprint
