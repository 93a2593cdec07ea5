// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "result.h"
#include "robot_profile.h"
#include "typed_commands.h"

#include <QByteArray>
#include <QHash>
#include <QWidget>

#include <optional>

class QComboBox;
class QGroupBox;
class QLabel;
class QPushButton;
class QTimer;
class ScriptTextEdit;

// Writes, uploads, plays and reads back Create 1 scripts (152, 153, 154), and
// starts the built-in demos (136). The script is typed one command a line (or
// separated by ';'), as the core assembler reads it; the byte count and any
// error, with its line, follow the typing. On other profiles everything is
// disabled and a line says why.
class ScriptEditor : public QWidget {
    Q_OBJECT
public:
    explicit ScriptEditor(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile);

    void setScriptText(const QString &text);
    QString scriptText() const;
    // Assembles now instead of after the typing pause.
    void reassemble();

    // The three scripts of the Create document, by title.
    static QStringList exampleTitles();
    void loadExample(int index);

    QPushButton *button(const QString &name) const; // "upload", "play", "show", "demo-0".."demo-9", "abort-demo"
    QString byteCountText() const;
    QString errorText() const;              // empty when the script assembles
    std::optional<int> errorLine() const;   // 1-based editor line of the error
    QString showScriptText() const;         // what the last Upload, Play or Show Script did
    QString disabledReason() const;         // empty on the Create 1

public slots:
    // The robot's answer to showScriptRequested(): the script's bytes, set
    // beside what was last uploaded to that robot (RobotSession::uploadedScript(),
    // nullopt: nothing), or why there is none.
    void showScriptReply(const QByteArray &script, const std::optional<QByteArray> &uploaded);
    void showScriptFailed(const QString &reason);

signals:
    void sendRequested(const std::vector<oi::OiCommand> &commands);
    // Play (153): the robot's session plays it, in Safe if it is in Passive
    // (RobotSession::playScript()).
    void playRequested();
    // Show Script (154): the robot's link asks, around its own stream.
    void showScriptRequested();

protected:
    void changeEvent(QEvent *event) override;

private:
    void retranslateUi();
    QPushButton *addButton(const QString &name, const QString &text);
    bool send(const oi::OiCommand &command);
    void upload();
    void play();
    void showScript();
    void showResult(const QString &text);
    void showError(const QString &message, std::optional<int> line);
    void refreshEnabled();
    QString scriptAsText(const QByteArray &body) const;

    const oi::RobotProfile *m_profile = &oi::profile(oi::ProfileId::Create2);
    ScriptTextEdit *m_editor = nullptr;
    QComboBox *m_examples = nullptr;
    QLabel *m_reason = nullptr;
    QLabel *m_byteCount = nullptr;
    QLabel *m_error = nullptr;
    QLabel *m_showResult = nullptr;
    QWidget *m_controls = nullptr;
    QGroupBox *m_demoBox = nullptr;
    QString m_refusal; // why the profile has no scripts, from the encoder
    QHash<QString, QPushButton *> m_buttons;
    QTimer *m_debounce = nullptr;

    std::optional<QByteArray> m_body;  // the assembled script, if it fits
    std::optional<int> m_errorLine;
    bool m_awaitingReply = false;
};
