// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "sensor_snapshot.h"

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

namespace oi {

enum class FrameKind : std::uint8_t { Stream, Reply };

// A byte of the robot's text: printable ASCII or a tab (CR and LF end lines).
constexpr bool isTextByte(std::uint8_t b) { return (b >= 0x20 && b < 0x7F) || b == '\t'; }

struct ParserCounters {
    std::uint64_t framesGood = 0;       // stream frames decoded
    std::uint64_t repliesGood = 0;      // 142 / 149 replies decoded
    std::uint64_t checksumFailures = 0; // candidate frames whose sum was not 0
    std::uint64_t lengthMismatches = 0; // n-bytes impossible, or disagreeing with the packets
    std::uint64_t bytesDiscarded = 0;   // bytes that belonged to no good frame, reply or text line
    std::uint64_t textBytes = 0;        // printable lines between frames (the robot's own words), ends included
    std::uint64_t textLines = 0;
    friend bool operator==(const ParserCounters &, const ParserCounters &) = default;
};

// Incremental parser for what the robot sends: stream frames (opcode 148)
// and the unframed replies to Sensors (142) and Query List (149).
//
// ERRATA 1: the checksum covers the header byte.
// ERRATA 2: after a bad length or checksum, scanning resumes at the byte
//   after the failed header, so a real frame after junk or a stray 19 is
//   never lost.
// ERRATA 3: replies carry no framing; their length comes from the packet
//   table, so the caller announces each request with expectReply().
//
// Text: between frames a docked Roomba 500 / 600 prints its charging status
//   ("bat:   min 0  sec 12  mV 16421 ..."), and Reset prints a banner. A run
//   of at least kMinTextLine printable characters ended by CR or LF, outside
//   any frame or reply, is such a line: it goes to the text handler and
//   counts as text, not as discarded. Byte 19 is not printable, so text
//   never hides a frame's header. The robot writes a line whole, between
//   frames: printable bytes cut short by a frame or reply are discarded.
//
// The parser keeps a fixed buffer and allocates nothing per byte.
class StreamParser {
public:
    enum class ChecksumMode : std::uint8_t {
        IncludeHeader,       // what real robots do (ERRATA 1); the default
        LegacyExcludeHeader, // what two of the documents' examples show
    };
    using SnapshotHandler = std::function<void(const SensorSnapshot &, FrameKind)>;
    // A line of text from the robot, without its CR / LF.
    using TextHandler = std::function<void(std::string_view line)>;
    static constexpr std::size_t kMinTextLine = 4;
    static constexpr std::size_t kMaxTextLine = 160; // longer runs are not the robot's lines

    explicit StreamParser(const RobotProfile &profile = oi::profile(ProfileId::Create2));

    void setProfile(const RobotProfile &profile);
    const RobotProfile &robotProfile() const { return *m_profile; }
    void setChecksumMode(ChecksumMode mode) { m_checksumMode = mode; }
    void setSnapshotHandler(SnapshotHandler handler) { m_handler = std::move(handler); }
    void setTextHandler(TextHandler handler) { m_textHandler = std::move(handler); }

    // The packet list the stream was started with. With it, a frame whose
    // n-bytes or packet ids disagree is refused at once; without it, any
    // well-formed frame is accepted, and a stray 19 holds the frames after it
    // until its claimed n-bytes have arrived (they are delayed, not lost).
    // Returns false for an id the profile lacks.
    bool setExpectedStream(std::span<const std::uint8_t> packetIds);
    void clearExpectedStream();
    // Where frames end, not what they say: with an expected stream, a stream
    // frame is checked (checksum, length, each id in its place) but its values
    // are not decoded, and the handler is given an empty snapshot. For
    // indexing a recording, which is read for its frames' ends only.
    void setFramesOnly(bool on) { m_framesOnly = on; }

