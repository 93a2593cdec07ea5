// SPDX-License-Identifier: GPL-3.0-or-later
#include "projector_view.h"

#include "lesson_runner.h"
#include "lesson_step_view.h"
#include "oi_text.h"
#include "screen_fit.h"
#include "shipped_lessons.h"
#include "stop_all_button.h"

#include <QEvent>
#include <QFontInfo>
#include <QProgressBar>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QKeyEvent>
#include <QVBoxLayout>

namespace {

// Type at the back of a classroom: about this many times the desktop's size
// on a 1920×1080 screen, and in proportion on others (a 1280×720 projector
// shows it smaller, so that the step, its views and readouts all fit).
constexpr qreal kScale = 2.2;
constexpr QSize kFullHd(1920, 1080);
// Nothing smaller, whatever the screen: read from the back of a classroom.
constexpr int kLeastPixels = 14;

} // namespace

QStringList ProjectorView::robotReadouts()
{
    return {"voltage", "current", "requested_velocity", "wall_signal"};
}

ProjectorView::ProjectorView(QWidget *parent) : QWidget(parent)
{
    setObjectName("projectorView");
    setAutoFillBackground(true);
    setFocusPolicy(Qt::StrongFocus);
    // The lesson's title and the robot's name as written: rich text would
    // open the files the pictures of a lesson file name.
    m_header = new QLabel(this);
    m_header->setObjectName("projectorHeader");
    m_header->setTextFormat(Qt::PlainText);
    m_header->setWordWrap(true); // a long lesson title takes two lines, not the hint's place
    m_hint = new QLabel(this);
    m_hint->setObjectName("projectorHint");
    m_hint->setTextFormat(Qt::PlainText);
    m_hint->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_view = new LessonStepView(this);
    m_view->setLeastTextPixels(kLeastPixels);
    m_reasonRow = new QWidget(this);
    m_reasonLabel = new QLabel(m_reasonRow);
    m_reasonLabel->setObjectName("projectorReason");
    m_reasonLabel->setTextFormat(Qt::PlainText);
    m_reasonLabel->setWordWrap(true);
    m_enterSafe = new QPushButton(m_reasonRow);
    m_enterSafe->setObjectName("projectorEnterSafe");
    m_enterSafe->setFocusPolicy(Qt::NoFocus); // the view keeps the keys
    connect(m_enterSafe, &QPushButton::clicked, this, &ProjectorView::safeRequested);
    auto *reasonRow = new QHBoxLayout(m_reasonRow);
    reasonRow->setContentsMargins(0, 0, 0, 0);
    reasonRow->addWidget(m_reasonLabel, 1);
    reasonRow->addWidget(m_enterSafe);
    m_reasonRow->hide();
    // Stop all at the top right, where the class and the teacher look first.
    m_stopAll = new StopAllButton(this);
    m_stopAll->setObjectName("projectorStopAll");
    m_stopAll->setFocusPolicy(Qt::NoFocus); // the view keeps the keys
    connect(m_stopAll, &QPushButton::clicked, this, &ProjectorView::stopAllRequested);
    auto *top = new QHBoxLayout;
    top->addWidget(m_header, 1);
    top->addWidget(m_stopAll, 0, Qt::AlignTop);

    // The hint at the foot, where it covers nothing.
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(24, 16, 24, 8);
    layout->addLayout(top);
    layout->addWidget(m_reasonRow);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_hint);

    applyPalette();
    applyScale();
    retranslateUi();
    hide();
    parent->installEventFilter(this);
}

void ProjectorView::applyPalette()
{
    // High contrast: white on black, yellow to point at things.
    QPalette p = palette();
    for (auto group : {QPalette::Active, QPalette::Inactive, QPalette::Disabled}) {
        p.setColor(group, QPalette::Window, Qt::black);
        p.setColor(group, QPalette::WindowText, Qt::white);
        p.setColor(group, QPalette::Base, QColor(0x10, 0x10, 0x10));
        p.setColor(group, QPalette::AlternateBase, QColor(0x20, 0x20, 0x20));
        p.setColor(group, QPalette::Text, Qt::white);
        p.setColor(group, QPalette::Button, QColor(0x30, 0x30, 0x30));
        p.setColor(group, QPalette::ButtonText, Qt::white);
        p.setColor(group, QPalette::Highlight, QColor(0xff, 0xd6, 0x00));
        p.setColor(group, QPalette::HighlightedText, Qt::black);
        p.setColor(group, QPalette::Mid, QColor(0x80, 0x80, 0x80));
    }
    setPalette(p);
    // A bar at 0 %: its figure white on a grey groove, not lost in the black.
    QPalette bar = p;
    for (auto group : {QPalette::Active, QPalette::Inactive, QPalette::Disabled}) {
        bar.setColor(group, QPalette::Base, QColor(0x40, 0x40, 0x40));
        bar.setColor(group, QPalette::Window, QColor(0x40, 0x40, 0x40));
        bar.setColor(group, QPalette::Text, Qt::white);
        bar.setColor(group, QPalette::WindowText, Qt::white);
        bar.setColor(group, QPalette::Highlight, QColor(0x2e, 0x9d, 0x4e));
        bar.setColor(group, QPalette::HighlightedText, Qt::white);
    }
    if (auto *progress = m_view->findChild<QProgressBar *>(QStringLiteral("lessonProgress")))
        progress->setPalette(bar);
}

