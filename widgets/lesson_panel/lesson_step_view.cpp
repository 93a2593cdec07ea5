// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_step_view.h"

#include "display_palette.h"
#include "lesson_runner.h"
#include "oi_text.h"
#include "robot_diagram.h"
#include "plot_stack.h"
#include "sensor_plots.h"
#include "shipped_lessons.h"
#include "value_gauge.h"

#include <QEvent>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QFontInfo>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QVBoxLayout>

#include <cmath>

namespace {

QString number(double v)
{
    return std::abs(v - std::round(v)) < 1e-9 ? QString::number(qint64(std::llround(v))) : QString::number(v, 'f', 1);
}

bool isIrPacket(const QString &key)
{
    return key == QLatin1String("ir_omni") || key == QLatin1String("ir_left") || key == QLatin1String("ir_right");
}

} // namespace

LessonStepView::LessonStepView(QWidget *parent)
    : QWidget(parent), m_profile(&oi::profile(oi::ProfileId::Create2))
{
    // The step's texts come from a lesson file and are shown as written:
    // rich text would open the files its pictures name.
    m_heading = new QLabel(this);
    m_heading->setObjectName("lessonStepHeading");
    m_heading->setTextFormat(Qt::PlainText);
    m_text = new QLabel(this);
    m_text->setObjectName("lessonStepText");
    m_text->setWordWrap(true);
    m_text->setTextFormat(Qt::PlainText);
    m_text->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    m_goal = new QLabel(this);
    m_goal->setObjectName("lessonGoal");
    m_goal->setWordWrap(true);
    m_goal->setTextFormat(Qt::PlainText);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 100);
    m_progress->setObjectName("lessonProgress");
    // With its figure in it, never an empty box beside the goal.
    m_progress->setTextVisible(true);
    m_progress->setAlignment(Qt::AlignCenter);
    m_outOfReach = new QLabel(this);
    m_outOfReach->setObjectName("lessonOutOfReach");
    m_outOfReach->setWordWrap(true);
    m_outOfReach->setTextFormat(Qt::PlainText);
    m_outOfReach->hide();
    m_placement = new QPushButton(this);
    m_placement->setObjectName("lessonPlacement");
    m_placement->setFocusPolicy(Qt::NoFocus); // the window's keys keep driving
    m_placement->hide();
    connect(m_placement, &QPushButton::clicked, this, [this] {
        if (m_step && m_step->virtualRobot)
            emit placementRequested(*m_step->virtualRobot);
    });
    m_diagram = new RobotDiagram(this);
    m_plots = new SensorPlots(this);
    m_plots->stack()->setWindowSeconds(30);
    m_plots->stack()->setChannelsFixed(true);
    // The step chooses what is plotted, over the last 30 s: no adding,
    // exporting or other windows here, and the plot keeps the room those
    // controls would take on a small screen.
    for (const char *tool : {"addPlot", "export", "window", "windowLabel"})
        if (QWidget *button = m_plots->findChild<QWidget *>(tool))
            button->hide();

    auto *goalRow = new QHBoxLayout;
    goalRow->addWidget(m_goal, 3);
    goalRow->addWidget(m_progress, 1);
    auto *views = new QSplitter(Qt::Horizontal, this);
    views->addWidget(m_diagram);
    views->addWidget(m_plots);
    views->setStretchFactor(0, 2);
    views->setStretchFactor(1, 3);
    // The readouts beside the views, not below them: on a 720p projector
    // the diagram and the plot keep the height.
    m_readoutGrid = new QGridLayout;
    auto *viewsRow = new QHBoxLayout;
    viewsRow->addWidget(views, 1);
    viewsRow->addLayout(m_readoutGrid);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_heading);
    layout->addWidget(m_text);
    layout->addLayout(goalRow);
    layout->addWidget(m_outOfReach);
    layout->addWidget(m_placement, 0, Qt::AlignLeft);
    layout->addLayout(viewsRow, 1);
    applyScale();
    retranslateUi();
    showStep();
}

