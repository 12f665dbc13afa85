#pragma once
// Small text helpers shared by the readers: strict number parsing, splitting, trimming.
#include <string>
#include <string_view>
#include <vector>

namespace lwb::core {

/// sqrt of a variance that rounding may have pushed slightly below zero; NaN stays NaN (an
/// undefined uncertainty must not be reported as 0).
inline double sqrtVariance(double v) { return v != v ? v : (v > 0 ? __builtin_sqrt(v) : 0.0); }

/// Parses the whole of `s` (surrounding blanks allowed) as a decimal number:
/// [+-] (digits [. digits] | . digits) [(e|E) [+-] digits]. False on empty text, trailing
/// garbage, hex floats, a point or exponent with no digits after it ("261.", "1e": a number
/// cut short), and overflow. Locale-independent. NaN / inf texts parse only when allowNonFinite.
bool parseDouble(std::string_view s, double* out, bool allowNonFinite = false);
/// As parseDouble, but a point with no digits after it is accepted ("26."): the FORTRAN
/// F-format the ILRS files (CRD, CPF, SINEX) are written in.
bool parseFortranDouble(std::string_view s, double* out);
/// Parses the whole of `s` as a base-10 integer. False on garbage or overflow.
bool parseLong(std::string_view s, long long* out);

std::string_view trim(std::string_view s);
/// Splits on runs of blanks (space, tab): the CRD/CPF/SINEX free format.
std::vector<std::string_view> splitBlanks(std::string_view s);
std::string toLower(std::string_view s);
/// "%.*g" formatting that round-trips a double (17 significant digits when needed).
std::string formatDouble(double v, int significant = 10);
/// Shortest "%g" text that reads back to exactly v.
std::string formatShortest(double v);
/// A field or line quoted in an error message: at most maxLen characters, control and
/// non-ASCII bytes shown as \xNN, "..." when cut.
std::string printableExcerpt(std::string_view s, size_t maxLen = 40);
/// "SOURCE:LINE: " — the prefix of a message about a line of a file.
std::string whereInFile(const std::string& source, long line);
/// Why `text` cannot be a text file of kind `kind` ("CRD", "CPF", ...): empty, or binary (a NUL
/// byte, with its line). Empty string when neither.
std::string textFileProblem(std::string_view text, const std::string& source, const char* kind);
/// A text file's lines as the readers take them: a UTF-8 byte order mark dropped, and a file
/// whose lines end with CR alone (classic Mac OS) rewritten into *storage with LF (the readers
/// split at LF; such a file read as one long line gave "no H4 session header in 1 lines").
/// CRLF files are left as they are (the readers drop the CR). The view is of *storage or of text.
std::string_view plainText(std::string_view text, std::string* storage);
/// Fixed-point formatting with `decimals` digits after the point.
std::string formatFixed(double v, int decimals);

/// Seconds of a day (any count: taken modulo 86 400) as "hh:mm:ss", rounded to the second.
std::string hmsRounded(double secondsOfDay);
/// " (did you mean X?)" for the name of `known` nearest to `given` (edit distance, case
/// ignored; a name that contains `given` whole counts as near), or "" when none is within a
/// third of the name's length (at least 2 edits). A mistyped option, command or key.
std::string didYouMean(std::string_view given, const std::vector<std::string>& known);

}  // namespace lwb::core
