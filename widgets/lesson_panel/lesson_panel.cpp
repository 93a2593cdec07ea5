// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_panel.h"

#include "lesson_file.h"
#include "lesson_step_view.h"
#include "robot_session.h"
#include "shipped_lessons.h"

#include <QComboBox>
#include <QEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace {

// A step in the list: its number and the first sentence of its text, whole
// (the list wraps it rather than cut it).
QString stepCaption(int index, const QString &text)
{
    return QStringLiteral("%1. %2").arg(index + 1).arg(text.section(QLatin1Char('.'), 0, 0));
}

} // namespace

LessonPanel::LessonPanel(RobotLesson &lesson, QWidget *parent) : QWidget(parent), m_lesson(lesson)
{
    m_chooser = new QComboBox(this);
    m_chooser->setObjectName("lessonChooser");
    // As wide as the room allows, not as the longest title: the buttons
    // beside it stay whole in a narrow dock.
    m_chooser->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_chooser->setMinimumContentsLength(16);
    m_openButton = new QPushButton(this);
    m_backButton = new QPushButton(this);
    m_skipButton = new QPushButton(this);
    m_restartButton = new QPushButton(this);
    m_error = new QLabel(this);
    m_error->setObjectName("lessonError");
    m_error->setWordWrap(true);
    m_error->setTextFormat(Qt::PlainText);
    m_error->setStyleSheet(QStringLiteral("QLabel { color: #b71c1c; font-weight: bold; }"));
    m_error->hide();
    // Every label here shows text from a lesson file (its title, summary,
    // robots) as written: rich text would open the files its pictures name.
    m_notice = new QLabel(this);
    m_notice->setWordWrap(true);
    m_notice->setTextFormat(Qt::PlainText);
    m_notice->hide();
    m_summary = new QLabel(this);
    m_summary->setObjectName("lessonSummary");
    m_summary->setWordWrap(true);
    m_summary->setTextFormat(Qt::PlainText);
    m_steps = new QListWidget(this);
    m_steps->setObjectName("lessonSteps");
    m_steps->setWordWrap(true);
    m_steps->setTextElideMode(Qt::ElideNone);
    m_steps->setResizeMode(QListView::Adjust); // wrapped again at every width
    m_steps->setMinimumHeight(fontMetrics().height() * 4);
    m_view = new LessonStepView(this);
    // In a short dock the step scrolls rather than making the window taller.
    m_viewScroll = new QScrollArea(this);
    m_viewScroll->setWidget(m_view);
    m_viewScroll->setWidgetResizable(true);
    m_viewScroll->setFrameShape(QFrame::NoFrame);
    m_view->setMinimumHeight(m_view->minimumSizeHint().height());

    auto *bar = new QHBoxLayout;
    bar->addWidget(m_chooser, 1);
    bar->addWidget(m_openButton);
    bar->addSpacing(12);
    bar->addWidget(m_backButton);
    bar->addWidget(m_skipButton);
    bar->addWidget(m_restartButton);
    auto *side = new QWidget(this);
    auto *sideLayout = new QVBoxLayout(side);
    sideLayout->setContentsMargins(0, 0, 0, 0);
    sideLayout->addWidget(m_summary);
    sideLayout->addWidget(m_steps, 1);
    // The steps in a column as wide as about 30 characters; the step's view takes the rest.
    side->setMaximumWidth(fontMetrics().averageCharWidth() * 34);
    auto *body = new QHBoxLayout;
    body->addWidget(side, 1);
    body->addWidget(m_viewScroll, 4);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_error);
    layout->addWidget(m_notice);
    layout->addLayout(body, 1);

    connect(m_chooser, &QComboBox::activated, this, &LessonPanel::onChosen);
    connect(m_openButton, &QPushButton::clicked, this, &LessonPanel::openLessonFile);
    connect(m_backButton, &QPushButton::clicked, this, &LessonPanel::previousStep);
    connect(m_skipButton, &QPushButton::clicked, this, &LessonPanel::nextStep);
    connect(m_restartButton, &QPushButton::clicked, this, &LessonPanel::restart);
    connect(m_steps, &QListWidget::itemActivated, this,
            [this](QListWidgetItem *item) { m_lesson.runner().goToStep(m_steps->row(item)); });
    connect(&m_lesson, &RobotLesson::robotChanged, this, &LessonPanel::showRobot);
    connect(&m_lesson.runner(), &LessonRunner::stepChanged, this, [this] {
        showSteps();
        showCurrentStep();
        emit lessonChanged();
    });

    retranslateUi();
    // The lesson as it is: one already running is shown, not closed.
    fillChooser();
    showSteps();
    showCurrentStep();
    showRobot();
}

