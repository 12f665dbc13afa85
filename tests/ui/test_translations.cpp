// The Chinese interface (issue 42): the translation complete and current, and the window in
// Chinese wherever its text is the program's own.
// - Complete: no message of ui/i18n/laserwb_zh_CN.ts unfinished or empty.
// - Current: lupdate run now over ui/ (as make translations runs it) finds no string the .ts
//   lacks, and the schema rows' texts file (lwb-i18n-strings) is the one committed: a new tr()
//   string or a new parameter row without its translation fails here, naming it.
// - The window: built in zh_CN with every workspace's demo open, no menu entry, tab, dock title,
//   group title, button, check box, label or table header shows an English word the program
//   wrote (what the data says — file names, satellite names, the core's messages — and format
//   names and units are not the program's words; they are listed below and stay).
#include <QtTest>
#include <QRegularExpression>
#include <QCheckBox>
#include <QAbstractButton>
#include <QDockWidget>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QMenuBar>
#include <QTabWidget>
#include <QTableView>
#include <QXmlStreamReader>

#include "test_support.hpp"
#include "ui/kit/i18n.hpp"
#include "ui/shell/main_window.hpp"

using namespace lwb::ui;

namespace {
struct Message {
    QString context, source;
    bool finished = false;
};

// The messages of a .ts file; false with *error when it cannot be read.
bool readTs(const QString& path, QList<Message>* out, QString* error) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        *error = path + ": cannot be read";
        return false;
    }
    QXmlStreamReader x(&f);
    QString context;
    Message m;
    bool inMessage = false;
    while (!x.atEnd()) {
        x.readNext();
        if (x.isStartElement()) {
            const auto n = x.name();
            if (n == QLatin1String("context")) context.clear();
            else if (n == QLatin1String("name") && !inMessage) context = x.readElementText();
            else if (n == QLatin1String("message")) {
                inMessage = true;
                m = Message{context, QString(), true};
            } else if (n == QLatin1String("source") && inMessage) m.source = x.readElementText();
            else if (n == QLatin1String("translation") && inMessage) {
                const bool unfinished = x.attributes().value("type") == QLatin1String("unfinished");
                const QString text = x.readElementText(QXmlStreamReader::IncludeChildElements);
                m.finished = !unfinished && !text.trimmed().isEmpty();
            }
        } else if (x.isEndElement() && x.name() == QLatin1String("message")) {
            inMessage = false;
            out->push_back(m);
        }
    }
    if (x.hasError()) {
        *error = QString("%1:%2: %3").arg(path).arg(x.lineNumber()).arg(x.errorString());
        return false;
    }
    return true;
}

QString tsPath() { return QString(LWB_SOURCE_DIR) + "/ui/i18n/laserwb_zh_CN.ts"; }

QString listOf(const QStringList& items) {
    return QString::number(items.size()) + ":\n  " + items.mid(0, 40).join("\n  ") + (items.size() > 40 ? "\n  ..." : "");
}

// An English word the program wrote: four letters or more, not a name, format or unit (data,
// file names and the core's messages are filtered by where they are shown, below).
bool englishWord(const QString& text, QString* word) {
    static const QSet<QString> kept = {
        // formats, standards, programs and names of things
        "CRD", "CPF", "SINEX", "NPT", "JSON", "TIFF", "GeoTIFF", "FITS", "HTML", "laserwb", "Laser", "Workbench",
        "Viridis", "Inferno", "English", "Python", "Dask", "ILRS", "MLRS", "LAGEOS", "BLITS", "demo", "Levenberg", "Marquardt",
        "Legendre", "Gauss", "Gaussian", "Otsu", "Sobel", "Canny", "Hough", "Fusion", "Ctrl", "Shift", "Space", "Enter",
        "Backspace", "Delete", "Home", "Tab", "Esc", "TEFM", "RANSAC", "AKAZE", "Huber", "Lowe", "Mendes", "Pavlis",
        "FCULa", "IRAF", "ZScale", "CRLB", "Shapiro", "Hover", "Wheel", "Drag"};
    // (a token with '_', '.' or '-' before it is a key, a file name or an option: code, not words)
    static const QRegularExpression wordRe("(?<![-_.A-Za-z0-9])[A-Za-z]{4,}(?![_.A-Za-z0-9])");
    for (auto it = wordRe.globalMatch(text); it.hasNext();) {
        const QString w = it.next().captured();
        if (!kept.contains(w) && !kept.contains(w.toUpper())) {
            *word = w;
            return true;
        }
    }
    return false;
}

