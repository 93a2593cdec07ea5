// SPDX-License-Identifier: GPL-3.0-or-later
#include "pty_robot_server.h"

#include "serial_line.h"

#include <QSocketNotifier>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

namespace sim {

namespace {
constexpr int kClientPollMs = 20;

// The termios speeds a client can choose, and the robot's rates among them
// (14400 and 28800 have none, so no client can follow the robot there).
constexpr struct {
    speed_t speed;
    int baud;
} kSpeeds[] = {{B300, 300},     {B600, 600},     {B1200, 1200},   {B2400, 2400},
               {B4800, 4800},   {B9600, 9600},   {B19200, 19200}, {B38400, 38400},
               {B57600, 57600}, {B115200, 115200}};

int baudOfSpeed(speed_t speed)
{
    for (const auto &s : kSpeeds)
        if (s.speed == speed)
            return s.baud;
    return 0;
}

speed_t speedOfBaud(int baud)
{
    for (const auto &s : kSpeeds)
        if (s.baud == baud)
            return s.speed;
    return B115200;
}

QString systemError(const char *what)
{
    return QStringLiteral("%1: %2").arg(QLatin1String(what), QString::fromLocal8Bit(std::strerror(errno)));
}
} // namespace

PtyRobotServer::PtyRobotServer(const oi::RobotProfile &profile, std::uint32_t seed, QObject *parent)
    : QObject(parent), m_robot(profile, seed, this), m_clientPoll(this) // children: moveToThread takes them along
{
    m_clientPoll.setInterval(kClientPollMs);
    connect(&m_clientPoll, &QTimer::timeout, this, &PtyRobotServer::checkForClient);
    connect(&m_robot, &RealTimeRobot::bytesOut, this, &PtyRobotServer::writeToClient);
}

PtyRobotServer::~PtyRobotServer() { close(); }

bool PtyRobotServer::open(QString *error)
{
    if (m_master >= 0)
        return true;
    auto fail = [&](const char *what) {
        if (error)
            *error = systemError(what);
        if (m_master >= 0)
            ::close(m_master);
        m_master = -1;
        return false;
    };
    m_master = posix_openpt(O_RDWR | O_NOCTTY);
    if (m_master < 0)
        return fail("posix_openpt");
    if (grantpt(m_master) != 0)
        return fail("grantpt");
    if (unlockpt(m_master) != 0)
        return fail("unlockpt");
    const char *name = ptsname(m_master);
    if (!name)
        return fail("ptsname");
    m_slavePath = QString::fromLocal8Bit(name);
    const int flags = fcntl(m_master, F_GETFL);
    if (flags < 0 || fcntl(m_master, F_SETFL, flags | O_NONBLOCK) != 0)
        return fail("fcntl");

    // Raw bytes both ways at the robot's rate: no echo, no line editing, no
    // CR/LF translation. The settings live with the pair, so a client that
    // does not set them itself still gets a clean line. Opening and closing the slave once puts
    // the master into the hung-up state, so a client's first open is seen
    // the same way as a reopen, and nothing is written before anyone listens.
    const int slave = ::open(name, O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (slave < 0)
        return fail("open slave");
    termios tio{};
    if (tcgetattr(slave, &tio) == 0) {
        cfmakeraw(&tio);
        cfsetspeed(&tio, speedOfBaud(m_robot.robot().baud()));
        tcsetattr(slave, TCSANOW, &tio);
    }
    ::close(slave);

    m_readNotifier = new QSocketNotifier(m_master, QSocketNotifier::Read, this);
    m_readNotifier->setEnabled(false);
    connect(m_readNotifier, &QSocketNotifier::activated, this, &PtyRobotServer::readFromClient);
    m_clientPoll.start();
    m_robot.start();
    return true;
}

void PtyRobotServer::close()
{
    m_robot.stop();
    m_clientPoll.stop();
    delete m_readNotifier;
    m_readNotifier = nullptr;
    if (m_master >= 0)
        ::close(m_master);
    m_master = -1;
    m_slavePath.clear();
    setClientConnected(false);
}

int PtyRobotServer::clientBaud() const
{
    // The master reads the slave's settings: the rate the client chose.
    termios tio{};
    if (m_master < 0 || tcgetattr(m_master, &tio) != 0)
        return 0;
    return baudOfSpeed(cfgetospeed(&tio));
}

void PtyRobotServer::setClientConnected(bool connected)
{
    if (connected == m_clientConnected)
        return;
    m_clientConnected = connected;
    emit clientConnectedChanged(connected);
}

void PtyRobotServer::checkForClient()
{
    if (m_master < 0)
        return;
    pollfd p{m_master, POLLIN, 0};
    if (::poll(&p, 1, 0) < 0 || (p.revents & POLLHUP))
        return; // still nobody on the other side
    m_clientPoll.stop();
    m_readNotifier->setEnabled(true);
    setClientConnected(true);
    if (p.revents & POLLIN)
        readFromClient();
}

void PtyRobotServer::readFromClient()
{
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(m_master, buffer, sizeof buffer);
        if (n > 0) {
            const SerialLine line{m_robot.robot().baud(), clientBaud()};
            m_robot.write(line.heardByRobot(QByteArray(buffer, qsizetype(n))));
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0 && errno == EAGAIN)
            return;
        // EIO: the last client closed the slave. Wait for the next one
        // without spinning on the hang-up.
        m_readNotifier->setEnabled(false);
        setClientConnected(false);
        m_clientPoll.start();
        return;
    }
}

void PtyRobotServer::writeToClient(const QByteArray &bytes)
{
    if (m_master < 0 || !m_clientConnected)
        return;
    const QByteArray heard = SerialLine{m_robot.robot().baud(), clientBaud()}.heardByClient(bytes);
    const char *data = heard.constData();
    qsizetype left = heard.size();
    while (left > 0) {
        const ssize_t n = ::write(m_master, data, std::size_t(left));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return; // a client that does not read loses bytes, as on a real line
        data += n;
        left -= n;
    }
}

} // namespace sim

#include "moc_pty_robot_server.cpp"
