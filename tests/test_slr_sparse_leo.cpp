// Issue 43, item 1: LEO passes without a prediction. A short sparse LEO pass (10–30 ranges over a
// real pass geometry, in bursts parted by gaps of 30 s – 3 min, or along one arc) is screened and
// post-fitted against its own TOF trend, which may now be an orbit arc (core/slr/oc.hpp
// computeTrendOc). The truth of a normal point is the normal point of the true track: the true
// TOF at the NP epoch plus the mean, over the points the bin kept, of their observed minus true
// TOF (what the ILRS algorithm gives with a perfect trend; the noise of the returns is not the
// trend's error). The simulator (core/sim/slr_sim_sparse) ranges a circular orbit of 500–1400 km
// from an ILRS station (its WGS-84 position) on the rotating Earth. Three trends are compared:
// the polynomial in TOF^2, the orbit arc, and the circular orbit itself (core/slr/orbit_fit.hpp).
// Asserted: the arc follows noise-free passes to a few ps,
// and on noisy ones rejects fewer returns, fails fewer passes and leaves fewer normal points over
// 5 mm than the polynomial alone; the target (every NP within 5 mm, every return kept) is
// not reached yet and the shortfalls are printed ("SHORT" lines; docs/slr-detection.md says why).
// Beside each NP's error stands its ceiling, the Cramér–Rao bound of its trend error under the
// pass's physical model (NpBound): an NP is short when it is beyond max(5 mm, 4 bounds).
// The shared real LEO passes must agree with the stations' own normal points at least as well.
// LWB_SPARSE_SEED=N runs one seed of sparseLeoPassesFollowTheArc, LWB_SPARSE_DEBUG=1 prints its points.
#include <QtTest>
#include <QTemporaryDir>
#include <cmath>

#include "core/common/rng.hpp"
#include "core/sim/slr_sim_sparse.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/ilrs_tables.hpp"
#include "core/slr/np_compare.hpp"
#include "core/slr/orbit_fit.hpp"
#include "core/slr/oc.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/pass_run.hpp"
#include "core/slr/postfit.hpp"
#include "test_support.hpp"
#include <Eigen/Dense>

using namespace lwb::core;
using namespace lwb::core::slr;
namespace sim = lwb::core::sim;

