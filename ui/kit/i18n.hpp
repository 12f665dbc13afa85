#pragma once
// The interface language: the workbench's own translation (ui/i18n/laserwb_LANG.ts, compiled by
// lrelease into the resources) and Qt's for its standard dialogs and buttons. The CLI, the core's
// messages and every file written stay English.
#include <string>

#include <QLocale>
#include <QString>
#include <QStringList>

namespace lwb::ui {

/// The languages of the interface besides English, as settings and --language name them.
QStringList translatedLanguages();
/// The language `choice` means: "" or "system" = the system locale's when it is one of
/// translatedLanguages() (zh_CN for any Chinese locale of simplified script), else "en".
QString resolveLanguage(const QString& choice);
/// Installs the translators of resolveLanguage(choice) on the application (replacing earlier
/// ones) and sets the default QLocale to it; returns the language in effect. Call before the
/// first window is built: widgets take their text when they are made.
QString installLanguage(const QString& choice);
/// The language installLanguage put in effect ("en" before any call).
QString currentLanguage();
/// A number's text as `locale` wrote it with the exponent as the CLI and the files write it
/// ("1.148e+10"): Qt 6's en_US and zh_CN write "1.148E+10" whatever the format asked.
QString lowerExponent(const QLocale& locale, QString text);
/// The settings key of the language choice ("" = the system's).
inline constexpr const char* kLanguageSetting = "view/language";

/// A schema row's text (label, doc, a special value's meaning) in the interface language: the
/// "schema" context of the translation, whose entries ui/i18n/schema_strings.cpp lists for lupdate
/// (written by lwb-i18n-strings: `make translations`).
QString schemaText(const std::string& text);

}  // namespace lwb::ui
