// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QLabel;
class QString;

// Sets the plain text of a one-line label that changes while the robot streams (a
// rate, a count). A label of free size asks its layout, and every layout up
// to the window, to be done again on each new text; this one keeps the size
// of its widest text so far, so a new text repaints the label alone and only
// a wider one lays the window out again.
void setLiveText(QLabel *label, const QString &text);
