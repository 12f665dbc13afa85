// Issue 43, item 3: no confident wrong answer on lunar passes. Simulated lunar ranging passes
// (core/sim/slr_sim_lunar: 10 Hz or 1 kHz, 30 min, returns 0.03–2 % of the shots, Poisson noise
// over a 200 ns–2 µs gate) written as CRD full-rate files of Apollo 15 and run as the CLI runs
// them without a prediction (O-C against the pass's own TOF trend, the missions table's 900 s
// bin): clean passes publish, adversarial ones (no signal, clustered noise, a band at the gate's
// edge, afterpulses, a second weak track, a gate that moves) end doubtful or publish normal
// points from kept points at most kMaxNoiseShare noise by the simulation's truth.
#include <QtTest>
#include <cmath>

#include "core/common/rng.hpp"
#include "core/sim/slr_sim_lunar.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/pass_run.hpp"
#include "test_support.hpp"

using namespace lwb::core;
namespace sim = lwb::core::sim;

namespace {

struct LunarOutcome {
    bool doubtful = false;
    size_t normalPoints = 0;
    long long kept = 0, keptNoise = 0, events = 0, signal = 0;
    std::string doubt, evidence;
    double noiseShare() const { return kept ? double(keptNoise) / double(kept) : 0; }
};

// The kept points that make the normal points: in a bin that formed one.
LunarOutcome runLunar(const sim::LunarSimParams& p, uint64_t seed, const QString& dir) {
    LunarOutcome o;
    const sim::LunarSimPass s = sim::simulateLunarPass(p, seed);
    if (!s.ok) qFatal("%s", s.error.c_str());
    o.events = static_cast<long long>(s.epochS.size());
    o.signal = s.signalCount;
    if (s.epochS.size() < 5) {
        o.doubtful = true;
        o.doubt = "fewer than 5 events";
        return o;
    }
    const QString path = dir + "/lunar.frd";
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) qFatal("cannot write %s", qPrintable(path));
    f.write(QByteArray::fromStdString(sim::lunarPassCrd(p, s)));
    f.close();
    const slr::PassInputResult in = slr::loadPass(path.toStdString(), -1, {});
    if (!in.ok) qFatal("%s", in.error.c_str());
    slr::PassSettings settings;
    std::string err;
    if (!slr::passSettings(in.pass, slr::commandDefaults(), nullptr, "", nullptr, &settings, &err)) qFatal("%s", err.c_str());
    const slr::PassRunResult r = slr::runPass(in.pass, settings.params);
    if (!r.ok) qFatal("%s", r.error.c_str());
    o.doubtful = !r.doubt.empty();
    o.doubt = r.doubt;
    for (const auto& e : r.binEvidence)
        o.evidence += QString(" [on %1 off %2 lam %3 share %4 p %5 T %6 room %7 rms %8 ps%9]")
                          .arg(e.onPoints).arg(e.offPoints).arg(e.expectedNoise, 0, 'f', 2).arg(e.noiseShare, 0, 'f', 2)
                          .arg(e.pValue, 0, 'g', 2).arg(e.trials, 0, 'f', 0).arg(e.edgeRoom, 0, 'f', 1)
                          .arg(r.post.stats.rms * 1e12, 0, 'f', 0).arg(e.why.empty() ? "" : " X")
                          .toStdString();
    const slr::DeliveredNormalPoints d = slr::deliveredNormalPoints(r);
    o.normalPoints = d.points.size();
    if (r.postOk)
        for (const auto& np : d.points)
            for (size_t i = 0; i < in.pass.t.size(); ++i)
                if (r.post.kept[i] && in.pass.t[i] >= np.binStartS && in.pass.t[i] < np.binStartS + np.windowS) {
                    ++o.kept;
                    o.keptNoise += s.isSignal[i] == 0;
                }
    return o;
}

struct Case {
    const char* name;
    sim::LunarSimParams p;
    bool clean;  // a pass that should publish
};

