// SPDX-License-Identifier: GPL-3.0-or-later
// The page's side of the hub's WebSocket (docs/blocks.md, "The hub"): sign
// in, subscribe, publish, and hand each MQTT message to whoever listens.

export class Hub {
    // events: { signedIn(message), refused(why), error(why), closed(why) }
    constructor(url, events) {
        this.url = url;
        this.events = events;
        this.signedIn = false;
        this.listeners = new Set();
        this.worker = null;
        this.open_ = false;
        this.queue = [];
    }

    // The socket lives in a worker (hub_worker.js), which also sends the
    // heartbeat while a program holds control.
    open() {
        this.worker = new Worker(new URL('./hub_worker.js', import.meta.url));
        this.worker.onmessage = ({ data }) => {
            if (data.opened) {
                this.open_ = true;
                for (const text of this.queue.splice(0))
                    this.worker.postMessage({ send: text });
            } else if ('received' in data) {
                this._received(data.received);
            } else if (data.closed) {
                const was = this.signedIn;
                this.signedIn = false;
                if (was)
                    this.listeners.forEach(l => l.brokerLost());
                this.events.closed('the page lost its connection to the classroom hub');
            } else if (data.stale) {
                this.listeners.forEach(l => l.heartbeatStale?.());
            }
        };
        this.worker.postMessage({ open: this.url });
    }

    send(message) {
        const text = JSON.stringify(message);
        if (this.open_)
            this.worker.postMessage({ send: text });
        else
            this.queue.push(text);
    }

    // Keeps control of robot as client, with a keep every heartbeatMs while
    // telemetry comes within staleMs; null stops.
    keep(keeping) {
        this.worker.postMessage({ keep: keeping });
    }

    signIn(user, password) {
        this.send({ op: 'sign-in', user, password });
    }

    subscribe(topic) { this.send({ op: 'subscribe', topic }); }
    unsubscribe(topic) { this.send({ op: 'unsubscribe', topic }); }
    publish(topic, payload, qos = 0) { this.send({ op: 'publish', topic, payload, qos, retain: false }); }

    // listener: { message(topic, payload), brokerLost() }; returns how to stop.
    listen(listener) {
        this.listeners.add(listener);
        return () => this.listeners.delete(listener);
    }

    _received(text) {
        let m;
        try {
            m = JSON.parse(text);
        } catch {
            return this.events.error(`the hub sent something that is not JSON: ${String(text).slice(0, 80)}`);
        }
        switch (m?.op) {
        case 'signed-in':
            this.signedIn = true;
            return this.events.signedIn(m);
        case 'refused':
            return this.events.refused(String(m.why));
        case 'message':
            return this.listeners.forEach(l => l.message(String(m.topic), String(m.payload)));
        case 'broker-lost':
            this.signedIn = false;
            this.listeners.forEach(l => l.brokerLost());
            return this.events.closed(`the classroom broker ended your connection: ${m.why}`);
        case 'error':
            return this.events.error(String(m.why));
        default:
            return this.events.error(`the hub sent an unknown message: ${String(text).slice(0, 80)}`);
        }
    }
}