namespace {

constexpr double kC = 299792458.0;
constexpr double kMmPerS = kC / 2 * 1e3;  // two-way s -> one-way mm

struct SparseOutcome {
    bool ok = false;
    std::string error;
    bool arc = false;               // the orbit-arc trend was chosen
    size_t signal = 0, signalKept = 0, noiseKept = 0;
    double rmsPs = NAN;
    std::vector<double> npErrMm;    // per NP: against the NP of the true track
    std::vector<double> npRawMm;    // per NP: against the true range at its epoch (noise included)
    std::vector<double> npBoundMm;  // per NP: its Cramer-Rao bound (NpBound)
    std::vector<uint8_t> npDelivered;  // per NP: the run delivers it (not dropped, the pass not doubtful)
    std::vector<double> npTrendErrMm;  // per NP: the run's estimate of its trend error, one sigma (normalPointTrendErrors)
    std::string doubt;
};

// The ceiling of a normal point's accuracy on a sparse pass: the Cramér–Rao bound of its trend
// error under the pass's physical model, seven parameters: the orbit's radius and mean motion,
// its plane and phase (three small rotations of the orbit), the station's latitude, a range
// bias; Gaussian jitter. An NP's trend error is the fitted trend at its epoch less the mean of
// the fitted trend at its bin's points (each against the truth); its gradient G in the
// parameters gives the bound sqrt(G' F^-1 G), F the Fisher information of the signal returns.
// No unbiased estimate of the trend from the returns does better; the test's tolerance for an
// NP is max(5 mm, 4 bounds).
class NpBound {
public:
    NpBound(const sim::SparseLeoPass& s, double jitterS) : s_(s) {
        Eigen::MatrixXd info = Eigen::MatrixXd::Zero(kP, kP);
        for (size_t i = 0; i < s.epochS.size(); ++i)
            if (s.isSignal[i]) {
                const Eigen::VectorXd g = gradient(s.epochS[i]);
                info += g * g.transpose() / (jitterS * jitterS);
            }
        cov_ = info.completeOrthogonalDecomposition().pseudoInverse();
    }
    // The bound (mm) of an NP at `epoch` over a bin's points at `binEpochs`.
    double sigmaMm(double epoch, const std::vector<double>& binEpochs) const {
        Eigen::VectorXd G = gradient(epoch);
        for (double t : binEpochs) G -= gradient(t) / double(binEpochs.size());
        return std::sqrt(std::max(0.0, G.dot(cov_ * G))) * kMmPerS;
    }

private:
    static constexpr int kP = 7;
    sim::SparseLeoPass perturbed(int k, double h) const {
        sim::SparseLeoPass q = s_;
        if (k == 0) {
            q.radiusM += h;
        } else if (k <= 3) {
            const Eigen::Matrix3d rot = Eigen::AngleAxisd(h, Eigen::Vector3d::Unit(k - 1)).toRotationMatrix();
            const Eigen::Vector3d pp = rot * Eigen::Vector3d(q.p[0], q.p[1], q.p[2]), qq = rot * Eigen::Vector3d(q.q[0], q.q[1], q.q[2]);
            for (int j = 0; j < 3; ++j) q.p[j] = pp(j), q.q[j] = qq(j);
        } else if (k == 4) {
            q.meanMotion += h;
        } else if (k == 5) {
            const double rxy = std::hypot(q.station[0], q.station[1]), lon = std::atan2(q.station[1], q.station[0]);
            const double r = std::hypot(rxy, q.station[2]), lat = std::atan2(q.station[2], rxy) + h;
            q.station[0] = r * std::cos(lat) * std::cos(lon), q.station[1] = r * std::cos(lat) * std::sin(lon);
            q.station[2] = r * std::sin(lat);
        }
        return q;
    }
    Eigen::VectorXd gradient(double t) const {
        static constexpr double kStep[kP] = {1.0, 1e-7, 1e-7, 1e-7, 1e-10, 1e-7, 0};
        Eigen::VectorXd g(kP);
        for (int k = 0; k < kP - 1; ++k)
            g(k) = (sim::sparseLeoTrueTof(perturbed(k, kStep[k]), t) - sim::sparseLeoTrueTof(perturbed(k, -kStep[k]), t)) /
                   (2 * kStep[k]);
        g(kP - 1) = 1;  // the range bias
        return g;
    }
    const sim::SparseLeoPass& s_;
    Eigen::MatrixXd cov_;
};

sim::SparseLeoParams sparseCase(uint64_t seed) {
    Rng rng(Rng::mix(4300, seed));
    sim::SparseLeoParams p;
    p.ranges = 10 + int(seed % 21);
    p.gaps = seed % 2 == 1;
    p.altitudeKm = rng.uniform(500, 1400);
    p.jitterS = rng.uniform(50e-12, 200e-12);
    p.noisePoints = seed % 3 == 0 ? 1 + int(seed / 3 % 3) : 0;
    p.stationLatDeg = rng.uniform(-60, 60);
    p.stationLonDeg = rng.uniform(-180, 180);
    // An ILRS station (within ±60° of latitude) at its own position: a real pass without a
    // prediction comes from a station the ILRS table knows (LWB_SPARSE_SIMU=1: the 6371 km
    // sphere's station SIMU instead, which the table does not know).
    if (!qEnvironmentVariableIsSet("LWB_SPARSE_SIMU")) {
        std::vector<int> pads;
        for (const IlrsStation& st : ilrsStations())
            if (std::fabs(st.latDeg) <= 60) pads.push_back(st.pad);
        p.stationPad = pads[static_cast<size_t>(rng.uniform() * double(pads.size())) % pads.size()];
    }
    return p;
}

// The own-TOF trend models compared: the polynomial in TOF^2 alone, the orbit arc (linear
// coefficients) without the circular orbit, and everything (the default).
enum class Trend { Polynomial, Arc, Orbit };

// Seed's case without jitter or noise points.
sim::SparseLeoPass noiseFreePass(uint64_t seed, sim::SparseLeoParams* params = nullptr) {
    sim::SparseLeoParams p = sparseCase(seed);
    p.jitterS = 0;
    p.noisePoints = 0;
    if (params) *params = p;
    return sim::simulateSparseLeoPass(p, seed);
}

SparseOutcome runSparse(const sim::SparseLeoParams& sp, uint64_t seed, Trend trend, const QString& dir) {
    const bool orbitArc = trend != Trend::Polynomial;
    SparseOutcome o;
    const sim::SparseLeoPass s = sim::simulateSparseLeoPass(sp, seed);
    if (!s.ok) {
        o.error = s.error;
        return o;
    }
    const QString path = dir + QString("/sparse_%1_%2.frd").arg(seed).arg(int(trend));
    {
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly)) return o;
        f.write(QByteArray::fromStdString(sim::sparseLeoPassCrd(s)));
    }
    PassInputParams ip;
    ip.trend.orbitArc = orbitArc;
    ip.trend.circularOrbit = trend == Trend::Orbit;
    const PassInputResult in = loadPass(path.toStdString(), 0, ip);
    if (!in.ok) {
        o.error = in.error;
        return o;
    }
    for (const std::string& n : in.notes) o.arc = o.arc || n.find("orbit-arc") != std::string::npos;
    PassSettings set;
    std::string err;
    if (!passSettings(in.pass, commandDefaults(), nullptr, "", nullptr, &set, &err)) {
        o.error = err;
        return o;
    }
    // The ILRS bin of the true altitude; the night minimum of 3 points a bin (a sparse pass).
    set.params.postfit.binLengthS = normalPointBinS(sp.altitudeKm);
    set.params.postfit.dayNight = PostfitParams::DayNight::Night;
    if (qEnvironmentVariableIsSet("LWB_SPLIT")) set.params.postfit.splitGapS = qEnvironmentVariable("LWB_SPLIT").toDouble();
    const PassRunResult run = runPass(in.pass, set.params);
    if (!run.ok || !run.postOk) {
        o.error = run.ok ? run.postNote : run.error;
        return o;
    }
    o.doubt = run.doubt;
    // The normal points of the post-fit on the run's accepted points, before the run's doubt
    // rules take them away (a doubt is counted apart: the trend and the post-fit are tested here).
    const PassData& d = in.pass;
    PassRunResult r = run;
    const PostfitParams pfp = postfitForPass(set.params.postfit, nullptr, &d);
    r.post = postfit(d.t, d.oc, run.accepted, d.tof, pfp);
    if (!r.post.ok) {
        o.error = r.post.error;
        return o;
    }
    if (qEnvironmentVariableIsSet("LWB_SPARSE_DEBUG")) {
        for (const std::string& n : in.notes) qInfo("  %s", n.c_str());
        for (size_t i = 0; i < d.t.size(); ++i)
            qInfo("  %10.1f oc %12.3f ns true err %8.3f ns flag %d acc %d kept %d res %10.3f ns", d.t[i], d.oc[i] * 1e9,
                  (d.tof[i] - sim::sparseLeoTrueTof(s, d.t[i])) * 1e9, d.stationFlag[i], run.accepted[i], r.post.kept[i],
                  r.post.residuals[i] * 1e9);
    }

    for (size_t i = 0; i < d.t.size(); ++i) {
        const bool sig = d.stationFlag[i] == 2;
        o.signal += sig;
        o.signalKept += sig && r.post.kept[i];
        o.noiseKept += !sig && r.post.kept[i];
    }
    o.rmsPs = r.post.stats.rms * 1e12;
    const std::vector<double> trendErr = normalPointTrendErrors(d, r.post);
    for (double e : trendErr) o.npTrendErrMm.push_back(e * kMmPerS);
    const double L = r.post.binLengthS;
    const NpBound bound(s, sp.jitterS);
    for (const NormalPoint& np : r.post.normalPoints) {
        double sum = 0;
        int m = 0;
        std::vector<double> binEpochs;
        for (size_t i = 0; i < d.t.size(); ++i)
            if (r.post.kept[i] && std::floor(d.t[i] / L) == std::floor(np.binStartS / L + 1e-9)) {
                sum += d.tof[i] - sim::sparseLeoTrueTof(s, d.t[i]);
                binEpochs.push_back(d.t[i]);
                ++m;
            }
        o.npBoundMm.push_back(bound.sigmaMm(np.epochS, binEpochs));
        const double truth = sim::sparseLeoTrueTof(s, np.epochS);
        o.npErrMm.push_back((np.tofS - truth - (m ? sum / m : 0)) * kMmPerS);
        if (qEnvironmentVariableIsSet("LWB_SPARSE_DEBUG"))
            qInfo("  NP %.1f (%d points): %.2f mm (bound %.2f mm); post-fit segments %zu, degree %d", np.epochS, np.points, o.npErrMm.back(), o.npBoundMm.back(),
                  r.post.segments.size(), r.post.degree);
        o.npRawMm.push_back((np.tofS - truth) * kMmPerS);
        const auto out = std::find_if(run.post.normalPoints.begin(), run.post.normalPoints.end(),
                                      [&](const NormalPoint& x) { return x.binStartS == np.binStartS; });
        o.npDelivered.push_back(out != run.post.normalPoints.end());
        if (m != np.points) o.error = "bin membership differs from the normal point's count";
    }
    o.ok = o.error.empty();
    return o;
}

