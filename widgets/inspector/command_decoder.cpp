// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_decoder.h"

#include "command_catalog.h"
#include "oi_text.h"
#include "schedule.h"
#include "script_assembler.h"
#include "song.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

#include <string>

namespace {

// "right-velocity" as the inspector shows it: "right velocity".
QString fieldLabel(std::string_view name) { return oitext::fromView(name).replace(QLatin1Char('-'), QLatin1Char(' ')); }

QString radiusNote(int radius)
{
    if (radius == oi::kRadiusStraight || radius == oi::kRadiusStraightAlt)
        return QCoreApplication::translate("CommandDecoder", " (straight)");
    if (radius == oi::kRadiusTurnInPlaceClockwise)
        return QCoreApplication::translate("CommandDecoder", " (turn in place clockwise)");
    if (radius == oi::kRadiusTurnInPlaceCounterClockwise)
        return QCoreApplication::translate("CommandDecoder", " (turn in place counter-clockwise)");
    return {};
}

// English needs no translation file to say "1 note" but "2 notes"; other
// languages give their own plural forms for both sources.
QString countText(std::size_t n, const QString &one, const QString &many) { return n == 1 ? one : many; }

} // namespace

QString CommandDecoder::packetLabel(int id) const
{
    if (const oi::PacketInfo *info = m_profile->packet(id))
        return QStringLiteral("%1 (%2)").arg(oitext::packetName(*info)).arg(id);
    if (const oi::PacketGroup *g = m_profile->group(id))
        return QCoreApplication::translate("CommandDecoder", "group %1 (packets %2..%3)").arg(id).arg(g->first).arg(g->last);
    return QCoreApplication::translate("CommandDecoder", "packet %1 (not on the %2)").arg(id).arg(oitext::fromView(m_profile->name));
}

CommandDecoder::Decoded CommandDecoder::decodeOne(std::span<const std::uint8_t> bytes) const
{
    Decoded d;
    d.length = bytes.size();
    if (bytes.empty())
        return d;
    // As the robot reads it: a value out of range is still shown.
    const oi::CommandDecode read = oi::readCommand(*m_profile, bytes);
    switch (read.status) {
    case oi::CommandDecode::Status::Error:
        d.meaning = QCoreApplication::translate("CommandDecoder", "not a command of the %1").arg(oitext::fromView(m_profile->name));
        return d;
    case oi::CommandDecode::Status::NeedMore: {
        const oi::Command command = read.command.command;
        const QString title = oitext::fromView(oi::commandSpec(command).title);
        d.status = Status::Incomplete;
        if (oi::hasVariablePart(command) && bytes.size() < oi::commandHeaderLength(command))
            d.meaning = QCoreApplication::translate("CommandDecoder", "%1, incomplete: its count byte is missing").arg(title);
        else
            d.meaning = QCoreApplication::translate("CommandDecoder", "%1, incomplete: %2 of %3 data bytes")
                            .arg(title)
                            .arg(bytes.size() - 1)
                            .arg(read.length - 1);
        return d;
    }
    case oi::CommandDecode::Status::Command:
        break;
    }
    d.status = Status::Complete;
    d.length = read.length;
    d.meaning = describe(read.command);
    d.command = read.command;
    return d;
}

std::vector<CommandDecoder::Decoded> CommandDecoder::decode(std::span<const std::uint8_t> bytes) const
{
    std::vector<Decoded> out;
    std::size_t at = 0;
    while (at < bytes.size()) {
        Decoded d = decodeOne(bytes.subspan(at));
        at += d.length;
        out.push_back(std::move(d));
    }
    return out;
}

