// SPDX-License-Identifier: GPL-3.0-or-later
// The drive pad: its controls, its round area, and the knob under the hand.
#include "drive_pad.h"

#include "measured_move.h"

#include "command_encoder.h"
#include "display_palette.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QPushButton>
#include <QSlider>
#include <QStandardItemModel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

// The round area itself: paints the zones, the knob and the command, and
// turns mouse positions into knob positions for the pad.
class DrivePadArea : public QWidget {
public:
    static constexpr int kMargin = 8;

    explicit DrivePadArea(DrivePad *pad) : QWidget(pad), m_pad(pad)
    {
        setObjectName("drivePadArea");
        setMinimumSize(150, 150);
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
        // Clicking the pad takes the focus out of text fields, so the drive
        // keys work from here.
        setFocusPolicy(Qt::StrongFocus);
        // Touch arrives as synthesized mouse events.
        setAttribute(Qt::WA_AcceptTouchEvents, false);
    }

    // A stop decided elsewhere ends the drag: only a new press drives again.
    void cancelDrag() { m_dragging = false; }

    double radius() const { return std::max(10.0, std::min(width(), height()) / 2.0 - kMargin - fontMetrics().height()); }
    QPointF centre() const { return QPointF(width() / 2.0, radius() + kMargin); }

    QPointF knobAt(QPointF pos) const
    {
        QPointF k((pos.x() - centre().x()) / radius(), (centre().y() - pos.y()) / radius());
        const double r = std::hypot(k.x(), k.y());
        return r > 1.0 ? k / r : k;
    }
    QPointF pointFor(QPointF knob) const
    {
        return centre() + QPointF(knob.x() * radius(), -knob.y() * radius());
    }

protected:
    void mousePressEvent(QMouseEvent *event) override
    {
        if (event->button() != Qt::LeftButton)
            return;
        m_dragging = true;
        m_pad->moveKnob(knobAt(event->position()));
    }
    void mouseMoveEvent(QMouseEvent *event) override
    {
        if (m_dragging && (event->buttons() & Qt::LeftButton))
            m_pad->moveKnob(knobAt(event->position()));
    }
    void mouseReleaseEvent(QMouseEvent *event) override
    {
        if (event->button() != Qt::LeftButton || !m_dragging)
            return;
        m_dragging = false;
        m_pad->release();
    }
    void changeEvent(QEvent *event) override
    {
        // A pad disabled mid-drag (Passive mode) must not resume on the next move.
        if (event->type() == QEvent::EnabledChange && !isEnabled())
            m_dragging = false;
        QWidget::changeEvent(event);
    }
    void paintEvent(QPaintEvent *) override
    {
        QPainter p(this);
        p.setRenderHint(QPainter::Antialiasing);
        const QPalette &pal = palette();
        const QPointF c = centre();
        const double r = radius();
        const QColor base = pal.color(isEnabled() ? QPalette::Active : QPalette::Disabled, QPalette::Base);
        const QColor line = pal.color(isEnabled() ? QPalette::Active : QPalette::Disabled, QPalette::Mid);
        const QColor accent = pal.color(isEnabled() ? QPalette::Active : QPalette::Disabled, QPalette::Highlight);

        p.setPen(QPen(line, 1.5));
        p.setBrush(base);
        p.drawEllipse(c, r, r);

        // The straight (vertical) and turn-in-place (horizontal) zones.
        const QRectF box(c.x() - r, c.y() - r, 2 * r, 2 * r);
        QColor zone = accent;
        zone.setAlpha(35);
        p.setPen(Qt::NoPen);
        p.setBrush(zone);
        const double z = DrivePad::kZoneDegrees;
        for (double middle : {90.0, 270.0, 0.0, 180.0}) {
            QPainterPath wedge(c);
            wedge.arcTo(box, middle - z, 2 * z);
            wedge.closeSubpath();
            p.drawPath(wedge);
        }
        p.setPen(QPen(line, 1, Qt::DashLine));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(c, r * DrivePad::kDeadZone, r * DrivePad::kDeadZone);
        p.drawLine(QPointF(c.x() - r, c.y()), QPointF(c.x() + r, c.y()));
        p.drawLine(QPointF(c.x(), c.y() - r), QPointF(c.x(), c.y() + r));

        // Dragged, the knob is under the mouse; otherwise it shows what
        // another input (keys, a gamepad) asks of the robot.
        const bool byPad = m_dragging || !m_pad->currentCommand().isStop();
        const QPointF knob = pointFor(byPad ? m_pad->knob() : m_pad->knobFor(m_pad->asked()));
        const bool moving = byPad ? !m_pad->currentCommand().isStop() : !m_pad->asked().isStop();
        p.setPen(QPen(accent, 2));
        if (moving)
            p.drawLine(c, knob);
        p.setBrush(moving ? accent : pal.color(QPalette::Button));
        p.setPen(QPen(line, 1.5));
        const double knobRadius = std::max(8.0, r * 0.12);
        p.drawEllipse(knob, knobRadius, knobRadius);

        p.setPen(pal.color(isEnabled() ? QPalette::Active : QPalette::Disabled, QPalette::WindowText));
        const QRectF text(0, c.y() + r + 2, width(), fontMetrics().height() + 4);
        // A narrow pad shortens the readout rather than cutting it at the edges.
        const QString readout = fontMetrics().elidedText(m_pad->readout(), Qt::ElideRight, width());
        p.drawText(text, Qt::AlignHCenter | Qt::AlignTop, readout);
    }

private:
    DrivePad *m_pad;
    bool m_dragging = false;
};

