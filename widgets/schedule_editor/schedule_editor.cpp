// SPDX-License-Identifier: GPL-3.0-or-later
#include "schedule_editor.h"

#include "typed_time_edit.h"

#include "schedule.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QEvent>
#include <QFontDatabase>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QTimeEdit>
#include <QVBoxLayout>

namespace {

const char *const kPresetsKey = "scheduleEditor/presets";

QString decimal(const oi::Bytes &bytes)
{
    QStringList parts;
    for (std::uint8_t b : bytes)
        parts << QString::number(b);
    return parts.join(' ');
}

QString fromView(std::string_view text) { return QString::fromUtf8(text.data(), qsizetype(text.size())); }

const char *const kDayNames[] = {
    QT_TRANSLATE_NOOP("ScheduleEditor", "Sunday"),   QT_TRANSLATE_NOOP("ScheduleEditor", "Monday"),
    QT_TRANSLATE_NOOP("ScheduleEditor", "Tuesday"),  QT_TRANSLATE_NOOP("ScheduleEditor", "Wednesday"),
    QT_TRANSLATE_NOOP("ScheduleEditor", "Thursday"), QT_TRANSLATE_NOOP("ScheduleEditor", "Friday"),
    QT_TRANSLATE_NOOP("ScheduleEditor", "Saturday")};

// The robot's day 0..6 (Sunday first) in the user's language.
QString dayName(int day) { return QCoreApplication::translate("ScheduleEditor", kDayNames[day]); }

// The user's 12/24-hour habit, without the seconds the robot does not keep.
QString shortTimeFormat()
{
    static const QRegularExpression seconds("[.:]?s+");
    return QLocale().timeFormat(QLocale::ShortFormat).remove(seconds);
}

QString shortTime(QTime time) { return QLocale().toString(time, shortTimeFormat()); }

// The robot always gets 24-hour values, whatever the display shows.
QTimeEdit *timeEdit(const QString &name, QWidget *parent)
{
    auto *edit = new TypedTimeEdit(parent);
    edit->setObjectName(name);
    edit->setDisplayFormat(shortTimeFormat());
    return edit;
}

QLabel *previewLabel(const QString &name, QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setObjectName(name);
    label->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setWordWrap(true);
    return label;
}

} // namespace