double worstAbs(const std::vector<double>& v) {
    double w = 0;
    for (double x : v) w = std::max(w, std::fabs(x));
    return w;
}

}  // namespace

class TestSlrSparseLeo : public QObject {
    Q_OBJECT
private slots:
    // The NP bound itself: positive and finite, proportional to the jitter (the Fisher
    // information goes as 1/sigma^2), zero for a bin of one point at its own epoch (the trend's
    // error cancels), and larger for an epoch far from the bin's points (the trend's slope
    // error then counts).
    void npBoundIsConsistent() {
        for (uint64_t seed = 1; seed <= 10; ++seed) {
            const sim::SparseLeoParams p = sparseCase(seed);
            const sim::SparseLeoPass s = sim::simulateSparseLeoPass(p, seed);
            QVERIFY(s.ok);
            const NpBound b1(s, p.jitterS), b2(s, 2 * p.jitterS);
            const std::vector<double> bin(s.epochS.begin(), s.epochS.begin() + 3);
            const double v1 = b1.sigmaMm(s.epochS[1], bin), v2 = b2.sigmaMm(s.epochS[1], bin);
            QVERIFY2(v1 > 0 && std::isfinite(v1), qPrintable(QString::number(v1)));
            QVERIFY2(std::fabs(v2 / v1 - 2) < 1e-6, qPrintable(QString("%1 vs %2").arg(v2).arg(v1)));
            QCOMPARE(b1.sigmaMm(s.epochS[2], {s.epochS[2]}), 0.0);
            QVERIFY(b1.sigmaMm(s.epochS.back(), bin) > v1);
        }
    }

