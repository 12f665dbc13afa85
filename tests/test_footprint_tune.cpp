// Issue 45: the footprint verdict criteria tuned from the analyst's verdicts (core/footprint/tune,
// laserwb-cli footprint tune). A simulated analyst judges every shot by its truth (a normal spot
// inside the wu2021 criteria good, no spot rejected, the other doubtful cases doubtful); half
// of a labelled set, drawn at random, is given to the tuning; the other half is then judged
// with the written config, as a fresh run. Asserted on the ground families the fit and the
// verdict were never tuned on (issue 32's fractal and photo-cut ground): false doubts at most
// 2 % of the good shots and misses (not-good judged good) at most 1 % of the others (the
// issue's bound), and fewer false doubts than the defaults. The simulator's own ground (photo)
// and the older synthetic ground are measured too: no more misses than 1 %, fewer false
// doubts than the defaults. Every figure is printed (docs/footprint.md quotes them).
#include <QtTest>
#include <QTemporaryDir>

#include "core/common/rng.hpp"
#include "core/common/text.hpp"
#include "core/footprint/batch.hpp"
#include "core/footprint/footprint_run.hpp"
#include "core/footprint/image_io.hpp"
#include "core/footprint/tune.hpp"
#include "core/sim/footprint_sim.hpp"
#include "test_support.hpp"

using namespace lwb::core;
using namespace lwb::core::footprint;
namespace sim = lwb::core::sim;
using lwbtest::runCli;

namespace {

// The CLI's `simulate footprint --case mixed` cycle: ten normal shots in fifteen, one of each
// doubtful case.
const sim::SpotCase kCases[] = {sim::SpotCase::Normal, sim::SpotCase::Normal,    sim::SpotCase::NoSpot,
                                sim::SpotCase::Normal, sim::SpotCase::Normal,    sim::SpotCase::Saturated,
                                sim::SpotCase::Normal, sim::SpotCase::Normal,    sim::SpotCase::DoubleSpot,
                                sim::SpotCase::Normal, sim::SpotCase::Normal,    sim::SpotCase::Edge,
                                sim::SpotCase::Normal, sim::SpotCase::Normal,    sim::SpotCase::Elongated};
const sim::Scene kScenes[] = {sim::Scene::Weak, sim::Scene::Moderate, sim::Scene::Strong, sim::Scene::Night};

// The simulated analyst's verdict of a shot.
Verdict analystVerdict(const sim::FootprintSimTruth& t) {
    if (t.expectGood) return Verdict::Good;
    return t.spotCase == sim::SpotCase::NoSpot ? Verdict::Rejected : Verdict::Doubtful;
}

struct LabelledSet {
    QString dir;
    std::vector<std::string> files;   // shot_NNNNNN.png
    std::vector<Verdict> labels;
    std::vector<bool> given;          // the half whose verdicts the tuning gets
};

// `count` shots of one ground family written as 16-bit PNGs into `dir`, the verdicts of a
// random half into dir/verdicts.csv (files relative to it).
LabelledSet simulateSet(const QString& dir, sim::GroundSource ground, int count, uint64_t seed) {
    LabelledSet s;
    s.dir = dir;
    QDir().mkpath(dir);
    sim::FootprintSimParams sp;
    sp.ground = ground;
    Rng half(Rng::mix(seed, 45));
    std::string csv = "file,verdict\n";
    for (int i = 0; i < count; ++i) {
        sp.scene = kScenes[i % 4];
        sp.spotCase = kCases[(i / 4) % 15];
        const sim::FootprintSimShot shot = sim::simulateFootprint(sp, Rng::mix(seed, static_cast<uint64_t>(i)));
        char name[32];
        std::snprintf(name, sizeof name, "shot_%06d.png", i);
        std::string err;
        if (!writeFrame16(lwbtest::str(dir) + "/" + name, shot.image, &err)) qFatal("%s", err.c_str());
        s.files.push_back(name);
        s.labels.push_back(analystVerdict(shot.truth));
        s.given.push_back(half.uniform() < 0.5);
        if (s.given.back()) csv += std::string(name) + "," + verdictName(s.labels.back()) + "\n";
    }
    lwbtest::writeText(dir + "/verdicts.csv", QByteArray::fromStdString(csv));
    return s;
}

// The confusion of the shots not given, judged by a fresh run under `config` ("" = defaults).
VerdictConfusion judgeOtherHalf(const LabelledSet& s, const std::string& config) {
    FootprintSources src;
    src.inputs = {lwbtest::str(s.dir)};
    src.configFile = config;
    FootprintSetup setup;
    FootprintError e;
    if (!setUpFootprintRun(src, &setup, &e)) qFatal("%s", e.message.c_str());
    const BatchResult run = runFootprintBatch(setup.shots, setup.params);
    VerdictConfusion c;
    for (const BatchItem& item : run.items) {
        const std::string name = item.file.substr(item.file.find_last_of('/') + 1);
        const size_t i = static_cast<size_t>(std::find(s.files.begin(), s.files.end(), name) - s.files.begin());
        if (i == s.files.size()) qFatal("unknown shot %s", name.c_str());
        if (!s.given[i]) c.add(s.labels[i], item.rois.at(0).result.verdict);
    }
    return c;
}

double pct(int k, int n) { return n ? 100.0 * k / n : 0; }

// 150 shots of synthetic ground, the scenes and cases in turn, fitted under the defaults.
struct FittedShot {
    sim::FootprintSimTruth truth;
    cv::Mat roi;
    FootprintResult result;
};
std::vector<FittedShot> fittedShots(uint64_t seed) {
    sim::FootprintSimParams sp;
    sp.ground = sim::GroundSource::Synthetic;
    std::vector<FittedShot> out;
    for (int i = 0; i < 150; ++i) {
        sp.scene = kScenes[i % 4];
        sp.spotCase = kCases[i % 15];
        const sim::FootprintSimShot shot = sim::simulateFootprint(sp, seed + static_cast<uint64_t>(i));
        FittedShot f{shot.truth, {}, {}};
        shot.image.convertTo(f.roi, CV_32F);
        f.result = processRoi(f.roi, FootprintParams{});
        out.push_back(std::move(f));
    }
    return out;
}

}  // namespace

