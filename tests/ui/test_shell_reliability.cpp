// Hostile session files and a missing display (issue 8, GUI part): each case once crashed,
// aborted, or was accepted as if fine.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QtTest>
#include <functional>
#include <random>
#include <sys/stat.h>

#include "lwb_version.hpp"
#include "test_support.hpp"
#include "ui/calib/calib_workspace.hpp"
#include "ui/footprint/footprint_controller.hpp"
#include "ui/footprint/footprint_workspace.hpp"
#include "ui/shell/main_window.hpp"
#include "ui/radiometry/radiometry_controller.hpp"
#include "ui/radiometry/radiometry_workspace.hpp"
#include "ui/slr/slr_controller.hpp"
#include "ui/slr/slr_workspace.hpp"

using namespace lwb::ui;

class TestShellReliability : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_base;  // baseSession()

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

    // A session of every workspace with real inputs: the demo, a folder of simulated footprint
    // frames (shot 3 shown) and, when the shared data is there, a CRD pass; written once.
    QString baseSession() {
        if (!m_base.isEmpty()) return m_base;
        const QString d = m_dir.path() + "/mut";
        auto failed = [](const QString& why) {
            qWarning("base session: %s", qPrintable(why));
            return QString();
        };
        if (!QDir().mkpath(d) || lwbtest::simulateFootprintFolder(d + "/shots").exitCode != 0) return failed("no frames");
        MainWindow w;
        QString err;
        if (!w.openDemo() || !w.waitIdle(60000)) return failed("the demo");
        if (!w.openPaths({d + "/shots"}, &err)) return failed(err);
        const QString pass = lwbtest::sharedPath("slr/7080_JASON1_crd_071220_2033_0.frd");
        if (QFile::exists(pass) && !w.openPaths({pass}, &err)) return failed(err);
        if (!w.waitIdle(60000)) return failed("jobs did not finish");
        w.workspace<lwb::ui::FootprintWorkspace>()->selectRow(3);
        if (!w.saveSession(d + "/base.lwb.json", &err)) return failed(err);
        if (lwbtest::readAll(d + "/base.lwb.json").size() < 500) return failed("under 500 bytes");
        return m_base = d + "/base.lwb.json";
    }

    // Opens `path` in `w`: 1 when it opens (and its jobs finish); 0 when it is refused with a
    // message naming the file and the window left as it was: every workspace's state, no
    // footprint load started (a refused part once left the shots reloading and the shot shown
    // lost, or "loading" for ever), every workspace idle. Fails the test otherwise.
    int openOrRefuse(MainWindow& w, const QString& path, const QString& label) {
        const QJsonObject before = w.workspace<lwb::ui::FootprintWorkspace>()->saveState();
        const QJsonObject slrBefore = w.workspace<lwb::ui::SlrWorkspace>()->saveState(),
                          calibBefore = w.workspace<lwb::ui::CalibWorkspace>()->saveState(),
                          radiometryBefore = w.workspace<lwb::ui::RadiometryWorkspace>()->saveState();
        QSignalSpy reset(w.workspace<lwb::ui::FootprintWorkspace>()->controller(), &FootprintController::shotsReset);
        QString err;
        if (w.openSession(path, true, &err)) {
            if (w.waitIdle(60000)) return 1;
            QTest::qFail(qPrintable(label + ": jobs did not finish"), __FILE__, __LINE__);
            return -1;
        }
        auto fail = [&](const QString& why) {
            QTest::qFail(qPrintable(label + ": " + why), __FILE__, __LINE__);
            return -1;
        };
        if (!err.contains(path)) return fail("the message does not name the file: " + err);
        const bool idle = w.workspace<lwb::ui::FootprintWorkspace>()->waitIdle(10000) &&
                          w.workspace<lwb::ui::SlrWorkspace>()->waitIdle(10000) &&
                          w.workspace<lwb::ui::CalibWorkspace>()->waitIdle(10000) &&
                          w.workspace<lwb::ui::RadiometryWorkspace>()->waitIdle(10000);
        if (!idle) return fail("busy after being refused");
        if (!reset.isEmpty()) return fail("the footprint list was replaced (" + err + ")");
        const struct {
            const char* name;
            QJsonObject was, now;
        } parts[] = {{"footprint", before, w.workspace<lwb::ui::FootprintWorkspace>()->saveState()},
                     {"slr", slrBefore, w.workspace<lwb::ui::SlrWorkspace>()->saveState()},
                     {"calib", calibBefore, w.workspace<lwb::ui::CalibWorkspace>()->saveState()},
                     {"radiometry", radiometryBefore, w.workspace<lwb::ui::RadiometryWorkspace>()->saveState()}};
        for (const auto& p : parts)
            if (p.was != p.now)
                return fail(QString("the %1 part changed (%2):\n%3\n%4")
                                .arg(p.name, err, QString::fromUtf8(QJsonDocument(p.was).toJson(QJsonDocument::Compact)),
                                     QString::fromUtf8(QJsonDocument(p.now).toJson(QJsonDocument::Compact))));
        return 0;
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
        FootprintController* c = w.workspace<lwb::ui::FootprintWorkspace>()->controller();
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
        QVERIFY2(w.workspace<lwb::ui::SlrWorkspace>()->openPath(copy, -1, &err), qPrintable(err));
        SlrController* c = w.workspace<lwb::ui::SlrWorkspace>()->controller();
        QVERIFY(c->waitIdle(60000));
        QVERIFY(c->hasRun());
        QVERIFY(!c->exportCrd(link, &err));
        QVERIFY2(err.contains("would overwrite the input"), qPrintable(err));
        QVERIFY(!c->exportCsv(copy, &err));
        QCOMPARE(lwbtest::readAll(copy), before);
        QVERIFY2(c->exportCrd(m_dir.path() + "/flags.frd", &err), qPrintable(err));
    }

    // laserwb --screenshot OUT FILE... (issue 27): OUT is an output like any other. Naming the
    // session, a pass or a frame given as input is refused with the file unchanged; a folder or a
    // missing folder is refused before anything opens; the PNG is written whole or not at all.
    void screenshotNeverReplacesAnInput() {
        const QString d = m_dir.path();
        const lwbtest::CliRun sim = lwbtest::runCli({"simulate", "slr", "--kind", "conventional", "--duration", "200", "--seed",
                                                     "1", "-q", d + "/shot-pass.frd"});
        QCOMPARE(sim.exitCode, 0);
        QVERIFY(lwbtest::writeText(d + "/s.lwb.json", "{\"format\": \"laserwb-session\", \"version\": 1}\n"));
        lwbtest::RunOptions o;
        o.env = {"QT_QPA_PLATFORM=offscreen"};
        for (const QString& victim : {d + "/s.lwb.json", d + "/shot-pass.frd"}) {
            const QByteArray before = lwbtest::readAll(victim);
            const lwbtest::CliRun r = lwbtest::runProgram(QString(LWB_GUI), {"--screenshot", victim, victim}, o);
            QVERIFY2(r.exitCode == 2, qPrintable(QString::number(r.exitCode) + r.err));
            QVERIFY2(r.err.contains("overwrite"), qPrintable(r.err));
            QCOMPARE(lwbtest::readAll(victim), before);
        }
        // The pass read through the session's inputs: the same file under another name.
        QVERIFY(QFile::link(d + "/shot-pass.frd", d + "/alias.png"));
        const QByteArray pass = lwbtest::readAll(d + "/shot-pass.frd");
        lwbtest::CliRun r = lwbtest::runProgram(QString(LWB_GUI), {"--screenshot", d + "/alias.png", d + "/shot-pass.frd"}, o);
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(lwbtest::readAll(d + "/shot-pass.frd"), pass);
        // A folder, or a folder that does not exist.
        r = lwbtest::runProgram(QString(LWB_GUI), {"--screenshot", d}, o);
        QCOMPARE(r.exitCode, 1);
        r = lwbtest::runProgram(QString(LWB_GUI), {"--screenshot", d + "/no/such/folder/w.png"}, o);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("does not exist"), qPrintable(r.err));
        // A good one, and nothing left beside it.
        r = lwbtest::runProgram(QString(LWB_GUI), {"--screenshot", d + "/w.png", "--size", "800x600", d + "/shot-pass.frd"}, o);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(lwbtest::readAll(d + "/w.png").startsWith("\x89PNG"));
        for (const QString& f : lwbtest::filesIn(d)) QVERIFY2(!f.startsWith(".lwb-"), qPrintable(f));
    }

    // Issue 41: every exit path joins the pools. A session whose footprint frames are loading
    // when its SLR path (a folder) is refused made main return while a loader thread was inside
    // the codec module's dlopen: 4 runs in 20 died by SIGABRT (gdcm's global constructor beside
    // the exit handlers). 40 runs, each refused with exit 1 and none by a signal.
    void refusedSessionNeverDiesBySignal() {
        const QString d = m_dir.path() + "/exit";
        QVERIFY(QDir().mkpath(d + "/aFolder"));
        const lwbtest::CliRun sim = lwbtest::runCli({"simulate", "footprint", "--count", "300", "--seed", "2", "-q", d + "/frames"});
        QCOMPARE(sim.exitCode, 0);
        const QString session = d + "/s.lwb.json";
        QVERIFY(lwbtest::writeText(session, QString("{\"format\": \"laserwb-session\", \"version\": 1, \"workspace\": \"footprint\", "
                                                     "\"footprint\": {\"inputs\": [\"%1/frames\"]}, \"slr\": {\"path\": \"%1/aFolder\"}}\n")
                                                 .arg(d)
                                                 .toUtf8()));
        lwbtest::RunOptions o;
        o.env = {"QT_QPA_PLATFORM=offscreen"};
        o.timeoutMs = 60000;
        int bySignal = 0, refused = 0;
        for (int i = 0; i < 40; ++i) {
            const lwbtest::CliRun r = lwbtest::runProgram(QString(LWB_GUI), {"--screenshot", d + "/x.png", session}, o);
            bySignal += r.exitCode == -2;
            refused += r.exitCode == 1 && r.err.contains("is a folder");
        }
        QCOMPARE(bySignal, 0);
        QCOMPARE(refused, 40);
        QVERIFY(!QFile::exists(d + "/x.png"));
    }

    // A session that is a FIFO, a device or a huge file is refused at once, as the CLI refuses such
    // inputs (it blocked forever on a FIFO and took > 6 GB on /dev/zero).
    void specialAndHugeSessionsAreRefused() {
        const QString fifo = m_dir.path() + "/fifo.lwb.json";
        QFile::remove(fifo);
        QVERIFY(::mkfifo(fifo.toLocal8Bit().constData(), 0600) == 0);
        const QString sparse = m_dir.path() + "/huge.lwb.json";
        {
            QFile f(sparse);
            QVERIFY(f.open(QIODevice::WriteOnly));
            QVERIFY(f.resize(MainWindow::kMaxSessionBytes + 1));  // sparse: no disk used
        }
        MainWindow w;
        QElapsedTimer t;
        t.start();
        for (const QString& s : {fifo, QString("/dev/zero"), sparse}) {
            QString err;
            QVERIFY(!w.openSession(s, true, &err));
            QVERIFY2(err.contains("FIFO") || err.contains("device") || err.contains("limit"), qPrintable(err));
        }
        QVERIFY2(t.elapsed() < 5000, qPrintable(QString::number(t.elapsed())));
        QFile::remove(sparse);
    }

    // Quitting right after a session whose pass cannot be opened crashed in 17 of 40 runs (a
    // pooled job still loading the codec module while the program exited): 20 runs, no crash.
    void exitAfterAnUnopenablePassDoesNotCrash() {
        const QString d = m_dir.path();
        QVERIFY(lwbtest::writeText(d + "/bad-pass.lwb.json",
                                   "{\"format\": \"laserwb-session\", \"version\": 1, \"workspace\": \"slr\", \"slr\": "
                                   "{\"path\": \"" + d.toUtf8() + "\"}}\n"));
        lwbtest::RunOptions o;
        o.env = {"QT_QPA_PLATFORM=offscreen"};
        for (int i = 0; i < 20; ++i) {
            const lwbtest::CliRun r = lwbtest::runProgram(QString(LWB_GUI), {"--screenshot", d + "/exit.png", d + "/bad-pass.lwb.json"}, o);
            QVERIFY2(r.exitCode == 0 || r.exitCode == 1, qPrintable(QString("run %1: exit %2 %3").arg(i).arg(r.exitCode).arg(r.err)));
        }
    }

    // The mutant CI found (a number inside a path replaced, so the path named nothing): every
    // check passed, the footprint part was restored (its 40 shots reloading), and the SLR part
    // then failed to read its pass, so the footprint part was undone: the list replaced twice and
    // the shot shown lost. Each input that only reading finds wrong, one workspace at a time,
    // with the others' parts as they were: refused, and the window as it was.
    void unreadableInputsAreRefusedBeforeAnyPartIsRestored() {
        const QString base = baseSession();
        QVERIFY(!base.isEmpty());
        const QJsonObject original = QJsonDocument::fromJson(lwbtest::readAll(base)).object();
        const QString d = m_dir.path() + "/unreadable";
        QVERIFY(QDir().mkpath(d));
        QVERIFY(lwbtest::writeText(d + "/text.tif", "x,y\n1,2\n"));
        QJsonObject noTrend = original["slr"].toObject()["oc"].toObject();  // (the pass has no prediction)
        noTrend["own_trend_min_points"] = 1000000;
        struct Edit {
            QStringList at;  // the value replaced, by keys
            QJsonValue with;
        };
        const struct {
            const char* label;
            bool needsPass;  // the shared CRD pass in the session
            QList<Edit> edits;
        } cases[] = {
            {"an SLR pass that is not there", true, {{{"slr", "path"}, "/nonexistent/x.frd"}}},
            {"an SLR pass that is a folder", true, {{{"slr", "path"}, d}}},
            {"a manual edit beyond the pass", true, {{{"slr", "forced"}, QJsonArray{QJsonArray{99999999, 1}}}}},
            // Its O-C, made with the session's settings, cannot be: no pass, so no point to edit
            // (read with the window's settings it had points, and setting the session's opened
            // it again, emptied, when the footprint part had been restored).
            {"a manual edit of a pass the session's O-C settings leave empty",
             true,
             {{{"slr", "oc"}, noTrend}, {{"slr", "forced"}, QJsonArray{QJsonArray{0, 1}}}}},
            {"station normal points not there", false, {{{"slr", "station_npt"}, "/nonexistent/x.npt"}}},
            {"a manual edit beyond the demo pass", false,
             {{{"slr"}, QJsonObject{{"demo", true}, {"forced", QJsonArray{QJsonArray{99999999, 0}}}}}}},
            {"calibration detectors not there", false, {{{"calibration", "inputs", "detectors"}, "/nonexistent/detectors.csv"}}},
            {"a radiometry image not there", false, {{{"radiometry", "image"}, "/nonexistent/x.tif"}}},
            {"a radiometry image that is text", false, {{{"radiometry", "image"}, d + "/text.tif"}}},
            {"radiometry frames not there", false,
             {{{"radiometry", "frames"}, QJsonArray{"/nonexistent/a.tif", "/nonexistent/b.tif"}}}},
        };
        MainWindow w;
        QVERIFY(openOrRefuse(w, base, "the base session") == 1);
        const int shown = w.workspace<lwb::ui::FootprintWorkspace>()->saveState()["current"].toInt(-1);
        QCOMPARE(shown, 3);
        const bool havePass = !original["slr"].toObject()["path"].toString().isEmpty();
        int n = 0;
        for (const auto& c : cases) {
            if (c.needsPass && !havePass) continue;  // (no shared CRD pass here)
            QJsonObject session = original;
            for (const Edit& e : c.edits) {
                QVERIFY2(original.contains(e.at.first()), c.label);  // (a part of the session, not a key it ignores)
                // The value set at its keys, the rest of the session as saved.
                std::function<QJsonObject(QJsonObject, int)> set = [&](QJsonObject o, int k) {
                    o[e.at[k]] = k + 1 == e.at.size() ? e.with : QJsonValue(set(o[e.at[k]].toObject(), k + 1));
                    return o;
                };
                session = set(session, 0);
            }
            const QString path = d + QString("/case%1.lwb.json").arg(n++);
            QVERIFY(lwbtest::writeText(path, QJsonDocument(session).toJson()));
            QVERIFY2(openOrRefuse(w, path, c.label) == 0, c.label);
            QCOMPARE(w.workspace<lwb::ui::FootprintWorkspace>()->saveState()["current"].toInt(-1), shown);
        }
        QVERIFY(n >= (havePass ? 10 : 6));
    }

    // A session's pass is read once, its O-C made with the session's oc.* settings: it was read
    // with the window's, and setting the session's afterwards read it again (twice the time of
    // a big pass; and a second reading that failed was found after other parts were restored).
    void sessionPassIsReadOnceWithItsOwnOcSettings() {
        const QString base = baseSession();
        QVERIFY(!base.isEmpty());
        QJsonObject session = QJsonDocument::fromJson(lwbtest::readAll(base)).object();
        QJsonObject slr = session["slr"].toObject();
        if (slr["path"].toString().isEmpty()) QSKIP("the shared CRD pass is not there");
        QJsonObject oc = slr["oc"].toObject();
        QVERIFY(oc.contains("own_trend_degree"));
        const int degree = oc["own_trend_degree"].toInt() == 4 ? 5 : 4;
        oc["own_trend_degree"] = degree;
        slr["oc"] = oc;
        session["slr"] = slr;
        const QString path = m_dir.path() + "/mut/own-oc.lwb.json";
        QVERIFY(lwbtest::writeText(path, QJsonDocument(session).toJson()));
        MainWindow w;
        QSignalSpy opened(w.workspace<lwb::ui::SlrWorkspace>()->controller(), &SlrController::passChanged);
        QString err;
        QVERIFY2(w.openSession(path, true, &err), qPrintable(err));
        QVERIFY(w.waitIdle(60000));
        QCOMPARE(opened.count(), 1);
        QCOMPARE(w.workspace<lwb::ui::SlrWorkspace>()->controller()->params().ownTrend.degree, degree);
        QCOMPARE(w.workspace<lwb::ui::SlrWorkspace>()->saveState()["oc"].toObject()["own_trend_degree"].toInt(), degree);
    }

    // Issue 27: the GUI session parser fuzzed where libFuzzer cannot reach it (the workspaces'
    // restoreState needs widgets): a session of every workspace with real inputs (a frame folder,
    // a CRD pass, the calibration and radiometry demos), mutated 160 times by a seeded generator —
    // bytes flipped, cut, deleted, repeated; numbers replaced by huge, tiny, non-numbers, arrays;
    // strings by empty, a device, a folder, a missing file, 10 000 characters. The mutants are
    // opened one after another in one window: each opens (and its jobs finish), or it is refused
    // with a message naming the file; nothing crashes or hangs, and a refused session leaves the
    // window as it was (every workspace's state, no footprint load started, every workspace idle).
    void mutatedSessionsOpenOrAreRefused() {
        const QString d = m_dir.path() + "/mut";
        const QString base = baseSession();
        QVERIFY(!base.isEmpty());
        const QByteArray original = lwbtest::readAll(base);
        QVERIFY(original.size() > 500);
        std::mt19937 rng(27);
        auto pick = [&](int n) { return int(std::uniform_int_distribution<int>(0, std::max(n - 1, 0))(rng)); };
        const QList<QByteArray> numbers = {"1e400", "-1e400", "1e-400", "-0", "99999999999999999999", "\"x\"", "null",
                                           "[]", "{}", "true", "-1", "0", "2147483648", "1.5"};
        const QList<QByteArray> strings = {"\"\"", "\"/dev/zero\"", "\"" + d.toUtf8() + "\"", "\"/nonexistent/x.frd\"",
                                           "\"" + QByteArray(10000, 'a') + "\"", "0", "null", "[\"a\"]"};
        int opened = 0, refused = 0;
        // One window for every mutant, as an analyst opens session after session: a refused one
        // leaves the window as it was, whatever the sessions opened before it left there.
        MainWindow w;
        for (int i = 0; i < 160; ++i) {
            QByteArray m = original;
            const int at = pick(m.size());
            switch (i % 7) {
                case 0: m[at] = char(pick(256)); break;
                case 1: m.truncate(at); break;
                case 2: m.remove(at, 1 + pick(40)); break;
                case 3: m.insert(at, m.mid(at, 1 + pick(60))); break;
                case 4:
                case 5: {  // a number (case 4) or a string value (case 5) replaced
                    const QRegularExpression re(i % 7 == 4 ? "-?[0-9][0-9.eE+-]*" : ": *\"[^\"]*\"");
                    QList<QRegularExpressionMatch> all;
                    for (auto it = re.globalMatch(QString::fromUtf8(m)); it.hasNext();) all.push_back(it.next());
                    if (all.isEmpty()) break;
                    const QRegularExpressionMatch hit = all[pick(int(all.size()))];
                    const QByteArray with = i % 7 == 4 ? numbers[pick(int(numbers.size()))] : ": " + strings[pick(int(strings.size()))];
                    m = QString::fromUtf8(m).replace(hit.capturedStart(), hit.capturedLength(), QString::fromUtf8(with)).toUtf8();
                    break;
                }
                default: m.insert(at, m.mid(pick(m.size()), 1 + pick(200))); break;  // a piece from elsewhere
            }
            const QString path = d + QString("/m%1.lwb.json").arg(i);
            QVERIFY(lwbtest::writeText(path, m));
            if (const int r = openOrRefuse(w, path, QString("mutant %1").arg(i)); r == 1)
                ++opened;
            else if (r == 0)
                ++refused;
            if (QTest::currentTestFailed()) {
                // The mutant itself: its paths (the temporary folder, the shared data) differ
                // between machines, so another machine's mutant i is another session.
                qWarning("mutant %d was:\n%s", i, m.left(4000).constData());
                return;
            }
            QFile::remove(path);
        }
        qInfo("160 mutants: %d opened, %d refused", opened, refused);
        QVERIFY(refused >= 40);  // cuts and flips of the structure must be refused
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
