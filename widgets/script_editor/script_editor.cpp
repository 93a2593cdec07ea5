// SPDX-License-Identifier: GPL-3.0-or-later
#include "script_editor.h"

#include "command_encoder.h"
#include "demo_names.h"
#include "display_palette.h"
#include "script_assembler.h"
#include "script_lines.h"
#include "script_text_edit.h"

#include <QComboBox>
#include <QEvent>
#include <QFontDatabase>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QTextBlock>
#include <QTimer>
#include <QVBoxLayout>

namespace {

constexpr int kMaxScriptBytes = 100; // ERRATA 11: the length byte counts bytes, at most 100
constexpr int kTypingPauseMs = 150;

struct Example {
    const char *title;
    const char *text;
};

// The example scripts of the Create document, written out as statements.
const Example kExamples[] = {
    {QT_TRANSLATE_NOOP("ScriptEditor", "Drive 40 cm and stop"),
     "# Drive 40 cm and stop\n"
     "drive 300 straight\n"
     "wait-distance 400\n"
     "drive 0 0\n"},
    {QT_TRANSLATE_NOOP("ScriptEditor", "Toggle LED on bump"),
     "# Toggle the Play LED on each bump, forever\n"
     "wait-event bump\n"
     "wait-event not-bump\n"
     "leds 2 0 0   # Play LED on\n"
     "wait-event bump\n"
     "wait-event not-bump\n"
     "leds 0 0 0   # Play LED off\n"
     "play-script\n"},
    {QT_TRANSLATE_NOOP("ScriptEditor", "Drive in a square"),
     "# Drive in a square, forever\n"
     "drive 300 straight\n"
     "wait-distance 400\n"
     "drive 300 ccw   # turn in place\n"
     "wait-angle 90\n"
     "play-script\n"},
};

QByteArray toByteArray(const oi::Bytes &bytes)
{
    return QByteArray(reinterpret_cast<const char *>(bytes.data()), qsizetype(bytes.size()));
}

QString fromStd(const std::string &text) { return QString::fromStdString(text); }

} // namespace