std::vector<Case> lunarCases() {
    std::vector<Case> c;
    auto base = [](double ret, double noise, double gate, double rate = 10) {
        sim::LunarSimParams p;
        p.returnProbability = ret;
        p.noisePerShot = noise;
        p.gateS = gate;
        p.fireRateHz = rate;
        return p;
    };
    c.push_back({"clean 10 Hz 2 % / 0.05 noise, 200 ns", base(0.02, 0.05, 200e-9), true});
    c.push_back({"clean 10 Hz 0.5 % / 0.05 noise, 200 ns", base(0.005, 0.05, 200e-9), true});
    c.push_back({"clean 10 Hz 0.2 % / 0.005 noise, 1 us", base(0.002, 0.005, 1e-6), true});
    c.push_back({"clean 1 kHz 0.1 % / 0.01 noise, 2 us", base(0.001, 0.01, 2e-6, 1000), true});
    c.push_back({"sparse 10 Hz 0.05 % / 0.005 noise, 200 ns", base(0.0005, 0.005, 200e-9), false});
    c.push_back({"sparse 10 Hz 0.03 % / 0.001 noise, 100 ns", base(0.0003, 0.001, 100e-9), false});
    c.push_back({"no signal 10 Hz 0.05 noise, 200 ns", base(0, 0.05, 200e-9), false});
    c.push_back({"no signal 10 Hz 0.005 noise, 1 us", base(0, 0.005, 1e-6), false});
    c.push_back({"no signal 1 kHz 0.002 noise, 2 us", base(0, 0.002, 2e-6, 1000), false});
    {
        auto p = base(0, 0.02, 200e-9);
        p.afterpulseProbability = 0.3;
        p.afterpulseDelayS = 5e-9;
        c.push_back({"no signal, afterpulses", p, false});
    }
    {
        auto p = base(0, 0.02, 200e-9);
        p.edgeBandS = 3e-9;
        p.edgeBandPerShot = 0.005;
        c.push_back({"no signal, edge band 3 ns", p, false});
    }
    {
        auto p = base(0, 0.01, 200e-9);
        p.burstCount = 3;
        p.burstLengthS = 60;
        p.burstFactor = 30;
        c.push_back({"no signal, 3 noise bursts", p, false});
    }
    {
        auto p = base(0, 0.01, 200e-9);
        p.gateShiftAtS = 900;
        p.gateShiftS = 60e-9;
        p.edgeBandS = 2e-9;
        p.edgeBandPerShot = 0.003;
        c.push_back({"no signal, moving gate with edge band", p, false});
    }
    {
        auto p = base(0.002, 0.02, 200e-9);
        p.edgeBandS = 3e-9;
        p.edgeBandPerShot = 0.005;
        c.push_back({"weak signal, edge band 3 ns", p, false});
    }
    {
        auto p = base(0.002, 0.02, 200e-9);
        p.secondProbability = 0.001;
        c.push_back({"weak signal, second track", p, false});
    }
    {
        auto p = base(0.002, 0.02, 200e-9);
        p.burstCount = 3;
        p.burstFactor = 30;
        c.push_back({"weak signal, noise bursts", p, false});
    }
    {
        auto p = base(0.002, 0.02, 200e-9);
        p.afterpulseProbability = 0.3;
        p.afterpulseDelayS = 5e-9;
        c.push_back({"weak signal, afterpulses", p, false});
    }
    {
        auto p = base(0.002, 0.02, 200e-9);
        p.gateShiftAtS = 900;
        p.gateShiftS = 60e-9;
        c.push_back({"weak signal, moving gate", p, false});
    }
    return c;
}

}  // namespace

