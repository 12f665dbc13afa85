// The row filter language (core/common/row_filter): precedence, strings, numbers against texts,
// NaN, errors with their positions, and the speed over 10 000 rows (printed, not timed).
#include <QtTest>
#include <chrono>
#include <cmath>
#include <random>

#include "core/common/row_filter.hpp"

using namespace lwb::core;

namespace {
const std::vector<std::string> kColumns = {"snr", "beam", "verdict", "note", "dx", "roi", "x"};

// snr, beam (text), verdict (text), note (text), dx, roi, x
std::vector<FilterCell> row(double snr, const std::string& beam, const std::string& verdict, const std::string& note,
                            double dx, double roi, double x = 0) {
    return {FilterCell::num(snr), FilterCell::str(beam), FilterCell::str(verdict), FilterCell::str(note),
            FilterCell::num(dx),  FilterCell::num(roi),  FilterCell::num(x)};
}

RowFilterResult compile(const std::string& text) {
    RowFilterParams p;
    p.text = text;
    p.columns = kColumns;
    return compileRowFilter(p);
}

bool eval(const std::string& text, const std::vector<FilterCell>& r) {
    const RowFilterResult c = compile(text);
    if (!c.ok) qWarning("%s: %s", text.c_str(), c.error.c_str());
    Q_ASSERT(c.ok);
    return c.empty || c.filter->matches(r);
}
}  // namespace

class TestRowFilter : public QObject {
    Q_OBJECT
private slots:
    void examplesOfTheIssue() {
        const auto a = row(5, "2", "doubtful", "", -0.7, 1);
        const auto b = row(20, "1", "good", "checked", 0.1, 0);
        QVERIFY(eval("snr < 10 and beam == 2", a));
        QVERIFY(!eval("snr < 10 and beam == 2", b));
        QVERIFY(eval("verdict == \"doubtful\" or note != \"\"", a));
        QVERIFY(eval("verdict == \"doubtful\" or note != \"\"", b));  // the note
        QVERIFY(!eval("verdict == \"doubtful\" or note != \"\"", row(20, "1", "good", "", 0, 0)));
        QVERIFY(eval("abs(dx) > 0.5", a));
        QVERIFY(!eval("abs(dx) > 0.5", b));
        QVERIFY(!eval("not (roi == 1)", a));
        QVERIFY(eval("not (roi == 1)", b));
    }

    void precedence() {
        const auto r = row(5, "2", "good", "", 0, 1);
        // and binds tighter than or: true or (false and false) = true; (true or false) and false = false.
        QVERIFY(eval("snr == 5 or snr == 6 and roi == 7", r));
        QVERIFY(!eval("(snr == 5 or snr == 6) and roi == 7", r));
        // not binds looser than a comparison, tighter than and.
        QVERIFY(!eval("not roi == 1", r));
        QVERIFY(eval("not roi == 2 and snr == 5", r));
        QVERIFY(!eval("not (roi == 1 and snr == 5)", r));
        QVERIFY(eval("not (roi == 2 and snr == 5)", r));
        QVERIFY(eval("not not roi == 1", r));
        // * before +, unary minus, parentheses.
        QVERIFY(eval("1 + 2 * snr == 11", r));
        QVERIFY(eval("(1 + 2) * snr == 15", r));
        QVERIFY(eval("-snr + 10 == 5", r));
        QVERIFY(eval("10 - 4 - 1 == 5", r));  // left to right
        QVERIFY(eval("20 / 2 / 2 == snr", r));
        QVERIFY(eval("sqrt(snr * 5) == 5", r));
        // words in any case, && || ! too.
        QVERIFY(eval("SNR == 5 AND Roi == 1", r));
        QVERIFY(eval("snr == 5 && !(roi == 2) || snr == 0", r));
    }