    // The circular orbit's fit itself (core/slr/orbit_fit.hpp) on noise-free passes from ILRS
    // stations, the station's position given: every residual within 2 ps on at least 34 of 40 (37 here)
    // (its search can miss the minimum; the BIC then keeps the arc). (The radius is not asserted:
    // a short pass leaves it sloppy, 30 km off with the residuals under 2 ps.) And what it
    // refuses: too few points, no station, unequal lengths.
    void circularOrbitFitsANoiseFreePass() {
        int fitted = 0;
        for (uint64_t seed = 1; seed <= 40; ++seed) {
            const sim::SparseLeoPass s = noiseFreePass(seed);
            QVERIFY(s.ok);
            const double tm = 0.5 * (s.epochS.front() + s.epochS.back());
            std::vector<double> ss;
            for (double t : s.epochS) ss.push_back(t - tm);
            CircularOrbitParams cp;
            const double a = kEarthRotationRate * (tm - s.tRefS);  // (the station at the middle epoch)
            cp.stationEcef = Eigen::Vector3d(std::cos(a) * s.station[0] - std::sin(a) * s.station[1],
                                             std::sin(a) * s.station[0] + std::cos(a) * s.station[1], s.station[2]);
            // (the apparent rate the arc would give: the orbit's, 3 % off)
            cp.arcRate = s.meanMotion * (seed % 2 ? 1.03 : 0.97);
            const CircularOrbitResult f = fitCircularOrbit(ss, s.tofS, {}, cp);
            QVERIFY2(f.ok, f.error.c_str());
            QCOMPARE(f.parameters, 5);
            double worst = 0;
            for (double r : f.residualS) worst = std::max(worst, std::fabs(r));
            fitted += worst < 2e-12;
        }
        qInfo("circular orbit within 2 ps of 40 noise-free passes: %d", fitted);
        QVERIFY(fitted >= 34);
        CircularOrbitParams cp;
        cp.arcRate = 1e-3;
        cp.stationEcef = Eigen::Vector3d(6371e3, 0, 0);
        const std::vector<double> s5 = {0, 1, 2, 3, 4}, t5 = {0.01, 0.01, 0.01, 0.01, 0.01};
        QVERIFY(fitCircularOrbit(s5, t5, {}, cp).error.find("too few points") != std::string::npos);
        std::vector<double> s20(20), t20(20, 0.01);
        for (size_t i = 0; i < 20; ++i) s20[i] = double(i);
        CircularOrbitParams noStation = cp;
        noStation.stationEcef = Eigen::Vector3d::Zero();
        QVERIFY(fitCircularOrbit(s20, t20, {}, noStation).error.find("no station") != std::string::npos);
        QVERIFY(fitCircularOrbit(s20, t5, {}, cp).error.find("differ in length") != std::string::npos);
    }

    // The simulator: a real pass geometry (the range of the true orbit at the stated epochs),
    // the counts asked for, gaps of at least 30 s between bursts (unless shrunk to fit).
    void simulatorGivesAPass() {
        for (uint64_t seed = 1; seed <= 20; ++seed) {
            const sim::SparseLeoParams p = sparseCase(seed);
            const sim::SparseLeoPass s = sim::simulateSparseLeoPass(p, seed);
            QVERIFY2(s.ok, s.error.c_str());
            QCOMPARE(s.epochS.size(), size_t(p.ranges + p.noisePoints));
            QVERIFY(std::is_sorted(s.epochS.begin(), s.epochS.end()));
            size_t sig = 0;
            for (size_t i = 0; i < s.epochS.size(); ++i) {
                sig += s.isSignal[i];
                const double rangeKm = s.trueTofS[i] * kC / 2e3;
                QVERIFY2(rangeKm >= p.altitudeKm - 1 && rangeKm < 4500, qPrintable(QString::number(rangeKm)));
                QVERIFY(s.epochS[i] >= s.passStartS - 1 && s.epochS[i] <= s.passEndS + 1);
                if (s.isSignal[i]) QVERIFY(std::fabs(s.tofS[i] - s.trueTofS[i]) < 8 * p.jitterS);
            }
            QCOMPARE(sig, size_t(p.ranges));
            QVERIFY(s.maxElevationDeg > 20);
        }
    }

