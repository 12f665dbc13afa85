// Issue 13: hard SLR passes and station-grade normal points.
//  - Simulated passes with exact truth (core/sim/slr_sim): a low pass from a noisy station with
//    gaps and a steep, curved O-C drift; daylight at 2–5 % signal; a track broken by 30–120 s
//    gaps; a last segment at another level after a gap. Default automatic screening; F1 against
//    the truth column.
//  - Track following (screen_follow.hpp) on a hand-made track: a piece beyond a gap is found,
//    pure noise is not followed.
//  - The Sun's elevation, the station position from the shared SINEX, the C1 fire rate.
//  - The shared frd/npt pairs: `laserwb-cli slr` with default settings against the station's own
//    normal points (see normalPointsAgainstTheStation).
#include <QtTest>
#include <Eigen/Dense>
#include <cctype>
#include <cmath>
#include <set>

#include "core/common/rng.hpp"
#include "core/sim/slr_sim.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/ilrs_tables.hpp"
#include "core/slr/np_context.hpp"
#include "core/slr/np_compare.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/pass_run.hpp"
#include "core/slr/postfit.hpp"
#include "core/slr/screen.hpp"
#include "core/slr/screen_follow.hpp"
#include "core/slr/sinex.hpp"
#include "core/slr/slr_run.hpp"
#include "core/slr/solar.hpp"
#include "test_support.hpp"

using namespace lwb::core;
using namespace lwb::core::slr;
namespace sim = lwb::core::sim;

namespace {

struct F1 {
    double precision = 0, recall = 0, f1 = 0;
};

F1 score(const std::vector<uint8_t>& accepted, const std::vector<uint8_t>& truth) {
    long long tp = 0, fp = 0, fn = 0;
    for (size_t i = 0; i < truth.size(); ++i) {
        tp += accepted[i] && truth[i];
        fp += accepted[i] && !truth[i];
        fn += !accepted[i] && truth[i];
    }
    F1 f;
    f.precision = tp + fp ? double(tp) / double(tp + fp) : 0;
    f.recall = tp + fn ? double(tp) / double(tp + fn) : 0;
    f.f1 = f.precision + f.recall > 0 ? 2 * f.precision * f.recall / (f.precision + f.recall) : 0;
    return f;
}

// The hard simulated cases (the same as `laserwb-cli simulate slr` options in docs/slr-detection.md).
sim::SlrSimParams hardCase(const QString& name) {
    std::string err;
    if (name.startsWith("leo")) {
        sim::SlrSimParams p = sim::slrSimPreset(sim::SlrKind::Leo);
        p.driftSPerS = 4e-9;
        if (name == "leo gaps night 30%") {
            p.signalFraction = 0.3;
            p.driftSPerS2 = 0.02e-9;
            sim::parseSlrGaps("150:45,330:90", &p.gaps, &err);
        } else if (name == "leo gaps + level shift") {
            p.signalFraction = 0.3;
            sim::parseSlrGaps("150:45,400:60:80", &p.gaps, &err);
        } else if (name == "leo day 3%") {
            p.daylight = true;
            p.points = 18000;
            p.durationS = 900;
            p.signalFraction = 0.03;
            p.driftSPerS2 = 0.01e-9;
        } else if (name == "leo day 2%") {
            p.daylight = true;
            p.points = 18000;
            p.durationS = 900;
            p.signalFraction = 0.02;
        }
        return p;
    }
    if (name == "khz day 3% gap") {
        sim::SlrSimParams p = sim::slrSimPreset(sim::SlrKind::Khz);
        p.daylight = true;
        p.points = 18000;
        p.durationS = 900;
        p.signalFraction = 0.03;
        sim::parseSlrGaps("200:60", &p.gaps, &err);
        return p;
    }
    if (name == "conventional gaps 30/60/120 s") {
        sim::SlrSimParams p = sim::slrSimPreset(sim::SlrKind::Conventional);
        p.signalFraction = 0.1;
        p.points = 15000;
        p.durationS = 1200;
        sim::parseSlrGaps("200:30,500:60,800:120", &p.gaps, &err);
        return p;
    }
    sim::SlrSimParams p = sim::slrSimPreset(sim::SlrKind::Diffuse);  // "diffuse day 5% gap"
    p.daylight = true;
    p.signalFraction = 0.05;
    sim::parseSlrGaps("100:40", &p.gaps, &err);
    return p;
}

// A simulated pass as the screening takes it (epochs, O-C as simulated, times of flight).
slr::PassData passOf(const sim::SlrSimPass& s, double altitudeKm) {
    slr::PassData pass;
    pass.t = s.epochS;
    pass.oc = s.ocS;
    pass.tof = s.tofS;
    pass.altitudeKm = altitudeKm;
    return pass;
}

}  // namespace

