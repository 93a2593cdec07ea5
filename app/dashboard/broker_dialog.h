// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "saved_brokers.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QSpinBox;

// "Connect to broker…": host, port, user, password, TLS with a CA file, and
// whether to remember the password. Offers the brokers used before. OK only
// with something it can connect to; what is wrong is said under the fields.
class BrokerDialog : public QDialog {
    Q_OBJECT
public:
    explicit BrokerDialog(const QList<SavedBroker> &recent, QWidget *parent = nullptr);

    SavedBroker broker() const;
    void setBroker(const SavedBroker &broker);
    // Empty when the fields make a broker to connect to.
    QString problem() const;

    // Why it is asked (a refused login): above the fields, until changed.
    void setNotice(const QString &text);
    QString notice() const;

    void accept() override;

private:
    void update();

    QList<SavedBroker> m_recent;
    QComboBox *m_host = nullptr;
    QSpinBox *m_port = nullptr;
    QLineEdit *m_user = nullptr;
    QLineEdit *m_password = nullptr;
    QCheckBox *m_remember = nullptr;
    QCheckBox *m_tls = nullptr;
    QLineEdit *m_caFile = nullptr;
    QLabel *m_problem = nullptr;
    QLabel *m_notice = nullptr;
    QDialogButtonBox *m_buttons = nullptr;
};