QString CommandDecoder::describe(const oi::OiCommand &command) const
{
    using C = oi::Command;
    const oi::CommandSpec &spec = oi::commandSpec(command.command);
    const QString title = oitext::fromView(spec.title);
    const std::vector<int> &v = command.fields;
    const oi::Bytes &data = command.data;
    switch (command.command) {
    case C::Song: {
        QStringList notes;
        for (std::size_t i = 0; i + 1 < data.size(); i += 2) {
            const oi::SongNote note{data[i], data[i + 1]};
            const QString name = note.isRest() ? QCoreApplication::translate("CommandDecoder", "rest")
                                               : QString::fromStdString(oi::midiNoteName(note.midi));
            notes << QStringLiteral("%1/%2").arg(name).arg(note.duration);
        }
        const int count = int(data.size() / 2);
        return QCoreApplication::translate("CommandDecoder", "%1 slot %2, %3%4")
            .arg(title)
            .arg(v[0])
            .arg(countText(std::size_t(count), QCoreApplication::translate("CommandDecoder", "%n note", nullptr, count),
                           QCoreApplication::translate("CommandDecoder", "%n notes", nullptr, count)))
            .arg(notes.isEmpty() ? QString() : QStringLiteral(": ") + notes.join(QLatin1Char(' ')));
    }
    case C::Stream:
    case C::QueryList: {
        QStringList ids;
        for (std::uint8_t id : data)
            ids << packetLabel(id);
        const int count = int(data.size());
        return QStringLiteral("%1 %2%3")
            .arg(title, countText(data.size(), QCoreApplication::translate("CommandDecoder", "%n packet", nullptr, count),
                                  QCoreApplication::translate("CommandDecoder", "%n packets", nullptr, count)))
            .arg(ids.isEmpty() ? QString() : QStringLiteral(": ") + ids.join(QStringLiteral(", ")));
    }
    case C::Script: {
        const auto text = oi::disassembleScript(*m_profile, data);
        return QStringLiteral("%1 %2%3")
            .arg(title, countText(data.size(), QCoreApplication::translate("CommandDecoder", "%n byte", nullptr, int(data.size())),
                                  QCoreApplication::translate("CommandDecoder", "%n bytes", nullptr, int(data.size()))))
            .arg(text && !text->empty() ? QStringLiteral(": ") + QString::fromStdString(*text) : QString());
    }
    case C::Baud: {
        const int baud = oi::baudForCode(v[0]);
        return QCoreApplication::translate("CommandDecoder", "%1 code %2%3")
            .arg(title)
            .arg(v[0])
            .arg(baud > 0 ? QStringLiteral(" (%1 bps)").arg(baud) : QString());
    }
    case C::Drive:
        return QCoreApplication::translate("CommandDecoder", "%1 velocity %2 radius %3%4").arg(title).arg(v[0]).arg(v[1]).arg(radiusNote(v[1]));
    case C::Sensors:
        return QStringLiteral("%1 %2").arg(title, packetLabel(v[0]));
    case C::PauseResumeStream:
        return QStringLiteral("%1: %2")
            .arg(title, v[0] == 0   ? QCoreApplication::translate("CommandDecoder", "pause")
                        : v[0] == 1 ? QCoreApplication::translate("CommandDecoder", "resume")
                                    : QCoreApplication::translate("CommandDecoder", "state %1").arg(v[0]));
    case C::DigitLedsAscii: {
        QString text;
        for (int c : v)
            text += c >= 32 && c < 127 ? QChar(c) : QChar(QChar::ReplacementCharacter);
        return QStringLiteral("%1 \"%2\"").arg(title, text);
    }
    case C::Schedule: {
        if ((v[0] & 0x7F) == 0)
            return QCoreApplication::translate("CommandDecoder", "%1 off").arg(title);
        QStringList days;
        for (int day = 0; day < 7; ++day)
            if (v[0] & (1 << day))
                days << QStringLiteral("%1 %2:%3")
                            .arg(oitext::fromView(oi::weekdayShortName(oi::Weekday(day))))
                            .arg(v[1 + 2 * day])
                            .arg(v[2 + 2 * day], 2, 10, QLatin1Char('0'));
        return QStringLiteral("%1 %2").arg(title, days.join(QStringLiteral(", ")));
    }
    case C::SetDayTime:
        if (v[0] >= 0 && v[0] <= 6)
            return QStringLiteral("%1 %2 %3:%4")
                .arg(title, oitext::fromView(oi::weekdayName(oi::Weekday(v[0]))))
                .arg(v[1])
                .arg(v[2], 2, 10, QLatin1Char('0'));
        break;
    default:
        break;
    }

    QString text = title;
    const auto names = oi::commandFieldNames(command.command);
    for (std::size_t i = 0; i < v.size(); ++i)
        text += QStringLiteral(" %1 %2").arg(fieldLabel(names[i])).arg(v[i]);
    return text;
}

std::optional<QByteArray> CommandDecoder::parseRaw(const QString &text, QString *error) const
{
    auto fail = [error](const QString &why) -> std::optional<QByteArray> {
        if (error)
            *error = why;
        return std::nullopt;
    };
    static const QRegularExpression separators(QStringLiteral("[\\s,]+"));
    const QStringList tokens = text.split(separators, Qt::SkipEmptyParts);
    if (tokens.isEmpty())
        return fail(QCoreApplication::translate("CommandDecoder", "Type the bytes to send, for example 128 131 or 0x80 0x83."));

    QByteArray bytes;
    for (qsizetype i = 0; i < tokens.size(); ++i) {
        long long value = 0;
        if (!oi::parseInteger(tokens[i].toStdString(), value))
            return fail(QCoreApplication::translate("CommandDecoder", "Byte %1: \u201c%2\u201d is not a number.").arg(i + 1).arg(tokens[i]));
        if (value < 0 || value > 255)
            return fail(QCoreApplication::translate("CommandDecoder", "Byte %1: %2 is outside 0..255.").arg(i + 1).arg(tokens[i]));
        bytes.append(char(value));
    }

    const auto all = std::span(reinterpret_cast<const std::uint8_t *>(bytes.constData()),
                               std::size_t(bytes.size()));
    std::size_t at = 0;
    while (at < all.size()) {
        const auto rest = all.subspan(at);
        // The values must be ones the command encoder itself would send.
        const oi::CommandDecode d = oi::decodeCommand(*m_profile, rest);
        if (d.status == oi::CommandDecode::Status::Command) {
            at += d.length;
            continue;
        }
        if (d.status == oi::CommandDecode::Status::Error && d.length == 0)
            return fail(QCoreApplication::translate("CommandDecoder", "Byte %1: %2 is not an opcode of the %3.")
                            .arg(at + 1)
                            .arg(d.error.value.value_or(0))
                            .arg(oitext::fromView(m_profile->name)));
        const oi::Command command = d.command.command;
        const QString title = QStringLiteral("%1 (%2)").arg(oitext::fromView(oi::commandSpec(command).title))
                                  .arg(oi::commandSpec(command).opcode);
        if (d.status == oi::CommandDecode::Status::Error)
            return fail(QCoreApplication::translate("CommandDecoder", "%1: %2").arg(title, QString::fromStdString(d.error.describe())));
        if (oi::hasVariablePart(command) && rest.size() < oi::commandHeaderLength(command))
            return fail(command == oi::Command::Song
                            ? QCoreApplication::translate("CommandDecoder", "%1 needs its song number and length bytes.").arg(title)
                            : QCoreApplication::translate("CommandDecoder", "%1 needs its count byte.").arg(title));
        return fail(QCoreApplication::translate("CommandDecoder", "%1 takes %2 data bytes; got %3.")
                        .arg(title)
                        .arg(d.length - 1)
                        .arg(rest.size() - 1));
    }
    return bytes;
}
