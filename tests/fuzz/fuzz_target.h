// SPDX-License-Identifier: GPL-3.0-or-later
// What the fuzz targets and their regression tests share.
#pragma once

#include "robot_profile.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace fuzz {

// The profile an input's first byte picks: 0 Create 1, 1 Roomba 500,
// 2 Create 2, modulo 3.
inline const oi::RobotProfile &profileOfByte(std::uint8_t byte)
{
    static constexpr oi::ProfileId kProfiles[] = {oi::ProfileId::Create1, oi::ProfileId::Roomba500,
                                                  oi::ProfileId::Create2};
    return oi::profile(kProfiles[byte % 3]);
}

// What a target returns to libFuzzer: 0 while the invariants hold; on a
// broken one it says which and aborts, so that libFuzzer keeps the input.
inline int abortOnFailure(const std::string &failure)
{
    if (!failure.empty()) {
        std::fprintf(stderr, "invariant violated: %s\n", failure.c_str());
        std::abort();
    }
    return 0;
}

} // namespace fuzz
