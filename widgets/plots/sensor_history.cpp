// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensor_history.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QSaveFile>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

// A channel's first allocation; it then doubles up to the capacity, so a
// short session holds little memory.
constexpr std::size_t kFirstBlock = 1024;
// Export writes in pieces of about this size rather than building the whole
// file (an hour of every channel is tens of megabytes) in memory.
constexpr qsizetype kWriteChunk = 64 * 1024;

QByteArray timeText(double t)
{
    QByteArray text = QByteArray::number(t, 'f', 6);
    while (text.endsWith('0'))
        text.chop(1);
    if (text.endsWith('.'))
        text.chop(1);
    if (text == "-0")
        text = "0";
    return text;
}

} // namespace

SensorHistory::SensorHistory(const oi::RobotProfile &profile, std::size_t capacity)
    : m_profile(&profile), m_capacity(std::max<std::size_t>(capacity, 1))
{
}

void SensorHistory::setProfile(const oi::RobotProfile &profile)
{
    if (&profile == m_profile)
        return;
    m_profile = &profile;
    clear();
}

bool SensorHistory::isChannel(int packetId) const
{
    return packetId >= 0 && packetId <= oi::kMaxPacketId && m_profile->packet(packetId) != nullptr;
}

const SensorHistory::Channel *SensorHistory::channel(int packetId) const
{
    return isChannel(packetId) ? &m_channels[static_cast<std::size_t>(packetId)] : nullptr;
}

void SensorHistory::push(Channel &c, double t, std::int32_t value)
{
    if (c.size() < m_capacity) {
        if (c.size() == c.times.capacity()) {
            // Reserve exactly, never past the capacity, so memoryBytes() is
            // the bound the header promises.
            const std::size_t grown =
                std::min(m_capacity, std::max(kFirstBlock, c.times.capacity() * 2));
            c.times.reserve(grown);
            c.values.reserve(grown);
        }
        c.times.push_back(t);
        c.values.push_back(value);
    } else {
        c.times[c.start] = t;
        c.values[c.start] = value;
        c.start = c.start + 1 == m_capacity ? 0 : c.start + 1;
    }
    ++c.appended;
}

bool SensorHistory::append(double t, const oi::SensorSnapshot &snapshot)
{
    if (!std::isfinite(t) || (m_appendCount > 0 && t < m_newestTime))
        return false;
    for (const oi::PacketInfo &info : m_profile->packets())
        if (snapshot.has(info.id))
            push(m_channels[info.id], t, snapshot.raw(info.id));
    m_newestTime = t;
    ++m_appendCount;
    ++m_revision;
    return true;
}

void SensorHistory::clear()
{
    for (Channel &c : m_channels)
        c = Channel{}; // gives the memory back, not just the samples
    m_newestTime = 0.0;
    m_appendCount = 0;
    ++m_revision;
    ++m_generation;
}

double SensorHistory::oldestTime() const
{
    double oldest = std::numeric_limits<double>::infinity();
    for (const oi::PacketInfo &info : m_profile->packets()) {
        const Channel &c = m_channels[info.id];
        if (c.size() > 0)
            oldest = std::min(oldest, c.times[c.start]);
    }
    return std::isfinite(oldest) ? oldest : 0.0;
}

std::size_t SensorHistory::sampleCount(int packetId) const
{
    const Channel *c = channel(packetId);
    return c ? c->size() : 0;
}

std::uint64_t SensorHistory::appendCount(int packetId) const
{
    const Channel *c = channel(packetId);
    return c ? c->appended : 0;
}

SensorHistory::Sample SensorHistory::sample(int packetId, std::size_t index) const
{
    const Channel *c = channel(packetId);
    if (!c || index >= c->size())
        return {};
    const std::size_t p = c->physical(index, m_capacity);
    return {c->times[p], c->values[p]};
}