QString plain(QString s) {
    // Code (<tt>: keys, commands) is not the program's words.
    static const QRegularExpression code("<tt>.*?</tt>");
    s.remove(code);
    static const QRegularExpression tag("<[^>]*>");
    s.remove(tag);
    s.remove('&');
    return s;
}

// Data shown by name, not the program's words: result lines (property showsData: their words
// are tr() strings, checked by the .ts's completeness, around the data's and the core's), and
// labels whose object names say they show data.
bool showsData(const QObject* o) {
    for (; o; o = o->parent()) {
        if (o->property("showsData").toBool()) return true;
        const QString n = o->objectName();
        if (n.contains("summary", Qt::CaseInsensitive) || n.contains("status", Qt::CaseInsensitive) ||
            n.contains("readout", Qt::CaseInsensitive) || n.contains("file", Qt::CaseInsensitive) ||
            n.contains("path", Qt::CaseInsensitive) || n.contains("hover", Qt::CaseInsensitive) ||
            n == "userGuide" || n.startsWith("data"))
            return true;
    }
    return false;
}

void collectMenu(QMenu* menu, const QString& where, QStringList* bad) {
    for (QAction* a : menu->actions()) {
        if (a->isSeparator()) continue;
        if (a->menu()) collectMenu(a->menu(), where + " ▸ " + plain(a->text()), bad);
        QString w;
        // (recent files and sessions are paths; a workspace's name comes from its title, checked as a tab)
        if (!a->text().contains('/') && englishWord(plain(a->text()), &w)) bad->append(where + " ▸ " + a->text() + "  [" + w + "]");
    }
}
}  // namespace

