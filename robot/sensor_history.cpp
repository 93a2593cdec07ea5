// SPDX-License-Identifier: GPL-3.0-or-later
#include "sensor_history.h"

#include "sensor_csv.h"

#include <QByteArray>
#include <QCoreApplication>
#include <QSaveFile>

#include <algorithm>
#include <iterator>
#include <cmath>
#include <limits>

namespace {

// Export writes in pieces of about this size rather than building the whole
// file (an hour of every channel is tens of megabytes) in memory.
constexpr qsizetype kWriteChunk = 64 * 1024;

template <typename T>
bool fits(std::int32_t value)
{
    return value >= std::numeric_limits<T>::min() && value <= std::numeric_limits<T>::max();
}

} // namespace

std::size_t SensorHistory::Channel::size() const
{
    return std::visit([](const auto &ring) { return ring.size(); }, values);
}

std::int32_t SensorHistory::Channel::value(std::size_t index) const
{
    return std::visit([index](const auto &ring) { return std::int32_t(ring[index]); }, values);
}

std::uint64_t SensorHistory::Channel::frameOf(std::size_t index) const
{
    const std::uint64_t seq = appended - size() + index;
    // A stream is one run; a packet that came and went has a few.
    auto run = runs.begin();
    if (runs.size() > 1)
        run = std::prev(std::upper_bound(runs.begin(), runs.end(), seq,
                                         [](std::uint64_t s, const Run &r) { return s < r.sample; }));
    return run->frame + (seq - run->sample);
}

SensorHistory::SensorHistory(const oi::RobotProfile &profile, std::size_t capacity)
    : m_profile(&profile), m_capacity(std::max<std::size_t>(capacity, 1))
{
    resetChannels();
}

void SensorHistory::setProfile(const oi::RobotProfile &profile)
{
    if (&profile == m_profile)
        return;
    m_profile = &profile;
    clear();
}

void SensorHistory::resetChannels()
{
    for (std::size_t id = 0; id < m_channels.size(); ++id) {
        Channel &c = m_channels[id];
        c = Channel{}; // gives the memory back, not just the samples
        // The narrowest type that holds the packet table's range.
        const oi::PacketInfo *info = m_profile->packet(int(id));
        if (!info)
            continue;
        if (info->min >= 0 && info->max <= 255)
            c.values = SampleRing<std::uint8_t>();
        else if (info->min >= -128 && info->max <= 127)
            c.values = SampleRing<std::int8_t>();
        else if (info->min >= 0 && info->max <= 65535)
            c.values = SampleRing<std::uint16_t>();
        else if (info->min >= -32768 && info->max <= 32767)
            c.values = SampleRing<std::int16_t>();
        else
            c.values = SampleRing<std::int32_t>();
    }
}

bool SensorHistory::isChannel(int packetId) const
{
    return packetId >= 0 && packetId <= oi::kMaxPacketId && m_profile->packet(packetId) != nullptr;
}

const SensorHistory::Channel *SensorHistory::channel(int packetId) const
{
    return isChannel(packetId) ? &m_channels[static_cast<std::size_t>(packetId)] : nullptr;
}

template <typename ValueOf>
void SensorHistory::storeFrame(double t, std::uint64_t present, ValueOf valueOf)
{
    if (present == 0)
        return;
    if (m_times.size() == m_capacity)
        dropOldestFrame();
    const std::uint64_t frame = m_firstFrame + m_times.size();
    m_times.push(t, m_capacity);
    for (const oi::PacketInfo &info : m_profile->packets()) {
        if (!((present >> info.id) & 1u))
            continue;
        Channel &c = m_channels[info.id];
        const std::int32_t value = valueOf(info.id);
        const bool narrow = std::visit(
            [value](const auto &ring) { return fits<typename std::decay_t<decltype(ring)>::value_type>(value); },
            c.values);
        if (!narrow) // a value the packet table does not allow: kept whole all the same
            c.values = std::visit([this](const auto &ring) { return ring.template convertedTo<std::int32_t>(m_capacity); },
                                  c.values);
        std::visit([&](auto &ring) { ring.push(typename std::decay_t<decltype(ring)>::value_type(value), m_capacity); },
                   c.values);
        if (!c.runs.empty() && c.runs.back().frame + c.runs.back().count == frame)
            ++c.runs.back().count;
        else
            c.runs.push_back({frame, c.appended, 1});
        ++c.appended;
    }
}

