// SPDX-License-Identifier: GPL-3.0-or-later
#include "firmware_banner.h"
#include "sensor_snapshot.h"

#include <QTest>

#include <cmath>
#include <string_view>

using namespace oi;

namespace {

// A literal with its NUL bytes, without the terminating one.
template <std::size_t N>
QByteArray bytes(const char (&text)[N])
{
    return QByteArray(text, N - 1);
}

std::string_view view(const QByteArray &text)
{
    return std::string_view(text.constData(), std::size_t(text.size()));
}

// What a Create 2 prints after Reset (7), with the line noise the reset leaves
// on the wire in front of it.
QByteArray realisticBanner()
{
    return bytes("\0\xff\xfe\x80")
           + QByteArray("bl-start\r\n"
                        "STR730\r\n"
                        "bootloader id: #x47186549 82ECCFFF\r\n"
                        "bootloader info rev: #xF000\r\n"
                        "bootloader rev: #x0001\r\n"
                        "2007-05-14-1715-L   \r\n"
                        "Roomba by iRobot!\r\n"
                        "str730\r\n"
                        "2012-03-22-1549-L   \r\n"
                        "battery-current-zero 258\r\n"
                        "2014-06-26-1149-L   \r\n"
                        "r3_robot/tags/release-3.3.0:4975 CLEAN\r\n"
                        "\r\n"
                        "bootloader id: #x47186549 82ECCFFF\r\n");
}

} // namespace

class TestFirmwareBanner : public QObject {
    Q_OBJECT
private slots:
    void parse_data()
    {
        QTest::addColumn<QByteArray>("banner");
        QTest::addColumn<bool>("found");
        QTest::addColumn<QByteArray>("release");
        QTest::addColumn<int>("major");
        QTest::addColumn<int>("minor");
        QTest::addColumn<int>("patch");
        // Expected corrections (ERRATA 16).
        QTest::addColumn<bool>("distanceUnreliable");
        QTest::addColumn<bool>("radiusUnreliable");
        QTest::addColumn<bool>("angleDivided");

        QTest::newRow("3.2.9") << QByteArray("r3_robot/tags/release-3.2.9:4975 CLEAN\r\n") << true
                               << QByteArray("release-3.2.9") << 3 << 2 << 9 << true << true << true;
        QTest::newRow("3.3.0") << QByteArray("r3_robot/tags/release-3.3.0:5100 CLEAN\r\n") << true
                               << QByteArray("release-3.3.0") << 3 << 3 << 0 << false << false
                               << true;
        QTest::newRow("3.4.0") << QByteArray("r3_robot/tags/release-3.4.0:5500 CLEAN\r\n") << true
                               << QByteArray("release-3.4.0") << 3 << 4 << 0 << false << false
                               << true;
        QTest::newRow("3.4.1") << QByteArray("r3_robot/tags/release-3.4.1:5867 CLEAN\r\n") << true
                               << QByteArray("release-3.4.1") << 3 << 4 << 1 << false << false
                               << false;
        QTest::newRow("stm32 3.7.7")
            << QByteArray("r3_robot/tags/release-stm32-3.7.7:6216 CLEAN\r\n") << true
            << QByteArray("release-stm32-3.7.7") << 3 << 7 << 7 << false << false << false;
        QTest::newRow("realistic multi-line CR LF") << realisticBanner() << true
                                                    << QByteArray("release-3.3.0") << 3 << 3 << 0
                                                    << false << false << true;
        QTest::newRow("document example with full stop")
            << QByteArray("for example: r3_robot/tags/release-3.3.0.\n") << true
            << QByteArray("release-3.3.0") << 3 << 3 << 0 << false << false << true;
        QTest::newRow("NUL ends the name")
            << bytes("\0\0r3_robot/tags/release-3.4.0\0\xff") << true
            << QByteArray("release-3.4.0") << 3 << 4 << 0 << false << false << true;
        QTest::newRow("first complete of several")
            << QByteArray("release-candidate\r\nrelease-3.2.9:1 CLEAN\r\n"
                          "r3_robot/tags/release-stm32-3.7.7:2 CLEAN\r\n")
            << true << QByteArray("release-3.2.9") << 3 << 2 << 9 << true << true << true;
        QTest::newRow("several digits a part")
            << QByteArray("release-10.12.105:1\r\n") << true << QByteArray("release-10.12.105")
            << 10 << 12 << 105 << false << false << false;

        const QByteArray banner = realisticBanner();
        const qsizetype tag = banner.indexOf("r3_robot/tags/release-");
        QTest::newRow("cut before the version")
            << banner.left(tag + 18) << false << QByteArray() << 0 << 0 << 0 << false << false
            << false;
        QTest::newRow("cut after release-") << banner.left(tag + 22) << false << QByteArray() << 0
                                            << 0 << 0 << false << false << false;
        QTest::newRow("cut inside the version") << banner.left(tag + 25) << false << QByteArray()
                                                << 0 << 0 << 0 << false << false << false;
        // "3.3.0" could still become "3.3.01..." until a ':' or line end arrives.
        QTest::newRow("cut right after the version")
            << banner.left(tag + 27) << false << QByteArray() << 0 << 0 << 0 << false << false
            << false;
        QTest::newRow("junk") << bytes("\0\x13\xff\x7f garbage \x80\x81 1.2.3 rel-3.4.1:\r\n")
                              << false << QByteArray() << 0 << 0 << 0 << false << false << false;
        QTest::newRow("empty") << QByteArray() << false << QByteArray() << 0 << 0 << 0 << false
                               << false << false;
        QTest::newRow("no version after tag")
            << QByteArray("bootloader id: #x47186549\r\nrelease-candidate\r\n") << false
            << QByteArray() << 0 << 0 << 0 << false << false << false;
        QTest::newRow("two parts only") << QByteArray("release-3.4:1\r\n") << false << QByteArray()
                                        << 0 << 0 << 0 << false << false << false;
        QTest::newRow("four parts") << QByteArray("release-3.4.1.2:1\r\n") << false
                                    << QByteArray() << 0 << 0 << 0 << false << false << false;
        QTest::newRow("part too large for int")
            << QByteArray("release-3.4.99999999999:1\r\n") << false << QByteArray() << 0 << 0
            << 0 << false << false << false;
        QTest::newRow("digits glued to a word") << QByteArray("release-stm3.3.0:1\r\n") << false
                                                << QByteArray() << 0 << 0 << 0 << false << false
                                                << false;
    }

