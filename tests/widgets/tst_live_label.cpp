// SPDX-License-Identifier: GPL-3.0-or-later
#include "live_label.h"

#include <QApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QTest>

namespace {

// Counts the requests to lay a widget out again.
class LayoutRequests : public QObject {
public:
    int count = 0;

protected:
    bool eventFilter(QObject *watched, QEvent *event) override
    {
        count += event->type() == QEvent::LayoutRequest;
        return QObject::eventFilter(watched, event);
    }
};

} // namespace

class TestLiveLabel : public QObject {
    Q_OBJECT
private slots:
    void aNewTextNoWiderRepaintsTheLabelAlone()
    {
        QWidget window;
        auto *layout = new QHBoxLayout(&window);
        auto *rate = new QLabel(&window);
        layout->addWidget(rate);
        layout->addWidget(new QLabel(QStringLiteral("beside"), &window), 1);
        window.show();
        setLiveText(rate, QStringLiteral("66.7 frames/s, 12 345 resyncs"));
        QCoreApplication::processEvents();
        LayoutRequests requests;
        window.installEventFilter(&requests);

        // A rate changing while the robot streams: the window keeps its layout.
        setLiveText(rate, QStringLiteral("66.6 frames/s"));
        setLiveText(rate, QStringLiteral("66.5 frames/s"));
        QCoreApplication::processEvents();
        QCOMPARE(rate->text(), QStringLiteral("66.5 frames/s"));
        QCOMPARE(requests.count, 0);
        QVERIFY(rate->width() >= rate->sizeHint().width());

        // A wider text makes room for itself, once.
        const QString wider = QStringLiteral("66.7 frames/s, 12 345 resyncs, 678 checksum failures");
        setLiveText(rate, wider);
        QCoreApplication::processEvents();
        QCOMPARE(requests.count, 1);
        QCOMPARE(rate->text(), wider);
        QVERIFY(rate->width() >= rate->sizeHint().width());
    }
};

QTEST_MAIN(TestLiveLabel)
#include "tst_live_label.moc"
