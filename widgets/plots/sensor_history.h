// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"
#include "sensor_snapshot.h"

#include <QString>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

// The recent values of every sensor packet, for plots and CSV export.
//
// One ring buffer per channel (a channel is a single packet, id 7..58, of the
// profile), each holding up to capacity() samples of (time in seconds, value).
// A channel allocates on its first sample and grows until it holds
// capacity() samples; from then on the oldest sample is overwritten, so memory
// stays bounded however long the session runs. Times must not decrease, which
// lets every range query be a binary search.
//
// A plain value class: no Qt objects, no signals. The session owns it and
// widgets read it from the GUI thread.
class SensorHistory {
public:
    struct Sample {
        double time = 0.0;
        std::int32_t value = 0;
        friend bool operator==(const Sample &, const Sample &) = default;
    };

    // One hour at the 15 ms stream period (66.7 Hz).
    static constexpr std::size_t kDefaultCapacity = 240'120;
    static constexpr std::size_t kBytesPerSample = sizeof(double) + sizeof(std::int32_t);

    explicit SensorHistory(const oi::RobotProfile &profile = oi::profile(oi::ProfileId::Create2),
                           std::size_t capacity = kDefaultCapacity);

    // Switching to another profile clears the history: the same packet id
    // can mean another thing there (ERRATA 4, packets 43 and 44).
    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &robotProfile() const { return *m_profile; }
    std::size_t capacity() const { return m_capacity; }

    // Records every packet `snapshot` carries at time `t` (seconds). Refuses
    // (records nothing, returns false) a time that is not finite or is older
    // than the newest time recorded.
    bool append(double t, const oi::SensorSnapshot &snapshot);
    void clear();

    // Whether `packetId` is a channel: a single packet of the profile.
    bool isChannel(int packetId) const;
    bool isEmpty() const { return m_appendCount == 0; }
    // Newest time appended since the last clear; 0 when empty.
    double newestTime() const { return m_newestTime; }
    // Oldest time any channel still holds; 0 when empty.
    double oldestTime() const;

    // Samples the channel holds now (at most capacity()).
    std::size_t sampleCount(int packetId) const;
    // Samples ever appended to the channel since the last clear. Readers that
    // keep a copy compare it to see how many samples are new.
    std::uint64_t appendCount(int packetId) const;
    // Sample `index` of the channel, 0 being the oldest held.
    Sample sample(int packetId, std::size_t index) const;
    // Index of the first sample with time >= t (lowerBound) or > t
    // (upperBound); sampleCount() if there is none. Binary searches.
    std::size_t lowerBound(int packetId, double t) const;
    std::size_t upperBound(int packetId, double t) const;
    // The samples with t0 <= time <= t1, oldest first.
    std::vector<Sample> samples(int packetId, double t0, double t1) const;

    // Bumped by every append and clear, so a reader can skip work when
    // nothing changed. generation() changes only on clear.
    std::uint64_t revision() const { return m_revision; }
    std::uint64_t generation() const { return m_generation; }

    // Bytes the sample buffers hold: at most
    // channels x capacity() x kBytesPerSample.
    std::size_t memoryBytes() const;

    // Writes the channels' samples with t0 <= time <= t1 as CSV, with
    // QSaveFile so a failed export leaves any existing file untouched.
    // Header: time_s, then <packet key>[unit] per channel (no brackets where
    // the packet has no unit). One row per distinct time; a channel without
    // a sample at that time leaves its cell empty. On failure returns false
    // and, if `error` is given, says why.
    bool exportCsv(const QString &path, const std::vector<int> &channels, double t0, double t1,
                   QString *error = nullptr) const;

    // Time as the CSV writes it: up to microseconds, without trailing zeros.
    static QString formatTime(double t);

private:
    struct Channel {
        std::vector<double> times;
        std::vector<std::int32_t> values;
        std::size_t start = 0; // physical index of the oldest sample once full
        std::uint64_t appended = 0;

        std::size_t size() const { return times.size(); }
        std::size_t physical(std::size_t index, std::size_t capacity) const
        {
            const std::size_t p = start + index;
            return p >= capacity ? p - capacity : p;
        }
    };

    const Channel *channel(int packetId) const;
    void push(Channel &c, double t, std::int32_t value);

    const oi::RobotProfile *m_profile;
    std::size_t m_capacity;
    std::array<Channel, oi::kMaxPacketId + 1> m_channels;
    double m_newestTime = 0.0;
    std::uint64_t m_appendCount = 0;
    std::uint64_t m_revision = 0;
    std::uint64_t m_generation = 0;
};
