// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "fleet_tile.h"

#include <QList>
#include <QWidget>

class QComboBox;
class QGridLayout;
class QLabel;
class QPushButton;
class QScrollArea;
class StopAllButton;

// Every robot on the broker, a large tile each, as many columns as fit:
// a whole classroom on a projector. Clicking a tile asks to select that
// robot. It takes plain values; the console decides what they say.
class FleetView : public QWidget {
    Q_OBJECT
public:
    explicit FleetView(QWidget *parent = nullptr);

    // Adds tiles for new names and updates the others (in the given order
    // for new ones); a tile repaints only when its values change.
    void setTiles(const QList<FleetTileValues> &tiles);
    // A robot gone from the window goes from the view.
    void removeTile(const QString &name);
    // What the last Stop all did ("Stopped all 3 robots at 21:58"), under the header.
    void setStopReport(const QString &text);
    QString stopReport() const;
    // The broker line above the tiles: where, and whether connected.
    void setBrokerText(const QString &text, bool connected);
    QString brokerText() const { return m_brokerText; }
    // While not connected: the broker of the last session, to connect to
    // again with the Connect button (which then says so). Empty: none.
    void setReconnectOffer(const QString &text);
    QString reconnectOffer() const { return m_reconnectOffer; }
    QLabel *brokerLabel() const { return m_broker; }
    QPushButton *connectButton() const { return m_connect; }
    // The tiles' order: by name (r2 before r10), or by pack health, the
    // worst first (replace, worn, good, not measured), then by name.
    enum class Order { Name, PackHealth };
    void setOrder(Order order);
    Order order() const { return m_order; }
    QComboBox *orderBox() const { return m_orderBox; }
    // Checks the tile of the selected robot (none for an empty name).
    void setSelected(const QString &name);

    FleetTile *tile(const QString &name) const;
    const QList<FleetTile *> &tiles() const { return m_tiles; }
    int columns() const { return m_columns; }
    // How many times the desktop's type the tiles use: as large as lets
    // every tile fit the view, from 0.8 up to 3.
    qreal tileScale() const { return m_scale; }
    // Stop all, red and large above the tiles (stopAllRequested()).
    QPushButton *stopAllButton() const;

signals:
    void robotClicked(const QString &name);
    void connectRequested();
    void stopAllRequested();

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    void relayout(bool force = false);
    void sortTiles();
    void retranslateUi();

    QLabel *m_stopped = nullptr;
    QLabel *m_broker = nullptr;
    QLabel *m_empty = nullptr;
    QPushButton *m_connect = nullptr;
    StopAllButton *m_stopAll = nullptr;
    QScrollArea *m_scroll = nullptr;
    QWidget *m_canvas = nullptr;
    QGridLayout *m_grid = nullptr;
    QList<FleetTile *> m_tiles;
    int m_columns = 0;
    qreal m_scale = 1;
    QString m_brokerText;
    QString m_reconnectOffer;
    bool m_connected = false;
    Order m_order = Order::Name;
    QComboBox *m_orderBox = nullptr;
};
