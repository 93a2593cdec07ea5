// SPDX-License-Identifier: GPL-3.0-or-later
// The LED editor's controls: the digits, the LEDs and the scheduling LEDs,
// laid out once.
#include "led_editor.h"

#include "seven_segment_display.h"

#include <QCheckBox>
#include <QFontDatabase>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>

namespace {

QLabel *wrappingLabel(const QString &name, QWidget *parent)
{
    auto *label = new QLabel(parent);
    label->setObjectName(name);
    label->setWordWrap(true);
    return label;
}

} // namespace

LedEditor::LedEditor(QWidget *parent) : QWidget(parent)
{
    m_liveTimer.setSingleShot(true);
    m_liveTimer.setTimerType(Qt::PreciseTimer); // the rate limit is a promise to the user
    m_liveTimer.setInterval(kLiveIntervalMs);
    connect(&m_liveTimer, &QTimer::timeout, this, &LedEditor::apply);

    m_live = new QCheckBox(this);
    m_live->setObjectName("live");
    m_apply = new QPushButton(this);
    m_apply->setObjectName("apply");
    m_preview = new QLabel(this);
    m_preview->setObjectName("bytePreview");
    m_preview->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_preview->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message = wrappingLabel("message", this);
    connect(m_apply, &QPushButton::clicked, this, &LedEditor::apply);
    connect(m_live, &QCheckBox::toggled, this, [this](bool live) {
        if (live)
            changed(); // what is pending goes out at once
        else
            m_liveTimer.stop();
        refresh();
    });

    auto *right = new QVBoxLayout;
    right->addWidget(buildLeds());
    right->addWidget(buildSchedulingLeds());
    right->addStretch();
    auto *columns = new QHBoxLayout;
    columns->addWidget(buildDigits(), 1);
    columns->addLayout(right, 1);

    auto *sendRow = new QHBoxLayout;
    sendRow->addWidget(m_live, 0, Qt::AlignTop);
    sendRow->addWidget(m_apply, 0, Qt::AlignTop);
    m_willSend = new QLabel(this);
    m_willSend->setMinimumHeight(m_apply->sizeHint().height());
    m_preview->setMinimumHeight(m_apply->sizeHint().height());
    sendRow->addWidget(m_willSend, 0, Qt::AlignTop);
    sendRow->addWidget(m_preview, 1, Qt::AlignTop);

    auto *layout = new QVBoxLayout(this);
    layout->addLayout(columns);
    layout->addLayout(sendRow);
    layout->addWidget(m_message);

    // Tab follows the screen: digits, LEDs, scheduling LEDs, then sending.
    QList<QWidget *> order{m_segments, m_clear, m_asciiText, m_debris, m_spot, m_dock, m_checkRobot, m_play,
                           m_advance, m_colour, m_intensity};
    for (QCheckBox *day : m_weekdays)
        order << day;
    order << m_schedule << m_clock << m_am << m_pm << m_colon << m_live << m_apply;
    for (int i = 1; i < order.size(); ++i)
        setTabOrder(order[i - 1], order[i]);

    setProfile(*m_profile); // also sets every text
}

QCheckBox *LedEditor::addCheck(const QString &name, QWidget *parent)
{
    auto *box = new QCheckBox(parent);
    box->setObjectName(name);
    return box;
}

QWidget *LedEditor::buildDigits()
{
    m_digitsGroup = new QGroupBox(this);
    m_digitsGroup->setObjectName("digitsGroup");
    m_digitsReason = wrappingLabel("digitsReason", m_digitsGroup);
    m_digitsContent = new QWidget(m_digitsGroup);

    m_segments = new SevenSegmentDisplay(m_digitsContent);
    m_segments->setObjectName("segmentEditor");
    m_segments->setEditable(true);
    m_clear = new QPushButton(m_digitsContent);
    m_clear->setObjectName("clearSegments");
    m_rawWarning = wrappingLabel("rawWarning", m_digitsContent);
    connect(m_segments, &SevenSegmentDisplay::segmentsChanged, this, [this] {
        m_digitsPending = DigitSource::Raw;
        changed();
    });
    connect(m_clear, &QPushButton::clicked, this, [this] {
        m_segments->setMasks({});
        m_digitsPending = DigitSource::Raw;
        changed();
    });

    m_asciiText = new QLineEdit(m_digitsContent);
    m_asciiText->setObjectName("asciiText");
    m_asciiText->setMaxLength(4);
    m_asciiPreview = new SevenSegmentDisplay(m_digitsContent);
    m_asciiPreview->setObjectName("asciiPreview");
    m_asciiMessage = wrappingLabel("asciiMessage", m_digitsContent);
    connect(m_asciiText, &QLineEdit::textChanged, this, &LedEditor::asciiEdited);

    m_rawTitle = new QLabel(m_digitsContent);
    m_rawTitle->setWordWrap(true);
    m_asciiTitle = new QLabel(m_digitsContent);
    m_asciiCaption = new QLabel(m_digitsContent);

    auto *rawRow = new QHBoxLayout;
    rawRow->addWidget(m_segments, 1);
    rawRow->addWidget(m_clear, 0, Qt::AlignTop);
    auto *content = new QVBoxLayout(m_digitsContent);
    content->setContentsMargins(0, 0, 0, 0);
    content->addWidget(m_rawTitle);
    content->addLayout(rawRow);
    content->addWidget(m_rawWarning);
    content->addSpacing(8);
    content->addWidget(m_asciiTitle);
    content->addWidget(m_asciiText);
    content->addWidget(m_asciiCaption);
    content->addWidget(m_asciiPreview);
    content->addWidget(m_asciiMessage);
    content->addStretch();

    auto *layout = new QVBoxLayout(m_digitsGroup);
    layout->addWidget(m_digitsReason);
    layout->addWidget(m_digitsContent);
    layout->addStretch();
    return m_digitsGroup;
}