std::size_t SensorHistory::lowerBound(int packetId, double t) const
{
    const Channel *c = channel(packetId);
    if (!c)
        return 0;
    std::size_t lo = 0, hi = c->size();
    while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (c->times[c->physical(mid, m_capacity)] < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

std::size_t SensorHistory::upperBound(int packetId, double t) const
{
    const Channel *c = channel(packetId);
    if (!c)
        return 0;
    std::size_t lo = 0, hi = c->size();
    while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (c->times[c->physical(mid, m_capacity)] <= t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

std::vector<SensorHistory::Sample> SensorHistory::samples(int packetId, double t0, double t1) const
{
    std::vector<Sample> out;
    const Channel *c = channel(packetId);
    if (!c || !(t0 <= t1))
        return out;
    const std::size_t first = lowerBound(packetId, t0), end = upperBound(packetId, t1);
    if (end <= first)
        return out;
    out.reserve(end - first);
    for (std::size_t i = first; i < end; ++i) {
        const std::size_t p = c->physical(i, m_capacity);
        out.push_back({c->times[p], c->values[p]});
    }
    return out;
}

std::size_t SensorHistory::memoryBytes() const
{
    std::size_t bytes = 0;
    for (const Channel &c : m_channels)
        bytes += c.times.capacity() * sizeof(double) + c.values.capacity() * sizeof(std::int32_t);
    return bytes;
}

QString SensorHistory::formatTime(double t) { return QString::fromLatin1(timeText(t)); }

bool SensorHistory::exportCsv(const QString &path, const std::vector<int> &channels, double t0,
                              double t1, QString *error) const
{
    auto fail = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (channels.empty())
        return fail(QCoreApplication::translate("SensorHistory", "No channels to export."));
    if (std::isnan(t0) || std::isnan(t1))
        return fail(QCoreApplication::translate("SensorHistory", "The time range to export is not a number."));
    for (int id : channels)
        if (!isChannel(id))
            return fail(QCoreApplication::translate("SensorHistory", "Packet %1 is not a sensor packet of the %2.")
                            .arg(id)
                            .arg(QString::fromUtf8(m_profile->name.data(),
                                                   qsizetype(m_profile->name.size()))));

    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return fail(QCoreApplication::translate("SensorHistory", "Cannot write %1: %2").arg(path, file.errorString()));

    QByteArray buffer;
    buffer.reserve(kWriteChunk + 1024);
    buffer += "time_s";
    for (int id : channels) {
        const oi::PacketInfo *info = m_profile->packet(id);
        buffer += ',';
        buffer += QByteArray(info->key.data(), qsizetype(info->key.size()));
        if (!info->unit.empty()) {
            buffer += '[';
            buffer += QByteArray(info->unit.data(), qsizetype(info->unit.size()));
            buffer += ']';
        }
    }
    buffer += '\n';

    // A merge of the channels' sorted times: each row takes the earliest
    // time any channel has next, and every channel with a sample at exactly
    // that time fills its cell.
    const std::size_t n = channels.size();
    std::vector<std::size_t> next(n), end(n);
    for (std::size_t i = 0; i < n; ++i) {
        next[i] = t0 <= t1 ? lowerBound(channels[i], t0) : 0;
        end[i] = t0 <= t1 ? upperBound(channels[i], t1) : 0;
    }
    const double none = std::numeric_limits<double>::infinity();
    for (;;) {
        double rowTime = none;
        for (std::size_t i = 0; i < n; ++i)
            if (next[i] < end[i])
                rowTime = std::min(rowTime, sample(channels[i], next[i]).time);
        if (rowTime == none)
            break;
        buffer += timeText(rowTime);
        for (std::size_t i = 0; i < n; ++i) {
            buffer += ',';
            bool found = false;
            std::int32_t value = 0;
            // Two snapshots may share a time; the later one wins.
            while (next[i] < end[i]) {
                const Sample s = sample(channels[i], next[i]);
                if (s.time != rowTime)
                    break;
                value = s.value;
                found = true;
                ++next[i];
            }
            if (found)
                buffer += QByteArray::number(value);
        }
        buffer += '\n';
        if (buffer.size() >= kWriteChunk) {
            if (file.write(buffer) != buffer.size())
                return fail(QCoreApplication::translate("SensorHistory", "Cannot write %1: %2").arg(path, file.errorString()));
            buffer.clear();
        }
    }
    if (file.write(buffer) != buffer.size())
        return fail(QCoreApplication::translate("SensorHistory", "Cannot write %1: %2").arg(path, file.errorString()));
    if (!file.commit())
        return fail(QCoreApplication::translate("SensorHistory", "Cannot save %1: %2").arg(path, file.errorString()));
    return true;
}
