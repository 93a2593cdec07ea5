// SPDX-License-Identifier: GPL-3.0-or-later
#include "replay_bar.h"

#include "display_palette.h"

#include <QComboBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QToolButton>

#include <algorithm>
#include <cmath>

namespace {
// The slider counts milliseconds: fine enough for a frame every 15 ms.
constexpr qint64 kUsPerStep = 1000;
} // namespace

QString ReplayBar::clock(qint64 us)
{
    const qint64 tenths = us / 100000;
    return QStringLiteral("%1:%2.%3")
        .arg(tenths / 600)
        .arg((tenths / 10) % 60, 2, 10, QLatin1Char('0'))
        .arg(tenths % 10);
}

// A slider that draws each marker as a tick across its groove.
class MarkedSlider : public QSlider {
public:
    using QSlider::QSlider;
    QList<PlotMarker> markers;

    // The x of `seconds` on the groove, in the slider's pixels.
    int tickX(double seconds) const
    {
        QStyleOptionSlider option;
        initStyleOption(&option);
        const QRect groove = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderGroove, this);
        const QRect handle = style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, this);
        // The handle's centre travels from half a handle in to half a handle from the end.
        const int span = groove.width() - handle.width();
        const int value = int(std::llround(seconds * 1e6 / double(kUsPerStep)));
        return groove.left() + handle.width() / 2
               + QStyle::sliderPositionFromValue(minimum(), maximum(), std::clamp(value, minimum(), maximum()), span);
    }

protected:
    void paintEvent(QPaintEvent *event) override
    {
        QSlider::paintEvent(event);
        QPainter p(this);
        p.setPen(QPen(palette().color(QPalette::Text), 2)); // as the plots draw markers
        for (const PlotMarker &m : markers) {
            const int x = tickX(m.seconds);
            p.drawLine(x, 0, x, height());
        }
    }
};

const QList<double> &ReplayBar::speeds()
{
    static const QList<double> list{0.25, 0.5, 1.0, 2.0, 4.0, 10.0};
    return list;
}

ReplayBar::ReplayBar(QWidget *parent) : QWidget(parent)
{
    auto *row = new QHBoxLayout(this);
    row->setContentsMargins(4, 0, 4, 0);
    m_back = new QToolButton(this);
    m_back->setObjectName("replayStepBack");
    m_playPause = new QToolButton(this);
    m_playPause->setObjectName("replayPlayPause");
    m_forward = new QToolButton(this);
    m_forward->setObjectName("replayStepForward");
    m_speed = new QComboBox(this);
    m_speed->setObjectName("replaySpeed");
    for (double s : speeds())
        m_speed->addItem(QStringLiteral("%1×").arg(s), s);
    m_speed->setCurrentIndex(int(speeds().indexOf(1.0)));
    m_previousMarker = new QToolButton(this);
    m_previousMarker->setObjectName("replayPreviousMarker");
    m_nextMarker = new QToolButton(this);
    m_nextMarker->setObjectName("replayNextMarker");
    m_slider = new MarkedSlider(Qt::Horizontal, this);
    m_slider->setObjectName("replaySlider");
    m_slider->setMinimumWidth(200);
    m_time = new QLabel(this);
    m_time->setObjectName("replayTime");
    m_damage = new QLabel(this);
    m_damage->setObjectName("replayDamage");
    m_damage->setWordWrap(false);
    m_damage->setStyleSheet(QStringLiteral("QLabel { color: %1; font-weight: bold; }")
                                .arg(display::stateColor(display::State::Alert, palette()).name()));
    for (QWidget *w : {static_cast<QWidget *>(m_back), static_cast<QWidget *>(m_playPause),
                       static_cast<QWidget *>(m_forward), static_cast<QWidget *>(m_speed)})
        row->addWidget(w);
    row->addWidget(m_previousMarker);
    row->addWidget(m_slider, 1);
    row->addWidget(m_nextMarker);
    row->addWidget(m_time);
    row->addWidget(m_damage);

    connect(m_playPause, &QToolButton::clicked, this, [this] {
        if (m_position.playing)
            emit pauseRequested();
        else
            emit playRequested();
    });
    connect(m_back, &QToolButton::clicked, this, [this] { emit stepRequested(-1); });
    connect(m_forward, &QToolButton::clicked, this, [this] { emit stepRequested(1); });
    connect(m_previousMarker, &QToolButton::clicked, this, &ReplayBar::previousMarkerRequested);
    connect(m_nextMarker, &QToolButton::clicked, this, &ReplayBar::nextMarkerRequested);
    connect(m_speed, &QComboBox::activated, this, [this](int i) { emit speedChosen(m_speed->itemData(i).toDouble()); });
    connect(m_slider, &QSlider::sliderPressed, this, [this] { m_dragging = true; });
    connect(m_slider, &QSlider::sliderReleased, this, [this] {
        m_dragging = false;
        emit seekRequested(m_slider->value() * kUsPerStep);
    });
    // Keys and clicks on the groove move the slider without a drag.
    connect(m_slider, &QSlider::actionTriggered, this, [this](int action) {
        if (action != QAbstractSlider::SliderMove)
            QMetaObject::invokeMethod(this, [this] { emit seekRequested(m_slider->value() * kUsPerStep); },
                                      Qt::QueuedConnection);
    });
    retranslateUi();
}

