// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "language_switcher.h"

#include <QObject>

class QAction;
class QActionGroup;
class QMenu;
class QWidget;

// View → Language: "System default" and every language the dashboard
// speaks, each named in its own words, so nobody is lost in a foreign menu.
// Made first, before any widget, so every widget is built translated: it
// applies the language kept from the last run.
class LanguageMenu : public QObject {
    Q_OBJECT
public:
    explicit LanguageMenu(QWidget *window);

    QMenu *menu() const { return m_menu; }
    QString current() const { return m_switcher.current(); }
    // "de", "es", "en", or "" to follow the system. Applies at once;
    // `remember` keeps the choice for the next start.
    void setLanguage(const QString &code, bool remember = true);
    void retranslate();

private:
    LanguageSwitcher m_switcher;
    QActionGroup *m_group;
    QAction *m_systemDefault;
    QMenu *m_menu;
};
