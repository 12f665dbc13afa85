// laserwb-cli slr end to end: every output on the shared MLRS files and on simulated passes,
// detection quality of the default automatic mode against the station's own filter flags and
// against the simulator's truth, and the bad inputs that must stop with a clear message, a
// non-zero exit and no output file.
//
// How the real passes are scored. The truth is the station's filter flag (2 data, 1 noise). The
// data README warns that a few noise-flagged points lie on the track itself: returns the
// station's own editing (its k-sigma clip) removed, which no screening can tell from signal.
// They are counted, not hidden: a robust Legendre trend (degree 8, 5-sigma clipped,
// sigma = 1.4826 MAD) is fitted to the flag-2 points; a flag-1 point inside the flag-2 time span
// and within 5 sigma of that trend is "on the track" (measured sigma 75-125 ps; the chance that a
// point of the 10 us wide noise lands in that +-0.6 ns band is below 1e-2 per pass). Such points
// are left out of the score (neither a true nor a false detection) and printed; every other
// point is scored against its flag. Precision = accepted flag-2 / accepted scored points,
// recall = accepted flag-2 / all flag-2. The raw figures (no exclusion) are printed too.
#include <QtTest>
#include <Eigen/Dense>
#include <cmath>

#include "core/common/csv.hpp"
#include "core/slr/crd.hpp"
#include "core/slr/pass_input.hpp"
#include "core/slr/pass_output.hpp"
#include "lwb_version.hpp"
#include "test_support.hpp"

using lwbtest::runCli;
using namespace lwb::core::slr;

namespace {

constexpr int kTimeoutMs = 120000;  // generous but finite: the slowest case here takes < 2 s

struct Row {
    long index = 0;
    double t = 0, oc = 0;
    std::string cls;
    int flag = -1;   // station flag (-1: none)
    int kept = 0;
};

bool readRows(const QString& path, std::vector<Row>* rows, QString* why) {
    const auto r = lwb::core::readCsv(path.toStdString());
    if (!r.ok) {
        *why = QString::fromStdString(r.error);
        return false;
    }
    const auto& t = r.table;
    const std::vector<std::string> want = {"index", "epoch_s", "oc_s", "class", "region", "residual_s", "kept", "station_flag"};
    for (size_t k = 0; k < want.size(); ++k)
        if (t.column(want[k]) != static_cast<int>(k)) {
            *why = QString("column %1 is not %2").arg(k).arg(QString::fromStdString(want[k]));
            return false;
        }
    for (const auto& row : t.rows) {
        Row x;
        x.index = std::stol(row[0]);
        x.t = std::stod(row[1]);
        x.oc = std::stod(row[2]);
        x.cls = row[3];
        x.kept = std::stoi(row[6]);
        x.flag = row[7].empty() ? -1 : std::stoi(row[7]);
        rows->push_back(x);
    }
    return true;
}

struct Score {
    double precision = 0, recall = 0, rawPrecision = 0;
    long tp = 0, fp = 0, flag2 = 0, onTrackFlag1 = 0, onTrackAccepted = 0;
    double sigmaPs = 0;
};

// Legendre basis value P_k(u), k = 0..deg.
Eigen::RowVectorXd legendre(double u, int deg) {
    Eigen::RowVectorXd p(deg + 1);
    p(0) = 1;
    if (deg > 0) p(1) = u;
    for (int k = 1; k < deg; ++k) p(k + 1) = ((2 * k + 1) * u * p(k) - k * p(k - 1)) / (k + 1);
    return p;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// Scores the CLI's classes against the station flags, with the on-track flag-1 points set apart
// (see the comment at the top).
Score scoreAgainstFlags(const std::vector<Row>& rows) {
    Score s;
    std::vector<size_t> use;
    for (size_t i = 0; i < rows.size(); ++i)
        if (rows[i].flag == 2) use.push_back(i);
    s.flag2 = static_cast<long>(use.size());
    double lo = 1e300, hi = -1e300;
    for (size_t i : use) {
        lo = std::min(lo, rows[i].t);
        hi = std::max(hi, rows[i].t);
    }
    const int deg = 8;
    auto u = [&](double t) { return 2 * (t - lo) / (hi - lo) - 1; };
    Eigen::VectorXd c;
    double sigma = 0;
    std::vector<size_t> fit = use;
    for (int it = 0; it < 30; ++it) {
        Eigen::MatrixXd a(static_cast<Eigen::Index>(fit.size()), deg + 1);
        Eigen::VectorXd b(static_cast<Eigen::Index>(fit.size()));
        for (size_t k = 0; k < fit.size(); ++k) {
            a.row(static_cast<Eigen::Index>(k)) = legendre(u(rows[fit[k]].t), deg);
            b(static_cast<Eigen::Index>(k)) = rows[fit[k]].oc;
        }
        c = a.colPivHouseholderQr().solve(b);
        std::vector<double> res;
        for (size_t i : fit) res.push_back(std::fabs(rows[i].oc - legendre(u(rows[i].t), deg).dot(c)));
        sigma = 1.4826 * median(res);
        std::vector<size_t> next;
        for (size_t i : use)
            if (std::fabs(rows[i].oc - legendre(u(rows[i].t), deg).dot(c)) <= 5 * sigma) next.push_back(i);
        if (next == fit) break;
        fit = next;
    }
    s.sigmaPs = sigma * 1e12;
    long rawTp = 0, rawFp = 0;
    for (const Row& r : rows) {
        const bool acc = r.cls != "noise";
        rawTp += acc && r.flag == 2;
        rawFp += acc && r.flag != 2;
        const bool onTrack = r.flag == 1 && r.t >= lo && r.t <= hi &&
                             std::fabs(r.oc - legendre(u(r.t), deg).dot(c)) <= 5 * sigma;
        if (onTrack) {
            ++s.onTrackFlag1;
            s.onTrackAccepted += acc;
            continue;
        }
        s.tp += acc && r.flag == 2;
        s.fp += acc && r.flag != 2;
    }
    s.precision = s.tp + s.fp ? double(s.tp) / double(s.tp + s.fp) : 0;
    s.recall = s.flag2 ? double(s.tp) / double(s.flag2) : 0;
    s.rawPrecision = rawTp + rawFp ? double(rawTp) / double(rawTp + rawFp) : 0;
    return s;
}

}  // namespace

class TestSlrCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString p(const QString& name) const { return m_dir.path() + "/" + name; }
    static QString slr(const QString& f) { return lwbtest::sharedPath("slr/" + f); }
    static bool have() { return lwbtest::haveShared("slr/7080_STELLA_crd_071220_2128_0.frd"); }

    /// Nothing but the expected files in the folder (no staged or temporary output left).
    void noStrayFiles() {
        for (const QString& f : lwbtest::filesIn(m_dir.path()))
            QVERIFY2(!f.contains(".tmp-") && !f.contains(".lwb-tmp-") && !f.contains(".lwb-stage-"), qPrintable(f));
    }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // ---------------------------------------------------------------- no normal point is a result (issue 29)
    // --npt-out alone is enough; a pass that forms no normal point still has its file, with the
    // reason in place of the records, and the exit code says which: 0 for "no signal found"
    // (a fixed scale at which no region reaches the area limit), 3 for a doubtful pass
    // (hy2c pass 1: 5 records on its own TOF trend). Never 1, and every output is there.
    /// Issue 44, "limits said, not hit": a pass whose run would not fit the memory the process may
    /// take is refused before it is read, with the figures (its file's size times the bytes an
    /// event measured, docs/benchmarks.md); a smaller one runs under the same limit. The limit
    /// here is the data segment's (ulimit -d 250 MB): the 10^6-event CRD file (55 MB) needs about
    /// 470 MB by the estimate and 394 MB measured, the 2·10^4-event one about 41 MB.
    void passBeyondTheMemoryIsRefusedBeforeReading() {
        QTemporaryDir dir;
        const QString big = dir.path() + "/big.frd", small = dir.path() + "/small.frd", table = dir.path() + "/big.csv";
        for (const auto& [n, f] : {std::pair{"1000000", big}, {"20000", small}})
            QVERIFY(runCli({"simulate", "slr", "--kind", "khz", "--points", n, "--seed", "3", "-q", f}).exitCode == 0);
        QVERIFY(runCli({"simulate", "slr", "--kind", "khz", "--points", "1000000", "--seed", "3", "-q", table}).exitCode == 0);
        auto limited = [&](const QString& in, const QString& out) {
            return lwbtest::runProgram(
                "/bin/sh", {"-c", QString("ulimit -d 250000 && exec '%1' slr '%2' -o '%3' -q").arg(LWB_CLI, in, out)});
        };
        for (const QString& in : {big, table}) {
            const QString out = in + ".out.csv";
            const lwbtest::CliRun r = limited(in, out);
            QCOMPARE(r.exitCode, 1);
            QVERIFY2(r.err.contains(in + ": about ") && r.err.contains("of memory is needed for its") &&
                         r.err.contains("is available (the data limit (ulimit -d))") && r.err.contains("not read"),
                     qPrintable(r.err));
            QVERIFY(!QFile::exists(out));
        }
        const lwbtest::CliRun s = limited(small, dir.path() + "/small.csv");
        QVERIFY2(s.exitCode == 0, qPrintable(s.err));
        QVERIFY(QFile::exists(dir.path() + "/small.csv"));
    }