void LessonStepView::setProfile(const oi::RobotProfile &profile)
{
    m_profile = &profile;
    m_diagram->setProfile(profile);
    m_plots->setProfile(profile);
    showStep();
}

void LessonStepView::setHistory(const SensorHistory *history)
{
    m_plots->setHistory(history);
}

void LessonStepView::setStep(const LessonStep *step, int index, int count, const QStringList &readouts)
{
    m_step = step;
    m_index = index;
    m_count = count;
    m_readoutKeys = step ? step->readout : readouts;
    showStep();
}

void LessonStepView::setScale(qreal scale)
{
    m_scale = scale;
    applyScale();
}

void LessonStepView::setLeastTextPixels(int pixels)
{
    m_leastTextPixels = pixels;
    m_diagram->setLeastTextPixels(pixels);
    applyScale();
}

void LessonStepView::applyScale()
{
    // `factor` times the desktop's type, never under m_leastTextPixels.
    const auto sized = [this](qreal factor, bool bold = false, qreal least = 0) {
        least = std::max<qreal>(least, m_leastTextPixels);
        QFont f = font();
        f.setPointSizeF(font().pointSizeF() * factor);
        f.setBold(bold);
        // In points still: the plots scale their axes' type from it.
        if (const int pixels = QFontInfo(f).pixelSize(); pixels > 0 && pixels < least)
            f.setPointSizeF(f.pointSizeF() * (least + 0.5) / pixels);
        return f;
    };
    m_heading->setFont(sized(1.3 * m_scale, true));
    m_text->setFont(sized(1.5 * m_scale));
    const QFont goal = sized(1.2 * m_scale, true);
    m_goal->setFont(goal);
    m_outOfReach->setFont(goal);
    m_placement->setFont(goal);
    const QFont progress = sized(std::max(1.0, 0.8 * m_scale), true);
    m_progress->setFont(progress);
    m_progress->setFixedHeight(std::max(int(18 * m_scale), QFontMetrics(progress).height() + 6));
    // Its axes' type is 0.9 times this.
    m_plots->setFont(sized(std::max(1.0, m_scale * 0.7), false, m_leastTextPixels / 0.9 + 1));
    for (ValueGauge *g : std::as_const(m_readouts)) {
        const QFont f = sized(m_scale);
        g->setFont(f);
        g->setMaximumWidth(QFontMetrics(f).averageCharWidth() * 26);
    }
}

void LessonStepView::showStep()
{
    const bool inLesson = m_step != nullptr;
    m_heading->setVisible(inLesson);
    m_text->setVisible(inLesson);
    m_goal->setVisible(inLesson);
    m_progress->setVisible(inLesson);
    if (inLesson) {
        m_heading->setText(tr("Step %1 of %2").arg(m_index + 1).arg(m_count));
        m_text->setText(lesson::translated(m_step->text));
        m_goal->setText(tr("Goal: %1").arg(describeGoal(m_step->goal, *m_profile)));
        m_progress->setValue(0);
        m_progress->setFormat(tr("%p %"));
    }
    if (!inLesson)
        m_outOfReach->hide();
    showPlacement();
    m_diagram->setHighlightedParts(inLesson ? m_step->highlight : QStringList());
    std::vector<int> channels;
    for (const QString &key : inLesson ? m_step->plot : QStringList())
        if (const oi::PacketInfo *p = lesson::packetByKey(*m_profile, key))
            channels.push_back(p->id);
    if (channels.empty())
        channels.push_back(lesson::packetByKey(*m_profile, "current")->id);
    m_plots->stack()->setChannels(0, channels);
    rebuildReadouts();
}

void LessonStepView::showPlacement()
{
    const bool shown = m_step && m_step->virtualRobot && m_virtualRobotHere;
    if (shown)
        m_placement->setText(tr("On the virtual robot: %1").arg(lesson::translated(m_step->virtualRobot->label)));
    m_placement->setVisible(shown);
}

