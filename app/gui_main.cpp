// laserwb: the workbench. With no arguments it opens the built-in demo.
//   laserwb [FILE...]   a session, or inputs opened where they belong (MainWindow::openPaths)
//   laserwb --screenshot OUT.png [--workspace footprint|slr] [--size WxH] [FILE...]
#include <cstdio>

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QTimer>

#include "core/common/allocator.hpp"
#include "lwb_version.hpp"
#include "ui/main_window.hpp"

int main(int argc, char** argv) {
    lwb::core::tuneAllocator();
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
    QCommandLineOption size("size", "Window size for --screenshot, WxH.", "WxH", "1480x900");
    cli.addOptions({shot, ws, size});
    cli.process(app);

    lwb::ui::MainWindow w;
    const QStringList args = cli.positionalArguments();
    if (args.isEmpty()) {
        w.openDemo();
    } else {
        QString err;
        if (!w.openPaths(args, &err) && cli.isSet(shot)) {
            fprintf(stderr, "laserwb: %s\n", qPrintable(err));
            return 1;
        }
    }
    if (cli.isSet(ws) || args.isEmpty()) w.showWorkspace(cli.value(ws));  // a session names its own workspace
    if (cli.isSet(shot)) {
        const QStringList wh = cli.value(size).split('x');
        if (wh.size() == 2) w.resize(wh[0].toInt(), wh[1].toInt());
        w.show();
        w.waitIdle(60000);
        const QString out = cli.value(shot);
        if (!w.grab().save(out)) {
            fprintf(stderr, "laserwb: cannot write %s\n", qPrintable(out));
            return 1;
        }
        return 0;
    }
    w.show();
    return app.exec();
}
