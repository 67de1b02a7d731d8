"""The single-point driver's files from Python: history tables and namelist case files."""

import os
import re

import numpy as np

from ._material import Material, DEFAULT_TRACTION_TOLERANCE

_NUMBER = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eEdD][+-]?\d+)?$")


def _number(text, where):
    if not _NUMBER.match(text):
        raise ValueError(f"{where}: cannot parse {text!r} as a number")
    value = float(text.replace("d", "e").replace("D", "e"))
    if not np.isfinite(value):
        raise ValueError(f"{where}: {text!r} is not a finite number")
    return value


# the names of a `# columns:` line after t (file order): separation, traction
_NAMES = {3: (("s_T", "Sigma_T"), ("s_N", "Sigma_N")),
          4: (("s_T1", "Sigma_T1"), ("s_T2", "Sigma_T2"), ("s_N", "Sigma_N"))}


def _column_names(text, where):
    """The traction flags (file order: shear(s), normal) of a `# columns:` comment."""
    depth, kept = 0, []
    for ch in text.split(":", 1)[1]:
        if ch == "(":
            depth += 1
        if depth > 0:
            if ch == ")":
                depth -= 1
            kept.append(" ")
        else:
            kept.append(ch)
    words = "".join(kept).split()
    if len(words) not in (3, 4):
        raise ValueError(f'{where}: "# columns:" names {len(words)} columns; expected t and 2 (2-D) or 3 '
                         '(3-D) components, e.g. "# columns: t s_T Sigma_N"')
    if words[0] != "t":
        raise ValueError(f'{where}: "# columns:" must start with t, got {words[0]!r}')
    flags = []
    for i, word in enumerate(words[1:]):
        names = _NAMES[len(words)][i]
        if word.lower() not in (names[0].lower(), names[1].lower()):
            raise ValueError(f'{where}: "# columns:" column {i + 2} is {word!r}; expected {names[0]} or '
                             f'{names[1]} (t, the shear component(s), then the normal one)')
        flags.append(word.lower() == names[1].lower())
    return len(words), flags


def read_history(path, control=False):
    """A history file of interphase-point (drivers/README.md): rows `t s_T s_N` or
    `t s_T1 s_T2 s_N`, `#` comments; a comment line `# columns: t s_T Sigma_N` names the columns
    of the rows below it, each component a separation (s_X, mm) or a traction (Sigma_X, MPa).

    Returns (time, separation) (control=False; a file that imposes a traction is then an error)
    or (time, value, control) (control=True; control (nrows, ntens) booleans, true where the
    value is a traction). Values and controls are in the C interface's order, normal first
    ((s_N, s_T) or (s_N, s_T1, s_T2)), ready for Material.run.
    """
    rows, flags, lines = [], [], []
    named, names_line = None, 0
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            where = f"{path}:{number}"
            head, hash_, comment = line.partition("#")
            if hash_ and comment.lstrip().lower().startswith("columns:"):
                ncolumns, named = _column_names(comment.lstrip(), where)
                names_line = number
                if rows and ncolumns != len(rows[0]):
                    raise ValueError(f'{where}: the "# columns:" line names {ncolumns} columns, but the data '
                                     f'lines have {len(rows[0])}')
                named = (ncolumns, named)
                continue
            words = head.split()
            if not words:
                continue
            if len(words) not in (3, 4):
                raise ValueError(f"{where}: {len(words)} columns; a history row is 't s_T s_N' or 't s_T1 s_T2 s_N'")
            if rows and len(words) != len(rows[0]):
                raise ValueError(f"{where}: {len(words)} columns, the first row has {len(rows[0])}")
            if named is not None and named[0] != len(words):
                raise ValueError(f'{where}: {len(words)} columns, but the "# columns:" line (line {names_line}) '
                                 f'names {named[0]}')
            rows.append([_number(w, where) for w in words])
            flags.append(named[1] if named is not None else [False] * (len(words) - 1))
            lines.append(number)
    if len(rows) < 2:
        raise ValueError(f"{path}: needs at least 2 data rows, found {len(rows)}")
    table = np.array(rows)
    time = table[:, 0]
    if not np.all(np.diff(time) > 0.0):
        bad = int(np.argmin(np.diff(time) > 0.0)) + 1
        raise ValueError(f"{path}:{lines[bad]}: time {time[bad]!r} is not greater than the previous time "
                         f"{time[bad - 1]!r}; times must increase strictly")
    value = np.concatenate([table[:, -1:], table[:, 1:-1]], axis=1)
    f = np.array(flags, dtype=bool)
    traction = np.concatenate([f[:, -1:], f[:, :-1]], axis=1)
    if control:
        return time, value, traction
    if traction.any():
        raise ValueError(f"{path}: the history imposes tractions (Sigma_ columns): read it with "
                         "read_history(path, control=True), which returns (time, value, control)")
    return time, value


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
    """A case file of interphase-point: `material` (Material), `time`, `value` and `control` (the
    history, normal first: separations, or tractions where `control` is true), `increments`,
    `traction_tolerance`, `output_every` and `output` (the CSV name the driver writes).
    `separation` is `value` (a history without traction control holds separations only)."""

    def __init__(self, material, time, value, increments, output, control=None,
                 traction_tolerance=DEFAULT_TRACTION_TOLERANCE, output_every=1):
        self.material, self.time, self.value = material, time, value
        self.control = np.zeros(value.shape, dtype=bool) if control is None else control
        self.increments, self.output = increments, output
        self.traction_tolerance, self.output_every = traction_tolerance, output_every

    @property
    def separation(self):
        return self.value

    def run(self, tangent=False):
        """Material.run on the case's history, as interphase-point replays it."""
        return self.material.run(self.value, self.time, self.increments, tangent=tangent,
                                 control=self.control if self.control.any() else None,
                                 traction_tolerance=self.traction_tolerance, output_every=self.output_every)


def read_case(path):
    """Read an interphase-point case file (drivers/README.md): its &material and &loading.

    The paths it names (history, table, rcurve_file) are taken relative to its folder, as the
    driver takes them. The history may impose tractions (`# columns:` lines).
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
    time, value, control = read_history(os.path.join(base, loading["history"]), control=True)
    return Case(material, time, value, int(loading["increments"]), loading.get("output"), control=control,
                traction_tolerance=float(loading.get("traction_tolerance", DEFAULT_TRACTION_TOLERANCE)),
                output_every=int(loading.get("output_every", 1)))
