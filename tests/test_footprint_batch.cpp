// The footprint command as a batch job (issue 31): shot lists and frame metadata carry time,
// beam and camera into the report, `trend` reads the report, and footprint -> trend follows a
// simulated drift of the spot centre over months; --files-from, --shard, --skip-existing,
// --summary-json and the provenance sidecar.
#include <QCryptographicHash>
#include <QtTest>
#include <cmath>
#include <map>

#include "core/common/csv.hpp"
#include "core/common/json.hpp"
#include "core/common/sha256.hpp"
#include "test_support.hpp"

using lwbtest::runCli;

namespace {
lwb::core::CsvTable readTable(const QString& path) { return lwb::core::readCsv(path.toStdString()).table; }
double num(const std::string& s) { return s.empty() ? NAN : std::stod(s); }

// The simulated months: two-beam LSI frames whose nominal centres drift by kDrift px a month.
constexpr int kMonths = 4, kShotsPerMonth = 5;
constexpr double kDriftX = 1.2, kDriftY = -0.8;
const double kBeam1[2] = {60, 311}, kBeam2[2] = {228, 158};
}  // namespace

class TestFootprintBatch : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString p(const QString& name) const { return m_dir.path() + "/" + name; }
    QByteArray m_shotList;  // file,time,beam,camera,center_x,center_y of every month's frames