void ProjectorView::applyScale()
{
    const qreal scale = kScale * screenfit::scaleFor(size(), kFullHd, 1 / kScale, 1.5);
    if (qFuzzyCompare(scale, m_scale))
        return;
    m_scale = scale;
    m_view->setScale(scale);
    QFont header = font();
    header.setPointSizeF(font().pointSizeF() * 1.6 * scale);
    header.setBold(true);
    m_header->setFont(header);
    QFont hint = font();
    hint.setPointSizeF(font().pointSizeF() * std::max(1.0, 0.6 * scale));
    hint.setPixelSize(std::max(kLeastPixels, QFontInfo(hint).pixelSize()));
    m_hint->setFont(hint);
    QFont reason = font();
    reason.setPointSizeF(font().pointSizeF() * 1.2 * scale);
    reason.setBold(true);
    m_reasonLabel->setFont(reason);
    m_enterSafe->setFont(reason);
    m_stopAll->setTypeScale(1.4 * scale);
    // Yellow points at what needs doing.
    QPalette yellow = m_reasonLabel->palette();
    yellow.setColor(QPalette::WindowText, QColor(0xff, 0xd6, 0x00));
    m_reasonLabel->setPalette(yellow);
}

void ProjectorView::resizeEvent(QResizeEvent *event)
{
    applyScale();
    QWidget::resizeEvent(event);
}

void ProjectorView::setRobot(const QString &name, const oi::RobotProfile &profile, const SensorHistory *history)
{
    m_robotName = name;
    m_view->setProfile(profile);
    m_view->setHistory(history);
    showHeader();
}

void ProjectorView::setLesson(const LessonRunner *runner)
{
    m_runner = runner;
    lessonChanged();
}

void ProjectorView::lessonChanged()
{
    const bool stepShown = m_runner && m_runner->isRunning() && !m_runner->isFinished();
    if (stepShown) {
        const Lesson &lesson = m_runner->lesson();
        m_view->setStep(&lesson.steps[m_runner->currentStep()], m_runner->currentStep(), int(lesson.steps.size()));
    } else {
        m_view->setStep(nullptr, 0, 0, robotReadouts());
    }
    showHeader();
}

void ProjectorView::refresh(const oi::SensorSnapshot &latest, bool live)
{
    m_latest = latest;
    m_live = live;
    if (!isVisible())
        return;
    m_view->refresh(latest, !live, m_runner);
    showHeader();
}

void ProjectorView::showHeader()
{
    QStringList parts;
    if (m_runner && m_runner->isRunning())
        parts << lesson::translated(m_runner->lesson().title);
    if (!m_robotName.isEmpty())
        parts << m_robotName;
    if (m_mode.reported())
        parts << oitext::modeName(*m_mode.reported());
    if (const auto battery = m_latest.batteryPercent())
        parts << tr("battery %1 %").arg(qRound(*battery));
    if (!m_live)
        parts << tr("NO LIVE DATA");
    if (m_runner && m_runner->isFinished())
        parts << tr("lesson complete");
    m_header->setText(parts.join(QStringLiteral(" · ")));
    // Without live data nothing can be entered; the header says so.
    const bool offer = m_offersSafe && m_live;
    const QString reason = reasonLine();
    m_reasonLabel->setText(reason);
    m_enterSafe->setVisible(offer);
    // A warning in Safe or Full (on the dock, not charging) shows without the offer.
    m_reasonRow->setVisible(offer || (m_live && !reason.isEmpty()));
}

QString ProjectorView::reasonLine() const
{
    const QString reason = m_mode.reason();
    const QString lead = reason.isEmpty() ? QString() : reason + ' ';
    // A stop the lesson's step is about (its cliff, its wheels): the line
    // agrees with the step instead of undoing what the step asks for.
    if (m_runner && m_runner->isRunning() && !m_runner->isFinished()
        && m_mode.stopExpectedBy(lesson::goalPackets(m_runner->lesson().steps[m_runner->currentStep()].goal)))
        return lead + tr("This step expects it: follow the step below.");
    return (lead + m_mode.nextStep()).trimmed();
}

QPushButton *ProjectorView::stopAllButton() const { return m_stopAll; }
QString ProjectorView::headerText() const { return m_header->text(); }
QString ProjectorView::reasonText() const { return m_reasonRow->isHidden() ? QString() : m_reasonLabel->text(); }

void ProjectorView::setMode(const RobotMode &mode, bool canCommand)
{
    m_mode = mode;
    // Safe refused by the dock is not offered again: the step says Full.
    m_offersSafe = mode.ignoresMotion() && canCommand && !mode.safeRefusedOnDock();
    showHeader();
}

bool ProjectorView::eventFilter(QObject *watched, QEvent *event)
{
    // Cover the whole window, whatever its size.
    if (watched == parentWidget() && (event->type() == QEvent::Resize || event->type() == QEvent::Show))
        setGeometry(parentWidget()->rect());
    return QWidget::eventFilter(watched, event);
}

void ProjectorView::keyPressEvent(QKeyEvent *event)
{
    // Enter: Enter Safe, while it is offered.
    if ((event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter) && m_enterSafe->isVisibleTo(this)) {
        m_enterSafe->click();
        return;
    }
    QWidget::keyPressEvent(event);
}

void ProjectorView::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ProjectorView::retranslateUi()
{
    m_hint->setText(tr("F11: leave the projector view · Esc: stop the robot and leave"));
    m_enterSafe->setText(tr("Enter Safe (Enter)"));
    setAccessibleName(tr("Projector view"));
    showHeader();
}

#include "moc_projector_view.cpp"
