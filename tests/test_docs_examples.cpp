// Documentation that runs (issue 26): every shell example of README.md and docs/*.md works as
// written, or this test fails.
//
//  - Every fenced block marked ```sh is run with bash (-e -o pipefail), block after block in the
//    order of its file, in one scratch folder per file, with the build's laserwb-cli and laserwb
//    first on PATH and ../shared (the real ILRS files) out of reach. The sample inputs the
//    examples use are made by an earlier block of the same file, from the simulators.
//  - A block whose first line is "# not run: REASON" is not run; it is listed with its reason
//    (build, install and fuzzing commands that CI or another test runs).
//  - Every `laserwb-cli ...` written inline in the prose names a command that exists and only
//    options that command's --help lists.
//  - Every `--set KEY=VALUE` example a command's --help gives is accepted by that command.
#include <QDirIterator>
#include <QRegularExpression>
#include <QtTest>

#include "core/footprint/batch.hpp"
#include "lwb_version.hpp"
#include "test_support.hpp"

using namespace lwbtest;

namespace {

struct Block {
    QString file;
    int line = 0;  ///< of the opening fence
    QString text;
    QString notRun;  ///< the reason, for a "# not run:" block
};

QStringList docFiles() {
    QStringList files{QStringLiteral(LWB_SOURCE_DIR "/README.md")};
    QDir docs(QStringLiteral(LWB_SOURCE_DIR "/docs"));
    for (const QString& f : docs.entryList({"*.md"}, QDir::Files, QDir::Name)) files << docs.filePath(f);
    return files;
}

QList<Block> shellBlocks(const QString& path) {
    QList<Block> out;
    const QStringList lines = QString::fromUtf8(readAll(path)).split('\n');
    for (int i = 0; i < lines.size(); ++i) {
        if (lines[i].trimmed() != "```sh") continue;
        Block b;
        b.file = QFileInfo(path).fileName();
        b.line = i + 1;
        int j = i + 1;
        for (; j < lines.size() && !lines[j].trimmed().startsWith("```"); ++j) b.text += lines[j] + "\n";
        const QString first = b.text.section('\n', 0, 0).trimmed();
        if (first.startsWith("# not run:")) b.notRun = first.mid(10).trimmed();
        out << b;
        i = j;
    }
    return out;
}

// The `laserwb-cli ...` spans of inline code in a Markdown file (outside fenced blocks).
QList<QPair<int, QString>> inlineCommands(const QString& path) {
    QList<QPair<int, QString>> out;
    const QStringList lines = QString::fromUtf8(readAll(path)).split('\n');
    bool fenced = false;
    QString para;
    int paraLine = 0;
    auto flush = [&] {
        static const QRegularExpression span("`(laserwb-cli [^`]+)`");
        for (auto it = span.globalMatch(para); it.hasNext();) out << qMakePair(paraLine, it.next().captured(1));
        para.clear();
    };
    for (int i = 0; i < lines.size(); ++i) {
        if (lines[i].trimmed().startsWith("```")) {
            fenced = !fenced;
            flush();
            continue;
        }
        if (fenced) continue;
        if (lines[i].trimmed().isEmpty()) {
            flush();
            continue;
        }
        if (para.isEmpty()) paraLine = i + 1;
        para += lines[i] + " ";  // a span may wrap onto the next line
    }
    flush();
    return out;
}

// The command words of a laserwb-cli invocation ("calib detector", "slr").
QStringList commandWords(const QStringList& args) {
    static const QStringList two{"simulate", "eval", "bench", "calib", "radiometry", "crd"};
    if (args.isEmpty()) return {};
    if (two.contains(args[0]) && args.size() > 1) return args.mid(0, 2);
    if ((args[0] == "slr" || args[0] == "footprint") && args.size() > 1 && args[1] == "tune") return args.mid(0, 2);
    return args.mid(0, 1);
}

}  // namespace

class TestDocsExamples : public QObject {
    Q_OBJECT
    QMap<QString, QString> m_help;  // command words -> its --help