    void noNormalPointIsAResult() {
        if (!have() || !lwbtest::haveShared("slr/hy2c_202109.fr2")) QSKIP("shared SLR data absent");
        const auto none = runCli({"slr", slr("7080_STELLA_crd_071220_2128_0.frd"), "--set", "screen.automatic=false", "--mag-t", "1",
                                  "--mag-oc", "1e7", "--area-min", "1000", "--connectivity", "8", "--npt-out", p("none.npt")},
                                 kTimeoutMs);
        QVERIFY2(none.exitCode == 0, qPrintable(none.err));
        QVERIFY(lwbtest::readAll(p("none.npt")).contains("\n00 no normal points: no signal found"));
        QVERIFY2(none.err.contains("screening precision undefined (nothing accepted)"), qPrintable(none.err));
        const auto doubtful = runCli({"slr", slr("hy2c_202109.fr2"), "--pass", "1", "--npt-out", p("d.npt"), "--crd-out", p("d.frd"),
                                      "-o", p("d.csv")},
                                     kTimeoutMs);
        QCOMPARE(doubtful.exitCode, 3);
        QVERIFY(QFile::exists(p("d.csv")) && QFile::exists(p("d.frd")));
        const QByteArray npt = lwbtest::readAll(p("d.npt"));
        QVERIFY2(npt.contains("\n00 no normal points: doubtful: 5 points on the pass's own TOF trend"), npt.constData());
        QVERIFY(!npt.contains("\n11 "));
        QVERIFY(npt.endsWith("H8\nH9\n"));
        // No output at all: the summary alone, nothing written (issue 43; noStrayFiles below).
        const auto summaryOnly = runCli({"slr", slr("hy2c_202109.fr2")});
        QVERIFY2(summaryOnly.exitCode == 0 || summaryOnly.exitCode == 3, qPrintable(summaryOnly.err));
        QVERIFY2(summaryOnly.err.contains("nothing written"), qPrintable(summaryOnly.err));
        noStrayFiles();
    }

