// SPDX-License-Identifier: GPL-3.0-or-later
// A recording that adds more markers than a recording holds: a Create 2
// streaming packet 7, one frame, then `markers` adds (ids from 1, at 0 s).
#pragma once

#include "oirec_records.h"
#include "recording_markers.h"

#include <QFile>
#include <QString>

inline QByteArray crowdedRecording(int markers)
{
    QByteArray file = oirecHeader(3, R"({"format":"Roomba Dashboard recording","version":3})");
    file += oirecRecord('S', 0, R"({"profile":"create2","baud":115200,"packets":[7]})");
    file += oirecRecord('R', 0, QByteArray("\x13\x02\x07\x00\xE4", 5));
    for (int id = 1; id <= markers; ++id)
        file += oirecRecord('M', 0, oilink::MarkerEdit::add({id, 0, "m"}).toJson());
    return file;
}

// Writes crowdedRecording(markers) to `path`; false if it cannot.
inline bool writeCrowdedRecording(const QString &path, int markers)
{
    const QByteArray bytes = crowdedRecording(markers);
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(bytes) == bytes.size();
}
