#pragma once
// Calendar helpers shared by the SLR readers (CRD, CPF, SINEX) and the O-C computation:
// Gregorian date <-> Modified Julian Date, and SINEX "YY:DOY:SSSSS" epochs.
// Times are UTC throughout; leap seconds are not modelled (a day is 86 400 s).
#include <string_view>

namespace lwb::core::slr {

constexpr double kSecondsPerDay = 86400.0;

/// True for a valid Gregorian date with year in 1800..2200 (the range the readers accept).
bool validDate(int year, int month, int day);

/// Modified Julian Date (days since 1858-11-17 0h) of a Gregorian date at 0h.
/// Valid for any year >= 1 (proleptic Gregorian); callers check validDate first.
long mjdFromDate(int year, int month, int day);

/// Inverse of mjdFromDate.
void dateFromMjd(long mjd, int* year, int* month, int* day);

/// Parses a SINEX 2.02 epoch "YY:DOY:SSSSS" (YY <= 50 -> 20YY, else 19YY; DOY 0..366,
/// SSSSS 0..86400) into MJD + seconds of day. "00:000:00000" is accepted and means 2000-01-00
/// (SINEX uses it for "unknown"); callers decide what it means for them. False when malformed.
bool parseSinexEpoch(std::string_view text, long* mjd, double* secondsOfDay);

}  // namespace lwb::core::slr