class TestSlrLunar : public QObject {
    Q_OBJECT
private slots:
    // 18 kinds of lunar pass x seeds 1-10 (docs/slr-detection.md, "Issue 43: lunar passes"):
    // - every pass without a signal (uniform noise; afterpulses; a 3 ns band at the gate's edge;
    //   noise bursts; a gate that moves with its edge band) ends doubtful with no normal point;
    // - a pass that publishes does so from kept points at most a third noise each, and at most
    //   15 % over the adversarial kinds with a signal (measured 31 of 217, 14 %: afterpulses and a second
    //   track put noise beside the track that the flanks do not measure; the rule bounds the
    //   share the flanks' density predicts at 10 % a bin);
    // - the four clean kinds publish on at least 9 seeds of 10 each (39 of 40 measured).
    void adversarialLunarPassesAreDoubtfulOrRight() {
        QTemporaryDir dir;
        const bool verbose = qEnvironmentVariableIsSet("LWB_LUNAR_VERBOSE");
        long long advKept = 0, advNoise = 0;
        int cleanPublished = 0, noSignalDoubtful = 0, noSignalRuns = 0;
        for (const Case& c : lunarCases()) {
            int doubtful = 0, published = 0, worstSeed = 0;
            double worst = 0;
            long long ev = 0, sig = 0;
            for (uint64_t seed = 1; seed <= 10; ++seed) {
                const LunarOutcome o = runLunar(c.p, seed, dir.path());
                ev += o.events;
                sig += o.signal;
                doubtful += o.doubtful;
                if (verbose)
                    qInfo("  seed %d: %s NPs %zu kept %lld noise %.2f%s %s", int(seed), o.doubtful ? "doubtful" : "ok",
                          o.normalPoints, o.kept, o.noiseShare(), o.evidence.c_str(), o.doubt.substr(0, 90).c_str());
                QVERIFY2(!o.doubtful || o.normalPoints == 0,
                         qPrintable(QString("%1, seed %2: doubtful with normal points").arg(c.name).arg(seed)));
                if (o.normalPoints == 0) continue;
                ++published;
                if (o.noiseShare() > worst) worst = o.noiseShare(), worstSeed = int(seed);
                QVERIFY2(3 * o.keptNoise <= o.kept, qPrintable(QString("%1, seed %2: normal points from %3 kept points, %4 noise")
                                                                   .arg(c.name).arg(seed).arg(o.kept).arg(o.keptNoise)));
                if (!c.clean) advKept += o.kept, advNoise += o.keptNoise;
            }
            qInfo("%-45s events %6lld signal %5lld | doubtful %2d published %2d worst noise share %.2f (seed %d)", c.name,
                  ev / 10, sig / 10, doubtful, published, worst, worstSeed);
            if (c.clean) {
                cleanPublished += published;
                QVERIFY2(published >= 9, c.name);
            }
            if (c.p.returnProbability == 0) {
                noSignalRuns += 10;
                noSignalDoubtful += doubtful;
                QVERIFY2(published == 0 && doubtful == 10, c.name);
            }
        }
        qInfo("clean kinds: %d of 40 publish; no-signal kinds: %d of %d doubtful; adversarial kinds with a signal: "
              "%lld of %lld kept points in published bins are noise", cleanPublished, noSignalDoubtful, noSignalRuns, advNoise, advKept);
        QVERIFY(cleanPublished >= 38);
        QVERIFY2(100 * advNoise <= 15 * advKept, qPrintable(QString("%1 of %2").arg(advNoise).arg(advKept)));
    }