    // The normal points are a station's product (issue 29): a fresh H1 production date
    // (SOURCE_DATE_EPOCH 1700000000 = 2023-11-14 22:13 UTC), a C5 software record (CRD v2) and
    // a record 50 with the pass's post-fit statistics (hy2c pass 6: RMS as the summary says,
    // quality 1: at most 10 % noise).
    void normalPointFileIsAStationProduct() {
        if (!lwbtest::haveShared("slr/hy2c_202109.fr2")) QSKIP("shared SLR data absent");
        const auto r = runCli({"slr", slr("hy2c_202109.fr2"), "--pass", "6", "--npt-out", p("h6.npt")}, kTimeoutMs,
                              {"SOURCE_DATE_EPOCH=1700000000"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QList<QByteArray> lines = lwbtest::readAll(p("h6.npt")).split('\n');
        QCOMPARE(lines.value(0).simplified(), QByteArray("H1 CRD 02 2023 11 14 22"));
        QVERIFY(lines.contains(QByteArray("C5 0 lwbsw na na laserwb " LWB_VERSION)));
        QByteArray rec50;
        for (const QByteArray& l : lines)
            if (l.startsWith("50 ")) rec50 = l;
        const QList<QByteArray> f = rec50.split(' ');
        QCOMPARE(f.size(), 7);
        const QRegularExpression rms("RMS ([0-9.]+) ps");
        const auto m = rms.match(r.err);
        QVERIFY2(m.hasMatch(), qPrintable(r.err));
        QCOMPARE(f[2].toDouble(), m.captured(1).toDouble());
        QCOMPARE(f[6], QByteArray("1"));
        const lwb::core::slr::CrdReadResult back = lwb::core::slr::readCrd(p("h6.npt").toStdString());
        QVERIFY2(back.ok, back.error.c_str());
        QVERIFY2(back.warnings.empty(), back.warnings.empty() ? "" : back.warnings.front().c_str());
        QCOMPARE(back.file.passes.at(0).normalPoints.size(), size_t(6));
    }

    // ---------------------------------------------------------------- end to end, CRD input
    void crdEndToEnd() {
        if (!have()) QSKIP("shared SLR data absent (../shared/data/slr)");
        const QString in = slr("7080_STELLA_crd_071220_2128_0.frd");
        const auto r = runCli({"slr", in, "-o", p("stella.csv"), "--crd-out", p("stella.frd"), "--npt-out", p("stella.npt")},
                              kTimeoutMs);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        // The summary names the counts, the scale, the post-fit and the comparison with the flags.
        for (const char* w : {"points 236", "accepted", "mag_T", "(auto)", "post-fit", "RMS", "normal points:",
                              "against the station's filter flags (150 data, 86 noise)"})
            QVERIFY2(r.err.contains(w), qPrintable(QString(w) + " missing in:\n" + r.err));
        std::vector<Row> rows;
        QString why;
        QVERIFY2(readRows(p("stella.csv"), &rows, &why), qPrintable(why));
        const CrdReadResult src = readCrd(in.toStdString());
        QVERIFY(src.ok);
        const CrdPass& sp = src.file.passes.front();
        QCOMPARE(rows.size(), sp.ranges.size());  // one row per type-10 record
        for (size_t i = 0; i < rows.size(); ++i) {
            QCOMPARE(rows[i].index, long(i));
            QVERIFY(rows[i].cls == "signal" || rows[i].cls == "recovered" || rows[i].cls == "band" || rows[i].cls == "noise");
            QCOMPARE(rows[i].flag, sp.ranges[i].filterFlag);
            QVERIFY(std::fabs(rows[i].t - sp.ranges[i].secOfDay) < 1e-6);
            if (rows[i].kept) QVERIFY(rows[i].cls != "noise");  // the post-fit keeps accepted points only
        }
        // --crd-out: the same file with this pass's flags as delivered = the CSV's kept column (2
        // kept by the post-fit, 1 noise or rejected: the flags of every product, issue 40); every
        // record kept.
        const CrdReadResult back = readCrd(p("stella.frd").toStdString());
        QVERIFY2(back.ok, back.error.c_str());
        QCOMPARE(back.file.passes.size(), src.file.passes.size());
        const CrdPass& bp = back.file.passes.front();
        QCOMPARE(bp.ranges.size(), sp.ranges.size());
        QCOMPARE(bp.records.size(), sp.records.size());
        QCOMPARE(bp.rangeLines.size(), sp.rangeLines.size());
        for (size_t i = 0; i < bp.ranges.size(); ++i) {
            QCOMPARE(bp.ranges[i].filterFlag, rows[i].kept ? 2 : 1);
            QCOMPARE(bp.ranges[i].tofS, sp.ranges[i].tofS);
            QCOMPARE(bp.ranges[i].secOfDay, sp.ranges[i].secOfDay);
        }
        // --npt-out: a CRD normal-point pass with as many points as the summary says.
        const CrdReadResult np = readCrd(p("stella.npt").toStdString());
        QVERIFY2(np.ok, np.error.c_str());
        QCOMPARE(np.file.passes.size(), size_t(1));
        QCOMPARE(np.file.passes[0].session.dataType, 1);
        QVERIFY(np.file.passes[0].ranges.empty());
        const QRegularExpression re("normal points: (\\d+)");
        const auto m = re.match(r.err);
        QVERIFY(m.hasMatch());
        QCOMPARE(np.file.passes[0].normalPoints.size(), size_t(m.captured(1).toInt()));
        QVERIFY(!np.file.passes[0].normalPoints.empty());
        for (const auto& n : np.file.passes[0].normalPoints) {
            QVERIFY(n.numRanges >= 3);                                  // the ILRS night minimum
            QVERIFY(n.tofS > 0.005 && n.tofS < 0.02);                   // Stella: 800-3000 km slant range
            QVERIFY(n.secOfDay >= sp.ranges.front().secOfDay - 1 && n.secOfDay <= sp.ranges.back().secOfDay + 1);
        }
        noStrayFiles();
    }

    void passSelection() {
        if (!have()) QSKIP("shared SLR data absent");
        const QString in = slr("beaconc_20070511.frd");
        const CrdReadResult src = readCrd(in.toStdString());
        QVERIFY(src.ok);
        QCOMPARE(src.file.passes.size(), size_t(3));
        for (int k = 1; k <= 3; ++k) {
            const QString out = p(QString("bc%1.csv").arg(k)), crd = p(QString("bc%1.frd").arg(k));
            const auto r = runCli({"slr", in, "--pass", QString::number(k), "-o", out, "--crd-out", crd, "-q"}, kTimeoutMs);
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            QVERIFY(r.err.isEmpty());  // --quiet
            std::vector<Row> rows;
            QString why;
            QVERIFY2(readRows(out, &rows, &why), qPrintable(why));
            QCOMPARE(rows.size(), src.file.passes[size_t(k - 1)].ranges.size());
            // The CRD written back: pass K carries the new flags, the other passes are untouched.
            const CrdReadResult back = readCrd(crd.toStdString());
            QVERIFY(back.ok);
            for (int j = 0; j < 3; ++j) {
                const auto& a = back.file.passes[size_t(j)].ranges;
                const auto& b = src.file.passes[size_t(j)].ranges;
                QCOMPARE(a.size(), b.size());
                for (size_t i = 0; i < a.size(); ++i)
                    QCOMPARE(a[i].filterFlag, j == k - 1 ? (rows[i].kept ? 2 : 1) : b[i].filterFlag);
            }
        }
        // Out of range: the message lists the passes, numbered from 1.
        const auto bad = runCli({"slr", in, "--pass", "99", "-o", p("bc99.csv")}, kTimeoutMs);
        QCOMPARE(bad.exitCode, 1);
        QVERIFY2(bad.err.contains("pass 99 asked for") && bad.err.contains("holds 3 passes") && bad.err.contains("\n  3: Beacon-C"),
                 qPrintable(bad.err));
        QVERIFY(!QFile::exists(p("bc99.csv")));
    }

    // ---------------------------------------------------------------- O-C CSV input, simulated truth
    /// Through the CLI, simulated passes with fixed seeds (1 for every row; no seed chosen after a
    /// run): kHz 60 s, conventional 600 s, diffuse 300 s (the kinds' presets otherwise), at 50 %,
    /// 10 % and 3 % signal. Requirement: precision and recall >= 0.90 against the simulator's truth.
    void simulatedThroughCli_data() {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("fraction");
        QTest::addColumn<QString>("duration");
        for (const char* k : {"khz", "conventional", "diffuse"})
            for (const char* f : {"0.5", "0.1", "0.03"})
                QTest::newRow(qPrintable(QString("%1 %2").arg(k, f)))
                    << k << f << (QString(k) == "khz" ? "60" : QString(k) == "conventional" ? "600" : "300");
    }
    void simulatedThroughCli() {
        QFETCH(QString, kind);
        QFETCH(QString, fraction);
        QFETCH(QString, duration);
        const QString pass = p("sim_" + kind + fraction + ".csv"), out = p("simout_" + kind + fraction + ".csv");
        const auto s = runCli({"simulate", "slr", "--kind", kind, "--signal-fraction", fraction, "--duration", duration,
                               "--seed", "1", "-q", pass},
                              kTimeoutMs);
        QVERIFY2(s.exitCode == 0, qPrintable(s.err));
        const auto r = runCli({"slr", pass, "-o", out}, kTimeoutMs);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains("O-C from O-C table"), qPrintable(r.err));
        QVERIFY2(r.err.contains("no normal points"), qPrintable(r.err));  // an O-C table has no altitude
        std::vector<Row> rows;
        QString why;
        QVERIFY2(readRows(out, &rows, &why), qPrintable(why));
        const auto truth = lwb::core::readCsv(pass.toStdString());
        QVERIFY(truth.ok);
        QCOMPARE(rows.size(), truth.table.rows.size());
        const int tc = truth.table.column("truth");
        long tp = 0, fp = 0, fn = 0;
        for (size_t i = 0; i < rows.size(); ++i) {
            QCOMPARE(rows[i].index, long(i));
            QCOMPARE(rows[i].flag, -1);
            const bool sig = truth.table.rows[i][size_t(tc)] == "1";
            const bool acc = rows[i].cls != "noise";
            tp += acc && sig;
            fp += acc && !sig;
            fn += !acc && sig;
        }
        const double prec = tp + fp ? double(tp) / double(tp + fp) : 0, rec = double(tp) / double(tp + fn);
        qInfo("%s %s%%: n %zu, precision %.4f recall %.4f", qPrintable(kind), qPrintable(fraction), rows.size(), prec, rec);
        QVERIFY2(prec >= 0.90 && rec >= 0.90, qPrintable(QString("precision %1 recall %2").arg(prec).arg(rec)));
        // With --np-bin the normal points are formed (30 s bins); --npt-out still needs a CRD.
        if (kind == "diffuse" && fraction == "0.1") {
            const auto nb = runCli({"slr", pass, "--np-bin", "30", "-o", p("npbin.csv")}, kTimeoutMs);
            QVERIFY2(nb.exitCode == 0, qPrintable(nb.err));
            QVERIFY2(nb.err.contains("normal points: 1"), qPrintable(nb.err));  // 300 s pass: 10 or 11 bins
            const auto refused = runCli({"slr", pass, "--np-bin", "30", "-o", p("np2.csv"), "--npt-out", p("np2.npt")}, kTimeoutMs);
            QCOMPARE(refused.exitCode, 2);
            QVERIFY2(refused.err.contains("--npt-out needs a CRD input"), qPrintable(refused.err));
            QVERIFY(!QFile::exists(p("np2.csv")) && !QFile::exists(p("np2.npt")));
        }
    }

    // ---------------------------------------------------------------- detection quality, real passes
    /// Default automatic mode against the station's flags (scoring: see the top of the file).
    /// Requirement: precision and recall >= 0.95.
    void detectionQualityReal_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("pass");
        QTest::newRow("JASON1") << "7080_JASON1_crd_071220_2033_0.frd" << 1;
        QTest::newRow("STELLA") << "7080_STELLA_crd_071220_2128_0.frd" << 1;
        QTest::newRow("Beacon-C") << "7080_Beacon-C_crd_071220_1715_0.frd" << 1;
        QTest::newRow("beaconc pass 1") << "beaconc_20070511.frd" << 1;
        QTest::newRow("beaconc pass 2") << "beaconc_20070511.frd" << 2;
        QTest::newRow("beaconc pass 3") << "beaconc_20070511.frd" << 3;
    }
    void detectionQualityReal() {
        QFETCH(QString, file);
        QFETCH(int, pass);
        if (!lwbtest::haveShared("slr/" + file)) QSKIP("shared SLR data absent");
        const QString out = p(QString("real_%1_%2.csv").arg(file).arg(pass));
        const auto r = runCli({"slr", slr(file), "--pass", QString::number(pass), "-o", out}, kTimeoutMs);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        std::vector<Row> rows;
        QString why;
        QVERIFY2(readRows(out, &rows, &why), qPrintable(why));
        const Score s = scoreAgainstFlags(rows);
        qInfo("%s pass %d: %ld flag-2 points, track sigma %.0f ps; %ld flag-1 points on the track (%ld of them accepted, "
              "not scored); precision %.4f (raw %.4f), recall %.4f",
              qPrintable(file), pass, s.flag2, s.sigmaPs, s.onTrackFlag1, s.onTrackAccepted, s.precision, s.rawPrecision,
              s.recall);
        QVERIFY(s.onTrackFlag1 <= 5);  // "a few" (README); more would mean the band is wrong
        QVERIFY2(s.precision >= 0.95, qPrintable(QString("precision %1").arg(s.precision)));
        // JASON1: the two returns 100 s before the arc (station NP 1, 2 ranges) cannot be told from
        // noise without a prediction (docs/slr-detection.md); the rest of the track is found.
        QVERIFY2(s.recall >= 0.95, qPrintable(QString("recall %1").arg(s.recall)));
    }