QWidget *LedEditor::buildLeds()
{
    auto *group = m_ledsGroup = new QGroupBox(this);
    group->setObjectName("ledsGroup");
    m_debris = addCheck("ledDebris", group);
    m_spot = addCheck("ledSpot", group);
    m_dock = addCheck("ledDock", group);
    m_checkRobot = addCheck("ledCheckRobot", group);
    m_play = addCheck("ledPlay", group);
    m_advance = addCheck("ledAdvance", group);

    m_colour = new QSlider(Qt::Horizontal, group);
    m_colour->setObjectName("powerColour");
    m_colour->setRange(0, 255);
    m_colour->setValue(0);
    m_intensity = new QSlider(Qt::Horizontal, group);
    m_intensity->setObjectName("powerIntensity");
    m_intensity->setRange(0, 255);
    m_intensity->setValue(128);
    for (QSlider *slider : {m_colour, m_intensity})
        slider->setMinimumWidth(120);
    m_colourValue = new QLabel(group);
    m_intensityValue = new QLabel(group);
    for (QLabel *value : {m_colourValue, m_intensityValue}) {
        value->setMinimumWidth(value->fontMetrics().horizontalAdvance("255") + 4);
        value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    }
    m_swatch = new QLabel(group);
    m_swatch->setObjectName("powerSwatch");
    m_swatch->setFixedSize(36, 36);

    auto *toggles = new QHBoxLayout;
    for (QCheckBox *box : {m_debris, m_spot, m_dock, m_checkRobot, m_play, m_advance}) {
        toggles->addWidget(box);
        connect(box, &QCheckBox::toggled, this, [this] {
            m_ledsPending = true;
            changed();
        });
    }
    toggles->addStretch();

    m_colourLabel = new QLabel(group);
    m_greenLabel = new QLabel(group);
    m_redLabel = new QLabel(group);
    m_intensityLabel = new QLabel(group);
    m_offLabel = new QLabel(group);
    m_fullLabel = new QLabel(group);
    auto *power = new QGridLayout;
    power->addWidget(m_colourLabel, 0, 0);
    power->addWidget(m_greenLabel, 0, 1);
    power->addWidget(m_colour, 0, 2);
    power->addWidget(m_redLabel, 0, 3);
    power->addWidget(m_colourValue, 0, 4);
    power->addWidget(m_intensityLabel, 1, 0);
    power->addWidget(m_offLabel, 1, 1);
    power->addWidget(m_intensity, 1, 2);
    power->addWidget(m_fullLabel, 1, 3);
    power->addWidget(m_intensityValue, 1, 4);
    power->addWidget(m_swatch, 0, 5, 2, 1, Qt::AlignCenter);
    power->setColumnStretch(2, 1);
    for (QSlider *slider : {m_colour, m_intensity})
        connect(slider, &QSlider::valueChanged, this, [this] {
            m_ledsPending = true;
            changed();
        });

    auto *layout = new QVBoxLayout(group);
    layout->addLayout(toggles);
    layout->addLayout(power);
    return group;
}

QWidget *LedEditor::buildSchedulingLeds()
{
    m_schedulingGroup = new QGroupBox(this);
    m_schedulingGroup->setObjectName("schedulingGroup");
    m_schedulingReason = wrappingLabel("schedulingReason", m_schedulingGroup);
    m_schedulingContent = new QWidget(m_schedulingGroup);

    auto *days = new QHBoxLayout;
    for (int day = 0; day < 7; ++day) {
        m_weekdays[day] = addCheck(QString("weekday%1").arg(day), m_schedulingContent);
        days->addWidget(m_weekdays[day]);
    }
    days->addStretch();
    auto *indicators = new QHBoxLayout;
    m_schedule = addCheck("schedSchedule", m_schedulingContent);
    m_clock = addCheck("schedClock", m_schedulingContent);
    m_am = addCheck("schedAm", m_schedulingContent);
    m_pm = addCheck("schedPm", m_schedulingContent);
    m_colon = addCheck("schedColon", m_schedulingContent);
    for (QCheckBox *box : {m_schedule, m_clock, m_am, m_pm, m_colon})
        indicators->addWidget(box);
    indicators->addStretch();
    for (QCheckBox *box : m_schedulingContent->findChildren<QCheckBox *>())
        connect(box, &QCheckBox::toggled, this, [this] {
            m_schedulingPending = true;
            changed();
        });

    auto *content = new QVBoxLayout(m_schedulingContent);
    content->setContentsMargins(0, 0, 0, 0);
    content->addLayout(days);
    content->addLayout(indicators);
    auto *layout = new QVBoxLayout(m_schedulingGroup);
    layout->addWidget(m_schedulingReason);
    layout->addWidget(m_schedulingContent);
    return m_schedulingGroup;
}
