// SPDX-License-Identifier: GPL-3.0-or-later
#include "gamepad_panel.h"

#include "gamepad_input.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QVBoxLayout>

// The left stick: a square for its travel, a lighter square for the
// deadband, and a dot where it is.
class StickView : public QWidget {
public:
    explicit StickView(QWidget *parent) : QWidget(parent)
    {
        setObjectName(QStringLiteral("stickView"));
        setFixedSize(100, 100);
    }
    void setState(QPointF stick, double deadband, bool active)
    {
        if (stick == m_stick && deadband == m_deadband && active == m_active)
            return;
        m_stick = stick;
        m_deadband = deadband;
        m_active = active;
        update();
    }

protected:
    void paintEvent(QPaintEvent *) override
    {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        const QRectF frame = QRectF(rect()).adjusted(4.5, 4.5, -4.5, -4.5);
        const QPalette &pal = palette();
        p.setPen(QPen(pal.color(QPalette::Mid), 1));
        p.setBrush(pal.color(QPalette::Base));
        p.drawRect(frame);
        const QPointF centre = frame.center();
        // The dot's centre stays inside the frame at full travel.
        const double half = frame.width() / 2 - kDotRadius;
        p.setPen(Qt::NoPen);
        p.setBrush(pal.color(QPalette::AlternateBase).darker(105));
        p.drawRect(QRectF(centre.x() - half * m_deadband, centre.y() - half * m_deadband,
                          2 * half * m_deadband, 2 * half * m_deadband));
        p.setPen(QPen(pal.color(QPalette::Mid), 1, Qt::DotLine));
        p.drawLine(QPointF(frame.left(), centre.y()), QPointF(frame.right(), centre.y()));
        p.drawLine(QPointF(centre.x(), frame.top()), QPointF(centre.x(), frame.bottom()));
        // Forward is up on screen.
        const QPointF dot(centre.x() + m_stick.x() * half, centre.y() - m_stick.y() * half);
        p.setPen(Qt::NoPen);
        p.setBrush(m_active ? QColor(0, 150, 70) : pal.color(QPalette::Dark));
        p.drawEllipse(dot, kDotRadius, kDotRadius);
    }

private:
    static constexpr double kDotRadius = 5;
    QPointF m_stick;
    double m_deadband = GamepadInput::kDefaultDeadband;
    bool m_active = false;
};

GamepadPanel::GamepadPanel(QWidget *parent) : QWidget(parent)
{
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("gamepadStatus"));
    m_status->setWordWrap(true);
    QFont bold = m_status->font();
    bold.setBold(true);
    m_status->setFont(bold);

    m_details = new QWidget(this);
    m_stick = new StickView(m_details);
    m_deadMan = new QLabel(m_details);
    m_deadMan->setObjectName(QStringLiteral("deadManState"));
    m_deadMan->setAutoFillBackground(true);
    m_deadMan->setMargin(3);
    m_command = new QLabel(m_details);
    m_command->setObjectName(QStringLiteral("gamepadCommand"));
    m_command->setWordWrap(true);
    m_command->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_shaping = new QLabel(m_details);
    m_shaping->setObjectName(QStringLiteral("gamepadShaping"));
    m_mapping = new QLabel(m_details);
    m_mapping->setObjectName(QStringLiteral("gamepadMapping"));
    m_mapping->setWordWrap(true);

    auto *text = new QVBoxLayout;
    text->addWidget(m_deadMan);
    m_commandTitle = new QLabel(m_details);
    text->addWidget(m_commandTitle);
    text->addWidget(m_command);
    text->addWidget(m_shaping);
    text->addStretch();
    auto *row = new QHBoxLayout;
    row->setContentsMargins(0, 0, 0, 0);
    row->addWidget(m_stick, 0, Qt::AlignTop);
    row->addLayout(text, 1);
    auto *details = new QVBoxLayout(m_details);
    details->setContentsMargins(0, 0, 0, 0);
    details->addLayout(row);
    details->addWidget(m_mapping);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_status);
    layout->addWidget(m_details);
    layout->addStretch();
    retranslateUi();
}

void GamepadPanel::retranslateUi()
{
    m_commandTitle->setText(tr("Would send:"));
    m_stick->setAccessibleName(tr("Left stick"));
    refresh();
}

void GamepadPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void GamepadPanel::setInput(GamepadInput *input)
{
    if (m_input)
        disconnect(m_input, nullptr, this, nullptr);
    m_input = input;
    if (input) {
        connect(input, &GamepadInput::gamepadChanged, this, &GamepadPanel::refresh);
        connect(input, &GamepadInput::stickMoved, this, &GamepadPanel::refresh);
        connect(input, &GamepadInput::deadManChanged, this, &GamepadPanel::refresh);
        connect(input, &GamepadInput::motionRequested, this, &GamepadPanel::refresh);
        connect(input, &GamepadInput::mappingChanged, this, &GamepadPanel::refresh);
        connect(input, &QObject::destroyed, this, &GamepadPanel::refresh, Qt::QueuedConnection);
    }
    refresh();
}

