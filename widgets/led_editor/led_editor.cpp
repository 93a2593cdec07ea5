// SPDX-License-Identifier: GPL-3.0-or-later
// The LED editor: the state of its controls, and the commands it makes of them.
#include "led_editor.h"

#include "seven_segment_display.h"
#include "seven_segment_font.h"

#include <QCheckBox>
#include <QEvent>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSlider>
#include <QStringList>

namespace {

QString decimal(const oi::Bytes &bytes)
{
    QStringList parts;
    for (std::uint8_t b : bytes)
        parts << QString::number(b);
    return parts.join(' ');
}

QString fromStd(const std::string &text) { return QString::fromStdString(text); }

} // namespace

void LedEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void LedEditor::retranslateUi()
{
    m_live->setText(tr("Live"));
    m_live->setToolTip(tr("Send changes as you make them, at most every %1 ms").arg(kLiveIntervalMs));
    m_apply->setText(tr("Apply"));
    m_willSend->setText(tr("Will send:"));

    m_digitsGroup->setTitle(tr("7-segment display (163, 164)"));
    m_segments->setToolTip(tr("Click a segment to switch it on or off"));
    m_segments->setAccessibleName(tr("Segment editor"));
    m_clear->setText(tr("Clear"));
    m_clear->setToolTip(tr("Switch every segment off"));
    m_asciiText->setPlaceholderText(tr("up to 4 characters"));
    m_asciiText->setAccessibleName(tr("Text for the display"));
    m_asciiPreview->setToolTip(tr("The robot's approximation of the text"));
    m_asciiPreview->setAccessibleName(tr("What the robot shows"));
    m_rawTitle->setText(tr("<b>Segments</b> (Digit LEDs Raw, 163): click to switch"));
    m_asciiTitle->setText(tr("<b>Text</b> (Digit LEDs ASCII, 164)"));
    m_asciiCaption->setText(tr("What the robot shows:"));
    bool refused = false;
    m_asciiMessage->setText(asciiProblem(m_asciiText->text(), &refused));

    m_ledsGroup->setTitle(tr("LEDs (139)"));
    // The SCI puts other LEDs on the same four bits (1, 2, 4, 8).
    const bool sci = m_profile && m_profile->caps.panel == oi::ButtonPanel::MaxCleanSpotPower;
    m_debris->setText(sci ? tr("Dirt Detect") : tr("Debris"));
    m_spot->setText(sci ? tr("Max") : tr("Spot"));
    m_dock->setText(sci ? tr("Clean") : tr("Dock"));
    m_checkRobot->setText(sci ? tr("Spot") : tr("Check Robot"));
    m_play->setText(tr("Play"));
    m_advance->setText(tr("Advance"));
    m_colour->setToolTip(tr("0 green … 255 red"));
    m_colour->setAccessibleName(tr("Power colour"));
    m_intensity->setAccessibleName(tr("Intensity"));
    m_swatch->setToolTip(tr("The power LED as set"));
    m_swatch->setAccessibleName(tr("Power LED"));
    m_colourLabel->setText(tr("Power colour"));
    m_greenLabel->setText(tr("green"));
    m_redLabel->setText(tr("red"));
    m_intensityLabel->setText(tr("Intensity"));
    m_offLabel->setText(tr("off"));
    m_fullLabel->setText(tr("full"));

    m_schedulingGroup->setTitle(tr("Scheduling LEDs (162)"));
    static const char *const kDays[] = {QT_TR_NOOP("Sun"), QT_TR_NOOP("Mon"), QT_TR_NOOP("Tue"), QT_TR_NOOP("Wed"),
                                        QT_TR_NOOP("Thu"), QT_TR_NOOP("Fri"), QT_TR_NOOP("Sat")};
    for (int day = 0; day < 7; ++day)
        m_weekdays[day]->setText(tr(kDays[day]));
    m_schedule->setText(tr("Schedule"));
    m_clock->setText(tr("Clock"));
    m_am->setText(tr("AM"));
    m_pm->setText(tr("PM"));
    m_colon->setText(tr("Colon"));

    // The profile's name is a brand; only the sentence around it is translated.
    const QString robot = QString::fromUtf8(m_profile->name.data(), m_profile->name.size());
    m_digitsReason->setText(tr("The %1 has no 7-segment display: Digit LEDs Raw (163) and Digit LEDs "
                               "ASCII (164) are Roomba 500 / Create 2 only.")
                                .arg(robot));
    const oi::CommandEncoder encoder(*m_profile);
    // Shown where the encoder warns (ERRATA 9), in words of its own so that it translates whole.
    m_rawWarning->setText(tr("⚠ Digit LEDs Raw (163) does not work in current Create 2 and Roomba 500/600 firmware. "
                             "It is sent anyway; use Text (164) to be sure."));
    if (const auto refusedScheduling = encoder.refuse(oi::Command::SchedulingLeds))
        m_schedulingReason->setText(tr("%1.").arg(fromStd(refusedScheduling->message)));
    refresh();
}