    // Announces `times` replies to a Sensors or Query List request for these
    // ids. Bytes that arrive while a reply is pending are read as that reply
    // once they are whole and consistent: every value in its packet's range
    // (a mode up to 4, for robots that report it one high). Lines of text
    // the robot printed before or among them are taken out; a byte that is
    // neither is discarded, and the reply still awaited.
    // Returns false (and expects nothing) for an id the profile lacks.
    bool expectReply(std::span<const std::uint8_t> packetIds, std::size_t times = 1);
    void cancelReplies() { m_replies.clear(); }
    std::size_t pendingReplies() const;

    void feed(std::span<const std::uint8_t> bytes);
    // The end of the input: no more bytes will come. A frame still waiting
    // for its rest was a stray 19, so the bytes held behind it are scanned
    // again from the byte after it, and frames among them come out. What is
    // left is discarded; an unfinished reply stays pending.
    void finish();

    // While a handler runs: how many bytes fed (since construction or
    // reset()) end with the frame or reply it is given, so that a reader of
    // a long run of bytes knows where each frame ends without feeding them
    // one at a time.
    std::uint64_t frameEndOffset() const { return m_frameEnd; }

    const ParserCounters &counters() const { return m_counters; }
    // Bytes held while waiting for the rest of a frame or reply.
    std::size_t pendingBytes() const { return m_length; }
    // Printable bytes outside frames held until a line end shows whether
    // they are text (or a non-printable byte shows they are not).
    std::size_t pendingTextBytes() const { return m_textLength; }
    // Forgets buffered bytes, pending replies and counters.
    void reset();

private:
    struct PendingReply {
        std::vector<std::uint8_t> ids;
        std::size_t bytes = 0;
        std::size_t times = 0;
    };

    std::size_t process();
    // Bytes outside any frame or reply: text lines, or discarded.
    void skip(std::span<const std::uint8_t> bytes);
    void dropPendingText();
    bool decodePayload(std::span<const std::uint8_t> payload);
    // Decodes into m_scratch; true when every value is one the robot can send.
    bool readsAsReply(const PendingReply &reply, std::span<const std::uint8_t> data);
    // The length of a whole line of text (and its line ends) that `bytes` starts with, or 0.
    std::size_t textLineAt(std::span<const std::uint8_t> bytes) const;
    // One pending reply from the buffer at `pos`: true when it was read
    // (or bytes were set aside as text or junk), false to wait for more.
    bool takeReply(std::size_t &pos);
    std::vector<std::uint8_t> m_replyBytes; // a reply without the text among it, reused
    std::size_t payloadSize(std::span<const std::uint8_t> packetIds) const;

    static constexpr std::size_t kCapacity = 32 * 1024; // fits the largest 149 reply and a frame

    const RobotProfile *m_profile;
    ChecksumMode m_checksumMode = ChecksumMode::IncludeHeader;
    SnapshotHandler m_handler;
    TextHandler m_textHandler;
    std::vector<std::uint8_t> m_expectedIds;
    std::vector<std::size_t> m_expectedOffsets; // of each expected id in the payload
    bool m_framesOnly = false;
    int m_expectedLength = -1; // n-bytes of the expected stream, -1 = any
    std::deque<PendingReply> m_replies;
    ParserCounters m_counters;
    SensorSnapshot m_scratch;
    std::size_t m_length = 0;
    std::uint64_t m_fed = 0;      // bytes fed; the buffer holds the last m_length of them
    std::uint64_t m_frameEnd = 0; // see frameEndOffset()
    std::array<std::uint8_t, kCapacity> m_buffer{};
    std::array<char, kMaxTextLine> m_text{};
    std::size_t m_textLength = 0;
    bool m_afterLine = false; // the last byte skipped ended a text line: CR LF and blank lines are text too
};

// `bytes` without the robot's lines of text, read as StreamParser reads
// them (and the line ends after them): for a reader waiting for an unframed
// reply while a docked robot prints its charging status.
std::vector<std::uint8_t> withoutTextLines(std::span<const std::uint8_t> bytes);

} // namespace oi