void LessonStepView::rebuildReadouts()
{
    qDeleteAll(m_readouts);
    m_readouts.clear();
    for (const QString &key : std::as_const(m_readoutKeys)) {
        const bool pose = lesson::poseReadouts().contains(key);
        if (!pose && !lesson::packetByKey(*m_profile, key))
            continue; // a packet this robot lacks
        auto *gauge = new ValueGauge(QString(), this);
        gauge->setObjectName(QStringLiteral("readout_%1").arg(key));
        gauge->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum); // the views take the height
        gauge->setCompact(true);
        // One column, or two when there are more than two: a column of four
        // is taller than a 1280x720 projector leaves beside the views.
        const int columns = m_readoutKeys.size() > 2 ? 2 : 1;
        const int at = int(m_readouts.size());
        m_readouts.insert(key, gauge);
        m_readoutGrid->addWidget(gauge, at / columns, at % columns, Qt::AlignTop);
    }
    applyScale();
    retranslateUi();
}

void LessonStepView::refresh(const oi::SensorSnapshot &latest, bool stale, const LessonRunner *runner)
{
    m_diagram->setSnapshot(latest);
    // One flag for every view of the step: the plot's badge never says Live
    // beside the diagram's STALE banner.
    m_diagram->setStale(stale);
    m_plots->setStale(stale);
    if (isVisible())
        m_plots->refresh();
    if (const bool here = runner && runner->trueDrivenMm().has_value(); here != m_virtualRobotHere) {
        m_virtualRobotHere = here;
        showPlacement();
    }
    if (m_step && runner) {
        m_progress->setValue(int(std::lround(runner->progress() * 100)));
        const double toRead = runner->secondsToRead();
        m_progress->setFormat(toRead > 0 ? tr("Done · next in %1 s").arg(std::ceil(toRead)) : tr("%p %"));
    }
    for (auto it = m_readouts.cbegin(); it != m_readouts.cend(); ++it) {
        const QString &key = it.key();
        ValueGauge *gauge = it.value();
        gauge->setStale(stale);
        if (lesson::poseReadouts().contains(key)) {
            const std::optional<double> v = runner ? runner->readout(key) : std::nullopt;
            const bool degrees = key.endsWith(QLatin1String("_deg"));
            gauge->setValue(v ? QString::number(*v, 'f', 0) : QStringLiteral("—"),
                            degrees ? QStringLiteral("°") : QStringLiteral("mm"));
            gauge->setDetail(v ? QString() : tr("only on the virtual robot"));
            continue;
        }
        const oi::PacketInfo *p = lesson::packetByKey(*m_profile, key);
        if (!latest.has(p->id)) {
            gauge->setValue(QStringLiteral("—"));
            continue;
        }
        const std::int32_t value = latest.raw(p->id);
        if (isIrPacket(key)) {
            // The short name in the large type; the whole one below it.
            const oi::IrCharacter ir = oi::decodeIrCharacter(*m_profile, std::uint8_t(value));
            const QString full = oitext::infraredName(ir);
            const QString shown = oitext::infraredShortName(ir);
            gauge->setValue(shown);
            gauge->setDetail(shown == full ? QString::number(value) : full + QStringLiteral(" · ") + QString::number(value));
        } else if (const auto bits = m_profile->bits(p->id); !bits.empty()) {
            QStringList on;
            for (const oi::BitMeaning &b : bits)
                if (value & b.mask)
                    on << oitext::bitName(b);
            gauge->setValue(on.isEmpty() ? tr("none") : on.join(QStringLiteral(" + ")));
            gauge->setDetail(QString::number(value));
        } else {
            gauge->setValue(QString::number(value), oitext::fromView(p->unit));
        }
    }
}

QString LessonStepView::headingText() const { return m_step ? m_heading->text() : QString(); }
QString LessonStepView::stepText() const { return m_text->text(); }
QString LessonStepView::goalText() const { return m_goal->text(); }
int LessonStepView::progressPercent() const { return m_progress->value(); }
QString LessonStepView::progressText() const { return m_progress->text(); }
QString LessonStepView::outOfReachText() const { return m_outOfReach->isHidden() ? QString() : m_outOfReach->text(); }

