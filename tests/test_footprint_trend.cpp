// Long-term centroid monitoring against paper 001's published monthly means (Tables 2 and 3).
#include <QtTest>

#include "core/footprint/trend.hpp"
#include "test_support.hpp"

using namespace lwb::core::footprint;

namespace {
// Paper 001 Table 3 (LSI) and Table 2 (LFI) monthly means, pixels, as published.
struct Month {
    const char* month;
    double lfi1x, lfi1y, lfi2x, lfi2y, lsi1x, lsi1y, lsi2x, lsi2y, lsiDistanceChange;
};
const Month kTable[] = {
    {"2020-03", 120.83, 263.71, 216.32, 162.51, 57.18, 313.10, 228.01, 156.67, 0},
    {"2020-04", 120.50, 264.51, 216.88, 162.63, 56.93, 313.35, 228.63, 156.31, 1.05},
    {"2020-05", 120.35, 263.88, 216.85, 162.56, 56.51, 313.39, 228.84, 156.14, 1.66},
    {"2020-06", 120.37, 263.79, 216.87, 162.36, 56.41, 313.35, 228.79, 156.09, 1.71},
    {"2020-07", 120.52, 263.90, 216.93, 162.10, 56.52, 313.32, 228.81, 156.29, 1.48},
    {"2020-08", 120.63, 263.28, 216.81, 161.65, 56.08, 313.68, 228.77, 156.18, 2.09},
    {"2020-09", 120.51, 262.26, 216.72, 161.53, 55.99, 313.75, 228.68, 156.22, 2.11},
    {"2020-10", 120.11, 261.85, 216.35, 161.60, 55.77, 313.63, 228.82, 156.62, 2.03},
    {"2020-11", 120.33, 262.02, 216.42, 161.64, 56.08, 314.031, 228.71, 156.22, 2.26},
    {"2020-12", 120.37, 262.30, 216.31, 161.82, 55.93, 313.74, 228.67, 156.50, 1.95},
    {"2021-01", 120.49, 262.55, 216.00, 161.65, 56.22, 313.62, 228.56, 156.62, 1.49},
    {"2021-02", 120.36, 262.55, 216.81, 161.17, 56.50, 313.51, 228.79, 156.49, 1.47},
    {"2021-03", 120.45, 262.67, 216.62, 161.68, 56.47, 313.62, 228.59, 156.56, 1.38},
    {"2021-04", 120.43, 262.63, 216.63, 161.07, 56.48, 312.99, 228.82, 156.25, 1.33},
};

QByteArray tableCsv() {
    QByteArray csv = "time,beam,x,y,camera\n";
    for (const Month& m : kTable) {
        const QString day = QString(m.month) + "-15T12:00:00Z";
        csv += QString("%1,1,%2,%3,LFI\n").arg(day).arg(m.lfi1x).arg(m.lfi1y).toUtf8();
        csv += QString("%1,2,%2,%3,LFI\n").arg(day).arg(m.lfi2x).arg(m.lfi2y).toUtf8();
        csv += QString("%1,1,%2,%3,LSI\n").arg(day).arg(m.lsi1x).arg(m.lsi1y).toUtf8();
        csv += QString("%1,2,%2,%3,LSI\n").arg(day).arg(m.lsi2x).arg(m.lsi2y).toUtf8();
    }
    return csv;
}
}  // namespace

