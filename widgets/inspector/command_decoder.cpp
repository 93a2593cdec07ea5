// SPDX-License-Identifier: GPL-3.0-or-later
#include "command_decoder.h"

#include "command_encoder.h"
#include "oi_text.h"
#include "schedule.h"
#include "script_assembler.h"
#include "song.h"

#include <QCoreApplication>
#include <QRegularExpression>
#include <QStringList>

#include <string>

namespace {

std::size_t dataBytes(std::string_view layout)
{
    std::size_t n = 0;
    for (char c : layout)
        n += c == 'w' ? 2 : 1;
    return n;
}

bool isVariable(const oi::CommandSpec &spec) { return spec.layout == "*"; }

// The data bytes read as the layout says: 'b' unsigned, 'c' signed byte,
// 'w' signed 16-bit, high byte first.
std::vector<int> fieldValues(std::string_view layout, std::span<const std::uint8_t> data)
{
    std::vector<int> values;
    std::size_t at = 0;
    for (char c : layout) {
        if (c == 'w') {
            values.push_back(static_cast<std::int16_t>((data[at] << 8) | data[at + 1]));
            at += 2;
        } else if (c == 'c') {
            values.push_back(static_cast<std::int8_t>(data[at++]));
        } else {
            values.push_back(data[at++]);
        }
    }
    return values;
}

// Field names from the catalogue's usage text ("VELOCITY RADIUS|straight"
// gives "velocity", "radius"), or none where the usage does not name one
// field per layout character.
QStringList fieldNames(const oi::CommandSpec &spec)
{
    std::string_view usage = spec.usage;
    if (const auto bar = usage.find(" | "); bar != std::string_view::npos)
        usage = usage.substr(0, bar);
    std::string plain;
    int depth = 0;
    for (char c : usage) {
        if (c == '(')
            ++depth;
        else if (c == ')')
            --depth;
        else if (depth == 0)
            plain += c;
    }
    QStringList names;
    for (const QString &token : QString::fromStdString(plain).split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        QString name = token.section(QLatin1Char('|'), 0, 0).toLower().replace(QLatin1Char('-'), QLatin1Char(' '));
        bool isNumber = false;
        name.toInt(&isNumber);
        if (isNumber || name.isEmpty())
            return {};
        names << name;
    }
    if (names.size() != qsizetype(spec.layout.size()))
        return {};
    return names;
}

QString radiusNote(int radius)
{
    if (radius == oi::kRadiusStraight || radius == oi::kRadiusStraightAlt || radius == -32768)
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

std::optional<std::size_t> CommandDecoder::commandLength(const oi::CommandSpec &spec,
                                                         std::span<const std::uint8_t> bytes)
{
    if (!isVariable(spec))
        return 1 + dataBytes(spec.layout);
    switch (spec.command) {
    case oi::Command::Song: // [140][slot][length][note duration]...
        if (bytes.size() < 3)
            return std::nullopt;
        return 3 + 2 * std::size_t(bytes[2]);
    case oi::Command::Stream: // [148 or 149][count][id]...
    case oi::Command::QueryList:
    case oi::Command::Script: // [152][length][byte]... (ERRATA 11: length counts bytes)
        if (bytes.size() < 2)
            return std::nullopt;
        return 2 + std::size_t(bytes[1]);
    default:
        return 1;
    }
}

CommandDecoder::Decoded CommandDecoder::decodeOne(std::span<const std::uint8_t> bytes) const
{
    Decoded d;
    d.length = bytes.size();
    if (bytes.empty())
        return d;
    d.spec = oi::commandSpecForOpcode(*m_profile, bytes[0]);
    if (!d.spec) {
        d.meaning = QCoreApplication::translate("CommandDecoder", "not a command of the %1").arg(oitext::fromView(m_profile->name));
        return d;
    }
    const QString title = oitext::fromView(d.spec->title);
    const std::optional<std::size_t> length = commandLength(*d.spec, bytes);
    if (!length) {
        d.status = Status::Incomplete;
        d.meaning = QCoreApplication::translate("CommandDecoder", "%1, incomplete: its count byte is missing").arg(title);
        return d;
    }
    if (*length > bytes.size()) {
        d.status = Status::Incomplete;
        d.meaning = QCoreApplication::translate("CommandDecoder", "%1, incomplete: %2 of %3 data bytes")
                        .arg(title)
                        .arg(bytes.size() - 1)
                        .arg(*length - 1);
        return d;
    }
    d.status = Status::Complete;
    d.length = *length;
    d.meaning = describe(*d.spec, bytes.subspan(1, *length - 1));
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

QString CommandDecoder::describe(const oi::CommandSpec &spec, std::span<const std::uint8_t> data) const
{
    using C = oi::Command;
    const QString title = oitext::fromView(spec.title);
    switch (spec.command) {
    case C::Song: {
        QStringList notes;
        for (std::size_t i = 2; i + 1 < data.size(); i += 2) {
            const oi::SongNote note{data[i], data[i + 1]};
            const QString name = note.isRest() ? QCoreApplication::translate("CommandDecoder", "rest")
                                               : QString::fromStdString(oi::midiNoteName(note.midi));
            notes << QStringLiteral("%1/%2").arg(name).arg(note.duration);
        }
        return QCoreApplication::translate("CommandDecoder", "%1 slot %2, %3%4")
            .arg(title)
            .arg(data[0])
            .arg(countText(data[1], QCoreApplication::translate("CommandDecoder", "%n note", nullptr, data[1]),
                           QCoreApplication::translate("CommandDecoder", "%n notes", nullptr, data[1])))
            .arg(notes.isEmpty() ? QString() : QStringLiteral(": ") + notes.join(QLatin1Char(' ')));
    }
    case C::Stream:
    case C::QueryList: {
        QStringList ids;
        for (std::size_t i = 1; i < data.size(); ++i)
            ids << packetLabel(data[i]);
        return QStringLiteral("%1 %2%3")
            .arg(title, countText(data[0], QCoreApplication::translate("CommandDecoder", "%n packet", nullptr, data[0]),
                                  QCoreApplication::translate("CommandDecoder", "%n packets", nullptr, data[0])))
            .arg(ids.isEmpty() ? QString() : QStringLiteral(": ") + ids.join(QStringLiteral(", ")));
    }
    case C::Script: {
        const auto body = data.subspan(1);
        const auto text = oi::disassembleScript(*m_profile, body);
        return QStringLiteral("%1 %2%3")
            .arg(title, countText(body.size(), QCoreApplication::translate("CommandDecoder", "%n byte", nullptr, int(body.size())),
                                  QCoreApplication::translate("CommandDecoder", "%n bytes", nullptr, int(body.size()))))
            .arg(text && !text->empty() ? QStringLiteral(": ") + QString::fromStdString(*text) : QString());
    }
    default:
        break;
    }

    const std::vector<int> v = fieldValues(spec.layout, data);
    switch (spec.command) {
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
    const QStringList names = fieldNames(spec);
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!names.isEmpty())
            text += QLatin1Char(' ') + names[qsizetype(i)];
        text += QLatin1Char(' ') + QString::number(v[i]);
    }
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
    const oi::CommandEncoder encoder(*m_profile);
    std::size_t at = 0;
    while (at < all.size()) {
        const auto rest = all.subspan(at);
        const oi::CommandSpec *spec = oi::commandSpecForOpcode(*m_profile, rest[0]);
        if (!spec)
            return fail(QCoreApplication::translate("CommandDecoder", "Byte %1: %2 is not an opcode of the %3.")
                            .arg(at + 1)
                            .arg(rest[0])
                            .arg(oitext::fromView(m_profile->name)));
        const QString title = QStringLiteral("%1 (%2)").arg(oitext::fromView(spec->title)).arg(spec->opcode);
        const std::optional<std::size_t> length = commandLength(*spec, rest);
        if (!length)
            return fail(spec->command == oi::Command::Song
                            ? QCoreApplication::translate("CommandDecoder", "%1 needs its song number and length bytes.").arg(title)
                            : QCoreApplication::translate("CommandDecoder", "%1 needs its count byte.").arg(title));
        if (*length > rest.size())
            return fail(QCoreApplication::translate("CommandDecoder", "%1 takes %2 data bytes; got %3.")
                            .arg(title)
                            .arg(*length - 1)
                            .arg(rest.size() - 1));

        // The values must be ones the encoder itself would send.
        const auto data = rest.subspan(1, *length - 1);
        std::vector<std::string> args;
        if (isVariable(*spec)) {
            for (std::uint8_t b : data)
                args.push_back(std::to_string(b));
        } else {
            for (int value : fieldValues(spec->layout, data))
                args.push_back(std::to_string(value));
        }
        const oi::EncodeResult encoded = oi::encodeCommand(encoder, spec->name, args);
        if (!encoded)
            return fail(QCoreApplication::translate("CommandDecoder", "%1: %2").arg(title, QString::fromStdString(encoded.error().describe())));
        if (!std::equal(encoded->begin(), encoded->end(), rest.begin(), rest.begin() + std::ptrdiff_t(*length))
            || encoded->size() != *length)
            return fail(QCoreApplication::translate("CommandDecoder", "%1: these bytes do not form the command the robot expects.").arg(title));
        at += *length;
    }
    return bytes;
}
