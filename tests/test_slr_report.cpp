// The one-page PDF report of a pass (laserwb-cli slr --report-out; core/slr/pass_report.hpp),
// read back as a station would: rendered by poppler's pdftoppm (a real page of A4 with the plots
// drawn where they belong) and its text by pdftotext (the satellite, the verdict, every normal
// point of the NPT written in the same run, the parameters and the command). Also: a pass with no
// normal points says why, a kHz pass of 2·10^5 points is still a small page, the report is an
// output like the others (its provenance, all or nothing, never standard output).
#include <QtTest>
#include <opencv2/imgcodecs.hpp>

#include "core/slr/crd.hpp"
#include "test_support.hpp"

using lwbtest::runCli;

namespace {
bool havePoppler() { return !QStandardPaths::findExecutable("pdftoppm").isEmpty() && !QStandardPaths::findExecutable("pdftotext").isEmpty(); }

// pdftotext -layout of the first page.
QString pdfText(const QString& pdf) {
    const lwbtest::CliRun r = lwbtest::runProgram("pdftotext", {"-layout", pdf, "-"});
    return r.exitCode == 0 ? r.out : QString("pdftotext failed: ") + r.err;
}

// The page rendered at `dpi` (pdftoppm -singlefile), null when it cannot be.
cv::Mat pdfPage(const QString& pdf, int dpi, const QString& outBase) {
    const lwbtest::CliRun r = lwbtest::runProgram("pdftoppm", {"-r", QString::number(dpi), "-png", "-singlefile", pdf, outBase});
    if (r.exitCode != 0) return {};
    return cv::imread((outBase + ".png").toStdString(), cv::IMREAD_GRAYSCALE);
}

// Share of pixels in the rectangle (fractions of the page) that are not near-white.
double inked(const cv::Mat& page, double x0, double y0, double x1, double y1) {
    long n = 0, ink = 0;
    for (int y = int(y0 * page.rows); y < int(y1 * page.rows); ++y)
        for (int x = int(x0 * page.cols); x < int(x1 * page.cols); ++x, ++n)
            if (page.at<uchar>(y, x) < 200) ++ink;
    return n ? double(ink) / n : 0;
}
}  // namespace

