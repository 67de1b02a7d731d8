"""The single-point driver's files from Python: history tables and namelist case files."""

import os
import re

import numpy as np

from . import _status
from ._library import InterphaseError
from ._material import Material, DEFAULT_TRACTION_TOLERANCE, _ENTRIES

_NUMBER = re.compile(r"^[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eEdD][+-]?[0-9]+)?$")
#: the largest file the readers take (bytes), as the driver's (interphase_text_input's MAX_FILE_BYTES)
MAX_FILE_BYTES = 64 * 1024 * 1024


def _text_lines(path):
    """The lines of a text file, read as the driver reads it: bytes as they are (UTF-8, with any
    other byte kept as a surrogate, so a comment in another encoding is read and a path named in
    the file opens the file of those bytes), at most MAX_FILE_BYTES (a larger file, /dev/zero
    included, is refused: ValueError naming the file), and without a UTF-8 byte-order mark (refused,
    as the driver refuses it)."""
    with open(path, "rb") as f:
        data = f.read(MAX_FILE_BYTES + 1)
    if len(data) > MAX_FILE_BYTES:
        raise ValueError(f"{path}: the file is larger than {MAX_FILE_BYTES} bytes")
    if data.startswith(b"\xef\xbb\xbf"):
        raise ValueError(f"{path}:1: the file starts with a UTF-8 byte-order mark (bytes EF BB BF): save it "
                         "without one")
    lines = data.decode("utf-8", errors="surrogateescape").split("\n")
    if lines and lines[-1] == "":
        lines.pop()
    return [line[:-1] if line.endswith("\r") else line for line in lines]


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


def _without_parentheses(text):
    """`text` with every character from a '(' to its ')' (to the end, if unclosed) a blank."""
    depth, kept = 0, []
    for ch in text:
        if ch == "(":
            depth += 1
        if depth > 0:
            if ch == ")":
                depth -= 1
            kept.append(" ")
        else:
            kept.append(ch)
    return "".join(kept)


def _column_names(text, where):
    """The traction flags (file order: shear(s), normal) of a `# columns:` comment."""
    _check_units(text.split(":", 1)[1], where)
    words = _without_parentheses(text.split(":", 1)[1]).split()
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


_COLUMN_NAMES = ("t", "s_t", "s_n", "s_t1", "s_t2", "sigma_t", "sigma_n", "sigma_t1", "sigma_t2")


def _column_words(comment):
    """What a comment (lower case) is when its words are two or more column names, after an
    optional first word `column` or `columns`, words in parentheses skipped: "tractions" when one
    of them is a traction's (`# t s_T Sigma_N`: read as a plain comment it would run the tractions
    as separations), "order" when they are not in the rows' order (`# t s_N s_T`), else None
    (interphase_driver_history's column_words_kind)."""
    words = _without_parentheses(comment).split()
    if words and words[0] in ("column", "columns"):
        words = words[1:]
    if len(words) < 2 or not all(w in _COLUMN_NAMES for w in words):
        return None
    if any(w.startswith("sigma_") for w in words):
        return "tractions"
    if words[0] == "t":
        words = words[1:]
    return None if words in (["s_t", "s_n"], ["s_t1", "s_t2", "s_n"]) else "order"


_UNITS = {"t": "s", "s_t": "mm", "s_t1": "mm", "s_t2": "mm", "s_n": "mm",
          "sigma_t": "MPa", "sigma_t1": "MPa", "sigma_t2": "MPa", "sigma_n": "MPa"}


def _check_units(text, where):
    """Refuse a unit in parentheses right after a column name of a `columns:` line (`text`, after
    the key) that is not the driver's: (mm) after s_X, (MPa) after Sigma_X, (s) after t (any
    case); parentheses after anything else are skipped (interphase_driver_history's check_units)."""
    i = 0
    while i < len(text):
        if text[i] != "(":
            i += 1
            continue
        depth, close = 0, i
        while close < len(text):
            depth += (text[close] == "(") - (text[close] == ")")
            if depth == 0:
                break
            close += 1
        unit = text[i + 1:close].strip()
        before = text[:i].rstrip()
        start = len(before)
        while start > 0 and before[start - 1] not in " \t)":
            start -= 1
        name = before[start:]
        wanted = _UNITS.get(name.lower())
        if wanted is not None and unit.lower() != wanted.lower():
            raise ValueError(f'{where}: "# columns:" gives {name} the unit ({unit}), but the driver reads {name} '
                             f'in {wanted}: convert the column, and write ({wanted}) or no unit')
        i = close + 1


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
    for number, line in enumerate(_text_lines(path), 1):
        where = f"{path}:{number}"
        head, hash_, comment = line.partition("#")
        key = comment.lstrip().lower()
        if hash_ and not key.startswith("columns:") and re.match(r"columns?[ \t]*:", key):
            raise ValueError(f'{where}: "#{comment.rstrip()}" looks like a "# columns:" line, but is not one: '
                             'write the key "columns:" (one word, the colon right after it), e.g. '
                             '"# columns: t s_T Sigma_N"')
        kind = _column_words(key) if hash_ else None
        if kind == "order":
            raise ValueError(f'{where}: "#{comment.rstrip()}" names the columns in another order than the rows '
                             'are read (t, the shear component(s), then the normal one: t s_T s_N or t s_T1 s_T2 '
                             's_N): reorder the columns and the comment')
        if kind == "tractions":
            raise ValueError(f'{where}: "#{comment.rstrip()}" names traction columns, but is not a "# columns:" '
                             'line, so every column would be read as a separation: write the key "columns:" '
                             'first, e.g. "# columns: t s_T Sigma_N"')
        if hash_ and key.startswith("columns:"):
            if head.strip():
                raise ValueError(f'{where}: a "# columns:" line holds nothing before the \'#\' (here '
                                 f"'{head.strip()}'): put the data row on a line of its own")
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


