// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include "../common/recording_transport.h" // one transport for app and link tests
