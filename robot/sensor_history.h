// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"
#include "sample_ring.h"
#include "sensor_csv.h"
#include "sensor_snapshot.h"

#include <QString>

#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <variant>
#include <vector>

// The recent values of every sensor packet, for plots and CSV export.
//
// Stored by frame: every append() with at least one packet is a frame, and
// the frames share one column of times. A channel (a single packet, id
// 7..58, of the profile) keeps its values in the narrowest type the packet
// table allows (one byte for bit fields and states, two for signals; a value
// outside the table's type widens that channel to four bytes, so nothing is
// lost), plus runs of the frames it was present in, which for a stream is a
// single run. One hour of group 100 at 66.7 Hz is then about 21 MB.
//
// The history holds the newest capacity() frames; older frames drop off with
// their values, so memory stays bounded however long the session runs.
// Times must not decrease, which lets every range query be a binary search.
//
// At a reduced rate (a robot nobody is looking at) every kReducedBlockFrames
// frames are kept as two: at the first and the last frame's time, each
// packet's minimum and maximum over the block, in the order they came, so
// a spike is never lost. Back at the full rate, new frames are kept whole
// again; what was reduced stays reduced.
//
// A plain value class on Qt Core and the standard library: no Qt objects,
// no signals. The session owns it and widgets read it from the GUI thread.
class SensorHistory {
public:
    struct Sample {
        double time = 0.0;
        std::int32_t value = 0;
        friend bool operator==(const Sample &, const Sample &) = default;
    };

    // One hour at the 15 ms stream period (66.7 Hz), in frames.
    static constexpr std::size_t kDefaultCapacity = 240'120;
    // At a reduced rate, this many frames become two.
    static constexpr int kReducedBlockFrames = 10;

    explicit SensorHistory(const oi::RobotProfile &profile = oi::profile(oi::ProfileId::Create2),
                           std::size_t capacity = kDefaultCapacity);

    // Switching to another profile clears the history: the same packet id
    // can mean another thing there (ERRATA 4, packets 43 and 44).
    void setProfile(const oi::RobotProfile &profile);
    const oi::RobotProfile &robotProfile() const { return *m_profile; }
    // Frames held at the most; no channel holds more samples than this.
    std::size_t capacity() const { return m_capacity; }

    // Records every packet `snapshot` carries at time `t` (seconds). Refuses
    // (records nothing, returns false) a time that is not finite or is older
    // than the newest time recorded.
    bool append(double t, const oi::SensorSnapshot &snapshot);
    void clear();

    // The reduced rate, for a robot that is not selected. Leaving it stores
    // the frames of the block in progress at once.
    void setReducedRate(bool reduced);
    bool isReducedRate() const { return m_reduced; }

    // Whether `packetId` is a channel: a single packet of the profile.
    bool isChannel(int packetId) const;
    bool isEmpty() const { return m_appendCount == 0; }
    // Newest time appended since the last clear; 0 when empty.
    double newestTime() const { return m_newestTime; }
    // Oldest time any channel still holds; 0 when none does.
    double oldestTime() const;
    // Frames held now (at most capacity()).
    std::size_t frameCount() const { return m_times.size(); }

    // Samples the channel holds now (at most capacity()).
    std::size_t sampleCount(int packetId) const;
    // Samples ever stored in the channel since the last clear. Readers that
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
    // The samples with index first <= i < end, oldest first.
    std::vector<Sample> samplesAt(int packetId, std::size_t first, std::size_t end) const;

    // Bumped by every append and clear, so a reader can skip work when
    // nothing changed. generation() changes only on clear.
    std::uint64_t revision() const { return m_revision; }
    std::uint64_t generation() const { return m_generation; }

    // Bytes the history has allocated for its frames: the time column, the
    // channels' values and their runs.
    std::size_t memoryBytes() const;

    // Writes the channels' samples with t0 <= time <= t1 as CSV, with
    // QSaveFile so a failed export leaves any existing file untouched.
    // Header: time_s, then <packet key>[unit] per channel (no brackets where
    // the packet has no unit). One row per distinct time; a channel without
    // a sample at that time leaves its cell empty. On failure returns false
    // and, if `error` is given, says why. With `marks` (in time order), the
    // ones between t0 and t1 fill a last column, `marker` (SensorCsv).
    bool exportCsv(const QString &path, const std::vector<int> &channels, double t0, double t1,
                   QString *error = nullptr, const QList<oilink::SensorCsv::Mark> &marks = {}) const;

    // Time as the CSV writes it: up to microseconds, without trailing zeros.
    static QString formatTime(double t);

private:
    // Consecutive frames a channel was present in.
    struct Run {
        std::uint64_t frame = 0;  // sequence number of the first frame
        std::uint64_t sample = 0; // the channel's sequence number of its first sample
        std::uint64_t count = 0;
    };
    using Values = std::variant<SampleRing<std::int8_t>, SampleRing<std::uint8_t>,
                                SampleRing<std::int16_t>, SampleRing<std::uint16_t>,
                                SampleRing<std::int32_t>>;
    struct Channel {
        Values values;
        std::deque<Run> runs; // cover exactly the samples held, oldest first
        std::uint64_t appended = 0;

        std::size_t size() const;
        std::int32_t value(std::size_t index) const;
        // Sequence number of the frame that holds sample `index`.
        std::uint64_t frameOf(std::size_t index) const;
    };
    // The frames of a block at the reduced rate, folded as they come.
    struct Block {
        struct Extremes {
            std::int32_t min = 0, max = 0;
            int minAt = 0, maxAt = 0; // frame of the block each came in
        };
        int frames = 0;
        double firstTime = 0.0, lastTime = 0.0;
        std::uint64_t present = 0; // bit per packet id
        std::array<Extremes, oi::kMaxPacketId + 1> extremes{};
    };

    const Channel *channel(int packetId) const;
    template <typename Before>
    std::size_t firstNotBefore(int packetId, Before before) const;
    double timeOfFrame(std::uint64_t frame) const { return m_times[std::size_t(frame - m_firstFrame)]; }
    // Stores one frame of packet values; `value(id)` is read for each id in `present`.
    template <typename ValueOf>
    void storeFrame(double t, std::uint64_t present, ValueOf value);
    void dropOldestFrame();
    void foldIntoBlock(double t, const oi::SensorSnapshot &snapshot);
    void storeBlock();
    void resetChannels();

    const oi::RobotProfile *m_profile;
    std::size_t m_capacity;
    SampleRing<double> m_times;
    std::uint64_t m_firstFrame = 0; // sequence number of m_times[0]
    std::array<Channel, oi::kMaxPacketId + 1> m_channels;
    bool m_reduced = false;
    Block m_block;
    double m_newestTime = 0.0;
    std::uint64_t m_appendCount = 0;
    std::uint64_t m_revision = 0;
    std::uint64_t m_generation = 0;
};
