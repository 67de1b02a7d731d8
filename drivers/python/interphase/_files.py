"""The single-point driver's files from Python: history tables and namelist case files."""

import os
import re

import numpy as np

from ._material import Material

_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eEdD][+-]?\d+)?$")


def _number(text, where):
    if not _NUMBER.match(text):
        raise ValueError(f"{where}: cannot parse {text!r} as a number")
    value = float(text.replace("d", "e").replace("D", "e"))
    if not np.isfinite(value):
        raise ValueError(f"{where}: {text!r} is not a finite number")
    return value


def read_history(path):
    """A history file of interphase-point (`t s_T s_N` or `t s_T1 s_T2 s_N` rows, `#` comments).

    Returns (time, separation): separation is (nrows, ntens) in the C interface's order, normal
    first ((s_N, s_T) or (s_N, s_T1, s_T2)), ready for Material.run.
    """
    rows = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            where = f"{path}:{number}"
            if len(words) not in (3, 4):
                raise ValueError(f"{where}: {len(words)} columns; a history row is 't s_T s_N' or 't s_T1 s_T2 s_N'")
            if rows and len(words) != len(rows[0]):
                raise ValueError(f"{where}: {len(words)} columns, the first row has {len(rows[0])}")
            rows.append([_number(w, where) for w in words])
    if len(rows) < 2:
        raise ValueError(f"{path}: needs at least 2 data rows, found {len(rows)}")
    table = np.array(rows)
    time = table[:, 0]
    if not np.all(np.diff(time) > 0.0):
        raise ValueError(f"{path}: times must increase strictly")
    separation = np.concatenate([table[:, -1:], table[:, 1:-1]], axis=1)
    return time, separation


def read_namelist(path):
    """{group: {entry: value}} of a namelist file (strings, numbers, logicals; one value each)."""
    text = open(path, encoding="utf-8").read()
    tokens = []
    for line in text.splitlines():
        i, n = 0, len(line)
        while i < n:
            c = line[i]
            if c in " \t,":
                i += 1
            elif c == "!":
                break
            elif c in "'\"":
                j, value = i + 1, ""
                while j < n:
                    if line[j] == c:
                        if j + 1 < n and line[j + 1] == c:
                            value += c
                            j += 2
                            continue
                        break
                    value += line[j]
                    j += 1
                tokens.append(("string", value))
                i = j + 1
            elif c in "=/":
                tokens.append((c, c))
                i += 1
            else:
                j = i
                while j < n and line[j] not in " \t,=/!":
                    j += 1
                tokens.append(("word", line[i:j]))
                i = j
    groups, group, name = {}, None, None
    for kind, value in tokens:
        if group is None:
            if kind == "word" and value.startswith("&"):
                group = value[1:].lower()
                groups[group] = {}
            continue
        if kind == "/":
            group = None
        elif kind == "=":
            continue
        elif name is None:
            name = value.lower()
        else:
            if kind == "string":
                groups[group][name] = value
            elif value.lower() in (".true.", "t", ".t."):
                groups[group][name] = True
            elif value.lower() in (".false.", "f", ".f."):
                groups[group][name] = False
            else:
                groups[group][name] = _number(value, f"{path}: &{group}: {name}")
            name = None
    return groups


class Case:
    """A case file of interphase-point: `material` (Material), `time` and `separation` (the
    history, normal first), `increments` and `output` (the CSV name the driver writes)."""

    def __init__(self, material, time, separation, increments, output):
        self.material, self.time, self.separation = material, time, separation
        self.increments, self.output = increments, output

    def run(self, tangent=False):
        """Material.run on the case's history, as interphase-point replays it."""
        return self.material.run(self.separation, self.time, self.increments, tangent=tangent)


def read_case(path):
    """Read an interphase-point case file (drivers/README.md): its &material and &loading.

    The paths it names (history, table, rcurve_file) are taken relative to its folder, as the
    driver takes them.
    """
    groups = read_namelist(path)
    base = os.path.dirname(os.path.abspath(path))
    if "material" not in groups or "loading" not in groups:
        raise ValueError(f"{path}: needs the groups &material and &loading")
    entries = dict(groups["material"])
    for key in ("table", "rcurve_file"):
        if key in entries:
            entries[key] = os.path.join(base, entries[key])
    material = Material(**entries)
    loading = groups["loading"]
    time, separation = read_history(os.path.join(base, loading["history"]))
    return Case(material, time, separation, int(loading["increments"]), loading.get("output"))
