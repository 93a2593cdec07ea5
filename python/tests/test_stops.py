# SPDX-License-Identifier: GPL-3.0-or-later
"""Every way a program ends or is stopped stops the robot, seen on the wire
to the robot (the bridge's recording) and in the program. The thresholds'
distributions over 20 runs are tests/bench/bench_python.py's; here a few
runs each."""

import signal
import time

from programs import DRIVE_THEN_SPIN
from conftest import first_stop_after, moving_since, wait_for, wait_for_recorded_stop



def start_driving(run_program, bridge):
    program = run_program(DRIVE_THEN_SPIN)
    program.wait_line("driving")
    wait_for(lambda: moving_since(bridge), 5, "the drive on the wire")
    return program


def test_ctrl_c_puts_drive_0_0_on_the_wire_at_once_and_gives_control_back(start_bridge, run_program):
    bridge = start_bridge("r1")
    latencies = []
    for run in range(3):
        program = start_driving(run_program, bridge)
        sent = program.kill(signal.SIGINT)
        stop = wait_for_recorded_stop(bridge, sent)
        latencies.append(stop - sent)
        status, lines, errors = program.finish(10)
        assert status != 0
        assert "Stopped with Ctrl-C" in errors and "robot.drive" not in errors
        # Given back by the program, not lapsed.
        wait_for(lambda: bridge.log_text().count("control: free") == run + 1, 5, "control given back")
        assert "no heartbeat" not in bridge.log_text()
    print("Ctrl-C to Drive 0,0: %s ms" % ", ".join("%.0f" % (1000 * x) for x in latencies))
    # 100 ms at the 95th percentile (the benchmark); under a loaded test
    # machine, the best of three, and none beyond the heartbeat's 300 ms.
    assert min(latencies) <= 0.1
    assert max(latencies) <= 0.3


def test_a_killed_program_stops_through_the_heartbeat(start_bridge, run_program):
    bridge = start_bridge("r1")
    latencies = []
    for run in range(2):
        program = start_driving(run_program, bridge)
        killed = program.kill(signal.SIGKILL)
        latencies.append(wait_for_recorded_stop(bridge, killed) - killed)
        program.finish(10)
    print("kill -9 to Drive 0,0: %s ms" % ", ".join("%.0f" % (1000 * x) for x in latencies))
    assert min(latencies) <= 0.35
    assert max(latencies) <= 0.6


def test_stop_all_stops_the_robot_and_raises_stopped_inside_a_busy_loop(broker, start_bridge, run_program):
    from conftest import Watcher
    bridge = start_bridge("r1")
    teacher = Watcher(broker.port, [])
    try:
        for run in range(2):
            program = start_driving(run_program, bridge)
            sent = time.time()
            teacher.publish("roomba/fleet/stop", {"client": "teacher"})
            stop = wait_for_recorded_stop(bridge, sent)
            when, line = program.wait_line("stopped", 5)
            print("stop all: Drive 0,0 after %.0f ms, Stopped raised after %.0f ms"
                  % (1000 * (stop - sent), 1000 * (when - sent)))
            assert line.split()[2:] == ["stop", "all"]
            assert stop - sent <= 0.1
            assert stop < when and when - sent <= 0.3
            assert program.finish(10)[0] == 0
    finally:
        teacher.close()


def test_a_takeover_raises_stopped_naming_who(broker, start_bridge, run_program):
    from conftest import Watcher
    bridge = start_bridge("r1")
    teacher = Watcher(broker.port, [])
    try:
        program = start_driving(run_program, bridge)
        sent = teacher.publish("roomba/r1/takeover/teacher", {"action": "take"})
        assert first_stop_after(bridge.recording(), sent) or wait_for_recorded_stop(bridge, sent)
        when, line = program.wait_line("stopped", 5)
        assert line.split()[2] == "teacher"
    finally:
        teacher.close()


def test_a_normal_end_stops_the_robot_and_gives_control_back(start_bridge, run_program, broker):
    from conftest import Watcher
    bridge = start_bridge("r1")
    watcher = Watcher(broker.port, ["roomba/r1/state"])
    try:
        program = run_program("""
import time
from roomba import Robot
robot = Robot()
robot.drive(100, 0)
robot.wait(0.3)
print("ending", time.time(), flush=True)
""", name="patrol.py")
        # The fleet view shows whose program holds the robot.
        wait_for(lambda: any(p and p.get("program") == "patrol.py" and p.get("controller")
                             for _, p in watcher.on("roomba/r1/state")), 10, "the program named in the state")
        status, lines, errors = program.finish(20)
        assert status == 0, errors
        ended = float(lines[-1].split()[1])
        assert wait_for_recorded_stop(bridge, ended) - ended < 1
        wait_for(lambda: watcher.on("roomba/r1/state") and watcher.on("roomba/r1/state")[-1][1]["controller"] is None,
                 5, "control given back")
    finally:
        watcher.close()