DrivePad::DrivePad(QWidget *parent) : QWidget(parent)
{
    // Texts come from retranslateUi(); the item data says which mapping.
    m_mapping = new QComboBox(this);
    m_mapping->setObjectName("mapping");
    for (Mapping m : {Mapping::Drive, Mapping::DriveDirect, Mapping::DrivePwm})
        m_mapping->addItem(QString(), int(m));
    connect(m_mapping, &QComboBox::currentIndexChanged, this, [this] {
        // A new mapping must not keep the robot going on the old one's terms.
        resetToCentre();
        emit motionRequested(m_command);
    });

    m_speed = new QSlider(Qt::Horizontal, this);
    m_speed->setObjectName("speedLimit");
    m_speed->setRange(10, kMaxSpeedLimit);
    m_speed->setSingleStep(10);
    m_speed->setPageStep(50);
    m_speed->setValue(kDefaultSpeedLimit);
    m_speedLabel = new QLabel(this);
    m_speedLabel->setObjectName("speedLimitValue");
    connect(m_speed, &QSlider::valueChanged, this, [this](int value) {
        m_speedLabel->setText(tr("%1 mm/s").arg(value));
        if (!m_command.isStop())
            updateCommand(m_knob);
    });

    m_passiveBar = new QWidget(this);
    m_passiveLabel = new QLabel(m_passiveBar);
    m_passiveLabel->setWordWrap(true);
    m_enterSafe = new QPushButton(m_passiveBar);
    m_enterSafe->setObjectName("enterSafe");
    connect(m_enterSafe, &QPushButton::clicked, this, &DrivePad::safeRequested);
    auto *passiveRow = new QHBoxLayout(m_passiveBar);
    passiveRow->setContentsMargins(0, 0, 0, 0);
    passiveRow->addWidget(m_passiveLabel, 1);
    passiveRow->addWidget(m_enterSafe);
    m_passiveBar->hide();

    m_area = new DrivePadArea(this);
    m_move = new MeasuredMove(this);
    m_move->setSpeedLimit(m_speed->value());
    connect(m_speed, &QSlider::valueChanged, m_move, &MeasuredMove::setSpeedLimit);

    m_speedTitle = new QLabel(this);
    m_speedTitle->setBuddy(m_speed); // names the slider for screen readers
    auto *speedRow = new QHBoxLayout;
    speedRow->addWidget(m_speedTitle);
    speedRow->addWidget(m_speed, 1);
    speedRow->addWidget(m_speedLabel);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    layout->addWidget(m_mapping);
    layout->addLayout(speedRow);
    layout->addWidget(m_passiveBar);
    m_padAndMove = new QBoxLayout(QBoxLayout::TopToBottom);
    m_padAndMove->addWidget(m_area, 1);
    m_padAndMove->addWidget(m_move);
    layout->addLayout(m_padAndMove, 1);
    retranslateUi();
}

void DrivePad::retranslateUi()
{
    m_mapping->setItemText(int(Mapping::Drive), tr("Drive (137): speed and radius"));
    m_mapping->setItemText(int(Mapping::DriveDirect), tr("Drive Direct (145): each wheel"));
    m_mapping->setItemText(int(Mapping::DrivePwm), tr("Drive PWM (146): each wheel, raw power"));
    m_speedTitle->setText(tr("Speed limit"));
    m_speedLabel->setText(tr("%1 mm/s").arg(m_speed->value()));
    // Room for the widest value, so the slider does not jump while dragging.
    m_speedLabel->setMinimumWidth(m_speedLabel->fontMetrics().horizontalAdvance(tr("%1 mm/s").arg(kMaxSpeedLimit))
                                  + m_speedLabel->fontMetrics().averageCharWidth());
    setReason(m_reason);
    m_enterSafe->setText(tr("Enter Safe"));
    m_area->setAccessibleName(tr("Drive pad"));
    setProfile(*m_profile); // the items' tool tips
    updateAccessibleDescription();
    m_area->update();
}

void DrivePad::resizeEvent(QResizeEvent *event)
{
    // A dock wider than tall (a tab under the diagram) keeps the pad round
    // and big with the move row beside it.
    const bool wide = width() > height() * 4 / 3;
    const QBoxLayout::Direction direction = wide ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom;
    if (m_padAndMove->direction() != direction) {
        m_padAndMove->setDirection(direction);
        m_move->setColumn(wide);
        // Now, not at the next layout pass: the pad's size is where the
        // mouse reads its knob.
        layout()->activate();
    }
    QWidget::resizeEvent(event);
}