class TestFootprintTrend : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void lsiDistanceChangeReproducesTable3() {
        const QString in = m_dir.path() + "/table.csv";
        QVERIFY(lwbtest::writeText(in, tableCsv()));
        std::vector<CentroidRecord> recs;
        std::string err;
        QVERIFY2(readCentroidCsv(in.toStdString(), &recs, &err), err.c_str());
        const TrendResult tr = computeTrend(recs, TrendParams{});
        QVERIFY2(tr.ok, tr.error.c_str());
        int checked = 0;
        for (const TrendRow& r : tr.rows) {
            if (r.camera != "LSI" || r.beam != "1") continue;
            for (const Month& m : kTable)
                if (r.month == m.month) {
                    // Published to 0.01 px from means published to 0.01 px: agree within 0.02 px.
                    QVERIFY2(std::fabs(r.distanceChangePx - m.lsiDistanceChange) <= 0.02,
                             qPrintable(QString("%1: %2 vs %3").arg(m.month).arg(r.distanceChangePx).arg(m.lsiDistanceChange)));
                    ++checked;
                }
        }
        QCOMPARE(checked, 14);
    }

    void lfiPlanarChangeMatchesThePaper() {
        // Paper 001 §3.2: beam 1 planar change ≈ 1.1 px ≈ 0.341″, beam 2 ≈ 1.4 px ≈ 0.434″ (at
        // 0.31″/px), from the first month to the last. Published to one decimal: ±0.1 px.
        const QString in = m_dir.path() + "/table2.csv";
        QVERIFY(lwbtest::writeText(in, tableCsv()));
        std::vector<CentroidRecord> recs;
        std::string err;
        QVERIFY(readCentroidCsv(in.toStdString(), &recs, &err));
        const TrendResult tr = computeTrend(recs, TrendParams{});
        QVERIFY(tr.ok);
        double b1 = -1, b2 = -1;
        for (const TrendRow& r : tr.rows)
            if (r.camera == "LFI" && r.month == "2021-04") (r.beam == "1" ? b1 : b2) = r.planarPx;
        QVERIFY(std::fabs(b1 - 1.1) <= 0.1);
        QVERIFY(std::fabs(b2 - 1.4) <= 0.1);
        QVERIFY(std::fabs(b1 * 0.31 - 0.341) <= 0.035);
        QVERIFY(std::fabs(b2 * 0.31 - 0.434) <= 0.035);
    }

    void monthlyMeansAndRejection() {
        // 40 shots around (100, 200) with one wild shot: the 3σ rejection removes it.
        std::vector<CentroidRecord> recs;
        for (int i = 0; i < 40; ++i) recs.push_back({"2020-05", "LFI", "1", 100 + 0.1 * ((i % 5) - 2), 200 + 0.1 * ((i % 3) - 1), i + 2});
        recs.push_back({"2020-05", "LFI", "1", 150, 120, 99});
        TrendResult tr = computeTrend(recs, TrendParams{});
        QVERIFY(tr.ok);
        QCOMPARE(tr.rows.size(), size_t(1));
        QCOMPARE(tr.rows[0].rejected, 1);
        QVERIFY(std::fabs(tr.rows[0].xMean - 100) < 1e-9 && std::fabs(tr.rows[0].yMean - 200) < 0.01);
        TrendParams off;
        off.rejectSigma = 0;
        tr = computeTrend(recs, off);
        QCOMPARE(tr.rows[0].rejected, 0);
        QVERIFY(tr.rows[0].xMean > 101);
    }

    void timeFormats() {
        std::string m;
        QVERIFY(monthOf("2020-03-15", &m) && m == "2020-03");
        QVERIFY(monthOf("2020/11/02 10:22", &m) && m == "2020-11");
        QVERIFY(monthOf("2021-04", &m) && m == "2021-04");
        QVERIFY(monthOf("1584230400", &m) && m == "2020-03");  // 2020-03-15 00:00 UTC
        QVERIFY(!monthOf("15/03/2020", &m));
        QVERIFY(!monthOf("2020-13-01", &m));
        // Issue 27: dates that do not exist, garbage after the date, and offsets that change the month.
        std::string why;
        QVERIFY(!monthOf("2021-02-30", &m, &why));
        QCOMPARE(why, std::string("February 2021 has 28 days"));
        QVERIFY(monthOf("2024-02-29", &m) && m == "2024-02");
        QVERIFY(!monthOf("2021-01-05Tgarbage", &m, &why));
        QVERIFY2(why.find("hh:mm") != std::string::npos, why.c_str());
        QVERIFY(!monthOf("2021-01-05T10:00:00 junk", &m));
        QVERIFY(!monthOf("2021-01-05T24:00", &m));
        QVERIFY(monthOf("2021-01-31T23:30-02:00", &m) && m == "2021-02");  // 01:30 UTC on 1 February
        QVERIFY(monthOf("2021-03-01T00:30+01:00", &m) && m == "2021-02");
        QVERIFY(monthOf("2021-03-01T00:30+0100", &m) && m == "2021-02");
        QVERIFY(monthOf("2016-12-31T23:59:60Z", &m) && m == "2016-12");   // a leap second
        QVERIFY(monthOf("2017-01-01T07:59:60+08:00", &m) && m == "2016-12");
        QVERIFY(!monthOf("2016-12-31T12:00:60Z", &m, &why));
        QVERIFY(monthOf("2020-03-15T10:22:01.25Z", &m) && m == "2020-03");
        QVERIFY(!monthOf("yesterday", &m));
    }

    void badCsvNamesTheLine() {
        const QString in = m_dir.path() + "/bad.csv";
        QVERIFY(lwbtest::writeText(in, "time,beam,x,y\n2020-03-01,1,10,20\n2020-03-02,1,abc,20\n"));
        std::vector<CentroidRecord> recs;
        std::string err;
        QVERIFY(!readCentroidCsv(in.toStdString(), &recs, &err));
        QVERIFY2(err.find("bad.csv:3:") != std::string::npos, err.c_str());
        QVERIFY(lwbtest::writeText(in, "when,beam,x,y\n2020-03-01,1,10,20\n"));
        QVERIFY(!readCentroidCsv(in.toStdString(), &recs, &err));
        QVERIFY(err.find("time") != std::string::npos);
    }
};

QTEST_GUILESS_MAIN(TestFootprintTrend)
#include "test_footprint_trend.moc"
