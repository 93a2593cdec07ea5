// SPDX-License-Identifier: GPL-3.0-or-later
#include "mode_panel.h"

#include "oi_text.h"

#include "command_catalog.h"
#include "demo_names.h"
#include "display_palette.h"

#include <QComboBox>
#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

ModePanel::ModePanel(QWidget *parent) : QWidget(parent)
{
    m_confirmFull = [](QWidget *owner) {
        return QMessageBox::question(owner, tr("Enter Full mode?"),
                                     tr("Full mode turns off the cliff, wheel-drop and charger "
                                        "safety stops. The robot will drive off a table edge if "
                                        "told to. It is also the way off the dock, where Safe is "
                                        "refused (on the dock it does not charge in Full). Enter "
                                        "Full mode?"))
               == QMessageBox::Yes;
    };

    m_modeLabel = new QLabel(this);
    m_modeLabel->setObjectName("modeLabel");
    m_modeLabel->setFont(display::valueFont(font(), 1.4));
    m_firmwareLabel = new QLabel(this);
    m_firmwareLabel->setObjectName("firmwareLabel");
    m_firmwareLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_safetyLabel = new QLabel(this);
    m_safetyLabel->setObjectName("safetyLabel");
    m_safetyLabel->setWordWrap(true);
    m_safetyLabel->setVisible(false);

    auto *modes = new QHBoxLayout;
    using C = oi::Command;
    for (auto [name, command] : {std::pair{"start", C::Start}, std::pair{"passive", C::Start},
                                 std::pair{"safe", C::Safe}, std::pair{"full", C::Full},
                                 std::pair{"stop", C::Stop}})
        modes->addWidget(addButton(name, command));

    auto *system = new QHBoxLayout;
    system->addWidget(addButton("reset", C::Reset));
    system->addWidget(addButton("power", C::Power));
    system->addStretch();

    // Four short names in the first row; the longer ones (long in German)
    // span the columns beside them, so the panel fits a 1280 px screen's dock.
    auto *cleaning = new QGridLayout;
    cleaning->addWidget(addButton("clean", C::Clean), 0, 0);
    cleaning->addWidget(addButton("spot", C::Spot), 0, 1);
    cleaning->addWidget(addButton("max", C::Max), 0, 2);
    cleaning->addWidget(addButton("seek-dock", C::SeekDock), 0, 3);
    cleaning->addWidget(addButton("cover", C::Cover), 1, 0);
    cleaning->addWidget(addButton("cover-and-dock", C::CoverAndDock), 1, 1, 1, 3);
    m_demo = new QComboBox(this);
    m_demo->setObjectName("demoChoice");
    for (int demo = demos::kAbort; demo <= demos::kLast; ++demo)
        m_demo->addItem(QString(), demo);
    m_demo->setCurrentIndex(1);
    // As wide as a short name: the list shows each name whole.
    m_demo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_demo->setMinimumContentsLength(10);
    cleaning->addWidget(m_demo, 2, 0, 1, 2);
    cleaning->addWidget(addButton("demo", C::Demo), 2, 2);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_modeLabel);
    layout->addLayout(modes);
    layout->addWidget(m_safetyLabel);
    layout->addLayout(system);
    layout->addWidget(m_firmwareLabel);
    layout->addLayout(cleaning);
    layout->addStretch();

    // Created row by row, so Tab already follows the layout.
    setMode(RobotMode());
    retranslateUi();
}

void ModePanel::retranslateUi()
{
    const std::pair<const char *, QString> texts[] = {
        {"start", tr("Start")},       {"passive", tr("Passive")}, {"safe", tr("Safe")},
        {"full", tr("Full")},         {"stop", tr("Stop")},       {"reset", tr("Reset")},
        {"power", tr("Power off")},   {"clean", tr("Clean")},     {"spot", tr("Spot")},
        {"max", tr("Max")},           {"seek-dock", tr("Seek Dock")}, {"cover", tr("Cover")},
        {"cover-and-dock", tr("Cover and Dock")}, {"demo", tr("Demo")}};
    for (const auto &[name, text] : texts)
        m_buttons.value(name)->setText(text);
    for (int i = 0; i < m_demo->count(); ++i) {
        const int demo = m_demo->itemData(i).toInt();
        m_demo->setItemText(i, QStringLiteral("%1  %2").arg(demo).arg(demos::name(demo)));
    }
    m_demo->setToolTip(tr("Demo to run"));
    m_demo->setAccessibleName(tr("Demo"));
    refreshButtons();
    setFirmware(m_firmware);
}

