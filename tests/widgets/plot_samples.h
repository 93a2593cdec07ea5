// SPDX-License-Identifier: GPL-3.0-or-later
// A sensor history the plot tests share.
#pragma once

#include "sensor_history.h"

#include <QTest>

// Samples every 0.1 s from `firstTenth`: voltage (rising by one a sample)
// and current always, the wall only on whole seconds.
inline void feed(SensorHistory &h, int firstTenth, int count)
{
    for (int k = firstTenth; k < firstTenth + count; ++k) {
        oi::SensorSnapshot s(oi::profile(oi::ProfileId::Create2));
        s.set(22, 14000 + k);
        s.set(23, -k);
        if (k % 10 == 0)
            s.set(8, (k / 10) % 2);
        QVERIFY(h.append(k / 10.0, s));
    }
}
