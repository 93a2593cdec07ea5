// SPDX-License-Identifier: GPL-3.0-or-later
// The German and Spanish translations are complete, keep their placeholders,
// cover every name in the Open Interface tables, and are embedded.
#include "language_switcher.h"
#include "ir_character.h"
#include "robot_mode.h"
#include "robot_profile.h"

#include <QCoreApplication>
#include <QFile>
#include <QRegularExpression>
#include <QTest>
#include <QTranslator>
#include <QXmlStreamReader>

namespace {
struct Message {
    QString context;
    QString source;
    QStringList translations; // one, or the plural forms
    bool finished = true;
};

QList<Message> readTs(const QString &path)
{
    QList<Message> out;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        qFatal("cannot read %s", qPrintable(path));
    QXmlStreamReader xml(&file);
    QString context;
    Message m;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const auto name = xml.name();
        if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            m = Message{context, {}, {}, true};
        } else if (name == QLatin1String("source")) {
            m.source = xml.readElementText();
        } else if (name == QLatin1String("translation")) {
            m.finished = xml.attributes().value("type").isEmpty();
            // Either text, or numerusform children.
            QString text;
            while (!(xml.isEndElement() && xml.name() == QLatin1String("translation")) && !xml.atEnd()) {
                xml.readNext();
                if (xml.isCharacters())
                    text += xml.text();
                else if (xml.isStartElement() && xml.name() == QLatin1String("numerusform"))
                    m.translations << xml.readElementText();
            }
            if (m.translations.isEmpty())
                m.translations << text;
            out << m;
        }
    }
    if (xml.hasError())
        qFatal("%s: %s", qPrintable(path), qPrintable(xml.errorString()));
    return out;
}

QStringList placeholders(const QString &text)
{
    QStringList found;
    static const QRegularExpression re(QStringLiteral("%L?[0-9n]"));
    for (const QRegularExpressionMatch &m : re.globalMatch(text))
        found << m.captured();
    found.sort();
    found.removeDuplicates();
    return found;
}
// A run of four words of the English source left in the translation, with
// at least two plain lower-case words among them (names such as "Digit LEDs
// Raw" or "Create 2" stay as they are): half a sentence not translated.
// Markup, quoted keys, identifiers, command-line options and units are not
// words of either language.
QString englishRun(const QString &original, const QString &translation)
{
    static const QRegularExpression notWords(QStringLiteral("<[^>]*>|\"[^\"]*\"|\\S*[-_]\\S*"));
    const QString source = QString(original).replace(notWords, QStringLiteral("\x01"));
    static const QRegularExpression word(QStringLiteral("[A-Za-z][A-Za-z']*"));
    QList<QRegularExpressionMatch> words;
    for (const QRegularExpressionMatch &m : word.globalMatch(source))
        words << m;
    for (qsizetype i = 0; i + 4 <= words.size(); ++i) {
        int plain = 0;
        for (qsizetype k = i; k < i + 4; ++k)
            plain += words[k].captured() == words[k].captured().toLower() && words[k].capturedLength() > 2;
        if (plain < 2)
            continue;
        const qsizetype from = words[i].capturedStart();
        const QString run = source.mid(from, words[i + 3].capturedEnd() - from);
        if (!run.contains(QChar(1)) && translation.contains(run))
            return run;
    }
    return {};
}
} // namespace

class TestTranslations : public QObject {
    Q_OBJECT
private slots:
    void complete_data()
    {
        QTest::addColumn<QString>("code");
        QTest::newRow("de") << "de";
        QTest::newRow("es") << "es";
    }