void ModePanel::changeEvent(QEvent *e)
{
    if (e->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(e);
}

QPushButton *ModePanel::addButton(const QString &name, oi::Command command)
{
    auto *b = new QPushButton(this);
    b->setObjectName(name);
    m_buttons.insert(name, b);
    m_commands.insert(b, command);
    connect(b, &QPushButton::clicked, this, [this, command] { request(command); });
    return b;
}

QPushButton *ModePanel::button(const QString &name) const { return m_buttons.value(name); }

void ModePanel::setFullModeConfirmation(std::function<bool(QWidget *)> confirm)
{
    m_confirmFull = std::move(confirm);
}

void ModePanel::setProfile(const oi::RobotProfile &profile)
{
    m_profile = &profile;
    refreshButtons();
}

void ModePanel::refreshButtons()
{
    for (auto it = m_commands.cbegin(); it != m_commands.cend(); ++it) {
        QPushButton *b = it.key();
        const oi::CommandSpec &spec = oi::commandSpec(it.value());
        const bool available = m_profile->has(it.value());
        b->setEnabled(available && m_unavailable.isEmpty());
        // The document's command title stays as printed: it names the protocol command.
        const QString opcode = tr("%1 (opcode %2)").arg(QString::fromUtf8(spec.title.data(), spec.title.size()))
                                   .arg(spec.opcode);
        b->setToolTip(!available ? tr("%1 is not available on the %2")
                                       .arg(opcode, QString::fromUtf8(m_profile->name.data(), m_profile->name.size()))
                      : m_unavailable.isEmpty() ? opcode
                                                : m_unavailable);
    }
    m_demo->setEnabled(m_profile->has(oi::Command::Demo) && m_unavailable.isEmpty());
}

void ModePanel::setUnavailable(const QString &reason)
{
    if (reason == m_unavailable)
        return;
    m_unavailable = reason;
    refreshButtons();
}

void ModePanel::request(oi::Command command)
{
    if (!m_profile->has(command))
        return; // its button is disabled, with the reason
    if (command == oi::Command::Full && !(m_confirmFull && m_confirmFull(this)))
        return;
    emit modeRequested(command, command == oi::Command::Demo ? m_demo->currentData().toInt() : 0);
}

void ModePanel::setMode(const RobotMode &mode)
{
    const std::optional<oi::OiMode> reported = mode.reported();
    m_modeLabel->setText(reported ? tr("Mode: %1").arg(oitext::modeName(*reported)) : tr("Mode: unknown"));
    highlight(reported);
    // Said only of the mode shown above it, by the same session.
    m_safetyLabel->setText(mode.advice());
    m_safetyLabel->setVisible(!m_safetyLabel->text().isEmpty());
    // A program the user started is no alarm: it is said in the usual colour.
    const QColor alert = display::stateColor(display::State::Alert, palette());
    m_safetyLabel->setStyleSheet(mode.cause() == RobotMode::Cause::OwnProgram
                                     ? QString("QLabel { font-weight: bold; }")
                                     : QString("QLabel { color: %1; font-weight: bold; }").arg(alert.name()));
}

void ModePanel::highlight(std::optional<oi::OiMode> mode)
{
    const QString highlighted = !mode ? QString()
                                : *mode == oi::OiMode::Passive ? "passive"
                                : *mode == oi::OiMode::Safe    ? "safe"
                                : *mode == oi::OiMode::Full    ? "full"
                                                               : QString();
    const QColor fill = display::stateColor(display::State::Active, palette());
    const QColor text = display::textOn(display::State::Active, palette());
    for (const QString &name : {QString("passive"), QString("safe"), QString("full")}) {
        QPushButton *b = m_buttons.value(name);
        b->setProperty("current", name == highlighted);
        b->setStyleSheet(name == highlighted ? QString("QPushButton { background: %1; color: %2; font-weight: bold; }")
                                                   .arg(fill.name(), text.name())
                                             : QString());
    }
}

std::optional<oi::OiMode> ModePanel::highlightedMode() const
{
    for (auto [name, mode] : {std::pair{"passive", oi::OiMode::Passive}, std::pair{"safe", oi::OiMode::Safe},
                              std::pair{"full", oi::OiMode::Full}})
        if (m_buttons.value(name)->property("current").toBool())
            return mode;
    return std::nullopt;
}

QString ModePanel::safetyMessage() const { return m_safetyLabel->isHidden() ? QString() : m_safetyLabel->text(); }

void ModePanel::setFirmware(const QString &release)
{
    m_firmware = release;
    m_firmwareLabel->setText(release.isEmpty() ? QString() : tr("Firmware: %1").arg(release));
}

#include "moc_mode_panel.cpp"
