// SPDX-License-Identifier: GPL-3.0-or-later
#include "motors_panel.h"

#include "command_catalog.h"
#include "display_palette.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QEvent>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QVBoxLayout>

namespace {

QString fromView(std::string_view text) { return QString::fromUtf8(text.data(), qsizetype(text.size())); }

// The commands this panel uses, named as the user reads them.
struct CommandName {
    oi::Command command;
    const char *title;
};
constexpr CommandName kCommandNames[] = {
    {oi::Command::Motors, QT_TRANSLATE_NOOP("MotorsPanel", "Motors")},
    {oi::Command::PwmMotors, QT_TRANSLATE_NOOP("MotorsPanel", "PWM Motors")},
    {oi::Command::Buttons, QT_TRANSLATE_NOOP("MotorsPanel", "Buttons")},
    {oi::Command::LowSideDrivers, QT_TRANSLATE_NOOP("MotorsPanel", "Low Side Drivers")},
    {oi::Command::PwmLowSideDrivers, QT_TRANSLATE_NOOP("MotorsPanel", "PWM Low Side Drivers")},
    {oi::Command::DigitalOutputs, QT_TRANSLATE_NOOP("MotorsPanel", "Digital Outputs")},
    {oi::Command::SendIr, QT_TRANSLATE_NOOP("MotorsPanel", "Send IR")},
};

QString commandTitle(oi::Command command)
{
    const int opcode = oi::commandSpec(command).opcode;
    for (const CommandName &name : kCommandNames)
        if (name.command == command)
            return QStringLiteral("%1 (%2)").arg(QCoreApplication::translate("MotorsPanel", name.title)).arg(opcode);
    return QString::number(opcode);
}

// The buttons command's buttons, left to right and top to bottom.
struct ButtonBit {
    const char *objectName;
    const char *text;
    int bits;
};
constexpr ButtonBit kButtonBits[] = {
    {"buttonClean", QT_TRANSLATE_NOOP("MotorsPanel", "Clean"), oi::bit::ButtonClean},
    {"buttonSpot", QT_TRANSLATE_NOOP("MotorsPanel", "Spot"), oi::bit::ButtonSpot},
    {"buttonDock", QT_TRANSLATE_NOOP("MotorsPanel", "Dock"), oi::bit::ButtonDock},
    {"buttonMinute", QT_TRANSLATE_NOOP("MotorsPanel", "Minute"), oi::bit::ButtonMinute},
    {"buttonHour", QT_TRANSLATE_NOOP("MotorsPanel", "Hour"), oi::bit::ButtonHour},
    {"buttonDay", QT_TRANSLATE_NOOP("MotorsPanel", "Day"), oi::bit::ButtonDay},
    {"buttonSchedule", QT_TRANSLATE_NOOP("MotorsPanel", "Schedule"), oi::bit::ButtonSchedule},
    {"buttonClock", QT_TRANSLATE_NOOP("MotorsPanel", "Clock"), oi::bit::ButtonClock},
};

int bitIf(const QCheckBox *box, int bit) { return box->isChecked() ? bit : 0; }

} // namespace