void SensorHistory::dropOldestFrame()
{
    const std::uint64_t frame = m_firstFrame;
    m_times.popFront();
    ++m_firstFrame;
    for (const oi::PacketInfo &info : m_profile->packets()) {
        Channel &c = m_channels[info.id];
        if (c.runs.empty() || c.runs.front().frame != frame)
            continue;
        std::visit([](auto &ring) { ring.popFront(); }, c.values);
        Run &run = c.runs.front();
        ++run.frame;
        ++run.sample;
        if (--run.count == 0)
            c.runs.pop_front();
    }
}

bool SensorHistory::append(double t, const oi::SensorSnapshot &snapshot)
{
    if (!std::isfinite(t) || (m_appendCount > 0 && t < m_newestTime))
        return false;
    if (m_reduced) {
        foldIntoBlock(t, snapshot);
    } else {
        std::uint64_t present = 0;
        for (const oi::PacketInfo &info : m_profile->packets())
            if (snapshot.has(info.id))
                present |= std::uint64_t{1} << info.id;
        storeFrame(t, present, [&snapshot](int id) { return snapshot.raw(id); });
    }
    m_newestTime = t;
    ++m_appendCount;
    ++m_revision;
    return true;
}

void SensorHistory::foldIntoBlock(double t, const oi::SensorSnapshot &snapshot)
{
    Block &b = m_block;
    if (b.frames == 0) {
        b.firstTime = t;
        b.present = 0;
    }
    for (const oi::PacketInfo &info : m_profile->packets()) {
        if (!snapshot.has(info.id))
            continue;
        const std::int32_t v = snapshot.raw(info.id);
        const std::uint64_t bit = std::uint64_t{1} << info.id;
        Block::Extremes &e = b.extremes[info.id];
        if (!(b.present & bit)) {
            e = {v, v, b.frames, b.frames};
            b.present |= bit;
            continue;
        }
        if (v < e.min) {
            e.min = v;
            e.minAt = b.frames;
        }
        if (v > e.max) {
            e.max = v;
            e.maxAt = b.frames;
        }
    }
    b.lastTime = t;
    if (++b.frames == kReducedBlockFrames)
        storeBlock();
}

void SensorHistory::storeBlock()
{
    Block &b = m_block;
    if (b.frames == 1) {
        storeFrame(b.firstTime, b.present, [&b](int id) { return b.extremes[id].min; });
    } else if (b.frames > 1) {
        auto earlier = [&b](int id) {
            const Block::Extremes &e = b.extremes[id];
            return e.minAt <= e.maxAt ? e.min : e.max;
        };
        auto later = [&b](int id) {
            const Block::Extremes &e = b.extremes[id];
            return e.minAt <= e.maxAt ? e.max : e.min;
        };
        storeFrame(b.firstTime, b.present, earlier);
        storeFrame(b.lastTime, b.present, later);
    }
    b.frames = 0;
}

void SensorHistory::setReducedRate(bool reduced)
{
    if (reduced == m_reduced)
        return;
    if (!reduced && m_block.frames > 0) {
        storeBlock();
        ++m_revision;
    }
    m_reduced = reduced;
}

void SensorHistory::clear()
{
    resetChannels();
    m_times.release();
    m_firstFrame = 0;
    m_block.frames = 0;
    m_newestTime = 0.0;
    m_appendCount = 0;
    ++m_revision;
    ++m_generation;
}

double SensorHistory::oldestTime() const
{
    // Every frame held has at least one sample.
    return m_times.empty() ? 0.0 : m_times.front();
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
    return {timeOfFrame(c->frameOf(index)), c->value(index)};
}