    void parse()
    {
        QFETCH(QByteArray, banner);
        QFETCH(bool, found);
        QFETCH(QByteArray, release);
        QFETCH(int, major);
        QFETCH(int, minor);
        QFETCH(int, patch);
        QFETCH(bool, distanceUnreliable);
        QFETCH(bool, radiusUnreliable);
        QFETCH(bool, angleDivided);

        const auto info = parseFirmwareBanner(view(banner));
        QCOMPARE(info.has_value(), found);
        if (!found)
            return;
        QCOMPARE(QByteArray::fromStdString(info->release), release);
        QCOMPARE(info->version.major, major);
        QCOMPARE(info->version.minor, minor);
        QCOMPARE(info->version.patch, patch);
        QCOMPARE(info->corrections.distanceUnreliable, distanceUnreliable);
        QCOMPARE(info->corrections.radiusUnreliable, radiusUnreliable);
        QCOMPARE(info->corrections.angleDivisor.has_value(), angleDivided);
        QCOMPARE(info->corrections.any(), distanceUnreliable || radiusUnreliable || angleDivided);
    }

    void everyPrefixOfTheBanner()
    {
        // Bytes arrive a few at a time: no prefix may give a wrong version, and
        // the right one appears as soon as the ':' after it has arrived.
        const QByteArray banner = realisticBanner();
        const qsizetype complete = banner.indexOf("3.3.0:") + 6;
        for (qsizetype length = 0; length <= banner.size(); ++length) {
            const auto info = parseFirmwareBanner(view(banner.left(length)));
            QCOMPARE(info.has_value(), length >= complete);
            if (info)
                QCOMPARE(QByteArray::fromStdString(info->version.toString()), QByteArray("3.3.0"));
        }
    }

    void corrections_data()
    {
        QTest::addColumn<int>("major");
        QTest::addColumn<int>("minor");
        QTest::addColumn<int>("patch");
        QTest::addColumn<bool>("distanceUnreliable");
        QTest::addColumn<bool>("radiusUnreliable");
        QTest::addColumn<bool>("angleDivided");

        QTest::newRow("0.0.0") << 0 << 0 << 0 << true << true << true;
        QTest::newRow("2.4.6") << 2 << 4 << 6 << true << true << true;
        QTest::newRow("3.2.0") << 3 << 2 << 0 << true << true << true;
        QTest::newRow("3.2.9") << 3 << 2 << 9 << true << true << true;
        QTest::newRow("3.2.99") << 3 << 2 << 99 << true << true << true;
        QTest::newRow("3.3.0") << 3 << 3 << 0 << false << false << true;
        QTest::newRow("3.3.9") << 3 << 3 << 9 << false << false << true;
        QTest::newRow("3.4.0") << 3 << 4 << 0 << false << false << true;
        QTest::newRow("3.4.1") << 3 << 4 << 1 << false << false << false;
        QTest::newRow("3.5.0") << 3 << 5 << 0 << false << false << false;
        QTest::newRow("3.7.7") << 3 << 7 << 7 << false << false << false;
        QTest::newRow("4.0.0") << 4 << 0 << 0 << false << false << false;
    }

