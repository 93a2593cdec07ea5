# SPDX-License-Identifier: GPL-3.0-or-later
"""At home: one command starts a broker and a practice robot, and the
classroom's program runs on it unchanged."""

import os
import subprocess

from conftest import PYTHON, PYTHON_DIR, SOURCE


def test_one_command_runs_the_square_on_a_practice_robot(folder):
    environment = dict(os.environ, PYTHONPATH=PYTHON_DIR, XDG_CONFIG_HOME=folder,
                       # A classroom's settings in the environment do not reach the practice robot.
                       ROOMBA_ROBOT="r7", ROOMBA_BROKER="mqtt://127.0.0.1:1")
    done = subprocess.run([PYTHON, "-m", "roomba.practice", os.path.join(SOURCE, "python", "examples", "square.py"),
                           "100"], env=environment, capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert "Back at the start" in done.stdout