    QString helpOf(const QStringList& words) {
        const QString key = words.join(' ');
        if (!m_help.contains(key)) {
            const CliRun r = runCli(words + QStringList{"--help"});
            m_help[key] = r.exitCode == 0 ? r.out : QString();
        }
        return m_help[key];
    }

private slots:
    void shellBlocksRunAsWritten() {
        const QString binDir = QFileInfo(QStringLiteral(LWB_CLI)).absolutePath();
        int run = 0, notRun = 0, files = 0;
        QStringList failures, skipped;
        for (const QString& path : docFiles()) {
            const QList<Block> blocks = shellBlocks(path);
            if (std::none_of(blocks.begin(), blocks.end(), [](const Block& b) { return b.notRun.isEmpty(); }))
                for (const Block& b : blocks) {  // (only blocks that are not run)
                    ++notRun;
                    skipped << QString("%1:%2 (%3)").arg(b.file).arg(b.line).arg(b.notRun);
                }
            if (std::none_of(blocks.begin(), blocks.end(), [](const Block& b) { return b.notRun.isEmpty(); })) continue;
            ++files;
            QTemporaryDir scratch;  // one per file: its blocks build on each other's outputs
            QVERIFY(scratch.isValid());
            for (const Block& b : blocks) {
                const QString where = QString("%1:%2").arg(b.file).arg(b.line);
                if (!b.notRun.isEmpty()) {
                    ++notRun;
                    skipped << where + " (" + b.notRun + ")";
                    continue;
                }
                QProcess sh;
                QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
                env.insert("PATH", binDir + ":" + env.value("PATH"));
                env.insert("QT_QPA_PLATFORM", "offscreen");
                env.remove("LWB_TERRAIN_PHOTOS");
                sh.setProcessEnvironment(env);
                sh.setWorkingDirectory(scratch.path());
                sh.setProcessChannelMode(QProcess::MergedChannels);
                sh.start("bash", {"-e", "-o", "pipefail", "-c", b.text});
                const bool finished = sh.waitForFinished(240000);
                if (!finished) sh.kill(), sh.waitForFinished();
                ++run;
                const QString output = QString::fromUtf8(sh.readAll());
                if (!finished || sh.exitStatus() != QProcess::NormalExit || sh.exitCode() != 0)
                    failures << QString("%1: %2 (exit %3)\n--- block ---\n%4--- output (last 2000 characters) ---\n%5")
                                    .arg(where, finished ? "failed" : "timed out (240 s)")
                                    .arg(sh.exitCode())
                                    .arg(b.text, output.right(2000));
            }
        }
        qInfo("documentation examples: %d shell blocks run in %d files, %d not run:", run, files, notRun);
        for (const QString& s : skipped) qInfo("  not run: %s", qPrintable(s));
        QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n\n")));
        // The README's examples are not all marked "not run" (a floor the suite cannot quietly lose:
        // README.md has 7 blocks that run).
        QVERIFY2(run >= 7, qPrintable(QString("only %1 blocks ran").arg(run)));
    }