    void corrections()
    {
        QFETCH(int, major);
        QFETCH(int, minor);
        QFETCH(int, patch);
        QFETCH(bool, distanceUnreliable);
        QFETCH(bool, radiusUnreliable);
        QFETCH(bool, angleDivided);

        const FirmwareCorrections c = correctionsFor({major, minor, patch});
        QCOMPARE(c.distanceUnreliable, distanceUnreliable);
        QCOMPARE(c.radiusUnreliable, radiusUnreliable);
        QCOMPARE(c.angleDivisor.has_value(), angleDivided);
        if (angleDivided)
            QVERIFY(*c.angleDivisor == 0.324056);
        QCOMPARE(c.any(), distanceUnreliable || radiusUnreliable || angleDivided);
    }

    // The frame handed on: packet 20 in whole degrees, the rest as it came.
    void correctFrame()
    {
        SensorSnapshot frame(profile(ProfileId::Create2));
        frame.set(19, 100);
        frame.set(20, -29);
        frame.set(40, 500);
        correctionsFor({3, 4, 0}).correct(frame);
        QCOMPARE(frame.raw(20), -89);
        QCOMPARE(frame.raw(19), 100);
        QCOMPARE(frame.raw(40), 500);
        correctionsFor({3, 4, 1}).correct(frame);
        QCOMPARE(frame.raw(20), -89);
        SensorSnapshot noAngle(profile(ProfileId::Create2));
        correctionsFor({3, 4, 0}).correct(noAngle);
        QVERIFY(!noAngle.has(20));
    }

    void correctedAngle_data()
    {
        QTest::addColumn<bool>("divided");
        QTest::addColumn<int>("raw");
        QTest::addColumn<double>("degrees");

        QTest::newRow("divided 100") << true << 100 << 308.58863900066655;
        QTest::newRow("divided -29") << true << -29 << -89.49070531019329;
        QTest::newRow("divided 0") << true << 0 << 0.0;
        QTest::newRow("fixed 100") << false << 100 << 100.0;
        QTest::newRow("fixed -29") << false << -29 << -29.0;
    }

    void correctedAngle()
    {
        QFETCH(bool, divided);
        QFETCH(int, raw);
        QFETCH(double, degrees);

        const FirmwareCorrections c = correctionsFor(divided ? FirmwareVersion{3, 4, 0}
                                                             : FirmwareVersion{3, 4, 1});
        QVERIFY2(std::abs(c.correctedAngleDegrees(raw) - degrees) < 1e-9,
                 QByteArray::number(c.correctedAngleDegrees(raw), 'g', 17).constData());
    }

    void versionToString_data()
    {
        QTest::addColumn<int>("major");
        QTest::addColumn<int>("minor");
        QTest::addColumn<int>("patch");
        QTest::addColumn<QByteArray>("text");

        QTest::newRow("3.4.0") << 3 << 4 << 0 << QByteArray("3.4.0");
        QTest::newRow("0.0.0") << 0 << 0 << 0 << QByteArray("0.0.0");
        QTest::newRow("10.12.105") << 10 << 12 << 105 << QByteArray("10.12.105");
    }

    void versionToString()
    {
        QFETCH(int, major);
        QFETCH(int, minor);
        QFETCH(int, patch);
        QFETCH(QByteArray, text);
        QCOMPARE(QByteArray::fromStdString(FirmwareVersion{major, minor, patch}.toString()), text);
    }

    void versionOrder()
    {
        // Compared part by part as numbers, not as text: 3.10.0 is after 3.9.9.
        QVERIFY((FirmwareVersion{3, 2, 9}) < (FirmwareVersion{3, 3, 0}));
        QVERIFY((FirmwareVersion{3, 4, 0}) < (FirmwareVersion{3, 4, 1}));
        QVERIFY((FirmwareVersion{3, 9, 9}) < (FirmwareVersion{3, 10, 0}));
        QVERIFY((FirmwareVersion{2, 99, 99}) < (FirmwareVersion{3, 0, 0}));
        QVERIFY((FirmwareVersion{3, 4, 0}) == (FirmwareVersion{3, 4, 0}));
        QVERIFY(!((FirmwareVersion{3, 4, 1}) <= (FirmwareVersion{3, 4, 0})));
    }
};

QTEST_GUILESS_MAIN(TestFirmwareBanner)
#include "tst_firmware_banner.moc"