_INTEGER = re.compile(r"^[+-]?[0-9]+$")


def _namelist_entries(path):
    """{group: {entry: (value, line)}} of a namelist file, read as strictly as the driver's
    pre-check reads it (drivers/interphase_driver_namelist.f90): one group of each name, each
    entry once and with one value (a quoted string, a number, .true./.false.), nothing outside a
    group. Numbers are int when written as integers, else float."""
    groups, group, name, values, entry_line = {}, None, None, [], 0
    group_lines = {}

    def fail(line, text):
        raise ValueError(f"{path}:{line}: {text}")

    def finish():
        if name is None:
            return
        if len(values) != 1:
            fail(entry_line, f"&{group}: {name} needs one value, got {len(values)}")
        kind, text = values[0]
        where = f"{path}:{entry_line}: &{group}: {name}"
        if kind == "string":
            value = text
        elif text.lower() in (".true.", "t", ".t."):
            value = True
        elif text.lower() in (".false.", "f", ".f."):
            value = False
        elif _INTEGER.match(text):
            value = int(text)
        else:
            value = _number(text, where)
        groups[group][name] = (value, entry_line)

    lines = _text_lines(path)
    for number, line in enumerate(lines, 1):
        i, n = 0, len(line)
        while i < n:
            c = line[i]
            if c in " \t":
                i += 1
            elif c == "!":
                break
            elif group is None:
                if c != "&":
                    fail(number, f'text outside a group: "{line[i:].strip()}"')
                j = i + 1
                while j < n and line[j] not in " \t,/=!":
                    j += 1
                group = line[i + 1:j].lower()
                if group in groups:
                    fail(number, f"&{group} given twice: a case file has one group of each name")
                groups[group] = {}
                group_lines[group] = number
                name, values = None, []
                i = j
            elif c == "/" or line[i:i + 4].lower() == "&end":
                finish()
                group, name, values = None, None, []
                i += 1 if c == "/" else 4
            elif c == ",":
                i += 1
            elif c == "=":
                fail(number, f'&{group}: "=" without an entry name')
            elif c in "'\"":
                j, text = i + 1, ""
                while j < n:
                    if line[j] == c:
                        if j + 1 < n and line[j + 1] == c:
                            text += c
                            j += 2
                            continue
                        break
                    text += line[j]
                    j += 1
                if j >= n:
                    fail(number, f"&{group}: a string that does not end on its line: {line[i:]}")
                if name is None:
                    fail(number, f"&{group}: a value without an entry name: {line[i:j + 1]}")
                values.append(("string", text))
                i = j + 1
            else:
                j = i
                while j < n and line[j] not in " \t,=/!":
                    j += 1
                word = line[i:j]
                k = j
                while k < n and line[k] in " \t":
                    k += 1
                if k < n and line[k] == "=":
                    finish()
                    name, values, entry_line = word.lower(), [], number
                    if name in groups[group]:
                        fail(number, f"&{group}: entry {name} given twice")
                    i = k + 1
                    continue
                if name is None:
                    fail(number, f"&{group}: a value without an entry name: {word}")
                values.append(("word", word))
                i = j
    if group is not None:
        raise ValueError(f'{path}: &{group} is not closed by "/"')
    return groups, group_lines


def read_namelist(path):
    """{group: {entry: value}} of a namelist file: quoted strings (str), numbers (int when written
    as integers, else float) and logicals (bool), one value each; the file is read as strictly as
    the driver's pre-check reads it (a group or an entry given twice, an entry with no value or
    with several, text outside a group: ValueError naming the file and the line)."""
    return {g: {k: v for k, (v, _) in entries.items()} for g, entries in _namelist_entries(path)[0].items()}


# the entries of interphase-point's groups and their kinds (drivers/interphase_driver_case.f90)
# (&material's entries are Material's, _ENTRIES; the words among them are strings, the rest numbers)
_MATERIAL_WORDS = ("model", "damage_law", "table", "rcurve", "rcurve_file", "growth_slip", "stiffness")
_KINDS = {
    "material": {k: "string" if k in _MATERIAL_WORDS else "real" for k in _ENTRIES},
    "loading": {"history": "string", "output": "string", "increments": "integer", "plot": "logical",
                "traction_tolerance": "real", "output_every": "integer", "tangent_check": "real",
                "tangent_step": "real"},
}
_KIND_WORDS = {"string": "a quoted string", "real": "a number", "integer": "an integer",
               "logical": ".true. or .false."}


