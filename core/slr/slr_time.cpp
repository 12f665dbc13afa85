#include "core/slr/slr_time.hpp"

#include "core/common/text.hpp"

namespace lwb::core::slr {

bool validDate(int year, int month, int day) {
    if (year < 1800 || year > 2200 || month < 1 || month > 12 || day < 1) return false;
    static const int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    const int n = kDays[month - 1] + (month == 2 && leap ? 1 : 0);
    return day <= n;
}

long mjdFromDate(int year, int month, int day) {
    // Days from civil (Howard Hinnant's algorithm), shifted from 1970-01-01 (MJD 40587).
    const long y = static_cast<long>(year) - (month <= 2 ? 1 : 0);
    const long era = (y >= 0 ? y : y - 399) / 400;
    const long yoe = y - era * 400;
    const long mp = (month + 9) % 12;
    const long doy = (153 * mp + 2) / 5 + day - 1;
    const long doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468 + 40587;
}

void dateFromMjd(long mjd, int* year, int* month, int* day) {
    const long z = mjd - 40587 + 719468;
    const long era = (z >= 0 ? z : z - 146096) / 146097;
    const long doe = z - era * 146097;
    const long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const long mp = (5 * doy + 2) / 153;
    const long d = doy - (153 * mp + 2) / 5 + 1;
    const long m = mp < 10 ? mp + 3 : mp - 9;
    *year = static_cast<int>(yoe + era * 400 + (m <= 2 ? 1 : 0));
    *month = static_cast<int>(m);
    *day = static_cast<int>(d);
}

bool parseSinexEpoch(std::string_view text, long* mjd, double* secondsOfDay) {
    text = trim(text);
    if (text.size() != 12 || text[2] != ':' || text[6] != ':') return false;
    long long yy = 0, doy = 0, sss = 0;
    for (size_t i = 0; i < text.size(); ++i)
        if (i != 2 && i != 6 && (text[i] < '0' || text[i] > '9')) return false;
    if (!parseLong(text.substr(0, 2), &yy) || !parseLong(text.substr(3, 3), &doy) || !parseLong(text.substr(7, 5), &sss))
        return false;
    if (doy > 366 || sss > 86400) return false;
    const int year = static_cast<int>(yy <= 50 ? 2000 + yy : 1900 + yy);
    *mjd = mjdFromDate(year, 1, 1) + static_cast<long>(doy) - 1;
    *secondsOfDay = static_cast<double>(sss);
    return true;
}

bool leapSecondAtEndOf(long mjd) {
    // The last day of each month that ended with a leap second (IERS Bulletin C).
    static const int kDays[][3] = {{1972, 6, 30},  {1972, 12, 31}, {1973, 12, 31}, {1974, 12, 31}, {1975, 12, 31},
                                   {1976, 12, 31}, {1977, 12, 31}, {1978, 12, 31}, {1979, 12, 31}, {1981, 6, 30},
                                   {1982, 6, 30},  {1983, 6, 30},  {1985, 6, 30},  {1987, 12, 31}, {1989, 12, 31},
                                   {1990, 12, 31}, {1992, 6, 30},  {1993, 6, 30},  {1994, 6, 30},  {1995, 12, 31},
                                   {1997, 6, 30},  {1998, 12, 31}, {2005, 12, 31}, {2008, 12, 31}, {2012, 6, 30},
                                   {2015, 6, 30},  {2016, 12, 31}};
    for (const auto& d : kDays)
        if (mjdFromDate(d[0], d[1], d[2]) == mjd) return true;
    return false;
}

}  // namespace lwb::core::slr
