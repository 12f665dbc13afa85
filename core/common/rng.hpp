#pragma once
// Deterministic random numbers for the simulators: the same seed gives the same stream on
// every platform and compiler (std:: distributions do not promise that).
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lwb::core {

class Rng {
public:
    explicit Rng(uint64_t seed) {
        uint64_t z = seed;
        for (auto& s : m_s) s = splitmix(z);
    }
    /// 64 random bits (xoshiro256**).
    uint64_t next() {
        const uint64_t r = rotl(m_s[1] * 5, 7) * 9;
        const uint64_t t = m_s[1] << 17;
        m_s[2] ^= m_s[0];
        m_s[3] ^= m_s[1];
        m_s[1] ^= m_s[2];
        m_s[0] ^= m_s[3];
        m_s[2] ^= t;
        m_s[3] = rotl(m_s[3], 45);
        return r;
    }
    /// Uniform in [0, 1).
    double uniform() { return (next() >> 11) * 0x1.0p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /// Standard normal (Marsaglia polar method).
    double normal() {
        if (m_haveSpare) {
            m_haveSpare = false;
            return m_spare;
        }
        double u, v, s;
        do {
            u = 2 * uniform() - 1;
            v = 2 * uniform() - 1;
            s = u * u + v * v;
        } while (s >= 1 || s == 0);
        const double f = std::sqrt(-2 * std::log(s) / s);
        m_spare = v * f;
        m_haveSpare = true;
        return u * f;
    }
    double normal(double mean, double sd) { return mean + sd * normal(); }
    /// Poisson deviate: exact (multiplication method) below 30, normal approximation above.
    double poisson(double lambda) {
        if (lambda <= 0) return 0;
        if (lambda < 30) {
            const double l = std::exp(-lambda);
            double p = uniform();
            int k = 0;
            while (p > l) {
                p *= uniform();
                ++k;
            }
            return k;
        }
        return std::max(0.0, std::round(lambda + std::sqrt(lambda) * normal()));
    }
    /// Derives an independent stream (for item i of a batch).
    static uint64_t mix(uint64_t seed, uint64_t i) {
        uint64_t z = seed ^ (0x9E3779B97F4A7C15ULL * (i + 1));
        return splitmix(z);
    }

private:
    static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    static uint64_t splitmix(uint64_t& z) {
        uint64_t r = (z += 0x9E3779B97F4A7C15ULL);
        r = (r ^ (r >> 30)) * 0xBF58476D1CE4E5B9ULL;
        r = (r ^ (r >> 27)) * 0x94D049BB133111EBULL;
        return r ^ (r >> 31);
    }
    uint64_t m_s[4];
    bool m_haveSpare = false;
    double m_spare = 0;
};

}  // namespace lwb::core

namespace lwb::core::sim {
using core::Rng;  // (the simulators' name for it)
}  // namespace lwb::core::sim
