// Unix conventions of laserwb-cli (issue 26): "-" is standard input or output wherever a command
// takes one input or one output, gzip-compressed text inputs are read as they are, and both give
// the same results as the plain file, byte for byte.
#include <QtTest>
#include <zlib.h>

#include "core/common/atomic_file.hpp"
#include "test_support.hpp"

using namespace lwbtest;

namespace {

struct Piped {
    int exitCode = -1;
    QByteArray out, err;
};

// laserwb-cli with `input` on its standard input.
Piped pipeCli(const QStringList& args, const QByteArray& input) {
    RunOptions o;
    o.input = input;
    const CliRun r = runProgram(QString(LWB_CLI), args, o);
    return {r.exitCode, r.out.toUtf8(), r.err.toUtf8()};
}

QByteArray gzipped(const QByteArray& data) {
    z_stream zs{};
    deflateInit2(&zs, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY);  // 15 + 16: a gzip header
    QByteArray out(int(deflateBound(&zs, uLong(data.size()))) + 64, '\0');
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.constData()));
    zs.avail_in = uInt(data.size());
    zs.next_out = reinterpret_cast<Bytef*>(out.data());
    zs.avail_out = uInt(out.size());
    deflate(&zs, Z_FINISH);
    out.resize(int(zs.total_out));
    deflateEnd(&zs);
    return out;
}

}  // namespace

