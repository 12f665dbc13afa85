#include "ui/kit/i18n.hpp"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QTranslator>

namespace lwb::ui {
namespace {
QString g_language = QStringLiteral("en");
QTranslator* g_own = nullptr;
QTranslator* g_qt = nullptr;
}  // namespace

QStringList translatedLanguages() { return {QStringLiteral("zh_CN")}; }

QString resolveLanguage(const QString& choice) {
    if (choice == QLatin1String("en")) return choice;
    if (translatedLanguages().contains(choice)) return choice;
    const QLocale sys = QLocale::system();
    if (sys.language() == QLocale::Chinese && sys.script() != QLocale::TraditionalChineseScript)
        return QStringLiteral("zh_CN");
    return QStringLiteral("en");
}

QString installLanguage(const QString& choice) {
    QCoreApplication* app = QCoreApplication::instance();
    for (QTranslator** t : {&g_own, &g_qt})
        if (*t) {
            if (app) app->removeTranslator(*t);
            delete *t;
            *t = nullptr;
        }
    const QString lang = resolveLanguage(choice);
    g_language = lang;
    QLocale::setDefault(lang == QLatin1String("en") ? QLocale(QLocale::English, QLocale::UnitedStates) : QLocale(lang));
    if (lang == QLatin1String("en") || !app) return lang;
    g_own = new QTranslator;
    if (!g_own->load(QStringLiteral(":/i18n/laserwb_%1.qm").arg(lang))) {
        qWarning("laserwb: no translation for %s in the program's resources: English", qPrintable(lang));
        delete g_own;
        g_own = nullptr;
        g_language = QStringLiteral("en");
        QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
        return g_language;
    }
    app->installTranslator(g_own);
    // Qt's own (standard buttons, file dialogs): Debian's qt6-translations-l10n; without it those
    // stay English and nothing else changes.
    g_qt = new QTranslator;
    if (g_qt->load(QStringLiteral("qtbase_%1").arg(lang), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        app->installTranslator(g_qt);
    else {
        delete g_qt;
        g_qt = nullptr;
    }
    return g_language;
}

QString currentLanguage() { return g_language; }

QString lowerExponent(const QLocale& locale, QString text) {
    const QString e = locale.exponential();
    if (!e.isEmpty() && e != QLatin1String("e")) text.replace(e, QStringLiteral("e"));
    return text;
}

QString schemaText(const std::string& text) {
    if (text.empty()) return QString();
    return QCoreApplication::translate("schema", text.c_str());
}

}  // namespace lwb::ui
