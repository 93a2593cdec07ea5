# SPDX-License-Identifier: GPL-3.0-or-later
"""Where the library finds the broker and the robot, and the song text."""

import json
import os

import pytest

from roomba import RobotError
from roomba.connection import resolve
from roomba.song import parse_song


def write(folder, name, content):
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(content if isinstance(content, str) else json.dumps(content))
    return path


def test_the_connection_file_then_the_environment_then_the_name(folder):
    path = write(folder, "alice.json", {"format": "roomba-connection", "version": 1,
                                        "broker": "mqtts://10.0.0.5:8883", "ca": "-----BEGIN CERTIFICATE-----",
                                        "username": "alice", "password": "secret", "robot": "r1"})
    c = resolve(environ={"ROOMBA_CONFIG": path})
    assert (c.host, c.port, c.tls, c.username, c.password, c.robot) == ("10.0.0.5", 8883, True, "alice", "secret", "r1")
    c = resolve(environ={"ROOMBA_CONFIG": path, "ROOMBA_ROBOT": "r2", "ROOMBA_USER": "bob", "ROOMBA_PASSWORD": "pw",
                         "ROOMBA_BROKER": "mqtt://127.0.0.1:1884"})
    assert (c.host, c.port, c.tls, c.username, c.password, c.robot) == ("127.0.0.1", 1884, False, "bob", "pw", "r2")
    assert resolve("r3", environ={"ROOMBA_CONFIG": path, "ROOMBA_ROBOT": "r2"}).robot == "r3"


def test_the_users_config_folder_and_the_defaults(folder):
    assert resolve(environ={"XDG_CONFIG_HOME": folder}).url == "mqtt://127.0.0.1:1883"
    os.makedirs(os.path.join(folder, "roomba"))
    write(folder, "roomba/connection.json", {"broker": "classroom.local", "robot": "r5"})
    os.environ["XDG_CONFIG_HOME"] = folder
    try:
        c = resolve(environ={})
    finally:
        del os.environ["XDG_CONFIG_HOME"]
    assert (c.url, c.robot) == ("mqtt://classroom.local:1883", "r5")


@pytest.mark.parametrize("content, words", [
    ("{not json", "damaged"),
    ([1, 2], "not a connection file"),
    ({"broker": "ftp://x"}, "not a broker address"),
    ({"port": 70000}, "from 1 to 65535"),
    ({"robot": "r 1"}, "not a robot name"),
    ({"password": 5}, "must be text"),
])
def test_a_bad_connection_file_says_what_is_wrong(folder, content, words):
    path = write(folder, "bad.json", content)
    with pytest.raises(RobotError) as e:
        resolve(environ={"ROOMBA_CONFIG": path})
    assert words in str(e.value)


def test_a_missing_connection_file_says_to_ask_for_it(folder):
    with pytest.raises(RobotError) as e:
        resolve(environ={"ROOMBA_CONFIG": os.path.join(folder, "nothing.json")})
    assert "Ask your teacher" in str(e.value)


def test_song_text_as_roomba_ctl_reads_it():
    assert parse_song("C4:16 E4:16, G4:32 rest:8 60:1 c#4:2 Db4:2") == [60, 16, 64, 16, 67, 32, 0, 8, 60, 1, 61, 2,
                                                                           61, 2]
    for bad, words in (("C4", "duration"), ("X4:16", "not a note"), ("C4:0", "duration"), ("", "at least one"),
                       (" ".join(["C4:8"] * 17), "at most 16")):
        with pytest.raises(ValueError) as e:
            parse_song(bad)
        assert words in str(e.value)