class TestTranslations : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void translationIsComplete() {
        QList<Message> msgs;
        QString err;
        QVERIFY2(readTs(tsPath(), &msgs, &err), qPrintable(err));
        QVERIFY2(msgs.size() > 800, qPrintable(QString("only %1 messages in %2").arg(msgs.size()).arg(tsPath())));
        QStringList open;
        for (const Message& m : msgs)
            if (!m.finished) open << m.context + ": " + m.source.left(100);
        QVERIFY2(open.isEmpty(), qPrintable("untranslated in " + tsPath() + " " + listOf(open)));
    }

    void translationIsCurrent() {
        // The schema rows' texts as lwb-i18n-strings writes them now.
        const QString strings = m_dir.path() + "/schema_strings.cpp";
        const lwbtest::CliRun g = lwbtest::runProgram(LWB_I18N_STRINGS, {strings});
        QVERIFY2(g.exitCode == 0, qPrintable(g.err));
        QVERIFY2(lwbtest::readAll(strings) == lwbtest::readAll(QString(LWB_SOURCE_DIR) + "/ui/i18n/schema_strings.cpp"),
                 "ui/i18n/schema_strings.cpp is not the parameter schemas' texts of now: run make translations and translate what it adds");
        // lupdate over the sources into a copy of the .ts: anything it adds is untranslated.
        const QString copy = m_dir.path() + "/current.ts";
        QFile::remove(copy);
        QVERIFY(QFile::copy(tsPath(), copy));
        QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
        const lwbtest::CliRun u = lwbtest::runProgram(
            LWB_LUPDATE, {"-silent", "-no-obsolete", "-locations", "none", "-I", QString(LWB_SOURCE_DIR), "-recursive",
                         QString(LWB_SOURCE_DIR) + "/ui", "-ts", copy});
        QVERIFY2(u.exitCode == 0, qPrintable(u.err));
        QList<Message> msgs;
        QString err;
        QVERIFY2(readTs(copy, &msgs, &err), qPrintable(err));
        QStringList open;
        for (const Message& m : msgs)
            if (!m.finished) open << m.context + ": " + m.source.left(100);
        QVERIFY2(open.isEmpty(), qPrintable("strings of the code with no translation (make translations, then translate) " + listOf(open)));
    }

    /// The window in Chinese: every workspace on its demo, its own words translated.
    void windowIsInChinese() {
        QCOMPARE(installLanguage("zh_CN"), QString("zh_CN"));
        QCOMPARE(currentLanguage(), QString("zh_CN"));
        QCOMPARE(QLocale().name(), QString("zh_CN"));
        {
            MainWindow w;
            w.resize(1280, 800);
            w.show();
            w.openDemo();
            QVERIFY(w.waitIdle(120000));
            QStringList bad;
            for (QAction* a : w.menuBar()->actions())
                if (a->menu()) collectMenu(a->menu(), plain(a->text()), &bad);
            const auto tabs = w.findChildren<QTabWidget*>();
            for (QTabWidget* t : tabs)
                for (int i = 0; i < t->count(); ++i) {
                    QString word;
                    if (englishWord(plain(t->tabText(i)), &word)) bad << "tab " + t->tabText(i) + "  [" + word + "]";
                }
            for (QDockWidget* d : w.findChildren<QDockWidget*>()) {
                QString word;
                if (englishWord(d->windowTitle(), &word)) bad << "dock " + d->windowTitle() + "  [" + word + "]";
            }
            for (QGroupBox* g : w.findChildren<QGroupBox*>()) {
                QString word;
                if (englishWord(plain(g->title()), &word)) bad << "group " + g->title() + "  [" + word + "]";
            }
            for (QAbstractButton* b : w.findChildren<QAbstractButton*>()) {
                QString word;
                if (!b->text().isEmpty() && !showsData(b) && englishWord(plain(b->text()), &word))
                    bad << "button " + b->text() + " (" + b->objectName() + ")  [" + word + "]";
            }
            // A schema row's checkbox: its tooltip is "<b>key</b><br>doc<br>true or false"; the doc
            // and the range in Chinese (they were English on every checkbox and combo box while
            // the sliders' were translated: a real-window run).
            for (QCheckBox* b : w.findChildren<QCheckBox*>()) {
                const QStringList parts = b->toolTip().split("<br>");
                if (parts.size() != 3 || !parts[0].startsWith("<b>")) continue;
                // (values and keys stay as the JSON and the CLI spell them: false, detector.background, 0..degree)
                QString text = plain(parts[1] + " " + parts[2]);
                text.replace(QRegularExpression("\\b(true|false)\\b|\\S*[._]\\S*"), " ");
                QString word;
                if (englishWord(text, &word))
                    bad << "tooltip of " + b->text() + ": " + plain(parts[1]).left(60) + "  [" + word + "]";
            }
            for (QLabel* l : w.findChildren<QLabel*>()) {
                QString word;
                if (!l->text().isEmpty() && !showsData(l) && englishWord(plain(l->text()), &word))
                    bad << "label " + plain(l->text()).left(80) + " (" + l->objectName() + ")  [" + word + "]";
            }
            for (QTableView* v : w.findChildren<QTableView*>()) {
                if (!v->model()) continue;
                for (int c = 0; c < v->model()->columnCount(); ++c) {
                    QString word;
                    const QString h = v->model()->headerData(c, Qt::Horizontal).toString();
                    if (englishWord(plain(h), &word)) bad << "header " + h + " (" + v->objectName() + ")  [" + word + "]";
                }
            }
            bad.removeDuplicates();
            for (const QString& b : bad) qWarning("English in the Chinese window: %s", qPrintable(b));
            QVERIFY2(bad.isEmpty(), qPrintable(QString("%1 English texts in the Chinese window (listed above)").arg(bad.size())));
            // The menus' own names in Chinese, the numbers as before (zh_CN writes 1,234.5 as C does).
            QCOMPARE(plain(w.menuBar()->actions().first()->text()).left(2), QString("文件"));
            QCOMPARE(QLocale().toString(1234.5, 'f', 1), QString("1,234.5"));
        }
        QCOMPARE(installLanguage("en"), QString("en"));
        MainWindow english;
        QCOMPARE(plain(english.menuBar()->actions().first()->text()), QString("File"));
    }

    /// The choice: English, Chinese, or the system's; anything else is the system's.
    void languageChoice() {
        QCOMPARE(resolveLanguage("en"), QString("en"));
        QCOMPARE(resolveLanguage("zh_CN"), QString("zh_CN"));
        const QString system = resolveLanguage(QString());
        QVERIFY(system == "en" || system == "zh_CN");
        QCOMPARE(resolveLanguage("xx"), system);
        // The program refuses a language it has not.
        const lwbtest::CliRun r = lwbtest::runProgram(LWB_GUI, {"--language", "fr", "--screenshot", m_dir.path() + "/x.png"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("--language fr"), qPrintable(r.err));
    }
};

QTEST_MAIN(TestTranslations)
#include "test_translations.moc"