// The index of the channel's first sample whose time is not `before` t: a
// binary search, since times never decrease.
template <typename Before>
std::size_t SensorHistory::firstNotBefore(int packetId, Before before) const
{
    const Channel *c = channel(packetId);
    if (!c)
        return 0;
    std::size_t lo = 0, hi = c->size();
    while (lo < hi) {
        const std::size_t mid = lo + (hi - lo) / 2;
        if (before(timeOfFrame(c->frameOf(mid))))
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

std::size_t SensorHistory::lowerBound(int packetId, double t) const
{
    return firstNotBefore(packetId, [t](double time) { return time < t; });
}

std::size_t SensorHistory::upperBound(int packetId, double t) const
{
    return firstNotBefore(packetId, [t](double time) { return time <= t; });
}

std::vector<SensorHistory::Sample> SensorHistory::samples(int packetId, double t0, double t1) const
{
    if (!(t0 <= t1))
        return {};
    return samplesAt(packetId, lowerBound(packetId, t0), upperBound(packetId, t1));
}

std::vector<SensorHistory::Sample> SensorHistory::samplesAt(int packetId, std::size_t first,
                                                            std::size_t end) const
{
    std::vector<Sample> out;
    const Channel *c = channel(packetId);
    if (!c)
        return out;
    end = std::min(end, c->size());
    if (end <= first)
        return out;
    out.reserve(end - first);
    // Walks the runs alongside rather than searching them for every sample.
    const std::uint64_t base = c->appended - c->size();
    auto run = c->runs.begin();
    std::visit(
        [&](const auto &ring) {
            for (std::size_t i = first; i < end; ++i) {
                const std::uint64_t seq = base + i;
                while (seq >= run->sample + run->count)
                    ++run;
                out.push_back({timeOfFrame(run->frame + (seq - run->sample)), std::int32_t(ring[i])});
            }
        },
        c->values);
    return out;
}

std::size_t SensorHistory::memoryBytes() const
{
    std::size_t bytes = m_times.bytes();
    for (const Channel &c : m_channels)
        bytes += std::visit([](const auto &ring) { return ring.bytes(); }, c.values)
            + c.runs.size() * sizeof(Run);
    return bytes;
}

QString SensorHistory::formatTime(double t) { return QString::fromLatin1(oilink::SensorCsv::timeText(t)); }

bool SensorHistory::exportCsv(const QString &path, const std::vector<int> &channels, double t0,
                              double t1, QString *error, const QList<oilink::SensorCsv::Mark> &marks) const
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

    std::vector<const oi::PacketInfo *> columns;
    for (int id : channels)
        columns.push_back(m_profile->packet(id));
    QList<oilink::SensorCsv::Mark> shown;
    for (const oilink::SensorCsv::Mark &m : marks)
        if (m.seconds >= t0 && m.seconds <= t1)
            shown << m;
    oilink::SensorCsv csv(std::move(columns), shown);
    QByteArray buffer;
    buffer.reserve(kWriteChunk + 1024);
    csv.appendHeader(buffer);

    // A merge of the channels' sorted times: each row takes the earliest
    // time any channel has next, and every channel with a sample at exactly
    // that time fills its cell.
    const std::size_t n = channels.size();
    std::vector<std::size_t> next(n), end(n);
    for (std::size_t i = 0; i < n; ++i) {
        next[i] = t0 <= t1 ? lowerBound(channels[i], t0) : 0;
        end[i] = t0 <= t1 ? upperBound(channels[i], t1) : 0;
    }
    std::vector<std::optional<std::int32_t>> cells(n);
    const double none = std::numeric_limits<double>::infinity();
    for (;;) {
        double rowTime = none;
        for (std::size_t i = 0; i < n; ++i)
            if (next[i] < end[i])
                rowTime = std::min(rowTime, sample(channels[i], next[i]).time);
        if (rowTime == none)
            break;
        for (std::size_t i = 0; i < n; ++i) {
            cells[i].reset();
            // Two snapshots may share a time; the later one wins.
            while (next[i] < end[i]) {
                const Sample s = sample(channels[i], next[i]);
                if (s.time != rowTime)
                    break;
                cells[i] = s.value;
                ++next[i];
            }
        }
        csv.appendRow(buffer, rowTime, cells);
        if (buffer.size() >= kWriteChunk) {
            if (file.write(buffer) != buffer.size())
                return fail(QCoreApplication::translate("SensorHistory", "Cannot write %1: %2").arg(path, file.errorString()));
            buffer.clear();
        }
    }
    csv.finish(buffer);
    if (file.write(buffer) != buffer.size())
        return fail(QCoreApplication::translate("SensorHistory", "Cannot write %1: %2").arg(path, file.errorString()));
    if (!file.commit())
        return fail(QCoreApplication::translate("SensorHistory", "Cannot save %1: %2").arg(path, file.errorString()));
    return true;
}
