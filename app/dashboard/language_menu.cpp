// SPDX-License-Identifier: GPL-3.0-or-later
#include "language_menu.h"

#include <QAction>
#include <QActionGroup>
#include <QCoreApplication>
#include <QEvent>
#include <QMenu>
#include <QSettings>

LanguageMenu::LanguageMenu(QWidget *window) : QObject(window)
{
    const QString saved = QSettings().value("language").toString();
    m_switcher.apply(saved);
    m_group = new QActionGroup(this);
    m_systemDefault = m_group->addAction(QString());
    m_systemDefault->setData(QString());
    for (const UiLanguage &l : uiLanguages())
        m_group->addAction(l.nativeName)->setData(l.code);
    for (QAction *a : m_group->actions()) {
        a->setCheckable(true);
        a->setChecked(a->data().toString() == saved);
    }
    connect(m_group, &QActionGroup::triggered, this, [this](QAction *a) { setLanguage(a->data().toString()); });
    m_menu = new QMenu(window);
    m_menu->setObjectName("languageMenu");
    m_menu->addActions(m_group->actions());
    m_menu->insertSeparator(m_group->actions().value(1));
}

void LanguageMenu::setLanguage(const QString &code, bool remember)
{
    if (remember)
        QSettings().setValue("language", code);
    for (QAction *a : m_group->actions())
        a->setChecked(a->data().toString() == code);
    m_switcher.apply(code);
    // Installing a translator posts LanguageChange; deliver it now, so every
    // widget speaks the new language before this returns.
    QCoreApplication::sendPostedEvents(nullptr, QEvent::LanguageChange);
}

void LanguageMenu::retranslate()
{
    m_menu->setTitle(tr("&Language"));
    m_systemDefault->setText(tr("System default"));
}

#include "moc_language_menu.cpp"
