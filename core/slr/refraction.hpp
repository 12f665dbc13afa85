#pragma once
// Tropospheric delay at optical wavelengths for laser ranging, as in the IERS Conventions
// (2010) §9.2: Mendes & Pavlis (2004) zenith delay (hydrostatic + non-hydrostatic, with the
// wavelength dispersion) and the FCULa mapping function (Mendes et al. 2002). Plus the
// geodetic helpers the O-C needs (GRS80 latitude/height, azimuth/elevation).
#include <Eigen/Core>

namespace lwb::core::slr {

/// Geodetic coordinates on the GRS80 ellipsoid.
struct Geodetic {
    double latitudeRad = 0;   ///< geodetic latitude (rad)
    double longitudeRad = 0;  ///< east longitude (rad)
    double heightM = 0;       ///< ellipsoidal height (m)
};

/// ECEF (m) -> geodetic latitude, longitude, height (GRS80), iterated to < 1e-12 rad.
Geodetic geodeticFromEcef(const Eigen::Vector3d& xyz);

/// Geodetic latitude, longitude (degrees) and height (m) on GRS80 -> ECEF (m).
Eigen::Vector3d ecefFromGeodetic(double latDeg, double lonDeg, double heightM);

/// Azimuth (rad, from north through east, 0..2π) and elevation (rad) of `target` seen from
/// `station` (both ECEF, m), with the geodetic vertical of the station.
void azimuthElevation(const Eigen::Vector3d& station, const Geodetic& geo, const Eigen::Vector3d& target,
                      double* azimuthRad, double* elevationRad);

/// Water vapour pressure (hPa) at the station from relative humidity (%), temperature (K)
/// and pressure (hPa): saturation pressure and enhancement factor as in IERS Conventions
/// (2010) §9.2 (Giacomo 1982 / Davis 1992).
double waterVapourPressureHpa(double temperatureK, double humidityPct, double pressureHpa);

struct ZenithDelay {
    double hydrostaticM = 0;     ///< m
    double nonHydrostaticM = 0;  ///< m
    double totalM = 0;           ///< m
};

/// Mendes & Pavlis (2004) zenith delay (m) for a laser wavelength (µm), surface pressure and
/// water vapour pressure (hPa), geodetic latitude (rad) and height (m); CO2 375 ppm.
ZenithDelay mendesPavlisZenithDelay(double latitudeRad, double heightM, double pressureHpa, double waterVapourHpa,
                                    double wavelengthUm);

/// FCULa mapping function (Mendes et al. 2002): ratio of slant to zenith delay at an
/// elevation (rad) for a station latitude (rad), height (m) and surface temperature (K).
double fculaMapping(double latitudeRad, double heightM, double temperatureK, double elevationRad);

/// One-way tropospheric delay (m) = Mendes-Pavlis zenith delay x FCULa mapping.
double mendesPavlisDelayM(const Geodetic& station, double pressureHpa, double temperatureK, double humidityPct,
                          double wavelengthUm, double elevationRad);

}  // namespace lwb::core::slr