    void comparisons() {
        const auto r = row(5, "2", "Doubtful", "", 0, 1);
        QVERIFY(eval("snr <= 5", r) && !eval("snr < 5", r) && eval("snr >= 5", r) && !eval("snr > 5", r));
        QVERIFY(eval("snr != 4", r) && !eval("snr != 5", r));
        QVERIFY(eval("1e1 > snr", r) && eval(".5e1 == snr", r));
    }

    void strings() {
        const auto r = row(5, "2", "Doubtful", "it's \"odd\"", 0, 1);
        QVERIFY(eval("verdict == \"doubtful\"", r));  // without regard to case
        QVERIFY(eval("verdict == 'DOUBTFUL'", r));
        QVERIFY(eval("verdict != \"good\"", r));
        QVERIFY(eval("verdict > \"a\" and verdict < \"e\"", r));  // text order
        QVERIFY(eval("note == \"it's \\\"odd\\\"\"", r));        // escaped quotes
        QVERIFY(eval("note == 'it\\'s \"odd\"'", r));
        QVERIFY(eval("beam == 2 and beam == \"2\" and beam > 1.5", r));  // a text that reads as a number
        QVERIFY(!eval("verdict == 2", r));   // a text that is no number against a number: false
        QVERIFY(!eval("verdict != 2", r));
        QVERIFY(eval("note != \"\"", r));
        QVERIFY(!eval("note != \"\"", row(5, "2", "good", "", 0, 1)));
    }

    void nanComparesFalse() {
        const double nan = std::nan("");
        const auto r = row(nan, "", "rejected", "", nan, 0);
        QVERIFY(!eval("snr < 10", r));
        QVERIFY(!eval("snr >= 10", r));
        QVERIFY(!eval("snr == snr", r));
        QVERIFY(!eval("snr != 3", r));
        QVERIFY(eval("not (snr >= 10)", r));
        QVERIFY(!eval("abs(dx) > 0.5", r));
        QVERIFY(!eval("dx + 1 > 0", r));
        QVERIFY(!eval("sqrt(-1) < 1", row(1, "", "", "", 0, 0)));
        QVERIFY(!eval("beam == 2", r));  // an empty text is no number
        // A row without the column (shorter than the list) reads it as missing.
        const RowFilterResult c = compile("x > 1");
        QVERIFY(c.ok);
        QVERIFY(!c.filter->matches({FilterCell::num(1)}));
    }

    void blankSelectsAll() {
        const RowFilterResult c = compile("   ");
        QVERIFY(c.ok);
        QVERIFY(c.empty);
        QVERIFY(!c.filter);
    }

    void usedColumns() {
        const RowFilterResult c = compile("x > 1 and SNR < 2 or x < 0");
        QVERIFY(c.ok);
        QCOMPARE(c.filter->usedColumns(), (std::vector<int>{0, 6}));
    }