class TestSlrHard : public QObject {
    Q_OBJECT
private slots:
    // ---------------------------------------------------------------- ILRS tables (issues 29, 43)
    // The shipped tables parse, and a pass takes its normal-point bin from the missions table
    // and its station's day or night from the stations table: without a SINEX file, hy2c pass 6
    // (GLSL, a night pass) forms the normal points it forms with the SLRF2014 SINEX given.
    // The missions table (issue 43) holds the ILRS satellites past and present that its sources
    // identify (resources/ilrs/README.md): each once by ILRS id, SIC, NORAD and name.
    void ilrsTablesGiveBinAndStation() {
        const auto& missions = slr::ilrsMissions();
        QVERIFY2(missions.size() >= 150, qPrintable(QString::number(missions.size())));
        std::set<long> ids, sics, norads;
        std::set<std::string> names;
        size_t gnss = 0;
        for (const auto& m : missions) {
            QVERIFY2(m.npBinS > 0 && m.altitudeKm > 0 && !m.source.empty(), m.name.c_str());
            QVERIFY2(m.ilrsId.size() == 7 && m.ilrsId.find_first_not_of("0123456789") == std::string::npos, m.name.c_str());
            QVERIFY2(ids.insert(std::stol(m.ilrsId)).second, m.ilrsId.c_str());
            QVERIFY2(m.sic < 0 || sics.insert(m.sic).second, m.name.c_str());
            QVERIFY2(m.norad < 0 || norads.insert(m.norad).second, m.name.c_str());
            std::string letters;  // findMission's name key: letters and digits, lower case
            for (char c : m.name)
                if (std::isalnum(static_cast<unsigned char>(c))) letters += char(std::tolower(static_cast<unsigned char>(c)));
            QVERIFY2(names.insert(letters).second, m.name.c_str());
            // Each row is found by its own ids and name.
            QCOMPARE(slr::findMission("", m.ilrsId), &m);
            QCOMPARE(slr::findMission(letters, ""), &m);
            // A bin from the altitude class agrees with the class of the nominal altitude.
            if (m.source == "class") QCOMPARE(m.npBinS, slr::normalPointBinS(m.altitudeKm));
            for (const char* g : {"gps", "glonass", "galileo", "giove", "compass", "qzs", "irnss"})
                gnss += letters.rfind(g, 0) == 0;
        }
        QVERIFY2(gnss >= 80, qPrintable(QString::number(gnss)));
        // The ILRS's own bins: ERS-2 (785 km) 15 s where a pass's altitude estimate gave 30 s;
        // ICESat (586-594 km) the 15 s of its class; GRACE and Sentinel-3 the ILRS table's examples.
        auto bin = [](const char* name, const char* id) {
            const slr::IlrsMission* m = slr::findMission(name, id);
            return m && m == slr::findMission(name, "") ? m->npBinS : -1.0;
        };
        QCOMPARE(bin("ers2", "9502101"), 15.0);
        QCOMPARE(bin("icesat", "0300201"), 15.0);
        QCOMPARE(bin("gracea", "0201201"), 5.0);
        QCOMPARE(bin("sentinel3a", "1601101"), 15.0);
        QCOMPARE(bin("topex", "9205201"), 15.0);
        QCOMPARE(bin("gps35", "9305401"), 300.0);
        QCOMPARE(bin("glonass134", "1407501"), 300.0);
        QCOMPARE(bin("galileo101", "1106001"), 300.0);
        const slr::IlrsMission* l1 = slr::findMission("", "7603901");  // LAGEOS-1 by its ILRS id alone
        QVERIFY(l1 && l1->name == "LAGEOS-1" && l1->npBinS == 120 && l1->sic == 1155 && l1->norad == 8820);
        QCOMPARE(slr::findMission("", "", 4146)->name, std::string("Etalon-2"));  // Etalon-2's SIC (was 526)
        // The lunar reflectors, by the ids the CRD H3 records give them (no NORAD).
        for (const char* r : {"apollo11", "apollo14", "apollo15", "luna17", "luna21"}) {
            const slr::IlrsMission* m = slr::findMission(r, "");
            QVERIFY2(m && m->norad < 0 && m->source.rfind("lunar", 0) == 0 && m->altitudeKm > 350000, r);
        }
        QCOMPARE(slr::findMission("", "103", 103), slr::findMission("apollo15", ""));
        const slr::IlrsMission* j = slr::findMission("JASON1", "0105501");
        QVERIFY(j && j->npBinS == 15);
        QCOMPARE(slr::findMission("jason1", "105501"), j);  // the CRD v2 samples' spelling
        QCOMPARE(slr::findMission("", "", 4378), j);        // by SIC
        QCOMPARE(slr::findMission("no such satellite", "9999999"), static_cast<const slr::IlrsMission*>(nullptr));
        QVERIFY(slr::ilrsStations().size() >= 150);
        const slr::IlrsStation* mlrs = slr::findStation(7080);
        QVERIFY(mlrs && std::fabs(mlrs->latDeg - 30.680) < 0.01 && std::fabs(mlrs->lonDeg + 104.015) < 0.01);
        QCOMPARE(slr::findStation(1), static_cast<const slr::IlrsStation*>(nullptr));

        if (!lwbtest::haveShared("slr/hy2c_202109.fr2")) QSKIP("shared data not found");
        const slr::PassInputResult in = slr::loadPass(lwbtest::sharedPath("slr/hy2c_202109.fr2").toStdString(), 5, {});
        QVERIFY2(in.ok, in.error.c_str());
        const slr::SinexReadResult snx =
            slr::readSinex(lwbtest::sharedPath("slr/SLRF2014_POS+VEL_2030.0_200428.snx").toStdString());
        QVERIFY2(snx.ok, snx.error.c_str());
        slr::PassSettings without, with;
        std::string err;
        QVERIFY(slr::passSettings(in.pass, slr::SlrParams{}, nullptr, "", nullptr, &without, &err));
        QVERIFY(slr::passSettings(in.pass, slr::SlrParams{}, nullptr, "", &snx.file, &with, &err));
        QCOMPARE(without.params.postfit.binLengthS, 30.0);  // HY-2C, 957 km: the 800-2000 km class
        QVERIFY(std::fabs(without.params.postfit.stationLatDeg - with.params.postfit.stationLatDeg) < 0.01);
        const slr::PassRunResult a = slr::runPass(in.pass, without.params), b = slr::runPass(in.pass, with.params);
        QVERIFY(a.postOk && b.postOk);
        QCOMPARE(a.post.normalPoints.size(), b.post.normalPoints.size());
        QCOMPARE(a.post.normalPoints.size(), size_t(6));  // 3 points a bin by night (5 with the day minimum)
        for (size_t k = 0; k < a.post.normalPoints.size(); ++k)
            QVERIFY(std::fabs(a.post.normalPoints[k].ocS - b.post.normalPoints[k].ocS) < 1e-15);
    }

