#include "core/slr/refraction.hpp"

#include <algorithm>
#include <cmath>

namespace lwb::core::slr {

namespace {
constexpr double kA = 6378137.0;              // GRS80 semi-major axis (m)
constexpr double kF = 1.0 / 298.257222101;    // GRS80 flattening
constexpr double kE2 = kF * (2.0 - kF);       // first eccentricity squared
}  // namespace

Eigen::Vector3d ecefFromGeodetic(double latDeg, double lonDeg, double heightM) {
    const double la = latDeg * M_PI / 180, lo = lonDeg * M_PI / 180;
    const double n = kA / std::sqrt(1 - kE2 * std::sin(la) * std::sin(la));
    return {(n + heightM) * std::cos(la) * std::cos(lo), (n + heightM) * std::cos(la) * std::sin(lo),
            (n * (1 - kE2) + heightM) * std::sin(la)};
}

Geodetic geodeticFromEcef(const Eigen::Vector3d& xyz) {
    Geodetic g;
    const double p = std::hypot(xyz.x(), xyz.y());
    g.longitudeRad = std::atan2(xyz.y(), xyz.x());
    if (p < 1e-9) {  // on the axis
        g.latitudeRad = xyz.z() >= 0 ? M_PI / 2 : -M_PI / 2;
        g.heightM = std::fabs(xyz.z()) - kA * std::sqrt(1 - kE2);
        return g;
    }
    double lat = std::atan2(xyz.z(), p * (1 - kE2));
    double h = 0;
    for (int i = 0; i < 20; ++i) {
        const double s = std::sin(lat);
        const double n = kA / std::sqrt(1 - kE2 * s * s);
        h = p / std::cos(lat) - n;
        const double next = std::atan2(xyz.z(), p * (1 - kE2 * n / (n + h)));
        const bool done = std::fabs(next - lat) < 1e-12;
        lat = next;
        if (done) break;
    }
    g.latitudeRad = lat;
    g.heightM = h;
    return g;
}

void azimuthElevation(const Eigen::Vector3d& station, const Geodetic& geo, const Eigen::Vector3d& target,
                      double* azimuthRad, double* elevationRad) {
    const double sl = std::sin(geo.latitudeRad), cl = std::cos(geo.latitudeRad);
    const double so = std::sin(geo.longitudeRad), co = std::cos(geo.longitudeRad);
    const Eigen::Vector3d up(cl * co, cl * so, sl), east(-so, co, 0), north(-sl * co, -sl * so, cl);
    const Eigen::Vector3d d = target - station;
    const double r = d.norm();
    const double e = d.dot(east), n = d.dot(north), u = d.dot(up);
    double az = std::atan2(e, n);
    if (az < 0) az += 2 * M_PI;
    if (azimuthRad) *azimuthRad = az;
    if (elevationRad) *elevationRad = r > 0 ? std::asin(std::max(-1.0, std::min(1.0, u / r))) : M_PI / 2;
}

double waterVapourPressureHpa(double temperatureK, double humidityPct, double pressureHpa) {
    const double t = temperatureK;
    const double tc = t - 273.15;
    // Saturation vapour pressure (Pa -> hPa) and enhancement factor (pressure in Pa).
    const double es = 0.01 * std::exp(1.2378847e-5 * t * t - 1.9121316e-2 * t + 33.93711047 - 6.3431645e3 / t);
    const double fw = 1.00062 + 3.14e-8 * (pressureHpa * 100.0) + 5.6e-7 * tc * tc;
    return humidityPct / 100.0 * fw * es;
}

ZenithDelay mendesPavlisZenithDelay(double latitudeRad, double heightM, double pressureHpa, double waterVapourHpa,
                                    double wavelengthUm) {
    // Dispersion constants (µm^-2) of Mendes & Pavlis (2004) eq. 20 and 32; CO2 content 375 ppm.
    const double k0 = 238.0185, k1 = 19990.975, k2 = 57.362, k3 = 579.55174;
    const double w0 = 295.235, w1 = 2.6422, w2 = -0.032380, w3 = 0.004028;
    const double xc = 375.0;
    const double sigma = 1.0 / wavelengthUm;
    const double s2 = sigma * sigma;
    const double f = 1.0 - 0.00266 * std::cos(2.0 * latitudeRad) - 0.00000028 * heightM;
    const double cco2 = 1.0 + 0.534e-6 * (xc - 450.0);
    const double fh = 0.01 * cco2 * (k1 * (k0 + s2) / ((k0 - s2) * (k0 - s2)) + k3 * (k2 + s2) / ((k2 - s2) * (k2 - s2)));
    const double fnh = 0.003101 * (w0 + 3.0 * w1 * s2 + 5.0 * w2 * s2 * s2 + 7.0 * w3 * s2 * s2 * s2);
    ZenithDelay z;
    z.hydrostaticM = 0.002416579 * fh * pressureHpa / f;
    z.nonHydrostaticM = 1.0e-4 * (5.316 * fnh - 3.759 * fh) * waterVapourHpa / f;
    z.totalM = z.hydrostaticM + z.nonHydrostaticM;
    return z;
}

double fculaMapping(double latitudeRad, double heightM, double temperatureK, double elevationRad) {
    // Coefficients a_i = a_i0 + a_i1 t + a_i2 cos(lat) + a_i3 H (Mendes et al. 2002, FCULa).
    const double tc = temperatureK - 273.15, cl = std::cos(latitudeRad), h = heightM;
    const double a1 = 0.121008e-02 + 0.17295e-05 * tc + 0.3191e-04 * cl - 0.18478e-07 * h;
    const double a2 = 0.304965e-02 + 0.2346e-05 * tc - 0.1035e-03 * cl - 0.1856e-07 * h;
    const double a3 = 0.68777e-01 + 0.1972e-04 * tc - 0.3458e-02 * cl + 0.1060e-06 * h;
    const double se = std::sin(elevationRad);
    const double top = 1.0 + a1 / (1.0 + a2 / (1.0 + a3));
    return top / (se + a1 / (se + a2 / (se + a3)));
}

double mendesPavlisDelayM(const Geodetic& station, double pressureHpa, double temperatureK, double humidityPct,
                          double wavelengthUm, double elevationRad) {
    const double e = waterVapourPressureHpa(temperatureK, humidityPct, pressureHpa);
    const ZenithDelay z = mendesPavlisZenithDelay(station.latitudeRad, station.heightM, pressureHpa, e, wavelengthUm);
    return z.totalM * fculaMapping(station.latitudeRad, station.heightM, temperatureK, elevationRad);
}

}  // namespace lwb::core::slr
