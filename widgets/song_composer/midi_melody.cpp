// SPDX-License-Identifier: GPL-3.0-or-later
#include "midi_melody.h"
#include "midi_file_check.h"

#include "bounded_file.h"

#include <QCoreApplication>

#include <smf.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace {

struct HeardNote {
    int pitch = 0;
    double start = 0.0;
    double end = -1.0; // -1 while still sounding
};

} // namespace

std::optional<QList<oi::SongNote>> melodyFromMidiFile(const QString &path, int *shortened,
                                                      QString *error)
{
    auto fail = [error, &path](const QString &why) {
        if (error)
            *error = QCoreApplication::translate("MidiMelody", "Could not import %1: %2").arg(path, why);
        return std::nullopt;
    };
    // A melody is a few kilobytes; a whole orchestral score rarely 1 MB.
    constexpr qint64 kMaxBytes = 8 << 20;
    QString why;
    const std::optional<QByteArray> read = files::readBounded(path, kMaxBytes, &why);
    if (!read)
        return fail(why);
    const QByteArray &bytes = *read;
    if (!isWellFormedMidiFile(bytes))
        return fail(QCoreApplication::translate("MidiMelody", "not a readable Standard MIDI File"));
    std::unique_ptr<smf_t, decltype(&smf_delete)> smf(smf_load_from_memory(bytes.constData(), int(bytes.size())),
                                                      &smf_delete);
    if (!smf)
        return fail(QCoreApplication::translate("MidiMelody", "not a readable Standard MIDI File"));

    std::vector<HeardNote> heard;
    while (smf_event_t *event = smf_get_next_event(smf.get())) {
        if (smf_event_is_metadata(event) || event->midi_buffer_length < 3)
            continue;
        const int status = event->midi_buffer[0] & 0xf0, channel = event->midi_buffer[0] & 0x0f;
        const int pitch = event->midi_buffer[1], velocity = event->midi_buffer[2];
        if (channel == 9) // percussion has no melody
            continue;
        const bool on = status == 0x90 && velocity > 0;
        const bool off = status == 0x80 || (status == 0x90 && velocity == 0);
        if (on) {
            heard.push_back({pitch, event->time_seconds, -1.0});
        } else if (off) {
            for (auto it = heard.rbegin(); it != heard.rend(); ++it) {
                if (it->pitch == pitch && it->end < 0) {
                    it->end = event->time_seconds;
                    break;
                }
            }
        }
    }
    if (heard.empty())
        return fail(QCoreApplication::translate("MidiMelody", "it has no notes"));
    const double songEnd = smf_get_length_seconds(smf.get());
    for (HeardNote &n : heard)
        if (n.end < 0)
            n.end = std::max(songEnd, n.start);

    // Onsets closer than half a 1/64 s tick count as one chord.
    std::stable_sort(heard.begin(), heard.end(),
                     [](const HeardNote &a, const HeardNote &b) { return a.start < b.start; });
    constexpr double chordWindow = 0.5 / 64.0;
    std::vector<HeardNote> melody;
    for (std::size_t i = 0; i < heard.size();) {
        std::size_t j = i;
        HeardNote top = heard[i];
        while (j < heard.size() && heard[j].start - heard[i].start < chordWindow) {
            if (heard[j].pitch > top.pitch)
                top = heard[j];
            ++j;
        }
        top.start = heard[i].start;
        melody.push_back(top);
        i = j;
    }

    QList<oi::SongNote> notes;
    int cut = 0;
    auto add = [&](int midi, double seconds) {
        long d64 = std::lround(seconds * 64.0);
        while (midi == oi::kRestNote && d64 > 255) { // long rests become several rests
            notes.append({std::uint8_t(midi), 255});
            d64 -= 255;
        }
        if (d64 > 255) {
            d64 = 255;
            ++cut;
        }
        if (d64 > 0)
            notes.append({std::uint8_t(midi), std::uint8_t(d64)});
    };
    double clock = melody.front().start; // silence before the first note is left out
    for (std::size_t i = 0; i < melody.size(); ++i) {
        const double nextStart = i + 1 < melody.size() ? melody[i + 1].start : melody[i].end;
        if (melody[i].start > clock)
            add(oi::kRestNote, melody[i].start - clock);
        const double end = std::min(melody[i].end, nextStart);
        const int midi = melody[i].pitch >= oi::kLowestNote ? melody[i].pitch : oi::kRestNote;
        add(midi, end - melody[i].start);
        clock = std::max(clock, end);
    }
    if (shortened)
        *shortened = cut;
    if (notes.isEmpty())
        return fail(QCoreApplication::translate("MidiMelody", "its notes are all shorter than 1/64 s"));
    return notes;
}
