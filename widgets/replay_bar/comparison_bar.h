// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QWidget>

class QComboBox;
class QLabel;
class QToolButton;

// A second run shown beside the robot's own: which file, where the two are
// aligned (at their starts, or at a marker both hold), and a button to close it.
class ComparisonBar : public QWidget {
    Q_OBJECT
public:
    explicit ComparisonBar(QWidget *parent = nullptr);

    // `fileName` compared; `markers` are the labels the runs share, offered
    // to align at; `alignedAt` is "" for the start or one of them.
    void showRun(const QString &fileName, const QStringList &markers, const QString &alignedAt);
    QComboBox *alignment() const { return m_align; }
    QToolButton *closeButton() const { return m_close; }

signals:
    // "" for the starts, or a marker's label.
    void alignRequested(const QString &marker);
    void closeRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();

    QString m_fileName;
    QLabel *m_label = nullptr;
    QComboBox *m_align = nullptr;
    QToolButton *m_close = nullptr;
};
