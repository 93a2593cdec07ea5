// SPDX-License-Identifier: GPL-3.0-or-later
// The page's WebSocket to the hub, in a worker of its own, with the
// heartbeat: what the library's heartbeat thread is to a Python program. A
// page busy drawing, or a tab behind others, stalls the page's own timers for
// longer than the bridge's lease; this worker keeps control meanwhile.
//
// From the page: { open: url }, { send: text }, { keep: { robot, client, heartbeatMs, staleMs } | null }.
// To the page: { opened }, { received: text }, { closed }, { stale } (the
// robot's telemetry stopped while in control: no keep was sent).

let socket = null;
let keeping = null;
let timer = null;
let telemetryAt = 0;

// The clock control messages carry (robot.js uses the same): it never goes
// back from one page to the next, as the bridge's lease wants.
const sentMs = () => Math.trunc(performance.timeOrigin + performance.now());

function keep() {
    if (!keeping || socket?.readyState !== WebSocket.OPEN)
        return;
    if (performance.now() - telemetryAt > keeping.staleMs) {
        postMessage({ stale: true });
        stopKeeping();
        return;
    }
    socket.send(JSON.stringify({ op: 'publish', topic: `roomba/${keeping.robot}/control/${keeping.client}`,
                                 payload: JSON.stringify({ action: 'keep', sent_ms: sentMs() }), qos: 0, retain: false }));
}

function stopKeeping() {
    keeping = null;
    clearInterval(timer);
    timer = null;
}

onmessage = ({ data }) => {
    if (data.open) {
        socket = new WebSocket(data.open);
        socket.onopen = () => postMessage({ opened: true });
        socket.onclose = () => {
            stopKeeping();
            postMessage({ closed: true });
        };
        socket.onmessage = event => {
            // Only the telemetry's arrival is read here, for the heartbeat's check.
            if (keeping && event.data.includes(`"roomba/${keeping.robot}/telemetry"`))
                telemetryAt = performance.now();
            postMessage({ received: event.data });
        };
    } else if ('send' in data) {
        socket?.send(data.send);
    } else if ('keep' in data) {
        stopKeeping();
        if (data.keep) {
            keeping = data.keep;
            telemetryAt = performance.now();
            // Twice as often as asked: a machine busy for a moment must not let control lapse.
            timer = setInterval(keep, keeping.heartbeatMs / 2);
            keep();
        }
    }
};