QString GamepadPanel::statusText() const { return m_status->text(); }
QString GamepadPanel::deadManText() const { return m_deadMan->text(); }
QString GamepadPanel::commandText() const { return m_command->text(); }
QString GamepadPanel::mappingText() const
{
    return m_mapping->text().replace(QChar::Nbsp, QLatin1Char(' '));
}

QString GamepadPanel::describe(const MotionCommand &command)
{
    switch (command.kind) {
    case MotionCommand::Kind::DriveDirect:
        return tr("Drive Direct: right %1 mm/s, left %2 mm/s").arg(command.right).arg(command.left);
    case MotionCommand::Kind::DrivePwm:
        return tr("Drive PWM: right %1, left %2").arg(command.right).arg(command.left);
    case MotionCommand::Kind::Drive: break;
    }
    const int v = command.velocity;
    const int r = command.radius;
    if (v == 0)
        return tr("Stop: Drive 0 mm/s");
    if (r == oi::kRadiusStraight || r == oi::kRadiusStraightAlt)
        return (v > 0 ? tr("Forward: Drive %1 mm/s, straight") : tr("Reverse: Drive %1 mm/s, straight")).arg(v);
    if (r == oi::kRadiusTurnInPlaceClockwise)
        return tr("Spin clockwise: Drive %1 mm/s, radius -1").arg(v);
    if (r == oi::kRadiusTurnInPlaceCounterClockwise)
        return tr("Spin counter-clockwise: Drive %1 mm/s, radius 1").arg(v);
    const QString way = v > 0 ? (r < 0 ? tr("Forward, arcing right") : tr("Forward, arcing left"))
                              : (r < 0 ? tr("Reverse, arcing right") : tr("Reverse, arcing left"));
    return tr("%1: Drive %2 mm/s, radius %3 mm").arg(way).arg(v).arg(r);
}

void GamepadPanel::refresh()
{
    GamepadInput *input = m_input.data();
    const bool connected = input && input->hasGamepad();
    if (input && !input->isAvailable())
        m_status->setText(tr("Gamepads unavailable: %1").arg(input->errorString()));
    else if (!connected)
        m_status->setText(tr("No gamepad connected — plug one in to drive with it"));
    else
        m_status->setText(input->gamepadName());
    m_details->setEnabled(connected);

    const QString deadManButton =
        GamepadInput::buttonName(input ? input->deadManButton() : SDL_CONTROLLER_BUTTON_RIGHTSHOULDER);
    const bool held = connected && input->isDeadManHeld();
    QPalette pal = m_deadMan->palette();
    if (held) {
        m_deadMan->setText(tr("Dead-man (%1) held: driving").arg(deadManButton));
        pal.setColor(QPalette::Window, QColor(200, 235, 205));
        pal.setColor(QPalette::WindowText, QColor(0, 90, 30));
    } else {
        m_deadMan->setText(tr("Dead-man (%1) released: hold it to drive").arg(deadManButton));
        pal = palette();
        pal.setColor(QPalette::Window, palette().color(QPalette::Window).darker(108));
    }
    m_deadMan->setPalette(pal);

    m_command->setText(describe(input ? input->command() : MotionCommand::stop()));
    const QPointF stick = input ? input->stick() : QPointF();
    m_stick->setState(stick, input ? input->deadband() : GamepadInput::kDefaultDeadband, held);
    // Only a change is announced, so set it only when it differs.
    const QString stickText = tr("%1% right, %2% forward")
                                  .arg(qRound(stick.x() * 100))
                                  .arg(qRound(stick.y() * 100));
    if (m_stick->accessibleDescription() != stickText)
        m_stick->setAccessibleDescription(stickText);
    if (input) {
        m_shaping->setText(tr("Speed limit %1 mm/s · deadband %2% · expo %3")
                               .arg(input->speedLimit())
                               .arg(qRound(input->deadband() * 100))
                               .arg(input->expo(), 0, 'g', 2));
        QStringList roles;
        roles << tr("Hold %1 to drive").arg(deadManButton);
        if (input->stopAllButton() != SDL_CONTROLLER_BUTTON_INVALID)
            roles << tr("%1: Stop All").arg(GamepadInput::buttonName(input->stopAllButton()));
        const auto modes = input->modeButtons();
        for (auto it = modes.cbegin(); it != modes.cend(); ++it)
            roles << tr("%1: %2").arg(GamepadInput::buttonName(it.key()), GamepadInput::modeName(it.value()));
        // Wrap between roles, never inside one.
        for (QString &role : roles)
            role.replace(QLatin1Char(' '), QChar::Nbsp);
        m_mapping->setText(roles.join(QStringLiteral(" · ")));
    } else {
        m_shaping->clear();
        m_mapping->clear();
    }
}

#include "moc_gamepad_panel.cpp"