class TestUnixIo : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString p(const QString& n) const { return m_dir.path() + "/" + n; }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        QCOMPARE(runCli({"simulate", "slr", "--kind", "conventional", "--duration", "600", "--seed", "7", "-q", p("pass.frd")}).exitCode, 0);
        QCOMPARE(runCli({"simulate", "slr", "--points", "3000", "--seed", "8", "-q", p("pass.csv")}).exitCode, 0);
        QCOMPARE(runCli({"slr", p("pass.frd"), "-o", p("ref.csv"), "--npt-out", p("ref.npt"), "-q"}).exitCode, 0);
        QVERIFY(writeText(p("pass.frd.gz"), gzipped(readAll(p("pass.frd")))));
    }

    void standardOutputCarriesTheDataAlone() {
        const CliRun r = runCli({"slr", p("pass.frd"), "-o", "-"}, 120000);
        QCOMPARE(r.exitCode, 0);
        QCOMPARE(r.out.toUtf8(), readAll(p("ref.csv")));  // the same bytes as the file output
        QVERIFY2(r.err.contains("screening"), qPrintable(r.err));  // the summary went to stderr
        QVERIFY(!QFile::exists(QDir::currentPath() + "/-"));
        // Two outputs cannot both be standard output.
        const CliRun two = runCli({"slr", p("pass.frd"), "-o", "-", "--npt-out", "-"});
        QCOMPARE(two.exitCode, 2);
        QVERIFY2(two.err.contains("standard output"), qPrintable(two.err));
        // Another command and another kind of output: trend to stdout.
        QCOMPARE(runCli({"simulate", "trend", "--months", "3", "--seed", "2", "-q", p("c.csv")}).exitCode, 0);
        const CliRun t = runCli({"trend", p("c.csv"), "-o", "-"});
        QCOMPARE(t.exitCode, 0);
        QVERIFY(t.out.startsWith("camera,beam,month,n,"));
        QCOMPARE(t.out.count('\n'), 1 + 3 * 2);
    }

    void standardInputIsTheSameAsTheFile() {
        // A CRD pass on standard input (told from a CSV by its H1 record), written to a file.
        const Piped r = pipeCli({"slr", "-", "-o", p("stdin.csv"), "--npt-out", p("stdin.npt"), "-q"}, readAll(p("pass.frd")));
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(readAll(p("stdin.csv")), readAll(p("ref.csv")));
        QCOMPARE(readAll(p("stdin.npt")).count("\n11 "), readAll(p("ref.npt")).count("\n11 "));
        // An O-C table on standard input to standard output.
        QCOMPARE(runCli({"slr", p("pass.csv"), "-o", p("csvref.csv"), "-q"}).exitCode, 0);
        const Piped c = pipeCli({"slr", "-", "-o", "-", "-q"}, readAll(p("pass.csv")));
        QVERIFY2(c.exitCode == 0, c.err.constData());
        QCOMPARE(c.out, readAll(p("csvref.csv")));
        // Nothing on standard input: an error that says so, not a hang.
        const Piped e = pipeCli({"slr", "-", "-o", p("none.csv")}, QByteArray());
        QCOMPARE(e.exitCode, 1);
        QVERIFY(!QFile::exists(p("none.csv")));
    }

    // Issue 41: `slr - < /dev/zero` grew to 4.3 GB before it was refused at the 2 GiB limit. A
    // stream that starts with 64 KiB of NUL bytes is refused there, at once; a text input with a
    // NUL byte further on is refused with its line, on standard input and as a file.
    void zerosOnStandardInputRefusedAtOnce() {
        QProcess proc;
        proc.setStandardInputFile("/dev/zero");
        proc.start(QString(LWB_CLI), {"slr", "-", "-o", p("zero.csv")});
        QVERIFY(proc.waitForFinished(60000));
        QCOMPARE(proc.exitStatus(), QProcess::NormalExit);
        QCOMPARE(proc.exitCode(), 1);
        const QString err = QString::fromUtf8(proc.readAllStandardError());
        QVERIFY2(err.contains("standard input starts with 65536 NUL bytes"), qPrintable(err));
        QVERIFY(!QFile::exists(p("zero.csv")));
        QByteArray crd = readAll(p("pass.frd"));
        int at = -1;
        for (int k = 0; k < 4; ++k) at = crd.indexOf('\n', at + 1);
        QVERIFY(at > 0);
        crd[at + 3] = '\0';  // inside line 5
        const Piped r = pipeCli({"slr", "-", "-o", p("nul.csv")}, crd);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("-:5: binary data (NUL byte)"), r.err.constData());
        QVERIFY(writeText(p("nul.frd"), crd));
        const CliRun f = runCli({"slr", p("nul.frd"), "-o", p("nul.csv")});
        QCOMPARE(f.exitCode, 1);
        QVERIFY2(f.err.contains("nul.frd:5: binary data (NUL byte)"), qPrintable(f.err));
        QVERIFY(!QFile::exists(p("nul.csv")));
    }

    // An image on standard input: the footprint report of "-" is the file's report.
    void footprintFrameOnStandardInput() {
        QCOMPARE(runCli({"simulate", "footprint", "--count", "1", "--seed", "4", "-q", p("one")}).exitCode, 0);
        QCOMPARE(runCli({"footprint", p("one/shot_000000.png"), "-o", p("one.csv"), "-q"}).exitCode, 0);
        const Piped r = pipeCli({"footprint", "-", "-o", "-", "-q"}, readAll(p("one/shot_000000.png")));
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QList<QByteArray> file = readAll(p("one.csv")).split('\n'), piped = r.out.split('\n');
        QCOMPARE(piped.size(), file.size());
        QCOMPARE(piped[0], file[0]);
        QCOMPARE(piped[1].mid(piped[1].indexOf(',')), file[1].mid(file[1].indexOf(',')));  // all but the file name
        QVERIFY(piped[1].startsWith("-,"));
        // Not an image: said so, nothing written.
        const Piped bad = pipeCli({"footprint", "-", "-o", p("bad.csv")}, "hello\n");
        QCOMPARE(bad.exitCode, 1);
        QVERIFY(!QFile::exists(p("bad.csv")));
    }

    void gzipInputsAreRead() {
        const CliRun r = runCli({"slr", p("pass.frd.gz"), "-o", p("gz.csv"), "--npt-out", p("gz.npt"), "-q"});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QCOMPARE(readAll(p("gz.csv")), readAll(p("ref.csv")));
        // A compressed file on standard input, and under a name that does not say so.
        const Piped s = pipeCli({"slr", "-", "-o", "-", "-q"}, readAll(p("pass.frd.gz")));
        QCOMPARE(s.exitCode, 0);
        QCOMPARE(s.out, readAll(p("ref.csv")));
        QVERIFY(QFile::copy(p("pass.frd.gz"), p("renamed.frd")));
        QCOMPARE(runCli({"slr", p("renamed.frd"), "-o", p("renamed.csv"), "-q"}).exitCode, 0);
        QCOMPARE(readAll(p("renamed.csv")), readAll(p("ref.csv")));
        // A gzip O-C table and a gzip trend table.
        QVERIFY(writeText(p("pass.csv.gz"), gzipped(readAll(p("pass.csv")))));
        QCOMPARE(runCli({"slr", p("pass.csv.gz"), "-o", p("csvgz.csv"), "-q"}).exitCode, 0);
        QCOMPARE(readAll(p("csvgz.csv")), readAll(p("csvref.csv")));
    }

    void damagedGzipIsAClearError() {
        const QByteArray gz = readAll(p("pass.frd.gz"));
        // Truncated: the end marker is missing.
        QVERIFY(writeText(p("cut.frd.gz"), gz.left(gz.size() / 2)));
        CliRun r = runCli({"slr", p("cut.frd.gz"), "-o", p("cut.csv")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("cut.frd.gz") && r.err.contains("truncated"), qPrintable(r.err));
        QVERIFY(!QFile::exists(p("cut.csv")));
        // Corrupt in the middle.
        QByteArray bad = gz;
        for (int i = 40; i < 80 && i < bad.size(); ++i) bad[i] = char(bad[i] ^ 0x5a);
        QVERIFY(writeText(p("bad.frd.gz"), bad));
        r = runCli({"slr", p("bad.frd.gz"), "-o", p("bad.csv")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("bad.frd.gz") && r.err.contains("gzip"), qPrintable(r.err));
        // A gzip bomb: more than the text input limit once decompressed is refused with the limit.
        std::string out, why;
        const QByteArray zeros = gzipped(QByteArray(8 << 20, '0'));
        QVERIFY(!lwb::core::gunzip(zeros.constData(), size_t(zeros.size()), &out, &why, 1 << 20));
        QVERIFY2(QString::fromStdString(why).contains("limit"), why.c_str());
        QVERIFY(out.empty());
        // Two gzip members one after the other (cat a.gz b.gz) read as one text.
        const QByteArray two = gzipped("abc\n") + gzipped("def\n");
        QVERIFY(lwb::core::gunzip(two.constData(), size_t(two.size()), &out, &why, 0));
        QCOMPARE(QByteArray::fromStdString(out), QByteArray("abc\ndef\n"));
    }

    void inputExtensionIgnoresGz() {
        QCOMPARE(lwb::core::inputExtension("a/b/pass.FRD.gz"), std::string("frd"));
        QCOMPARE(lwb::core::inputExtension("pass.csv"), std::string("csv"));
        QCOMPARE(lwb::core::inputExtension("dir.x/pass"), std::string());
        QCOMPARE(lwb::core::inputExtension("pass.gz"), std::string());
    }
};

QTEST_GUILESS_MAIN(TestUnixIo)
#include "test_unix_io.moc"
