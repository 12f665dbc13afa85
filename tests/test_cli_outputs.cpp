// One output discipline for every laserwb-cli command (issue 8): outputs are checked before any
// work, written under staging names and renamed into place together. Here every command with two
// or more outputs is made to fail on its last output — while writing, and while renaming after
// the others were already renamed — and nothing may be left: no new file, no replaced file, no
// staging file. And an output that names an input through another spelling (./x, a symbolic
// link, a hard link), a device or a FIFO is refused with the input unchanged.
#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>
#include <QProcess>
#include <opencv2/imgcodecs.hpp>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/common/output_set.hpp"
#include "core/sim/scene_sim.hpp"
#include "test_support.hpp"

using namespace lwbtest;

namespace {
const int kTimeoutMs = 120000;

struct Case {
    QStringList args;     ///< with @name for files in the case's folder
    QStringList outputs;  ///< the outputs, last one last
};
}  // namespace

class TestCliOutputs : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString p(const QString& n) const { return m_dir.path() + "/" + n; }
    QString m_calib;  // simulate calib folder

    QStringList expand(const QStringList& args) const {
        QStringList out;
        for (const QString& a : args) out << (a.startsWith('@') ? p(a.mid(1)) : a);
        return out;
    }
    void noStagingFiles() const {
        for (const QString& f : filesIn(m_dir.path()))
            QVERIFY2(!f.contains(".lwb-stage-") && !f.contains(".lwb-backup-") && !f.contains(".tmp-") && !f.contains(".lwb-tmp-"), qPrintable(f));
    }

    // The commands with two or more outputs, each with its inputs prepared in the folder.
    QMap<QString, Case> multiOutputCases() const {
        QMap<QString, Case> c;
        const QString slrIn = sharedPath("slr/7080_STELLA_crd_071220_2128_0.frd");
        if (QFile::exists(slrIn))
            c["slr"] = {{"slr", slrIn, "--np-bin", "30", "-q", "-o", "@s.csv", "--crd-out", "@s.frd", "--npt-out", "@s.npt"},
                        {"s.csv", "s.frd", "s.npt"}};
        c["calib detector"] = {{"calib", "detector", "@calib/detectors.csv", "-q", "-o", "@d.csv", "--detectors", "@d_rep.csv"},
                               {"d.csv", "d_rep.csv"}};
        c["calib waveform"] = {{"calib", "waveform", "@calib/waveform.csv", "--features", "@calib/features.csv", "-o", "@w.csv",
                                "--model", "@w_model.csv"},
                               {"w.csv", "w_model.csv"}};
        c["calib pointing"] = {{"calib", "pointing", "@calib/control_points.csv", "--beams", "@calib/beams.json", "--model", "dual",
                                "-q", "-o", "@pt.csv", "--params", "@pt_p.csv", "--residuals", "@pt_r.csv", "--iterations",
                                "@pt_i.csv", "--beams-out", "@pt_b.json"},
                               {"pt.csv", "pt_p.csv", "pt_r.csv", "pt_i.csv", "pt_b.json"}};
        c["radiometry mosaic"] = {{"radiometry", "mosaic", "@f0.png", "@f1.png", "@f2.png", "-q", "-o", "@row.tif", "--coverage",
                                   "@cov.png", "--pairs", "@pairs.csv"},
                                  {"row.tif", "cov.png", "pairs.csv"}};
        c["radiometry gcp"] = {{"radiometry", "gcp", "@img.png", "--gcps", "@gcps.csv", "-q", "-o", "@map.tif", "--valid",
                                "@valid.png", "--residuals", "@gcp_res.csv"},
                               {"map.tif", "valid.png", "gcp_res.csv"}};
        c["radiometry fit"] = {{"radiometry", "fit", "@regions.csv", "-q", "-o", "@fit.csv", "--regions", "@fit_regions.csv"},
                               {"fit.csv", "fit_regions.csv"}};
        c["radiometry apply"] = {{"radiometry", "apply", "@img.png", "--fit", "@fit_in.csv", "--check", "@check.csv", "-q", "-o",
                                  "@refl.tif", "--uncertainty", "@unc.tif", "--table", "@table.csv"},
                                 {"refl.tif", "unc.tif", "table.csv"}};
        c["simulate calib"] = {{"simulate", "calib", "@simc", "-q"},
                               {"simc/beams.json", "simc/control_points.csv", "simc/pointing_truth.csv", "simc/detectors.csv",
                                "simc/detector_truth.csv", "simc/waveform.csv", "simc/features.csv",
                                "simc/waveform_truth.csv"}};
        c["simulate footprint"] = {{"simulate", "footprint", "--count", "3", "-q", "@simf"},
                                   {"simf/shot_000000.png", "simf/shot_000001.png", "simf/shot_000002.png", "simf/truth.csv"}};
        return c;
    }

    // Runs a case that must succeed (to learn it works at all), then with the fault.
    void runWithFault(const QString& name, const Case& c, const QString& phase, bool outputsExistBefore) {
        for (const QString& o : c.outputs) QFile::remove(p(o));
        QDir(p("simc")).removeRecursively();
        QDir(p("simf")).removeRecursively();
        if (outputsExistBefore) {
            QDir().mkpath(p("simc"));
            QDir().mkpath(p("simf"));
            for (const QString& o : c.outputs) QVERIFY(writeText(p(o), "previous content of " + o.toUtf8()));
        }
        const QString last = c.outputs.last().section('/', -1);
        const CliRun r = runCli(expand(c.args), kTimeoutMs, {"LWB_FAULT_OUTPUT=" + phase + ":" + last});
        QVERIFY2(r.exitCode == 1, qPrintable(name + " " + phase + ": exit " + QString::number(r.exitCode) + "\n" + r.err));
        QVERIFY2(r.err.contains(last), qPrintable(name + ": the message names the output: " + r.err));
        for (const QString& o : c.outputs) {
            if (outputsExistBefore)
                QVERIFY2(readAll(p(o)) == "previous content of " + o.toUtf8(), qPrintable(name + " " + phase + ": " + o + " replaced"));
            else
                QVERIFY2(!QFile::exists(p(o)), qPrintable(name + " " + phase + ": " + o + " left behind"));
        }
        if (!outputsExistBefore) {
            // A folder the run created for its outputs is gone too.
            if (c.outputs.first().startsWith("simc/")) QVERIFY2(!QFileInfo::exists(p("simc")), qPrintable(name));
            if (c.outputs.first().startsWith("simf/")) QVERIFY2(!QFileInfo::exists(p("simf")), qPrintable(name));
        }
        noStagingFiles();
        for (const char* sub : {"simc", "simf"})
            for (const QString& f : filesIn(p(sub))) QVERIFY2(!f.contains(".lwb-"), qPrintable(f));
    }