    // Noise-free passes: how closely the orbit arc follows a real pass's TOF.
    void arcFollowsANoiseFreePass() {
        std::vector<double> worsts, worstsBefore;
        for (uint64_t seed = 1; seed <= 40; ++seed) {
            sim::SparseLeoParams p;
            const sim::SparseLeoPass s = noiseFreePass(seed, &p);
            QVERIFY(s.ok);
            const CrdReadResult crd = parseCrd(sim::sparseLeoPassCrd(s), "sim.frd");
            QVERIFY2(crd.ok, crd.error.c_str());
            const OcResult oc = computeTrendOc(crd.file.passes.front(), TrendOcParams());
            QVERIFY2(oc.ok, oc.error.c_str());
            TrendOcParams polyOnly;
            polyOnly.orbitArc = false;
            const OcResult before = computeTrendOc(crd.file.passes.front(), polyOnly);
            QVERIFY(before.ok);
            double worst = 0, worstBefore = 0;
            for (double v : oc.oc_s) worst = std::max(worst, std::fabs(v));
            for (double v : before.oc_s) worstBefore = std::max(worstBefore, std::fabs(v));
            worsts.push_back(worst);
            worstsBefore.push_back(worstBefore);
            QVERIFY2(worst <= 200e-12, qPrintable(QString("seed %1: %2 ps").arg(seed).arg(worst * 1e12)));
            const std::string& note = oc.notes.front();
            qInfo("seed %llu: %d ranges%s over %.0f s, %.0f km, max el %.0f: max |O-C| %.1f ps (%s), polynomial alone %.1f ps",
                  (unsigned long long)seed, p.ranges, p.gaps ? " with gaps" : "", s.epochS.back() - s.epochS.front(),
                  p.altitudeKm, s.maxElevationDeg, worst * 1e12, note.substr(note.find("relative to") + 12, 30).c_str(),
                  worstBefore * 1e12);
        }
        std::sort(worsts.begin(), worsts.end());
        std::sort(worstsBefore.begin(), worstsBefore.end());
        qInfo("noise-free, 40 passes: max |O-C| median %.1f ps, 90th %.1f ps, worst %.1f ps; the polynomial alone: median %.1f "
              "ps, 90th %.1f ps, worst %.1f ps",
              worsts[20] * 1e12, worsts[36] * 1e12, worsts.back() * 1e12, worstsBefore[20] * 1e12, worstsBefore[36] * 1e12,
              worstsBefore.back() * 1e12);
        QVERIFY(worsts[36] <= 10e-12);  // 90 % of the passes within 10 ps (CRD TOFs are given to 1 ps)
    }

