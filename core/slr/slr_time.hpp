#pragma once
// Calendar helpers shared by the SLR readers (CRD, CPF, SINEX) and the O-C computation:
// Gregorian date <-> Modified Julian Date, and SINEX "YY:DOY:SSSSS" epochs.
// Times are UTC throughout. A day is 86 400 s, except a day that ends with a leap second
// (23:59:60 UTC; leapSecondAtEndOf): CRD records of such a day may be at 86400..86401 s, and a
// pass that crosses its midnight is 86 401 s longer in elapsed time at the next day's 0h.
#include <string_view>

namespace lwb::core::slr {

constexpr double kSecondsPerDay = 86400.0;

/// True for a valid Gregorian date with year in 1800..2200 (the range the readers accept).
bool validDate(int year, int month, int day);

/// Modified Julian Date (days since 1858-11-17 0h) of a Gregorian date at 0h.
/// Valid for any year >= 1 (proleptic Gregorian); callers check validDate first.
long mjdFromDate(int year, int month, int day);

/// True when the UTC day `mjd` ends with a positive leap second (23:59:60), from IERS Bulletin C:
/// the 27 leap seconds from 1972-06-30 to 2016-12-31 (none since, to this writing: Bulletin C 70,
/// July 2025, announced none for the end of 2025).
bool leapSecondAtEndOf(long mjd);

/// Inverse of mjdFromDate.
void dateFromMjd(long mjd, int* year, int* month, int* day);

/// Parses a SINEX 2.02 epoch "YY:DOY:SSSSS" (YY <= 50 -> 20YY, else 19YY; DOY 0..366,
/// SSSSS 0..86400) into MJD + seconds of day. "00:000:00000" is accepted and means 2000-01-00
/// (SINEX uses it for "unknown"); callers decide what it means for them. False when malformed.
bool parseSinexEpoch(std::string_view text, long* mjd, double* secondsOfDay);

}  // namespace lwb::core::slr
