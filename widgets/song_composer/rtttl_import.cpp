// SPDX-License-Identifier: GPL-3.0-or-later
#include "rtttl_import.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace {

bool validDuration(int d) { return d == 1 || d == 2 || d == 4 || d == 8 || d == 16 || d == 32; }
bool validOctave(int o) { return o >= 4 && o <= 7; }

// Semitone of a note letter above C, or -1.
int letterSemitone(QChar c)
{
    switch (c.toLower().toLatin1()) {
    case 'c': return 0;
    case 'd': return 2;
    case 'e': return 4;
    case 'f': return 5;
    case 'g': return 7;
    case 'a': return 9;
    case 'b':
    case 'h': return 11;
    default: return -1;
    }
}

} // namespace

std::optional<RtttlTune> parseRtttl(const QString &text, QString *error)
{
    auto fail = [error](const QString &why) {
        if (error)
            *error = QCoreApplication::translate("RtttlImport", "RTTTL: %1").arg(why);
        return std::nullopt;
    };
    const QStringList sections = text.trimmed().split(':');
    if (sections.size() != 3)
        return fail(QCoreApplication::translate("RtttlImport", "expected NAME:DEFAULTS:NOTES, e.g. \"Beep:d=4,o=5,b=120:c,e,g\""));

    RtttlTune tune;
    tune.name = sections.at(0).trimmed();
    int defDuration = 4, defOctave = 6, bpm = 63; // the format's own defaults
    for (const QString &raw : sections.at(1).split(',', Qt::SkipEmptyParts)) {
        const QString item = raw.trimmed().toLower();
        const qsizetype eq = item.indexOf('=');
        bool ok = false;
        const int value = eq > 0 ? item.mid(eq + 1).trimmed().toInt(&ok) : 0;
        const QString key = item.left(eq).trimmed();
        if (!ok)
            return fail(QCoreApplication::translate("RtttlImport", "default \"%1\" is not KEY=NUMBER").arg(raw.trimmed()));
        if (key == "d" && validDuration(value))
            defDuration = value;
        else if (key == "o" && validOctave(value))
            defOctave = value;
        else if (key == "b" && value >= 1 && value <= 900)
            bpm = value;
        else
            return fail(QCoreApplication::translate("RtttlImport", "default \"%1\" is not valid (d: 1..32, o: 4..7, b: 1..900)")
                            .arg(raw.trimmed()));
    }

    const QStringList items = sections.at(2).split(',', Qt::SkipEmptyParts);
    if (items.isEmpty())
        return fail(QCoreApplication::translate("RtttlImport", "the tune has no notes"));
    for (qsizetype i = 0; i < items.size(); ++i) {
        const QString item = items.at(i).trimmed().toLower();
        qsizetype pos = 0;
        // Past 999 a number is no duration or octave; stop there, before it overflows.
        auto readNumber = [&]() {
            int v = 0, digits = 0;
            while (pos < item.size() && item.at(pos).isDigit()) {
                v = std::min(v * 10 + item.at(pos++).digitValue(), 1000);
                ++digits;
            }
            return digits ? v : -1;
        };
        auto bad = [&](const QString &why) {
            return fail(QCoreApplication::translate("RtttlImport", "note %1 \"%2\": %3").arg(i + 1).arg(items.at(i).trimmed(), why));
        };
        int duration = readNumber();
        if (duration == -1)
            duration = defDuration;
        else if (!validDuration(duration))
            return bad(QCoreApplication::translate("RtttlImport", "duration must be 1, 2, 4, 8, 16 or 32"));
        if (pos >= item.size())
            return bad(QCoreApplication::translate("RtttlImport", "no note letter"));
        const QChar letter = item.at(pos++);
        const bool pause = letter == 'p';
        int semitone = pause ? 0 : letterSemitone(letter);
        if (semitone < 0)
            return bad(QCoreApplication::translate("RtttlImport", "\"%1\" is not a note (a..g, h) or pause (p)").arg(letter));
        if (pos < item.size() && item.at(pos) == '#') {
            ++semitone;
            ++pos;
        }
        bool dotted = false;
        if (pos < item.size() && item.at(pos) == '.') {
            dotted = true;
            ++pos;
        }
        int octave = readNumber();
        if (octave == -1)
            octave = defOctave;
        else if (!validOctave(octave))
            return bad(QCoreApplication::translate("RtttlImport", "octave must be 4..7"));
        if (pos < item.size() && item.at(pos) == '.') {
            dotted = true;
            ++pos;
        }
        if (pos != item.size())
            return bad(QCoreApplication::translate("RtttlImport", "unexpected \"%1\"").arg(item.mid(pos)));

        // A whole note lasts four beats.
        double seconds = 60.0 / bpm * 4.0 / duration;
        if (dotted)
            seconds *= 1.5;
        const long d64 = std::lround(seconds * 64.0);
        if (d64 < 1 || d64 > 255)
            return bad(QCoreApplication::translate("RtttlImport", "lasts %1/64 s at %2 beats per minute; a note lasts 1..255").arg(d64).arg(bpm));
        const int midi = pause ? oi::kRestNote : 12 * (octave + 1) + semitone;
        tune.notes.append({std::uint8_t(midi), std::uint8_t(d64)});
    }
    return tune;
}
