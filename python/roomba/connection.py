# SPDX-License-Identifier: GPL-3.0-or-later
"""Where the broker and the robot are: a connection file, then the environment.

A connection file is what `roomba-classroom init` writes for each student
(docs/python.md): JSON with the broker, its port, the CA certificate, the
account, its password and the robot to drive by default. The library reads
the file named by ROOMBA_CONFIG, else roomba/connection.json in the user's
config folder ($XDG_CONFIG_HOME, ~/.config). ROOMBA_ROBOT, ROOMBA_BROKER,
ROOMBA_USER, ROOMBA_PASSWORD and ROOMBA_CA override what it says.
"""

import json
import os
import re
from dataclasses import dataclass
from typing import Optional
from urllib.parse import urlsplit

from .errors import RobotError

NAME_RULE = re.compile(r"^[A-Za-z0-9_-]{1,64}$")
DEFAULT_PORTS = {"mqtt": 1883, "mqtts": 8883}


@dataclass
class Connection:
    host: str = "127.0.0.1"
    port: int = 1883
    tls: bool = False
    ca_pem: Optional[str] = None  # the CA certificate's text
    username: Optional[str] = None
    password: Optional[str] = None
    robot: Optional[str] = None
    source: str = "the defaults"  # where it was read, for messages

    @property
    def url(self):
        return "%s://%s:%d" % ("mqtts" if self.tls else "mqtt", self.host, self.port)


def default_config_path():
    base = os.environ.get("XDG_CONFIG_HOME") or os.path.join(os.path.expanduser("~"), ".config")
    return os.path.join(base, "roomba", "connection.json")


def parse_broker(text, where):
    """mqtt://HOST:PORT, mqtts://HOST:PORT or HOST[:PORT] as (host, port, tls)."""
    if "://" not in text:
        text = "mqtt://" + text
    parts = urlsplit(text)
    if parts.scheme not in DEFAULT_PORTS or not parts.hostname:
        raise RobotError("%s: %r is not a broker address. Write it like mqtt://192.168.1.10:1883 "
                         "or mqtts://classroom.local:8883." % (where, text))
    try:
        port = parts.port or DEFAULT_PORTS[parts.scheme]
    except ValueError:
        raise RobotError("%s: %r has a port that is not a number from 1 to 65535." % (where, text)) from None
    return parts.hostname, port, parts.scheme == "mqtts"


def read_file(path):
    """The settings of a connection file, checked; RobotError says what is wrong."""
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except OSError as e:
        raise RobotError("Cannot read the connection file %s: %s. Ask your teacher for your "
                         "connection file again." % (path, e.strerror)) from None
    except ValueError as e:
        raise RobotError("The connection file %s is damaged (%s). Ask your teacher for your "
                         "connection file again." % (path, e)) from None
    if not isinstance(data, dict):
        raise RobotError("The connection file %s is not a connection file. Ask your teacher for "
                         "yours." % path)
    c = Connection(source=path)
    text_keys = ("broker", "ca", "username", "password", "robot")
    for key, value in data.items():
        if key in text_keys and not isinstance(value, str):
            raise RobotError("%s: %r must be text." % (path, key))
    if "broker" in data:
        c.host, c.port, c.tls = parse_broker(data["broker"], path)
    if "port" in data:
        if not isinstance(data["port"], int) or not 1 <= data["port"] <= 65535:
            raise RobotError("%s: \"port\" must be a number from 1 to 65535." % path)
        c.port = data["port"]
    if "tls" in data:
        c.tls = bool(data["tls"])
    c.ca_pem = data.get("ca")
    if c.ca_pem:
        c.tls = True
    c.username = data.get("username")
    c.password = data.get("password")
    c.robot = data.get("robot")
    return c


def resolve(robot=None, environ=None):
    """The connection to use: the file, the environment over it, `robot` over both."""
    env = os.environ if environ is None else environ
    path = env.get("ROOMBA_CONFIG")
    if path:
        c = read_file(path)
    elif os.path.exists(default_config_path()):
        c = read_file(default_config_path())
    else:
        c = Connection()
    if env.get("ROOMBA_BROKER"):
        c.host, c.port, c.tls = parse_broker(env["ROOMBA_BROKER"], "ROOMBA_BROKER")
        c.source = "ROOMBA_BROKER"
    if env.get("ROOMBA_USER"):
        c.username = env["ROOMBA_USER"]
    if env.get("ROOMBA_PASSWORD"):
        c.password = env["ROOMBA_PASSWORD"]
    if env.get("ROOMBA_CA"):
        try:
            with open(env["ROOMBA_CA"], encoding="ascii") as f:
                c.ca_pem = f.read()
        except OSError as e:
            raise RobotError("ROOMBA_CA: cannot read %s: %s." % (env["ROOMBA_CA"], e.strerror)) from None
        c.tls = True
    if env.get("ROOMBA_ROBOT"):
        c.robot = env["ROOMBA_ROBOT"]
    if robot is not None:
        c.robot = robot
    for what, value in (("robot name", c.robot), ("account name", c.username)):
        if value is not None and not NAME_RULE.match(value):
            raise RobotError("%r is not a %s: 1 to 64 letters, digits, '-' or '_'." % (value, what))
    return c