def _checked_case_entries(path):
    """The case file's groups, each entry checked against its kind (as interphase-point checks
    them): ValueError naming the file, the line, the group and the entry."""
    groups, group_lines = _namelist_entries(path)
    known = ", ".join("&" + g for g in _KINDS)
    for group, entries in groups.items():
        if group not in _KINDS:
            raise ValueError(f"{path}:{group_lines[group]}: &{group} is not a group of this case file; "
                             f"its groups: {known}")
        for name, (value, line) in entries.items():
            where = f"{path}:{line}: &{group}: {name}"
            kind = _KINDS[group].get(name)
            if kind is None:
                raise ValueError(f"{where} is not an entry of &{group}; its entries: "
                                 + ", ".join(_KINDS[group]))
            good = {"string": isinstance(value, str),
                    "real": isinstance(value, (int, float)) and not isinstance(value, bool),
                    "integer": isinstance(value, int) and not isinstance(value, bool),
                    "logical": isinstance(value, bool)}[kind]
            if not good:
                raise ValueError(f"{where} = {value!r} is not {_KIND_WORDS[kind]}")
            if kind == "integer" and abs(value) > 999_999_999:   # (the driver's limit: 9 digits)
                raise ValueError(f"{where} = {value!r} is too large: an integer of at most 9 digits")
    for group in _KINDS:
        if group not in groups:
            raise ValueError(f'{path}: &{group}: group not found (expected "&{group} ... /")')
    missing = [k for k in ("history", "increments", "output") if k not in groups["loading"]]
    if missing:
        raise ValueError(f"{path}: &loading: missing entr{'ies' if len(missing) > 1 else 'y'} "
                         + ", ".join(missing))
    increments, line = groups["loading"]["increments"]
    if increments < 1:
        raise ValueError(f"{path}:{line}: &loading: increments must be at least 1, got {increments}")
    if "tangent_step" in groups["loading"] and not groups["loading"].get("tangent_check", (0.0, 0))[0] > 0.0:
        raise ValueError(f"{path}:{groups['loading']['tangent_step'][1]}: &loading: tangent_step is an entry of "
                         "the tangent check only: set tangent_check > 0 too, or drop tangent_step")
    return ({g: {k: v for k, (v, _) in entries.items()} for g, entries in groups.items()},
            {g: {k: line for k, (_, line) in entries.items()} for g, entries in groups.items()})


# The &material entry that holds the constant a PROPS status refuses (as interphase-point names it:
# drivers/interphase_driver_case.f90, props_entry); the selectors are set from the entries' words.
_PROPS_ENTRY = {_status.STATUS_BAD_MU: "mu", _status.STATUS_BAD_S0_N: "s0_n", _status.STATUS_BAD_SF_N: "sf_n",
                _status.STATUS_BAD_S0_T: "s0_t", _status.STATUS_BAD_SF_T: "sf_t", _status.STATUS_BAD_K_N: "k_n",
                _status.STATUS_BAD_K_T: "k_t", _status.STATUS_BAD_D0: "d0", _status.STATUS_BAD_RCURVE: "rcurve",
                _status.STATUS_BAD_GC_I: "g_ci", _status.STATUS_BAD_GC_II: "g_cii"}
_OPTION_ENTRY = {"contact band chi": "contact_band", "viscosity eta": "viscosity"}


def _props_entry(error):
    """The &material entry an InterphaseError of the PROPS check refers to, or None."""
    if error.status == _status.STATUS_BAD_OPTION:
        return next((entry for symbol, entry in _OPTION_ENTRY.items() if f") {symbol} =" in error.detail), None)
    return _PROPS_ENTRY.get(error.status)


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
    groups, lines = _checked_case_entries(path)
    base = os.path.dirname(os.path.abspath(path))
    entries = dict(groups["material"])
    for key in ("table", "rcurve_file"):
        if key in entries and entries[key].strip():     # ('': left out, as the driver reads it)
            entries[key] = os.path.join(base, entries[key])
    try:
        material = Material(**entries)
    except TypeError as error:          # a missing entry: name the file
        raise TypeError(f"{path}: &material: {error}") from None
    except InterphaseError as error:    # a constant out of range: name the file, its line and entry
        entry = _props_entry(error)
        if entry is None or entry not in lines["material"]:
            raise InterphaseError(error.status, f"{path}: &material: {error.detail}") from None
        raise InterphaseError(error.status, f"{path}:{lines['material'][entry]}: &material: {entry}: "
                              f"{error.detail}") from None
    loading = groups["loading"]
    time, value, control = read_history(os.path.join(base, loading["history"]), control=True)
    return Case(material, time, value, loading["increments"], loading["output"], control=control,
                traction_tolerance=float(loading.get("traction_tolerance", DEFAULT_TRACTION_TOLERANCE)),
                output_every=loading.get("output_every", 1))