    void complete()
    {
        QFETCH(QString, code);
        const QList<Message> messages = readTs(QStringLiteral(ROOMBA_TRANSLATIONS_DIR "/roomba_dashboard_%1.ts").arg(code));
        QVERIFY(messages.size() > 800);
        QStringList problems;
        for (const Message &m : messages) {
            const QString where = m.context + ": " + m.source;
            if (!m.finished)
                problems << "unfinished: " + where;
            for (const QString &t : m.translations) {
                if (t.trimmed().isEmpty())
                    problems << "empty: " + where;
                // %n may be left out of a singular form ("ein Lied"); every other one stays.
                QStringList want = placeholders(m.source), have = placeholders(t);
                if (m.translations.size() > 1) {
                    want.removeAll("%n");
                    have.removeAll("%n");
                }
                if (want != have)
                    problems << QString("placeholders %1 became %2: %3").arg(want.join(','), have.join(','), where);
                if (m.source.count('&') == 1 && m.source.contains(QRegularExpression("&\\w")) && t.count('&') != 1)
                    problems << "accelerator lost: " + where;
                if (const QString run = englishRun(m.source, t); !run.isEmpty())
                    problems << QString("English left in the translation (\"%1\"): %2").arg(run, where);
            }
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
    }

    // The check above finds a message half translated, and lets names be.
    void englishRunIsFound()
    {
        QCOMPARE(englishRun("⚠ Raw (163) does not work in current Create 2 firmware. It is sent anyway.",
                            "⚠ Raw (163) does not work in current Create 2 firmware. Es wird trotzdem gesendet."),
                 QString("Raw (163) does not work"));
        QCOMPARE(englishRun("⚠ Raw (163) does not work in current Create 2 firmware.",
                            "⚠ Raw (163) funktioniert mit der aktuellen Firmware von Create 2 nicht."),
                 QString());
        QCOMPARE(englishRun("Digit LEDs Raw (163) and Digit LEDs ASCII (164)", "Digit LEDs Raw (163) und Digit LEDs ASCII (164)"),
                 QString());
    }

    // A robot beside a bridge says why it stopped as words a program reads;
    // the window shows them in its own language, never the bridge's English.
    void aBridgesCauseIsShownInTheWindowsLanguage()
    {
        QTranslator german;
        QVERIFY(german.load(":/i18n/roomba_dashboard_de"));
        QCoreApplication::installTranslator(&german);
        const QString said = RobotMode::shortReasonOf({"safety", "cliff_front_left"});
        QCoreApplication::removeTranslator(&german);
        QCOMPARE(said, QString("Abgrund (vorne links)"));
    }

    // Every packet, bit and remote-button name of every profile is translated
    // in the embedded catalogue.
    void openInterfaceNames_data() { complete_data(); }
    void openInterfaceNames()
    {
        QFETCH(QString, code);
        QTranslator translator;
        QVERIFY2(translator.load(":/i18n/roomba_dashboard_" + code), "the .qm is not embedded");
        QStringList missing;
        auto check = [&](const char *context, std::string_view name) {
            const std::string text(name);
            if (translator.translate(context, text.c_str()).isEmpty())
                missing << QString("%1: %2").arg(context, QString::fromStdString(text));
        };
        for (oi::ProfileId id : {oi::ProfileId::Roomba500, oi::ProfileId::Create2, oi::ProfileId::Create1}) {
            const oi::RobotProfile &p = oi::profile(id);
            for (const oi::PacketInfo &info : p.packets()) {
                check("PacketName", info.name);
                for (const oi::BitMeaning &bit : p.bits(info.id))
                    check("BitName", bit.name);
            }
            for (int v = 0; v < 256; ++v) {
                const oi::IrCharacter ir = oi::decodeIrCharacter(p, std::uint8_t(v));
                using Kind = oi::IrCharacter::Kind;
                if (ir.kind == Kind::None || ir.kind == Kind::Remote || ir.kind == Kind::VirtualWall)
                    check("InfraredName", ir.name());
            }
        }
        missing.removeDuplicates();
        QVERIFY2(missing.isEmpty(), qPrintable(missing.join('\n')));
    }

    void switcherFallsBackToEnglish()
    {
        LanguageSwitcher switcher;
        QCOMPARE(switcher.apply("de"), QString("de"));
        QCOMPARE(QCoreApplication::translate("MainWindow", "Modes"), QString("Modi"));
        QCOMPARE(switcher.apply("xx"), systemUiLanguage()); // not offered: the system's choice
        QCOMPARE(switcher.apply("en"), QString("en"));
        QCOMPARE(QCoreApplication::translate("MainWindow", "Modes"), QString("Modes"));
    }
};

QTEST_MAIN(TestTranslations)
#include "tst_translations.moc"
