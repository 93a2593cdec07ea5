// SPDX-License-Identifier: GPL-3.0-or-later
// The one way the programs open a file someone sent: a regular file within
// its reader's limit, checked before a byte is read. A named pipe is refused
// at once, not waited on; a device is refused, not read for ever.
#include "bounded_file.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <sys/stat.h>

class TestBoundedFile : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;

    QString write(const QString &name, const QByteArray &bytes)
    {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
            qFatal("cannot write %s", qPrintable(path));
        return path;
    }

private slots:
    void aFileWithinItsLimitIsReadWhole()
    {
        const QString path = write("ten.json", QByteArray(10, 'x'));
        QString error;
        QCOMPARE(files::readBounded(path, 10, &error).value_or("refused"), QByteArray(10, 'x'));
        QCOMPARE(error, QString());
    }

    void aLargerFileIsRefusedNamingTheLimit()
    {
        const QString path = write("big.json", QByteArray(3 << 20, 'x'));
        QString error;
        QVERIFY(!files::readBounded(path, 1 << 20, &error));
        QCOMPARE(error, QString("3 MB, larger than the 1 MB this program reads of such a file"));
    }

    // Without the check, opening a pipe with no writer waits for one for ever.
    void aNamedPipeIsRefusedAtOnce()
    {
        const QString path = m_dir.filePath("pipe.json");
        QCOMPARE(::mkfifo(QFile::encodeName(path).constData(), 0600), 0);
        QString error;
        QVERIFY(!files::readBounded(path, 1 << 20, &error));
        QCOMPARE(error, QString("not a regular file but a named pipe"));
        QFile file;
        QVERIFY(!files::openBounded(file, path, 1 << 20, &error, QIODevice::ReadWrite));
        QVERIFY(!file.isOpen());
    }

    // /dev/zero says it is 0 bytes long and never ends.
    void aDeviceOrAFolderIsRefused()
    {
        QString error;
        QVERIFY(!files::readBounded("/dev/zero", 1 << 20, &error));
        QCOMPARE(error, QString("not a regular file but a device"));
        QVERIFY(!files::readBounded(m_dir.path(), 1 << 20, &error));
        QCOMPARE(error, QString("not a regular file but a folder"));
    }

    void aLinkIsCheckedForWhatItNames()
    {
        const QString link = m_dir.filePath("zero.json");
        QVERIFY(QFile::link("/dev/zero", link));
        QString error;
        QVERIFY(!files::readBounded(link, 1 << 20, &error));
        QCOMPARE(error, QString("not a regular file but a device"));
    }

    void aMissingFileSaysSo()
    {
        QString error;
        QVERIFY(!files::readBounded(m_dir.filePath("gone.json"), 1 << 20, &error));
        QCOMPARE(error, QString("No such file or directory"));
    }

    void anOpenedFileCanBeWrittenToo()
    {
        const QString path = write("named.oirec", "abc");
        QFile file;
        QVERIFY(files::openBounded(file, path, 10, nullptr, QIODevice::ReadWrite));
        QCOMPARE(file.readAll(), QByteArray("abc"));
        QVERIFY(file.write("d"));
    }

    void sizesReadAsPeopleSayThem()
    {
        QCOMPARE(files::sizeText(512), QString("512 bytes"));
        QCOMPARE(files::sizeText(64 << 10), QString("64 KB"));
        QCOMPARE(files::sizeText(1000 << 10), QString("1000 KB"));
        QCOMPARE(files::sizeText(5 << 19), QString("2.5 MB"));
        QCOMPARE(files::sizeText(qint64(1) << 30), QString("1 GB"));
    }
};

QTEST_GUILESS_MAIN(TestBoundedFile)
#include "tst_bounded_file.moc"
