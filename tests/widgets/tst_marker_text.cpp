// SPDX-License-Identifier: GPL-3.0-or-later
// A marker's note comes from a recording someone may have sent: the Markers
// dock shows it as written, in its table, its tooltip and the note editor,
// never as rich text, which would open the files its pictures name.
#include "marker_list.h"
#include "marker_note_editor.h"

#include <QLabel>
#include <QTableWidget>
#include <QTest>
#include <QTextDocument>

namespace {

const QString kNote = QStringLiteral(R"(<b>x</b> <img src="/dev/zero">)");

// The text a tooltip shows, as QToolTip reads it: rich text when it looks like it.
QString tooltipShows(const QString &tip)
{
    QTextDocument document;
    if (Qt::mightBeRichText(tip))
        document.setHtml(tip);
    else
        document.setPlainText(tip);
    return document.toPlainText();
}

} // namespace

class TestMarkerText : public QObject {
    Q_OBJECT
private slots:
    void aNoteIsShownAsWritten()
    {
        MarkerList list;
        list.setMarkers({{1, 2000000, kNote}});
        const QTableWidgetItem *note = list.findChild<QTableWidget *>()->item(0, 1);
        QCOMPARE(note->text(), kNote);
        QCOMPARE(tooltipShows(note->toolTip()), kNote);

        MarkerNoteEditor editor;
        editor.edit(1, QStringLiteral("Marker %1 at 0:02:").arg(kNote));
        const auto *label = editor.findChild<QLabel *>("markerNoteLabel");
        QCOMPARE(label->textFormat(), Qt::PlainText);
        QCOMPARE(label->text(), QStringLiteral("Marker %1 at 0:02:").arg(kNote));
    }
};

QTEST_MAIN(TestMarkerText)
#include "tst_marker_text.moc"