void DrivePad::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void DrivePad::updateAccessibleDescription()
{
    QString text = spokenDescription(m_command.isStop() ? m_asked : m_command);
    if (m_passive)
        text = m_passiveLabel->text();
    // Only a change is announced, so set it only when it differs.
    if (m_area->accessibleDescription() != text)
        m_area->setAccessibleDescription(text);
}

void DrivePad::setProfile(const oi::RobotProfile &profile)
{
    m_profile = &profile;
    auto *model = qobject_cast<QStandardItemModel *>(m_mapping->model());
    for (Mapping m : {Mapping::Drive, Mapping::DriveDirect, Mapping::DrivePwm}) {
        QStandardItem *item = model->item(int(m));
        item->setEnabled(isMappingAvailable(m));
        item->setToolTip(mappingDisabledReason(m));
    }
    if (!isMappingAvailable(mapping()))
        setMapping(Mapping::Drive);
}

bool DrivePad::isMappingAvailable(Mapping mapping) const { return mappingDisabledReason(mapping).isEmpty(); }

QString DrivePad::mappingDisabledReason(Mapping mapping) const
{
    const oi::Command command = mapping == Mapping::DrivePwm      ? oi::Command::DrivePwm
                                : mapping == Mapping::DriveDirect ? oi::Command::DriveDirect
                                                                  : oi::Command::Drive;
    if (!oi::CommandEncoder(*m_profile).refuse(command))
        return {};
    const QString robot = QString::fromUtf8(m_profile->name.data(), qsizetype(m_profile->name.size()));
    switch (mapping) {
    case Mapping::DriveDirect: return tr("Drive Direct (145) is not available on the %1").arg(robot);
    case Mapping::DrivePwm: return tr("Drive PWM (146) is not available on the %1").arg(robot);
    case Mapping::Drive: break;
    }
    return tr("Drive (137) is not available on the %1").arg(robot);
}

DrivePad::Mapping DrivePad::mapping() const { return Mapping(m_mapping->currentData().toInt()); }
void DrivePad::setMapping(Mapping mapping) { m_mapping->setCurrentIndex(int(mapping)); }
int DrivePad::speedLimit() const { return m_speed->value(); }
void DrivePad::setSpeedLimit(int mmPerSecond) { m_speed->setValue(mmPerSecond); }

void DrivePad::setPassive(bool passive)
{
    if (passive == m_passive)
        return;
    m_passive = passive;
    m_passiveBar->setVisible(passive);
    m_area->setEnabled(!passive);
    if (passive)
        resetToCentre();
    updateAccessibleDescription();
}

void DrivePad::setReason(const QString &reason)
{
    m_reason = reason;
    const QString text = reason.isEmpty() ? tr("Passive mode: enter Safe to drive") : reason;
    if (text == m_passiveLabel->text())
        return;
    m_passiveLabel->setText(text);
    // A reason is an alert, as in the Modes dock; the plain hint is not.
    m_passiveLabel->setStyleSheet(reason.isEmpty() ? QString()
                                                   : QString("QLabel { color: %1; font-weight: bold; }")
                                                         .arg(display::stateColor(display::State::Alert, palette()).name()));
    updateAccessibleDescription();
}

QString DrivePad::passiveText() const { return m_passiveBar->isHidden() ? QString() : m_passiveLabel->text(); }

void DrivePad::resetToCentre()
{
    static_cast<DrivePadArea *>(m_area)->cancelDrag();
    m_knob = {};
    m_command = MotionCommand::stop(MotionCommand::Kind(int(mapping())));
    updateAccessibleDescription();
    m_area->update();
}

QPointF DrivePad::knobAt(QPoint areaPos) const { return static_cast<DrivePadArea *>(m_area)->knobAt(areaPos); }
QPoint DrivePad::areaPointFor(QPointF knob) const
{
    return static_cast<DrivePadArea *>(m_area)->pointFor(knob).toPoint();
}

void DrivePad::moveKnob(QPointF knob)
{
    if (m_passive)
        return;
    updateCommand(knob);
}

void DrivePad::release()
{
    resetToCentre();
    emit motionRequested(m_command);
}

void DrivePad::updateCommand(QPointF knob)
{
    m_knob = knob;
    const MotionCommand command = commandAt(knob);
    m_area->update();
    if (command == m_command)
        return;
    m_command = command;
    updateAccessibleDescription();
    emit motionRequested(m_command);
}

void DrivePad::showAsked(const MotionCommand &asked)
{
    if (asked == m_asked)
        return;
    m_asked = asked;
    updateAccessibleDescription();
    m_area->update();
}

QString DrivePad::readout() const
{
    return describe(m_command.isStop() ? m_asked : m_command);
}

#include "moc_drive_pad.cpp"
