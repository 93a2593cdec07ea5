// SPDX-License-Identifier: GPL-3.0-or-later
// Compiles the libraries' shared precompiled header (cmake/build_speed.cmake).
int roomba_pch_donor()
{
    return 0;
}