    // 120 seeded passes: 10–30 ranges (10 + seed mod 21), odd seeds in bursts with gaps, even
    // seeds along one arc; 500–1400 km, jitter 50–200 ps, every third seed 1–3 noise points in a
    // 2 us gate; ILRS stations within ±60° of latitude. Measured per pass against the target (not
    // doubtful without noise, every return kept, no noise kept, post-fit RMS 0.3–2 x the jitter,
    // every NP within 5 mm of the truth; shortfalls printed), and the same passes with the
    // polynomial trend alone and with the arc without the circular orbit. Asserted: fewer failed
    // passes, under half the rejected returns and fewer passes with an NP over 5 mm than the
    // polynomial alone; fewer NPs beyond max(5 mm, 4 bounds) and fewer passes over 5 mm than the
    // arc alone, and no more failures. And no confident wrong answer: none of the NPs beyond
    // max(5 mm, 4 bounds) is delivered by the run (its pass doubtful or the NP dropped as
    // imprecise, pass_run.hpp kMaxNpTrendErrorMm), at most a quarter of the others withheld, and
    // the run's own one-sigma estimate of each NP's trend error (normalPointTrendErrors) the
    // errors' scale at their core (median |error| / estimate 0.45-0.95). (The target's "not
    // doubtful without noise" now gives SHORT lines where the estimate withholds a pass's NPs.)
    void sparseLeoPassesFollowTheArc() {
        QTemporaryDir dir;
        QStringList failures;
        constexpr uint64_t kSeeds = 120;
        double worstAfter = 0, worstBefore = 0;
        size_t failedAfter = 0, lostAfter = 0, passesAfterOver5 = 0, doubtful = 0, nps = 0, npsBefore = 0, arcs = 0, lostBefore = 0, failedBefore = 0, passesBeforeOver5 = 0;
        double worstRmsRatio = 0, bestRmsRatio = 1e9;
        size_t beyondBound = 0, boundOver = 0, arcBeyondBound = 0, arcOver5 = 0, arcFailed = 0;
        size_t confidentBeyond = 0, withinWithheld = 0;  // NPs beyond the tolerance the run delivers; within it, not delivered
        std::vector<double> zs;  // per NP: |error| over the run's own one-sigma estimate of it
        size_t delivered = 0, deliveredOver5 = 0;
        double deliveredWorst = 0;
        double arcWorst = 0;
        for (uint64_t seed = 1; seed <= kSeeds; ++seed) {
            if (qEnvironmentVariableIsSet("LWB_SPARSE_SEED") && seed != qEnvironmentVariable("LWB_SPARSE_SEED").toULongLong()) continue;
            const sim::SparseLeoParams p = sparseCase(seed);
            const QString what = QString("seed %1: %2 ranges%3, %4 km, %5 ps, %6 noise")
                                     .arg(seed)
                                     .arg(p.ranges)
                                     .arg(p.gaps ? " with gaps" : "")
                                     .arg(p.altitudeKm, 0, 'f', 0)
                                     .arg(p.jitterS * 1e12, 0, 'f', 0)
                                     .arg(p.noisePoints);
            // The arc without the circular orbit: NPs beyond the tolerance, passes over 5 mm.
            const SparseOutcome c = runSparse(p, seed, Trend::Arc, dir.path());
            if (c.ok) {
                for (size_t k = 0; k < c.npErrMm.size(); ++k)
                    arcBeyondBound += !(std::fabs(c.npErrMm[k]) <= std::max(5.0, 4 * c.npBoundMm[k]));
                arcOver5 += worstAbs(c.npErrMm) > 5;
                arcWorst = std::max(arcWorst, worstAbs(c.npErrMm));
            } else {
                ++arcFailed;
            }
            const SparseOutcome a = runSparse(p, seed, Trend::Orbit, dir.path());
            auto fail = [&](const QString& why) {
                failures << what + ": " + why;
                qInfo("SHORT %s", qPrintable(failures.back()));
            };
            if (!a.ok) {
                fail(QString::fromStdString(a.error));
                ++failedAfter;
                continue;
            }
            if (p.noisePoints == 0 && !a.doubt.empty()) fail("doubtful: " + QString::fromStdString(a.doubt));
            else if (!a.doubt.empty()) {
                ++doubtful;
                qInfo("%s: doubtful: %s", qPrintable(what), a.doubt.c_str());
            }
            if (a.signalKept != a.signal) fail(QString("%1 of %2 returns kept").arg(a.signalKept).arg(a.signal));
            if (a.noiseKept != 0) fail(QString("%1 noise points kept").arg(a.noiseKept));
            const double ratio = a.rmsPs / (p.jitterS * 1e12);
            worstRmsRatio = std::max(worstRmsRatio, ratio);
            bestRmsRatio = std::min(bestRmsRatio, ratio);
            if (!(ratio >= 0.3 && ratio <= 2.0)) fail(QString("post-fit RMS %1 ps").arg(a.rmsPs));
            bool boundOver5 = false;
            for (size_t k = 0; k < a.npErrMm.size(); ++k)
                if (std::isfinite(a.npTrendErrMm[k]) && a.npTrendErrMm[k] > 0) zs.push_back(std::fabs(a.npErrMm[k]) / a.npTrendErrMm[k]);
            for (size_t k = 0; k < a.npErrMm.size(); ++k) {
                const double e = a.npErrMm[k], tol = std::max(5.0, 4 * a.npBoundMm[k]);
                boundOver5 = boundOver5 || 4 * a.npBoundMm[k] > 5;
                if (!(std::fabs(e) <= tol)) {
                    fail(QString("NP %1 mm off (bound %2 mm)%3").arg(e).arg(a.npBoundMm[k]).arg(a.npDelivered[k] ? ", DELIVERED" : ", not delivered"));
                    ++beyondBound;
                    if (a.npDelivered[k]) ++confidentBeyond;
                } else if (!a.npDelivered[k]) {
                    ++withinWithheld;
                }
                if (a.npDelivered[k]) {
                    ++delivered;
                    deliveredOver5 += std::fabs(e) > 5;
                    deliveredWorst = std::max(deliveredWorst, std::fabs(e));
                }
            }
            boundOver += boundOver5;
            worstAfter = std::max(worstAfter, worstAbs(a.npErrMm));
            lostAfter += a.signal - a.signalKept;
            passesAfterOver5 += worstAbs(a.npErrMm) > 5;
            nps += a.npErrMm.size();
            arcs += a.arc;
            const SparseOutcome b = runSparse(p, seed, Trend::Polynomial, dir.path());
            if (!b.ok) {
                ++failedBefore;
                continue;
            }
            lostBefore += b.signal - b.signalKept;
            worstBefore = std::max(worstBefore, worstAbs(b.npErrMm));
            passesBeforeOver5 += worstAbs(b.npErrMm) > 5;
            npsBefore += b.npErrMm.size();
        }
        qInfo("%llu sparse LEO passes, orbit arc chosen on %zu: %zu normal points, worst %.3f mm from the truth; post-fit "
              "RMS %.2f-%.2f x the jitter; %zu of the passes with noise points judged doubtful by the run; %zu returns rejected, "
              "%zu passes over 5 mm, %zu failed",
              static_cast<unsigned long long>(kSeeds), arcs, nps, worstAfter, bestRmsRatio, worstRmsRatio, doubtful, lostAfter,
              passesAfterOver5, failedAfter);
        qInfo("  the polynomial trend alone: %zu passes failed, %zu returns rejected, %zu normal points, worst "
              "%.1f mm (%zu passes over 5 mm)",
              failedBefore, lostBefore, npsBefore, worstBefore, passesBeforeOver5);
        // Issue 43's target (every normal point within 5 mm, every return kept) is not reached
        // yet (docs/slr-detection.md, "Sparse LEO passes without a prediction"): the per-pass
        // failures above are printed; asserted is what the arc measurably improves.
        qInfo("  the ceiling: %zu passes have an NP whose Cramer-Rao bound exceeds 5/4 mm; %zu normal points beyond max(5 mm, "
              "4 bounds)", boundOver, beyondBound);
        qInfo("  the arc without the circular orbit: %zu normal points beyond max(5 mm, 4 bounds), %zu passes over 5 mm, worst "
              "%.1f mm, %zu failed", arcBeyondBound, arcOver5, arcWorst, arcFailed);
        qInfo("  delivered by the run (the pass not doubtful, the NP not dropped as imprecise): %zu of the %zu NPs beyond "
              "max(5 mm, 4 bounds); %zu of the %zu within withheld; of the %zu delivered, %zu over 5 mm (worst %.2f mm)",
              confidentBeyond, beyondBound, withinWithheld, nps - beyondBound, delivered, deliveredOver5, deliveredWorst);
        std::sort(zs.begin(), zs.end());
        const auto zq = [&](double q) { return zs.empty() ? NAN : zs[size_t(q * double(zs.size() - 1))]; };
        qInfo("  |NP error| over the run's own one-sigma estimate of it (normalPointTrendErrors), %zu NPs: median %.2f, 90th "
              "%.2f, 99th %.2f (a Gaussian: 0.67, 1.64, 2.58)", zs.size(), zq(0.5), zq(0.9), zq(0.99));
        qInfo("%lld per-pass shortfalls against the target (SHORT lines)", static_cast<long long>(failures.size()));
        QCOMPARE(failedBefore >= 1, true);          // the polynomial alone fails passes ...
        QVERIFY(nps >= kSeeds);                      // (bins of 3 points or more form)
        QVERIFY(lostAfter * 2 < lostBefore);         // ... and rejects more than twice the returns
        QVERIFY(passesAfterOver5 < passesBeforeOver5);
        QVERIFY(failedAfter < failedBefore);
        // The circular orbit against the arc alone: fewer normal points beyond the tolerance,
        // fewer passes over 5 mm, no more failures.
        QVERIFY2(beyondBound < arcBeyondBound, qPrintable(QString("%1 vs %2").arg(beyondBound).arg(arcBeyondBound)));
        QVERIFY(passesAfterOver5 < arcOver5);
        QVERIFY(failedAfter <= arcFailed);
        // No confident wrong answer: every normal point beyond the tolerance is withheld (its
        // pass doubtful, or the NP dropped as imprecise: pass_run.hpp kMaxNpTrendErrorMm), at a
        // cost of at most a quarter of the others.
        QCOMPARE(confidentBeyond, size_t(0));
        QCOMPARE(deliveredOver5, size_t(0));  // every normal point the run delivers within 5 mm of the truth
        // The estimate is the errors' scale at their core (median |z| 0.45-0.95, a Gaussian's 0.67),
        // not an underestimate by half or an overestimate by half; its tail is heavier (noise kept
        // and minima the linearisation does not see).
        QVERIFY2(zq(0.5) >= 0.45 && zq(0.5) <= 0.95, qPrintable(QString::number(zq(0.5))));
        QVERIFY2(withinWithheld * 4 <= nps - beyondBound, qPrintable(QString::number(withinWithheld)));
    }

