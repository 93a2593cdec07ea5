// SPDX-License-Identifier: GPL-3.0-or-later
#include "broker_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

BrokerDialog::BrokerDialog(const QList<SavedBroker> &recent, QWidget *parent) : QDialog(parent), m_recent(recent)
{
    setWindowTitle(tr("Connect to broker"));
    auto *form = new QFormLayout(this);
    m_notice = new QLabel(this);
    m_notice->setObjectName("brokerNotice");
    m_notice->setWordWrap(true);
    m_notice->setTextFormat(Qt::PlainText);
    m_notice->hide();
    form->addRow(m_notice);
    m_host = new QComboBox(this);
    m_host->setObjectName("brokerHost");
    m_host->setEditable(true);
    for (const SavedBroker &b : recent)
        m_host->addItem(b.address.host);
    m_host->setCurrentText(QStringLiteral("127.0.0.1"));
    form->addRow(tr("&Host:"), m_host);
    m_port = new QSpinBox(this);
    m_port->setObjectName("brokerPort");
    m_port->setRange(1, 65535);
    m_port->setValue(1883);
    form->addRow(tr("&Port:"), m_port);
    m_user = new QLineEdit(this);
    m_user->setObjectName("brokerUser");
    m_user->setPlaceholderText(tr("anonymous"));
    form->addRow(tr("&User:"), m_user);
    m_password = new QLineEdit(this);
    m_password->setObjectName("brokerPassword");
    m_password->setEchoMode(QLineEdit::Password);
    form->addRow(tr("Pass&word:"), m_password);
    m_remember = new QCheckBox(tr("&Remember the password (kept in plain text in the settings)"), this);
    m_remember->setObjectName("brokerRemember");
    form->addRow(QString(), m_remember);
    m_tls = new QCheckBox(tr("&TLS"), this);
    m_tls->setObjectName("brokerTls");
    form->addRow(QString(), m_tls);
    auto *caRow = new QHBoxLayout;
    m_caFile = new QLineEdit(this);
    m_caFile->setObjectName("brokerCaFile");
    m_caFile->setPlaceholderText(tr("the system's certificates"));
    auto *browse = new QPushButton(tr("&Browse…"), this);
    caRow->addWidget(m_caFile, 1);
    caRow->addWidget(browse);
    auto *caLabel = new QLabel(tr("&CA file:"), this);
    caLabel->setBuddy(m_caFile); // a row of a layout has none by itself
    form->addRow(caLabel, caRow);
    m_problem = new QLabel(this);
    m_problem->setObjectName("brokerProblem");
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #b00020;"));
    form->addRow(m_problem);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    m_buttons->button(QDialogButtonBox::Ok)->setText(tr("Connect"));
    form->addRow(m_buttons);

    connect(m_buttons, &QDialogButtonBox::accepted, this, &BrokerDialog::accept);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &BrokerDialog::reject);
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString file = QFileDialog::getOpenFileName(this, tr("CA certificate"), m_caFile->text(),
                                                          tr("Certificates (*.pem *.crt);;All files (*)"));
        if (!file.isEmpty()) {
            m_caFile->setText(file);
            m_tls->setChecked(true);
        }
    });
    connect(m_host, &QComboBox::activated, this, [this](int index) {
        if (index >= 0 && index < m_recent.size())
            setBroker(m_recent[index]);
    });
    for (QLineEdit *edit : {m_user, m_password, m_caFile})
        connect(edit, &QLineEdit::textChanged, this, &BrokerDialog::update);
    connect(m_host, &QComboBox::currentTextChanged, this, &BrokerDialog::update);
    connect(m_tls, &QCheckBox::toggled, this, &BrokerDialog::update);
    if (!recent.isEmpty())
        setBroker(recent.first());
    update();
}

void BrokerDialog::setBroker(const SavedBroker &b)
{
    m_host->setCurrentText(b.address.host);
    m_port->setValue(b.address.port);
    m_user->setText(b.address.username);
    m_password->setText(b.address.password);
    m_remember->setChecked(b.rememberPassword);
    m_tls->setChecked(b.address.tls);
    m_caFile->setText(b.address.caFile);
    update();
}

SavedBroker BrokerDialog::broker() const
{
    SavedBroker b;
    b.address.host = m_host->currentText().trimmed();
    b.address.port = m_port->value();
    b.address.username = m_user->text().trimmed();
    b.address.password = m_password->text();
    b.address.tls = m_tls->isChecked();
    b.address.caFile = b.address.tls ? m_caFile->text().trimmed() : QString();
    b.rememberPassword = m_remember->isChecked();
    return b;
}

QString BrokerDialog::problem() const
{
    const SavedBroker b = broker();
    if (b.address.host.isEmpty())
        return tr("Enter the broker's host name or address.");
    if (b.address.host.contains(QLatin1Char(' ')) || b.address.host.contains(QLatin1Char('/')))
        return tr("\"%1\" is not a host name.").arg(b.address.host);
    if (!b.address.password.isEmpty() && b.address.username.isEmpty())
        return tr("A password needs a user name.");
    if (b.address.tls && !b.address.caFile.isEmpty() && !QFileInfo(b.address.caFile).isReadable())
        return tr("The CA file %1 cannot be read.").arg(b.address.caFile);
    return {};
}

void BrokerDialog::update()
{
    const QString why = problem();
    m_problem->setText(why);
    m_problem->setVisible(!why.isEmpty());
    m_caFile->setEnabled(m_tls->isChecked());
    m_buttons->button(QDialogButtonBox::Ok)->setEnabled(why.isEmpty());
}

void BrokerDialog::setNotice(const QString &text)
{
    m_notice->setText(text);
    m_notice->setVisible(!text.isEmpty());
    // The login was refused: the password is what to type again.
    if (!text.isEmpty())
        (m_user->text().isEmpty() ? m_user : m_password)->setFocus(Qt::OtherFocusReason);
}

QString BrokerDialog::notice() const { return m_notice->text(); }

void BrokerDialog::accept()
{
    if (!problem().isEmpty())
        return;
    QDialog::accept();
}

#include "moc_broker_dialog.cpp"
