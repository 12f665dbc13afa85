#pragma once
// SHA-256 (FIPS 180-4) of a file or of bytes, as lower-case hex: the input checksums of the
// outputs' provenance (core/common/provenance.hpp). Written here rather than linked: the
// project links no cryptographic library (OpenSSL's libcrypto is not among its dependencies),
// and a checksum of the inputs needs nothing more than the one hash. On an x86-64 CPU with the
// SHA extensions the blocks are hashed with them (issue 44: the portable rounds were 18 % of a
// 10^6-event CRD run, hashing its input and its table); the same digest either way (tested).
#include <cstdint>
#include <string>
#include <string_view>

namespace lwb::core {

class Sha256 {
public:
    Sha256();
    void update(const void* data, size_t size);
    /// The digest as 64 hex digits; the object is spent afterwards.
    std::string hex();

private:
    void block(const unsigned char* p);
    void blocks(const unsigned char* p, size_t count);
    uint32_t m_h[8];
    bool m_extensions = false;
    unsigned char m_buf[64];
    size_t m_fill = 0;
    uint64_t m_bits = 0;
};

/// True when new hashes use the CPU's SHA extensions.
bool sha256UsesCpuExtensions();
/// Tests and benchmarks: new hashes use the portable rounds only (true) or the CPU's extensions
/// where it has them (false, the default).
void sha256PortableOnly(bool on);

/// The SHA-256 of `bytes`.
std::string sha256Hex(std::string_view bytes);
/// The SHA-256 of a file read in blocks (any size; "-", standard input, is not hashed). False
/// with *error ("FILE: why") when it cannot be read.
bool sha256File(const std::string& path, std::string* hex, std::string* error);

}  // namespace lwb::core
