// Validation statistics of paper 002 (tables 5 and 6): the published means, "RMSE" and lake
// standard deviations reproduced from the published input numbers, and which statistic each
// published figure is.
#include <QtTest>

#include "core/calib/validation_stats.hpp"
#include "test_support.hpp"

using namespace lwb::core::calib;

namespace {
// Paper 002 table 6, laser − control (m), as printed (ALGORITHMS.md §3).
const std::vector<double> kFlatBeam1 = {0.173, 0.183, 0.137, -0.026, -0.056, -0.070, -0.008, 0.087,  0.111, 0.125, 0.149,
                                        0.158, -0.004, 0.094, 0.101, 0.068, -0.006, -0.036, -0.135, -0.104, -0.056, -0.034};
const std::vector<double> kFlatBeam2 = {-0.125, -0.186, -0.262, -0.082, 0.004, -0.024, -0.077, -0.125,
                                        0.008,  0.066,  0.087,  0.113,  0.042, 0.061,  0.117,  0.023,
                                        0.137,  0.026,  0.126,  0.103,  0.100, 0.053,  -0.073, 0.059};
// Paper 002 table 5, lake heights (m).
const std::vector<double> kLakeBeam1 = {10.745765, 10.796222, 10.69541, 10.671369, 10.72016, 10.73029, 10.659727};
const std::vector<double> kLakeBeam2 = {8.675473, 8.66211, 8.682429, 8.786174};

// The paper prints three decimals: a reproduced figure must round to it (|x − p| ≤ 0.0005 m).
constexpr double kRound3 = 0.0005;

ElevationStats statsOf(const std::vector<double>& d) {
    const ElevationStatsResult r = elevationStats(d);
    if (!r.ok) qFatal("%s", r.error.c_str());
    return r.stats;
}
}  // namespace

