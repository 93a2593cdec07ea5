// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual robot's songs: Song (140) stores one, Play (141) starts it.
#include "virtual_robot.h"

#include "virtual_robot_state.h"

namespace sim {

using oi::Command;

bool VirtualRobot::State::songCommand(const oi::OiCommand &c)
{
    const std::vector<int> &f = c.fields;
    switch (c.command) {
    case Command::Song:
        storeSong(c);
        return true;
    case Command::Play:
        // The Create's document: Play does nothing while a song is
        // playing. The Roomba models start the new song.
        if (const auto slot = std::size_t(f[0]);
            slot < songs.size() && songs[slot] && !(caps().playWaitsForSong && songPlaying())) {
            songNumber = f[0];
            songEndsAt = now + Microseconds(std::int64_t(songs[slot]->totalDuration64()) * 15625);
        }
        return true;
    default:
        return false;
    }
}

void VirtualRobot::State::storeSong(const oi::OiCommand &c)
{
    const std::size_t slot = std::size_t(c.fields[0]), notes = c.data.size() / 2;
    if (slot >= songs.size() || notes < 1 || notes > std::size_t(oi::kMaxSongNotes))
        return;
    oi::Song song;
    for (std::size_t i = 0; i < notes; ++i)
        song.notes.push_back({c.data[2 * i], c.data[2 * i + 1]});
    songs[slot] = std::move(song);
}

// --- The public face ---

std::optional<oi::Song> VirtualRobot::song(int slot) const
{
    if (slot < 0 || std::size_t(slot) >= m_state->songs.size())
        return std::nullopt;
    return m_state->songs[std::size_t(slot)];
}

bool VirtualRobot::songPlaying() const { return m_state->songPlaying(); }

bool VirtualRobot::sounding() const { return m_state->sounding(); }

} // namespace sim
