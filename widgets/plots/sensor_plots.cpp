// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensor_plots.h"

#include "display_palette.h"
#include "plot_stack.h"
#include "sensor_history.h"

#include <QComboBox>
#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QShortcut>
#include <QVBoxLayout>

#include <algorithm>

#include <cmath>
#include <limits>

namespace {

const double kWindowChoices[] = {10, 20, 30, 60, 120, 300, 600};

QString windowLabel(double seconds)
{
    if (seconds >= 60 && std::fmod(seconds, 60.0) == 0)
        return SensorPlots::tr("%1 min").arg(seconds / 60);
    return SensorPlots::tr("%1 s").arg(seconds);
}

} // namespace

SensorPlots::SensorPlots(QWidget *parent) : QWidget(parent)
{
    // Clicks give the panel focus for Space; Tab stops only on its controls.
    setFocusPolicy(Qt::ClickFocus);
    // The controls first: Tab reaches them before the plots.
    m_pauseButton = new QPushButton(this);
    m_windowBox = new QComboBox(this);
    m_addButton = new QPushButton(this);
    m_exportButton = new QPushButton(this);
    m_stack = new PlotStack(this);

    m_pauseButton->setObjectName(QStringLiteral("pause"));
    m_pauseButton->setCheckable(true);
    connect(m_pauseButton, &QPushButton::toggled, m_stack, &PlotStack::setPaused);
    connect(m_stack, &PlotStack::pausedChanged, this, &SensorPlots::applyPaused);

    m_windowBox->setObjectName(QStringLiteral("window"));
    for (double s : kWindowChoices)
        m_windowBox->addItem(windowLabel(s), s);
    m_windowBox->setCurrentIndex(m_windowBox->findData(m_stack->windowSeconds()));
    connect(m_windowBox, &QComboBox::activated, this,
            [this](int index) { m_stack->setWindowSeconds(m_windowBox->itemData(index).toDouble()); });
    connect(m_stack, &PlotStack::windowSecondsChanged, this, &SensorPlots::showWindowSeconds);
    m_windowLabel = new QLabel(this);
    m_windowLabel->setObjectName(QStringLiteral("windowLabel"));
    m_windowLabel->setBuddy(m_windowBox);

    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("plotStatus"));
    m_status->setMargin(3);

    m_addButton->setObjectName(QStringLiteral("addPlot"));
    connect(m_addButton, &QPushButton::clicked, this, [this] { m_stack->addPlot(); });

    m_exportButton->setObjectName(QStringLiteral("export"));
    auto *exportMenu = new QMenu(m_exportButton);
    m_exportVisible = exportMenu->addAction(QString(), this, [this] { exportInteractively(true); });
    m_exportAll = exportMenu->addAction(QString(), this, [this] { exportInteractively(false); });
    m_exportButton->setMenu(exportMenu);

    auto *bar = new QHBoxLayout;
    bar->setContentsMargins(0, 0, 0, 0);
    bar->addWidget(m_pauseButton);
    bar->addSpacing(8);
    bar->addWidget(m_windowLabel);
    bar->addWidget(m_windowBox);
    bar->addSpacing(8);
    bar->addWidget(m_status);
    bar->addStretch(1);
    bar->addWidget(m_addButton);
    bar->addWidget(m_exportButton);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(4);
    layout->addLayout(bar);
    layout->addWidget(m_stack, 1);

    for (const QKeySequence &key : {QKeySequence(Qt::Key_Space), QKeySequence(Qt::CTRL | Qt::Key_Space)}) {
        auto *shortcut = new QShortcut(key, this);
        shortcut->setContext(Qt::WidgetWithChildrenShortcut);
        connect(shortcut, &QShortcut::activated, this, [this] { m_stack->setPaused(!m_stack->isPaused()); });
    }
    retranslateUi();
}

void SensorPlots::retranslateUi()
{
    m_pauseButton->setToolTip(tr("Pause or resume following the newest sample (Space)"));
    for (int i = 0; i < m_windowBox->count(); ++i)
        m_windowBox->setItemText(i, windowLabel(m_windowBox->itemData(i).toDouble()));
    m_windowBox->setToolTip(tr("How much time the plots show"));
    m_windowLabel->setText(tr("&Window"));
    m_addButton->setText(tr("Add plot"));
    m_addButton->setToolTip(tr("Add another plot below the others"));
    m_exportButton->setText(tr("Export CSV"));
    m_exportButton->setToolTip(tr("Write the plotted channels to a CSV file"));
    m_exportVisible->setText(tr("Visible range…"));
    m_exportAll->setText(tr("Whole history…"));
    applyPaused();
}