    // The ERS-class pass: 785 km, 18 records at 10 Hz (12 returns in bursts, 6 noise
    // points in a 1 us gate), bins of 15 s; seeds 1-20, measured with the arc allowed and with
    // the polynomial alone. Asserted: the arc keeps more returns and no pass fails. Printed: the
    // normal points the run delivers that are over 5 mm from the truth (2026-12-07: 2 of 14 with
    // the arc, seed 14 through 2 kept noise points, seed 15 through the arc's misfit, which the
    // run's estimate of its precision, a variance, does not show; not asserted yet).
    void ersClassPass() {
        QTemporaryDir dir;
        double worst[2] = {0, 0};
        size_t lost[2] = {0, 0}, noiseKept[2] = {0, 0}, failed[2] = {0, 0}, over5[2] = {0, 0};
        size_t delivered[2] = {0, 0}, deliveredOver5[2] = {0, 0};  // NPs the run delivers; of them over 5 mm
        for (uint64_t seed = 1; seed <= 20; ++seed) {
            sim::SparseLeoParams p;
            p.altitudeKm = 785;
            p.ranges = 12;
            p.noisePoints = 6;
            p.gaps = true;
            p.jitterS = 150e-12;
            p.gateS = 1e-6;
            p.stationPad = 7080;  // McDonald (the default position's station)
            for (int arc = 0; arc < 2; ++arc) {
                const SparseOutcome a = runSparse(p, seed, arc == 1 ? Trend::Orbit : Trend::Polynomial, dir.path());
                if (!a.ok) {
                    ++failed[arc];
                    continue;
                }
                lost[arc] += a.signal - a.signalKept;
                noiseKept[arc] += a.noiseKept;
                worst[arc] = std::max(worst[arc], worstAbs(a.npErrMm));
                over5[arc] += worstAbs(a.npErrMm) > 5;
                for (size_t k = 0; k < a.npErrMm.size(); ++k) {
                    delivered[arc] += a.npDelivered[k];
                    deliveredOver5[arc] += a.npDelivered[k] && std::fabs(a.npErrMm[k]) > 5;
                    if (a.npDelivered[k] && std::fabs(a.npErrMm[k]) > 5)
                        qInfo("  seed %d (%s): NP %.1f mm from the truth delivered, estimate %.2f mm, %zu noise kept, %zu of %zu returns",
                              int(seed), arc ? "arc" : "polynomial", a.npErrMm[k], a.npTrendErrMm[k], a.noiseKept, a.signalKept, a.signal);
                }
            }
        }
        for (int arc = 0; arc < 2; ++arc)
            qInfo("ERS-class passes (12 returns + 6 noise, 785 km), 20 seeds, %s: %zu failed, %zu of 240 returns rejected, "
                  "%zu noise points kept, %zu passes with an NP over 5 mm, worst NP %.1f mm from the truth; the run delivers %zu "
                  "NPs, %zu of them over 5 mm",
                  arc ? "orbit arc allowed" : "polynomial alone", failed[arc], lost[arc], noiseKept[arc], over5[arc], worst[arc],
                  delivered[arc], deliveredOver5[arc]);
        QCOMPARE(failed[1], size_t(0));
        QVERIFY(lost[1] < lost[0]);
    }