    // The bins of the shared real passes and of the simulated kinds come from the missions table
    // (issue 43): each pass's bin is its satellite's row, said so; the simulator's satellites
    // other than LAGEOS-1 (simsat-*, ids 9999901/9999/99999) are in no row and keep the altitude
    // rule (bin 0 here), said so.
    void ilrsBinsOfSharedAndSimulatedPasses() {
        auto settingsOf = [](const std::string& path, slr::PassSettings* out, const slr::IlrsMission** m) {
            const slr::PassInputResult in = slr::loadPass(path, -1, {});
            QVERIFY2(in.ok, in.error.c_str());
            *m = slr::findMission(in.pass.crd->passes[size_t(in.pass.passIndex)].target);
            std::string err;
            QVERIFY2(slr::passSettings(in.pass, slr::SlrParams{}, nullptr, "", nullptr, out, &err), err.c_str());
        };
        auto noted = [](const slr::PassSettings& s, const std::string& what) {
            for (const auto& n : s.notes)
                if (n.find(what) != std::string::npos) return true;
            return false;
        };
        QTemporaryDir dir;
        for (sim::SlrKind kind : {sim::SlrKind::Khz, sim::SlrKind::Conventional, sim::SlrKind::Diffuse, sim::SlrKind::Leo}) {
            const sim::SlrSimParams sp = sim::slrSimPreset(kind);
            const sim::SlrSimPass p = sim::simulateSlrPass(sp, 1);
            QVERIFY2(p.ok, p.error.c_str());
            const QString path = dir.path() + "/" + sim::slrKindName(kind) + ".frd";
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(QByteArray::fromStdString(sim::slrPassCrd(sp, p)));
            f.close();
            slr::PassSettings s;
            const slr::IlrsMission* m = nullptr;
            settingsOf(path.toStdString(), &s, &m);
            if (kind == sim::SlrKind::Conventional) {  // "lageos1 7603901 1155 8820"
                QVERIFY(m && m->name == "LAGEOS-1");
                QCOMPARE(s.params.postfit.binLengthS, 120.0);
                QVERIFY(noted(s, "s for LAGEOS-1 (ILRS missions table: "));
            } else {
                QVERIFY2(!m, sim::slrKindName(kind));
                QCOMPARE(s.params.postfit.binLengthS, 0.0);
                QVERIFY(noted(s, "satellite not in the ILRS missions table"));
            }
        }
        const std::pair<const char*, double> shared[] = {
            {"blits_201206.frd", 30}, {"7080_JASON1_crd_071220_2033_0.frd", 15}, {"7080_STELLA_crd_071220_2128_0.frd", 30},
            {"beaconc_20070511.frd", 15}, {"7080_Beacon-C_crd_071220_1715_0.frd", 15}, {"hy2c_202109.fr2", 30}};
        if (!lwbtest::haveShared("slr/hy2c_202109.fr2")) QSKIP("shared data not found");
        for (const auto& [file, expected] : shared) {
            slr::PassSettings s;
            const slr::IlrsMission* m = nullptr;
            settingsOf(lwbtest::sharedPath(QString("slr/") + file).toStdString(), &s, &m);
            QVERIFY2(m, file);
            QVERIFY2(s.params.postfit.binLengthS == m->npBinS && m->npBinS == expected, file);
            QVERIFY2(noted(s, "s for " + m->name + " (ILRS missions table: " + m->source + ")"), file);
        }
    }

    // The station's check against a prediction (issue 29): the range and time bias fitted to the
    // kept O-C recover the simulator's truth within 3 sigma (plus 10 ps for the range bias), for
    // three seeds and two kinds; the
    // sigmas are small against the biases drawn (|b| up to 20 ns, |tau| up to 2 ms for LEO).
    // Without a CPF (O-C against the pass's own TOF trend) there is none, and it says why.
    void rangeAndTimeBiasAgainstThePrediction() {
        for (sim::SlrKind kind : {sim::SlrKind::Leo, sim::SlrKind::Conventional})
            for (uint64_t seed = 1; seed <= 3; ++seed) {
                sim::SlrSimParams sp = sim::slrSimPreset(kind);
                sp.signalFraction = 0.3;
                const sim::SlrSimPass s = sim::simulateSlrPass(sp, seed);
                QVERIFY2(s.ok, s.error.c_str());
                slr::PassData pass = passOf(s, sp.altitudeKm);
                pass.ocOrigin = "CPF prediction";
                const slr::PassRunResult r = slr::runPass(pass, slr::SlrParams{});
                QVERIFY2(r.ok && r.postOk && r.bias.ok, r.bias.why.c_str());
                const slr::PassBias& b = r.bias;
                const QString what = QString("kind %1 seed %2: b %3 ± %4 ns (truth %5), tau %6 ± %7 us (truth %8)")
                                         .arg(int(kind)).arg(seed)
                                         .arg(b.rangeBiasS * 1e9).arg(b.rangeBiasSigmaS * 1e9).arg(s.rangeBiasS * 1e9)
                                         .arg(b.timeBiasS * 1e6).arg(b.timeBiasSigmaS * 1e6).arg(s.timeBiasS * 1e6);
                // Stated tolerance: 3 sigma plus 10 ps (1.5 mm one-way). The k-sigma rejection clips
                // the simulated returns' tail unevenly and moves their mean by a few ps (measured:
                // 4.9 ps on the LEO kind, seed 1, against a sigma of 1.2 ps).
                QVERIFY2(std::fabs(b.rangeBiasS - s.rangeBiasS) <= 3 * b.rangeBiasSigmaS + 10e-12, qPrintable(what));
                QVERIFY2(std::fabs(b.timeBiasS - s.timeBiasS) <= 3 * b.timeBiasSigmaS + 1e-9, qPrintable(what));
                QVERIFY2(b.rangeBiasSigmaS < 20e-12 && b.timeBiasSigmaS < 20e-6, qPrintable(what));
            }
        sim::SlrSimParams sp = sim::slrSimPreset(sim::SlrKind::Leo);
        const sim::SlrSimPass s = sim::simulateSlrPass(sp, 1);
        const slr::PassRunResult own = slr::runPass(passOf(s, sp.altitudeKm), slr::SlrParams{});
        QVERIFY(own.ok && !own.bias.ok && own.bias.why.find("not against a CPF") != std::string::npos);
    }