ScriptEditor::ScriptEditor(QWidget *parent) : QWidget(parent)
{
    m_reason = new QLabel(this);
    m_reason->setObjectName("disabledReason");
    m_reason->setWordWrap(true);

    m_controls = new QWidget(this);

    m_examples = new QComboBox(m_controls);
    m_examples->setObjectName("examples");
    m_examples->setSizeAdjustPolicy(QComboBox::AdjustToContents); // its texts change with the language
    m_examples->addItem(QString());
    for (int i = 0; i < exampleTitles().size(); ++i)
        m_examples->addItem(QString());
    connect(m_examples, &QComboBox::activated, this, [this](int index) {
        if (index > 0)
            loadExample(index - 1);
        m_examples->setCurrentIndex(0);
    });

    m_byteCount = new QLabel(m_controls);
    m_byteCount->setObjectName("byteCount");
    m_byteCount->setAlignment(Qt::AlignRight | Qt::AlignVCenter);

    m_editor = new ScriptTextEdit(m_controls);
    m_editor->setObjectName("scriptText");
    m_editor->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    // Scripts need no tab characters, so Tab moves on for keyboard users.
    m_editor->setTabChangesFocus(true);
    m_editor->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_editor->setMinimumHeight(10 * m_editor->fontMetrics().lineSpacing());

    m_error = new QLabel(m_controls);
    m_error->setObjectName("scriptError");
    m_error->setWordWrap(true);
    m_error->setTextInteractionFlags(Qt::TextSelectableByMouse);
    QPalette errorPalette = m_error->palette();
    errorPalette.setColor(QPalette::WindowText, display::stateColor(display::State::Alert, palette()));
    m_error->setPalette(errorPalette);

    m_showResult = new QLabel(m_controls);
    m_showResult->setObjectName("showScriptResult");
    m_showResult->setWordWrap(true);
    m_showResult->setTextInteractionFlags(Qt::TextSelectableByMouse);

    m_debounce = new QTimer(this);
    m_debounce->setSingleShot(true);
    m_debounce->setInterval(kTypingPauseMs);
    connect(m_debounce, &QTimer::timeout, this, &ScriptEditor::reassemble);
    connect(m_editor, &QPlainTextEdit::textChanged, m_debounce, qOverload<>(&QTimer::start));


    addButton("upload", QString());
    addButton("play", QString());
    addButton("show", QString());
    connect(button("upload"), &QPushButton::clicked, this, &ScriptEditor::upload);
    connect(button("play"), &QPushButton::clicked, this, &ScriptEditor::play);
    connect(button("show"), &QPushButton::clicked, this, &ScriptEditor::showScript);

    auto *demoBox = m_demoBox = new QGroupBox(m_controls);
    auto *demoGrid = new QGridLayout(demoBox);
    // Four across: German names fit a column beside the diagram.
    constexpr int kColumns = 4;
    for (int demo = demos::kFirst; demo <= demos::kLast; ++demo) {
        QPushButton *b = addButton(QString("demo-%1").arg(demo), QString());
        b->setParent(demoBox);
        connect(b, &QPushButton::clicked, this, [this, demo] { send({oi::Command::Demo, {demo}, {}}); });
        demoGrid->addWidget(b, demo / kColumns, demo % kColumns);
    }
    QPushButton *abort = addButton("abort-demo", QString());
    abort->setParent(demoBox);
    connect(abort, &QPushButton::clicked, this,
            [this] { send({oi::Command::Demo, {demos::kAbort}, {}}); });
    demoGrid->addWidget(abort, demos::kLast / kColumns + 1, 0, 1, kColumns);

    auto *top = new QHBoxLayout;
    top->addWidget(m_examples);
    top->addStretch();
    top->addWidget(m_byteCount);

    auto *buttons = new QHBoxLayout;
    buttons->addWidget(button("upload"));
    buttons->addWidget(button("play"));
    buttons->addWidget(button("show"));
    buttons->addStretch();

    auto *controls = new QVBoxLayout(m_controls);
    controls->setContentsMargins(0, 0, 0, 0);
    controls->addLayout(top);
    controls->addWidget(m_editor, 1);
    controls->addWidget(m_error);
    controls->addLayout(buttons);
    controls->addWidget(m_showResult);
    controls->addWidget(demoBox);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_reason);
    layout->addWidget(m_controls, 1);

    m_showResult->setVisible(false);
    setProfile(*m_profile); // also sets every text
}

void ScriptEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void ScriptEditor::retranslateUi()
{
    m_examples->setItemText(0, tr("Load an example…"));
    const QStringList titles = exampleTitles();
    for (int i = 0; i < titles.size(); ++i)
        m_examples->setItemText(i + 1, titles[i]);
    m_examples->setAccessibleName(tr("Example scripts"));
    // The script keywords stay as they are: the assembler reads them.
    m_editor->setPlaceholderText(tr("One command a line, e.g.\n%1").arg("drive 300 straight\nwait-distance 400\ndrive 0 0"));
    m_editor->setAccessibleName(tr("Script"));
    button("upload")->setText(tr("Upload (152)"));
    button("play")->setText(tr("Play (153)"));
    button("play")->setToolTip(tr("Run the stored script"));
    button("show")->setText(tr("Show Script (154)"));
    button("show")->setToolTip(tr("Read the stored script back and compare it with what was uploaded"));
    m_demoBox->setTitle(tr("Demos (136)"));
    for (int demo = demos::kFirst; demo <= demos::kLast; ++demo)
        button(QString("demo-%1").arg(demo))->setText(tr("%1  %2").arg(demo).arg(demos::name(demo)));
    button("abort-demo")->setText(demos::name(demos::kAbort));
    if (!m_refusal.isEmpty())
        m_reason->setText(tr("Scripts and demos are for the original Create only: %1.").arg(m_refusal));
    reassemble(); // the byte count, the error and the upload tool tip
}

QPushButton *ScriptEditor::addButton(const QString &name, const QString &text)
{
    auto *b = new QPushButton(text, m_controls);
    b->setObjectName(name);
    m_buttons.insert(name, b);
    return b;
}

QPushButton *ScriptEditor::button(const QString &name) const { return m_buttons.value(name); }