ScheduleEditor::ScheduleEditor(QWidget *parent) : QWidget(parent)
{
    m_clock = [] { return QDateTime::currentDateTime(); };

    m_reason = new QLabel(this);
    m_reason->setObjectName("reason");
    m_reason->setWordWrap(true);
    m_content = new QWidget(this);

    // The weekly grid.
    auto *weekly = m_weekly = new QGroupBox(m_content);
    auto *grid = new QGridLayout;
    for (int day = 0; day < 7; ++day) {
        m_days[day] = new QCheckBox(weekly);
        m_days[day]->setObjectName(QString("day%1").arg(day));
        m_times[day] = timeEdit(QString("time%1").arg(day), weekly);
        m_times[day]->setEnabled(false);
        // One column a day, Sunday first, as the robot counts them.
        grid->addWidget(m_days[day], 0, day);
        grid->addWidget(m_times[day], 1, day);
        connect(m_days[day], &QCheckBox::toggled, m_times[day], &QWidget::setEnabled);
        connect(m_days[day], &QCheckBox::toggled, this, &ScheduleEditor::refresh);
        connect(m_times[day], &QTimeEdit::timeChanged, this, &ScheduleEditor::refresh);
    }
    auto *sendButton = m_sendSchedule = new QPushButton(weekly);
    sendButton->setObjectName("sendSchedule");
    auto *disableButton = m_disableAll = new QPushButton(weekly);
    disableButton->setObjectName("disableAll");
    connect(sendButton, &QPushButton::clicked, this, &ScheduleEditor::sendSchedule);
    connect(disableButton, &QPushButton::clicked, this, &ScheduleEditor::disableAll);
    m_schedulePreview = previewLabel("schedulePreview", weekly);
    m_lastSent = new QLabel(weekly);
    m_lastSent->setObjectName("lastSent");
    m_lastSent->setWordWrap(true);
    auto *sendRow = new QHBoxLayout;
    sendRow->addWidget(sendButton);
    sendRow->addWidget(disableButton);
    sendRow->addStretch();
    auto *weeklyLayout = new QVBoxLayout(weekly);
    weeklyLayout->addLayout(grid);
    weeklyLayout->addLayout(sendRow);
    weeklyLayout->addWidget(m_schedulePreview);
    weeklyLayout->addWidget(m_lastSent);

    // Presets of the grid.
    auto *presets = m_presetBox = new QGroupBox(m_content);
    m_presets = new QComboBox(presets);
    m_presets->setObjectName("presetList");
    m_presets->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_loadPreset = new QPushButton(presets);
    m_loadPreset->setObjectName("loadPreset");
    m_deletePreset = new QPushButton(presets);
    m_deletePreset->setObjectName("deletePreset");
    m_presetName = new QLineEdit(presets);
    m_presetName->setObjectName("presetName");
    auto *saveButton = m_savePreset = new QPushButton(presets);
    saveButton->setObjectName("savePreset");
    connect(m_loadPreset, &QPushButton::clicked, this, [this] { loadPreset(m_presets->currentText()); });
    connect(m_deletePreset, &QPushButton::clicked, this, [this] { deletePreset(m_presets->currentText()); });
    connect(saveButton, &QPushButton::clicked, this, [this] { savePreset(m_presetName->text()); });
    connect(m_presetName, &QLineEdit::returnPressed, this, [this] { savePreset(m_presetName->text()); });
    auto *presetLayout = new QGridLayout(presets);
    presetLayout->addWidget(m_presets, 0, 0);
    presetLayout->addWidget(m_loadPreset, 0, 1);
    presetLayout->addWidget(m_deletePreset, 0, 2);
    presetLayout->addWidget(m_presetName, 1, 0);
    presetLayout->addWidget(saveButton, 1, 1);
    presetLayout->setColumnStretch(0, 1);
    presetLayout->setRowStretch(2, 1);

    // The robot's clock.
    auto *clock = m_clockBox = new QGroupBox(m_content);
    auto *fromComputer = m_fromComputer = new QPushButton(clock);
    fromComputer->setObjectName("setFromComputer");
    m_clockDay = new QComboBox(clock);
    m_clockDay->setObjectName("clockDay");
    m_clockDay->setSizeAdjustPolicy(QComboBox::AdjustToContents); // its texts change with the language
    for (int day = 0; day < 7; ++day)
        m_clockDay->addItem(QString(), day);
    m_clockTime = timeEdit("clockTime", clock);
    auto *setChosen = m_setChosen = new QPushButton(clock);
    setChosen->setObjectName("setDayTime");
    m_clockPreview = previewLabel("clockPreview", clock);
    connect(fromComputer, &QPushButton::clicked, this, &ScheduleEditor::setDayTimeFromComputer);
    connect(setChosen, &QPushButton::clicked, this, &ScheduleEditor::sendChosenDayTime);
    connect(m_clockDay, &QComboBox::currentIndexChanged, this, &ScheduleEditor::refresh);
    connect(m_clockTime, &QTimeEdit::timeChanged, this, &ScheduleEditor::refresh);
    auto *chosenRow = new QHBoxLayout;
    chosenRow->addWidget(m_clockDay);
    chosenRow->addWidget(m_clockTime);
    chosenRow->addWidget(setChosen);
    chosenRow->addStretch();
    auto *clockLayout = new QVBoxLayout(clock);
    clockLayout->addWidget(fromComputer, 0, Qt::AlignLeft);
    clockLayout->addLayout(chosenRow);
    clockLayout->addWidget(m_clockPreview);
    clockLayout->addStretch();

    m_message = new QLabel(m_content);
    m_message->setObjectName("message");
    m_message->setWordWrap(true);
    m_message->setTextFormat(Qt::PlainText); // it names presets, as written

    auto *lower = new QHBoxLayout;
    lower->addWidget(presets, 1);
    lower->addWidget(clock, 1);
    auto *contentLayout = new QVBoxLayout(m_content);
    contentLayout->setContentsMargins(0, 0, 0, 0);
    contentLayout->addWidget(weekly);
    contentLayout->addLayout(lower);
    contentLayout->addWidget(m_message);
    contentLayout->addStretch();

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_reason);
    layout->addWidget(m_content);

    refreshPresets();
    setProfile(*m_profile); // also sets every text
}

void ScheduleEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ScheduleEditor::retranslateUi()
{
    m_weekly->setTitle(tr("Weekly cleaning schedule (167)"));
    for (int day = 0; day < 7; ++day) {
        m_days[day]->setText(dayName(day));
        m_times[day]->setAccessibleName(tr("Cleaning time on %1").arg(dayName(day)));
        m_clockDay->setItemText(day, dayName(day)); // index and data stay
    }
    m_sendSchedule->setText(tr("Send Schedule"));
    m_disableAll->setText(tr("Disable all"));
    m_disableAll->setToolTip(tr("Clear every day and send a schedule with no cleaning"));
    m_lastSent->setText(m_lastSentAt.isEmpty()
                            ? tr("Nothing sent yet. The robot cannot report its schedule, so this "
                                 "shows what was last sent from here.")
                            : tr("Last sent: %1 at %2").arg(m_lastSentSchedule, m_lastSentAt));

    m_presetBox->setTitle(tr("Presets"));
    m_presets->setAccessibleName(tr("Saved presets"));
    m_loadPreset->setText(tr("Load"));
    m_deletePreset->setText(tr("Delete"));
    m_presetName->setPlaceholderText(tr("Preset name"));
    m_presetName->setAccessibleName(tr("Preset name"));
    m_savePreset->setText(tr("Save"));
    m_savePreset->setToolTip(tr("Save the grid under this name"));

    m_clockBox->setTitle(tr("Robot clock (168)"));
    m_fromComputer->setText(tr("Set from this computer's clock"));
    m_clockDay->setAccessibleName(tr("Day for the robot clock"));
    m_clockTime->setAccessibleName(tr("Time for the robot clock"));
    m_setChosen->setText(tr("Set Day/Time"));

    m_reason->setText(tr("The %1 has no cleaning schedule or clock: Schedule (167) and "
                         "Set Day/Time (168) are Roomba 500 / Create 2 only.")
                          .arg(fromView(m_profile->name)));
    if (m_messageText)
        m_message->setText(m_messageText());
    refresh();
}

void ScheduleEditor::showMessage(std::function<QString()> text)
{
    m_messageText = std::move(text);
    m_message->setText(m_messageText());
}

void ScheduleEditor::setProfile(const oi::RobotProfile &profile)
{
    m_profile = &profile;
    const oi::CommandEncoder encoder(profile);
    const auto refused = encoder.refuse(oi::Command::Schedule);
    m_content->setEnabled(!refused);
    m_reason->setVisible(bool(refused));
    retranslateUi(); // the reason names the profile
}

void ScheduleEditor::setClock(std::function<QDateTime()> clock) { m_clock = std::move(clock); }

void ScheduleEditor::setChosenDayTime(oi::Weekday day, QTime time)
{
    m_clockDay->setCurrentIndex(static_cast<int>(day));
    m_clockTime->setTime(time);
}

oi::CleaningSchedule ScheduleEditor::schedule() const
{
    oi::CleaningSchedule s;
    for (int day = 0; day < 7; ++day)
        if (m_days[day]->isChecked()) {
            const QTime t = m_times[day]->time();
            s.days[day] = oi::ClockTime{t.hour(), t.minute()};
        }
    return s;
}

void ScheduleEditor::setSchedule(const oi::CleaningSchedule &schedule)
{
    for (int day = 0; day < 7; ++day) {
        m_days[day]->setChecked(schedule.days[day].has_value());
        if (schedule.days[day])
            m_times[day]->setTime(QTime(schedule.days[day]->hour, schedule.days[day]->minute));
    }
    refresh();
}

void ScheduleEditor::refresh()
{
    const oi::CommandEncoder encoder(*m_profile);
    const auto bytes = encoder.schedule(schedule());
    // Where the profile lacks the commands the reason above says why.
    m_scheduleBytes = bytes.ok() ? decimal(*bytes) : QString();
    m_schedulePreview->setText(bytes.ok() ? tr("Will send: %1").arg(m_scheduleBytes) : QString());
    const QTime t = m_clockTime->time();
    const auto clock = encoder.setDayTime(m_clockDay->currentIndex(), t.hour(), t.minute());
    m_clockBytes = clock.ok() ? decimal(*clock) : QString();
    m_clockPreview->setText(clock.ok() ? tr("Will send: %1").arg(m_clockBytes) : QString());
}

QString ScheduleEditor::schedulePreview() const { return m_scheduleBytes; }
QString ScheduleEditor::clockPreview() const { return m_clockBytes; }
QString ScheduleEditor::lastSent() const { return m_lastSent->text(); }
QString ScheduleEditor::message() const { return m_message->text(); }

bool ScheduleEditor::send(const oi::OiCommand &command)
{
    const oi::EncodeResult result = oi::encodeCommand(oi::CommandEncoder(*m_profile), command);
    if (!result.ok()) {
        const QString why = QString::fromStdString(result.error().describe()); // the protocol's words
        showMessage([why] { return tr("Not sent: %1").arg(why); });
        return false;
    }
    emit sendRequested({command});
    return true;
}