    // The window's shape (windowShapeDoubt) on 3 000 draws each, clipped at 3σ as the post-fit
    // clips: one track (a Gaussian, one with an exponential tail, a t₃, a core with a 5× wider
    // fifth, half Gaussian and half flat) is refused at most 0.2 % of the time with 300 points
    // and 0.5 % with 50; noise filling the window is refused at least 97 % of the time with 300,
    // a track of 30 % on a flat floor at least 97 % with 300 and half the time with 50.
    void windowShapeTellsOneTrackFromNoise() {
        Rng rng(11);
        auto draw = [&](int kind) {
            switch (kind) {
                case 0: return rng.normal();
                case 1: return rng.normal() - 1.5 * std::log(1 - rng.uniform());
                case 2: {
                    double chi2 = 0;
                    for (int k = 0; k < 3; ++k) {
                        const double z = rng.normal();
                        chi2 += z * z;
                    }
                    return rng.normal() / std::sqrt(chi2 / 3);
                }
                case 3: return rng.uniform() < 0.8 ? rng.normal() : 5 * rng.normal();
                case 4: return rng.uniform() < 0.5 ? rng.normal() : rng.uniform(-3, 3);
                case 5: return rng.uniform(-1, 1);
                default: return rng.uniform() < 0.3 ? 0.01 * rng.normal() : rng.uniform(-3, 3);
            }
        };
        auto refusedShare = [&](int kind, int n) {
            int refused = 0;
            for (int d = 0; d < 3000; ++d) {
                slr::PostfitResult post;
                for (int i = 0; i < n; ++i) post.residuals.push_back(draw(kind) * 1e-10);
                post.kept.assign(size_t(n), 1);
                for (int round = 0; round < 10; ++round) {
                    double s1 = 0, s2 = 0, m = 0;
                    for (int i = 0; i < n; ++i)
                        if (post.kept[size_t(i)]) {
                            s1 += post.residuals[size_t(i)];
                            s2 += post.residuals[size_t(i)] * post.residuals[size_t(i)];
                            ++m;
                        }
                    const double mean = s1 / m, sd = std::sqrt(std::max(0.0, s2 / m - mean * mean));
                    for (int i = 0; i < n; ++i)
                        if (std::fabs(post.residuals[size_t(i)] - mean) > 3 * sd) post.kept[size_t(i)] = 0;
                }
                if (!slr::windowShapeDoubt(post).empty()) ++refused;
            }
            return refused / 3000.0;
        };
        const char* names[] = {"Gaussian", "exponential tail", "t3", "5x wider fifth", "half flat", "flat", "30 % on a floor"};
        for (int n : {300, 50}) {
            QString line;
            double worstTrack = 0;
            for (int kind = 0; kind < 7; ++kind) {
                const double share = refusedShare(kind, n);
                line += QString(" %1 %2;").arg(names[kind]).arg(share, 0, 'f', 4);
                if (kind <= 4) worstTrack = std::max(worstTrack, share);
                if (kind == 5 && n == 300) QVERIFY2(share >= 0.97, qPrintable(line));
                if (kind == 6) QVERIFY2(share >= (n == 300 ? 0.97 : 0.5), qPrintable(line));
            }
            qInfo("%d points, refused:%s", n, qPrintable(line));
            QVERIFY2(worstTrack <= (n == 300 ? 0.002 : 0.005), qPrintable(line));
        }
    }

