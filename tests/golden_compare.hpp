#pragma once
// Golden outputs compared as numbers (issue 26). Last digits move between CPUs: glibc's libm and
// OpenCV choose code paths by CPU (FMA, AVX2, AVX-512) and the compiler may contract a*b+c into
// one fused operation, so an output that is right on one machine differs from the recorded one
// in its 9th or 10th significant digit on another. A golden file is therefore compared token by
// token, never as text:
//
//  - Each line is cut into fields (CSV: at commas, the header naming the columns; other text: the
//    whole line is one field) and each field into alternating text and number tokens.
//  - Text tokens must be identical (verdicts, classes, reasons, names, units).
//  - Two numbers both written without a decimal point or exponent (a count, an index, a flag)
//    must be identical too. (A real value %g prints as "0" on one CPU and "3e-17" on another is
//    compared as a number.)
//  - Any other number may differ by the largest of
//      rel × max(|golden|, |today|)          the relative tolerance (default 1e-8),
//      colRel × the column's largest |value| (CSV only, default 1e-12: a value that is zero in
//                                             truth, 1e-17 on one CPU and 0 on another), and
//      one unit in the last printed digit    (a value on a rounding boundary: 0.12345 written as
//                                             0.1234 here and 0.1235 there).
//    A column documented as less precise gets its own rel (Tolerance::columns) or an absolute
//    allowance (Tolerance::columnsAbs; whole numbers too, such as an iteration count).
//  - Line and field counts must match.
//
// A failure names the file, the line, the column (or field) and both values.
#include <QByteArray>
#include <QList>
#include <QMap>
#include <QString>
#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdlib>
#include <string>

