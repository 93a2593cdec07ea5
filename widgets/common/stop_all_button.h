// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPushButton>

// The red Stop all button, alike wherever a class looks: the robot bar, the
// fleet view, the projector view. It names its key (Shift+Esc); what it
// stops is for its owner to wire to clicked().
class StopAllButton : public QPushButton {
    Q_OBJECT
public:
    explicit StopAllButton(QWidget *parent);

    // Its type `factor` times the desktop's, bold.
    void setTypeScale(qreal factor);

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();

    QFont m_base;
};
