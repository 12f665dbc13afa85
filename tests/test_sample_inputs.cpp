// The simulators that make the documentation's sample inputs (README, "Sample inputs") write
// inputs with exact truth, and the commands the README runs on them recover that truth within
// stated tolerances: a sample a user tries first must give right answers, not merely run.
#include <QtTest>
#include <cmath>

#include "test_support.hpp"

using namespace lwbtest;

namespace {

// A CSV as rows of fields keyed by the header's names.
QList<QMap<QString, QString>> csvRows(const QByteArray& text) {
    QList<QMap<QString, QString>> rows;
    const QList<QByteArray> lines = text.split('\n');
    if (lines.isEmpty()) return rows;
    const QStringList head = QString::fromUtf8(lines[0]).split(',');
    for (int i = 1; i < lines.size(); ++i) {
        if (lines[i].isEmpty()) continue;
        const QStringList f = QString::fromUtf8(lines[i]).split(',');
        QMap<QString, QString> r;
        for (int k = 0; k < head.size(); ++k) r[head[k]] = f.value(k);
        rows << r;
    }
    return rows;
}

double num(const QMap<QString, QString>& r, const QString& key) {
    bool ok = false;
    const double v = r.value(key).toDouble(&ok);
    return ok ? v : NAN;
}

}  // namespace

class TestSampleInputs : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString p(const QString& n) const { return m_dir.path() + "/" + n; }