void ScheduleEditor::sendSchedule()
{
    const oi::CleaningSchedule s = schedule();
    const auto bytes = oi::scheduleBytes(s); // days, then hour and minute Sunday..Saturday
    if (!send({oi::Command::Schedule, std::vector<int>(bytes.begin(), bytes.end()), {}}))
        return;
    m_lastSentSchedule = QString::fromStdString(oi::formatSchedule(s));
    m_lastSentAt = shortTime(m_clock().time());
    m_lastSent->setText(tr("Last sent: %1 at %2").arg(m_lastSentSchedule, m_lastSentAt));
    const bool off = s.isOff();
    showMessage([off] { return off ? tr("Sent: no scheduled cleaning.") : tr("Schedule sent."); });
}

void ScheduleEditor::disableAll()
{
    if (auto refused = oi::CommandEncoder(*m_profile).refuse(oi::Command::Schedule)) {
        const QString why = QString::fromStdString(refused->describe());
        showMessage([why] { return tr("Not sent: %1").arg(why); });
        return;
    }
    setSchedule(oi::CleaningSchedule{});
    sendSchedule();
}

void ScheduleEditor::sendDayTime(int day, int hour, int minute)
{
    if (send({oi::Command::SetDayTime, {day, hour, minute}, {}}))
        showMessage([=] {
            return tr("Robot clock set to %1 %2.").arg(dayName(day), shortTime(QTime(hour, minute)));
        });
}

void ScheduleEditor::setDayTimeFromComputer()
{
    const QDateTime now = m_clock();
    // Qt counts Monday 1 .. Sunday 7; the robot counts Sunday 0 .. Saturday 6.
    sendDayTime(now.date().dayOfWeek() % 7, now.time().hour(), now.time().minute());
}

void ScheduleEditor::sendChosenDayTime()
{
    const QTime t = m_clockTime->time();
    sendDayTime(m_clockDay->currentIndex(), t.hour(), t.minute());
}

QStringList ScheduleEditor::presetNames() const
{
    return QSettings().value(kPresetsKey).toMap().keys();
}

void ScheduleEditor::refreshPresets()
{
    const QString current = m_presets->currentText();
    m_presets->clear();
    m_presets->addItems(presetNames());
    m_presets->setCurrentIndex(qMax(0, m_presets->findText(current)));
    const bool any = m_presets->count() > 0;
    m_presets->setEnabled(any);
    m_loadPreset->setEnabled(any);
    m_deletePreset->setEnabled(any);
}

bool ScheduleEditor::savePreset(const QString &name)
{
    const QString trimmed = name.trimmed();
    if (trimmed.isEmpty()) {
        showMessage([] { return tr("Not saved: give the preset a name."); });
        return false;
    }
    QSettings settings;
    QVariantMap map = settings.value(kPresetsKey).toMap();
    const bool replaced = map.contains(trimmed);
    map.insert(trimmed, QString::fromStdString(oi::formatSchedule(schedule())));
    settings.setValue(kPresetsKey, map);
    refreshPresets();
    m_presets->setCurrentIndex(m_presets->findText(trimmed));
    showMessage([=] {
        return (replaced ? tr("Preset \"%1\" replaced.") : tr("Preset \"%1\" saved.")).arg(trimmed);
    });
    return true;
}

bool ScheduleEditor::loadPreset(const QString &name)
{
    const QVariantMap map = QSettings().value(kPresetsKey).toMap();
    if (!map.contains(name)) {
        showMessage([=] { return tr("No preset named \"%1\".").arg(name); });
        return false;
    }
    const auto parsed = oi::parseSchedule(map.value(name).toString().toStdString());
    if (!parsed.ok()) {
        // A damaged preset leaves the grid as it was.
        const QString why = QString::fromStdString(parsed.error().describe());
        showMessage([=] { return tr("Preset \"%1\" is damaged: %2").arg(name, why); });
        return false;
    }
    setSchedule(parsed.value());
    m_message->setText(tr("Preset \"%1\" loaded; press Send Schedule to send it.").arg(name));
    return true;
}

bool ScheduleEditor::deletePreset(const QString &name)
{
    QSettings settings;
    QVariantMap map = settings.value(kPresetsKey).toMap();
    if (!map.remove(name)) {
        showMessage([=] { return tr("No preset named \"%1\".").arg(name); });
        return false;
    }
    settings.setValue(kPresetsKey, map);
    refreshPresets();
    showMessage([=] { return tr("Preset \"%1\" deleted.").arg(name); });
    return true;
}

#include "moc_schedule_editor.cpp"
