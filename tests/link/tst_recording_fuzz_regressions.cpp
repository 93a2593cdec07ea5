// SPDX-License-Identifier: GPL-3.0-or-later
// Recordings replayed through the check fuzz_recording (tests/fuzz) runs:
// its seeds, and damaged files that must be refused or read only up to the
// damage.
#include "../fuzz/recording_replay.h"

#include <QDir>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTest>
#include <QtEndian>

namespace {

template <typename T>
void appendLittleEndian(QByteArray &out, T value)
{
    char bytes[sizeof(T)];
    qToLittleEndian(value, bytes);
    out.append(bytes, sizeof(T));
}

// A recording as recording_format.md lays it out, record by record.
class RecordingBytes {
public:
    RecordingBytes()
    {
        const QByteArray header = R"({"format":"Roomba Dashboard recording","version":1})";
        m_bytes = QByteArray("OIRECORD");
        appendLittleEndian<quint16>(m_bytes, 1);
        appendLittleEndian<quint32>(m_bytes, quint32(header.size()));
        m_bytes += header;
    }
    RecordingBytes &record(char kind, qint64 timeUs, const QByteArray &payload)
    {
        QByteArray r(1, kind);
        appendLittleEndian<qint64>(r, timeUs);
        appendLittleEndian<quint16>(r, quint16(payload.size()));
        r += payload;
        appendLittleEndian<quint16>(r, qChecksum(r));
        m_bytes += r;
        return *this;
    }
    RecordingBytes &stream(const QByteArray &json) { return record('S', 0, json); }
    QByteArray bytes() const { return m_bytes; }

private:
    QByteArray m_bytes;
};

// The document's example frame: packets 29 and 13 (ERRATA 1).
const QByteArray kFrame = QByteArray::fromHex("13051d02190d00a3");

} // namespace

class TestRecordingFuzzRegressions : public QObject {
    Q_OBJECT
private slots:
    void seedsHoldTheInvariants_data()
    {
        QTest::addColumn<QString>("path");
        const QDir seeds(ROOMBA_FUZZ_CORPUS "/recording");
        for (const QString &name : seeds.entryList(QDir::Files))
            QTest::newRow(qPrintable(name)) << seeds.filePath(name);
        QVERIFY(seeds.count() > 0);
    }
    void seedsHoldTheInvariants()
    {
        QFETCH(QString, path);
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const std::string failure = fuzz::checkRecordingInput(file.readAll());
        QVERIFY2(failure.empty(), failure.c_str());
    }

    // A packet id beyond a byte was handed to the parser cut to a byte:
    // a stream "of packet 300" was read as one of packet 44.
    void unknownStreamPacketsAreRefused_data()
    {
        QTest::addColumn<QByteArray>("stream");
        QTest::newRow("300, read as 44") << QByteArray(R"({"profile":"create2","baud":115200,"packets":[300]})");
        QTest::newRow("-1") << QByteArray(R"({"profile":"create2","baud":115200,"packets":[29,-1]})");
        QTest::newRow("not a number") << QByteArray(R"({"profile":"create2","baud":115200,"packets":["29"]})");
        QTest::newRow("not on the Create") << QByteArray(R"({"profile":"create1","baud":57600,"packets":[100]})");
    }
    void unknownStreamPacketsAreRefused()
    {
        QFETCH(QByteArray, stream);
        const QByteArray file = RecordingBytes().stream(stream).record('R', 15000, kFrame).bytes();
        QString error;
        QVERIFY(!oilink::Recording::fromBytes(file, "bad.oirec", &error));
        QVERIFY2(error.contains("unreadable stream description"), qPrintable(error));
        QVERIFY(fuzz::checkRecordingInput(file).empty());
    }

    void knownStreamPacketsAreRead()
    {
        const QByteArray file = RecordingBytes()
                                    .stream(R"({"profile":"create2","baud":115200,"packets":[29,13]})")
                                    .record('R', 15000, kFrame)
                                    .record('R', 30000, kFrame)
                                    .bytes();
        QString error;
        const auto recording = oilink::Recording::fromBytes(file, "good.oirec", &error);
        QVERIFY2(recording, qPrintable(error));
        QCOMPARE(recording->frames().size(), std::size_t(2));
        QVERIFY(fuzz::checkRecordingInput(file).empty());
    }
};

QTEST_GUILESS_MAIN(TestRecordingFuzzRegressions)
#include "tst_recording_fuzz_regressions.moc"
