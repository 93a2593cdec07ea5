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
    // `nextSteps`: what the user can do about it, shown above what was tried.
    void finish(const QString &summary, const QStringList &nextSteps = {});
    void clear();                      // hidden until the next check
    // Whether its robot is the one the window shows: it is visible only
    // then, and only with something to say.
    void setShownRobot(bool shown);

    QString summary() const { return m_summary; }
    QStringList steps() const { return m_steps; }
    QStringList nextSteps() const { return m_nextSteps; }
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
    QLabel *m_viewTried = nullptr;
    QLabel *m_viewNext = nullptr;
    QString m_summary;
    QStringList m_steps;
    QStringList m_nextSteps;
    bool m_shownRobot = true;
    bool m_hasNews = false;
};