    // ---------------------------------------------------------------- small passes (issue 29)
    // Short LEO passes of 10 to 20 filtered points are screened on their merits: a station's
    // pass of 10 points within ±0.9 ns (hy2c_202109 pass 2) once accepted nothing. The station
    // flagged every point data: all must be accepted. A 5-point pass on its own TOF trend is
    // doubtful, not "no signal" (its trend misses the range by tens of ns).
    void smallRealPassesAreScreened() {
        if (!lwbtest::haveShared("slr/hy2c_202109.fr2")) QSKIP("shared data not found");
        const std::string path = lwbtest::sharedPath("slr/hy2c_202109.fr2").toStdString();
        for (int k : {1, 2}) {  // passes 2 and 3: 10 and 20 points
            const slr::PassInputResult in = slr::loadPass(path, k, {});
            QVERIFY2(in.ok, in.error.c_str());
            const slr::PassRunResult r = slr::runPass(in.pass, slr::SlrParams{});
            QVERIFY2(r.ok, r.error.c_str());
            QCOMPARE(r.acceptedCount, in.pass.t.size());
            QVERIFY2(r.doubt.empty(), r.doubt.c_str());
            QVERIFY(r.agreement.available && r.agreement.recall == 1.0);
        }
        const slr::PassInputResult five = slr::loadPass(path, 0, {});
        QVERIFY2(five.ok, five.error.c_str());
        QCOMPARE(five.pass.t.size(), size_t(5));
        const slr::PassRunResult r5 = slr::runPass(five.pass, slr::SlrParams{});
        QVERIFY(r5.ok && r5.acceptedCount == 0 && !r5.doubt.empty());
        // Below 5 records a pass is not screened, in every mode (kMinPassPoints).
        const slr::PassInputResult four = slr::loadPass(path, 4, {});
        QVERIFY(!four.ok);
        QVERIFY2(four.error.find("a pass needs at least 5") != std::string::npos, four.error.c_str());
    }

    // A simulated short filtered LEO pass (the station's own filter: no noise floor), 8 to 19
    // points with 60 ps jitter: every point is accepted, whatever the seed.
    void smallFilteredPassesKeepEveryPoint() {
        for (long long n : {8LL, 12LL, 14LL, 19LL})
            for (uint64_t seed = 1; seed <= 5; ++seed) {
                sim::SlrSimParams sp = sim::slrSimPreset(sim::SlrKind::Leo);
                sp.points = n;
                sp.durationS = 60;
                sp.signalFraction = 1;
                sp.jitterS = 60e-12;
                const sim::SlrSimPass s = sim::simulateSlrPass(sp, seed);
                QVERIFY2(s.ok, s.error.c_str());
                const slr::PassRunResult r = slr::runPass(passOf(s, sp.altitudeKm), slr::SlrParams{});
                QVERIFY2(r.ok, r.error.c_str());
                QVERIFY2(r.acceptedCount == size_t(n),
                         qPrintable(QString("%1 points, seed %2: %3 accepted").arg(n).arg(seed).arg(r.acceptedCount)));
            }
    }

    // ---------------------------------------------------------------- hopeless passes (issue 29)
    // A lunar-like pass: 2 % of the points are returns, the rest uniform noise in a ±100 ns
    // gate, 30 minutes, 10 Hz-class. No confident wrong answer: with 500 points every seed ends
    // doubtful with no normal point; with 3000 points each seed either ends doubtful with none,
    // or forms none, or its normal points rest on kept points at least 90 % true signal (the
    // simulation's truth). Measured on these seeds: 5 of 8 doubtful, none publishes.
    void lunarLikePassesAreDoubtfulOrRight() {
        auto runSim = [](long long points, uint64_t seed, std::vector<uint8_t>* truth) {
            sim::SlrSimParams sp = sim::slrSimPreset(sim::SlrKind::Conventional);
            sp.points = points;
            sp.durationS = 1800;
            sp.signalFraction = 0.02;
            sp.gateS = 200e-9;
            const sim::SlrSimPass s = sim::simulateSlrPass(sp, seed);
            *truth = s.isSignal;
            return slr::runPass(passOf(s, sp.altitudeKm), slr::SlrParams{});
        };
        for (uint64_t seed = 1; seed <= 6; ++seed) {
            std::vector<uint8_t> truth;
            const slr::PassRunResult r = runSim(500, seed, &truth);
            QVERIFY2(r.ok, r.error.c_str());
            QVERIFY2(!r.doubt.empty(), qPrintable(QString("seed %1: %2 accepted, not doubtful").arg(seed).arg(r.acceptedCount)));
            QVERIFY(!r.postOk || r.post.normalPoints.empty());
        }
        int doubtful = 0, published = 0;
        for (uint64_t seed = 1; seed <= 8; ++seed) {
            std::vector<uint8_t> truth;
            const slr::PassRunResult r = runSim(3000, seed, &truth);
            QVERIFY2(r.ok, r.error.c_str());
            if (!r.doubt.empty()) {
                ++doubtful;
                QVERIFY(!r.postOk || r.post.normalPoints.empty());
                continue;
            }
            if (!r.postOk || r.post.normalPoints.empty()) continue;
            ++published;
            long tp = 0, kept = 0;
            for (size_t i = 0; i < truth.size(); ++i)
                if (r.post.kept[i]) {
                    ++kept;
                    tp += truth[i];
                }
            QVERIFY2(tp >= 0.9 * kept, qPrintable(QString("seed %1: %2 of %3 kept points are signal").arg(seed).arg(tp).arg(kept)));
        }
        qInfo("3000-point lunar-like passes: %d doubtful, %d with normal points on a true track", doubtful, published);
        QVERIFY(doubtful >= 1);  // before issue 29 none was: nothing accepted was "no signal", exit 0
    }

