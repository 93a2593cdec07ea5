// SPDX-License-Identifier: GPL-3.0-or-later
#include "doctor_details.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

DoctorDetails::DoctorDetails(QWidget *parent)
    : QWidget(parent), m_line(new QLabel(this)), m_detailsButton(new QPushButton(tr("Details…"), this))
{
    setObjectName("connectionDoctor");
    m_line->setObjectName("doctorSummary");
    m_detailsButton->setObjectName("doctorDetailsButton");
    m_detailsButton->setAccessibleName(tr("Connection check details"));
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_line, 1);
    layout->addWidget(m_detailsButton);
    connect(m_detailsButton, &QPushButton::clicked, this, &DoctorDetails::showDetails);
    setVisible(false);
}

void DoctorDetails::start()
{
    m_steps.clear();
    m_nextSteps.clear();
    m_summary.clear();
    m_line->setText(tr("Checking the connection…"));
    m_detailsButton->setEnabled(false);
    m_hasNews = true;
    updateVisibility();
}

void DoctorDetails::addStep(const QString &step)
{
    m_steps.append(step);
    m_detailsButton->setEnabled(true);
    if (m_viewSteps) {
        m_viewSteps->addItem(step);
        m_viewTried->setVisible(true);
        m_viewSteps->setVisible(true);
    }
}

void DoctorDetails::finish(const QString &summary, const QStringList &nextSteps)
{
    m_summary = summary;
    m_nextSteps = nextSteps;
    m_line->setText(summary);
    // The status bar may cut the line short: the whole of it, what to do, and the steps.
    QStringList tip{summary};
    if (!nextSteps.isEmpty())
        tip << QString() << nextSteps;
    if (!m_steps.isEmpty())
        tip << QString() << m_steps;
    m_line->setToolTip(tip.join(QLatin1Char('\n')));
    m_detailsButton->setEnabled(true);
    if (m_view)
        detailsView(); // an open view shows the new finding
    m_hasNews = true;
    updateVisibility();
}

void DoctorDetails::clear()
{
    m_steps.clear();
    m_nextSteps.clear();
    m_summary.clear();
    m_line->clear();
    m_hasNews = false;
    updateVisibility();
}

void DoctorDetails::setShownRobot(bool shown)
{
    m_shownRobot = shown;
    updateVisibility();
}

void DoctorDetails::updateVisibility()
{
    setVisible(m_shownRobot && m_hasNews);
}

QWidget *DoctorDetails::detailsView()
{
    if (!m_view) {
        auto *dialog = new QDialog(this);
        dialog->setObjectName("doctorDetailsView");
        dialog->setWindowTitle(tr("Connection check"));
        m_viewSummary = new QLabel(dialog);
        m_viewSummary->setWordWrap(true);
        m_viewSteps = new QListWidget(dialog);
        m_viewSteps->setAccessibleName(tr("What was tried"));
        auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
        connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::hide);
        auto *layout = new QVBoxLayout(dialog);
        m_viewNext = new QLabel(dialog);
        m_viewNext->setObjectName("doctorNextSteps");
        m_viewNext->setWordWrap(true);
        m_viewNext->setTextFormat(Qt::PlainText);
        m_viewTried = new QLabel(tr("What was tried:"), dialog);
        layout->addWidget(m_viewSummary);
        layout->addWidget(m_viewNext);
        layout->addWidget(m_viewTried);
        layout->addWidget(m_viewSteps, 1);
        // Without a list the texts stay at the top, not spread over the dialog.
        layout->addStretch(0);
        for (QLabel *text : {m_viewSummary, m_viewNext, m_viewTried})
            text->setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Maximum);
        layout->addWidget(buttons);
        dialog->resize(560, 320);
        m_view = dialog;
    }
    m_viewSummary->setText(m_summary.isEmpty() ? m_line->text() : m_summary);
    m_viewNext->setText(m_nextSteps.isEmpty()
                            ? QString()
                            : tr("What to do next:") + QLatin1Char('\n')
                                  + QStringLiteral("\u2022 ") + m_nextSteps.join(QStringLiteral("\n\u2022 ")));
    m_viewNext->setVisible(!m_nextSteps.isEmpty());
    // No empty box under a heading: what was tried shows only when something was.
    m_viewTried->setVisible(!m_steps.isEmpty());
    m_viewSteps->setVisible(!m_steps.isEmpty());
    m_viewSteps->clear();
    m_viewSteps->addItems(m_steps);
    return m_view;
}

void DoctorDetails::showDetails()
{
    QWidget *view = detailsView();
    view->show();
    view->raise();
}

#include "moc_doctor_details.cpp"