void ReplayBar::retranslateUi()
{
    m_back->setToolTip(tr("One frame back"));
    m_back->setAccessibleName(tr("One frame back"));
    m_forward->setToolTip(tr("One frame forward"));
    m_forward->setAccessibleName(tr("One frame forward"));
    m_previousMarker->setToolTip(tr("Previous marker (,)"));
    m_previousMarker->setAccessibleName(tr("Previous marker"));
    m_nextMarker->setToolTip(tr("Next marker (.)"));
    m_nextMarker->setAccessibleName(tr("Next marker"));
    m_speed->setToolTip(tr("Replay speed"));
    m_speed->setAccessibleName(tr("Replay speed"));
    m_slider->setToolTip(tr("Position in the recording"));
    m_slider->setAccessibleName(tr("Position in the recording"));
    showPosition();
}

void ReplayBar::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    if (event->type() == QEvent::StyleChange && !m_playIcon.isNull())
        showIcons();
    QWidget::changeEvent(event);
}

void ReplayBar::showEvent(QShowEvent *event)
{
    if (m_playIcon.isNull())
        showIcons();
    QWidget::showEvent(event);
}

void ReplayBar::showIcons()
{
    m_back->setIcon(style()->standardIcon(QStyle::SP_MediaSeekBackward));
    m_forward->setIcon(style()->standardIcon(QStyle::SP_MediaSeekForward));
    m_previousMarker->setIcon(style()->standardIcon(QStyle::SP_MediaSkipBackward));
    m_nextMarker->setIcon(style()->standardIcon(QStyle::SP_MediaSkipForward));
    m_playIcon = style()->standardIcon(QStyle::SP_MediaPlay);
    m_pauseIcon = style()->standardIcon(QStyle::SP_MediaPause);
    m_playPause->setIcon(m_position.playing ? m_pauseIcon : m_playIcon);
}

void ReplayBar::setPosition(const Position &position)
{
    m_position = position;
    showPosition();
}

void ReplayBar::setMarkers(const QList<PlotMarker> &markers)
{
    if (markers == m_slider->markers)
        return;
    m_slider->markers = markers;
    m_previousMarker->setEnabled(!markers.isEmpty());
    m_nextMarker->setEnabled(!markers.isEmpty());
    m_slider->update();
}

const QList<PlotMarker> &ReplayBar::markers() const
{
    return m_slider->markers;
}

int ReplayBar::tickX(double seconds) const
{
    return m_slider->mapTo(this, QPoint(m_slider->tickX(seconds), 0)).x();
}

void ReplayBar::showPosition()
{
    const Position &p = m_position;
    const QString playText = p.playing ? tr("Pause") : tr("Play");
    m_playPause->setIcon(p.playing ? m_pauseIcon : m_playIcon);
    m_playPause->setToolTip(playText);
    m_playPause->setAccessibleName(playText);
    const int index = int(speeds().indexOf(p.speed));
    if (index >= 0)
        m_speed->setCurrentIndex(index);
    m_slider->setRange(0, int(p.durationUs / kUsPerStep));
    if (!m_dragging)
        m_slider->setValue(int(p.positionUs / kUsPerStep));
    m_time->setText(tr("%1 / %2, frame %3 of %4")
                        .arg(clock(p.positionUs), clock(p.durationUs))
                        .arg(p.frame + 1)
                        .arg(p.frameCount));
    m_damage->setVisible(!p.damage.isEmpty());
    m_damage->setText(tr("Damaged: replays up to %1").arg(clock(p.durationUs)));
    m_damage->setToolTip(p.damage);
    setAccessibleDescription(m_time->text());
}

#include "moc_replay_bar.cpp"
