// SPDX-License-Identifier: GPL-3.0-or-later
#include "language_switcher.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>

namespace {
// Where qt_add_translations embeds the compiled .ts files (app/CMakeLists.txt).
constexpr char kTranslationPrefix[] = ":/i18n/roomba_dashboard_";
} // namespace

const QList<UiLanguage> &uiLanguages()
{
    static const QList<UiLanguage> languages{
        {QStringLiteral("en"), QStringLiteral("English")},
        {QStringLiteral("de"), QStringLiteral("Deutsch")},
        {QStringLiteral("es"), QStringLiteral("Español")},
    };
    return languages;
}

bool isUiLanguage(const QString &code)
{
    for (const UiLanguage &l : uiLanguages())
        if (l.code == code)
            return true;
    return false;
}

QString systemUiLanguage()
{
    for (const QString &tag : QLocale::system().uiLanguages()) {
        const QString code = tag.section(QLatin1Char('-'), 0, 0).toLower();
        if (isUiLanguage(code))
            return code;
    }
    return QStringLiteral("en");
}

bool loadUiTranslation(QTranslator &translator, const QString &code)
{
    return translator.load(kTranslationPrefix + code);
}

LanguageSwitcher::~LanguageSwitcher()
{
    removeTranslators();
}

void LanguageSwitcher::removeTranslators()
{
    if (m_dashboardInstalled)
        QCoreApplication::removeTranslator(&m_dashboard);
    if (m_qtInstalled)
        QCoreApplication::removeTranslator(&m_qt);
    m_dashboardInstalled = m_qtInstalled = false;
}

QString LanguageSwitcher::apply(const QString &code)
{
    const QString language = code.isEmpty() || !isUiLanguage(code) ? systemUiLanguage() : code;
    removeTranslators();
    m_current = QStringLiteral("en");
    if (language == QLatin1String("en")) // the source language needs no translator
        return m_current;
    if (m_qt.load(QStringLiteral("qtbase_") + language, QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        m_qtInstalled = QCoreApplication::installTranslator(&m_qt);
    if (loadUiTranslation(m_dashboard, language))
        m_dashboardInstalled = QCoreApplication::installTranslator(&m_dashboard);
    if (m_dashboardInstalled)
        m_current = language;
    else
        removeTranslators(); // all English rather than half
    return m_current;
}