private slots:
    // Issue 41: standard output is part of the set. `-o -` was streamed after the other files
    // were committed: to a full device it failed with --npt-out already written (and a closed
    // pipe killed the process by SIGPIPE, exit 141). Now the files are rolled back, exit 1.
    void standardOutputFailureRollsTheSetBack() {
        const QString in = sharedPath("slr/7080_STELLA_crd_071220_2128_0.frd");
        if (!QFile::exists(in)) QSKIP("shared data absent");
        for (const QString& sink : {QString("/dev/full"), QString()}) {
            const QString npt = p("stdout_set.npt");
            QFile::remove(npt);
            QProcess proc;
            proc.setStandardOutputFile(sink.isEmpty() ? QProcess::nullDevice() : sink);
            proc.start(QString(LWB_CLI), {"slr", in, "-o", "-", "--npt-out", npt, "-q"});
            QVERIFY(proc.waitForFinished(60000));
            if (sink.isEmpty()) {  // (the null device takes everything: the set is written)
                QCOMPARE(proc.exitCode(), 0);
                QVERIFY(QFile::exists(npt));
                continue;
            }
            QCOMPARE(proc.exitStatus(), QProcess::NormalExit);
            QCOMPARE(proc.exitCode(), 1);
            QVERIFY2(QString::fromUtf8(proc.readAllStandardError()).contains("cannot write standard output"), "no reason");
            QVERIFY2(!QFile::exists(npt), "the normal points were written beside a failed standard output");
        }
    }

    void initTestCase() {
        QVERIFY(m_dir.isValid());
        // Calibration inputs from the simulator.
        CliRun r = runCli({"simulate", "calib", p("calib"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        // Radiometry inputs: three overlapping frames, a 16-bit image with GCPs, regions and a fit.
        lwb::core::sim::RowFramesParams rp;
        rp.frames = 3;
        const auto rf = lwb::core::sim::simulateRowFrames(rp, {}, 5);
        for (size_t k = 0; k < rf.frames.size(); ++k)
            QVERIFY(cv::imwrite(p(QString("f%1.png").arg(k)).toStdString(), rf.frames[k]));
        cv::Mat img(60, 120, CV_16UC1);
        for (int y = 0; y < img.rows; ++y)
            for (int x = 0; x < img.cols; ++x) img.at<uint16_t>(y, x) = static_cast<uint16_t>(1000 + 200 * x + y);
        QVERIFY(cv::imwrite(p("img.png").toStdString(), img));
        QVERIFY(writeText(p("gcps.csv"), "id,x,y,map_x,map_y\nA,0,0,0,0.6\nB,119,0,1.19,0.6\nC,0,59,0,0.01\nD,119,59,1.19,0.01\n"));
        QVERIFY(writeText(p("regions.csv"), "name,reflectance,dn\na,10,1000\nb,20,2000\nc,30.1,3000\nd,39.9,4000\n"));
        QVERIFY(writeText(p("fit_in.csv"), "k,b,k_sd,b_sd,cov_kb,n\n0.001,0,1e-6,0.01,0,4\n"));
        QVERIFY(writeText(p("check.csv"), "name,reflectance,x,y,w,h\nc1,1.7035,2,2,4,4\n"));
    }

    // The image codecs (OpenCV imgcodecs, GDAL: ~120 libraries, ~0.1 s of start-up) are loaded
    // only by a run that reads or writes an image: the dynamic loader's own list of the files
    // it opened (LD_DEBUG=files) shows them absent from an SLR run and present in a GeoTIFF
    // run, which also works (the module is found beside the executable). An SLR run loads no
    // OpenCV at all (13 of its 19 ms of start-up): the imaging commands run in
    // laserwb-cli-imaging, which laserwb-cli starts in its place.
    void imageCodecsLoadOnlyWhenAnImageIsRead() {
        const QString pass = p("codecs_pass.csv");
        CliRun r = runCli({"simulate", "slr", "--points", "300", "--seed", "3", "-q", pass});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = runCli({"slr", pass, "-o", p("codecs_out.csv"), "-q"}, 120000, {"LD_DEBUG=files"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err.right(2000)));
        QVERIFY2(r.err.contains("file=libstdc++"), "LD_DEBUG output not seen");
        for (const char* lib : {"libgdal", "libopencv", "liblaserwb_codecs", "libtbb", "liblapack"})
            QVERIFY2(!r.err.contains(QString("file=") + lib) && !r.err.contains(QString("/") + lib), lib);
        r = runCli({"radiometry", "apply", p("img.png"), "--fit", p("fit_in.csv"), "-o", p("codecs_refl.tif"), "-q"}, 120000,
                   {"LD_DEBUG=files"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err.right(2000)));
        QVERIFY(r.err.contains("liblaserwb_codecs.so"));
        QVERIFY(r.err.contains("libgdal"));
        QVERIFY(r.err.contains("file=libopencv_core"));  // (in laserwb-cli-imaging)
        QVERIFY(QFileInfo(p("codecs_refl.tif")).size() > 0);
    }

    // Every multi-output command works when nothing is injected (so the fault runs below test
    // the discipline, not a broken command).
    void everyMultiOutputCommandWorks_data() {
        QTest::addColumn<QString>("name");
        for (const QString& n : multiOutputCases().keys()) QTest::newRow(qPrintable(n)) << n;
    }
    void everyMultiOutputCommandWorks() {
        QFETCH(QString, name);
        const Case c = multiOutputCases()[name];
        QDir(p("simc")).removeRecursively();
        QDir(p("simf")).removeRecursively();
        const CliRun r = runCli(expand(c.args), kTimeoutMs);
        QVERIFY2(r.exitCode == 0, qPrintable(name + ": " + r.err));
        for (const QString& o : c.outputs) QVERIFY2(QFile::exists(p(o)), qPrintable(name + ": " + o));
        noStagingFiles();
        if (name.startsWith("calib") || name.startsWith("radiometry")) provenanceListsEveryOutput(name, c);
    }

    // Issue 31: the calibration and radiometry commands' outputs carry a provenance sidecar
    // beside their first output: the command, the parameters, every input and output with the
    // SHA-256 its file has (checked here with Qt's own SHA-256).
    void provenanceListsEveryOutput(const QString& name, const Case& c) {
        const QString side = p(c.outputs.first() + ".provenance.json");
        QJsonParseError pe;
        const QJsonObject o = QJsonDocument::fromJson(readAll(side), &pe).object();
        QVERIFY2(pe.error == QJsonParseError::NoError && !o.isEmpty(), qPrintable(name + ": " + side));
        QCOMPARE(o["command"].toString(), name);
        QVERIFY2(o["parameters"].isObject() && !o["parameters"].toObject().isEmpty(), qPrintable(name));
        QVERIFY2(!o["inputs"].toArray().isEmpty(), qPrintable(name));
        QStringList listed;
        for (const QJsonValue& v : o["outputs"].toArray()) {
            const QJsonObject f = v.toObject();
            const QString path = QFileInfo(side).dir().filePath(f["path"].toString());
            const QByteArray sum = QCryptographicHash::hash(readAll(path), QCryptographicHash::Sha256).toHex();
            QCOMPARE(f["sha256"].toString().toLatin1(), sum);
            listed << QFileInfo(path).fileName();
        }
        QStringList want;
        for (const QString& out : c.outputs) want << QFileInfo(out).fileName();
        listed.sort();
        want.sort();
        QCOMPARE(listed, want);
    }

    // The last output fails while being written or while being renamed into place (after the
    // others were renamed): exit 1, the output named, and no output left (or each previous file
    // kept exactly as it was).
    void lastOutputFailsNothingLeft_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("phase");
        QTest::addColumn<bool>("existed");
        for (const QString& n : multiOutputCases().keys())
            for (const char* phase : {"write", "rename"})
                for (bool existed : {false, true})
                    QTest::newRow(qPrintable(n + " " + phase + (existed ? " over old files" : ""))) << n << phase << existed;
    }
    void lastOutputFailsNothingLeft() {
        QFETCH(QString, name);
        QFETCH(QString, phase);
        QFETCH(bool, existed);
        runWithFault(name, multiOutputCases()[name], phase, existed);
    }

    // -o naming an input through another spelling is refused (exit 2) and the input unchanged.
    void outputNamingAnInputIsRefused_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("input");
        QTest::newRow("footprint ./x") << QStringList{"footprint", "@shot.png", "-o", "./shot.png"} << "shot.png";
        QTest::newRow("footprint folder input") << QStringList{"footprint", "@shots", "-o", "@shots/shot_000001.png"}
                                                << "shots/shot_000001.png";
        QTest::newRow("trend symlink") << QStringList{"trend", "@cent.csv", "-o", "@cent_link.csv"} << "cent.csv";
        QTest::newRow("trend hard link") << QStringList{"trend", "@cent.csv", "-o", "@cent_hard.csv"} << "cent.csv";
        QTest::newRow("calib detector ../x") << QStringList{"calib", "detector", "@det.csv", "-o", "@sub/../det.csv"} << "det.csv";
        QTest::newRow("calib detector report") << QStringList{"calib", "detector", "@det.csv", "--detectors", "./det.csv"}
                                               << "det.csv";
        QTest::newRow("calib stats") << QStringList{"calib", "stats", "@diff.csv", "-o", "./diff.csv"} << "diff.csv";
        QTest::newRow("calib pointing beams-out") << QStringList{"calib", "pointing", "@calib/control_points.csv", "--beams",
                                                                 "@calib/beams.json", "-o", "@pp.csv", "--beams-out",
                                                                 "./calib/beams.json"}
                                                  << "calib/beams.json";
        QTest::newRow("radiometry apply") << QStringList{"radiometry", "apply", "@img.png", "--k", "0.001", "--b", "0", "-o",
                                                         "./img.png"}
                                          << "img.png";
        QTest::newRow("radiometry mosaic coverage") << QStringList{"radiometry", "mosaic", "@f0.png", "@f1.png", "-o", "@r.tif",
                                                                   "--coverage", "./f1.png"}
                                                    << "f1.png";
        QTest::newRow("radiometry fit regions") << QStringList{"radiometry", "fit", "@regions.csv", "-o", "@fx.csv",
                                                               "--regions", "@regions_link.csv"}
                                                << "regions.csv";
        // Auxiliary inputs (issue 27): a config, a beams file, control points, a preset.
        QTest::newRow("trend --config") << QStringList{"trend", "@cent.csv", "--config", "@cfg.json", "-o", "./cfg.json"} << "cfg.json";
        QTest::newRow("footprint --config") << QStringList{"footprint", "@shot.png", "--config", "@fcfg.json", "-o", "@fcfg.json"}
                                            << "fcfg.json";
        QTest::newRow("calib pointing --params over --beams")
            << QStringList{"calib", "pointing", "@calib/control_points.csv", "--beams", "@calib/beams.json", "-o", "@pp.csv",
                           "--params", "./calib/beams.json"}
            << "calib/beams.json";
        QTest::newRow("radiometry gcp --residuals over --gcps")
            << QStringList{"radiometry", "gcp", "@img.png", "--gcps", "@gcps.csv", "-o", "@m.tif", "--residuals", "./gcps.csv"}
            << "gcps.csv";
        QTest::newRow("radiometry apply --table over --fit")
            << QStringList{"radiometry", "apply", "@img.png", "--fit", "@fit_in.csv", "--check", "@check.csv", "-o", "@r2.tif",
                           "--table", "@fit_in.csv"}
            << "fit_in.csv";
        QTest::newRow("slr --config") << QStringList{"slr", "@sim.frd", "--config", "@scfg.json", "-o", "@scfg.json"} << "scfg.json";
        QTest::newRow("slr --preset") << QStringList{"slr", "@sim.frd", "--preset", "@presets.json", "-o", "./presets.json"}
                                      << "presets.json";
        QTest::newRow("slr --all-passes over --config in the folder")
            << QStringList{"slr", "@sim.frd", "--all-passes", "--out-dir", "@day", "--config", "@day/summary.csv"} << "day/summary.csv";
        const QString slrIn = sharedPath("slr/7080_STELLA_crd_071220_2128_0.frd");
        if (QFile::exists(slrIn)) {
            QTest::newRow("slr --stations over -o")
                << QStringList{"slr", "@blits.frd", "--pass", "3", "--cpf", "@blits.hts", "--stations", "@stations.snx", "-o",
                               "./stations.snx"}
                << "stations.snx";
            QTest::newRow("slr --cpf over --npt-out")
                << QStringList{"slr", "@blits.frd", "--pass", "3", "--cpf", "@blits.hts", "--stations", "@stations.snx", "-o",
                               "@bo.csv", "--npt-out", "@blits.hts"}
                << "blits.hts";
            QTest::newRow("slr crd-out ./pass") << QStringList{"slr", "@pass.frd", "-o", "@o.csv", "--crd-out", "./pass.frd",
                                                               "--area-min", "1000000"}
                                                << "pass.frd";
            QTest::newRow("slr symlink") << QStringList{"slr", "@pass.frd", "-o", "@pass_link.frd"} << "pass.frd";
        }
    }
    void outputNamingAnInputIsRefused() {
        QFETCH(QStringList, args);
        QFETCH(QString, input);
        // Fresh inputs.
        QDir().mkpath(p("sub"));
        QDir().mkpath(p("shots"));
        QVERIFY(runCli({"simulate", "footprint", "--count", "2", "-q", p("shots")}).exitCode == 0);
        QFile::remove(p("shot.png"));
        QVERIFY(QFile::copy(p("shots/shot_000000.png"), p("shot.png")));
        QVERIFY(writeText(p("cent.csv"), "time,beam,x,y\n2020-03-01,1,120.8,263.7\n2020-04-01,1,120.5,264.5\n"));
        QFile::remove(p("cent_link.csv"));
        QFile::remove(p("cent_hard.csv"));
        QVERIFY(QFile::link(p("cent.csv"), p("cent_link.csv")));
        QVERIFY(::link(p("cent.csv").toLocal8Bit().constData(), p("cent_hard.csv").toLocal8Bit().constData()) == 0);
        QFile::remove(p("det.csv"));
        QVERIFY(QFile::copy(p("calib/detectors.csv"), p("det.csv")));
        QVERIFY(writeText(p("diff.csv"), "d\n0.1\n-0.05\n0.02\n"));
        QFile::remove(p("regions_link.csv"));
        QVERIFY(QFile::link(p("regions.csv"), p("regions_link.csv")));
        const QString slrIn = sharedPath("slr/7080_STELLA_crd_071220_2128_0.frd");
        if (QFile::exists(slrIn)) {
            QFile::remove(p("pass.frd"));
            QFile::remove(p("pass_link.frd"));
            QVERIFY(QFile::copy(slrIn, p("pass.frd")));
            QVERIFY(QFile::link(p("pass.frd"), p("pass_link.frd")));
        }
        // Auxiliary inputs.
        CliRun cfg = runCli({"trend", "--print-config"});
        QVERIFY(cfg.exitCode == 0 && writeText(p("cfg.json"), cfg.out.toUtf8()));
        cfg = runCli({"footprint", "--print-config"});
        QVERIFY(cfg.exitCode == 0 && writeText(p("fcfg.json"), cfg.out.toUtf8()));
        if (!QFile::exists(p("sim.frd")))
            QVERIFY(runCli({"simulate", "slr", "--kind", "conventional", "--duration", "300", "--seed", "3", "-q", p("sim.frd")}).exitCode == 0);
        cfg = runCli({"slr", "--print-config"});
        QVERIFY(cfg.exitCode == 0 && writeText(p("scfg.json"), cfg.out.toUtf8()));
        QDir().mkpath(p("day"));
        QVERIFY(writeText(p("day/summary.csv"), cfg.out.toUtf8()));  // a config that happens to bear an output's name
        QVERIFY(writeText(p("presets.json"), "{\"format\": \"laserwb-slr-presets\", \"version\": 1, \"satellites\": "
                                             "[{\"name\": \"lageos1\", \"postfit\": {\"reject_sigma\": 3}}]}\n"));
        if (haveShared("slr/blits_201206.frd")) {
            for (const auto& [from, to] : {std::pair<QString, QString>{"slr/blits_201206.frd", "blits.frd"},
                                           {"slr/blits_cpf_120626_6801.hts", "blits.hts"},
                                           {"slr/SLRF2014_POS+VEL_2030.0_200428.snx", "stations.snx"}}) {
                QFile::remove(p(to));
                QVERIFY(QFile::copy(sharedPath(from), p(to)));
            }
        }
        const QByteArray before = readAll(p(input));
        QVERIFY(!before.isEmpty());
        // Relative spellings are relative to the folder: run there.
        const QString cwd = QDir::currentPath();
        QDir::setCurrent(m_dir.path());
        const CliRun r = runCli(expand(args), kTimeoutMs);
        QDir::setCurrent(cwd);
        QVERIFY2(r.exitCode == 2, qPrintable(QString::number(r.exitCode) + ": " + r.err));
        QVERIFY2(r.err.contains("would overwrite") && r.err.contains("input"), qPrintable(r.err));
        QVERIFY2(readAll(p(input)) == before, "the input was changed");
        noStagingFiles();
    }

    // Two outputs naming one file in different spellings: refused before anything is written.
    void twoOutputsOneFileRefused() {
        const QString slrIn = sharedPath("slr/7080_STELLA_crd_071220_2128_0.frd");
        if (!QFile::exists(slrIn)) QSKIP("shared SLR data absent");
        QFile::remove(p("same.csv"));
        const QString cwd = QDir::currentPath();
        QDir::setCurrent(m_dir.path());
        const CliRun r = runCli({"slr", slrIn, "-o", "same.csv", "--crd-out", "./same.csv"}, kTimeoutMs);
        QDir::setCurrent(cwd);
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("same file"), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("same.csv")));
    }

    // A device or a FIFO as an output is refused and left as it was.
    void specialFilesAreNotReplaced() {
        CliRun r = runCli({"trend", p("cent.csv"), "-o", "/dev/null"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("character device"), qPrintable(r.err));
        struct stat st {};
        QVERIFY(::stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode));
        QVERIFY(writeText(p("cent.csv"), "time,beam,x,y\n2020-03-01,1,120.8,263.7\n"));
        QFile::remove(p("fifo_out"));
        QVERIFY(::mkfifo(p("fifo_out").toLocal8Bit().constData(), 0600) == 0);
        r = runCli({"trend", p("cent.csv"), "-o", p("fifo_out")}, 20000);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("FIFO"), qPrintable(r.err));
        QVERIFY(::stat(p("fifo_out").toLocal8Bit().constData(), &st) == 0 && S_ISFIFO(st.st_mode));
        // A symbolic link as output: the file it names is replaced, the link stays a link.
        QFile::remove(p("real_out.csv"));
        QFile::remove(p("link_out.csv"));
        QVERIFY(writeText(p("real_out.csv"), "old"));
        QVERIFY(QFile::link(p("real_out.csv"), p("link_out.csv")));
        r = runCli({"trend", p("cent.csv"), "-o", p("link_out.csv"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFileInfo(p("link_out.csv")).isSymLink());
        QVERIFY(readAll(p("real_out.csv")).startsWith("camera,beam,month"));
    }

    // The core class itself: a missing folder, and commit restoring what it replaced.
    // A set of files in one folder commits as a unit (issue 27): killed (SIGKILL) half-way
    // through replacing an earlier run, the folder never holds a truth.csv that disagrees with its
    // shots; the next run removes what the killed one left and the earlier, larger run's extra shots.
    void killedMultiFileCommitLeavesNoMixedSet() {
        const QString dir = p("killset");
        QDir(dir).removeRecursively();
        QVERIFY(runCli({"simulate", "footprint", "--count", "12", "--seed", "1", "-q", dir}).exitCode == 0);
        // The set's invariant: truth.csv absent, or naming exactly the shots in the folder.
        auto consistent = [&](QString* why) {
            const QStringList shots = QDir(dir).entryList({"shot_*.png"}, QDir::Files, QDir::Name);
            if (!QFile::exists(dir + "/truth.csv")) return true;
            QStringList listed;
            for (const QByteArray& l : readAll(dir + "/truth.csv").split('\n').mid(1))
                if (!l.isEmpty()) listed << QString::fromUtf8(l.split(',').value(0));
            *why = QString("truth.csv lists %1 shots, the folder holds %2").arg(listed.size()).arg(shots.size());
            return listed == shots;
        };
        QString why;
        QVERIFY(consistent(&why));
        // Killed just before renaming a new shot, then just before the manifest.
        for (const QString& at : {QString("shot_000003.png"), QString("truth.csv")}) {
            const CliRun r = runCli({"simulate", "footprint", "--count", "6", "--seed", "2", "-q", dir}, kTimeoutMs,
                                    {"LWB_FAULT_OUTPUT=kill:" + at});
            QCOMPARE(r.exitCode, -2);  // killed
            QVERIFY2(consistent(&why), qPrintable(at + ": " + why));
            QVERIFY2(!QFile::exists(dir + "/truth.csv"), "the old manifest is gone while the set is being replaced");
            bool leftovers = false;
            for (const QString& f : filesIn(dir)) leftovers = leftovers || f.startsWith(".lwb-");
            QVERIFY2(leftovers, "a killed run leaves its staging files (the next run removes them)");
            // Committed as a set (issue 41): the next run writing into the folder first puts the
            // earlier set back from the killed commit's journal, whole (12 shots and their
            // truth.csv), even when that run fails itself (a full disk at its truth.csv).
            const CliRun again = runCli({"simulate", "footprint", "--count", "6", "--seed", "2", "-q", dir}, kTimeoutMs,
                                        {"LWB_FAULT_OUTPUT=write:truth.csv"});
            QVERIFY2(again.exitCode != 0, qPrintable(again.err));
            QVERIFY2(QFile::exists(dir + "/truth.csv"), qPrintable(at + ": the earlier set's truth.csv was not put back"));
            QVERIFY2(consistent(&why), qPrintable(at + ": " + why));
            QCOMPARE(QDir(dir).entryList({"shot_*.png"}, QDir::Files).size(), 12);
            for (const QString& f : filesIn(dir)) QVERIFY2(!f.startsWith(".lwb-"), qPrintable(at + ": " + f));
        }
        // The next run: a whole, consistent set of 6, no leftovers, the earlier run's shots 6..11 gone.
        QVERIFY(runCli({"simulate", "footprint", "--count", "6", "--seed", "2", "-q", dir}).exitCode == 0);
        QVERIFY2(consistent(&why), qPrintable(why));
        QCOMPARE(QDir(dir).entryList({"shot_*.png"}, QDir::Files).size(), 6);
        for (const QString& f : filesIn(dir)) QVERIFY2(!f.startsWith(".lwb-"), qPrintable(f));
        // Killed at moments spread over a whole run (real SIGKILL from outside, during writing or
        // committing). The moments are fractions of a timed full run, so that they fall inside the
        // run on any CPU. Only a process still running is signalled: QProcess::processId() is 0 once
        // the child has finished, and kill(0, SIGKILL) kills the caller's whole process group (ctest,
        // make, CI's shell: how CI died with exit 137, on a CPU fast enough to finish early).
        const QStringList args = {"simulate", "footprint", "--count", "400", "--seed", "3", "-q", dir};
        QElapsedTimer full;
        full.start();
        QVERIFY(runCli(args).exitCode == 0);
        const qint64 fullMs = std::max<qint64>(full.elapsed(), 20);
        QVERIFY2(consistent(&why), qPrintable(why));
        int killedMidway = 0;
        for (int k = 1; k <= 6; ++k) {
            QProcess run;
            run.start(QString(LWB_CLI), args);
            QVERIFY(run.waitForStarted());
            const qint64 pid = run.processId();
            QVERIFY(pid > 1);
            QTest::qWait(int(fullMs * k / 7));
            // No event processing between this check and kill(): Qt reaps the child only in its event
            // loop, so while state() is Running the pid is still this child's (alive or a zombie).
            if (run.state() == QProcess::Running) {
                QCOMPARE(::kill(pid_t(pid), SIGKILL), 0);
                ++killedMidway;
            }
            run.waitForFinished();
            QVERIFY2(consistent(&why), qPrintable(QString("killed after %1 ms of a %2 ms run: ").arg(fullMs * k / 7).arg(fullMs) + why));
        }
        // Most moments fall inside the run (a run slower than the timed one only helps).
        QVERIFY2(killedMidway >= 3, qPrintable(QString("only %1 of 6 runs were still running when killed").arg(killedMidway)));
        QVERIFY(runCli({"simulate", "footprint", "--count", "5", "--seed", "4", "-q", dir}).exitCode == 0);
        QVERIFY2(consistent(&why), qPrintable(why));
        QCOMPARE(QDir(dir).entryList({"shot_*.png"}, QDir::Files).size(), 5);
        for (const QString& f : filesIn(dir)) QVERIFY2(!f.startsWith(".lwb-"), qPrintable(f));
    }

    // Two runs writing a set into one folder at once (issue 41: their shots and truth mixed): the
    // second is refused while the first holds the folder (flock), and the first's set is whole.
    // The first run is long (kConcurrentShots) so that it is still writing when the second comes;
    // the second's message saying so is the proof that it was.
    void concurrentSetsIntoOneFolderRefused() {
        const QString dir = p("lockset");
        QDir(dir).removeRecursively();
        const int kConcurrentShots = 6000;
        QProcess first;
        first.start(QString(LWB_CLI),
                    {"simulate", "footprint", "--count", QString::number(kConcurrentShots), "--seed", "5", "-q", dir});
        QVERIFY(first.waitForStarted());
        QElapsedTimer t;
        t.start();
        bool writing = false;  // its staging files appear once its outputs are checked (and the folder locked)
        while (!writing && t.elapsed() < 60000) {
            for (const QString& f : filesIn(dir)) writing = writing || f.startsWith(".lwb-stage-");
            if (!writing) QTest::qWait(10);
        }
        QVERIFY2(writing, "the first run never started writing");
        const CliRun second = runCli({"simulate", "footprint", "--count", "4", "--seed", "6", "-q", dir});
        QVERIFY(first.waitForFinished(300000));
        QCOMPARE(first.exitCode(), 0);
        QVERIFY2(second.exitCode != 0 && second.err.contains("another run is writing its files into this folder"),
                 qPrintable(QString::number(second.exitCode) + ": " + second.err));
        QStringList listed;
        for (const QByteArray& l : readAll(dir + "/truth.csv").split('\n').mid(1))
            if (!l.isEmpty()) listed << QString::fromUtf8(l.split(',').value(0));
        QCOMPARE(listed.size(), kConcurrentShots);
        QCOMPARE(QDir(dir).entryList({"shot_*.png"}, QDir::Files, QDir::Name), listed);
        // Once the first has ended, the folder is free again.
        QCOMPARE(runCli({"simulate", "footprint", "--count", "4", "--seed", "6", "-q", dir}).exitCode, 0);
        QCOMPARE(QDir(dir).entryList({"shot_*.png"}, QDir::Files).size(), 4);
        QDir(dir).removeRecursively();
    }

    // --all-passes into a folder of an earlier run: the earlier pass files go, summary.csv is the
    // manifest; a file of the folder that is not an output of the kind stays.
    void allPassesReplacesTheWholeSet() {
        const QString frd = p("three.frd"), dir = p("passes");
        QDir(dir).removeRecursively();
        QVERIFY(QDir().mkpath(dir));
        // Three passes in one file: the simulator's pass three times (each a valid pass).
        const CliRun sim = runCli({"simulate", "slr", "--kind", "conventional", "--duration", "200", "--seed", "6", "-q", p("one.frd")});
        QVERIFY(sim.exitCode == 0);
        const QByteArray one = readAll(p("one.frd"));
        QVERIFY(writeText(frd, one + one + one));
        QVERIFY(writeText(dir + "/pass009.csv", "from an earlier run\n"));
        QVERIFY(writeText(dir + "/notes.txt", "the analyst's notes\n"));
        const CliRun r = runCli({"slr", frd, "--all-passes", "--out-dir", dir, "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(QFile::exists(dir + "/pass001.csv") && QFile::exists(dir + "/pass003.csv") && QFile::exists(dir + "/summary.csv"));
        QVERIFY2(!QFile::exists(dir + "/pass009.csv"), "an earlier run's pass file was left beside the new summary");
        QCOMPARE(readAll(dir + "/notes.txt"), QByteArray("the analyst's notes\n"));
    }

    // Leftovers of a killed run are removed only when their process is gone.
    void leftoversOfLiveProcessesStay() {
        const QString dir = p("left");
        QDir(dir).removeRecursively();
        QVERIFY(QDir().mkpath(dir));
        const QString mine = QString(".lwb-stage-%1-1-x.csv").arg(::getpid());
        QVERIFY(writeText(dir + "/" + mine, "a live run's staging file"));
        QVERIFY(writeText(dir + "/.lwb-tmp-999999999-ab-y.csv", "a dead run's"));
        QVERIFY(writeText(dir + "/.lwb-backupx", "not ours: no pid"));
        QCOMPARE(lwb::core::removeLeftovers(dir.toStdString()), 1);
        QVERIFY(QFile::exists(dir + "/" + mine));
        QVERIFY(QFile::exists(dir + "/.lwb-backupx"));
        QVERIFY(!QFile::exists(dir + "/.lwb-tmp-999999999-ab-y.csv"));
    }

    void outputSetUnit() {
        lwb::core::OutputSet none;
        none.addOutput(p("no/such/folder/x.csv").toStdString());
        QVERIFY(!none.check());
        QVERIFY2(QString::fromStdString(none.error()).contains("does not exist"), none.error().c_str());
        QVERIFY(!none.namingProblem());

        QVERIFY(writeText(p("a.txt"), "A-old"));
        QFile::remove(p("b.txt"));
        {
            lwb::core::OutputSet s;
            s.addOutput(p("a.txt").toStdString());
            s.addOutput(p("b.txt").toStdString());
            QVERIFY2(s.check(), s.error().c_str());
            QVERIFY(writeText(QString::fromStdString(s.stagingPath(p("a.txt").toStdString())), "A-new"));
            QVERIFY(writeText(QString::fromStdString(s.stagingPath(p("b.txt").toStdString())), "B-new"));
            qputenv("LWB_FAULT_OUTPUT", "rename:b.txt");
            const bool ok = s.commit();
            qunsetenv("LWB_FAULT_OUTPUT");
            QVERIFY(!ok);
        }
        QCOMPARE(readAll(p("a.txt")), QByteArray("A-old"));  // put back
        QVERIFY(!QFile::exists(p("b.txt")));
        noStagingFiles();
        {
            lwb::core::OutputSet s;
            s.addOutput(p("a.txt").toStdString());
            QVERIFY(s.check());
            QVERIFY(writeText(QString::fromStdString(s.stagingPath(p("a.txt").toStdString())), "A-new"));
            // Abandoned (destroyed without commit): the target is untouched.
        }
        QCOMPARE(readAll(p("a.txt")), QByteArray("A-old"));
        noStagingFiles();
    }
};

QTEST_GUILESS_MAIN(TestCliOutputs)
#include "test_cli_outputs.moc"
