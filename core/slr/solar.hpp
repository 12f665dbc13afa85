#pragma once
// Day or night at an SLR station: the Sun's elevation from a low-precision solar position (the
// Astronomical Almanac's formula: about 0.01° in 1950–2050, far below what day/night needs)
// and the station's geodetic latitude and longitude (from its ITRF position, WGS-84 ellipsoid).
// The ILRS minimum number of ranges per normal point is 6 by day and 3 by night.

namespace lwb::core::slr {

/// The Sun's apparent elevation above the horizon (degrees, geometric, no refraction) at a
/// station (geodetic latitude and east longitude, degrees) at a UTC epoch given as a modified
/// Julian date (days, fractional).
double sunElevationDeg(double mjdUtc, double latDeg, double lonDeg);

/// Geodetic latitude, longitude (degrees) and height (m) of an Earth-fixed position (m), WGS-84.
void geodeticFromEcef(double x, double y, double z, double* latDeg, double* lonDeg, double* heightM);

/// Day for the ILRS minimum: the Sun's centre above −0.833° (the upper limb at the horizon with
/// standard refraction: sunrise to sunset).
inline bool isDaylight(double sunElevationDeg) { return sunElevationDeg > -0.833; }

}  // namespace lwb::core::slr