void LedEditor::setProfile(const oi::RobotProfile &profile)
{
    m_profile = &profile;
    m_liveTimer.stop();
    const bool playAdvance = profile.caps.panel == oi::ButtonPanel::PlayAdvance;
    // ERRATA 15: LEDs the profile lacks are switched off, not just hidden,
    // so their bits never go out.
    for (QCheckBox *box : {m_debris, m_spot, m_dock, m_checkRobot, m_play, m_advance}) {
        const bool shown = (box == m_play || box == m_advance) == playAdvance;
        box->setVisible(shown);
        if (!shown) {
            const QSignalBlocker block(box);
            box->setChecked(false);
        }
    }

    const oi::CommandEncoder encoder(profile);
    const auto digitsRefused = encoder.refuse(oi::Command::DigitLedsAscii);
    // Hidden as well as disabled, so nothing on screen looks usable.
    m_digitsContent->setEnabled(!digitsRefused);
    m_digitsContent->setVisible(!digitsRefused);
    m_digitsReason->setVisible(bool(digitsRefused));
    // ERRATA 9: the encoder knows where 163 is sent but does nothing.
    const auto raw = encoder.digitLedsRaw(0, 0, 0, 0);
    m_rawWarning->setVisible(raw.ok() && !raw.warning.empty());

    const auto schedulingRefused = encoder.refuse(oi::Command::SchedulingLeds);
    m_schedulingContent->setEnabled(!schedulingRefused);
    m_schedulingContent->setVisible(!schedulingRefused);
    m_schedulingReason->setVisible(bool(schedulingRefused));

    // The new robot has not been told anything yet by this editor.
    m_ledsPending = false;
    m_schedulingPending = false;
    m_digitsPending.reset();
    m_message->clear();
    retranslateUi(); // the reasons and the LEDs' names are the profile's
}

bool LedEditor::liveMode() const { return m_live->isChecked(); }
void LedEditor::setLiveMode(bool live) { m_live->setChecked(live); }

void LedEditor::setMode(const RobotMode &mode)
{
    const QString blocked = mode.whyNot(oi::Command::Leds);
    if (blocked == m_blocked)
        return;
    m_blocked = blocked;
    if (!m_blocked.isEmpty())
        m_liveTimer.stop();
    changed(); // in live mode, what waited goes out now
}

QColor LedEditor::powerLedColor(int colour, int intensity)
{
    colour = qBound(0, colour, 255);
    const qreal scale = qBound(0, intensity, 255) / 255.0;
    return QColor(qRound(colour * scale), qRound((255 - colour) * scale), 0);
}

int LedEditor::ledBits() const
{
    int bits = 0;
    const std::pair<QCheckBox *, std::uint8_t> boxes[] = {
        {m_debris, oi::bit::LedDebris},  {m_spot, oi::bit::LedSpot},  {m_dock, oi::bit::LedDock},
        {m_checkRobot, oi::bit::LedCheckRobot}, {m_play, oi::bit::LedPlay}, {m_advance, oi::bit::LedAdvance}};
    for (auto [box, bit] : boxes)
        if (box->isChecked())
            bits |= bit;
    return bits;
}

int LedEditor::weekdayBits() const
{
    int bits = 0;
    for (int day = 0; day < 7; ++day)
        if (m_weekdays[day]->isChecked())
            bits |= 1 << day;
    return bits;
}

int LedEditor::schedulingBits() const
{
    int bits = 0;
    const std::pair<QCheckBox *, std::uint8_t> boxes[] = {{m_schedule, oi::bit::SchedSchedule},
                                                          {m_clock, oi::bit::SchedClock},
                                                          {m_am, oi::bit::SchedAm},
                                                          {m_pm, oi::bit::SchedPm},
                                                          {m_colon, oi::bit::SchedColon}};
    for (auto [box, bit] : boxes)
        if (box->isChecked())
            bits |= bit;
    return bits;
}

oi::OiCommand LedEditor::digitsCommand() const
{
    if (m_digitsPending == DigitSource::Raw) {
        const auto m = m_segments->masks();
        return {oi::Command::DigitLedsRaw, {m[0], m[1], m[2], m[3]}, {}};
    }
    const auto &c = m_asciiCodes;
    return {oi::Command::DigitLedsAscii, {c[0], c[1], c[2], c[3]}, {}};
}

std::vector<oi::OiCommand> LedEditor::pendingTyped() const
{
    std::vector<oi::OiCommand> commands;
    if (m_ledsPending)
        commands.push_back({oi::Command::Leds, {ledBits(), m_colour->value(), m_intensity->value()}, {}});
    if (m_schedulingPending)
        commands.push_back({oi::Command::SchedulingLeds, {weekdayBits(), schedulingBits()}, {}});
    if (m_digitsPending)
        commands.push_back(digitsCommand());
    return commands;
}