void SensorPlots::setHistory(const SensorHistory *history) { m_stack->setHistory(history); }
const SensorHistory *SensorPlots::history() const { return m_stack->history(); }
void SensorPlots::setProfile(const oi::RobotProfile &profile) { m_stack->setProfile(profile); }
void SensorPlots::setCorrections(const oi::FirmwareCorrections &corrections) { m_stack->setCorrections(corrections); }
void SensorPlots::setMarkers(const QList<PlotMarker> &markers) { m_stack->setMarkers(markers); }
void SensorPlots::refresh() { m_stack->refresh(); }

void SensorPlots::addPlot(const std::vector<int> &channels) { m_stack->addPlot(channels); }

void SensorPlots::setMinimumPlotHeight(int pixels) { m_stack->setMinimumPlotHeight(pixels); }

void SensorPlots::showDefaultPlots()
{
    if (m_stack->plotCount() == 0)
        m_stack->addPlot();
    m_stack->setChannels(0, {28, 29, 30, 31});
    m_stack->addPlot({22, 23});
}

void SensorPlots::setComparison(const SensorHistory *history, double shiftSeconds, const QString &label,
                                const QString &primaryLabel)
{
    m_stack->setComparison(history, shiftSeconds, label, primaryLabel);
}

void SensorPlots::setStale(bool stale, bool replayEnded, bool replay)
{
    replayEnded = stale && replayEnded;
    if (stale == m_stale && replayEnded == m_replayEnded && replay == m_replay)
        return;
    m_stale = stale;
    m_replayEnded = replayEnded;
    m_replay = replay;
    applyPaused();
}

QString SensorPlots::statusText() const { return m_status->text(); }

void SensorPlots::showWindowSeconds(double seconds)
{
    int index = m_windowBox->findData(seconds);
    if (index < 0) {
        // A window between the choices gets its own entry, in order.
        index = 0;
        while (index < m_windowBox->count() && m_windowBox->itemData(index).toDouble() < seconds)
            ++index;
        m_windowBox->insertItem(index, windowLabel(seconds), seconds);
    }
    m_windowBox->setCurrentIndex(index);
}

void SensorPlots::applyPaused()
{
    const bool paused = m_stack->isPaused();
    {
        const QSignalBlocker blocker(m_pauseButton);
        m_pauseButton->setChecked(paused);
    }
    m_pauseButton->setText(paused ? tr("Resume") : tr("Pause"));
    const display::State state = paused              ? display::State::Warning
                                 : m_stale || m_replay ? display::State::Stale
                                                       : display::State::Active;
    const QPalette pal = palette();
    m_status->setText(paused    ? tr("Paused: drag or arrows pan, wheel or +/- zoom, Space resumes")
                      : m_replayEnded ? tr("Replay finished")
                      : m_replay ? tr("Replay, not live")
                      : m_stale ? tr("Not live: no fresh data")
                                : tr("Live"));
    m_status->setStyleSheet(QStringLiteral("QLabel { background: %1; color: %2; border-radius: 3px; }")
                                .arg(display::stateColor(state, pal).name(), display::textOn(state, pal).name()));
}

bool SensorPlots::exportCsv(const QString &path, double from, double to, QString *error) const
{
    const auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (!m_stack->history())
        return fail(tr("There is no sensor history to export."));
    const std::vector<int> ids = m_stack->plottedChannels();
    if (ids.empty())
        return fail(tr("No channels are plotted."));
    // The markers drawn go in too, in time order.
    QList<oilink::SensorCsv::Mark> marks;
    for (const PlotMarker &m : m_stack->markers())
        marks << oilink::SensorCsv::Mark{m.seconds, m.label};
    std::stable_sort(marks.begin(), marks.end(), [](const auto &a, const auto &b) { return a.seconds < b.seconds; });
    return m_stack->history()->exportCsv(path, ids, from, to, error, marks);
}

bool SensorPlots::exportVisibleCsv(const QString &path, QString *error) const
{
    return exportCsv(path, m_stack->timeFrom(), m_stack->timeTo(), error);
}

bool SensorPlots::exportAllCsv(const QString &path, QString *error) const
{
    const double inf = std::numeric_limits<double>::infinity();
    return exportCsv(path, -inf, inf, error);
}

void SensorPlots::exportInteractively(bool visibleOnly)
{
    const QString path = QFileDialog::getSaveFileName(
        this, visibleOnly ? tr("Export the visible range") : tr("Export the whole history"),
        QStringLiteral("sensors.csv"), tr("CSV files (*.csv);;All files (*)"));
    if (path.isEmpty())
        return;
    QString error;
    const bool ok = visibleOnly ? exportVisibleCsv(path, &error) : exportAllCsv(path, &error);
    if (!ok)
        QMessageBox::warning(this, tr("Export failed"), error);
}

void SensorPlots::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    if (event->type() == QEvent::PaletteChange)
        applyPaused();
    // Its style sheet keeps the status from following the panel's type by itself.
    if (event->type() == QEvent::FontChange)
        m_status->setFont(font());
}

#include "moc_sensor_plots.cpp"
