// SPDX-License-Identifier: GPL-3.0-or-later
#include "seven_segment_font.h"

#include <QTest>

using namespace oi;

namespace {

QByteArray toByteArray(const std::array<std::uint8_t, 4> &codes)
{
    return QByteArray(reinterpret_cast<const char *>(codes.data()), static_cast<qsizetype>(codes.size()));
}

void addShapeColumns()
{
    QTest::addColumn<int>("code");
    QTest::addColumn<int>("segments");
}

void addShape(char c, int segments)
{
    QTest::addRow("%c", c) << int(static_cast<unsigned char>(c)) << segments;
}

} // namespace

class TestSevenSegmentFont : public QObject {
    Q_OBJECT
private slots:
    void segmentBits()
    {
        // Digit LEDs Raw (163): bit 0 = A .. bit 6 = G, bit 7 reserved.
        QCOMPARE(int(segment::A), 0x01);
        QCOMPARE(int(segment::B), 0x02);
        QCOMPARE(int(segment::C), 0x04);
        QCOMPARE(int(segment::D), 0x08);
        QCOMPARE(int(segment::E), 0x10);
        QCOMPARE(int(segment::F), 0x20);
        QCOMPARE(int(segment::G), 0x40);
    }

    void digits_data()
    {
        addShapeColumns();
        addShape('0', 0x3F);
        addShape('1', 0x06);
        addShape('2', 0x5B);
        addShape('3', 0x4F);
        addShape('4', 0x66);
        addShape('5', 0x6D);
        addShape('6', 0x7D);
        addShape('7', 0x07);
        addShape('8', 0x7F);
        addShape('9', 0x6F);
    }
    void digits()
    {
        QFETCH(int, code);
        QFETCH(int, segments);
        QCOMPARE(int(sevenSegmentForAscii(code)), segments);
        QVERIFY(isSevenSegmentCharacter(code));
    }

    void letters_data()
    {
        addShapeColumns();
        addShape('A', 0x77);
        addShape('B', 0x7C); // b
        addShape('C', 0x39);
        addShape('D', 0x5E); // d
        addShape('E', 0x79);
        addShape('F', 0x71);
        addShape('G', 0x3D);
        addShape('H', 0x76);
        addShape('I', 0x30);
        addShape('J', 0x1E);
        addShape('K', 0x75);
        addShape('L', 0x38);
        addShape('M', 0x15);
        addShape('N', 0x37);
        addShape('O', 0x3F);
        addShape('P', 0x73);
        addShape('Q', 0x67); // q
        addShape('R', 0x50); // r
        addShape('S', 0x6D);
        addShape('T', 0x78); // t
        addShape('U', 0x3E);
        addShape('V', 0x1C); // v
        addShape('W', 0x2A);
        addShape('X', 0x76);
        addShape('Y', 0x6E); // y
        addShape('Z', 0x5B);
    }
    void letters()
    {
        QFETCH(int, code);
        QFETCH(int, segments);
        QCOMPARE(int(sevenSegmentForAscii(code)), segments);
        QVERIFY(isSevenSegmentCharacter(code));
        // Case-blind: the small letter shows the same shape.
        const int small = code - 'A' + 'a';
        QCOMPARE(int(sevenSegmentForAscii(small)), segments);
        QVERIFY(isSevenSegmentCharacter(small));
    }

    void punctuation_data()
    {
        addShapeColumns();
        addShape(' ', 0x00);
        addShape('!', 0x06);
        addShape('"', 0x22);
        addShape('#', 0x7E);
        addShape('$', 0x6D); // as S
        addShape('%', 0x24);
        addShape('&', 0x7B);
        addShape('\'', 0x02);
        addShape('(', 0x39); // as [
        addShape(')', 0x0F); // as ]
        addShape(',', 0x10);
        addShape('-', 0x40);
        addShape('.', 0x04);
        addShape('/', 0x52);
        addShape(':', 0x09);
        addShape(';', 0x0D);
        addShape('<', 0x61);
        addShape('=', 0x48);
        addShape('>', 0x43);
        addShape('?', 0x53);
        addShape('[', 0x39);
        addShape('\\', 0x64);
        addShape(']', 0x0F);
        addShape('^', 0x23);
        addShape('_', 0x08);
        addShape('`', 0x20);
        addShape('{', 0x46);
        addShape('|', 0x30);
        addShape('}', 0x70);
        addShape('~', 0x01);
    }
    void punctuation()
    {
        QFETCH(int, code);
        QFETCH(int, segments);
        QCOMPARE(int(sevenSegmentForAscii(code)), segments);
        QVERIFY(isSevenSegmentCharacter(code));
    }

    void documentAliases()
    {
        QCOMPARE(sevenSegmentForAscii('$'), sevenSegmentForAscii('S'));
        QCOMPARE(sevenSegmentForAscii('('), sevenSegmentForAscii('['));
        QCOMPARE(sevenSegmentForAscii(')'), sevenSegmentForAscii(']'));
        QCOMPARE(sevenSegmentForAscii('s'), sevenSegmentForAscii('5'));
    }

    void blankCodes_data()
    {
        QTest::addColumn<int>("code");
        QTest::newRow("'*' not in the table") << int('*');
        QTest::newRow("'+' not in the table") << int('+');
        QTest::newRow("'@' not in the table") << int('@');
        QTest::newRow("NUL") << 0;
        QTest::newRow("31") << 31;
        QTest::newRow("DEL") << 127;
        QTest::newRow("200") << 200;
        QTest::newRow("255") << 255;
        QTest::newRow("256") << 256;
        QTest::newRow("negative") << -1;
    }
    void blankCodes()
    {
        QFETCH(int, code);
        QCOMPARE(int(sevenSegmentForAscii(code)), 0);
        QVERIFY(!isSevenSegmentCharacter(code));
    }

    void spaceIsListedAndBlank()
    {
        QVERIFY(isSevenSegmentCharacter(' '));
        QCOMPARE(int(sevenSegmentForAscii(' ')), 0);
    }

    void everyListedCodeHasAShape()
    {
        int listed = 0;
        for (int code = 32; code <= 126; ++code) {
            const bool expectListed = code != '*' && code != '+' && code != '@';
            QCOMPARE(isSevenSegmentCharacter(code), expectListed);
            const int segments = sevenSegmentForAscii(code);
            QVERIFY2((segments & 0x80) == 0, "bit 7 is reserved");
            if (expectListed && code != ' ') {
                QVERIFY2(segments != 0, qPrintable(QStringLiteral("code %1 shows blank").arg(code)));
                ++listed;
            }
        }
        QCOMPARE(listed, 91); // 95 printable codes less space, '*', '+' and '@'
    }

    void digitAsciiCodes_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QByteArray>("codes");
        QTest::newRow("document example") << "ABCD" << QByteArray("\x41\x42\x43\x44", 4);
        QTest::newRow("empty pads") << "" << QByteArray("    ", 4);
        QTest::newRow("short pads right") << "Hi" << QByteArray("Hi  ", 4);
        QTest::newRow("keeps case") << "cLn" << QByteArray("cLn ", 4);
        QTest::newRow("first four") << "HELLO" << QByteArray("HELL", 4);
        QTest::newRow("time") << "12:5" << QByteArray("12:5", 4);
    }
    void digitAsciiCodes()
    {
        QFETCH(QString, text);
        QFETCH(QByteArray, codes);
        QCOMPARE(toByteArray(oi::digitAsciiCodes(text.toStdString())), codes);
    }
};

QTEST_GUILESS_MAIN(TestSevenSegmentFont)
#include "tst_seven_segment_font.moc"