QStringList ScriptEditor::exampleTitles()
{
    QStringList titles;
    for (const Example &e : kExamples)
        titles << tr(e.title);
    return titles;
}

void ScriptEditor::loadExample(int index)
{
    if (index < 0 || index >= int(std::size(kExamples)))
        return;
    setScriptText(QString::fromUtf8(kExamples[index].text));
}

void ScriptEditor::setScriptText(const QString &text)
{
    m_editor->setPlainText(text);
    reassemble();
}

QString ScriptEditor::scriptText() const { return m_editor->toPlainText(); }
QString ScriptEditor::byteCountText() const { return m_byteCount->text(); }
QString ScriptEditor::errorText() const { return m_error->text(); }
std::optional<int> ScriptEditor::errorLine() const { return m_errorLine; }
QString ScriptEditor::showScriptText() const { return m_showResult->text(); }
QString ScriptEditor::disabledReason() const { return m_reason->isHidden() ? QString() : m_reason->text(); }

void ScriptEditor::setProfile(const oi::RobotProfile &profile)
{
    m_profile = &profile;
    // Another robot: any reply still due belongs to the old one.
    m_awaitingReply = false;
    m_showResult->clear();
    m_showResult->setVisible(false);
    const oi::CommandEncoder encoder(profile);
    if (auto refusal = encoder.refuse(oi::Command::Script)) {
        m_refusal = fromStd(refusal->message);
        m_reason->setVisible(true);
        m_controls->setEnabled(false);
    } else {
        m_refusal.clear();
        m_reason->clear();
        m_reason->setVisible(false);
        m_controls->setEnabled(true);
    }
    retranslateUi(); // the reason names the profile; also reassembles
}

void ScriptEditor::reassemble()
{
    m_debounce->stop();
    m_body.reset();
    const QString text = scriptText();
    if (!m_controls->isEnabled()) {
        m_byteCount->setText(tr("? / %1 bytes").arg(kMaxScriptBytes)); // not assembled without scripts
        showError({}, std::nullopt);
        refreshEnabled();
        return;
    }
    const oi::Result<oi::Bytes> body = oi::assembleScript(*m_profile, text.toStdString());
    if (!body) {
        // No byte count for text that does not assemble.
        m_byteCount->setText(text.trimmed().isEmpty() ? tr("0 / %1 bytes").arg(kMaxScriptBytes)
                                                      : tr("? / %1 bytes").arg(kMaxScriptBytes));
        const oi::OiError &e = body.error();
        const std::optional<int> statement = script_lines::statementNumber(e.field);
        const std::optional<int> line = statement ? script_lines::lineOfStatement(text, *statement) : std::nullopt;
        // An empty editor is not a mistake, just nothing to upload yet.
        const bool empty = !statement && text.trimmed().isEmpty();
        showError(empty ? QString()
                  : line ? tr("Line %1: %2").arg(*line).arg(fromStd(e.describe()))
                         : fromStd(e.describe()),
                  line);
    } else {
        const int size = int(body->size());
        m_byteCount->setText(tr("%1 / %2 bytes").arg(size).arg(kMaxScriptBytes));
        if (size > kMaxScriptBytes) {
            showError(tr("The script is %1 bytes; the robot stores at most %2. Remove %3 bytes to upload it.")
                          .arg(size)
                          .arg(kMaxScriptBytes)
                          .arg(size - kMaxScriptBytes),
                      std::nullopt);
        } else {
            m_body = toByteArray(*body);
            showError({}, std::nullopt);
        }
    }
    refreshEnabled();
}

void ScriptEditor::showError(const QString &message, std::optional<int> line)
{
    m_error->setText(message);
    m_error->setVisible(!message.isEmpty());
    m_errorLine = line;

    QPalette countPalette = palette();
    if (!message.isEmpty() && !line)
        countPalette.setColor(QPalette::WindowText, display::stateColor(display::State::Alert, palette()));
    m_byteCount->setPalette(countPalette);

    QList<QTextEdit::ExtraSelection> selections;
    if (line) {
        QTextEdit::ExtraSelection bad;
        QColor background = display::stateColor(display::State::Alert, palette());
        background.setAlpha(70); // a tint, so the line's text stays readable
        bad.format.setBackground(background);
        bad.format.setProperty(QTextFormat::FullWidthSelection, true);
        bad.cursor = QTextCursor(m_editor->document()->findBlockByNumber(*line - 1));
        selections << bad;
    }
    m_editor->setExtraSelections(selections);
}

