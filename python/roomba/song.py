# SPDX-License-Identifier: GPL-3.0-or-later
"""Song text as `roomba-ctl encode song` reads it: NOTE:DURATION, separated
by spaces or commas. A note is C4 (MIDI 60), C#4, Db4, a MIDI number, or
rest; a duration is in 1/64 s, 1 to 255."""

import re

NOTE = re.compile(r"^([A-Ga-g])([#b]?)(-?\d)$")
SEMITONES = {"c": 0, "d": 2, "e": 4, "f": 5, "g": 7, "a": 9, "b": 11}
MAX_NOTES = 16  # one song slot


def note_number(text):
    """The MIDI number of a note's name, 0 for a rest, or None."""
    if text.lower() in ("rest", "r"):
        return 0
    if text.isdigit():
        n = int(text)
        return n if n <= 255 else None
    m = NOTE.match(text)
    if not m:
        return None
    n = 12 * (int(m.group(3)) + 1) + SEMITONES[m.group(1).lower()] + {"#": 1, "b": -1, "": 0}[m.group(2)]
    return n if 0 <= n <= 127 else None


def parse_song(text):
    """[note, duration, note, duration, ...]; ValueError names the note at fault."""
    if not isinstance(text, str):
        raise ValueError("play() takes the song as text, like \"C4:16 E4:16 G4:32\"")
    words = [w for w in re.split(r"[\s,]+", text.strip()) if w]
    if not words:
        raise ValueError("play() needs at least one note, like \"C4:16\"")
    if len(words) > MAX_NOTES:
        raise ValueError("a song holds at most %d notes, not %d: play it in parts" % (MAX_NOTES, len(words)))
    data = []
    for i, word in enumerate(words, 1):
        note, _, duration = word.partition(":")
        n = note_number(note)
        if n is None:
            raise ValueError("note %d, %r: %r is not a note (write C4, C#4, Db4, a number or rest)" % (i, word, note))
        if not duration.isdigit() or not 1 <= int(duration) <= 255:
            raise ValueError("note %d, %r: the duration must be a number from 1 to 255 (64 is one second), "
                             "like C4:16" % (i, word))
        data += [n, int(duration)]
    return data