void LessonPanel::showRobot()
{
    if (RobotSession *robot = m_lesson.robot()) {
        m_view->setProfile(*m_lesson.seenProfile());
        m_view->setHistory(&robot->history());
    } else {
        m_view->setHistory(nullptr);
    }
    updateNotice();
}

bool LessonPanel::openLesson(const QString &path, QString *error)
{
    QString why;
    const std::optional<Lesson> lesson = loadLessonFile(path, &why);
    if (!lesson) {
        showError(tr("This lesson cannot be opened: %1").arg(why));
        fillChooser(); // back to the lesson that runs
        if (error)
            *error = why;
        return false;
    }
    if (!path.startsWith(QLatin1Char(':')) && !m_openedFiles.contains(path))
        m_openedFiles << path;
    showError(QString());
    m_view->setProfile(robot() ? robot()->robotProfile() : oi::profile(oi::ProfileId::Create2));
    m_lesson.start(*lesson, path);
    fillChooser();
    updateNotice();
    return true;
}

void LessonPanel::openLessonFile()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open lesson"), QString(),
                                                      tr("Lessons (*.json);;All files (*)"));
    if (!path.isEmpty())
        openLesson(path);
}

void LessonPanel::restart() { m_lesson.runner().goToStep(0); }
void LessonPanel::nextStep() { m_lesson.runner().goToStep(m_lesson.runner().currentStep() + 1); }
void LessonPanel::previousStep() { m_lesson.runner().goToStep(m_lesson.runner().currentStep() - 1); }

void LessonPanel::closeLesson()
{
    m_lesson.stop();
    fillChooser();
    showSteps();
    showCurrentStep();
    updateNotice();
    emit lessonChanged();
}

void LessonPanel::onChosen(int index)
{
    const QString path = m_chooser->itemData(index).toString();
    if (path.isEmpty())
        closeLesson();
    else if (path != m_lesson.path())
        openLesson(path);
}

void LessonPanel::fillChooser()
{
    const QSignalBlocker block(m_chooser);
    m_chooser->clear();
    m_chooser->addItem(tr("Choose a lesson…"), QString());
    QStringList paths = lesson::shippedLessonPaths();
    paths += m_openedFiles;
    for (const QString &path : std::as_const(paths)) {
        const std::optional<Lesson> l = loadLessonFile(path);
        if (!l)
            continue;
        const QString title = lesson::translated(l->title);
        m_chooser->addItem(path.startsWith(QLatin1Char(':'))
                               ? title
                               : QStringLiteral("%1 (%2)").arg(title, QFileInfo(path).fileName()),
                           path);
    }
    m_chooser->setCurrentIndex(std::max(0, m_chooser->findData(m_lesson.path())));
}