void ScriptEditor::refreshEnabled()
{
    // A screen reader hears the byte count and any error with the script.
    m_editor->setAccessibleDescription(m_error->text().isEmpty()
                                           ? m_byteCount->text()
                                           : tr("%1. %2").arg(m_byteCount->text(), m_error->text()));
    const bool create = m_controls->isEnabled();
    button("upload")->setEnabled(create && m_body.has_value());
    button("upload")->setToolTip(m_body ? tr("Store the script on the robot (152)")
                                        : tr("Fix the script before uploading it"));
    button("show")->setEnabled(create && !m_awaitingReply);
}

bool ScriptEditor::send(const oi::OiCommand &command)
{
    // Buttons are disabled where the profile lacks the command; nothing else fails.
    if (!oi::encodeCommand(oi::CommandEncoder(*m_profile), command))
        return false;
    emit sendRequested({command});
    return true;
}

void ScriptEditor::upload()
{
    // Typing may still be inside the pause: never upload stale text.
    reassemble();
    if (!m_body)
        return;
    const QByteArray body = *m_body;
    const oi::OiCommand script{oi::Command::Script, {}, oi::Bytes(body.cbegin(), body.cend())};
    if (const oi::EncodeResult bytes = oi::encodeCommand(oi::CommandEncoder(*m_profile), script); !bytes) {
        showError(fromStd(bytes.error().describe()), std::nullopt);
        return;
    }
    if (!send(script))
        return;
    m_awaitingReply = false; // a Show Script still due would read the script before this one
    showResult(tr("Uploaded (152): %1 / %2 bytes. Play (153) runs the script; Show Script (154) reads it back.")
                   .arg(body.size())
                   .arg(kMaxScriptBytes));
    refreshEnabled();
}

void ScriptEditor::play()
{
    emit playRequested();
    // ERRATA 20: a waiting Create reads nothing, so the user is told before it runs away.
    showResult(tr("Play (153) sent. While the script waits (155–158) the Create hears no command, not even a stop; "
                  "it listens again when the script ends."));
}

void ScriptEditor::showResult(const QString &text)
{
    m_showResult->setText(text);
    m_showResult->setVisible(true);
}

void ScriptEditor::showScript()
{
    m_awaitingReply = true;
    showResult(tr("Asking for the robot's script…"));
    refreshEnabled();
    emit showScriptRequested();
}

QString ScriptEditor::scriptAsText(const QByteArray &body) const
{
    if (body.isEmpty())
        return tr("(empty)");
    const auto *data = reinterpret_cast<const std::uint8_t *>(body.constData());
    const oi::Result<std::string> text = oi::disassembleScript(*m_profile, std::span(data, std::size_t(body.size())));
    if (text)
        return fromStd(*text);
    QStringList numbers;
    for (char b : body)
        numbers << QString::number(quint8(b));
    return tr("%1 (not readable: %2)").arg(numbers.join(u' '), fromStd(text.error().describe()));
}

void ScriptEditor::showScriptReply(const QByteArray &body, const std::optional<QByteArray> &uploaded)
{
    if (!m_awaitingReply)
        return;
    m_awaitingReply = false;
    if (uploaded && body == *uploaded) {
        m_showResult->setText(tr("The robot's script matches what was sent: %1").arg(scriptAsText(body)));
    } else {
        m_showResult->setText(tr("The robot's script differs from what was sent.\nOn the robot: %1\nSent: %2")
                                  .arg(scriptAsText(body),
                                       uploaded ? scriptAsText(*uploaded) : tr("nothing uploaded yet")));
    }
    refreshEnabled();
}

void ScriptEditor::showScriptFailed(const QString &reason)
{
    if (!m_awaitingReply)
        return;
    m_awaitingReply = false;
    m_showResult->setText(tr("No script came back: %1").arg(reason));
    refreshEnabled();
}

#include "moc_script_editor.cpp"
