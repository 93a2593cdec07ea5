// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPolygonF>
#include <QWidget>

#include <array>
#include <cstdint>

// The robot's four 7-segment digits. Positions run 0..3 left to right, which
// are the robot's digits 3, 2, 1, 0 (the order opcodes 163 and 164 send
// them). Each digit is a segment mask: bit 0 = A (top) .. bit 6 = G (middle).
// When editable, clicking a segment switches it and emits segmentsChanged;
// from the keyboard, the arrow keys move between segments and Space switches.
class SevenSegmentDisplay : public QWidget {
    Q_OBJECT
public:
    explicit SevenSegmentDisplay(QWidget *parent = nullptr);

    void setEditable(bool editable);
    bool isEditable() const { return m_editable; }

    void setMasks(const std::array<std::uint8_t, 4> &masks);
    std::array<std::uint8_t, 4> masks() const { return m_masks; }

    // Where segment `segmentBit` (0 = A .. 6 = G) of the digit at `position`
    // is drawn, for clicking it.
    QPoint segmentCentre(int position, int segmentBit) const;
    // The segment the keyboard works on, as position * 7 + segment bit.
    int currentSegment() const { return m_current; }

    // The lit segments in words, for screen readers.
    QString describeMasks() const;

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

signals:
    void segmentsChanged(const std::array<std::uint8_t, 4> &masks);

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    QPolygonF segmentShape(int position, int segmentBit) const;
    QRectF digitCell(int position) const;
    void toggle(int position, int segmentBit);
    void updateDescription();

    std::array<std::uint8_t, 4> m_masks{};
    bool m_editable = false;
    int m_current = 0;
};