void LessonPanel::showSteps()
{
    const bool running = m_lesson.runner().isRunning();
    const Lesson &lesson = m_lesson.runner().lesson();
    m_steps->clear();
    m_steps->setVisible(running);
    m_summary->setText(running ? lesson::translated(lesson.summary)
                               : tr("Choose a lesson above, or open a lesson file. Each step says what to do "
                                    "and turns green when the robot shows it was done."));
    for (int i = 0; running && i < lesson.steps.size(); ++i) {
        auto *item = new QListWidgetItem(stepCaption(i, lesson::translated(lesson.steps[i].text)), m_steps);
        QFont f = item->font();
        if (m_lesson.runner().isStepDone(i)) {
            item->setText(QStringLiteral("✔ ") + item->text());
            item->setBackground(QColor(0x1b, 0x5e, 0x20));
            item->setForeground(Qt::white);
        } else if (i == m_lesson.runner().currentStep()) {
            item->setText(QStringLiteral("▶ ") + item->text());
            f.setBold(true);
        }
        item->setFont(f);
    }
    if (running && m_lesson.runner().currentStep() < m_steps->count())
        m_steps->setCurrentRow(m_lesson.runner().currentStep());
    m_backButton->setEnabled(running && m_lesson.runner().currentStep() > 0);
    m_skipButton->setEnabled(running && !m_lesson.runner().isFinished());
    m_restartButton->setEnabled(running);
}

void LessonPanel::showCurrentStep()
{
    const Lesson &lesson = m_lesson.runner().lesson();
    const int step = m_lesson.runner().currentStep();
    m_viewScroll->setVisible(m_lesson.runner().isRunning());
    if (m_lesson.runner().isRunning() && step < lesson.steps.size())
        m_view->setStep(&lesson.steps[step], step, int(lesson.steps.size()));
    else
        m_view->setStep(nullptr, 0, 0);
    updateNotice();
}

void LessonPanel::refresh()
{
    if (!isVisible() || !m_lesson.runner().isRunning())
        return;
    const bool live = robot() && robot()->isLive();
    m_view->refresh(robot() ? robot()->latest() : oi::SensorSnapshot(), !live, &m_lesson.runner());
    // A goal the robot's state now rules out says so, and what to do.
    QString outOfReach;
    if (robot() && !m_lesson.runner().isFinished() && m_lesson.runner().progress() < 1) {
        const LessonGoal &goal = m_lesson.runner().lesson().steps[m_lesson.runner().currentStep()].goal;
        outOfReach = robot()->mode().outOfReach(lesson::goalPackets(goal), lesson::goalDrives(goal));
    }
    m_view->setOutOfReach(outOfReach);
}

void LessonPanel::showError(const QString &message)
{
    m_error->setText(message);
    m_error->setVisible(!message.isEmpty());
}

QString LessonPanel::errorText() const { return m_error->isHidden() ? QString() : m_error->text(); }
QString LessonPanel::noticeText() const { return m_notice->isHidden() ? QString() : m_notice->text(); }

void LessonPanel::updateNotice()
{
    QString notice;
    if (m_lesson.runner().isFinished())
        notice = tr("Lesson complete: every step is done. Well done!");
    else if (m_lesson.runner().isRunning() && robot() && !m_lesson.runner().lesson().suits(robot()->robotProfile()))
        notice = tr("This lesson needs a robot this one is not (%1): some goals cannot be met.")
                     .arg(m_lesson.runner().lesson().profiles.join(QStringLiteral(", ")));
    else if (m_lesson.runner().isRunning() && !robot())
        notice = tr("No robot is selected: the goals are checked on the selected robot's data.");
    m_notice->setText(notice);
    m_notice->setVisible(!notice.isEmpty());
}

void LessonPanel::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void LessonPanel::retranslateUi()
{
    m_openButton->setText(tr("Open lesson file…"));
    m_backButton->setText(tr("◀ Back"));
    m_skipButton->setText(tr("Skip ▶"));
    m_restartButton->setText(tr("Restart"));
    m_chooser->setAccessibleName(tr("Lesson"));
    m_steps->setAccessibleName(tr("Lesson steps"));
    fillChooser();
    showSteps();
    updateNotice();
}

#include "moc_lesson_panel.cpp"