namespace lwbtest {

struct Tolerance {
    double rel = 1e-8;     ///< relative to the larger of the two values
    double colRel = 1e-12; ///< relative to the column's largest magnitude (CSV)
    /// Per-column relative tolerances that replace `rel` ("column name" → rel).
    QMap<QString, double> columns;
    /// Per-column absolute tolerances added to the allowance ("column name" → abs), whole
    /// numbers included (an iteration count).
    QMap<QString, double> columnsAbs;
};

struct NumberToken {
    bool isNumber = false;
    bool integral = false;  ///< written without '.', 'e' or 'E'
    double value = 0;
    double lastDigit = 0;   ///< the value of one unit in the last written digit
    QByteArray text;
};

/// Cuts a field into text and number tokens. A number: optional sign, digits with an optional
/// '.', an optional exponent. A sign is part of the number only at the start of the field or
/// after a character that cannot end a word ("2020-03-11" is 2020, "-03", "-11" on both sides
/// alike, which compares the same either way).
inline QList<NumberToken> tokenize(const QByteArray& s) {
    QList<NumberToken> out;
    QByteArray text;
    auto flushText = [&] {
        if (text.isEmpty()) return;
        NumberToken t;
        t.text = text;
        out << t;
        text.clear();
    };
    const int n = s.size();
    int i = 0;
    auto isDigit = [&](int k) { return k < n && s[k] >= '0' && s[k] <= '9'; };
    while (i < n) {
        int j = i;
        if ((s[j] == '-' || s[j] == '+') && (isDigit(j + 1) || (j + 1 < n && s[j + 1] == '.' && isDigit(j + 2)))) ++j;
        const bool startsNumber = isDigit(j) || (j < n && s[j] == '.' && isDigit(j + 1));
        // A digit glued to a word ("x2", "F2", "aero1") belongs to the word.
        const bool gluedToWord = i > 0 && (std::isalpha(static_cast<unsigned char>(s[i - 1])) || s[i - 1] == '_');
        if (!startsNumber || gluedToWord) {
            text += s[i++];
            continue;
        }
        const int start = i;
        int k = j;
        int fracDigits = 0;
        bool point = false, expo = false;
        while (isDigit(k)) ++k;
        if (k < n && s[k] == '.') {
            point = true;
            ++k;
            while (isDigit(k)) {
                ++k;
                ++fracDigits;
            }
        }
        int expValue = 0;
        if (k < n && (s[k] == 'e' || s[k] == 'E')) {
            int m = k + 1;
            if (m < n && (s[m] == '-' || s[m] == '+')) ++m;
            if (isDigit(m)) {
                expo = true;
                const int es = k + 1;
                k = m;
                while (isDigit(k)) ++k;
                expValue = std::atoi(s.mid(es, k - es).constData());
            }
        }
        // A number followed by a letter or '_' is part of a word ("2d", "7080_STELLA"): text.
        if (k < n && (std::isalpha(static_cast<unsigned char>(s[k])) || s[k] == '_')) {
            while (i < k) text += s[i++];
            continue;
        }
        flushText();
        NumberToken t;
        t.isNumber = true;
        t.text = s.mid(start, k - start);
        t.value = std::strtod(t.text.constData(), nullptr);
        t.integral = !point && !expo;
        t.lastDigit = std::pow(10.0, expValue - fracDigits);
        out << t;
        i = k;
    }
    flushText();
    return out;
}

/// Splits a CSV line at commas outside double quotes.
inline QList<QByteArray> csvFields(const QByteArray& line) {
    QList<QByteArray> f;
    QByteArray cur;
    bool quoted = false;
    for (char c : line) {
        if (c == '"') quoted = !quoted;
        if (c == ',' && !quoted) {
            f << cur;
            cur.clear();
        } else {
            cur += c;
        }
    }
    f << cur;
    return f;
}

/// Compares `today` with `golden` as described at the top of this file. `file` names the output
/// in the message; `csv` says whether its first line is a header of comma-separated columns.
/// Returns "" when they agree, else what differs, and where.
inline QString compareNumbers(const QString& file, const QByteArray& golden, const QByteArray& today, bool csv,
                              const Tolerance& tol = {}) {
    QList<QByteArray> g = golden.split('\n'), t = today.split('\n');
    for (QList<QByteArray>* l : {&g, &t}) {
        while (!l->isEmpty() && l->last().isEmpty()) l->removeLast();
        for (QByteArray& s : *l)
            if (s.endsWith('\r')) s.chop(1);
    }
    if (g.size() != t.size())
        return QString("%1: %2 lines, golden has %3").arg(file).arg(t.size()).arg(g.size());
    QList<QByteArray> header;
    QList<double> colMax;
    if (csv && !g.isEmpty()) {
        header = csvFields(g[0]);
        colMax = QList<double>(header.size(), 0.0);
        for (int i = 1; i < g.size(); ++i) {
            const QList<QByteArray> f = csvFields(g[i]);
            for (int c = 0; c < f.size() && c < colMax.size(); ++c)
                for (const NumberToken& k : tokenize(f[c]))
                    if (k.isNumber && std::isfinite(k.value)) colMax[c] = std::max(colMax[c], std::fabs(k.value));
        }
    }
    for (int i = 0; i < g.size(); ++i) {
        const QList<QByteArray> gf = csv ? csvFields(g[i]) : QList<QByteArray>{g[i]};
        const QList<QByteArray> tf = csv ? csvFields(t[i]) : QList<QByteArray>{t[i]};
        const QString where = QString("%1 line %2").arg(file).arg(i + 1);
        if (gf.size() != tf.size())
            return QString("%1: %2 fields, golden has %3\n  golden: %4\n  today:  %5")
                .arg(where)
                .arg(tf.size())
                .arg(gf.size())
                .arg(QString::fromUtf8(g[i].left(300)), QString::fromUtf8(t[i].left(300)));
        for (int c = 0; c < gf.size(); ++c) {
            const QString column = csv ? QString("column %1 (%2)").arg(c + 1).arg(QString::fromUtf8(header.value(c)))
                                       : QString("field %1").arg(c + 1);
            const QList<NumberToken> a = tokenize(gf[c]), b = tokenize(tf[c]);
            auto differ = [&](const QString& why) {
                return QString("%1, %2: %3\n  golden: %4\n  today:  %5")
                    .arg(where, column, why, QString::fromUtf8(gf[c].left(300)), QString::fromUtf8(tf[c].left(300)));
            };
            if (a.size() != b.size()) return differ("not the same shape of text and numbers");
            const QString colName = QString::fromUtf8(header.value(c));
            const double rel = tol.columns.value(colName, tol.rel);
            const double abs = tol.columnsAbs.value(colName, 0.0);
            for (int k = 0; k < a.size(); ++k) {
                if (a[k].isNumber != b[k].isNumber || !a[k].isNumber || (a[k].integral && b[k].integral && abs == 0)) {
                    if (a[k].text != b[k].text) return differ("\"" + QString::fromUtf8(b[k].text) + "\", golden \"" +
                                                             QString::fromUtf8(a[k].text) + "\"");
                    continue;
                }
                const double x = a[k].value, y = b[k].value;
                if (!std::isfinite(x) || !std::isfinite(y)) {
                    if (a[k].text != b[k].text) return differ("not the same non-finite value");
                    continue;
                }
                const double allowed = std::max({rel * std::max(std::fabs(x), std::fabs(y)),
                                                 csv ? tol.colRel * colMax.value(c) : 0.0,
                                                 // (the two decimals' difference in binary carries their
                                                 // rounding: 48.420717 - 48.420716 is 1e-6 + 3e-14)
                                                 (a[k].integral && b[k].integral)
                                                     ? 0.0
                                                     : std::max(a[k].lastDigit, b[k].lastDigit) +
                                                           8 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(x), std::fabs(y)),
                                                 abs});
                if (std::fabs(x - y) > allowed)
                    return differ(QString("%1 vs golden %2: differs by %3, more than the %4 allowed (relative %5)")
                                      .arg(QString::fromUtf8(b[k].text), QString::fromUtf8(a[k].text))
                                      .arg(std::fabs(x - y), 0, 'g', 3)
                                      .arg(allowed, 0, 'g', 3)
                                      .arg(std::fabs(x - y) / std::max(std::fabs(x), std::fabs(y)), 0, 'g', 3));
            }
        }
    }
    return {};
}

}  // namespace lwbtest