// Every text is set in retranslateUi(), so a language switch applies at once.
MotorsPanel::MotorsPanel(QWidget *parent) : QWidget(parent)
{
    // Roomba 500/600: brushes and vacuum.
    m_motorsGroup = group("motorsGroup");
    m_mainBrush = checkBox("mainBrush");
    m_mainBrushOutward = checkBox("mainBrushOutward");
    m_sideBrush = checkBox("sideBrush");
    m_sideBrushClockwise = checkBox("sideBrushClockwise");
    m_vacuum = checkBox("vacuum");
    auto *motors = new QGridLayout(m_motorsGroup);
    motors->addWidget(m_mainBrush, 0, 0);
    motors->addWidget(m_mainBrushOutward, 0, 1);
    motors->addWidget(m_sideBrush, 1, 0);
    motors->addWidget(m_sideBrushClockwise, 1, 1);
    motors->addWidget(m_vacuum, 2, 0);
    // Check boxes only as wide as their text, so a click beside it does nothing.
    motors->setColumnStretch(2, 1);
    for (QCheckBox *box : {m_mainBrush, m_mainBrushOutward, m_sideBrush, m_sideBrushClockwise, m_vacuum})
        connect(box, &QCheckBox::toggled, this, &MotorsPanel::sendMotors);

    m_pwmMotorsGroup = group("pwmMotorsGroup");
    auto *pwm = new QGridLayout(m_pwmMotorsGroup);
    m_mainBrushDuty = dutySlider("mainBrushDuty", -127, 127);
    m_sideBrushDuty = dutySlider("sideBrushDuty", -127, 127);
    m_vacuumDuty = dutySlider("vacuumDuty", 0, 127);
    int row = 0;
    for (QSlider *slider : {m_mainBrushDuty, m_sideBrushDuty, m_vacuumDuty}) {
        m_pwmTitles[row] = dutyTitle(slider);
        pwm->addWidget(m_pwmTitles[row], row, 0);
        pwm->addWidget(slider, row, 1);
        pwm->addWidget(findChild<QLabel *>(slider->objectName() + "Value"), row, 2);
        connect(slider, &QSlider::valueChanged, this, &MotorsPanel::sendPwmMotors);
        ++row;
    }
    m_pwmNote = new QLabel(m_pwmMotorsGroup);
    m_pwmNote->setWordWrap(true);
    pwm->addWidget(m_pwmNote, row, 0, 1, 3);

    // The robot releases a pressed button by itself after 1/6 s.
    m_buttonsGroup = group("buttonsGroup");
    auto *buttons = new QGridLayout(m_buttonsGroup);
    for (std::size_t i = 0; i < std::size(kButtonBits); ++i) {
        auto *b = new QPushButton(m_buttonsGroup);
        b->setObjectName(kButtonBits[i].objectName);
        const int pressed = kButtonBits[i].bits;
        connect(b, &QPushButton::clicked, this,
                [this, pressed] { send({oi::Command::Buttons, {pressed}, {}}); });
        buttons->addWidget(b, int(i / 4), int(i % 4));
    }

    // Create: low side drivers, digital outputs and the IR output.
    m_lowSideGroup = group("lowSideGroup");
    auto *lowSide = new QHBoxLayout(m_lowSideGroup);
    for (int i = 0; i < 3; ++i) {
        m_lowSide[i] = checkBox(QString("lowSide%1").arg(i));
        lowSide->addWidget(m_lowSide[i]);
        connect(m_lowSide[i], &QCheckBox::toggled, this, &MotorsPanel::sendLowSideDrivers);
    }
    lowSide->addStretch();

    m_pwmLowSideGroup = group("pwmLowSideGroup");
    auto *pwmLowSide = new QGridLayout(m_pwmLowSideGroup);
    // Top to bottom in the command's byte order: LD2, LD1, LD0.
    for (int i = 2; i >= 0; --i) {
        m_lowSideDuty[i] = dutySlider(QString("lowSide%1Duty").arg(i), 0, 128);
        m_lowSideTitles[i] = dutyTitle(m_lowSideDuty[i]);
        const int r = 2 - i;
        pwmLowSide->addWidget(m_lowSideTitles[i], r, 0);
        pwmLowSide->addWidget(m_lowSideDuty[i], r, 1);
        pwmLowSide->addWidget(findChild<QLabel *>(m_lowSideDuty[i]->objectName() + "Value"), r, 2);
        connect(m_lowSideDuty[i], &QSlider::valueChanged, this, &MotorsPanel::sendPwmLowSideDrivers);
    }
    m_lowSideNote = new QLabel(m_pwmLowSideGroup);
    pwmLowSide->addWidget(m_lowSideNote, 3, 0, 1, 3);

    m_digitalOutputsGroup = group("digitalOutputsGroup");
    auto *outputs = new QHBoxLayout(m_digitalOutputsGroup);
    for (int i = 0; i < 3; ++i) {
        m_digitalOutputs[i] = checkBox(QString("digitalOutput%1").arg(i));
        outputs->addWidget(m_digitalOutputs[i]);
        connect(m_digitalOutputs[i], &QCheckBox::toggled, this, &MotorsPanel::sendDigitalOutputs);
    }
    outputs->addStretch();

    m_sendIrGroup = group("sendIrGroup");
    auto *ir = new QHBoxLayout(m_sendIrGroup);
    m_irByteTitle = new QLabel(m_sendIrGroup);
    m_irByte = new QSpinBox(m_sendIrGroup);
    m_irByte->setObjectName("irByte");
    m_irByte->setRange(0, 255);
    m_irByteTitle->setBuddy(m_irByte);
    m_sendIr = new QPushButton(m_sendIrGroup);
    m_sendIr->setObjectName("sendIr");
    connect(m_sendIr, &QPushButton::clicked, this,
            [this] { send({oi::Command::SendIr, {m_irByte->value()}, {}}); });
    ir->addWidget(m_irByteTitle);
    ir->addWidget(m_irByte);
    ir->addWidget(m_sendIr);
    ir->addStretch();

    m_allOff = new QPushButton(this);
    m_allOff->setObjectName("allOff");
    connect(m_allOff, &QPushButton::clicked, this, &MotorsPanel::allOff);

    m_unavailable = new QLabel(this);
    m_unavailable->setObjectName("unavailable");
    m_unavailable->setWordWrap(true);
    m_lastSent = new QLabel(this);
    m_lastSent->setObjectName("lastSent");
    m_lastSent->setFont(display::valueFont(font(), 1.2));
    m_lastSent->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *bottom = new QHBoxLayout;
    bottom->addWidget(m_allOff);
    bottom->addWidget(m_lastSent, 1);

    auto *layout = new QVBoxLayout(this);
    for (QGroupBox *g : {m_motorsGroup, m_pwmMotorsGroup, m_buttonsGroup, m_lowSideGroup,
                         m_pwmLowSideGroup, m_digitalOutputsGroup, m_sendIrGroup})
        layout->addWidget(g);
    layout->addLayout(bottom);
    layout->addWidget(m_unavailable);
    layout->addStretch();

    retranslateUi();
}