    // The evidence of a bin on hand-made residuals: a dense track among sparse noise stands; the
    // same track at the gate's edge, or among noise as dense as itself, does not.
    void binEvidenceOnHandMadeBins() {
        auto make = [](double trackAt, double noisePerNs, double gateLo, double gateHi, uint64_t seed) {
            slr::PostfitResult post;
            Rng rng(seed);
            std::vector<double> t;
            const int track = 30;
            const long long noise = static_cast<long long>(noisePerNs * (gateHi - gateLo) * 1e9);
            for (int i = 0; i < track; ++i) {
                t.push_back(rng.uniform(0, 900));
                post.residuals.push_back(trackAt + 150e-12 * rng.normal());
            }
            for (long long i = 0; i < noise; ++i) {
                t.push_back(rng.uniform(0, 900));
                post.residuals.push_back(rng.uniform(gateLo, gateHi));
            }
            post.stats.rms = 150e-12;
            slr::NormalPoint np;
            np.binStartS = 0;
            np.windowS = 900;
            post.normalPoints.push_back(np);
            return std::make_pair(t, post);
        };
        {
            const auto [t, post] = make(0, 1, -100e-9, 100e-9, 1);  // 30 on a track, 200 over 200 ns
            const auto e = slr::normalPointEvidence(t, post);
            QCOMPARE(e.size(), size_t(1));
            QVERIFY2(e[0].why.empty(), e[0].why.c_str());
            QVERIFY(e[0].expectedNoise < 3 && e[0].pValue < 1e-10 && e[0].edgeRoom > 20);
        }
        {
            const auto [t, post] = make(0, 1, -0.5e-9, 100e-9, 2);  // the gate opens at the track
            const auto e = slr::normalPointEvidence(t, post);
            QVERIFY2(e[0].why.find("edge of the gate") != std::string::npos, e[0].why.c_str());
        }
        {
            const auto [t, post] = make(0, 30, -100e-9, 100e-9, 3);  // 27 noise a window: 30 on it is no track
            const auto e = slr::normalPointEvidence(t, post);
            QVERIFY2(!e[0].why.empty(), "a track as dense as the noise stood");
        }
        {
            // The room to the gate's edge against the literal walk over every point of the bin
            // (the 16 nearest points in time off the window, earlier first at a tie), with
            // epochs on a 0.5 s grid (equal epochs: the ties), out of order and then in order,
            // and a second bin: the walk over the off-window points alone and the bins taken
            // from an order sorted once give the same median.
          for (const bool sorted : {false, true}) {
            auto [t, post] = make(0, 3, -20e-9, 35e-9, 4);
            for (double& x : t) x = std::floor(2 * x) / 2;
            if (sorted) {
                std::vector<size_t> idx(t.size());
                for (size_t i = 0; i < idx.size(); ++i) idx[i] = i;
                std::stable_sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return t[a] < t[b]; });
                std::vector<double> t2, r2;
                for (size_t i : idx) {
                    t2.push_back(t[i]);
                    r2.push_back(post.residuals[i]);
                }
                t = t2;
                post.residuals = r2;
            }
            post.kept.assign(t.size(), 1);
            slr::NormalPoint second;
            second.binStartS = 450;
            second.windowS = 450;
            post.normalPoints[0].windowS = 450;
            post.normalPoints.push_back(second);
            const auto e = slr::normalPointEvidence(t, post);
            QCOMPARE(e.size(), size_t(2));
            const double h = 3 * post.stats.rms;
            for (size_t k = 0; k < 2; ++k) {
                std::vector<std::pair<double, double>> pts;
                for (size_t i = 0; i < t.size(); ++i)
                    if (t[i] >= 450.0 * double(k) && t[i] < 450.0 * double(k + 1)) pts.emplace_back(t[i], post.residuals[i]);
                std::sort(pts.begin(), pts.end());
                std::vector<double> rooms;
                for (size_t i = 0; i < pts.size(); ++i) {
                    if (std::fabs(pts[i].second) > h) continue;
                    double lo = -h, hi = h;
                    size_t a = i, b = i, got = 0;
                    while (got < 16 && (a > 0 || b + 1 < pts.size())) {
                        const bool left = a > 0 && (b + 1 >= pts.size() || pts[i].first - pts[a - 1].first <= pts[b + 1].first - pts[i].first);
                        const double r = pts[left ? --a : ++b].second;
                        if (std::fabs(r) <= h) continue;
                        lo = std::min(lo, r);
                        hi = std::max(hi, r);
                        ++got;
                    }
                    rooms.push_back(std::min(-h - lo, hi - h) / (2 * h));
                }
                QVERIFY(rooms.size() >= 10);
                std::nth_element(rooms.begin(), rooms.begin() + long(rooms.size() / 2), rooms.end());
                QCOMPARE(e[k].edgeRoom, rooms[rooms.size() / 2]);
            }
          }
        }
        // Every point within the window and none beside it (a scale that joins the whole gate
        // into one region; a station's narrow gate): the counts cannot measure the noise, the
        // window's shape judges. Noise filling the window is refused; a track (a fifth of it
        // moved by 0.67σ) stands.
        for (const bool flat : {true, false}) {
            slr::PostfitResult post;
            Rng rng(flat ? 5 : 6);
            std::vector<double> t;
            for (int i = 0; i < 2000; ++i) {
                t.push_back(rng.uniform(0, 900));
                post.residuals.push_back(flat ? rng.uniform(-300e-12, 300e-12) : 150e-12 * rng.normal() + (rng.uniform(0, 1) < 0.2 ? 100e-12 : 0));
            }
            double ss = 0;
            for (double r : post.residuals) ss += r * r;
            post.stats.rms = std::sqrt(ss / 2000);
            post.kept.assign(2000, 1);
            for (size_t i = 0; i < 2000; ++i)
                if (std::fabs(post.residuals[i]) > 3 * post.stats.rms) post.kept[i] = 0;
            slr::NormalPoint np;
            np.windowS = 900;
            post.normalPoints.push_back(np);
            const auto e = slr::normalPointEvidence(t, post);
            if (flat) {
                QCOMPARE(e[0].offPoints, 0LL);
                QVERIFY2(e[0].why.find("fill the post-fit's window evenly") != std::string::npos, e[0].why.c_str());
            } else {
                QVERIFY2(e[0].why.empty(), e[0].why.c_str());
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestSlrLunar)
#include "test_slr_lunar.moc"