std::vector<oi::Bytes> LedEditor::pendingCommands() const
{
    const oi::CommandEncoder encoder(*m_profile);
    std::vector<oi::Bytes> out;
    for (const oi::OiCommand &command : pendingTyped())
        if (const oi::EncodeResult r = oi::encodeCommand(encoder, command))
            out.push_back(r.value());
    return out;
}

QString LedEditor::bytePreview() const { return m_preview->text(); }
QString LedEditor::message() const { return m_message->text(); }

QString LedEditor::asciiProblem(const QString &text, bool *refused) const
{
    QStringList outside, blank;
    for (QChar ch : text) {
        const int code = ch.unicode();
        if (code < 32 || code > 126)
            outside << QString("'%1' (%2)").arg(ch).arg(code);
        else if (!oi::isSevenSegmentCharacter(code))
            blank << QString("'%1'").arg(ch);
    }
    *refused = !outside.isEmpty();
    if (*refused)
        return tr("Not sent: %1 outside ASCII 32..126. Use letters, digits and punctuation.")
            .arg(outside.join(", "));
    if (blank.isEmpty())
        return {};
    return blank.size() == 1 ? tr("%1 shows blank: the robot has no shape for it.").arg(blank[0])
                             : tr("%1 show blank: the robot has no shape for them.").arg(blank.join(", "));
}

void LedEditor::asciiEdited()
{
    const QString text = m_asciiText->text();
    bool refused = false;
    m_asciiMessage->setText(asciiProblem(text, &refused));
    if (refused) {
        // Nothing goes out for text the robot cannot take; the last valid
        // text stays in the preview.
        if (m_digitsPending == DigitSource::Ascii)
            m_digitsPending.reset();
        refresh();
        return;
    }
    m_asciiCodes = oi::digitAsciiCodes(text.toStdString());
    std::array<std::uint8_t, 4> shapes{};
    for (int i = 0; i < 4; ++i)
        shapes[i] = oi::sevenSegmentForAscii(m_asciiCodes[i]);
    m_asciiPreview->setMasks(shapes);
    m_digitsPending = DigitSource::Ascii;
    changed();
}

void LedEditor::changed()
{
    refresh();
    // Trailing rate limit: the first change starts the timer, later ones
    // only update the state, and the timer sends whatever is latest.
    if (liveMode() && m_blocked.isEmpty() && !pendingCommands().empty() && !m_liveTimer.isActive())
        m_liveTimer.start();
}

void LedEditor::refresh()
{
    m_colourValue->setText(QString::number(m_colour->value()));
    m_intensityValue->setText(QString::number(m_intensity->value()));
    const QColor swatch = powerLedColor(m_colour->value(), m_intensity->value());
    m_swatch->setStyleSheet(QString("background-color: %1; border: 1px solid %2; border-radius: 18px;")
                                .arg(swatch.name(), palette().color(QPalette::Mid).name()));
    m_swatch->setAccessibleDescription(
        tr("Colour %1 of 255 (green to red), intensity %2 of 255").arg(m_colour->value()).arg(m_intensity->value()));

    const auto commands = pendingCommands();
    QStringList lines;
    for (const auto &bytes : commands)
        lines << decimal(bytes);
    m_preview->setText(lines.isEmpty() ? tr("nothing (no changes since the last send)") : lines.join('\n'));
    m_apply->setEnabled(m_blocked.isEmpty() && !liveMode() && !commands.empty());
    if (!m_blocked.isEmpty())
        m_apply->setToolTip(m_blocked);
    else
        m_apply->setToolTip(liveMode() ? tr("Live mode sends changes as you make them")
                                       : tr("Send the changes shown under \"Will send\""));
}

void LedEditor::apply()
{
    m_liveTimer.stop();
    if (!m_blocked.isEmpty()) {
        m_message->setText(m_blocked); // the changes stay pending
        return;
    }
    const oi::CommandEncoder encoder(*m_profile);
    QStringList problems;
    for (const oi::OiCommand &command : pendingTyped()) {
        const oi::EncodeResult r = oi::encodeCommand(encoder, command);
        if (!r.ok()) {
            problems << fromStd(r.error().describe());
            continue;
        }
        // The one warning an LED command has (Digit LEDs Raw), in the
        // window's language rather than the encoder's English.
        if (!r.warning.empty())
            problems << m_rawWarning->text();
        emit sendRequested({command});
    }
    m_ledsPending = false;
    m_schedulingPending = false;
    m_digitsPending.reset();
    m_message->setText(problems.join('\n'));
    refresh();
}

#include "moc_led_editor.cpp"