private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // simulate trend -> trend: each month's mean within 4 standard errors of the true centre
    // (0.15 px scatter, 20 shots: 4 x 0.034 = 0.13 px), and most planted outliers rejected.
    void trendRecoversTheTrueMonthlyCentres() {
        CliRun r = runCli({"simulate", "trend", "--months", "12", "--seed", "4", p("c.csv"), "--truth", p("t.csv")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        static const QRegularExpression planted("\\((\\d+) outliers\\)");
        const int outliers = planted.match(r.err).captured(1).toInt();
        QVERIFY2(outliers > 0, qPrintable(r.err));
        r = runCli({"trend", p("c.csv"), "-o", p("m.csv"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const auto truth = csvRows(readAll(p("t.csv"))), months = csvRows(readAll(p("m.csv")));
        QCOMPARE(truth.size(), 24);
        QCOMPARE(months.size(), 24);
        int rejected = 0;
        double worst = 0;
        for (const auto& t : truth) {
            const auto it = std::find_if(months.begin(), months.end(), [&](const QMap<QString, QString>& m) {
                return m["beam"] == t["beam"] && m["month"] == t["month"];
            });
            QVERIFY2(it != months.end(), qPrintable(t["month"]));
            worst = std::max({worst, std::fabs(num(*it, "x_mean") - num(t, "x_true")), std::fabs(num(*it, "y_mean") - num(t, "y_true"))});
            rejected += int(num(*it, "rejected"));
        }
        qInfo("trend on simulate trend: worst monthly mean error %.3f px, %d shots rejected", worst, rejected);
        QVERIFY2(worst < 0.13, qPrintable(QString::number(worst)));
        // The outliers (1.5-4 px off, 10 to 27 sigma of the scatter) are all rejected by the
        // 3-sigma rule, which may also take a few of the 480 good shots (0.3 % each per axis).
        QVERIFY2(rejected >= outliers && rejected <= outliers + 5,
                 qPrintable(QString("%1 rejected, %2 planted").arg(rejected).arg(outliers)));
    }

    // A two-beam frame: each beam's spot found within 0.5 px of its truth, as its own ROI.
    void twoBeamFramesGiveBothSpots() {
        CliRun r = runCli({"simulate", "footprint", "--full-frame", "--center", "60,311", "--center", "228,158", "--count", "4",
                           "--seed", "3", "-q", p("lsi")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = runCli({"footprint", "--center", "60,311", "--center", "228,158", p("lsi"), "-o", p("lsi.csv"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const auto truth = csvRows(readAll(p("lsi/truth.csv"))), rows = csvRows(readAll(p("lsi.csv")));
        QCOMPARE(rows.size(), 8);
        for (const auto& row : rows) {
            const QString name = QFileInfo(row["file"]).fileName();
            const auto t = std::find_if(truth.begin(), truth.end(), [&](const QMap<QString, QString>& x) { return x["file"] == name; });
            QVERIFY(t != truth.end());
            const bool second = row["roi"] == "1";
            const double dx = num(row, "x") - num(*t, second ? "x2" : "x"), dy = num(row, "y") - num(*t, second ? "y2" : "y");
            QVERIFY2(std::hypot(dx, dy) < 0.5, qPrintable(name + " roi " + row["roi"] + ": off by " + QString::number(std::hypot(dx, dy))));
        }
        // One centre, or a case other than normal, keeps the one-beam frame.
        r = runCli({"simulate", "footprint", "--full-frame", "--center", "60,311", "--center", "228,158", "--case", "mixed",
                    "--count", "2", "--seed", "3", "-q", p("bad")});
        QCOMPARE(r.exitCode, 2);
    }

    // simulate calib's validation differences: calib stats gives each beam's mean within 3
    // standard errors of the simulated bias.
    void calibStatsRecoversTheSimulatedBias() {
        CliRun r = runCli({"simulate", "calib", "--seed", "5", "-q", p("cal")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = runCli({"calib", "stats", p("cal/diffs.csv"), "--group", "beam", "-o", p("st.csv")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const auto truth = csvRows(readAll(p("cal/diffs_truth.csv"))), stats = csvRows(readAll(p("st.csv")));
        QCOMPARE(truth.size(), 2);
        QCOMPARE(stats.size(), 2);
        for (int b = 0; b < 2; ++b) {
            const double se = num(truth[b], "sd_m") / std::sqrt(24.0);
            QVERIFY2(std::fabs(num(stats[b], "mean") - num(truth[b], "mean_m")) < 3 * se, qPrintable(stats[b]["mean"]));
        }
    }

    // simulate radiometry -> mosaic -> fit -> apply: k and b within 3 of their standard errors of
    // the simulated line, every check surface within the paper's 5 %, the control points fitted
    // to their picking error.
    void radiometryChainRecoversTheSimulatedLine() {
        CliRun r = runCli({"simulate", "radiometry", "-q", p("field")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QStringList frames;
        for (const QString& f : QDir(p("field")).entryList({"frame_*.png"}, QDir::Files, QDir::Name)) frames << p("field/" + f);
        QCOMPARE(frames.size(), 6);
        r = runCli(QStringList{"radiometry", "mosaic"} + frames + QStringList{"-o", p("row.tif"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = runCli({"radiometry", "fit", p("field/regions.csv"), "--image", p("row.tif"), "-o", p("fit.csv"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const auto truth = csvRows(readAll(p("field/truth.csv"))), fit = csvRows(readAll(p("fit.csv")));
        QCOMPARE(fit.size(), 1);
        QCOMPARE(num(fit[0], "n"), 6.0);
        QVERIFY2(std::fabs(num(fit[0], "k") - num(truth[0], "k")) < 3 * num(fit[0], "k_sd"), qPrintable(fit[0]["k"]));
        QVERIFY2(std::fabs(num(fit[0], "b") - num(truth[0], "b")) < 3 * num(fit[0], "b_sd"), qPrintable(fit[0]["b"]));
        r = runCli({"radiometry", "apply", p("row.tif"), "--fit", p("fit.csv"), "-o", p("refl.tif"), "--check",
                    p("field/check.csv"), "--table", p("errors.csv"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(csvRows(readAll(p("errors.csv"))).size(), 4);
        r = runCli({"radiometry", "gcp", p("row.tif"), "--gcps", p("field/gcps.csv"), "-o", p("map.tif"), "--residuals",
                    p("res.csv"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const auto res = csvRows(readAll(p("res.csv")));
        QCOMPARE(res.size(), 6);
        double rms = 0;
        for (const auto& g : res) rms += num(g, "d_px") * num(g, "d_px");
        rms = std::sqrt(rms / res.size());
        // Picked to 0.3 px per axis: an affine fit of 6 points (6 parameters per 12 coordinates)
        // leaves residuals of about 0.3 x sqrt(2) x sqrt(1/2) px; a wrong map would be pixels off.
        qInfo("control points: residual RMS %.3f px", rms);
        QVERIFY2(rms > 0.02 && rms < 0.8, qPrintable(QString::number(rms)));
        for (const auto& g : res) QCOMPARE(g["outlier"], QString("0"));
        // One mark 1 km off (issue 27: no word of it): named, the map written, exit 3.
        QByteArray gcps = readAll(p("field/gcps.csv"));
        QList<QByteArray> lines = gcps.split('\n');
        QList<QByteArray> g3 = lines[3].split(',');
        g3[3] = QByteArray::number(g3[3].toDouble() + 1000, 'f', 4);
        lines[3] = g3.join(',');
        QVERIFY(writeText(p("gcps_off.csv"), lines.join('\n')));
        r = runCli({"radiometry", "gcp", p("row.tif"), "--gcps", p("gcps_off.csv"), "-o", p("map_off.tif"), "--residuals",
                    p("res_off.csv"), "-q"});
        QCOMPARE(r.exitCode, 3);
        QVERIFY2(r.err.contains("G3 (line 4)") && r.err.contains("999.99"), qPrintable(r.err));  // (1000 m less its survey noise)
        QVERIFY(QFile::exists(p("map_off.tif")));
        for (const auto& g : csvRows(readAll(p("res_off.csv")))) QCOMPARE(g["outlier"], QString(g["id"] == "G3" ? "1" : "0"));
    }

    // A simulated CRD pass: the screening agrees with its filter flags (the truth).
    void crdPassIsScreenedAgainstItsTruth() {
        CliRun r = runCli({"simulate", "slr", "--kind", "conventional", "--seed", "5", "-q", p("pass.frd")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(readAll(p("pass.frd")).startsWith("H1 CRD  2 "));
        r = runCli({"slr", p("pass.frd"), "-o", p("s.csv")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        int tp = 0, fp = 0, fn = 0;
        for (const auto& row : csvRows(readAll(p("s.csv")))) {
            const bool accepted = row["class"] != "noise", signal = row["station_flag"] == "2";
            tp += accepted && signal;
            fp += accepted && !signal;
            fn += !accepted && signal;
        }
        const double precision = double(tp) / (tp + fp), recall = double(tp) / (tp + fn);
        qInfo("simulated CRD pass: precision %.4f, recall %.4f", precision, recall);
        QVERIFY(precision > 0.99 && recall > 0.99);
    }
};

QTEST_GUILESS_MAIN(TestSampleInputs)
#include "test_sample_inputs.moc"