void MotorsPanel::retranslateUi()
{
    m_motorsGroup->setTitle(tr("Brushes and vacuum — Motors (138)"));
    m_mainBrush->setText(tr("Main brush"));
    m_mainBrushOutward->setText(tr("Outward"));
    m_sideBrush->setText(tr("Side brush"));
    m_sideBrushClockwise->setText(tr("Clockwise"));
    m_vacuum->setText(tr("Vacuum"));

    m_pwmMotorsGroup->setTitle(tr("Duty cycle — PWM Motors (144)"));
    m_pwmTitles[0]->setText(tr("Main brush"));
    m_pwmTitles[1]->setText(tr("Side brush"));
    m_pwmTitles[2]->setText(tr("Vacuum"));
    m_pwmNote->setText(tr("Brushes -127..127 (negative turns them the other way), "
                          "vacuum 0..127; 127 is full power."));

    m_buttonsGroup->setTitle(tr("Press a button — Buttons (165)"));
    for (const ButtonBit &b : kButtonBits)
        findChild<QPushButton *>(b.objectName)->setText(tr(b.text));

    m_lowSideGroup->setTitle(tr("Low side drivers — Low Side Drivers (138)"));
    m_pwmLowSideGroup->setTitle(tr("Duty cycle — PWM Low Side Drivers (144)"));
    for (int i = 0; i < 3; ++i) {
        m_lowSide[i]->setText(tr("LD%1").arg(i));
        m_lowSideTitles[i]->setText(tr("LD%1").arg(i));
    }
    m_lowSideNote->setText(tr("0..128; 128 is 100%."));

    m_digitalOutputsGroup->setTitle(tr("Cargo bay — Digital Outputs (147)"));
    for (int i = 0; i < 3; ++i)
        m_digitalOutputs[i]->setText(tr("Output %1").arg(i));

    m_sendIrGroup->setTitle(tr("IR output — Send IR (151)"));
    m_irByteTitle->setText(tr("Byte"));
    m_sendIr->setText(tr("Send IR"));
    m_allOff->setText(tr("All off"));

    showLastSent();
    // What the mode says comes again with the mode (MotorsPanel::setMode()).
    refreshGroups(nullptr);
}

void MotorsPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

QGroupBox *MotorsPanel::group(const QString &name)
{
    auto *g = new QGroupBox(this);
    g->setObjectName(name);
    return g;
}

QCheckBox *MotorsPanel::checkBox(const QString &name)
{
    auto *box = new QCheckBox(this);
    box->setObjectName(name);
    return box;
}

QLabel *MotorsPanel::dutyTitle(QSlider *slider)
{
    auto *title = new QLabel(this);
    title->setObjectName(slider->objectName() + "Title");
    title->setBuddy(slider); // names the slider for screen readers
    return title;
}

QSlider *MotorsPanel::dutySlider(const QString &name, int min, int max)
{
    auto *slider = new QSlider(Qt::Horizontal, this);
    slider->setObjectName(name);
    slider->setRange(min, max);
    slider->setMinimumWidth(160);
    // One command when the handle is let go, not one per pixel dragged.
    slider->setTracking(false);
    auto *value = new QLabel("0", this);
    value->setObjectName(name + "Value");
    value->setMinimumWidth(value->fontMetrics().horizontalAdvance("-128") + 4);
    value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    const auto show = [value](int v) { value->setText(QString::number(v)); };
    connect(slider, &QSlider::sliderMoved, value, show);
    connect(slider, &QSlider::valueChanged, value, show);
    return slider;
}

void MotorsPanel::setProfile(const oi::RobotProfile &profile, const RobotMode &mode)
{
    m_profile = &profile;
    clearControls();
    refreshGroups(&mode);
}

void MotorsPanel::setMode(const RobotMode &mode)
{
    refreshGroups(&mode);
}

void MotorsPanel::refreshGroups(const RobotMode *mode)
{
    using C = oi::Command;
    QStringList missing;
    for (auto [g, command] : {std::pair{m_motorsGroup, C::Motors}, std::pair{m_pwmMotorsGroup, C::PwmMotors},
                              std::pair{m_buttonsGroup, C::Buttons}, std::pair{m_lowSideGroup, C::LowSideDrivers},
                              std::pair{m_pwmLowSideGroup, C::PwmLowSideDrivers},
                              std::pair{m_digitalOutputsGroup, C::DigitalOutputs},
                              std::pair{m_sendIrGroup, C::SendIr}}) {
        const bool available = m_profile->has(command);
        g->setVisible(available);
        if (mode) {
            const QString why = mode->whyNot(command);
            g->setEnabled(available && why.isEmpty());
            g->setToolTip(why);
        }
        if (!available)
            missing << commandTitle(command);
    }
    m_unavailable->setText(missing.isEmpty() ? QString()
                                             : tr("Not on the %1, so not shown: %2.")
                                                   .arg(fromView(m_profile->name), missing.join(", ")));
    m_unavailable->setVisible(!missing.isEmpty());
    const C off = m_profile->has(C::Motors) ? C::Motors : C::LowSideDrivers;
    if (mode) {
        const QString why = mode->whyNot(off);
        m_allOff->setEnabled(m_profile->has(off) && why.isEmpty());
        m_allOff->setToolTip(why);
    }
}

