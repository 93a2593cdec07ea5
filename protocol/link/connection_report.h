// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

// What ConnectionDoctor found (connection_doctor.h): the value its and the
// link's signals carry, apart from the doctor itself.

#include "brc_line.h"
#include "robot_profile.h"

#include <QMetaType>
#include <QObject>
#include <QString>
#include <QStringList>

#include <optional>

namespace oilink {

// Why a link gets no valid data, as ConnectionDoctor found it.
struct ConnectionReport {
    Q_GADGET
public:
    enum class Finding {
        Healthy,            // answers at the baud and as the profile asked for
        NothingComesBack,   // not a byte, and the BRC pin is out of reach
        AsleepDidNotWake,   // silent even after a BRC pulse: off, unplugged, or on the dock with old firmware
        WrongBaud,          // answers at another baud
        GarbledAtEveryBaud, // bytes, but no baud makes sense of them
        Baud19200AfterPulses, // silent until the three BRC pulses, then talks at 19200
        WokeAfterPulse,     // was asleep; a BRC pulse woke it
        WokeOnOtherLine,    // was asleep; a pulse on the other line than the wake line woke it
        OtherProfile,       // answers as another robot than the one asked for
        RoombaOrCreate2,    // a Roomba 500 or a Create 2: ask the user which
        TextOnDock,         // prints its charging status (so the baud and cable are right) but does not answer
    };
    Q_ENUM(Finding)

    Finding finding = Finding::NothingComesBack;
    QString summary;        // one line, for a status bar
    QStringList steps;      // what was tried and what came of it
    int baud = 0;           // where it answered; 0 where the transport has no baud or nothing answered
    std::optional<oi::ProfileId> profile; // Create 1 or Create 2 (the Roomba family) as found
    std::optional<oi::BrcLine> wakeLine;  // WokeOnOtherLine: the line that woke it
};

} // namespace oilink

Q_DECLARE_METATYPE(oilink::ConnectionReport)
