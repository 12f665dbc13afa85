// laserwb: the workbench. With no arguments it opens the built-in demo.
//   laserwb [FILE...]   a session, or inputs opened where they belong (MainWindow::openPaths)
//   laserwb --screenshot OUT.png [--workspace footprint|slr] [--size WxH|screen] [--language en|zh_CN] [FILE...]
#include <cstdio>

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QSettings>
#include <QThreadPool>
#include <QTimer>

#include "core/common/allocator.hpp"
#include "core/common/image_codecs.hpp"
#include "core/common/output_set.hpp"
#include "lwb_version.hpp"
#include "ui/kit/frame_loader.hpp"
#include "ui/kit/i18n.hpp"
#include "ui/shell/main_window.hpp"

int main(int argc, char** argv) {
    lwb::core::reexecWithHugePages(argv);
    lwb::core::tuneAllocator();
    lwb::core::useOneArena();
    // --screenshot renders without a display, and --help / --version need none.
    bool offscreen = false;
    for (int i = 1; i < argc; ++i) {
        const QByteArray a(argv[i]);
        offscreen |= a == "--screenshot" || a == "--help" || a == "-h" || a == "--help-all" || a == "-?" ||
                     a == "--version" || a == "-v";
    }
    if (offscreen && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    // Without a display Qt would abort (exit 134); say what to do instead.
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY") &&
        qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY")) {
        fprintf(stderr,
                "laserwb: no display (neither DISPLAY nor WAYLAND_DISPLAY is set). Run it in a desktop session,\n"
                "use 'laserwb --screenshot OUT.png' to render the window offscreen, or laserwb-cli for batch work.\n");
        return 1;
    }
    QApplication app(argc, argv);
    QApplication::setApplicationName("laserwb");
    QApplication::setOrganizationName("LaserWorkbench");
    QApplication::setApplicationVersion(LWB_VERSION);
    QGuiApplication::setDesktopFileName("io.github.laserwb.LaserWorkbench");  // resources/desktop/
    QCommandLineParser cli;
    cli.setApplicationDescription("Laser Workbench: footprint spot review, SLR pass screening, calibration.");
    cli.addHelpOption();
    cli.addVersionOption();
    cli.addPositionalArgument("FILE",
                              "What to open, each where it belongs: a session (.json); a CRD pass (.frd .fr2 .crd, "
                              "gzip too) or an O-C table with its CPF prediction and SINEX station file (SLR); "
                              "footprint images, a folder of frames or a shot list (footprint). None: the built-in demo.",
                              "[FILE...]");
    QCommandLineOption shot("screenshot", "Render the window to OUT.png and exit.", "OUT.png");
    QCommandLineOption ws("workspace",
                          "Workspace (and tab) to show: footprint, footprint:trend, slr, calibration, "
                          "calibration:waveform, radiometry.",
                          "name",
                          "footprint");
    QCommandLineOption size("size",
                            "Window size for --screenshot, WxH, or 'screen': the size the window first opens at on "
                            "this screen (fitted to its available area).",
                            "WxH|screen", "1480x900");
    QCommandLineOption lang("language",
                            "Interface language for this run: en, zh_CN, or system (the locale's). Without it, "
                            "the choice of View > Language (the system's at first).",
                            "en|zh_CN|system");
    cli.addOptions({shot, ws, size, lang});
    cli.process(app);
    // Before the window: every widget takes its text when it is made.
    if (cli.isSet(lang)) {
        const QString l = cli.value(lang);
        if (l != "en" && l != "system" && !lwb::ui::translatedLanguages().contains(l)) {
            fprintf(stderr, "laserwb: --language %s: give en, %s or system\n", qPrintable(l),
                    qPrintable(lwb::ui::translatedLanguages().join(", ")));
            return 2;
        }
        lwb::ui::installLanguage(l == "system" ? QString() : l);
    } else {
        lwb::ui::installLanguage(QSettings().value(lwb::ui::kLanguageSetting).toString());
    }

    // The screenshot is an output like any other (core/common/output_set.hpp): checked before
    // anything is opened (not a folder, device or one of the files given), written to a staging
    // file and renamed into place, so a full disk or a crash never leaves a half PNG, and no input
    // read on the way (a session's pass, its CPF) is ever replaced.
    const QStringList args = cli.positionalArguments();
    lwb::core::OutputSet outs;
    const std::string shotPath = cli.value(shot).toStdString();
    if (cli.isSet(shot)) {
        outs.addOutput(shotPath);
        for (const QString& a : args) outs.addInput(a.toStdString());
        if (!outs.check()) {
            fprintf(stderr, "laserwb: --screenshot %s\n", outs.error().c_str());
            return outs.namingProblem() ? 2 : 1;
        }
    }
    // One shutdown path: no worker thread may outlive main (a footprint loader still inside the
    // codec module's dlopen while the exit handlers ran aborted 2-4 runs in 20 of a refused
    // session). The codec module is loaded here, once, before any pool starts (its libraries'
    // constructors never run beside exit handlers), and on every return — refusal, error,
    // screenshot, quit — the window's jobs are cancelled (its destructor, first) and both pools
    // are waited for (this object's destructor, after the window's).
    (void)lwb::core::codecs::codecModule();
    struct JoinPools {
        ~JoinPools() {
            lwb::ui::loaderPool()->waitForDone();
            QThreadPool::globalInstance()->waitForDone();
        }
    } joinPools;
    lwb::ui::MainWindow w;
    if (args.isEmpty()) {
        w.openDemo();
    } else if (cli.isSet(shot)) {
        QString err;
        if (!w.openPaths(args, &err)) {
            fprintf(stderr, "laserwb: %s\n", qPrintable(err));
            return 1;
        }
    } else {
        // In a window: shown first, so that a file that cannot be opened is reported over it.
        QTimer::singleShot(0, &w, [&w, args] { w.openPaths(args); });
    }
    if (cli.isSet(ws) || args.isEmpty()) w.showWorkspace(cli.value(ws));  // a session names its own workspace
    if (cli.isSet(shot)) {
        const QStringList wh = cli.value(size).split('x');
        if (cli.value(size) == "screen") {
            // (as constructed: fitted to the screen)
        } else if (wh.size() == 2 && wh[0].toInt() > 0 && wh[1].toInt() > 0) {
            w.resize(wh[0].toInt(), wh[1].toInt());
        } else {
            fprintf(stderr, "laserwb: --size %s: give WIDTHxHEIGHT (e.g. 1280x800) or 'screen'\n", qPrintable(cli.value(size)));
            return 2;
        }
        w.show();
        w.waitIdle(60000);
        const QString staged = QString::fromStdString(outs.stagingPath(shotPath));
        const QByteArray format = QFileInfo(cli.value(shot)).suffix().toLower().toLatin1();
        if (!w.grab().save(staged, format.isEmpty() ? "png" : format.constData())) {
            fprintf(stderr, "laserwb: cannot write %s (nothing written)\n", shotPath.c_str());
            outs.abandon();
            return 1;
        }
        if (!outs.commit()) {
            fprintf(stderr, "laserwb: %s\n", outs.error().c_str());
            return outs.namingProblem() ? 2 : 1;
        }
        return 0;
    }
    w.show();
    return app.exec();
}