private slots:
    // Four months of frames, the spot centres drifting; a shot list with times and beams, as an
    // analyst keeps it beside the frames (relative paths: relative to the list's folder).
    void initTestCase() {
        QVERIFY(QDir().mkpath(p("frames")));
        m_shotList = "file,time,beam,camera,center_x,center_y\n";
        for (int m = 0; m < kMonths; ++m) {
            const double x1 = kBeam1[0] + kDriftX * m, y1 = kBeam1[1] + kDriftY * m;
            const double x2 = kBeam2[0] + kDriftX * m, y2 = kBeam2[1] + kDriftY * m;
            const QString dir = QString("month%1").arg(m);
            const auto r = runCli({"simulate", "footprint", "--full-frame", "--scene", "strong", "--count",
                                   QString::number(kShotsPerMonth), "--seed", QString::number(100 + m), "--center",
                                   QString("%1,%2").arg(x1).arg(y1), "--center", QString("%1,%2").arg(x2).arg(y2), "-q",
                                   p("frames/" + dir)});
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            for (int i = 0; i < kShotsPerMonth; ++i) {
                // Times in the forms a list may hold: a date, a date-time in UTC, one with an offset.
                const QString file = QString("%1/shot_%2.png").arg(dir).arg(i, 6, 10, QChar('0'));
                const QString time = i % 3 == 0   ? QString("2021-%1-%2").arg(m + 3, 2, 10, QChar('0')).arg(i + 10)
                                     : i % 3 == 1 ? QString("2021-%1-%2T08:30:00Z").arg(m + 3, 2, 10, QChar('0')).arg(i + 10)
                                                  : QString("2021-%1-%2T12:00:00+02:00").arg(m + 3, 2, 10, QChar('0')).arg(i + 10);
                m_shotList += QString("%1,%2,1,LSI,%3,%4\n%1,%2,2,LSI,%5,%6\n")
                                  .arg(file, time)
                                  .arg(x1)
                                  .arg(y1)
                                  .arg(x2)
                                  .arg(y2)
                                  .toUtf8();
            }
        }
        QVERIFY(lwbtest::writeText(p("frames/shots.csv"), m_shotList));
    }

    // footprint -> trend in batch: the monthly means follow the simulated truth. The truth of a
    // month is the mean of the exact spot positions (truth.csv) of the shots the trend used (the
    // report's good ones); the centres jitter by up to 3 px about the nominal drift, so the drift
    // itself is checked through that truth, not the nominal one.
    void footprintThenTrendFollowsTheTruth() {
        const auto f = runCli({"footprint", p("frames/shots.csv"), "-o", p("report.csv"), "-q"});
        QVERIFY2(f.exitCode == 0, qPrintable(f.err));
        const auto rep = readTable(p("report.csv"));
        QCOMPARE(int(rep.rows.size()), 2 * kMonths * kShotsPerMonth);
        for (const char* c : {"time", "beam", "camera"}) QVERIFY2(rep.column(c) >= 0, c);
        const auto t = runCli({"trend", p("report.csv"), "-o", p("trend.csv"), "--set", "reject_sigma=0"});
        QVERIFY2(t.exitCode == 0, qPrintable(t.err));
        // The truth of each (beam, month) over the shots the report judged good.
        std::map<std::pair<std::string, int>, std::pair<double, int>> sumX, sumY;
        int good = 0;
        for (const auto& row : rep.rows) {
            if (row[rep.column("verdict")] != "good") continue;
            ++good;
            const std::string file = row[rep.column("file")];
            const int month = file[file.find("month") + 5] - '0';
            const QString dir = p(QString("frames/month%1").arg(month));
            const auto truth = readTable(dir + "/truth.csv");
            const std::string name = file.substr(file.rfind('/') + 1);
            const std::string beam = row[rep.column("beam")];
            QCOMPARE(row[rep.column("camera")], std::string("LSI"));
            for (const auto& tr : truth.rows)
                if (tr[truth.column("file")] == name) {
                    const bool second = beam == "2";
                    auto& sx = sumX[{beam, month}];
                    auto& sy = sumY[{beam, month}];
                    sx.first += num(tr[truth.column(second ? "x2" : "x")]);
                    sy.first += num(tr[truth.column(second ? "y2" : "y")]);
                    ++sx.second;
                    ++sy.second;
                }
        }
        QVERIFY2(good >= 2 * kMonths * kShotsPerMonth * 3 / 4, qPrintable(QString("only %1 good shots").arg(good)));
        const auto tr = readTable(p("trend.csv"));
        QCOMPARE(int(tr.rows.size()), 2 * kMonths);
        std::map<std::string, std::pair<double, double>> firstTruth;
        double worst = 0, worstDrift = 0, worstDistance = 0;
        for (const auto& row : tr.rows) {
            const std::string beam = row[tr.column("beam")], month = row[tr.column("month")];
            QCOMPARE(row[tr.column("camera")], std::string("LSI"));
            const int m = std::stoi(month.substr(5)) - 3;
            QVERIFY(m >= 0 && m < kMonths);
            const auto& sx = sumX[{beam, m}];
            const auto& sy = sumY[{beam, m}];
            QCOMPARE(std::stoi(row[tr.column("n")]), sx.second);
            const double tx = sx.first / sx.second, ty = sy.first / sy.second;
            if (!firstTruth.count(beam)) firstTruth[beam] = {tx, ty};
            // Tolerance: 0.15 px on a monthly mean of strong-scene shots, whose single-shot errors
            // are about 0.1-0.3 px on the photographic ground.
            worst = std::max(worst, std::hypot(num(row[tr.column("x_mean")]) - tx, num(row[tr.column("y_mean")]) - ty));
            const double dxTrue = tx - firstTruth[beam].first, dyTrue = ty - firstTruth[beam].second;
            worstDrift = std::max(worstDrift, std::hypot(num(row[tr.column("dx_px")]) - dxTrue, num(row[tr.column("dy_px")]) - dyTrue));
            // The distance between the beams that month (the LSI frame check), against the truth's.
            const auto& ox = sumX[{beam == "1" ? "2" : "1", m}];
            const auto& oy = sumY[{beam == "1" ? "2" : "1", m}];
            const double dTrue = std::hypot(tx - ox.first / ox.second, ty - oy.first / oy.second);
            worstDistance = std::max(worstDistance, std::fabs(num(row[tr.column("beam_distance_px")]) - dTrue));
        }
        qInfo("monthly mean vs truth: worst %.3f px; drift vs true drift: worst %.3f px; beam distance: worst %.3f px",
              worst, worstDrift, worstDistance);
        QVERIFY2(worstDistance < 0.3, qPrintable(QString::number(worstDistance)));
        QVERIFY2(worst < 0.15, qPrintable(QString::number(worst)));
        QVERIFY2(worstDrift < 0.2, qPrintable(QString::number(worstDrift)));
    }

    // A folder of frames with a metadata table: the same report as the shot list gives (but the
    // order: the folder's frames by name), the time, beam and camera taken from the table.
    void metadataAnnotatesAFolder() {
        QByteArray md = "file,time,beam,camera\n";
        for (int i = 0; i < kShotsPerMonth; ++i)
            md += QString("shot_%1.png,2021-03-%2,1,LSI\n").arg(i, 6, 10, QChar('0')).arg(i + 1, 2, 10, QChar('0')).toUtf8();
        QVERIFY(lwbtest::writeText(p("frames/month0/meta.csv"), md));
        const auto r = runCli({"footprint", p("frames/month0"), "--metadata", p("frames/month0/meta.csv"), "--center",
                               QString("%1,%2").arg(kBeam1[0]).arg(kBeam1[1]), "-o", p("meta_report.csv"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const auto rep = readTable(p("meta_report.csv"));
        QCOMPARE(int(rep.rows.size()), kShotsPerMonth);
        for (int i = 0; i < kShotsPerMonth; ++i) {
            QCOMPARE(rep.rows[i][rep.column("time")], QString("2021-03-%1").arg(i + 1, 2, 10, QChar('0')).toStdString());
            QCOMPARE(rep.rows[i][rep.column("beam")], std::string("1"));
        }
        // A frame no row describes is counted on stderr; its columns stay empty.
        QVERIFY(lwbtest::writeText(p("frames/month0/meta1.csv"), "file,time,beam\nshot_000000.png,2021-03-01,1\n"));
        const auto part = runCli({"footprint", p("frames/month0"), "--metadata", p("frames/month0/meta1.csv"), "-o",
                                  p("meta_part.csv")});
        QVERIFY2(part.exitCode == 0, qPrintable(part.err));
        QVERIFY2(part.err.contains("4 of 5 shots have no row in"), qPrintable(part.err));
        // trend on a report without times says how to give them.
        const auto none = runCli({"footprint", p("frames/month1"), "-o", p("no_times.csv"), "-q"});
        QCOMPARE(none.exitCode, 0);
        const auto t = runCli({"trend", p("no_times.csv"), "-o", p("no_times_trend.csv")});
        QCOMPARE(t.exitCode, 1);
        QVERIFY2(t.err.contains("without a time or a beam") && t.err.contains("--metadata"), qPrintable(t.err));
        QVERIFY(!QFile::exists(p("no_times_trend.csv")));
    }

    // Bad shot lists: the file and line, exit 1, nothing written, and the summary says why.
    void badShotListsNameFileAndLine() {
        struct Case {
            QByteArray text;
            QString expect;
        };
        const QList<Case> cases = {
            {"name,time\na.png,2021-01-01\n", "bad.csv:1: a shot list needs a 'file' column"},
            {"file,time\nmonth0/shot_000000.png,2021-02-30\n", "bad.csv:2: time \"2021-02-30\": February 2021 has 28 days"},
            {"file,center_x\nmonth0/shot_000000.png,5\n", "bad.csv:1: center_x and center_y go together"},
            {"file,center_x,center_y\nmonth0/shot_000000.png,5,\n", "bad.csv:2: center_x and center_y go together"},
            {"file,time\n\"\",2021-01-01\n", "bad.csv:2: empty file"},
        };
        for (const Case& c : cases) {
            QVERIFY(lwbtest::writeText(p("frames/bad.csv"), c.text));
            QFile::remove(p("bad_summary.json"));
            const auto r = runCli({"footprint", p("frames/bad.csv"), "-o", p("bad_report.csv"), "--summary-json",
                                   p("bad_summary.json")});
            QCOMPARE(r.exitCode, 1);
            QVERIFY2(r.err.contains(c.expect), qPrintable(r.err));
            QVERIFY(!QFile::exists(p("bad_report.csv")));
            const auto j = lwb::core::readJsonFile(p("bad_summary.json").toStdString());
            QVERIFY2(j.ok, j.error.c_str());
            QCOMPARE(j.value["exit_code"].get<int>(), 1);
            QVERIFY(QString::fromStdString(j.value["error"].get<std::string>()).contains(c.expect));
        }
    }

    // --shard K/N: contiguous blocks; the shards' reports one after the other (their headers
    // once) are the unsharded report, byte for byte. The inputs come from --files-from on
    // standard input, a shot list among them.
    void shardsTogetherAreTheWholeRun() {
        const QByteArray list = "# the run's inputs\n" + p("frames/month1").toUtf8() + "\n\n" + p("frames/shots.csv").toUtf8() + "\n";
        lwbtest::RunOptions o;
        o.input = list;
        const QString cli = QString(LWB_CLI);
        const auto whole = lwbtest::runProgram(cli, {"footprint", "--files-from", "-", "-o", p("whole.csv"), "-q",
                                                     "--summary-json", p("whole.json")}, o);
        QVERIFY2(whole.exitCode == 0, qPrintable(whole.err));
        const QByteArray all = lwbtest::readAll(p("whole.csv"));
        const int shots = kShotsPerMonth + 2 * kMonths * kShotsPerMonth;
        QCOMPARE(int(all.count('\n')), 1 + shots);
        QByteArray joined;
        size_t counted = 0;
        for (int k = 1; k <= 3; ++k) {
            const QString out = p(QString("shard%1.csv").arg(k)), js = p(QString("shard%1.json").arg(k));
            const auto r = lwbtest::runProgram(cli, {"footprint", "--files-from", "-", "--shard", QString("%1/3").arg(k), "-o",
                                                     out, "-q", "--summary-json", js}, o);
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            const QByteArray s = lwbtest::readAll(out);
            joined += k == 1 ? s : s.mid(s.indexOf('\n') + 1);
            const auto j = lwb::core::readJsonFile(js.toStdString());
            QVERIFY2(j.ok, j.error.c_str());
            QCOMPARE(j.value["inputs_total"].get<int>(), shots);
            QCOMPARE(j.value["shard"].get<std::string>(), QString("%1/3").arg(k).toStdString());
            const size_t n = j.value["inputs"].size();
            QCOMPARE(n, size_t((k * shots) / 3 - ((k - 1) * shots) / 3));
            counted += n;
        }
        QCOMPARE(counted, size_t(shots));
        QCOMPARE(joined, all);
        // A bad share is a usage error.
        for (const QString bad : {"0/3", "4/3", "3", "a/b", "1/0"}) {
            const auto r = runCli({"footprint", p("frames/month1"), "--shard", bad, "-o", p("never.csv")});
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains("--shard must be K/N"), qPrintable(r.err));
        }
    }

    // --skip-existing: a complete report (its sidecar lists it with the checksum it has) is not
    // made again; one changed since, or made with other parameters, is.
    void skipExistingSkipsCompleteOutputs() {
        const QStringList base = {"footprint", p("frames/month2"), "-o", p("skip.csv"), "--skip-existing", "--summary-json",
                                  p("skip.json")};
        const auto first = runCli(base);
        QVERIFY2(first.exitCode == 0, qPrintable(first.err));
        QVERIFY(first.err.contains("-> " + p("skip.csv")));
        const QByteArray made = lwbtest::readAll(p("skip.csv"));
        const auto again = runCli(base);
        QCOMPARE(again.exitCode, 0);
        QVERIFY2(again.err.contains("skipped"), qPrintable(again.err));
        auto statusCounts = [&]() {
            const auto j = lwb::core::readJsonFile(p("skip.json").toStdString());
            return j.ok ? j.value["status_counts"] : lwb::core::Json();
        };
        QCOMPARE(statusCounts().value("skipped", 0), kShotsPerMonth);
        // A report changed since it was written is made again (and so is the original).
        QVERIFY(lwbtest::writeText(p("skip.csv"), made + "tampered\n"));
        const auto redo = runCli(base);
        QCOMPARE(redo.exitCode, 0);
        QVERIFY2(redo.err.contains("changed since it was written"), qPrintable(redo.err));
        QCOMPARE(lwbtest::readAll(p("skip.csv")), made);
        QCOMPARE(statusCounts().value("skipped", 0), 0);
        // A frame replaced since: made again.
        const QString frame = p("frames/month2/shot_000001.png");
        const QByteArray original = lwbtest::readAll(frame);
        QVERIFY(lwbtest::writeText(frame, lwbtest::readAll(p("frames/month2/shot_000002.png"))));
        const auto changed = runCli(base);
        QCOMPARE(changed.exitCode, 0);
        QVERIFY2(changed.err.contains("shot_000001.png: changed since the outputs were made"), qPrintable(changed.err));
        QVERIFY(lwbtest::writeText(frame, original));
        QCOMPARE(runCli(base).exitCode, 0);  // (made again from the original)
        QCOMPARE(lwbtest::readAll(p("skip.csv")), made);
        // Other parameters: made again.
        const auto other = runCli(base + QStringList{"--method", "gcm"});
        QCOMPARE(other.exitCode, 0);
        QVERIFY2(other.err.contains("other parameters"), qPrintable(other.err));
        const QByteArray remade = lwbtest::readAll(p("skip.csv"));
        QVERIFY(remade != made);
        // The summary may not land on an output of the run.
        const auto clash = runCli({"footprint", p("frames/month2"), "-o", p("skip.csv"), "--method", "gcm", "-q",
                                   "--summary-json", p("skip.csv")});
        QCOMPARE(clash.exitCode, 2);
        QVERIFY2(clash.err.contains("a file of this run"), qPrintable(clash.err));
        QCOMPARE(lwbtest::readAll(p("skip.csv")), remade);
        // Issue 41: a folder where the sidecar should be was "internal error: basic_filebuf::
        // underflow ... Is a directory". Now it is said, and the run refuses it as an output.
        QVERIFY(QFile::remove(p("skip.csv.provenance.json")));
        QVERIFY(QDir().mkpath(p("skip.csv.provenance.json")));
        const auto folder = runCli(base);
        QVERIFY2(folder.exitCode == 1 || folder.exitCode == 2, qPrintable(folder.err));
        QVERIFY2(!folder.err.contains("internal error") && folder.err.contains("skip.csv.provenance.json: is a folder"),
                 qPrintable(folder.err));
        QCOMPARE(lwbtest::readAll(p("skip.csv")), remade);
        QVERIFY(QDir(p("skip.csv.provenance.json")).removeRecursively());
    }

    // The sidecar: version, parameters, settings, and the SHA-256 of every input and output,
    // the same for the same run (no clock in it).
    void provenanceSidecarRecordsTheRun() {
        const auto r = runCli({"footprint", p("frames/shots.csv"), "-o", p("prov.csv"), "-q", "--set", "roi.size=28"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QByteArray side = lwbtest::readAll(p("prov.csv.provenance.json"));
        const auto j = lwb::core::parseJson(side.toStdString(), "sidecar");
        QVERIFY2(j.ok, j.error.c_str());
        QCOMPARE(j.value["command"].get<std::string>(), std::string("footprint"));
        QVERIFY(!j.value["version"].get<std::string>().empty());
        QCOMPARE(j.value["parameters"]["roi"]["size"].get<int>(), 28);
        auto sha = [](const QString& f) {
            return QCryptographicHash::hash(lwbtest::readAll(f), QCryptographicHash::Sha256).toHex().toStdString();
        };
        const auto& inputs = j.value["inputs"];
        QCOMPARE(int(inputs.size()), 1 + kMonths * kShotsPerMonth);  // the list and its frames (each once)
        for (const auto& in : inputs)
            QCOMPARE(in["sha256"].get<std::string>(), sha(QString::fromStdString(in["path"].get<std::string>())));
        QCOMPARE(j.value["outputs"][0]["sha256"].get<std::string>(), sha(p("prov.csv")));
        // Our SHA-256 against the standard's examples (FIPS 180-4 appendix).
        QCOMPARE(lwb::core::sha256Hex("abc"), std::string("ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"));
        QCOMPARE(lwb::core::sha256Hex(std::string(1000000, 'a')),
                 std::string("cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0"));
        QCOMPARE(lwb::core::sha256Hex(""), std::string("e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855"));
        // Reproducible: the same run again writes the same sidecar.
        QVERIFY(QFile::remove(p("prov.csv")) && QFile::remove(p("prov.csv.provenance.json")));
        const auto r2 = runCli({"footprint", p("frames/shots.csv"), "-o", p("prov.csv"), "-q", "--set", "roi.size=28"});
        QCOMPARE(r2.exitCode, 0);
        QCOMPARE(lwbtest::readAll(p("prov.csv.provenance.json")), side);
    }
};

QTEST_GUILESS_MAIN(TestFootprintBatch)
#include "test_footprint_batch.moc"