    // ---------------------------------------------------------------- simulator extensions
    void simulatorGapsDriftAndLevelShift() {
        sim::SlrSimParams p = sim::slrSimPreset(sim::SlrKind::Leo);
        p.signalFraction = 0.3;
        p.driftSPerS = 4e-9;
        std::string err;
        QVERIFY(sim::parseSlrGaps("150:45,400:60:80,500:20:nodata", &p.gaps, &err));
        QCOMPARE(p.gaps.size(), size_t(3));
        QCOMPARE(p.gaps[1].levelShiftS, 80e-9);
        QVERIFY(!p.gaps[2].noise);
        const sim::SlrSimPass pass = sim::simulateSlrPass(p, 7);
        QVERIFY2(pass.ok, pass.error.c_str());
        const double t0 = p.startSod;
        for (size_t i = 0; i < pass.epochS.size(); ++i) {
            const double x = pass.epochS[i] - t0;
            if (pass.isSignal[i]) {
                QVERIFY2(!(x >= 150 && x < 195) && !(x >= 400 && x < 460), qPrintable(QString::number(x)));
                // Signal sits on the model track (60 ps jitter: 8 sigma).
                QVERIFY(std::fabs(pass.ocS[i] - pass.trackOcS[i]) < 8 * p.jitterS);
            }
            QVERIFY(!(x >= 500 && x < 520));  // no data at all in the no-data gap
        }
        // The level shift: the model track jumps by 80 ns across the second gap, beyond eq. 1 and
        // the drift (checked at the last signal point before and the first after, against eq. 1).
        auto eq1 = [&](double t) {
            const double mid = t0 + 0.5 * pass.durationS, x = t - mid;
            return sim::slrTrackOc(p, pass.rangeBiasS, pass.timeBiasS, pass.tcaSod, t) + p.driftSPerS * x;
        };
        for (size_t i = 0; i < pass.epochS.size(); ++i) {
            const double x = pass.epochS[i] - t0;
            const double extra = pass.trackOcS[i] - eq1(pass.epochS[i]);
            QVERIFY(std::fabs(extra - (x >= 460 ? 80e-9 : 0.0)) < 1e-15);
        }
        QVERIFY(!sim::parseSlrGaps("150", &p.gaps, &err));
        QVERIFY(err.find("START:LENGTH") != std::string::npos);
        QVERIFY(!sim::parseSlrGaps("10:-5", &p.gaps, &err));
    }

