#include "core/common/image_header.hpp"

#include <cctype>
#include <cstdint>

namespace lwb::core {

namespace {

class Bytes {
public:
    Bytes(std::string_view b, bool bigEndian) : m_b(b), m_be(bigEndian) {}
    bool has(size_t off, size_t n) const { return off <= m_b.size() && n <= m_b.size() - off; }
    uint64_t get(size_t off, size_t n) const {  // caller checked has(off, n)
        uint64_t v = 0;
        for (size_t i = 0; i < n; ++i) {
            const uint64_t byte = static_cast<unsigned char>(m_b[off + (m_be ? i : n - 1 - i)]);
            v = (v << 8) | byte;
        }
        return v;
    }

private:
    std::string_view m_b;
    bool m_be;
};

void png(std::string_view b, ImageHeader* h) {
    h->format = "PNG";
    const Bytes r(b, true);
    if (!r.has(16, 8) || b.substr(12, 4) != "IHDR") return;
    h->width = static_cast<long long>(r.get(16, 4));
    h->height = static_cast<long long>(r.get(20, 4));
    h->complete = true;
}

void tiff(std::string_view b, ImageHeader* h) {
    h->format = "TIFF";
    const bool be = b[0] == 'M';
    const Bytes r(b, be);
    const bool big = r.get(2, 2) == 43;  // BigTIFF
    if (big && !r.has(8, 8)) return;
    const uint64_t ifd = big ? r.get(8, 8) : r.get(4, 4);
    const size_t countSize = big ? 8 : 2, entrySize = big ? 20 : 12, valueOff = big ? 12 : 8;
    if (ifd > b.size() || !r.has(static_cast<size_t>(ifd), countSize)) return;
    const uint64_t n = r.get(static_cast<size_t>(ifd), countSize);
    bool haveW = false, haveH = false;
    for (uint64_t k = 0; k < n && k < 4096; ++k) {
        const size_t e = static_cast<size_t>(ifd) + countSize + static_cast<size_t>(k) * entrySize;
        if (!r.has(e, entrySize)) return;
        const uint64_t tag = r.get(e, 2), type = r.get(e + 2, 2);
        if (tag != 256 && tag != 257) continue;
        // SHORT (3) or LONG (4) or LONG8 (16), left-justified in the value field.
        // The value must fit the entry's value field (4 bytes in classic TIFF, 8 in BigTIFF):
        // a LONG8 in a classic TIFF does not, and its read ran past the entry (and the buffer).
        const size_t width = type == 3 ? 2 : type == 4 ? 4 : type == 16 ? 8 : 0;
        if (width == 0 || valueOff + width > entrySize) return;
        const long long v = static_cast<long long>(r.get(e + valueOff, width));
        if (tag == 256) h->width = v, haveW = true;
        else h->height = v, haveH = true;
    }
    h->complete = haveW && haveH;
}

void pnm(std::string_view b, ImageHeader* h) {
    h->format = "PNM";
    size_t i = 2;
    long long v[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        for (;;) {  // blanks and # comments
            while (i < b.size() && std::isspace(static_cast<unsigned char>(b[i]))) ++i;
            if (i < b.size() && b[i] == '#') {
                while (i < b.size() && b[i] != '\n') ++i;
                continue;
            }
            break;
        }
        const size_t start = i;
        while (i < b.size() && std::isdigit(static_cast<unsigned char>(b[i])) && v[k] < (1LL << 40))
            v[k] = v[k] * 10 + (b[i++] - '0');
        if (i == start) return;
    }
    h->width = v[0];
    h->height = v[1];
    h->complete = true;
}

void jpeg(std::string_view b, ImageHeader* h) {
    h->format = "JPEG";
    const Bytes r(b, true);
    size_t i = 2;
    while (r.has(i, 4)) {
        if (static_cast<unsigned char>(b[i]) != 0xFF) return;
        const unsigned m = static_cast<unsigned char>(b[i + 1]);
        if (m == 0xFF) {  // fill byte
            ++i;
            continue;
        }
        if (m == 0xD8 || m == 0x01 || (m >= 0xD0 && m <= 0xD7)) {  // markers without a length
            i += 2;
            continue;
        }
        const size_t len = static_cast<size_t>(r.get(i + 2, 2));
        const bool sof = m >= 0xC0 && m <= 0xCF && m != 0xC4 && m != 0xC8 && m != 0xCC;
        if (sof) {
            if (!r.has(i + 5, 4)) return;
            h->height = static_cast<long long>(r.get(i + 5, 2));
            h->width = static_cast<long long>(r.get(i + 7, 2));
            h->complete = true;
            return;
        }
        if (len < 2) return;
        i += 2 + len;
    }
}

}  // namespace

ImageHeader readImageHeader(std::string_view b) {
    ImageHeader h;
    if (b.size() >= 8 && b.substr(0, 8) == std::string_view("\x89PNG\r\n\x1a\n", 8)) {
        h.recognised = true;
        png(b, &h);
    } else if (b.size() >= 8 && (b.substr(0, 4) == std::string_view("II*\0", 4) || b.substr(0, 4) == std::string_view("MM\0*", 4) ||
                                 b.substr(0, 4) == std::string_view("II+\0", 4) || b.substr(0, 4) == std::string_view("MM\0+", 4))) {
        h.recognised = true;
        tiff(b, &h);
    } else if (b.size() >= 2 && b[0] == 'P' && b[1] >= '1' && b[1] <= '6') {
        h.recognised = true;
        pnm(b, &h);
    } else if (b.size() >= 3 && static_cast<unsigned char>(b[0]) == 0xFF && static_cast<unsigned char>(b[1]) == 0xD8 &&
               static_cast<unsigned char>(b[2]) == 0xFF) {
        h.recognised = true;
        jpeg(b, &h);
    }
    return h;
}

namespace {
// A PNG's chunks walked from the signature to IEND (length, type, data, CRC each): "" when the
// file holds them whole, else where it ends. The decoder was handed a truncated file and said
// "unknown format" with libpng's own "Read Error" on stderr (issue 42).
std::string pngTruncation(std::string_view b) {
    size_t at = 8;  // after the signature
    while (at + 8 <= b.size()) {
        const auto u = [&](size_t i) { return static_cast<uint32_t>(static_cast<unsigned char>(b[i])); };
        const uint64_t length = (u(at) << 24) | (u(at + 1) << 16) | (u(at + 2) << 8) | u(at + 3);
        const std::string type(b.substr(at + 4, 4));
        const uint64_t end = at + 12 + length;
        if (end > b.size())
            return "truncated PNG: the file ends inside its " + type + " chunk (" + std::to_string(b.size()) + " bytes, the chunk needs " +
                   std::to_string(end) + ")";
        if (type == "IEND") return {};
        at = static_cast<size_t>(end);
    }
    return "truncated PNG: the file ends after " + std::to_string(b.size()) + " bytes without the IEND chunk";
}
}  // namespace

std::string imageSizeProblem(std::string_view bytes, const std::string& source, long long maxPixels) {
    const ImageHeader h = readImageHeader(bytes);
    if (!h.recognised) return source + ": not a readable image (no PNG, TIFF, PGM or JPEG signature)";
    if (!h.complete) return source + ": not a readable image (" + h.format + " header truncated or damaged: no image size)";
    if (h.width <= 0 || h.height <= 0)
        return source + ": " + h.format + " header gives an empty image (" + std::to_string(h.width) + " x " +
               std::to_string(h.height) + ")";
    // width and height are below 2^40 each; compare without overflow.
    if (maxPixels > 0 && h.width > maxPixels / h.height)
        return source + ": the image is " + std::to_string(h.width) + " x " + std::to_string(h.height) + " = " +
               (h.width <= INT64_MAX / h.height ? std::to_string(h.width * h.height) : std::string("over 9.2e18")) + " pixels, more than the limit of " + std::to_string(maxPixels) +
               " pixels (raise it with --max-pixels)";
    if (std::string_view(h.format) == "PNG")  // (format is a C string: compared as text, not as a pointer)
        if (std::string why = pngTruncation(bytes); !why.empty()) return source + ": not a readable image (" + why + ")";
    return {};
}

}  // namespace lwb::core