class TestFootprintTune : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // Half the verdicts given, the other half judged, per ground family.
    void tunedOnHalfHoldsOnTheOtherHalf_data() {
        QTest::addColumn<int>("ground");
        QTest::addColumn<bool>("heldOutFamily");
        QTest::newRow("fractal") << int(sim::GroundSource::Fractal) << true;
        QTest::newRow("photo-cuts") << int(sim::GroundSource::PhotoCuts) << true;
        QTest::newRow("photo") << int(sim::GroundSource::Photo) << false;
        QTest::newRow("synthetic") << int(sim::GroundSource::Synthetic) << false;
    }
    void tunedOnHalfHoldsOnTheOtherHalf() {
        QFETCH(int, ground);
        QFETCH(bool, heldOutFamily);
        const auto g = static_cast<sim::GroundSource>(ground);
        sim::FootprintSimParams probe;
        probe.ground = g;
        if (const std::string why = sim::groundProblem(probe); !why.empty()) QSKIP(why.c_str());
        const QString dir = m_dir.path() + "/" + sim::groundSourceName(g);
        const LabelledSet s = simulateSet(dir, g, 1400, 4500 + static_cast<uint64_t>(ground));
        FootprintTuneSources src;
        src.run.inputs = {lwbtest::str(dir)};
        src.verdicts = lwbtest::str(dir + "/verdicts.csv");
        const FootprintTuneResult r = tuneFootprint(src);
        QVERIFY2(r.ok, r.error.message.c_str());
        int given = 0;
        for (bool b : s.given) given += b;
        QCOMPARE(r.labelled, size_t(given));  // every row found (relative to the table's folder)
        QCOMPARE(r.unmatchedRows, size_t(0));
        const std::string config = lwbtest::str(dir + "/tuned.json");
        std::string err;
        QVERIFY2(writeTunedFootprintConfig(r, src, config, &err), err.c_str());
        QVERIFY(QFile::exists(QString::fromStdString(config) + ".provenance.json"));
        // On the half tuned on: never more misses than the starting point.
        QVERIFY(r.tuning.confusionAfter.misses() <= r.tuning.confusionBefore.misses());
        QVERIFY(r.tuning.confusionAfter.falseDoubts() + r.tuning.confusionAfter.misses() <=
                r.tuning.confusionBefore.falseDoubts() + r.tuning.confusionBefore.misses());
        const VerdictConfusion before = judgeOtherHalf(s, ""), after = judgeOtherHalf(s, config);
        const int good = after.analystGood(), notGood = after.analystNotGood();
        QVERIFY(good > 300 && notGood > 150);
        std::string moved;
        for (const VerdictChange& c : r.tuning.changes)
            moved += " " + c.name() + " " + formatDouble(c.before, 4) + "->" + formatDouble(c.after, 4);
        qInfo("%s: other half (%d good, %d not good): false doubts %.1f %% -> %.1f %%, misses %.1f %% -> %.1f %%; "
              "cross-validated on the given half %.1f %% / %.1f %%; moved:%s",
              sim::groundSourceName(g), good, notGood, pct(before.falseDoubts(), good), pct(after.falseDoubts(), good),
              pct(before.misses(), notGood), pct(after.misses(), notGood),
              pct(r.tuning.heldOut.falseDoubts(), r.tuning.heldOut.analystGood()),
              pct(r.tuning.heldOut.misses(), r.tuning.heldOut.analystNotGood()), moved.c_str());
        QVERIFY2(after.falseDoubts() < before.falseDoubts(), "the tuning spares no good shot the defaults doubted");
        QVERIFY2(pct(after.misses(), notGood) <= 1.0, "more than 1 % of the not-good shots judged good");
        if (heldOutFamily) QVERIFY2(pct(after.falseDoubts(), good) <= 2.0, "more than 2 % of the good shots doubted");
    }

    // The verdict without reasons (the tuning's inner loop) is the verdict with them.
    void quickCheckIsTheFullCheck() {
        Rng rng(45);
        int checked = 0;
        for (const FittedShot& f : fittedShots(900)) {
            const cv::Mat& roi = f.roi;
            const FootprintResult& r = f.result;
            for (int k = 0; k < 20; ++k) {
                VerdictParams v;
                v.axisRatio = {rng.uniform() < 0.8, rng.uniform(0.5, 1.1), rng.uniform(1.1, 2.0)};
                v.majorAxisPx = {rng.uniform() < 0.8, rng.uniform(5, 12), rng.uniform(14, 25)};
                v.tiltDeg = {rng.uniform() < 0.8, -rng.uniform(10, 60), rng.uniform(10, 60)};
                v.eccentricity = {rng.uniform() < 0.5, rng.uniform(0, 0.4), rng.uniform(0.5, 1)};
                v.mseEnabled = rng.uniform() < 0.8;
                v.mseMax = std::pow(10, rng.uniform(-6, -3));
                v.maxUncertaintyPx = rng.uniform(0.1, 1.5);
                v.edgeExtent = rng.uniform(0.6, 2);
                v.saturationMaxPixels = static_cast<int>(rng.uniform(0, 5));
                v.secondSpotFraction = rng.uniform(0.2, 0.8);
                FootprintResult full = r;
                judgeResult(&full, roi.cols, roi.rows, v);
                QCOMPARE(int(checkVerdict(measureResult(r, roi.cols, roi.rows), v)), int(full.verdict));
                QCOMPARE(full.verdict == Verdict::Good, full.reasons.empty());
                ++checked;
            }
        }
        QCOMPARE(checked, 3000);
    }

    // The strip beside a slider: the verdicts along a criterion's values, as judge gives them.
    void sweepFollowsTheVerdict() {
        const FootprintParams p;
        std::vector<VerdictMeasures> shots;
        std::vector<int> labels;
        int goodNow = 0;
        for (const FittedShot& f : fittedShots(700)) {
            shots.push_back(measureResult(f.result, f.roi.cols, f.roi.rows));
            goodNow += f.result.verdict == Verdict::Good;
            labels.push_back(shots.size() % 3 == 1 ? -1 : int(analystVerdict(f.truth)));
        }
        const std::vector<double> values = {1e-7, 1e-6, p.verdict.mseMax, 1e-4, 1e-3};
        const CriterionSweep s = sweepCriterion(shots, labels, p, "verdict.mse_max", "", values);
        QCOMPARE(s.good.size(), values.size());
        QCOMPARE(s.labelled, 100);
        QCOMPARE(s.good[2], goodNow);  // at the current value: the run's own verdicts
        QCOMPARE(s.changed[2], 0);
        for (size_t k = 1; k < values.size(); ++k) QVERIFY(s.good[k] >= s.good[k - 1]);  // a looser limit passes more
        for (size_t k = 0; k < values.size(); ++k) QCOMPARE(s.changed[k], std::abs(s.good[k] - goodNow));
        QVERIFY(s.good.front() < goodNow);
        // A range's end; a row that is not a verdict threshold gives nothing.
        const CriterionSweep t = sweepCriterion(shots, {}, p, "verdict.tilt_deg", "hi", {10, 30, 60});
        QCOMPARE(t.changed[1], 0);
        QVERIFY(t.good[0] <= t.good[1] && t.good[1] <= t.good[2]);
        QCOMPARE(t.labelled, 0);
        QVERIFY(sweepCriterion(shots, {}, p, "segment.threshold_factor", "", {0.2}).good.empty());
        QVERIFY(sweepCriterion(shots, {}, p, "verdict.tilt_deg", "", {10}).good.empty());
    }

    // An analyst who agrees with every computed verdict moves nothing.
    void agreeingVerdictsMoveNothing() {
        const QString dir = m_dir.path() + "/agree";
        const LabelledSet s = simulateSet(dir, sim::GroundSource::Synthetic, 120, 7);
        const QString report = dir + "/report.csv";
        const lwbtest::CliRun run = runCli({"footprint", "-q", dir, "-o", report});
        QCOMPARE(run.exitCode, 0);
        const QString config = dir + "/tuned.json";
        const lwbtest::CliRun r = runCli({"footprint", "tune", dir, "--verdicts", report, "--config-out", config});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains("no criterion moved"), qPrintable(r.out));
        QVERIFY(r.out.contains("false doubts 0 of"));
        // The written config is the defaults: the same report again.
        const lwbtest::CliRun again = runCli({"footprint", "-q", dir, "--config", config, "-o", dir + "/again.csv"});
        QCOMPARE(again.exitCode, 0);
        QCOMPARE(lwbtest::readAll(dir + "/again.csv"), lwbtest::readAll(report));
    }

    // Bad verdict tables: what and where, nothing written.
    void badVerdictsSayWhatAndWhere() {
        const QString dir = m_dir.path() + "/bad";
        simulateSet(dir, sim::GroundSource::Synthetic, 30, 8);
        const QString out = dir + "/out.json";
        auto tune = [&](const QByteArray& table) {
            lwbtest::writeText(dir + "/v.csv", table);
            return runCli({"footprint", "tune", "-q", dir, "--verdicts", dir + "/v.csv", "--config-out", out});
        };
        lwbtest::CliRun r = tune("file,judgement\nshot_000000.png,good\n");
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("v.csv:1:") && r.err.contains("'verdict'"), qPrintable(r.err));
        r = tune("file,verdict\nshot_000000.png,good\nshot_000001.png,fine\n");
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("v.csv:3:") && r.err.contains("\"fine\""), qPrintable(r.err));
        r = tune("file,verdict\nshot_000000.png,good\nshot_000000.png,doubtful\n");
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("v.csv:3:") && r.err.contains("line 2"), qPrintable(r.err));
        r = tune("file,verdict\nelsewhere.png,good\n");
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("no shot of the inputs has a verdict"), qPrintable(r.err));
        QByteArray allGood = "file,verdict\n";
        for (int i = 0; i < 20; ++i) allGood += QByteArray("shot_0000") + (i < 10 ? "0" : "") + QByteArray::number(i) + ".png,good\n";
        r = tune(allGood);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("every shot with a verdict is good"), qPrintable(r.err));
        r = tune("file,verdict\nshot_000000.png,good\nshot_000002.png,rejected\n");
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("too few shots"), qPrintable(r.err));
        // The workbench's review export: only the rows its override column marks manual count.
        QByteArray review = "file,verdict,override\n";
        for (int i = 0; i < 30; ++i)
            review += QByteArray("shot_0000") + (i < 10 ? "0" : "") + QByteArray::number(i) + ".png," +
                      (i % 3 ? "good," : "doubtful,") + (i < 12 ? "manual" : "") + "\n";
        lwbtest::writeText(dir + "/review.csv", review);
        FootprintTuneSources src;
        src.run.inputs = {lwbtest::str(dir)};
        src.verdicts = lwbtest::str(dir + "/review.csv");
        const FootprintTuneResult fromReview = tuneFootprint(src);
        QVERIFY2(fromReview.ok, fromReview.error.message.c_str());
        QCOMPARE(fromReview.labelled, size_t(12));
        QVERIFY(std::any_of(fromReview.notes.begin(), fromReview.notes.end(),
                            [](const std::string& n) { return n.find("18 row(s)") != std::string::npos; }));
        QCOMPARE(runCli({"footprint", "tune", dir, "--config-out", out}).exitCode, 2);  // no --verdicts
        QCOMPARE(runCli({"footprint", "tune", dir, "--verdicts", dir + "/v.csv"}).exitCode, 2);  // no --config-out
        QVERIFY(!QFile::exists(out));
        QVERIFY(!QFile::exists(out + ".provenance.json"));
    }
};

QTEST_APPLESS_MAIN(TestFootprintTune)
#include "test_footprint_tune.moc"