    // ---------------------------------------------------------------- presets
    void presets() {
        if (!have()) QSKIP("shared SLR data absent");
        const QString in = slr("7080_STELLA_crd_071220_2128_0.frd");
        QVERIFY(lwbtest::writeText(p("presets.json"),
                                   "{\"format\": \"laserwb-slr-presets\", \"version\": 1, \"satellites\": [\n"
                                   " {\"name\": \"Stella\", \"ilrs_id\": \"9306102\", \"altitude_km\": 815,\n"
                                   "  \"screen\": {\"automatic\": false, \"mag_t\": 1, \"mag_oc\": 1e7, \"area_limit\": 3,"
                                   " \"connectivity\": 8},\n"
                                   "  \"postfit\": {\"reject_sigma\": 2.5, \"bin_length_s\": 15}},\n"
                                   " {\"name\": \"lageos1\", \"ilrs_id\": \"7603901\"}]}\n"));
        auto r = runCli({"slr", in, "--preset", p("presets.json"), "-o", p("pre.csv")}, kTimeoutMs);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains("preset Stella"), qPrintable(r.err));
        QVERIFY2(r.err.contains("mag_T 1,") && r.err.contains("mag_OC 1e+07,") && r.err.contains("area limit 3,"),
                 qPrintable(r.err));
        QVERIFY(!r.err.contains("(auto)"));
        QVERIFY2(r.err.contains("2.5-sigma"), qPrintable(r.err));
        QVERIFY2(r.err.contains("bins of 15 s"), qPrintable(r.err));  // the preset's bin (the altitude alone gives 30 s)
        // An explicit option overrides the preset.
        r = runCli({"slr", in, "--preset", p("presets.json"), "--mag-t", "2", "--reject", "3", "-o", p("pre2.csv")}, kTimeoutMs);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains("mag_T 2,") && r.err.contains("3-sigma"), qPrintable(r.err));
        // --satellite picks another entry; an unknown one is a clear error, nothing written.
        r = runCli({"slr", in, "--preset", p("presets.json"), "--satellite", "ajisai", "-o", p("pre3.csv")}, kTimeoutMs);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("no preset for satellite \"ajisai\"") && r.err.contains("Stella (9306102)"), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("pre3.csv")));
        r = runCli({"slr", slr("7080_JASON1_crd_071220_2033_0.frd"), "--preset", p("presets.json"), "-o", p("pre4.csv")},
                   kTimeoutMs);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("\"JASON1\" (ILRS id 0105501)"), qPrintable(r.err));
        // A broken presets file names itself.
        QVERIFY(lwbtest::writeText(p("broken.json"), "{\"satellites\": [{\"name\": \"x\", \"screen\": {\"connectivity\": 5}}]}"));
        r = runCli({"slr", in, "--preset", p("broken.json"), "-o", p("pre5.csv")}, kTimeoutMs);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("broken.json") && r.err.contains("connectivity"), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("pre5.csv")));
        noStrayFiles();
    }

    // ---------------------------------------------------------------- usage errors: exit 2, nothing written
    void usageErrors_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QString crd = "STELLA";  // replaced by the shared file
        QTest::newRow("no input") << QStringList{"-o", "@out"} << "no input file";
        QTest::newRow("two inputs") << QStringList{crd, crd, "-o", "@out"} << "exactly one input";
        QTest::newRow("unknown option") << QStringList{crd, "--bogus", "-o", "@out"} << "unknown option --bogus";
        QTest::newRow("connectivity 5") << QStringList{crd, "--connectivity", "5", "-o", "@out"}
                                        << "--connectivity 5: slr: screen.connectivity must be 4, 8 or 0 (auto)";
        QTest::newRow("mag-t 1e30") << QStringList{crd, "--mag-t", "1e30", "-o", "@out"}
                                    << "--mag-t 1e30: slr.screen.mag_t = 1e+30: must be in (0, 1e+15] (0 = auto)";
        QTest::newRow("cos-c 1.2 via --set") << QStringList{crd, "--set", "screen.cosine_c=1.2", "-o", "@out"}
                                             << "slr.screen.cosine_c = 1.2: must be in [0.5, 1)";
        QTest::newRow("unknown --set key") << QStringList{crd, "--set", "screen.cosine=0.9", "-o", "@out"} << "unknown parameter";
        QTest::newRow("mag-oc text") << QStringList{crd, "--mag-oc", "big", "-o", "@out"} << "--mag-oc";
        QTest::newRow("cos-c 1") << QStringList{crd, "--cos-c", "1", "-o", "@out"} << "--cos-c";
        QTest::newRow("area -1") << QStringList{crd, "--area-min", "-1", "-o", "@out"} << "--area-min";
        QTest::newRow("reject 0.5") << QStringList{crd, "--reject", "0.5", "-o", "@out"} << "--reject";
        QTest::newRow("pass 0") << QStringList{crd, "--pass", "0", "-o", "@out"} << "--pass";
        QTest::newRow("cpf alone") << QStringList{crd, "--cpf", "x.hts", "-o", "@out"} << "--cpf and --stations go together";
        QTest::newRow("satellite alone") << QStringList{crd, "--satellite", "stella", "-o", "@out"} << "--preset";
        QTest::newRow("output over input") << QStringList{crd, "-o", crd} << "overwrite the input";
        QTest::newRow("same outputs") << QStringList{crd, "-o", "@out", "--crd-out", "@out"} << "same file";
        QTest::newRow("crd-out from csv") << QStringList{"@csv", "-o", "@out", "--crd-out", "@crd"} << "--crd-out needs a CRD input";
        QTest::newRow("pass for csv") << QStringList{"@csv", "--pass", "2", "-o", "@out"} << "O-C table";
    }
    void usageErrors() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        if (!have()) QSKIP("shared SLR data absent");
        QVERIFY(lwbtest::writeText(p("small.csv"), "epoch_s,oc_s\n1,1e-9\n2,2e-9\n3,3e-9\n4,4e-9\n"));
        QStringList full{"slr"};
        for (const QString& a : args)
            full << (a == "STELLA" ? slr("7080_STELLA_crd_071220_2128_0.frd")
                     : a == "@out" ? p("usage-out.csv")
                     : a == "@csv" ? p("small.csv")
                     : a == "@crd" ? p("usage-out.frd")
                                   : a);
        QFile::remove(p("usage-out.csv"));
        const auto r = runCli(full, kTimeoutMs);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY2(r.err.contains("--help"), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("usage-out.csv")) && !QFile::exists(p("usage-out.frd")));
        noStrayFiles();
    }

    // Issue 27: --all-passes on 20 000 passes took more than 120 s because every pass taken from
    // the file copied the whole file (and summarised all its passes): quadratic. The passes of
    // one reading share it. (A station's daily file: 2 000 passes 117 s -> 7 s, 20 000 in 88 s.)
    void passesOfOneFileShareIt() {
        const QString in = slr("hy2c_202109.fr2");
        if (!QFile::exists(in)) QSKIP("shared SLR data absent");
        const auto crd = std::make_shared<const lwb::core::slr::CrdReadResult>(lwb::core::slr::readCrd(in.toStdString()));
        QVERIFY2(crd->ok, crd->error.c_str());
        QVERIFY(crd->file.passes.size() >= 2);
        std::vector<lwb::core::slr::PassInputResult> taken;
        for (int i = 0; i < int(crd->file.passes.size()) && taken.size() < 2; ++i) {
            lwb::core::slr::PassInputResult r = lwb::core::slr::passFromCrd(crd, in.toStdString(), i, {}, {});
            if (!r.ok) continue;  // (a pass too short for a trend)
            QVERIFY(r.pass.crd.get() == &crd->file);  // the same file, not a copy
            QVERIFY(r.passes.empty());                // no summary of every pass per pass
            taken.push_back(std::move(r));
        }
        QCOMPARE(taken.size(), size_t(2));
        QCOMPARE(crd.use_count(), 3L);
    }

    // Review findings (second review, 2026-11-21): each case below once went wrong.
    void unscreenedRecordsKeepTheirFlags() {
        // Records without an O-C (here: dropped from the pass's index as if outside the
        // prediction) keep the station's flag in --crd-out instead of turning into noise.
        const QString in = slr("7080_STELLA_crd_071220_2128_0.frd");
        if (!QFile::exists(in)) QSKIP("shared SLR data absent");
        lwb::core::slr::PassInputResult loaded = lwb::core::slr::loadPass(in.toStdString(), -1, {});
        QVERIFY2(loaded.ok, loaded.error.c_str());
        lwb::core::slr::PassData pass = loaded.pass;
        const auto& ranges = pass.crd->passes[size_t(pass.passIndex)].ranges;
        // Keep only the second half of the points "screened"; mark all of them noise.
        const size_t half = pass.rangeIndex.size() / 2;
        std::vector<uint32_t> second;
        for (size_t i = half; i < pass.rangeIndex.size(); ++i) second.push_back(pass.rangeIndex.at(i));
        pass.rangeIndex = lwb::core::slr::CrdStepColumn<uint32_t>::of(second);
        std::vector<uint8_t> accepted(pass.rangeIndex.size(), 0);
        std::string err;
        QVERIFY2(lwb::core::slr::writeScreenedCrd(p("partial.frd").toStdString(), pass, accepted, &err), err.c_str());
        const auto back = lwb::core::slr::readCrd(p("partial.frd").toStdString());
        QVERIFY2(back.ok, back.error.c_str());
        const auto& out = back.file.passes[size_t(pass.passIndex)].ranges;
        QCOMPARE(out.size(), ranges.size());
        std::vector<char> screened(ranges.size(), 0);
        for (size_t k : second) screened[k] = 1;
        int kept2 = 0;
        for (size_t k = 0; k < ranges.size(); ++k) {
            QCOMPARE(out[k].filterFlag, screened[k] ? 1 : ranges[k].filterFlag);
            kept2 += !screened[k] && ranges[k].filterFlag == 2;
        }
        QVERIFY(kept2 > 10);  // the test means something: station data flags were kept
    }

    void damagedRecordRefusedPastTheWarningCap() {
        // 600 unknown records fill the reader's warning list; a damaged type-10 line in the pass
        // to screen must still be found and the run refused, nothing written.
        const QString in = slr("7080_STELLA_crd_071220_2128_0.frd");
        if (!QFile::exists(in)) QSKIP("shared SLR data absent");
        QList<QByteArray> lines = lwbtest::readAll(in).split('\n');
        int firstData = -1;
        for (int i = 0; i < lines.size(); ++i)
            if (lines[i].startsWith("10 ")) {
                firstData = i;
                break;
            }
        QVERIFY(firstData > 0);
        QList<QByteArray> junk;
        for (int i = 0; i < 600; ++i) junk << "77 an unknown record";
        lines[firstData + 5] = "10 74100.5 abc std 2 2 0 0 0";
        for (int i = junk.size() - 1; i >= 0; --i) lines.insert(firstData, junk[i]);
        QVERIFY(lwbtest::writeText(p("damaged.frd"), lines.join('\n')));
        const auto r = runCli({"slr", p("damaged.frd"), "-o", p("dmg.csv"), "--crd-out", p("dmg.frd")}, kTimeoutMs);
        QVERIFY2(r.exitCode == 1, qPrintable(r.err));
        QVERIFY2(r.err.contains("damaged record"), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("dmg.csv")) && !QFile::exists(p("dmg.frd")));
    }

    void unwritableSecondOutputWritesNothing() {
        const QString in = slr("7080_STELLA_crd_071220_2128_0.frd");
        if (!QFile::exists(in)) QSKIP("shared SLR data absent");
        QVERIFY(QDir().mkpath(p("adir")));
        const auto r = runCli({"slr", in, "-o", p("first.csv"), "--crd-out", p("adir")}, kTimeoutMs);
        QVERIFY2(r.exitCode == 1, qPrintable(r.err));
        QVERIFY2(r.err.contains("is a folder"), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("first.csv")));
    }

    // ---- issue 8 -------------------------------------------------------------------------------
    /// Item 2 at its cause: a value std::to_chars cannot fit is refused, never written as the
    /// buffer's old bytes (the reader refuses such epochs now; a pass built in memory can still hold one).
    void screenCsvRefusesWhatDoesNotFit() {
        PassData pass;
        pass.t = {0.0, 1.0, 1e300};
        pass.oc = {1e-9, 2e-9, 3e-9};
        ScreenResult screen;
        screen.ok = true;
        screen.pointClass.assign(3, PointClass::Signal);
        const std::string out = p("nofit.csv").toStdString();
        std::string err;
        QVERIFY(!writeScreenCsv(out, pass, screen, screen.pointClass, nullptr, &err));
        QVERIFY2(err.find("point 2") != std::string::npos && err.find("too large") != std::string::npos, err.c_str());
        QVERIFY(!QFile::exists(p("nofit.csv")));
        noStrayFiles();
        pass.t[2] = 2.0;  // the same pass with a sound epoch is written
        QVERIFY2(writeScreenCsv(out, pass, screen, screen.pointClass, nullptr, &err), err.c_str());
        QVERIFY(lwbtest::readAll(p("nofit.csv")).contains("\n2,2.000000000,3.000000e-09,signal,"));
    }

    /// A long pass is formatted in blocks on the cores and written in order: the rows come out in
    /// pass order, and the first point that does not fit is the one named, not a later block's.
    void screenCsvWrittenInOrderAcrossBlocks() {
        const size_t n = 40000;  // 5 blocks of 8192 rows
        PassData pass;
        for (size_t i = 0; i < n; ++i) {
            pass.t.push_back(1000.0 + 0.5 * static_cast<double>(i));
            pass.oc.push_back(1e-9 * static_cast<double>(i % 7));
        }
        ScreenResult screen;
        screen.ok = true;
        screen.pointClass.assign(n, PointClass::Noise);
        std::vector<PointClass> classes(n, PointClass::Noise);
        for (size_t i = 0; i < n; i += 3) classes[i] = PointClass::Signal;
        const std::string out = p("blocks.csv").toStdString();
        std::string err;
        pass.t[35000] = 1e300;
        pass.t[20000] = 1e300;
        QVERIFY(!writeScreenCsv(out, pass, screen, classes, nullptr, &err));
        QVERIFY2(err.find("point 20000 ") != std::string::npos, err.c_str());
        QVERIFY(!QFile::exists(p("blocks.csv")));
        noStrayFiles();
        pass.t[35000] = 1000.0 + 0.5 * 35000;
        pass.t[20000] = 1000.0 + 0.5 * 20000;
        QVERIFY2(writeScreenCsv(out, pass, screen, classes, nullptr, &err), err.c_str());
        const QList<QByteArray> lines = lwbtest::readAll(p("blocks.csv")).split('\n');
        QCOMPARE(lines.size(), static_cast<qsizetype>(n + 2));  // header, n rows, the empty piece after the last newline
        for (size_t i = 0; i < n; ++i) {
            const QByteArray want = QByteArray::number(static_cast<qulonglong>(i)) + "," +
                                    QByteArray::number(1000.0 + 0.5 * static_cast<double>(i), 'f', 9) + ",";
            if (!lines[static_cast<qsizetype>(i + 1)].startsWith(want) ||
                lines[static_cast<qsizetype>(i + 1)].contains(i % 3 == 0 ? ",noise," : ",signal,"))
                QFAIL(qPrintable("row " + QString::number(i) + ": " + lines[static_cast<qsizetype>(i + 1)]));
        }
    }

    /// Item 9: CRD told by its content, not its name.
    void crdRecognisedByContent_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("text");  // "-" for no file
        QTest::addColumn<bool>("crd");
        const QByteArray crd = "H1 CRD 2 2021 9 1 21\nH2 GLSL 1824 81 1 4 EUROLAS\n";
        QTest::newRow("v2C ending") << "pass.v2C" << crd << true;
        QTest::newRow("no ending, lower case") << "pass" << crd.toLower() << true;
        QTest::newRow("comments and blank lines first") << "pass.txt" << "\n00 a comment\n   \n" + crd << true;
        QTest::newRow("CRLF and a BOM") << "pass.dat" << "\xEF\xBB\xBFh1 crd 1 2007 12 20 2\r\n" + crd << true;
        QTest::newRow("a CPF (its reader names the mistake)") << "pred.v2C" << QByteArray("H1 CPF 2 HTS 2012\n") << true;
        QTest::newRow("csv") << "oc.csv" << QByteArray("epoch_s,oc_s\n1,2\n") << false;
        QTest::newRow("csv without ending") << "oc" << QByteArray("epoch_s,oc_s\n1,2\n") << false;
        QTest::newRow("csv called .frd") << "oc.frd" << QByteArray("# O-C\nepoch_s,oc_s\n1,2\n") << false;
        QTest::newRow("garbage called .frd") << "bin.frd" << QByteArray("\x7f" "ELF garbage\n") << true;
        QTest::newRow("garbage called .csv") << "bin.csv" << QByteArray("\x7f" "ELF garbage\n") << false;
        QTest::newRow("missing .npt") << "gone.npt" << QByteArray("-") << true;
        QTest::newRow("missing .csv") << "gone.csv" << QByteArray("-") << false;
    }
    void crdRecognisedByContent() {
        QFETCH(QString, name);
        QFETCH(QByteArray, text);
        QFETCH(bool, crd);
        QTemporaryDir dir;
        const QString path = dir.filePath(name);
        if (text != "-") QVERIFY(lwbtest::writeText(path, text));
        QCOMPARE(isCrdFile(path.toStdString()), crd);
    }
    void crdWithAnyNameThroughCli() {
        const QString beacon = slr("7080_Beacon-C_crd_071220_1715_0.frd");
        if (!QFile::exists(beacon)) QSKIP("shared SLR data absent");
        const auto src = readCrd(beacon.toStdString());
        QVERIFY2(src.ok, src.error.c_str());
        for (const QString name : {"beacon.v2C", "beacon"}) {
            QVERIFY(lwbtest::writeText(p(name), lwbtest::readAll(beacon)));
            const QString out = p(name + "-out.csv"), crdOut = p(name + "-out.frd");
            const auto r = runCli({"slr", p(name), "-o", out, "--crd-out", crdOut}, kTimeoutMs);
            QVERIFY2(r.exitCode == 0, qPrintable(r.err));
            std::vector<Row> rows;
            QString why;
            QVERIFY2(readRows(out, &rows, &why), qPrintable(why));
            QCOMPARE(rows.size(), src.file.passes.front().ranges.size());
            QVERIFY(readCrd(crdOut.toStdString()).ok);
        }
    }

    /// Item 9: a run that fails says what in the file is wrong (file:line), not only "no full-rate pass".
    void readerProblemsAreNamed_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QStringList>("messages");
        const QByteArray head = "h1 CRD 2 2018 2 1 17\nh2 CHAL 9998 19 01 4 WPLTN\nh3 lageos2 9207002 5986 22195 0 1 1\n";
        const QByteArray np = head + "h4 1 2018 2 1 15 14 58 2018 2 1 15 48 57 0 0 0 0 1 0 2 0\nc0 0 532.000 std\n"
                              "11 54927.620161400002 0.044106029140 std 2 120.0 1457 70.0 0.319 2.496 -12.0 1.2 0 5.7\n"
                              "11 56209.259001400002   corrupted    std 2 120.0 1515 72.1 0.227 2.222 -14.0 1.3 0 5.7\n"
                              "11 56836.982001400000 0.049325702229 std 2 120.0 1140 68.3 0.418 2.467 -16.0 0.9 0 5.7\n"
                              "h8\nh9\n";
        QTest::newRow("normal points only, one corrupted")
            << "np.v2C" << np
            << QStringList{"no full-rate pass", "pass 1: station normal points (2 normal-point records",
                           "np.v2C:7: type 11 record skipped: field 2 (time of flight)"};
        QByteArray fr = head + "h4 0 2018 2 1 15 14 58 2018 2 1 15 48 57 0 0 0 0 1 0 9 0\nc0 0 532.000 std\n"
                               "10 54927.6 0.044106029140 std 2 2 0 0 0 na\n10 54928.6 corrupted std 2 2 0 0 0 na\nh8\n";
        QTest::newRow("range type 9, a corrupted type 10")
            << "fr.v2C" << fr
            << QStringList{"pass 1: skipped (1 full-rate records; a pass needs at least 5)", "fr.v2C:4: H4 field 20 (range type indicator) is 9",
                           "fr.v2C:7: type 10 record skipped: field 2 (time of flight)"};
        QTest::newRow("H1 names CPF") << "cpf.frd" << QByteArray(np).replace("h1 CRD", "H1 CPF")
                                      << QStringList{"cpf.frd:1: H1 names the format \"CPF\", not \"CRD\""};
        QTest::newRow("a bad block does not hide the good one")
            << "blocks.frd" << QByteArray(np).replace("h8\nh9\n", "h8\nh4 0 2018 2 1 -1 -1 -1 -1 -1 -1 -1 -1 -1 0 0 0 0 1 0 2 0\nh9\n")
            << QStringList{"no full-rate pass", "pass 2 cannot be used: ", "blocks.frd:10: H4 start date-time"};
    }
    void readerProblemsAreNamed() {
        QFETCH(QString, name);
        QFETCH(QByteArray, text);
        QFETCH(QStringList, messages);
        QVERIFY(lwbtest::writeText(p(name), text));
        const auto r = runCli({"slr", p(name), "-o", p("named.csv")}, kTimeoutMs);
        QVERIFY2(r.exitCode == 1, qPrintable(r.err));
        for (const QString& m : messages) QVERIFY2(r.err.contains(m), qPrintable("no \"" + m + "\" in:\n" + r.err));
        QVERIFY(!QFile::exists(p("named.csv")));
    }

    /// Item 9: the prediction's problems named: a damaged position record, a missing 99 end
    /// record, a prediction of another satellite.
    void cpfProblemsAreNamed_data() {
        QTest::addColumn<QString>("edit");
        QTest::addColumn<int>("exitCode");
        QTest::addColumn<QString>("message");
        QTest::newRow("two records, one corrupted") << "corrupt" << 1 << "cpf.hts:5: type 10 record skipped: X, Y, Z";
        QTest::newRow("no 99 end record") << "no99" << 0 << "the file ends without the 99 end-of-ephemeris record";
        QTest::newRow("another satellite") << "lageos2" << 1 << "cpf.hts: the prediction is for another satellite";
        QTest::newRow("NORAD number differs") << "norad" << 0 << "the NORAD number of the prediction and the pass differ";
        QTest::newRow("no H2 to compare") << "noH2" << 0 << "cannot check that the prediction is for the pass's satellite";
    }
    void cpfProblemsAreNamed() {
        QFETCH(QString, edit);
        QFETCH(int, exitCode);
        QFETCH(QString, message);
        const QString crd = slr("blits_201206.frd"), cpf = slr("blits_cpf_120626_6801.hts"),
                      snx = slr("SLRF2014_POS+VEL_2030.0_200428.snx");
        if (!QFile::exists(crd) || !QFile::exists(cpf) || !QFile::exists(snx)) QSKIP("shared SLR data absent");
        QList<QByteArray> lines = lwbtest::readAll(cpf).split('\n');
        while (!lines.isEmpty() && lines.back().trimmed().isEmpty()) lines.removeLast();
        QVERIFY(lines[1].startsWith("H2  0904907 5558    35871 "));
        if (edit == "corrupt") {  // H1 H2 H9, two records (the second damaged), 99
            lines = {lines[0], lines[1], lines[2], lines[3], "10 0 56104    240.00000  0   corrupted  1.0  2.0", "99"};
        } else if (edit == "no99") {
            QVERIFY(lines.back().startsWith("99"));
            lines.removeLast();
        } else if (edit == "lageos2") {
            lines[1].replace("0904907 5558    35871", "9207002 5986    22195");
        } else if (edit == "norad") {
            lines[1].replace("0904907 5558    35871", "0904907 5558    35872");
        } else if (edit == "noH2") {
            lines.removeAt(1);
        }
        QVERIFY(lwbtest::writeText(p("cpf.hts"), lines.join('\n') + "\n"));
        // Pass 41 of the month (28 June 2012, 08:29) lies within the CPF's 26 June - 1 July span.
        const QString out = p("cpf-out.csv");
        QFile::remove(out);
        const auto r = runCli({"slr", crd, "--pass", "41", "--cpf", p("cpf.hts"), "--stations", snx, "-o", out}, kTimeoutMs);
        QVERIFY2(r.exitCode == exitCode, qPrintable(r.err));
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QCOMPARE(QFile::exists(out), exitCode == 0);
    }

    /// Item 8 at the core: a pass with a damaged record is read (the GUI shows it) but no writer
    /// takes it: its points are incomplete and the damaged line would be written back.
    void damagedPassIsNotWritten() {
        const QString beacon = slr("7080_Beacon-C_crd_071220_1715_0.frd");
        if (!QFile::exists(beacon)) QSKIP("shared SLR data absent");
        QList<QByteArray> lines = lwbtest::readAll(beacon).split('\n');
        lines[19] = "10 62171.73";  // line 20 cut short
        QVERIFY(lwbtest::writeText(p("cut.frd"), lines.join('\n')));
        const PassInputResult in = loadPass(p("cut.frd").toStdString(), -1, {});
        QVERIFY2(in.ok, in.error.c_str());
        QVERIFY2(QString::fromStdString(in.pass.damaged).startsWith(p("cut.frd") + ":20: type 10 record skipped"),
                 in.pass.damaged.c_str());
        const size_t n = in.pass.t.size();
        ScreenResult screen;
        screen.ok = true;
        screen.pointClass.assign(n, PointClass::Signal);
        const std::vector<uint8_t> accepted(n, 1);
        std::string err;
        QVERIFY(!writeScreenCsv(p("cut.csv").toStdString(), in.pass, screen, screen.pointClass, nullptr, &err));
        QCOMPARE(err, in.pass.damaged);
        QVERIFY(!writeScreenedCrd(p("cut-out.frd").toStdString(), in.pass, accepted, &err));
        QCOMPARE(err, in.pass.damaged);
        NormalPoint np;
        np.epochS = in.pass.t.front();
        np.tofS = in.pass.tof.front();
        QVERIFY(!writeNormalPointCrd(p("cut.npt").toStdString(), in.pass, {np}, &err));
        QCOMPARE(err, in.pass.damaged);
        for (const char* f : {"cut.csv", "cut-out.frd", "cut.npt"}) QVERIFY(!QFile::exists(p(f)));
    }

    void helpAndDispatch() {
        auto r = runCli({"slr", "--help"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains("--pass K") && r.out.contains("1-based") && r.out.contains("--preset FILE"));
        r = runCli({"--help"});
        QVERIFY(r.out.contains("  slr "));
        r = runCli({"simulate"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("which one? (footprint, trend, slr, calib, radiometry)"), qPrintable(r.err));
        r = runCli({"bench", "lunar"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("unknown kind \"lunar\" (footprint, slr)"), qPrintable(r.err));
    }

    // ---------------------------------------------------------------- bad inputs: exit 1, clear message, nothing written
    void badInputs_data() {
        QTest::addColumn<QString>("name");     // file written into the temporary folder
        QTest::addColumn<QByteArray>("text");  // its content; "@BEACON" is replaced by the shared Beacon-C pass
        QTest::addColumn<QStringList>("extra");
        QTest::addColumn<QString>("message");
        const QByteArray h = "h1 CRD  0 2007 12 20  2\nh2 MDOL       7080 24 19  4\nh3 STELLA      9306102 7  22824 0 1\n"
                             "h4  0 2007 12 20 21 28 10 2007 12 20 21 34 00  0 0 0 0 1 0 2 0\nc0 0 532.000 std\n";
        QByteArray same;
        for (int i = 0; i < 30; ++i) same += "10 77302.896480316 0.006390000000 std 2 2 0 0 0\n";
        QTest::newRow("truncated record") << "trunc.frd" << QByteArray("@BEACON:20:10 62171.73") << QStringList{}
                                          << "trunc.frd:20: type 10 record skipped";
        QTest::newRow("text in a number") << "text.frd" << QByteArray("@BEACON:20:10 62122.905138281523 abc std 2 1 0 0 0")
                                          << QStringList{} << "text.frd:20:";
        QTest::newRow("no records") << "empty.frd" << h + "h8\nh9\n" << QStringList{} << "empty.frd:";
        QTest::newRow("one record") << "one.frd" << h + "10 77302.896480316 0.006390000000 std 2 2 0 0 0\nh8\nh9\n"
                                    << QStringList{} << "1 full-rate records; a pass needs at least 5";
        QTest::newRow("identical records") << "same.frd" << h + same + "h8\nh9\n" << QStringList{} << "same.frd";
        QTest::newRow("identical csv rows") << "same.csv" << QByteArray("epoch_s,oc_s\n") + QByteArray("5,1e-9\n").repeated(50)
                                            << QStringList{} << "epochs are equal";
        QTest::newRow("NaN in csv") << "nan.csv" << QByteArray("epoch_s,oc_s\n1,1e-9\n2,NaN\n3,3e-9\n") << QStringList{}
                                    << "nan.csv:3:";
        QTest::newRow("two csv rows") << "two.csv" << QByteArray("epoch_s,oc_s\n1,1e-9\n2,2e-9\n") << QStringList{}
                                      << "a pass needs at least 5";
        // Issue 8 item 2: an epoch of 1e300 once went through and the CSV got 64 bytes of stack.
        QTest::newRow("epoch 1e300") << "e300.csv" << QByteArray("epoch_s,oc_s\n1,1e-9\n1e300,2e-9\n3,3e-9\n4,4e-9\n")
                                     << QStringList{} << "e300.csv:3: epoch_s 1e300 is not a plausible epoch";
        QTest::newRow("epoch 1e60") << "e60.csv" << QByteArray("epoch_s,oc_s\n1,1e-9\n2,2e-9\n3,3e-9\n-1e60,4e-9\n")
                                    << QStringList{} << "e60.csv:5: epoch_s -1e60 is not a plausible epoch";
        QTest::newRow("O-C 1e300") << "oc300.csv" << QByteArray("epoch_s,oc_s\n1,1e-9\n2,1e300\n3,3e-9\n4,4e-9\n")
                                   << QStringList{} << "oc300.csv:3: oc_s 1e300 is not a plausible O-C";
        QTest::newRow("O-C in ns") << "ns.csv" << QByteArray("epoch_s,oc_s\n1,1.5\n2,12.5\n3,3.5\n4,4.5\n")
                                   << QStringList{} << "ns.csv:3: oc_s 12.5 is not a plausible O-C";
        QTest::newRow("csv without oc") << "hdr.csv" << QByteArray("epoch_s,range\n1,2\n") << QStringList{} << "hdr.csv:1:";
        QTest::newRow("binary crd") << "bin.frd" << QByteArray("\x00\x01\x02\x03garbage\x00", 12) << QStringList{} << "bin.frd";
        QTest::newRow("missing file") << "nothere.frd" << QByteArray() << QStringList{} << "nothere.frd";
        QTest::newRow("bad cpf") << "@BEACON" << QByteArray() << QStringList{"--cpf", "@junk", "--stations", "@junk"} << "junk.hts";
    }
    void badInputs() {
        QFETCH(QString, name);
        QFETCH(QByteArray, text);
        QFETCH(QStringList, extra);
        QFETCH(QString, message);
        const QString beacon = slr("7080_Beacon-C_crd_071220_1715_0.frd");
        QString input = p(name);
        if (name == "@BEACON" || text.startsWith("@BEACON")) {
            if (!QFile::exists(beacon)) QSKIP("shared SLR data absent");
            if (name == "@BEACON") {
                input = beacon;
            } else {
                // "@BEACON:LINE:TEXT": the shared pass with line LINE replaced.
                const QList<QByteArray> spec = text.split(':');
                QList<QByteArray> lines = lwbtest::readAll(beacon).split('\n');
                lines[spec[1].toInt() - 1] = spec[2];
                QVERIFY(lwbtest::writeText(input, lines.join('\n')));
            }
        } else if (name != "nothere.frd") {
            QVERIFY(lwbtest::writeText(input, text));
        }
        lwbtest::writeText(p("junk.hts"), "this is not a prediction\n");
        QStringList args{"slr", input};
        for (const QString& e : extra) args << (e == "@junk" ? p("junk.hts") : e);
        const QString out = p("bad-out.csv"), crd = p("bad-out.frd");
        QFile::remove(out);
        QFile::remove(crd);
        if (input.endsWith(".frd")) args << "--crd-out" << crd;
        args << "-o" << out;
        const auto r = runCli(args, kTimeoutMs);
        QVERIFY2(r.err != "timeout", "the command hung");
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(message), qPrintable(r.err));
        QVERIFY(!QFile::exists(out));
        QVERIFY(!QFile::exists(crd));
        noStrayFiles();
    }

    // A printed config given back gives the same run (issue 27): the printed "unknown" altitude
    // and fire rate (0) and day/night ("auto") keep what the pass tells. It exited 2 ("the
    // satellite's altitude is unknown") and, with the day flag printed false, formed 6 normal
    // points instead of 4 on STELLA.
    void printedConfigRoundTrips_data() {
        QTest::addColumn<QString>("pass");
        QTest::newRow("simulated CRD") << "sim";
        if (lwbtest::haveShared("slr/7080_STELLA_crd_071220_2128_0.frd")) QTest::newRow("STELLA") << lwbtest::sharedPath("slr/7080_STELLA_crd_071220_2128_0.frd");
    }
    void printedConfigRoundTrips() {
        QFETCH(QString, pass);
        if (pass == "sim") {
            pass = p("roundtrip.frd");
            QCOMPARE(runCli({"simulate", "slr", "--kind", "conventional", "--duration", "900", "--seed", "4", "-q", pass}).exitCode, 0);
        }
        const lwbtest::CliRun cfg = runCli({"slr", pass, "--print-config"});
        QCOMPARE(cfg.exitCode, 0);
        QVERIFY(lwbtest::writeText(p("rt.json"), cfg.out.toUtf8()));
        QCOMPARE(runCli({"slr", pass, "-o", p("rt_a.csv"), "--npt-out", p("rt_a.npt"), "-q"}).exitCode, 0);
        const lwbtest::CliRun again = runCli({"slr", pass, "--config", p("rt.json"), "-o", p("rt_b.csv"), "--npt-out", p("rt_b.npt"), "-q"});
        QVERIFY2(again.exitCode == 0, qPrintable(again.err));
        QCOMPARE(lwbtest::readAll(p("rt_b.csv")), lwbtest::readAll(p("rt_a.csv")));
        QCOMPARE(lwbtest::readAll(p("rt_b.npt")), lwbtest::readAll(p("rt_a.npt")));
        QVERIFY(lwbtest::readAll(p("rt_a.npt")).contains("\n11 "));
        // A config written before day_night ("daylight": false) still reads (as "auto").
        QByteArray old = cfg.out.toUtf8();
        QVERIFY(old.contains("\"day_night\": \"auto\""));
        old.replace("\"day_night\": \"auto\"", "\"daylight\": false");
        QVERIFY(lwbtest::writeText(p("rt_old.json"), old));
        QCOMPARE(runCli({"slr", pass, "--config", p("rt_old.json"), "-o", p("rt_c.csv"), "--npt-out", p("rt_c.npt"), "-q"}).exitCode, 0);
        QCOMPARE(lwbtest::readAll(p("rt_c.npt")), lwbtest::readAll(p("rt_a.npt")));
    }

    // A prediction that does not describe the pass is refused, not used (issue 27: a CPF of
    // zeros gave "O-C from CPF prediction" with 6 normal points; one record 1000 km off cut the
    // recall from 0.999 to 0.83 without a word). Here the BLITS prediction with its epochs moved
    // by a minute (O-C of milliseconds), with one record moved by 1000 km, and shuffled.
    void predictionsThatDoNotFitAreRefused() {
        if (!lwbtest::haveShared("slr/blits_cpf_120626_6801.hts")) QSKIP("shared SLR data absent");
        const QString frd = lwbtest::sharedPath("slr/blits_201206.frd"), snx = lwbtest::sharedPath("slr/SLRF2014_POS+VEL_2030.0_200428.snx");
        const QList<QByteArray> lines = lwbtest::readAll(lwbtest::sharedPath("slr/blits_cpf_120626_6801.hts")).split('\n');
        QByteArray late, off;
        int records = 0;
        for (const QByteArray& l : lines) {
            QList<QByteArray> f = l.simplified().split(' ');
            if (f.value(0) == "10" && f.size() >= 8) {
                ++records;
                QList<QByteArray> g = f;
                g[3] = QByteArray::number(f[3].toDouble() + 60, 'f', 6);  // every epoch a minute late
                late += g.join(' ') + "\n";
                if (records == 100) f[5] = QByteArray::number(f[5].toDouble() + 1e6, 'f', 3);
                off += f.join(' ') + "\n";
            } else {
                late += l + "\n";
                off += l + "\n";
            }
        }
        QVERIFY(lwbtest::writeText(p("late.hts"), late) && lwbtest::writeText(p("off.hts"), off));
        lwbtest::CliRun r = runCli({"slr", frd, "--pass", "3", "--cpf", p("late.hts"), "--stations", snx, "-o", p("late.csv")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("does not describe this pass") && r.err.contains(" ms"), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("late.csv")));
        r = runCli({"slr", frd, "--pass", "3", "--cpf", p("off.hts"), "--stations", snx, "-o", p("off.csv")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("off.hts:") && r.err.contains("off the orbit"), qPrintable(r.err));
        // In --all-passes the late prediction is set aside pass by pass, with the reason.
        r = runCli({"slr", frd, "--all-passes", "--out-dir", p("late"), "--cpf", p("late.hts"), "--stations", snx, "-q"});
        QVERIFY2(r.exitCode == 0 || r.exitCode == 3, qPrintable(r.err));
        const QByteArray summary = lwbtest::readAll(p("late/summary.csv"));
        QVERIFY(summary.contains("does not describe this pass"));
        QVERIFY(!summary.contains("CPF prediction"));
    }

    // No confident answer from noise (issue 27): a 0.2 %-signal pass (no scale shows a track) and
    // a pass whose track is doubled 3 ns away (two tracks merged into one of 1.5 ns RMS) write the
    // points' classes, form no normal points and exit 3 with the reason, even with -q.
    void doubtfulPassesGiveNoNormalPoints() {
        QCOMPARE(runCli({"simulate", "slr", "--kind", "khz", "--points", "100000", "--signal-fraction", "0.002", "--seed", "3",
                         "-q", p("faint.csv")}).exitCode, 0);
        lwbtest::CliRun r = runCli({"slr", p("faint.csv"), "-o", p("faint_out.csv"), "--np-bin", "5", "-q"});
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains("doubtful") && r.err.contains("cannot be told from noise"), qPrintable(r.err));
        QVERIFY(QFile::exists(p("faint_out.csv")));
        // The track doubled: every signal point again 3 ns later (and a microsecond later in time).
        QCOMPARE(runCli({"simulate", "slr", "--kind", "conventional", "--duration", "600", "--seed", "9", "-q", p("one.csv")}).exitCode, 0);
        const QList<QByteArray> lines = lwbtest::readAll(p("one.csv")).split('\n');
        QList<QPair<double, QByteArray>> rows;
        for (int i = 1; i < lines.size(); ++i) {
            const QList<QByteArray> f = lines[i].split(',');
            if (f.size() < 3) continue;
            rows.append({f[0].toDouble(), f[0] + "," + f[1]});
            if (f[2] == "1")
                rows.append({f[0].toDouble() + 1e-6, QByteArray::number(f[0].toDouble() + 1e-6, 'g', 17) + "," +
                                                          QByteArray::number(f[1].toDouble() + 3e-9, 'g', 17)});
        }
        std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        QByteArray two = "epoch_s,oc_s\n";
        for (const auto& row : rows) two += row.second + "\n";
        QVERIFY(lwbtest::writeText(p("two.csv"), two));
        r = runCli({"slr", p("two.csv"), "-o", p("two_out.csv"), "--np-bin", "30", "-q"});
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains("two parallel tracks 2.99") || r.err.contains("two parallel tracks 3.00"), qPrintable(r.err));
        // The pass as simulated (one track): exit 0, normal points.
        r = runCli({"slr", p("one.csv"), "-o", p("one_out.csv"), "--np-bin", "30"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.err.contains("normal points: ") && !r.err.contains("doubtful"), qPrintable(r.err));
        // Issue 41: a kHz pass (half noise) with a ghost of 60 % of its signal 3 ns later: the band
        // keeps noise between the two tracks, so no gap is empty (exit 0 and RMS 1.5 ns before).
        QCOMPARE(runCli({"simulate", "slr", "--kind", "khz", "--points", "20000", "--seed", "3", "-q", p("k.csv")}).exitCode, 0);
        const QByteArray ghost = lwbtest::withGhostTrack(lwbtest::readAll(p("k.csv")));
        QVERIFY(lwbtest::writeText(p("ghost.csv"), ghost));
        r = runCli({"slr", p("ghost.csv"), "-o", p("ghost_out.csv"), "--np-bin", "30", "-q"});
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains("two parallel tracks 2.99") || r.err.contains("two parallel tracks 3.00"), qPrintable(r.err));
        // Issue 41: a 0.5 %-signal debris pass (20 signal points among 3980): 5 noise points were
        // accepted as the track, exit 0. Resting on fewer than 10 image points, it must stand 20
        // times above the noise, and does not: doubtful.
        QCOMPARE(runCli({"simulate", "slr", "--kind", "diffuse", "--points", "4000", "--signal-fraction", "0.005", "--seed",
                         "3", "-q", p("faint_debris.csv")}).exitCode, 0);
        r = runCli({"slr", p("faint_debris.csv"), "-o", p("faint_debris_out.csv"), "--np-bin", "30", "-q"});
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains("point(s) the image found") && r.err.contains("cannot be told from noise"), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestSlrCli)
#include "test_slr_cli.moc"
