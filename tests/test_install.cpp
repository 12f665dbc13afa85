// The workbench installs like a real program (issue 26): `cmake --install build --prefix P` into
// a temporary prefix, then the installed programs run from there, with the build tree out of
// reach (moved aside is not possible while the suite runs, so the checks make sure the
// installed helpers, codec module and photographs are the ones used), and `cpack -G DEB`
// makes a package holding the same files.
#include <QtTest>

#include "lwb_version.hpp"
#include "test_support.hpp"

using namespace lwbtest;

namespace {

using Run = CliRun;

Run run(const QString& program, const QStringList& args, const QStringList& env = {}, const QString& cwd = {},
        int timeoutMs = 300000) {
    RunOptions o;
    o.env = env;
    o.cwd = cwd;
    o.timeoutMs = timeoutMs;
    return runProgram(program, args, o);
}

// Every command of laserwb-cli, as it is typed.
const QList<QStringList> kCommands{{"footprint"},           {"trend"},          {"slr"},
                                   {"simulate", "footprint"}, {"simulate", "trend"}, {"simulate", "slr"},
                                   {"simulate", "calib"},     {"simulate", "radiometry"}, {"eval", "footprint"},
                                   {"bench", "footprint"},    {"bench", "slr"},   {"calib", "detector"},
                                   {"calib", "waveform"},     {"calib", "pointing"}, {"calib", "stats"},
                                   {"radiometry", "mosaic"},  {"radiometry", "gcp"}, {"radiometry", "fit"},
                                   {"radiometry", "apply"},   {"radiometry", "check"}, {"demo"}};

}  // namespace

class TestInstall : public QObject {
    Q_OBJECT
    QTemporaryDir m_tmp;
    QString m_prefix;

    QString cli() const { return m_prefix + "/bin/laserwb-cli"; }

private slots:
    void initTestCase() {
        QVERIFY(m_tmp.isValid());
        m_prefix = m_tmp.path() + "/prefix";
        const Run r = run(QStringLiteral(LWB_CMAKE_COMMAND), {"--install", QStringLiteral(LWB_BUILD_DIR), "--prefix", m_prefix});
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
    }

    void installsTheFilesOfAProgram() {
        const QStringList expected{"bin/laserwb-cli",
                                   "libexec/laserwb/laserwb-cli-imaging",
                                   "libexec/laserwb/liblaserwb_codecs.so",
                                   "share/man/man1/laserwb-cli.1.gz",
                                   "share/man/man1/laserwb-cli-slr.1.gz",
                                   "share/man/man1/laserwb-cli-footprint.1.gz",
                                   "share/man/man1/laserwb-cli-radiometry-gcp.1.gz",
                                   "share/bash-completion/completions/laserwb-cli",
                                   "share/bash-completion/completions/laserwb",
                                   "share/applications/io.github.laserwb.LaserWorkbench.desktop",
                                   "share/icons/hicolor/scalable/apps/laserwb.svg",
                                   "share/metainfo/io.github.laserwb.LaserWorkbench.metainfo.xml",
                                   "share/laserwb/terrain/aero1.jpg",
                                   "share/laserwb/terrain/aero3.jpg",
                                   "share/laserwb/terrain/README.md",
                                   "share/doc/laserwb/LICENSE",
                                   "share/doc/laserwb/README.md",
                                   "share/doc/laserwb/CITATION.cff",
                                   "share/doc/laserwb/docs/algorithms.md",
                                   "share/doc/laserwb/examples/slr.py",  // (issue 46: examples/ was not installed)
                                   "share/doc/laserwb/examples/_inputs.py",
                                   "share/doc/laserwb/examples/slr.ipynb",
                                   "share/mime/packages/laserwb.xml"};
        for (const QString& f : expected) QVERIFY2(QFile::exists(m_prefix + "/" + f), qPrintable(f + " not installed"));
#ifdef LWB_GUI
        QVERIFY(QFile::exists(m_prefix + "/bin/laserwb"));
        QVERIFY(QFile::exists(m_prefix + "/share/man/man1/laserwb.1.gz"));
#endif
        // Not installed: the build tree's benches and tests.
        QVERIFY(!QFile::exists(m_prefix + "/bin/laserwb-uibench"));
        QVERIFY(!QFile::exists(m_prefix + "/bin/laserwb-cli-imaging"));
    }

