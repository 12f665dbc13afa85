#pragma once
// Helpers shared by the tests: temporary folders, the shared data folder, running the CLI.
#include <QDir>
#include <QFile>
#include <QProcess>
#include <QString>
#include <QTemporaryDir>
#include <QtTest>
#include <string>

namespace lwbtest {

/// ../shared/data/<rel> beside the checkout (configured at build time).
inline QString sharedPath(const QString& rel) { return QString(LWB_SHARED_DIR) + "/data/" + rel; }

/// True when the shared data folder is present; tests QSKIP otherwise.
inline bool haveShared(const QString& rel) { return QFile::exists(sharedPath(rel)); }

struct CliRun {
    int exitCode = -1;
    QString out, err;
};

/// How runProgram runs a program: extra environment ("NAME=value"), working folder, what goes
/// to its standard input (closed after), how long to wait.
struct RunOptions {
    QStringList env;
    QString cwd;
    QByteArray input;
    int timeoutMs = 120000;
};

/// Runs a program and waits for it; a crash is exitCode -2, a timeout -1 with err "timeout".
inline CliRun runProgram(const QString& program, const QStringList& args, const RunOptions& o = {}) {
    QProcess p;
    if (!o.env.isEmpty()) {
        QProcessEnvironment e = QProcessEnvironment::systemEnvironment();
        for (const QString& kv : o.env) e.insert(kv.section('=', 0, 0), kv.section('=', 1));
        p.setProcessEnvironment(e);
    }
    if (!o.cwd.isEmpty()) p.setWorkingDirectory(o.cwd);
    p.start(program, args);
    if (!o.input.isEmpty()) p.write(o.input);
    p.closeWriteChannel();
    CliRun r;
    if (!p.waitForFinished(o.timeoutMs)) {
        p.kill();
        p.waitForFinished();
        r.err = "timeout";
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

/// Runs laserwb-cli with args; waits up to timeoutMs. `env` entries ("NAME=value") are added
/// to the child's environment.
inline CliRun runCli(const QStringList& args, int timeoutMs = 120000, const QStringList& env = {}) {
    RunOptions o;
    o.env = env;
    o.timeoutMs = timeoutMs;
    return runProgram(QString(LWB_CLI), args, o);
}

inline std::string str(const QString& s) { return s.toStdString(); }

inline QByteArray readAll(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return f.readAll();
}

inline bool writeText(const QString& path, const QByteArray& text) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate)) return false;
    return f.write(text) == text.size();
}

/// Files in a folder other than the expected ones (a half-written temporary, say).
// The 40-shot simulated footprint folder (seed 5, mixed cases, with its truth.csv) the footprint
// ui tests open, written to DIR.
inline CliRun simulateFootprintFolder(const QString& dir) {
    return runCli({"simulate", "footprint", "--count", "40", "--seed", "5", "--case", "mixed", "-q", dir});
}

inline QStringList filesIn(const QString& dir) { return QDir(dir).entryList(QDir::Files | QDir::Hidden); }

/// An O-C table (epoch_s,oc_s) of a simulated pass (`simulate slr` CSV, with its truth column)
/// and a ghost of its track: three signal points in five again `shiftS` later (and 0.1 ms later
/// in time), as a double echo or a second target would give (issue 41).
inline QByteArray withGhostTrack(const QByteArray& simulatedCsv, double shiftS = 3e-9) {
    const QList<QByteArray> lines = simulatedCsv.split('\n');
    QByteArray out = "epoch_s,oc_s\n";
    for (int i = 1; i < lines.size(); ++i) {
        const QList<QByteArray> f = lines[i].split(',');
        if (f.size() < 3) continue;
        out += f[0] + "," + f[1] + "\n";
        if (f[2] == "1" && i % 5 < 3)
            out += QByteArray::number(f[0].toDouble() + 1e-4, 'f', 6) + "," + QByteArray::number(f[1].toDouble() + shiftS, 'g', 17) + "\n";
    }
    return out;
}

}  // namespace lwbtest
