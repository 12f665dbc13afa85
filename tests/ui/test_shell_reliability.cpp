// Hostile session files and a missing display (issue 8, GUI part): each case once crashed,
// aborted, or was accepted as if fine.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QtTest>

#include "lwb_version.hpp"
#include "test_support.hpp"
#include "ui/footprint_controller.hpp"
#include "ui/footprint_workspace.hpp"
#include "ui/main_window.hpp"
#include "ui/radiometry_controller.hpp"
#include "ui/radiometry_workspace.hpp"
#include "ui/slr_controller.hpp"
#include "ui/slr_workspace.hpp"

using namespace lwb::ui;

class TestShellReliability : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    struct GuiRun {
        int exitCode = -1;
        bool crashed = false;
        QString out, err;
    };
    // The workbench executable with no display at all (DISPLAY, WAYLAND_DISPLAY and
    // QT_QPA_PLATFORM removed), as on a server or in CI.
    GuiRun runGuiWithoutDisplay(const QStringList& args) {
        QProcess p;
        QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
        for (const char* v : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"}) e.remove(v);
        p.setProcessEnvironment(e);
        p.start(QString(LWB_GUI), args);
        GuiRun r;
        if (!p.waitForFinished(60000)) {
            p.kill();
            p.waitForFinished();
            return r;
        }
        r.crashed = p.exitStatus() != QProcess::NormalExit;
        r.exitCode = p.exitCode();
        r.out = QString::fromUtf8(p.readAllStandardOutput());
        r.err = QString::fromUtf8(p.readAllStandardError());
        return r;
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
    }

    // "version": 1e300 once passed the check (toInt() gives 0 for it).
    void sessionVersionMustBeAWholeNumberThisProgramReads_data() {
        QTest::addColumn<QByteArray>("version");
        QTest::addColumn<QString>("message");
        QTest::newRow("1e300") << QByteArray("1e300") << "must be a whole number";
        QTest::newRow("1.5") << QByteArray("1.5") << "must be a whole number";
        QTest::newRow("0") << QByteArray("0") << "must be a whole number";
        QTest::newRow("string") << QByteArray("\"1\"") << "must be a whole number";
        QTest::newRow("missing") << QByteArray() << "must be a whole number";
        QTest::newRow("newer") << QByteArray("99") << "newer than this program reads";
    }
    void sessionVersionMustBeAWholeNumberThisProgramReads() {
        QFETCH(QByteArray, version);
        QFETCH(QString, message);
        MainWindow w;
        w.openDemo();
        FootprintController* c = w.footprint()->controller();
        QVERIFY(c->waitIdle(30000));
        const int before = c->count();
        const QString path = m_dir.path() + "/v.lwb.json";
        QByteArray text = "{\"format\": \"laserwb-session\"";
        if (!version.isEmpty()) text += ", \"version\": " + version;
        text += ", \"footprint\": {}}\n";
        QVERIFY(lwbtest::writeText(path, text));
        QString err;
        QVERIFY(!w.openSession(path, true, &err));
        QVERIFY2(err.contains(message), qPrintable(err));
        QCOMPARE(c->count(), before);
    }

    // A region rectangle of 2147483647 overflowed a signed int building a QRect.
    void hugeRegionRectangleIsRefused() {
        RadiometryWorkspace r;
        RadiometryController* c = r.controller();
        r.openDemo();
        QVERIFY(c->waitIdle(60000));
        const QJsonObject state = QJsonDocument::fromJson(QJsonDocument(r.saveState()).toJson()).object();
        const size_t regionsBefore = c->regions().size();
        for (const QJsonArray& rect : {QJsonArray{2147483647, 0, 10, 10}, QJsonArray{0, 0, 2147483647, 2147483647},
                                       QJsonArray{10, 10, 1.5, 4}, QJsonArray{-1, 0, 4, 4}}) {
            QJsonObject bad = state;
            QJsonArray regions = bad["regions"].toArray();
            QJsonObject r0 = regions[0].toObject();
            r0["rect"] = rect;
            regions[0] = r0;
            bad["regions"] = regions;
            QString err;
            QVERIFY(!r.restoreState(bad, &err));
            QVERIFY2(err.contains("rect must be"), qPrintable(err));
            QCOMPARE(c->regions().size(), regionsBefore);
        }
    }

    // Exporting over the CRD file that is open (a symbolic link to it, here) would destroy the
    // station's data: refused, the file unchanged.
    void exportOverTheOpenPassIsRefused() {
        const QString stella = lwbtest::sharedPath("slr/7080_STELLA_crd_071220_2128_0.frd");
        if (!QFile::exists(stella)) QSKIP("shared data absent");
        const QString copy = m_dir.path() + "/pass.frd", link = m_dir.path() + "/pass-link.frd";
        QFile::remove(copy);
        QFile::remove(link);
        QVERIFY(QFile::copy(stella, copy));
        QVERIFY(QFile::link(copy, link));
        const QByteArray before = lwbtest::readAll(copy);
        MainWindow w;
        QString err;
        QVERIFY2(w.slr()->openPath(copy, -1, &err), qPrintable(err));
        SlrController* c = w.slr()->controller();
        QVERIFY(c->waitIdle(60000));
        QVERIFY(c->hasRun());
        QVERIFY(!c->exportCrd(link, &err));
        QVERIFY2(err.contains("read from"), qPrintable(err));
        QVERIFY(!c->exportCsv(copy, &err));
        QCOMPARE(lwbtest::readAll(copy), before);
        QVERIFY2(c->exportCrd(m_dir.path() + "/flags.frd", &err), qPrintable(err));
    }

    // `laserwb --help` without a display aborted (exit 134); without a display and without
    // --help it now says what to do instead of aborting.
    void helpWithoutADisplay() {
        GuiRun r = runGuiWithoutDisplay({"--help"});
        QVERIFY(!r.crashed);
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("Laser Workbench") && r.out.contains("--screenshot"), qPrintable(r.out + r.err));
        r = runGuiWithoutDisplay({"--version"});
        QVERIFY(!r.crashed);
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(LWB_VERSION), qPrintable(r.out));  // the one version (top CMakeLists.txt)
        r = runGuiWithoutDisplay({});
        QVERIFY(!r.crashed);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("no display") && r.err.contains("--screenshot"), qPrintable(r.err));
    }
};

QTEST_MAIN(TestShellReliability)
#include "test_shell_reliability.moc"
