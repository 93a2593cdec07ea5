// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>
#include <QWidget>

class QLabel;
class QListWidget;
class QPushButton;

// What the connection doctor found, in one line for the status bar, and a
// Details button that lists what it tried, step by step.
class DoctorDetails : public QWidget {
    Q_OBJECT
public:
    explicit DoctorDetails(QWidget *parent = nullptr);

    void start();                      // "Checking the connection…", steps cleared
    void addStep(const QString &step);
    void finish(const QString &summary);
    void clear();                      // hidden until the next check
    // Whether its robot is the one the window shows: it is visible only
    // then, and only with something to say.
    void setShownRobot(bool shown);

    QString summary() const { return m_summary; }
    QStringList steps() const { return m_steps; }
    // The list the Details button shows (created on first use).
    QWidget *detailsView();

private:
    void showDetails();
    void updateVisibility();

    QLabel *m_line;
    QPushButton *m_detailsButton;
    QWidget *m_view = nullptr;
    QLabel *m_viewSummary = nullptr;
    QListWidget *m_viewSteps = nullptr;
    QString m_summary;
    QStringList m_steps;
    bool m_shownRobot = true;
    bool m_hasNews = false;
};
