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
    if (m_viewSteps)
        m_viewSteps->addItem(step);
}

void DoctorDetails::finish(const QString &summary)
{
    m_summary = summary;
    m_line->setText(summary);
    // The status bar may cut the line short: the whole of it, and the steps.
    m_line->setToolTip((QStringList{summary, QString()} + m_steps).join(QLatin1Char('\n')));
    m_detailsButton->setEnabled(true);
    if (m_viewSummary)
        m_viewSummary->setText(summary);
    m_hasNews = true;
    updateVisibility();
}

void DoctorDetails::clear()
{
    m_steps.clear();
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
        layout->addWidget(m_viewSummary);
        layout->addWidget(new QLabel(tr("What was tried:"), dialog));
        layout->addWidget(m_viewSteps);
        layout->addWidget(buttons);
        dialog->resize(560, 320);
        m_view = dialog;
    }
    m_viewSummary->setText(m_summary.isEmpty() ? m_line->text() : m_summary);
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