void MotorsPanel::clearControls()
{
    for (QCheckBox *box : findChildren<QCheckBox *>()) {
        const QSignalBlocker block(box);
        box->setChecked(false);
    }
    for (QSlider *slider : findChildren<QSlider *>()) {
        const QSignalBlocker block(slider);
        slider->setValue(0);
        findChild<QLabel *>(slider->objectName() + "Value")->setText("0");
    }
}

void MotorsPanel::sendMotors()
{
    namespace bit = oi::bit;
    const int bits = bitIf(m_mainBrush, bit::MotorMainBrush) | bitIf(m_mainBrushOutward, bit::MotorMainBrushOutward)
                     | bitIf(m_sideBrush, bit::MotorSideBrush)
                     | bitIf(m_sideBrushClockwise, bit::MotorSideBrushClockwise) | bitIf(m_vacuum, bit::MotorVacuum);
    send({oi::Command::Motors, {bits}, {}});
}

void MotorsPanel::sendPwmMotors()
{
    send({oi::Command::PwmMotors, {m_mainBrushDuty->value(), m_sideBrushDuty->value(), m_vacuumDuty->value()}, {}});
}

void MotorsPanel::sendLowSideDrivers()
{
    int bits = 0;
    for (int i = 0; i < 3; ++i)
        bits |= bitIf(m_lowSide[i], 1 << i);
    send({oi::Command::LowSideDrivers, {bits}, {}});
}

void MotorsPanel::sendPwmLowSideDrivers()
{
    send({oi::Command::PwmLowSideDrivers,
          {m_lowSideDuty[2]->value(), m_lowSideDuty[1]->value(), m_lowSideDuty[0]->value()},
          {}});
}

void MotorsPanel::sendDigitalOutputs()
{
    int bits = 0;
    for (int i = 0; i < 3; ++i)
        bits |= bitIf(m_digitalOutputs[i], 1 << i);
    send({oi::Command::DigitalOutputs, {bits}, {}});
}

void MotorsPanel::allOff()
{
    const bool roomba = m_profile->has(oi::Command::Motors);
    if (!roomba && !m_profile->has(oi::Command::LowSideDrivers))
        return;
    std::vector<oi::OiCommand> off{{roomba ? oi::Command::Motors : oi::Command::LowSideDrivers, {0}, {}}};
    if (const oi::Command pwm = roomba ? oi::Command::PwmMotors : oi::Command::PwmLowSideDrivers; m_profile->has(pwm))
        off.push_back({pwm, {0, 0, 0}, {}});
    clearControls();
    send(off);
}

void MotorsPanel::send(const oi::OiCommand &command) { send(std::vector<oi::OiCommand>{command}); }

void MotorsPanel::send(const std::vector<oi::OiCommand> &commands)
{
    // Controls for commands the profile lacks are hidden and every control's
    // range is the command's range, so nothing here can be refused.
    const oi::CommandEncoder encoder(*m_profile);
    QStringList text;
    for (const oi::OiCommand &command : commands) {
        const oi::EncodeResult bytes = oi::encodeCommand(encoder, command);
        if (!bytes)
            return;
        for (std::uint8_t b : *bytes)
            text << QString::number(b);
    }
    m_lastSent->setProperty("bytes", text.join(' '));
    showLastSent();
    emit sendRequested(commands);
}

void MotorsPanel::showLastSent()
{
    const QString bytes = lastSentText();
    m_lastSent->setText(bytes.isEmpty() ? tr("Last sent: —") : tr("Last sent: %1").arg(bytes));
}

QString MotorsPanel::lastSentText() const { return m_lastSent->property("bytes").toString(); }

QString MotorsPanel::unavailableText() const { return m_unavailable->isHidden() ? QString() : m_unavailable->text(); }

#include "moc_motors_panel.cpp"