    void errorsWithPositions_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<int>("pos");
        QTest::addColumn<QString>("says");
        QTest::newRow("unknown column") << "snrr < 10" << 1 << "column 'snrr' unknown at 1; columns: snr, beam, verdict, note, dx, roi, x";
        QTest::newRow("unknown later") << "snr < 10 and bem == 2" << 14 << "column 'bem' unknown at 14";
        QTest::newRow("missing operand") << "snr <" << 6 << "expected a value, a column or '(' but the expression ends at 6";
        QTest::newRow("single =") << "snr = 2" << 5 << "expected '==' (one '=' is no comparison) at 5";
        QTest::newRow("unclosed paren") << "(snr < 1" << 9 << "expected ')' to close the '(' at 1, found the end at 9";
        QTest::newRow("value alone") << "snr" << 1 << "expected a comparison (such as snr < 10), found a value alone at 1";
        QTest::newRow("chained") << "snr < 1 < 2" << 9 << "expected 'and' or 'or' between comparisons, not '<' at 9";
        QTest::newRow("function") << "foo(2) > 1" << 1 << "function 'foo' unknown (abs and sqrt are) at 1";
        QTest::newRow("string") << "note == \"abc" << 9 << "string not closed";
        QTest::newRow("dangling or") << "snr < 10 or" << 12 << "but the expression ends at 12";
        QTest::newRow("two values") << "snr < 10 snr" << 10 << "expected 'and', 'or' or an operator, found 'snr' at 10";
        QTest::newRow("and of values") << "snr and roi == 1" << 1 << "expected a comparison before 'and' at 1";
        QTest::newRow("comparison in abs") << "abs(snr < 1) > 0" << 5 << "expected a value inside abs(...) at 5";
        QTest::newRow("stray character") << "snr < 10 ; roi" << 10 << "unexpected character ';' at 10";
        QTest::newRow("extra paren") << "(snr < 1))" << 10 << "found ')' at 10";
        QTest::newRow("number glued") << "snr < 10x" << 9 << "after the number '10' at 9";
    }
    void errorsWithPositions() {
        QFETCH(QString, text);
        QFETCH(int, pos);
        QFETCH(QString, says);
        const RowFilterResult c = compile(text.toStdString());
        QVERIFY(!c.ok);
        QVERIFY(!c.filter);
        QCOMPARE(int(c.errorPos), pos);
        QVERIFY2(QString::fromStdString(c.error).contains(says), c.error.c_str());
    }

    void deepNestingIsAnErrorNotACrash() {
        std::string t;
        for (int i = 0; i < 1000; ++i) t += "not ";
        t += "snr < 1";
        const RowFilterResult c = compile(t);
        QVERIFY(!c.ok);
        QVERIFY2(c.error.find("nested too deeply") != std::string::npos, c.error.c_str());
        const RowFilterResult p = compile(std::string(1000, '(') + "snr < 1" + std::string(1000, ')'));
        QVERIFY(!p.ok);
        QVERIFY2(p.error.find("nested too deeply") != std::string::npos, p.error.c_str());
        // A text too long to be typed is refused before parsing (a long chain of terms would
        // otherwise be a deep tree to evaluate).
        std::string chain = "snr";
        while (chain.size() < 5000) chain += " + snr";
        const RowFilterResult l = compile(chain + " > 0");
        QVERIFY(!l.ok);
        QVERIFY2(l.error.find("longer than 4096 characters") != std::string::npos, l.error.c_str());
        const RowFilterResult ok150 = compile(std::string(150, '(') + "snr < 1" + std::string(150, ')'));
        QVERIFY2(ok150.ok, ok150.error.c_str());  // a deep but reasonable nesting is fine
    }

    // 10 000 rows: the count is checked against a direct computation; the time is printed.
    void tenThousandRows() {
        std::mt19937 rng(7);
        std::uniform_real_distribution<double> u(0, 30), d(-1, 1);
        std::vector<std::vector<FilterCell>> rows;
        int expect = 0;
        static const char* verdicts[] = {"good", "doubtful", "rejected"};
        for (int i = 0; i < 10000; ++i) {
            const double snr = i % 50 == 0 ? std::nan("") : u(rng);
            const std::string beam = std::to_string(1 + i % 2);
            const std::string v = verdicts[i % 3];
            const std::string note = i % 7 == 0 ? "look" : "";
            const double dx = d(rng);
            rows.push_back(row(snr, beam, v, note, dx, i % 2));
            const bool sel = (snr < 10 && beam == "2") || v == "doubtful" || (std::fabs(dx) > 0.5 && !note.empty());
            expect += sel;
        }
        const RowFilterResult c =
            compile("snr < 10 and beam == 2 or verdict == \"doubtful\" or abs(dx) > 0.5 and note != \"\"");
        QVERIFY2(c.ok, c.error.c_str());
        const auto t0 = std::chrono::steady_clock::now();
        int n = 0;
        for (const auto& r : rows) n += c.filter->matches(r);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        QCOMPARE(n, expect);
        qInfo("row filter: 10000 rows in %.2f ms (%d selected)", ms, n);
    }
};

QTEST_APPLESS_MAIN(TestRowFilter)
#include "test_row_filter.moc"