    void inlineCommandsNameRealOptions() {
        int checked = 0;
        QStringList problems;
        for (const QString& path : docFiles()) {
            for (const auto& [line, text] : inlineCommands(path)) {
                QStringList args = text.simplified().split(' ').mid(1);
                const QStringList words = commandWords(args);
                const QString where = QString("%1:%2: `%3`").arg(QFileInfo(path).fileName()).arg(line).arg(text.simplified());
                // `laserwb-cli --version`, `laserwb-cli COMMAND`, `laserwb-cli calib …`: not one command
                if (words.isEmpty() || words[0].startsWith('-') || words[0] == "COMMAND" || words.join(' ').contains(QChar(0x2026)))
                    continue;
                const QString help = helpOf(words);
                if (help.isEmpty()) {
                    problems << where + ": no such command (" + words.join(' ') + " --help fails)";
                    continue;
                }
                for (const QString& a : args.mid(words.size())) {
                    if (!a.startsWith("--")) continue;
                    const QString opt = a.section('=', 0, 0);
                    static const QStringList common{"--help", "--quiet", "--help-params", "--print-config", "--config", "--set"};
                    if (common.contains(opt)) continue;
                    if (!help.contains(opt)) problems << where + ": " + opt + " is not an option of " + words.join(' ');
                }
                ++checked;
            }
        }
        qInfo("documentation: %d inline laserwb-cli commands checked against their --help", checked);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join("\n")));
        QVERIFY(checked >= 10);
    }

    // One version: the top CMakeLists.txt's, which the programs print; the citation and the
    // changelog's latest release must say the same.
    void versionIsTheSameEverywhere() {
        QCOMPARE(runCli({"version"}).out.trimmed(), QString("laserwb-cli " LWB_VERSION));
        static const QRegularExpression cff("(?m)^version:\\s*\"?([0-9][^\"\\s]*)\"?");
        const QRegularExpressionMatch m = cff.match(QString::fromUtf8(readAll(LWB_SOURCE_DIR "/CITATION.cff")));
        QVERIFY2(m.hasMatch(), "CITATION.cff has no version");
        QCOMPARE(m.captured(1), QString(LWB_VERSION));
        static const QRegularExpression release("(?m)^## \\[([0-9][^\\]]*)\\]");
        const QRegularExpressionMatch r = release.match(QString::fromUtf8(readAll(LWB_SOURCE_DIR "/CHANGELOG.md")));
        QVERIFY2(r.hasMatch(), "CHANGELOG.md has no release");
        QCOMPARE(r.captured(1), QString(LWB_VERSION));
    }

    // Issue 46: the README's list of the footprint report's columns had fallen behind the report
    // (cov_*_px2 and radius95_px missing): it is the header, in order.
    void readmeListsTheReportColumns() {
        const QString readme = QString::fromUtf8(readAll(LWB_SOURCE_DIR "/README.md"));
        static const QRegularExpression list("holds one row per image \\(per ROI\\): `([^`]*)`");
        const QRegularExpressionMatch m = list.match(readme);
        QVERIFY2(m.hasMatch(), "README.md: the report's column list is gone");
        QString listed = m.captured(1);
        listed.remove(QRegularExpression("\\s"));
        QCOMPARE(listed, QString::fromStdString(lwb::core::footprint::footprintCsvHeader()).trimmed());
    }

    // Issue 46: `help CMD`, `CMD --version` and "did you mean" were missing. help CMD [KIND] is
    // CMD [KIND] --help, byte for byte; every command answers --version; a mistyped command,
    // kind, option or --set key names the nearest (and only a near one).
    void helpVersionAndDidYouMean() {
        for (const QStringList& c : QList<QStringList>{{"slr"}, {"crd", "check"}, {"footprint"}, {"calib", "detector"},
                                                       {"simulate", "slr"}, {"radiometry"}}) {
            const CliRun h = runCli(QStringList{"help"} + c), direct = runCli(c + QStringList{"--help"});
            QCOMPARE(h.exitCode, 0);
            QVERIFY2(!h.out.isEmpty() && h.out == direct.out, qPrintable(c.join(' ')));
            const CliRun v = runCli(c + QStringList{"--version"});
            QCOMPARE(v.exitCode, 0);
            QCOMPARE(v.out.trimmed(), QString("laserwb-cli " LWB_VERSION));
        }
        const QList<QPair<QStringList, QString>> typos{
            {{"sl", "x.frd"}, "unknown command \"sl\" (did you mean slr?)"},
            {{"radiometri", "fit"}, "(did you mean radiometry?)"},
            {{"simulate", "slrr"}, "unknown kind \"slrr\" (footprint, trend, slr, calib, radiometry) (did you mean slr?)"},
            {{"calib", "pointng"}, "(did you mean pointing?)"},
            {{"slr", "x.frd", "--crd-ot", "y.frd"}, "unknown option --crd-ot (did you mean --crd-out?)"},
            {{"footprint", "--versoin"}, "(did you mean --version?)"},
            {{"slr", "x.frd", "--set", "screen.cosin_c=0.9"}, "unknown parameter \"screen.cosin_c\" for slr (did you mean screen.cosine_c?)"},
            {{"footprint", "x.png", "--set", "segment.threshold_factr=1"}, "(did you mean segment.threshold_factor?)"}};
        for (const auto& [args, said] : typos) {
            const CliRun r = runCli(args);
            QCOMPARE(r.exitCode, 2);
            QVERIFY2(r.err.contains(said), qPrintable(args.join(' ') + ": " + r.err));
        }
        // nothing near: no guess
        const CliRun far = runCli({"xyzzy"});
        QVERIFY(far.err.contains("unknown command \"xyzzy\"") && !far.err.contains("did you mean"));
        const CliRun farOpt = runCli({"slr", "x.frd", "--bogus"});
        QVERIFY(farOpt.err.contains("unknown option --bogus") && !farOpt.err.contains("did you mean"));
    }

    // A flag a command takes is in its --help (the README used -q everywhere; most --help texts
    // did not say it): -q, --quiet and --help-params for every command that accepts them.
    void acceptedFlagsAreInTheHelp() {
        const QList<QStringList> commands{{"footprint"}, {"trend"}, {"slr"}, {"simulate", "footprint"}, {"simulate", "trend"},
                                          {"simulate", "slr"}, {"simulate", "calib"}, {"simulate", "radiometry"},
                                          {"eval", "footprint"}, {"calib", "detector"}, {"calib", "waveform"},
                                          {"calib", "pointing"}, {"calib", "stats"}, {"radiometry", "mosaic"},
                                          {"radiometry", "gcp"}, {"radiometry", "fit"}, {"radiometry", "apply"},
                                          {"radiometry", "check"}};
        QStringList missing;
        for (const QStringList& c : commands) {
            const QString help = helpOf(c);
            for (const QString& flag : {QString("-q"), QString("--help-params")}) {
                // Accepted: `CMD FLAG --help` prints the help (an unknown flag is a usage error).
                if (runCli(c + QStringList{flag, "--help"}).exitCode != 0) continue;
                if (!help.contains(QRegularExpression("(^|[\\s,])" + QRegularExpression::escape(flag) + "([\\s,]|$)",
                                                      QRegularExpression::MultilineOption)))
                    missing << c.join(' ') + " takes " + flag + " but its --help does not say so";
            }
        }
        QVERIFY2(missing.isEmpty(), qPrintable(missing.join("\n")));
    }

    void helpSetExamplesAreAccepted() {
        const QList<QStringList> commands{{"footprint"}, {"trend"}, {"slr"}, {"calib", "detector"}, {"calib", "waveform"},
                                          {"calib", "pointing"}, {"calib", "stats"}, {"radiometry", "mosaic"},
                                          {"radiometry", "gcp"}, {"radiometry", "fit"}, {"radiometry", "apply"},
                                          {"radiometry", "check"}};
        static const QRegularExpression setExample("--set ([a-z_][a-z0-9_.]*=[^\\s,;)]+)");
        int examples = 0;
        for (const QStringList& c : commands) {
            const QString help = helpOf(c);
            QVERIFY2(!help.isEmpty(), qPrintable(c.join(' ') + " --help failed"));
            for (auto it = setExample.globalMatch(help); it.hasNext();) {
                const QString kv = it.next().captured(1);
                // (placeholders: --set roi.size=N, --set method=...)
                static const QRegularExpression placeholder("=([A-Z_]+|\\.\\.\\.)$");
                if (kv.endsWith('=') || placeholder.match(kv).hasMatch()) continue;
                const CliRun r = runCli(c + QStringList{"--set", kv, "--print-config"});
                QVERIFY2(r.exitCode == 0, qPrintable(c.join(' ') + " --help shows --set " + kv + ", which it rejects: " + r.err));
                ++examples;
            }
        }
        qInfo("--help: %d --set examples accepted", examples);
        QVERIFY(examples >= 5);
    }
};

QTEST_GUILESS_MAIN(TestDocsExamples)
#include "test_docs_examples.moc"