    // ---------------------------------------------------------------- hard passes with truth
    void hardPassesWithTruth_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("seed");
        QTest::addColumn<double>("minF1");
        // Issue 13: F1 ≥ 0.95 on low-orbit noisy passes with gaps, ≥ 0.90 at 3 % in daylight.
        // Seeds fixed in advance (1; 2 for the two cases the issue names).
        for (int seed : {1, 2}) {
            QTest::newRow(qPrintable(QString("leo gaps night 30% seed %1").arg(seed))) << "leo gaps night 30%" << seed << 0.95;
            QTest::newRow(qPrintable(QString("leo day 3% seed %1").arg(seed))) << "leo day 3%" << seed << 0.90;
        }
        QTest::newRow("leo gaps + level shift seed 1") << "leo gaps + level shift" << 1 << 0.95;
        QTest::newRow("conventional gaps 30/60/120 s seed 1") << "conventional gaps 30/60/120 s" << 1 << 0.95;
        QTest::newRow("leo day 2% seed 1") << "leo day 2%" << 1 << 0.90;
        QTest::newRow("khz day 3% gap seed 1") << "khz day 3% gap" << 1 << 0.90;
        QTest::newRow("diffuse day 5% gap seed 1") << "diffuse day 5% gap" << 1 << 0.90;
    }
    void hardPassesWithTruth() {
        QFETCH(QString, name);
        QFETCH(int, seed);
        QFETCH(double, minF1);
        const sim::SlrSimParams p = hardCase(name);
        const sim::SlrSimPass pass = sim::simulateSlrPass(p, static_cast<uint64_t>(seed));
        QVERIFY2(pass.ok, pass.error.c_str());
        const ScreenResult r = screenSignal(pass.epochS, pass.ocS, ScreenParams{});
        QVERIFY2(r.ok, r.error.c_str());
        const F1 f = score(acceptedMask(r), pass.isSignal);
        qInfo("%s seed %d: %zu points, precision %.4f recall %.4f F1 %.4f (track following +%lld -%lld)", qPrintable(name),
              seed, pass.epochS.size(), f.precision, f.recall, f.f1, r.followedAdded, r.followedDropped);
        QVERIFY2(f.f1 >= minF1, qPrintable(QString("F1 %1").arg(f.f1)));
        // The first return of the track is found (issue 13: "from its first return").
        size_t first = 0;
        while (!pass.isSignal[first]) ++first;
        size_t firstFound = first;
        while (firstFound < pass.epochS.size() && !(pass.isSignal[firstFound] && r.accepted(firstFound))) ++firstFound;
        QVERIFY2(pass.epochS[firstFound] - pass.epochS[first] < 10,
                 qPrintable(QString("first return found %1 s late").arg(pass.epochS[firstFound] - pass.epochS[first])));
    }

    // Scales given by hand that a kHz pass's track cannot be told at. One joins the whole gate into one region (mag_T 0.2,
    // mag_OC 4e9 on a pass the automatic mode screens at 2 and 4e10): every point is accepted,
    // the post-fit's 3σ window spans the gate, no noise is left beside it to measure, and its 21
    // normal points were delivered with exit 0 (a 10^7-event pass: 56 ns RMS, 10 % signal). The
    // window's flat shape now refuses them; the automatic scale's stand.
    void aScaleThatAcceptsTheWholeGateIsDoubtful() {
        // The pass as laserwb-cli opens it: a CRD file, O-C from its own TOF trend.
        sim::SlrSimParams sp = sim::slrSimPreset(sim::SlrKind::Khz);
        sp.points = 100000;
        sp.signalFraction = 0.1;
        const sim::SlrSimPass s = sim::simulateSlrPass(sp, 1);
        QVERIFY2(s.ok, s.error.c_str());
        QTemporaryDir dir;
        const QString path = dir.path() + "/k100k.frd";
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray::fromStdString(sim::slrPassCrd(sp, s)));
        f.close();
        slr::SlrSources src;
        src.input = path.toStdString();
        const slr::LoadedSlrPass loaded = slr::loadSlrPass(src);
        QVERIFY2(loaded.ok, loaded.error.message.c_str());
        const slr::PassData& pass = *loaded.opened.pass;
        const slr::SlrParams automatic = loaded.opened.settings.params;
        auto runAt = [&](double magT, double magOc, int area) {
            slr::SlrParams p = automatic;
            p.screen.automatic = false;
            p.screen.magT = magT;
            p.screen.magOc = magOc;
            p.screen.areaLimit = area;
            p.screen.connectivity = 8;
            const slr::PassRunResult r = slr::runPass(pass, p);
            qInfo("mag_T %g, mag_OC %g, area %d: accepted %zu, post-fit RMS %.1f ps, %zu normal points; %s", magT, magOc, area,
                  size_t(r.acceptedCount), r.post.stats.rms * 1e12, r.post.normalPoints.size(), r.doubt.c_str());
            return r;
        };
        const slr::PassRunResult joined = runAt(0.2, 4e9, 12);
        QVERIFY2(joined.ok, joined.error.c_str());
        QVERIFY(joined.acceptedCount > 99000);
        QVERIFY2(joined.doubt.find("fill the post-fit's window evenly") != std::string::npos, joined.doubt.c_str());
        QVERIFY(joined.post.normalPoints.empty());
        // A scale that splits the gate's noise instead (every region a candidate): half the pass
        // kept, the track a spike on a floor that fills the window, the other half within the same
        // window called noise; 21 normal points 5.2 m off were delivered.
        const slr::PassRunResult half = runAt(1000, 1e8, 1);
        QVERIFY2(half.doubt.find("the rest of the track was left out as noise") != std::string::npos, half.doubt.c_str());
        QVERIFY(half.post.normalPoints.empty());
        // A scale finer than the track (O-C pixels of 1 ps on a 25 ps track): a sliver of it kept,
        // 37 of the 141 points within ±10 ps of its fit in one bin; 3 normal points 1.8 mm from the
        // whole track's, with a precision of 0.1 mm, were delivered.
        const slr::PassRunResult sliver = runAt(1, 1e12, 12);
        QVERIFY2(sliver.doubt.find("the rest of the track was left out as noise") != std::string::npos, sliver.doubt.c_str());
        QVERIFY(sliver.post.normalPoints.empty());
        // The automatic scale's normal points stand.
        const slr::PassRunResult good = slr::runPass(pass, automatic);
        QVERIFY2(good.ok && good.doubt.empty(), good.doubt.c_str());
        QVERIFY(good.post.normalPoints.size() >= 18);
    }

    // ---------------------------------------------------------------- track following
    void trackFollowingBridgesAGapAndLeavesNoiseAlone() {
        // A curved track (8 ns/s, 0.02 ns/s²) with 60 ps jitter, 2 returns/s over 0..300 s except
        // a gap 120..180 s; uniform noise 1/s over a 10 µs gate. Only 0..60 s is "accepted".
        sim::Rng rng(5);
        std::vector<double> t, oc;
        std::vector<uint8_t> truth, acc;
        auto track = [](double x) { return 8e-9 * (x - 150) + 0.02e-9 * (x - 150) * (x - 150); };
        for (double x = 0; x < 300; x += 0.5)
            if (x < 120 || x >= 180) {
                t.push_back(x);
                oc.push_back(track(x) + 60e-12 * rng.normal());
                truth.push_back(1);
                acc.push_back(x < 60);
            }
        for (int k = 0; k < 300; ++k) {
            t.push_back(rng.uniform(0, 300));
            oc.push_back(rng.uniform(-5e-6, 5e-6));
            truth.push_back(0);
            acc.push_back(0);
        }
        const FollowResult f = followTrack(t, oc, acc, FollowParams{});
        QVERIFY(f.ok);
        const F1 q = score(f.accepted, truth);
        qInfo("followed: precision %.4f recall %.4f, +%lld, sigma %.1f ps", q.precision, q.recall, f.added, f.sigmaS * 1e12);
        QVERIFY2(q.recall > 0.99, qPrintable(QString::number(q.recall)));  // across the 60 s gap to the end
        QVERIFY2(q.precision > 0.99, qPrintable(QString::number(q.precision)));
        // σ of the track: 60 ps within 25 %.
        QVERIFY(std::fabs(f.sigmaS - 60e-12) < 15e-12);
        // Pure noise marked as accepted in a clump of 8: no track to follow, nothing added.
        std::vector<uint8_t> noiseAcc(t.size(), 0);
        std::vector<size_t> noiseIdx;
        for (size_t i = 0; i < t.size(); ++i)
            if (!truth[i] && noiseIdx.size() < 8) noiseIdx.push_back(i);
        for (size_t i : noiseIdx) noiseAcc[i] = 1;
        std::vector<double> tn, on;
        std::vector<uint8_t> an;
        for (size_t i = 0; i < t.size(); ++i)
            if (!truth[i]) {
                tn.push_back(t[i]);
                on.push_back(oc[i]);
                an.push_back(noiseAcc[i]);
            }
        const FollowResult g = followTrack(tn, on, an, FollowParams{});
        QVERIFY(g.ok);
        QCOMPARE(g.added, 0LL);
    }

    /// Track following runs once, after the refinement, on the O-C as given. It also ran inside
    /// the refinement's screening of the flattened O-C (following the kinks at the ends of the
    /// subtracted trend, and scoring a followed round against an unfollowed one): the result then
    /// differed from following the unfollowed screening (by 1 point on each of these passes).
    void trackFollowingRunsOnceAfterTheRefinement_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("seed");
        QTest::newRow("leo day 3%") << "leo day 3%" << 3;
        QTest::newRow("conventional gaps") << "conventional gaps 30/60/120 s" << 2;
    }
    void trackFollowingRunsOnceAfterTheRefinement() {
        QFETCH(QString, name);
        QFETCH(int, seed);
        const sim::SlrSimPass pass = sim::simulateSlrPass(hardCase(name), static_cast<uint64_t>(seed));
        QVERIFY2(pass.ok, pass.error.c_str());
        ScreenParams p;
        p.acceptFloorless = false;  // (judged on the input alone, after both)
        const ScreenResult followed = screenSignal(pass.epochS, pass.ocS, p);
        ScreenParams q = p;
        q.followTrack = false;
        const ScreenResult screened = screenSignal(pass.epochS, pass.ocS, q);
        QVERIFY(followed.ok && screened.ok);
        QVERIFY2(screened.refinedRounds >= 1, "the pass must be refined for this test to mean anything");
        const FollowResult f = followTrack(pass.epochS, pass.ocS, acceptedMask(screened), FollowParams{});
        QVERIFY(f.ok);
        QVERIFY(acceptedMask(followed) == f.accepted);
    }

    void poissonTailBound() {
        QCOMPARE(poissonTail(0, 3.0), 1.0);
        QCOMPARE(poissonTail(2, 5.0), 1.0);  // m ≤ mean: not improbable
        // P(N ≥ 1 | 1e-3) = 1 − e^−0.001 = 9.995e-4; the bound is within 0.1 %.
        QVERIFY(std::fabs(poissonTail(1, 1e-3) - 9.995e-4) < 1e-6);
        // P(N ≥ 10 | 1) = 1.114e-7 (exact sum): an upper bound within 10 %.
        const double p10 = poissonTail(10, 1.0);
        QVERIFY2(p10 >= 1.114e-7 && p10 < 1.23e-7, qPrintable(QString::number(p10)));
    }

    // ---------------------------------------------------------------- day or night
    void sunElevation() {
        // McDonald (30.68° N): at the December solstice the noon Sun stands at 90 − 30.68 − 23.44
        // = 35.9°; the highest elevation over the day within 0.3°, the lowest below −50°.
        double hi = -90, lo = 90;
        for (int m = 0; m < 1440; ++m) {
            const double e = sunElevationDeg(54455.0 + m / 1440.0, 30.68, -104.02);  // 2007-12-21
            hi = std::max(hi, e);
            lo = std::min(lo, e);
        }
        QVERIFY2(std::fabs(hi - 35.88) < 0.3, qPrintable(QString::number(hi)));
        QVERIFY(lo < -50);
        // Local solar noon at 104.02° W is 18:56 UTC; the JASON1 pass at 20:33 UTC is day, 06:00 UTC night.
        QVERIFY(isDaylight(sunElevationDeg(54454.0 + (20 + 33 / 60.0) / 24, 30.68, -104.02)));
        QVERIFY(!isDaylight(sunElevationDeg(54454.0 + 6.0 / 24, 30.68, -104.02)));
        // Equator at the March equinox (2008-03-20 12:00 UTC, Greenwich meridian): near the zenith.
        QVERIFY(sunElevationDeg(54545.5, 0, 0) > 88);
    }

    void stationAndFireRateFromTheFiles() {
        if (!lwbtest::haveShared("slr/7080_JASON1_crd_071220_2033_0.frd")) QSKIP("shared SLR data absent");
        const CrdReadResult crd = readCrd(lwbtest::str(lwbtest::sharedPath("slr/7080_JASON1_crd_071220_2033_0.frd")));
        QVERIFY2(crd.ok, crd.error.c_str());
        QCOMPARE(crdFireRateHz(crd.file.passes[0]), 10.0);  // "c1 0 ml1 Nd-Yag 1064.00 10.00 ..."
        const SinexReadResult snx = readSinex(lwbtest::str(lwbtest::sharedPath("slr/SLRF2014_POS+VEL_2030.0_200428.snx")));
        QVERIFY2(snx.ok, snx.error.c_str());
        PostfitParams pp;
        fillNormalPointContext(crd.file.passes[0], crd.file.passes[0].station.cdpPadId, &snx.file, &pp);
        // SITE/ID of 7080: 255° 59' 5.2" E, 30° 40' 48.9" N (approximate: within 0.01°).
        QVERIFY2(std::fabs(pp.stationLatDeg - 30.6803) < 0.01, qPrintable(QString::number(pp.stationLatDeg)));
        QVERIFY2(std::fabs(pp.stationLonDeg - (255.98478 - 360)) < 0.01, qPrintable(QString::number(pp.stationLonDeg)));
        QCOMPARE(pp.fireRateHz, 10.0);
        QCOMPARE(pp.dayStartMjd, 54454.0);  // 2007-12-20
    }

    // ---------------------------------------------------------------- normal points vs the station
    /// The shared frd/npt pairs (the same passes, the station's own normal points), screened and
    /// post-fitted with default settings by `laserwb-cli slr`. Bin length: the station's (15 s for
    /// JASON1, Beacon-C and beaconc_20070511, given with --np-bin because the altitude table gives
    /// 30 s for the altitude the CLI estimates, 1150–1570 km; STELLA 30 s, the table's). Without
    /// --stations the day minimum of 6 applies (these MLRS passes are all daytime: sunElevation).
    /// Every station NP of at least 6 ranges must have a project NP in the same bin; over the
    /// matched bins, mean |Δrange| ≤ 2 mm one-way and RMS ≤ 3 mm. Δ compares the two at the same
    /// epoch: when the NP epochs differ, the difference of a cubic through the station's flag-2
    /// ranges within a bin length of the station epoch is removed (the range changes by km/s).
    void normalPointsAgainstTheStation_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("pass");
        QTest::addColumn<bool>("giveBin");
        // (issue 29: the ILRS missions table gives each satellite the station's own bin, 15 s for
        // Jason-1 and Beacon-C where --np-bin had to say it: no row needs it now)
        QTest::newRow("JASON1") << "7080_JASON1_crd_071220_2033_0" << 1 << false;
        QTest::newRow("STELLA") << "7080_STELLA_crd_071220_2128_0" << 1 << false;
        QTest::newRow("Beacon-C") << "7080_Beacon-C_crd_071220_1715_0" << 1 << false;
        QTest::newRow("beaconc pass 1") << "beaconc_20070511" << 1 << false;
        QTest::newRow("beaconc pass 2") << "beaconc_20070511" << 2 << false;
        QTest::newRow("beaconc pass 3") << "beaconc_20070511" << 3 << false;
    }
    void normalPointsAgainstTheStation() {
        QFETCH(QString, file);
        QFETCH(int, pass);
        QFETCH(bool, giveBin);
        if (!lwbtest::haveShared("slr/" + file + ".npt")) QSKIP("shared SLR data absent");
        const CrdReadResult st = readCrd(lwbtest::str(lwbtest::sharedPath("slr/" + file + ".npt")));
        const CrdReadResult fr = readCrd(lwbtest::str(lwbtest::sharedPath("slr/" + file + ".frd")));
        QVERIFY(st.ok && fr.ok);
        const auto& snp = st.file.passes[size_t(pass - 1)].normalPoints;
        const auto& ranges = fr.file.passes[size_t(pass - 1)].ranges;
        QVERIFY(!snp.empty());
        const double L = snp.front().windowS;
        QTemporaryDir dir;
        const QString out = dir.path() + "/np.csv", npt = dir.path() + "/np.npt";
        QStringList args = {"slr", lwbtest::sharedPath("slr/" + file + ".frd"), "--pass", QString::number(pass), "-o", out,
                            "--npt-out", npt, "-q"};
        if (giveBin) args << "--np-bin" << QString::number(L);
        const auto r = lwbtest::runCli(args);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const CrdReadResult mine = readCrd(lwbtest::str(npt));
        QVERIFY2(mine.ok, mine.error.c_str());
        const auto& mnp = mine.file.passes.front().normalPoints;
        constexpr double c = 299792458.0;
        std::vector<double> d;
        QString list;
        for (const CrdNormalPoint& s : snp) {
            const long bin = long(std::floor(s.secOfDay / L));
            const CrdNormalPoint* m = nullptr;
            for (const CrdNormalPoint& x : mnp)
                if (long(std::floor(x.secOfDay / L)) == bin) m = &x;
            if (!m) {
                list += QString(" -/%1").arg(s.numRanges);
                QVERIFY2(s.numRanges < 6, qPrintable(QString("station NP at %1 s with %2 ranges has no project NP")
                                                          .arg(s.secOfDay, 0, 'f', 3)
                                                          .arg(s.numRanges)));
                continue;
            }
            double corr = 0;
            if (std::fabs(m->secOfDay - s.secOfDay) > 1e-6) {
                std::vector<CrdRange> near;  // (copies: the pass's ranges are columns, a record a value)
                for (const CrdRange& x : ranges)
                    if (x.filterFlag == 2 && std::fabs(x.secOfDay - s.secOfDay) <= L) near.push_back(x);
                QVERIFY(near.size() >= 4);
                Eigen::MatrixXd A(Eigen::Index(near.size()), 4);
                Eigen::VectorXd b(Eigen::Index(near.size()));
                for (size_t k = 0; k < near.size(); ++k) {
                    const double u = (near[k].secOfDay - s.secOfDay) / L;
                    A.row(Eigen::Index(k)) << 1, u, u * u, u * u * u;
                    b(Eigen::Index(k)) = near[k].tofS;
                }
                const Eigen::VectorXd q = A.colPivHouseholderQr().solve(b);
                const double u = (m->secOfDay - s.secOfDay) / L;
                corr = q(1) * u + q(2) * u * u + q(3) * u * u * u;
            }
            d.push_back((m->tofS - s.tofS - corr) * c / 2 * 1e3);
            list += QString(" %1/%2").arg(d.back(), 0, 'f', 1).arg(s.numRanges);
        }
        QVERIFY(!d.empty());
        double sa = 0, s2 = 0;
        for (double v : d) {
            sa += std::fabs(v);
            s2 += v * v;
        }
        const double meanAbs = sa / double(d.size()), rms = std::sqrt(s2 / double(d.size()));
        qInfo("%s pass %d, bins of %.0f s: %zu of %zu station NPs matched; mean |d| %.2f mm, RMS %.2f mm; per NP (mm/ranges):%s",
              qPrintable(file), pass, L, d.size(), snp.size(), meanAbs, rms, qPrintable(list));
        // The workbench's comparison (core compareWithStation) on the same run: the same bins
        // matched, and where the two normal points share their epoch the same difference within
        // 0.2 mm (the CRD's TOF to 1 ps is 0.15 mm; measured 0.00-0.07 mm). Where the epochs
        // differ the two put them on one epoch differently: the cubic above through the
        // station's ranges within a bin, compareWithStation on our post-fit trend. Measured: 0.3 s
        // apart 0.14 mm, 1.4 s apart (beaconc pass 3's last bin) 4.6 mm; there polynomials of
        // degree 5-6 through the pass's last 60-300 s of flag-2 ranges (RMS 103 ps) put the TOF
        // change between the two epochs 122 ps above the observed one, the trend about 115 ps,
        // the local cubic 146 ps: the trend is the better transfer. Bound there: 5 mm.
        {
            const PassInputResult in = loadPass(lwbtest::str(lwbtest::sharedPath("slr/" + file + ".frd")), pass - 1, {});
            QVERIFY2(in.ok, in.error.c_str());
            SlrParams params;
            params.postfit.rejectSigma = 3;  // (the CLI's default)
            PassSettings set;
            std::string err;
            QVERIFY2(passSettings(in.pass, params, nullptr, "", nullptr, &set, &err), err.c_str());
            const PassRunResult run = runPass(in.pass, set.params);
            QVERIFY(run.postOk);
            const NpComparison cmp = compareWithStation(in.pass, run.post, st.file, "station.npt");
            QVERIFY2(cmp.ok, cmp.error.c_str());
            qInfo("  compareWithStation: %s", cmp.describe().c_str());
            QCOMPARE(cmp.block, size_t(pass - 1));
            QCOMPARE(cmp.matched, d.size());
            QCOMPARE(cmp.matched + cmp.stationOnly, snp.size());
            QCOMPARE(cmp.matched + cmp.oursOnly, mnp.size());
            size_t k = 0;
            for (const NpDifference& row : cmp.rows) {
                if (row.match != NpDifference::Match::Both) continue;
                const double apart = std::fabs(row.ourT - row.stationT);
                if (apart > 1e-3)
                    qInfo("  bin at %.3f s, epochs %.3f s apart: %.2f mm on our trend, %.2f mm by the station's ranges", row.t,
                          apart, row.deltaMm, d[k]);
                QVERIFY2(std::fabs(row.deltaMm - d[k]) <= (apart > 1e-3 ? 5.0 : 0.2),
                         qPrintable(QString("bin at %1 s (ours at %4 s): %2 mm here, %3 mm by the station's ranges").arg(row.t, 0, 'f', 3).arg(row.deltaMm).arg(d[k]).arg(row.ourT, 0, 'f', 3)));
                ++k;
            }
        }
        if (file.startsWith("7080_Beacon-C"))
            QEXPECT_FAIL("Beacon-C", "known: without a prediction the O-C (against a fitted TOF trend) bends by nanoseconds in "
                                     "the first 10 s; the station keeps two ranges there 6.5 and 3.7 ns off any smooth trend "
                                     "through the rest, the k-sigma rejection drops them, and the first and last NPs differ "
                                     "(docs/slr-detection.md)",
                         Continue);
        QVERIFY2(meanAbs <= 2.0 && rms <= 3.0, qPrintable(QString("mean |d| %1 mm, RMS %2 mm").arg(meanAbs).arg(rms)));
    }
};

QTEST_GUILESS_MAIN(TestSlrHard)
#include "test_slr_hard.moc"