    void versionAndEveryHelpRunFromThePrefix() {
        Run r = run(cli(), {"version"});
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out.trimmed(), QString("laserwb-cli " LWB_VERSION));
        r = run(cli(), {"--help"});
        QCOMPARE(r.exitCode, 0);
        for (const QStringList& c : kCommands) {
            // Each command's help, from the installed programs (the imaging ones through the
            // installed helper in libexec/laserwb/), promptly: --help must not run the command.
            QElapsedTimer t;
            t.start();
            r = run(cli(), c + QStringList{"--help"}, {}, {}, 20000);
            QVERIFY2(r.exitCode == 0, qPrintable(c.join(' ') + " --help: exit " + QString::number(r.exitCode) + "\n" + r.err));
            QVERIFY2(r.out.startsWith("usage: laserwb-cli " + c.join(' ')), qPrintable(c.join(' ') + ": " + r.out.left(200)));
            QVERIFY2(t.elapsed() < 10000, qPrintable(c.join(' ') + " --help took " + QString::number(t.elapsed()) + " ms"));
        }
    }

    void installedProgramsUseInstalledFiles() {
        // The footprint simulator reads the installed photographs and decodes through the
        // installed codec module: LD_DEBUG names the libraries loaded, and the truth file names
        // the photograph each ground came from.
        QTemporaryDir work;
        Run r = run(cli(), {"simulate", "footprint", "--count", "2", "--seed", "1", "-q", work.path() + "/shots"},
                    {"LD_DEBUG=files", "LD_DEBUG_OUTPUT=" + work.path() + "/ld"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QString loaded;
        for (const QString& f : QDir(work.path()).entryList({"ld.*"}, QDir::Files)) loaded += readAll(work.path() + "/" + f);
        QVERIFY2(loaded.contains(m_prefix + "/bin/../libexec/laserwb/liblaserwb_codecs.so") ||
                     loaded.contains(m_prefix + "/libexec/laserwb/liblaserwb_codecs.so"),
                 "the installed codec module was not the one loaded");
        QVERIFY(!loaded.contains(QStringLiteral(LWB_BUILD_DIR "/bin/liblaserwb_codecs.so")));
        const QString truth = QString::fromUtf8(readAll(work.path() + "/shots/truth.csv"));
        QVERIFY2(truth.contains("aero"), qPrintable(truth));
        // A run end to end from the prefix: the report of the two shots.
        r = run(cli(), {"footprint", work.path() + "/shots", "-o", work.path() + "/report.csv", "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(readAll(work.path() + "/report.csv").count('\n'), 3);
    }

#ifdef LWB_PYTHON
    void pythonModuleImportsFromThePrefix() {
        // The installed package, with the build tree's out of PYTHONPATH: imported from the
        // prefix, reads frames through the installed codec module (LD_DEBUG), and writes the
        // installed CLI's report byte for byte.
        QTemporaryDir work;
        const QString site = m_prefix + "/" LWB_PYTHON_INSTALL_DIR;
        QVERIFY2(QFile::exists(site + "/laserwb/__init__.py"), qPrintable(site));
        Run r = run(cli(), {"simulate", "footprint", "--count", "3", "--seed", "2", "-q", work.path() + "/shots"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        r = run(cli(), {"footprint", work.path() + "/shots", "-o", work.path() + "/cli.csv", "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QString script =
            "import sys, laserwb\n"
            "print(laserwb.__file__)\n"
            "rep = laserwb.footprint.fit_batch(sys.argv[1])\n"
            "rep.write_csv(sys.argv[2])\n"
            "p = laserwb.slr.SlrParams()\n"
            "try:\n"
            "    p['screen.cosine_c'] = 2\n"
            "except ValueError as e:\n"
            "    print('refused:', e)\n";
        r = run(QStringLiteral(LWB_PYTHON), {"-c", script, work.path() + "/shots", work.path() + "/py.csv"},
                {"PYTHONPATH=" + site, "LD_DEBUG=files", "LD_DEBUG_OUTPUT=" + work.path() + "/ld"}, work.path());
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.startsWith(site + "/laserwb/__init__.py"), qPrintable(r.out));
        QVERIFY2(r.out.contains("refused: slr.screen.cosine_c = 2: must be in [0.5, 1)"), qPrintable(r.out));
        QString loaded;
        for (const QString& f : QDir(work.path()).entryList({"ld.*"}, QDir::Files)) loaded += readAll(work.path() + "/" + f);
        QVERIFY2(loaded.contains("/libexec/laserwb/liblaserwb_codecs.so"), "the installed codec module was not loaded");
        QVERIFY(!loaded.contains(QStringLiteral(LWB_BUILD_DIR "/bin/liblaserwb_codecs.so")));
        QVERIFY(!loaded.contains(QStringLiteral(LWB_BUILD_DIR "/python/")));
        QCOMPARE(readAll(work.path() + "/py.csv"), readAll(work.path() + "/cli.csv"));
        QCOMPARE(readAll(work.path() + "/py.csv").count('\n'), 4);
    }
#endif

    void manPagesAndDesktopFilesAreValid() {
        // A man page renders (man -l), with its name and the command's options.
        Run r = run("sh", {"-c", "zcat '" + m_prefix + "/share/man/man1/laserwb-cli-slr.1.gz'"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(".TH LASERWB-CLI-SLR"));
        QVERIFY(r.out.contains("all\\-passes") || r.out.contains("all-passes"));
        QVERIFY(r.out.contains(LWB_VERSION));
        // Issue 46: EXAMPLES (the README's), FILES, and the whole exit-status table (4 was missing).
        for (const char* section : {".SH EXAMPLES", ".SH FILES", ".SH \"EXIT STATUS\"", ".SH \"SEE ALSO\""})
            QVERIFY2(r.out.contains(section), section);
        QVERIFY(r.out.contains("laserwb\\-cli slr pass.frd") || r.out.contains("laserwb-cli slr pass.frd"));
        QVERIFY2(r.out.contains(".B 4\n"), "exit status 4 not in the page");
        // The ILRS types by name and by their H1 record, in a MIME database of their own; the desktop
        // entry claims those, not every PNG, TIFF and JSON file.
        if (!QStandardPaths::findExecutable("update-mime-database").isEmpty()) {
            QDir().mkpath(m_tmp.path() + "/mime/packages");
            QVERIFY(QFile::copy(m_prefix + "/share/mime/packages/laserwb.xml", m_tmp.path() + "/mime/packages/laserwb.xml"));
            r = run("update-mime-database", {m_tmp.path() + "/mime"});
            QVERIFY2(r.exitCode == 0 && !r.err.contains("rror"), qPrintable(r.out + r.err));
            const QString globs = QString::fromUtf8(readAll(m_tmp.path() + "/mime/globs2"));
            for (const char* g : {"application/x-ilrs-crd:*.frd", "application/x-ilrs-crd:*.npt", "application/x-ilrs-cpf:*.cpf",
                                  "application/x-laserwb-session:*.lwb.json"})
                QVERIFY2(globs.contains(g), g);
            QVERIFY(readAll(m_tmp.path() + "/mime/magic").contains("H1 CRD"));
        }
        const QString entry = QString::fromUtf8(readAll(m_prefix + "/share/applications/io.github.laserwb.LaserWorkbench.desktop"));
        QVERIFY(entry.contains("application/x-ilrs-crd;") && entry.contains("application/x-ilrs-cpf;"));
        QVERIFY(!entry.contains("image/png") && !entry.contains("application/json;"));
        if (!QStandardPaths::findExecutable("desktop-file-validate").isEmpty()) {
            r = run("desktop-file-validate", {m_prefix + "/share/applications/io.github.laserwb.LaserWorkbench.desktop"});
            QVERIFY2(r.exitCode == 0 && r.out.trimmed().isEmpty(), qPrintable(r.out + r.err));
        } else {
            qWarning("desktop-file-validate not installed (Debian desktop-file-utils): desktop entry not validated");
        }
        if (!QStandardPaths::findExecutable("appstreamcli").isEmpty()) {
            r = run("appstreamcli", {"validate", "--no-net", "--explain", m_prefix + "/share/metainfo/io.github.laserwb.LaserWorkbench.metainfo.xml"});
            QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        } else {
            qWarning("appstreamcli not installed (Debian appstream): metainfo not validated");
        }
        const QString meta = QString::fromUtf8(readAll(m_prefix + "/share/metainfo/io.github.laserwb.LaserWorkbench.metainfo.xml"));
        QVERIFY(meta.contains("<release version=\"" LWB_VERSION "\""));
        // The completion script loads and completes a command's options from its --help.
        r = run("bash", {"-c", "source '" + m_prefix + "/share/bash-completion/completions/laserwb-cli'; "
                         "COMP_WORDS=(laserwb-cli slr --all); COMP_CWORD=2; _laserwb_cli; echo \"${COMPREPLY[*]}\""},
                {"PATH=" + m_prefix + "/bin:" + qEnvironmentVariable("PATH")});
        QVERIFY2(r.exitCode == 0 && r.out.contains("--all-passes"), qPrintable(r.out + r.err));
        // Issue 46: an option's values from its --help line (--connectivity and footprint --preset
        // completed file names); an option that takes a file still completes file names.
        const QList<QPair<QString, QString>> choices{{"slr x.frd --connectivity ''", "4 8"},
                                                      {"footprint --preset ''", "wu2021 yao2021"},
                                                      {"footprint --method t", "tefm"},
                                                      {"simulate slr --kind d", "diffuse daylight dayspad"}};
        for (const auto& [words, want] : choices) {
            r = run("bash", {"-c", "source '" + m_prefix + "/share/bash-completion/completions/laserwb-cli'; "
                             "COMP_WORDS=(laserwb-cli " + words + "); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _laserwb_cli; "
                             "echo \"${COMPREPLY[*]}\""},
                    {"PATH=" + m_prefix + "/bin:" + qEnvironmentVariable("PATH")});
            QVERIFY2(r.exitCode == 0 && r.out.trimmed() == want, qPrintable(words + ": " + r.out + r.err));
        }
    }

#ifdef LWB_GUI
    void workbenchRendersFromThePrefix() {
        QTemporaryDir work;
        const QString png = work.path() + "/w.png";
        const Run r = run(m_prefix + "/bin/laserwb", {"--screenshot", png, "--size", "1024x700"}, {"QT_QPA_PLATFORM=offscreen"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        // A PNG of the window's size (IHDR: width and height, big-endian, at bytes 16 and 20).
        const QByteArray b = readAll(png);
        QVERIFY(b.startsWith("\x89PNG\r\n\x1a\n") && b.size() > 24);
        auto be32 = [&](int at) {
            return (uint(uchar(b[at])) << 24) | (uint(uchar(b[at + 1])) << 16) | (uint(uchar(b[at + 2])) << 8) | uint(uchar(b[at + 3]));
        };
        QCOMPARE(be32(16), 1024u);
        QCOMPARE(be32(20), 700u);
        const Run v = run(m_prefix + "/bin/laserwb", {"--version"});
        QVERIFY2(v.out.contains(LWB_VERSION), qPrintable(v.out));
    }
#endif

    void debianPackageHoldsTheInstallation() {
        if (QStandardPaths::findExecutable("dpkg-deb").isEmpty()) QSKIP("dpkg-deb not available");
        // cpack in a copy of nothing: it installs into its own staging folder under the build tree.
        const Run r = run(QStringLiteral(LWB_CPACK_COMMAND), {"-G", "DEB", "-B", m_tmp.path() + "/pkg"}, {},
                          QStringLiteral(LWB_BUILD_DIR), 600000);
        QVERIFY2(r.exitCode == 0, qPrintable(r.out + r.err));
        const QStringList debs = QDir(m_tmp.path() + "/pkg").entryList({"laserwb_*.deb"});
        QCOMPARE(debs.size(), 1);
        QVERIFY2(debs[0].startsWith("laserwb_" LWB_VERSION "_"), qPrintable(debs[0]));
        const QString deb = m_tmp.path() + "/pkg/" + debs[0];
        const Run c = run("dpkg-deb", {"-c", deb});
        QCOMPARE(c.exitCode, 0);
        for (const char* f : {"./usr/bin/laserwb-cli", "./usr/libexec/laserwb/liblaserwb_codecs.so",
                                 "./usr/share/man/man1/laserwb-cli-slr.1.gz", "./usr/share/applications/io.github.laserwb.LaserWorkbench.desktop",
                                 "./usr/share/laserwb/terrain/aero1.jpg"})
            QVERIFY2(c.out.contains(f), qPrintable(QString(f) + " not in the package:\n" + c.out));
#ifdef LWB_PYTHON
        QVERIFY2(c.out.contains("./usr/" LWB_PYTHON_INSTALL_DIR "/laserwb/__init__.py"), qPrintable(c.out));
#endif
        const Run info = run("dpkg-deb", {"-f", deb, "Version", "Depends", "Section", "Suggests"});
        QVERIFY2(info.out.contains("Version: " LWB_VERSION), qPrintable(info.out));
        QVERIFY2(info.out.contains("libqt6") && info.out.contains("libopencv") && info.out.contains("libgdal"),
                 qPrintable(info.out));
        QVERIFY2(c.out.contains("./usr/share/mime/packages/laserwb.xml"), qPrintable(c.out));
#ifdef LWB_PYTHON
        // Issue 46: `import laserwb` failed after `apt install` (Depends came from the libraries alone):
        // the module's Python minor version, its numpy, and Dask as a suggestion.
        const Run ver = run(LWB_PYTHON, {"-c", "import sys; print('%d.%d %d.%d' % (sys.version_info[0], sys.version_info[1], "
                                                "sys.version_info[0], sys.version_info[1] + 1))"});
        const QStringList mm = ver.out.trimmed().split(' ');
        QCOMPARE(mm.size(), 2);
        for (const QString& want : {"python3 (>= " + mm[0] + ")", "python3 (<< " + mm[1] + ")", QString("python3-numpy"),
                                    QString("Suggests: python3-distributed")})
            QVERIFY2(info.out.contains(want), qPrintable(want + " not in:\n" + info.out));
#endif
        qInfo("%s", qPrintable(c.out));
    }
};

QTEST_GUILESS_MAIN(TestInstall)
#include "test_install.moc"
