// Core utilities: JSON, CSV, strict numbers, atomic writes.
#include <QtTest>

#include "core/common/atomic_file.hpp"
#include "core/common/csv.hpp"
#include "core/common/json.hpp"
#include "core/common/text.hpp"
#include "test_support.hpp"

using namespace lwb::core;

class TestCommon : public QObject {
    Q_OBJECT
private slots:
    void jsonRoundTrip() {
        Json j = Json::object();
        j.set("name", "wu2021");
        j.set("ratio", 1.25);
        j.set("tiny", 1e-5);
        j.set("flag", true);
        Json arr = Json::array();
        arr.push(1.0);
        arr.push(-30);
        j.set("range", arr);
        j.set("none", Json());
        const JsonParseResult back = parseJson(j.dump(), "mem");
        QVERIFY2(back.ok, back.error.c_str());
        QCOMPARE(back.value.find("name")->asString(), std::string("wu2021"));
        QCOMPARE(back.value.find("ratio")->asNumber(), 1.25);
        QCOMPARE(back.value.find("tiny")->asNumber(), 1e-5);  // shortest text still round-trips exactly
        QVERIFY(back.value.find("flag")->asBool());
        QCOMPARE(back.value.find("range")->items().size(), size_t(2));
        QVERIFY(back.value.find("none")->isNull());
        QVERIFY(j.dump().find("0.10000000000000001") == std::string::npos);
    }

    void jsonErrorsCarryLineAndColumn_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("where");
        QTest::newRow("nan literal") << "{\n  \"a\": NaN\n}" << "cfg:2:8";
        QTest::newRow("trailing comma") << "{\"a\": 1,}" << "cfg:1:9";
        QTest::newRow("unclosed") << "{\"a\": [1, 2" << "cfg:1:12";
        QTest::newRow("duplicate key") << "{\"a\": 1, \"a\": 2}" << "cfg:1:";
        QTest::newRow("garbage after") << "{} x" << "cfg:1:4";
        QTest::newRow("empty") << "" << "cfg:1:1";
        QTest::newRow("huge number") << "{\"a\": 1e999}" << "cfg:1:7";
    }
    void jsonErrorsCarryLineAndColumn() {
        QFETCH(QString, text);
        QFETCH(QString, where);
        const JsonParseResult r = parseJson(text.toStdString(), "cfg");
        QVERIFY(!r.ok);
        QVERIFY2(QString::fromStdString(r.error).startsWith(where), r.error.c_str());
    }

    void jsonTypedGetters() {
        const JsonParseResult r = parseJson("{\"n\": \"3\", \"i\": 2.5, \"ok\": 4}", "m");
        QVERIFY(r.ok);
        double d = 0;
        int i = 0;
        std::string err;
        QVERIFY(!jsonNumber(r.value, "n", &d, &err));
        QVERIFY(err.find("\"n\"") != std::string::npos);
        QVERIFY(!jsonInt(r.value, "i", &i, &err));
        QVERIFY(jsonInt(r.value, "ok", &i, &err));
        QCOMPARE(i, 4);
        QVERIFY(jsonNumber(r.value, "absent", &d, &err));  // absent keys leave the value alone
    }

    void strictNumbers() {
        double d = 0;
        long long l = 0;
        QVERIFY(parseDouble(" 1.5e3 ", &d));
        QCOMPARE(d, 1500.0);
        QVERIFY(!parseDouble("1.5x", &d));
        QVERIFY(!parseDouble("", &d));
        QVERIFY(!parseDouble("nan", &d));
        QVERIFY(!parseDouble("inf", &d));
        QVERIFY(parseDouble("nan", &d, true));
        QVERIFY(!parseDouble("1e400", &d));
        QVERIFY(parseLong("-42", &l));
        QCOMPARE(l, -42LL);
        QVERIFY(!parseLong("4.2", &l));
        QVERIFY(!parseLong("99999999999999999999999", &l));
    }

    void csvQuotingAndLines() {
        const CsvReadResult r = parseCsv("# comment\r\na,b,c\r\n1,\"x,y\",\"say \"\"hi\"\"\"\r\n\r\n2,,3\n", "t.csv");
        QVERIFY2(r.ok, r.error.c_str());
        QCOMPARE(r.table.header.size(), size_t(3));
        QCOMPARE(r.table.rows.size(), size_t(2));
        QCOMPARE(r.table.rows[0][1], std::string("x,y"));
        QCOMPARE(r.table.rows[0][2], std::string("say \"hi\""));
        QCOMPARE(r.table.lines[1], 5L);
        QCOMPARE(r.table.column("B"), 1);
        QCOMPARE(csvEscape("a,b"), std::string("\"a,b\""));
        QCOMPARE(csvEscape("plain"), std::string("plain"));
    }

    void csvErrorsNameTheLine() {
        CsvReadResult r = parseCsv("a,b\n1,2\n3\n", "f.csv");
        QVERIFY(!r.ok);
        QVERIFY2(r.error.rfind("f.csv:3:", 0) == 0, r.error.c_str());
        r = parseCsv("a,b\n1,\"open\n", "f.csv");
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("f.csv:line 2") != std::string::npos || r.error.find("f.csv:") == 0, r.error.c_str());
        r = parseCsv("", "e.csv");
        QVERIFY(!r.ok);
    }

    void atomicWriteLeavesNoHalfFile() {
        QTemporaryDir dir;
        const std::string target = (dir.path() + "/out.csv").toStdString();
        std::string err;
        QVERIFY(writeFileAtomic(target, "first\n", &err));
        {
            AtomicFile f(target);
            QVERIFY(f.ok());
            f.stream() << "second, never committed\n";
            // f goes out of scope without commit(): the old content must survive.
        }
        QCOMPARE(lwbtest::readAll(dir.path() + "/out.csv"), QByteArray("first\n"));
        QCOMPARE(lwbtest::filesIn(dir.path()), QStringList{"out.csv"});
        // A folder that does not exist: an error, and nothing created.
        QVERIFY(!writeFileAtomic((dir.path() + "/missing/x.csv").toStdString(), "x", &err));
        QVERIFY(err.find("missing") != std::string::npos);
        // A folder as target.
        QVERIFY(!writeFileAtomic(dir.path().toStdString(), "x", &err));
    }
};

QTEST_GUILESS_MAIN(TestCommon)
#include "test_common.moc"
