// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// A translator that marks every string it translates, so that a test can find
// visible text that skipped tr() or was not set again on LanguageChange.

#include <QAbstractButton>
#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QStringList>
#include <QTabWidget>
#include <QTranslator>
#include <QWidget>

inline constexpr QChar kPseudoOpen(0x27E6);  // ⟦
inline constexpr QChar kPseudoClose(0x27E7); // ⟧

class PseudoTranslator : public QTranslator {
public:
    QString translate(const char *, const char *source, const char *, int n) const override
    {
        QString text = QString::fromUtf8(source);
        if (n >= 0)
            text.replace(QLatin1String("%n"), QString::number(n));
        return kPseudoOpen + text + kPseudoClose;
    }
    bool isEmpty() const override { return false; }
};

// Text a reader sees that should have gone through a translator: it has
// letters, outside markup, and no pseudo mark.
inline bool looksUntranslated(const QString &text)
{
    QString plain = text;
    plain.remove(QRegularExpression(QStringLiteral("<[^>]*>")));
    plain.remove(QRegularExpression(QStringLiteral("&[a-z]+;")));
    if (plain.contains(kPseudoOpen))
        return false;
    for (QChar c : plain)
        if (c.isLetter())
            return true;
    return false;
}

// Every visible text under `root` (labels, buttons, group titles, tabs, combo
// items, placeholders, tool tips, accessible names) that looks untranslated,
// as "ClassName 'objectName': text". `allowed` lists texts that are never
// translated: brand names, units, "OI".
inline QStringList untranslatedTexts(QWidget *root, const QStringList &allowed = {})
{
    QStringList found;
    auto check = [&](QWidget *w, const QString &text) {
        if (!text.isEmpty() && looksUntranslated(text) && !allowed.contains(text))
            found << QStringLiteral("%1 '%2': %3").arg(QLatin1String(w->metaObject()->className()),
                                                      w->objectName(), text);
    };
    QList<QWidget *> widgets = root->findChildren<QWidget *>();
    widgets.prepend(root);
    for (QWidget *w : widgets) {
        if (!w->isVisibleTo(root) && w != root)
            continue;
        // Qt's own parts (a dock's float and close buttons) follow Qt's translations.
        if (w->objectName().startsWith(QLatin1String("qt_")))
            continue;
        check(w, w->toolTip());
        check(w, w->accessibleName());
        if (auto *label = qobject_cast<QLabel *>(w))
            check(w, label->text());
        else if (auto *button = qobject_cast<QAbstractButton *>(w))
            check(w, button->text());
        else if (auto *group = qobject_cast<QGroupBox *>(w))
            check(w, group->title());
        else if (auto *dock = qobject_cast<QDockWidget *>(w))
            check(w, dock->windowTitle());
        else if (auto *edit = qobject_cast<QLineEdit *>(w))
            check(w, edit->placeholderText());
        if (auto *tabs = qobject_cast<QTabWidget *>(w))
            for (int i = 0; i < tabs->count(); ++i)
                check(w, tabs->tabText(i));
        if (auto *combo = qobject_cast<QComboBox *>(w); combo && !combo->isEditable())
            for (int i = 0; i < combo->count(); ++i)
                check(w, combo->itemText(i));
    }
    return found;
}

// Installs a PseudoTranslator for the life of this object; installing and
// removing it sends LanguageChange to every widget, as the language menu does.
class ScopedPseudoTranslation {
public:
    ScopedPseudoTranslation() { QCoreApplication::installTranslator(&m_translator); }
    ~ScopedPseudoTranslation() { QCoreApplication::removeTranslator(&m_translator); }
    ScopedPseudoTranslation(const ScopedPseudoTranslation &) = delete;
    ScopedPseudoTranslation &operator=(const ScopedPseudoTranslation &) = delete;

private:
    PseudoTranslator m_translator;
};
