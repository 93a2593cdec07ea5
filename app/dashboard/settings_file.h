// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

// The dashboard's settings file (QSettings, organisation and application
// names set) as people pass it around: one that is corrupt or was written by
// another version of the settings is not read and not overwritten. It is
// moved aside under a new name, and the dashboard starts with defaults and
// says so once.
namespace SettingsFile {

inline constexpr int kVersion = 1;
inline constexpr char kVersionKey[] = "settingsVersion";

struct Check {
    QString notice; // empty when the file was fine (or absent)
    QString keptAs; // where the bad file went, when it was moved aside
};

// Checks the settings file and, when it cannot be used, moves it aside
// (suffix ".bad-YYYYMMDD-HHMMSS") and starts afresh. A readable file with no
// version is this version's and gains the key.
Check check();

// check(), with its notice printed on standard error and shown in the main
// window's status bar once the event loop runs. Call after QApplication and
// before anything reads the settings.
void checkAtStart();

} // namespace SettingsFile
