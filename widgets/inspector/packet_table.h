// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "packet_table_model.h"

#include <QWidget>

class QPushButton;
class QTableView;

// The packet table beside the byte log: one row per packet seen, its value,
// bytes and rate, and a Plot button (or a double-click) that asks for a plot
// of the packet. Hidden, it takes no snapshots and draws nothing.
class PacketTable : public QWidget {
    Q_OBJECT
public:
    // 15 Hz: every other tick of the display.
    static constexpr int kRefreshIntervalMs = 66;

    explicit PacketTable(QWidget *parent = nullptr);

    void setProfile(const oi::RobotProfile &profile) { m_model->setProfile(profile); }
    void setShowsHex(bool hex) { m_model->setShowsHex(hex); }
    void addSnapshot(double seconds, const oi::SensorSnapshot &snapshot);
    void clear() { m_model->clear(); }
    // Shows what came since the last refresh now rather than at the next tick.
    void refresh();

    PacketTableModel *model() const { return m_model; }
    // The packet of the current row, or -1.
    int currentPacketId() const;

signals:
    void plotRequested(int packetId);

protected:
    void changeEvent(QEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    void retranslateUi();
    void requestPlot();
    void updatePlotButton();

    PacketTableModel *m_model;
    QTableView *m_view;
    QPushButton *m_plotButton;
    // Whether it was on screen at the display's tick m_onScreenAtTick.
    bool m_onScreen = false;
    quint64 m_onScreenAtTick = 0;
    bool m_onScreenKnown = false;
};