class TestCalibStats : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void flatGroundMeansMatchThePaper() {
        const ElevationStats b1 = statsOf(kFlatBeam1), b2 = statsOf(kFlatBeam2);
        QCOMPARE(b1.n, 22);
        QCOMPARE(b2.n, 24);
        QVERIFY2(std::fabs(b1.mean - 0.039) <= kRound3, std::to_string(b1.mean).c_str());  // published AVE 0.039
        QVERIFY2(std::fabs(b2.mean - 0.007) <= kRound3, std::to_string(b2.mean).c_str());  // published AVE 0.007
    }

    // Which statistic is the paper's "RMSE" (中误差)? Beam 1's 0.097 m is the sample standard
    // deviation about the mean (n − 1); its RMS about zero (0.103) and population std (0.095) do
    // not round to 0.097. Beam 2's 0.104 m is the RMS about zero (0.1040; the population std,
    // 0.1038, rounds the same), while its sample std is 0.106. The paper is not consistent, so
    // the code labels every statistic and calls none of them "RMSE".
    void beam1RmseIsTheSampleStandardDeviation() {
        const ElevationStats s = statsOf(kFlatBeam1);
        QVERIFY2(std::fabs(s.stdSample - 0.097) <= kRound3, std::to_string(s.stdSample).c_str());
        QVERIFY(std::fabs(s.rmsAboutZero - 0.097) > 0.004);   // 0.103: not what was published
        QVERIFY(std::fabs(s.stdPopulation - 0.097) > 0.001);  // 0.095: not what was published
    }
    void beam2RmseIsTheRmsAboutZero() {
        const ElevationStats s = statsOf(kFlatBeam2);
        QVERIFY2(std::fabs(s.rmsAboutZero - 0.104) <= kRound3, std::to_string(s.rmsAboutZero).c_str());
        QVERIFY(std::fabs(s.stdSample - 0.104) > 0.001);  // 0.106: not what was published
    }
    void lakeStandardDeviationsAreSampleStd() {
        // Table 5: published std 0.047 (beam 1, 7 points) and 0.057 (beam 2, 4 points).
        const ElevationStats b1 = statsOf(kLakeBeam1), b2 = statsOf(kLakeBeam2);
        QVERIFY2(std::fabs(b1.stdSample - 0.047) <= kRound3, std::to_string(b1.stdSample).c_str());
        QVERIFY2(std::fabs(b2.stdSample - 0.057) <= kRound3, std::to_string(b2.stdSample).c_str());
        // The population (n) formula would give 0.043 and 0.049: the paper used n − 1.
        QVERIFY(std::fabs(b1.stdPopulation - 0.047) > 0.003);
        QVERIFY(std::fabs(b2.stdPopulation - 0.057) > 0.006);
    }
    void minMaxMedianOfTheTable() {
        const ElevationStats s = statsOf(kFlatBeam2);
        QCOMPARE(s.min, -0.262);  // the table's smallest difference (row 3)
        QCOMPARE(s.max, 0.137);   // and its largest (row 17)
        const ElevationStats t = statsOf({1.0, 3.0, 2.0, 10.0});
        QCOMPARE(t.median, 2.5);  // even count: mean of the middle two
        QCOMPARE(t.meanAbs, 4.0);
    }
    void everyStatisticIsLabelled() {
        const auto rows = labelledStats(statsOf(kFlatBeam1));
        QStringList keys;
        for (const auto& r : rows) {
            keys << QString::fromStdString(r.key);
            QVERIFY(!r.label.empty());
        }
        for (const char* k : {"n", "mean", "rms_about_zero", "std_sample", "std_population", "min", "max"})
            QVERIFY2(keys.contains(k), k);
        // The labels say which published "RMSE" each one is.
        for (const auto& r : rows) {
            if (r.key == "rms_about_zero") QVERIFY(r.label.find("beam 2 'RMSE'") != std::string::npos);
            if (r.key == "std_sample") QVERIFY(r.label.find("beam 1 'RMSE'") != std::string::npos);
        }
    }
    void singleValueHasNoSampleStd() {
        const ElevationStats s = statsOf({0.5});
        QVERIFY(std::isnan(s.stdSample));
        QCOMPARE(s.rmsAboutZero, 0.5);
    }
    void badInputsGiveClearErrors() {
        QVERIFY(!elevationStats({}).ok);
        const ElevationStatsResult r = elevationStats({0.1, NAN, 0.2});
        QVERIFY(!r.ok);
        QVERIFY2(r.error.find("2") != std::string::npos, r.error.c_str());  // names the position
    }
    void csvGroupsAndLaserMinusControl() {
        const QString p = m_dir.path() + "/d.csv";
        QVERIFY(lwbtest::writeText(p, "beam,laser,control\n1,1046.096,1045.923\n2,1053.565,1053.690\n1,1043.427,1043.244\n"));
        std::vector<DifferenceGroup> g;
        std::string err;
        QVERIFY2(readDifferencesCsv(p.toStdString(), "beam", &g, &err), err.c_str());
        QCOMPARE(g.size(), size_t(2));
        QCOMPARE(g[0].group, std::string("1"));
        QCOMPARE(g[0].d.size(), size_t(2));
        QVERIFY(std::fabs(g[0].d[0] - 0.173) < 1e-9);   // table 6 row 1, beam 1
        QVERIFY(std::fabs(g[1].d[0] + 0.125) < 1e-9);   // table 6 row 1, beam 2
    }
    void malformedCsvNamesTheLine() {
        const QString p = m_dir.path() + "/bad.csv";
        QVERIFY(lwbtest::writeText(p, "d\n0.1\n0.2\nabc\n"));
        std::vector<DifferenceGroup> g;
        std::string err;
        QVERIFY(!readDifferencesCsv(p.toStdString(), "", &g, &err));
        QVERIFY2(err.find(":4:") != std::string::npos, err.c_str());
        QVERIFY(lwbtest::writeText(p, "d\n0.1\nnan\n"));
        QVERIFY(!readDifferencesCsv(p.toStdString(), "", &g, &err));
        QVERIFY2(err.find(":3:") != std::string::npos, err.c_str());
    }
};

QTEST_GUILESS_MAIN(TestCalibStats)
#include "test_calib_stats.moc"
