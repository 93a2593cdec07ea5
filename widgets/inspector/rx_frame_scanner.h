// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "robot_profile.h"

#include <QByteArray>
#include <QString>
#include <QtGlobal>

#include <cstdint>
#include <deque>
#include <span>
#include <vector>

// Cuts the bytes a robot sends into pieces a person can read: stream frames
// ([19][n][id data]...[checksum], checked as the parser checks them),
// replies to the Sensors and Query List requests it was told about, text
// (the reset banner), and whatever else is left.
//
// For display only: the link's StreamParser decides what the session sees.
// A frame may arrive split across reads, so the scanner holds back the bytes
// of a frame or reply that has begun but not ended (at most kMaxHeld).
class RxFrameScanner {
public:
    enum class Kind : std::uint8_t { StreamFrame, Reply, Text, Bytes };
    struct Piece {
        Kind kind = Kind::Bytes;
        QByteArray bytes;
        // What it says, in words: made when a reader shows it (describe()),
        // since a log nobody looks at keeps many frames a second.
        QString meaning;
        const oi::RobotProfile *profile = nullptr;
        std::vector<std::uint8_t> replyIds; // the request a reply answers
    };
    // Fills in piece.meaning if it is not there yet.
    static void describe(Piece &piece);

    static constexpr qsizetype kMaxHeld = 32 * 1024;
    // A reply comes within a few milliseconds; an expectation older than
    // this (by the timestamps given) is dropped rather than misreading later
    // bytes as its answer.
    static constexpr qint64 kReplyTimeoutMs = 1000;

    explicit RxFrameScanner(const oi::RobotProfile &profile = oi::profile(oi::ProfileId::Create2))
        : m_profile(&profile) {}
    void setProfile(const oi::RobotProfile &profile);

    // A Sensors (142) or Query List (149) request for these ids went out at
    // `msecs`; the next bytes that are no stream frame are read as its reply.
    void expectReply(std::vector<std::uint8_t> ids, qint64 msecs);
    std::vector<Piece> feed(std::span<const std::uint8_t> bytes, qint64 msecs);
    // Bytes held back waiting for the rest of a frame or reply.
    qsizetype heldBytes() const { return m_held.size(); }
    void reset();

private:
    enum class Match : std::uint8_t { No, Yes, NeedMore };
    struct Expectation {
        std::vector<std::uint8_t> ids;
        std::size_t bytes = 0;
        qint64 msecs = 0;
    };

    Match matchFrame(std::span<const std::uint8_t> at, std::size_t *length) const;
    Piece otherPiece(std::span<const std::uint8_t> bytes) const;

    const oi::RobotProfile *m_profile;
    QByteArray m_held;
    std::deque<Expectation> m_replies;
};