void LessonStepView::setOutOfReach(const QString &why)
{
    m_outOfReach->setText(why);
    m_outOfReach->setVisible(m_step && !why.isEmpty());
    QPalette alert = m_outOfReach->palette();
    alert.setColor(QPalette::WindowText, display::stateColor(display::State::Alert, palette()));
    m_outOfReach->setPalette(alert);
}

QString LessonStepView::readoutText(const QString &key) const
{
    const ValueGauge *g = m_readouts.value(key);
    return g ? g->text() : QString();
}

QString LessonStepView::describeGoal(const LessonGoal &goal, const oi::RobotProfile &profile)
{
    QString text;
    switch (goal.kind) {
    case LessonGoal::Kind::Any:
    case LessonGoal::Kind::All: {
        QStringList parts;
        for (const LessonGoal &g : goal.goals)
            parts << describeGoal(g, profile);
        text = parts.join(goal.kind == LessonGoal::Kind::Any ? tr(" or ") : tr(" and "));
        break;
    }
    case LessonGoal::Kind::Drive:
        text = tr("drive %1 mm").arg(number(goal.distanceMm));
        break;
    case LessonGoal::Kind::Turn:
        text = tr("turn %1°").arg(number(goal.degrees));
        break;
    case LessonGoal::Kind::Packet: {
        const oi::PacketInfo *p = lesson::packetByKey(profile, goal.packet);
        if (!p)
            return tr("%1 (this robot has no such sensor)").arg(goal.packet);
        const QString name = oitext::packetName(*p);
        QStringList parts;
        QStringList bits;
        for (const QString &bit : goal.bits)
            for (const oi::BitMeaning &b : profile.bits(p->id))
                if (QLatin1String(b.key.data(), qsizetype(b.key.size())) == bit)
                    bits << oitext::bitName(b);
        if (!bits.isEmpty())
            parts << tr("%1 on").arg(bits.join(QStringLiteral(" + ")));
        if (goal.above && goal.below)
            parts << tr("%1 between %2 and %3").arg(name, number(*goal.above), number(*goal.below));
        else if (goal.above)
            parts << tr("%1 above %2").arg(name, number(*goal.above));
        else if (goal.below)
            parts << tr("%1 below %2").arg(name, number(*goal.below));
        if (goal.equals)
            parts << tr("%1 = %2").arg(name, number(*goal.equals));
        if (goal.ir == QLatin1String("dock"))
            parts << tr("%1 sees the dock").arg(name);
        else if (goal.ir == QLatin1String("virtual_wall"))
            parts << tr("%1 sees a virtual wall").arg(name);
        else if (goal.ir == QLatin1String("any"))
            parts << tr("%1 sees any IR").arg(name);
        text = parts.join(QStringLiteral(", "));
        break;
    }
    }
    if (goal.holdSeconds > 0)
        text = tr("%1 for %2 s").arg(text, number(goal.holdSeconds));
    return text;
}

void LessonStepView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    if (event->type() == QEvent::FontChange)
        applyScale();
    QWidget::changeEvent(event);
}

void LessonStepView::retranslateUi()
{
    for (auto it = m_readouts.cbegin(); it != m_readouts.cend(); ++it) {
        const QString &key = it.key();
        QString title;
        if (key == QLatin1String(lesson::kDrivenMm))
            title = tr("Driven, by odometry");
        else if (key == QLatin1String(lesson::kTurnedDeg))
            title = tr("Turned, by odometry");
        else if (key == QLatin1String(lesson::kTrueDrivenMm))
            title = tr("Driven, true");
        else if (key == QLatin1String(lesson::kTrueTurnedDeg))
            title = tr("Turned, true");
        else
            title = oitext::packetName(*lesson::packetByKey(*m_profile, key));
        it.value()->setTitle(title);
    }
    if (m_step) {
        m_heading->setText(tr("Step %1 of %2").arg(m_index + 1).arg(m_count));
        m_text->setText(lesson::translated(m_step->text));
        m_goal->setText(tr("Goal: %1").arg(describeGoal(m_step->goal, *m_profile)));
    }
    showPlacement();
}

#include "moc_lesson_step_view.cpp"