    // The shared real LEO passes (no prediction): the normal points against the stations' own,
    // with the arc allowed (the default) and with the polynomial alone; which model was taken.
    // The agreement must not get worse than the polynomial's by more than 0.1 mm (mean |d|).
    void realPassesAgainstTheStation_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("pass");
        QTest::newRow("JASON1") << "7080_JASON1_crd_071220_2033_0" << 1;
        QTest::newRow("STELLA") << "7080_STELLA_crd_071220_2128_0" << 1;
        QTest::newRow("Beacon-C") << "7080_Beacon-C_crd_071220_1715_0" << 1;
        QTest::newRow("beaconc pass 1") << "beaconc_20070511" << 1;
        QTest::newRow("beaconc pass 2") << "beaconc_20070511" << 2;
        QTest::newRow("beaconc pass 3") << "beaconc_20070511" << 3;
    }
    void realPassesAgainstTheStation() {
        QFETCH(QString, file);
        QFETCH(int, pass);
        if (!lwbtest::haveShared("slr/" + file + ".npt")) QSKIP("shared SLR data absent");
        const CrdReadResult st = readCrd(lwbtest::str(lwbtest::sharedPath("slr/" + file + ".npt")));
        QVERIFY(st.ok);
        double meanAbs[2] = {NAN, NAN};
        for (int arc = 0; arc < 2; ++arc) {
            PassInputParams ip;
            ip.trend.orbitArc = arc == 1;
            const PassInputResult in = loadPass(lwbtest::str(lwbtest::sharedPath("slr/" + file + ".frd")), pass - 1, ip);
            QVERIFY2(in.ok, in.error.c_str());
            PassSettings set;
            std::string err;
            QVERIFY2(passSettings(in.pass, commandDefaults(), nullptr, "", nullptr, &set, &err), err.c_str());
            const PassRunResult run = runPass(in.pass, set.params);
            QVERIFY(run.postOk);
            // (the post-fit's normal points, before the run's doubt rules: the trend is tested)
            const PostfitResult post = postfit(in.pass.t, in.pass.oc, run.accepted, in.pass.tof,
                                               postfitForPass(set.params.postfit, nullptr, &in.pass));
            QVERIFY(post.ok);
            const NpComparison cmp = compareWithStation(in.pass, post, st.file, "station.npt");
            QVERIFY2(cmp.ok, cmp.error.c_str());
            meanAbs[arc] = cmp.meanAbsMm;
            qInfo("%s pass %d, %s: %s; %s", qPrintable(file), pass, arc ? "arc allowed" : "polynomial",
                  in.notes.empty() ? "" : in.notes.front().c_str(), cmp.describe().c_str());
        }
        QVERIFY2(meanAbs[1] <= meanAbs[0] + 0.1, qPrintable(QString("%1 mm against %2").arg(meanAbs[1]).arg(meanAbs[0])));
    }
};

QTEST_GUILESS_MAIN(TestSlrSparseLeo)
#include "test_slr_sparse_leo.moc"
