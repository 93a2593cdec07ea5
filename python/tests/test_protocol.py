# SPDX-License-Identifier: GPL-3.0-or-later
"""The classroom protocol's table (protocol/mqtt/classroom_protocol.json): docs/mqtt.md says what it
says, the Python library computes a move's time as the bridge does, and an installed package finds
its copy."""

import os
import re
import subprocess
import sys

import pytest

from roomba import protocol
from roomba.robot import kinematic_seconds

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DOC = os.path.join(ROOT, "docs", "mqtt.md")


def number(cell):
    return float(cell.replace("\u2212", "-")) if cell else None


def doc_tables(path):
    """Each table of a Markdown file: its header's first cell, and its rows as (line, cells)."""
    tables, current = [], None
    with open(path, encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            if not line.startswith("|"):
                current = None
                continue
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if current is None:
                current = (cells[0], [])
                tables.append(current)
            elif not set("".join(cells)) <= set("-: "):
                current[1].append((n, cells))
    return tables


def rows_of(tables, header):
    return [row for first, rows in tables if first == header for row in rows]


def word(cell):
    m = re.fullmatch(r"`([^`]+)`", cell)
    return m.group(1) if m else None


def differences(path, table):
    """What the page at `path` says that the table does not, one line per row."""
    tables = doc_tables(path)
    name = os.path.relpath(path, ROOT)
    wrong = []

    def compare(kind, doc_rows, expected):
        seen = set()
        for n, key, said in doc_rows:
            if key not in expected:
                wrong.append("%s:%d: %s %s is not in the protocol's table" % (name, n, kind, key))
            elif said != expected[key]:
                wrong.append("%s:%d: %s %s: the page says %s, the table %s" % (name, n, kind, key, said, expected[key]))
            seen.add(key)
        for key in expected:
            if key not in seen:
                wrong.append("%s: %s %s of the protocol's table has no row" % (name, kind, key))

    goals = {"%s.%s" % (row["command"], f["field"]): (float(f["min"]), float(f["max"]), f["unit"])
             for row in table["goal_commands"] for f in row["fields"]}
    compare("goal field", [(n, "%s.%s" % (word(c[0]), word(c[1])), (number(c[2]), number(c[3]), c[4]))
                           for n, c in rows_of(tables, "command")], goals)
    compare("figure", [(n, word(c[0]), number(c[1])) for n, c in rows_of(tables, "figure")],
            {key: float(row["value"]) for key, row in table["figures"].items()})
    compare("stop", [(n, word(c[0]), c[1]) for n, c in rows_of(tables, "stop")],
            {row["stop"]: "yes" if row["frees_control"] else "no" for row in table["stop_reasons"]})
    return wrong


def test_docs_mqtt_md_says_what_the_protocol_table_says():
    wrong = differences(DOC, protocol.TABLE)
    assert not wrong, "docs/mqtt.md and protocol/mqtt/classroom_protocol.json disagree:\n" + "\n".join(wrong)


def test_a_number_changed_in_the_page_is_named_by_its_row(tmp_path):
    # The comparison above can fail: the same page with one range edited.
    page = open(DOC, encoding="utf-8").read()
    edited = page.replace("| `turn` | `rate` | 15 | 240 |", "| `turn` | `rate` | 15 | 250 |")
    assert edited != page
    path = tmp_path / "mqtt.md"
    path.write_text(edited, encoding="utf-8")
    wrong = differences(str(path), protocol.TABLE)
    assert len(wrong) == 1 and "goal field turn.rate: the page says (15.0, 250.0, 'degrees/s')" in wrong[0], wrong


def test_a_move_takes_the_time_the_table_gives_for_it():
    # The bridge's test (tst_classroom_protocol) checks MotionGoal against the same examples.
    for example in protocol.TABLE["move_time_examples"]:
        seconds = kinematic_seconds(example["command"], example["fields"])
        assert seconds == pytest.approx(example["kinematic_seconds"], abs=1e-3), example


def test_every_goal_field_names_its_unit_and_a_range():
    for command, fields in protocol.GOALS.items():
        for field, (low, high, unit) in fields.items():
            assert low < high and unit, (command, field)


def test_an_installed_package_reads_its_own_copy_of_the_table(tmp_path):
    build, cmake = os.environ.get("ROOMBA_BUILD_DIR"), os.environ.get("CMAKE_COMMAND")
    if not build or not cmake:
        pytest.skip("run by ctest, which names the build to install from")
    subprocess.run([cmake, "--install", build, "--component", "python", "--prefix", str(tmp_path)],
                   check=True, capture_output=True)
    site = tmp_path / "lib" / "python3" / "dist-packages"
    copy = site / "roomba" / "classroom_protocol.json"
    assert copy.is_file() and not copy.is_symlink()
    found = subprocess.run(
        [sys.executable, "-c", "import roomba.protocol as p; print(p.PATH); print(p.HEARTBEAT_S)"],
        cwd=str(tmp_path), env=dict(os.environ, PYTHONPATH=str(site)), check=True, capture_output=True, text=True)
    path, heartbeat = found.stdout.split()
    assert path == str(copy)
    assert float(heartbeat) == protocol.HEARTBEAT_S