class TestSlrReport : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() {
        if (!havePoppler()) QSKIP("pdftoppm/pdftotext (Debian poppler-utils) absent: make deps installs them");
    }

    /// A real pass with its prediction: the page, its plots and its tables.
    void realPassReport() {
        const QString frd = lwbtest::sharedPath("slr/blits_201206.frd"), cpf = lwbtest::sharedPath("slr/blits_cpf_120626_6801.hts"),
                      snx = lwbtest::sharedPath("slr/SLRF2014_POS+VEL_2030.0_200428.snx");
        if (!QFile::exists(frd) || !QFile::exists(cpf) || !QFile::exists(snx)) QSKIP("shared data absent");
        const QString pdf = m_dir.path() + "/blits.pdf", npt = m_dir.path() + "/blits.npt";
        const lwbtest::CliRun r = runCli({"slr", frd, "--pass", "3", "--cpf", cpf, "--stations", snx, "--report-out", pdf,
                                          "--npt-out", npt, "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFile::exists(pdf + ".provenance.json"));
        // The normal points of the NPT, the report's table's rows.
        lwb::core::slr::CrdReadResult crd = lwb::core::slr::readCrd(npt.toStdString());
        QVERIFY2(crd.ok && crd.file.passes.size() == 1, crd.error.c_str());
        const size_t nps = crd.file.passes[0].normalPoints.size();
        QVERIFY2(nps >= 3, qPrintable(QString::number(nps)));
        const QString text = pdfText(pdf);
        for (const QString& want : {QString("SLR pass report"), QString("blits"), QString("OK"), QString("O-C and screening"),
                                    QString("Binary image"), QString("Residual histogram"), QString("Parameters"),
                                    QString("Normal points (%1)").arg(nps), QString("Provenance"), QString("CPF prediction"),
                                    QString("--cpf"), QString("sha256")})
            QVERIFY2(text.contains(want), qPrintable(want + " not in the report:\n" + text));
        // Every normal point's epoch (hh:mm:ss of its seconds of day) is in the table (≤ 25 fit).
        int listed = 0;
        for (const auto& np : crd.file.passes[0].normalPoints) {
            const long s = std::lround(np.secOfDay);
            const QString hms = QString::asprintf("%02ld:%02ld:%02ld", (s / 3600) % 24, (s / 60) % 60, s % 60);
            listed += text.contains(hms);
        }
        QVERIFY2(listed == int(std::min<size_t>(nps, 20)), qPrintable(QString("%1 of %2 epochs listed").arg(listed).arg(nps)));
        // One A4 page (at 50 dpi 413 × 585 px), with ink in each of the four plots' boxes.
        const cv::Mat page = pdfPage(pdf, 50, m_dir.path() + "/blits");
        QVERIFY(!page.empty());
        QVERIFY2(std::abs(page.cols - 413) <= 2 && std::abs(page.rows - 585) <= 2,
                 qPrintable(QString("%1 x %2").arg(page.cols).arg(page.rows)));
        QVERIFY(lwbtest::runProgram("pdfinfo", {pdf}).out.contains(QRegularExpression("Pages:\\s+1\\b")));
        const double oc = inked(page, 0.12, 0.16, 0.47, 0.33), res = inked(page, 0.60, 0.16, 0.95, 0.33);
        const double img = inked(page, 0.12, 0.40, 0.47, 0.54), hist = inked(page, 0.60, 0.40, 0.95, 0.54);
        QVERIFY2(oc > 0.01 && res > 0.01 && img > 0.005 && hist > 0.05,
                 qPrintable(QString("ink: O-C %1, residuals %2, image %3, histogram %4").arg(oc).arg(res).arg(img).arg(hist)));
    }

    /// A pass of noise alone: the verdict and why there are no normal points, on the page.
    void noSignalSaysWhy() {
        const QString frd = m_dir.path() + "/noise.frd", pdf = m_dir.path() + "/noise.pdf";
        QVERIFY(runCli({"simulate", "slr", "--kind", "conventional", "--points", "3000", "--signal-fraction", "0.002", "--seed", "5", "-q", frd}).exitCode == 0);
        const lwbtest::CliRun r = runCli({"slr", frd, "--report-out", pdf, "-q"});
        QVERIFY2(r.exitCode == 0 || r.exitCode == 3, qPrintable(r.err));
        const QString text = pdfText(pdf);
        QVERIFY2(text.contains("Normal points (0)") && text.contains("None:"), qPrintable(text));
        QVERIFY2(text.contains(r.exitCode == 3 ? "DOUBTFUL" : "NO SIGNAL"), qPrintable(text));
        QVERIFY2(!text.contains(QRegularExpression("\\bnan\\b", QRegularExpression::CaseInsensitiveOption)), qPrintable(text));  // (a precision of nothing accepted is said, not NaN)
    }

    /// A kHz pass of 2·10^5 points: the plots are rasters, the page stays small and quick.
    void largePassStaysOnePage() {
        const QString frd = m_dir.path() + "/khz.frd", pdf = m_dir.path() + "/khz.pdf";
        QVERIFY(runCli({"simulate", "slr", "--kind", "khz", "--points", "200000", "--seed", "2", "-q", frd}).exitCode == 0);
        const lwbtest::CliRun r = runCli({"slr", frd, "--report-out", pdf, "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const qint64 size = QFileInfo(pdf).size();
        QVERIFY2(size > 20000 && size < 1500000, qPrintable(QString::number(size)));
        QVERIFY(pdfText(pdf).contains("200000 points"));
    }

    /// An output like the others: never to standard output, nothing written when refused.
    void reportIsAnOutput() {
        const lwbtest::CliRun r = runCli({"slr", "whatever.frd", "--report-out", "-"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--report-out needs a file"), qPrintable(r.err));
        const QString pdf = m_dir.path() + "/missing.pdf";
        const lwbtest::CliRun m = runCli({"slr", m_dir.path() + "/no-such.frd", "--report-out", pdf});
        QVERIFY(m.exitCode != 0);
        QVERIFY(!QFile::exists(pdf));
    }
};

QTEST_GUILESS_MAIN(TestSlrReport)
#include "test_slr_report.moc"
