// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QList>
#include <QString>
#include <QTranslator>

// The languages the dashboard speaks, and switching between them while it
// runs. Installing a translator sends LanguageChange to every widget, which
// sets its texts again.
struct UiLanguage {
    QString code;       // "de"
    QString nativeName; // "Deutsch": what its speakers look for in a menu
};

// English first, then the translations embedded in the program.
const QList<UiLanguage> &uiLanguages();
bool isUiLanguage(const QString &code);
// The first of the system's preferred languages that the dashboard speaks,
// else English.
QString systemUiLanguage();

// Loads the dashboard's own catalogue for `code` (not "en") into `translator`.
bool loadUiTranslation(QTranslator &translator, const QString &code);

class LanguageSwitcher {
public:
    LanguageSwitcher() = default;
    ~LanguageSwitcher();
    LanguageSwitcher(const LanguageSwitcher &) = delete;
    LanguageSwitcher &operator=(const LanguageSwitcher &) = delete;

    // `code` is one of uiLanguages(), or empty to follow the system. Returns
    // the language now in effect.
    QString apply(const QString &code);
    QString current() const { return m_current; }

private:
    void removeTranslators();

    QTranslator m_dashboard;
    QTranslator m_qt; // Qt's own strings: standard buttons, file dialogs
    bool m_dashboardInstalled = false;
    bool m_qtInstalled = false;
    QString m_current = QStringLiteral("en");
};
