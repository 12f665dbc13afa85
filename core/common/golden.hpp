#pragma once
// Golden-section search for the minimum of a unimodal function on [a, b].
#include <algorithm>
#include <cmath>

namespace lwb::core {

/// The abscissa of the lower of the two last probes after at most `iterations` steps or once the
/// bracket is no wider than `tolerance`; *fMin (when given) its value. f is called
/// iterations + 2 times at most.
template <class F>
double goldenSection(double a, double b, int iterations, double tolerance, F&& f, double* fMin = nullptr) {
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
    for (int it = 0; it < iterations && b - a > tolerance; ++it) {
        if (fc <= fd) {
            b = d, d = c, fd = fc;
            c = b - g * (b - a), fc = f(c);
        } else {
            a = c, c = d, fc = fd;
            d = a + g * (b - a), fd = f(d);
        }
    }
    if (fMin) *fMin = std::min(fc, fd);
    return fc <= fd ? c : d;
}

}  // namespace lwb::core
