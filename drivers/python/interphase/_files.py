"""The single-point driver's files from Python: history tables and namelist case files."""

import os
import re
import struct
import sys

import numpy as np

from . import _status
from ._library import InterphaseError
from ._material import Material, DEFAULT_TRACTION_TOLERANCE, TRACTION_TOLERANCE_MAX, DEFAULT_TANGENT_STEP, _count, _path

_NUMBER = re.compile(r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eEdD][+-]?[0-9]+)?")
# why a nonzero literal below the smallest normal double is refused (interphase_text_input's UNDERFLOW_WHY)
_UNDERFLOW_WHY = "out of range (|x| < 2.2e-308)"
#: the largest file the readers take (bytes), as the driver's (interphase_text_input's MAX_FILE_BYTES)
MAX_FILE_BYTES = 64 * 1024 * 1024
#: the longest line the readers take (bytes, without its newline), as the driver's (MAX_LINE_LEN)
MAX_LINE_LEN = 65536
#: the longest text of a string entry of a case file (bytes), as the driver's (ENTRY_LEN): a longer
#: one is refused (the driver's namelist read would cut it short)
ENTRY_LEN = 1024
#: the largest |separation| of a history (mm), as the update admits (interphase_params' SEPARATION_MAX)
SEPARATION_MAX = 1.0e20
#: the largest |imposed traction| of a history (MPa): the UMAT's bound on STRESS (HOST_VALUE_MAX)
TRACTION_MAX = 1.0e150
# the driver reads a regular file in chunks of this many bytes (interphase_text_input's CHUNK_LEN):
# which of the two limits a line passes first is told chunk by chunk
_CHUNK = 4096
_BLANKS = re.compile(r"[ \t\r]+")


def _words(text):
    """The blank-separated words of `text`, blanks being space, tab and carriage return only, as
    the driver splits a line (interphase_driver_text's split_words): a no-break space (U+00A0) or
    any other character is part of a word."""
    return [w for w in _BLANKS.split(text) if w]


def _lower(text):
    """`text` with A-Z in lower case, nothing else changed (the driver's to_lower)."""
    return text.translate(_ASCII_LOWER)


_ASCII_LOWER = str.maketrans("ABCDEFGHIJKLMNOPQRSTUVWXYZ", "abcdefghijklmnopqrstuvwxyz")


def _before_comment(line):
    """`line` up to the '!' that starts a comment: a '!' inside quotes is the string's (the driver's
    control-character scan in check_namelist_file)."""
    quote = None
    for k, ch in enumerate(line):
        if quote is not None:
            if ch == quote:
                quote = None        # (a doubled quote closes and reopens)
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            return line[:k]
    return line


def _counted(count, noun):
    """A count and its noun, singular for one: '1 column', '3 columns' (the driver's count_text)."""
    return f"{count} {noun}" + ("" if count == 1 else "s")


def _clip(text):
    """At most the first 60 bytes of `text`, with '...' when cut, and a control character other
    than a tab as '?' (the driver's clip_text, for messages)."""
    raw = text.encode("utf-8", errors="surrogateescape")
    if len(raw) > 60:
        raw = raw[:57] + b"..."
    raw = bytes(63 if (b < 32 and b != 9) or b == 127 else b for b in raw)
    return raw.decode("utf-8", errors="surrogateescape")


def _text_lines(path, what=None):
    """The lines of a text file, read as the driver reads it (interphase_text_input): bytes as
    they are (UTF-8, with any other byte kept as a surrogate, so a comment in another encoding is
    read and a path named in the file opens the file of those bytes), one trailing carriage return
    dropped; a line longer than MAX_LINE_LEN bytes (a trailing carriage return counted, a comment
    too), a file larger than MAX_FILE_BYTES (/dev/zero included) and a UTF-8 byte-order mark are
    refused: ValueError 'path:line: cannot read the line: why', the driver's message. A file that
    cannot be opened raises the OSError of open(), with the driver's message when `what` names the
    file ('history file': 'absolute path: cannot open the history file: reason')."""
    try:
        f = open(path, "rb")
    except OSError as error:
        if what is None:
            raise
        raise type(error)(f"{os.path.abspath(path)}: cannot open the {what}: {error.strerror}") from None
    with f:
        data = f.read(MAX_FILE_BYTES + _CHUNK)
    lines, start, number = [], 0, 0
    while start < len(data):
        number += 1
        end = data.find(b"\n", start)
        stop = len(data) if end < 0 else end            # the line: data[start:stop], its newline at end
        line = data[start:stop]
        line = line[:-1] if line.endswith(b"\r") else line
        why = None
        too_long = stop - start > MAX_LINE_LEN
        # (the byte past the limit in this line, its newline included; both limits passed in one
        # chunk: the line's is told first)
        too_large = len(data) > MAX_FILE_BYTES and start <= MAX_FILE_BYTES <= (stop if end >= 0 else stop - 1)
        if too_long and not (too_large and (start + MAX_LINE_LEN) // _CHUNK > MAX_FILE_BYTES // _CHUNK):
            why = f"line longer than {MAX_LINE_LEN} characters"
        elif too_large:
            why = f"file larger than {MAX_FILE_BYTES} bytes"
        elif number == 1 and line.startswith(b"\xef\xbb\xbf"):
            why = "the file starts with a UTF-8 byte-order mark (bytes EF BB BF): save it without one"
        if why is not None:
            raise ValueError(f"{path}:{number}: cannot read the line: {why}")
        lines.append(line.decode("utf-8", errors="surrogateescape"))
        if end < 0:
            break
        start = end + 1
    return lines


def _real_text(value):
    """A real as the driver's messages write it (interphase_real_text's real_text: Fortran g0.d
    editing with the fewest digits that read back as the same double, a leading zero, a digit after
    a final point): -1.0, 0.0, 0.75, -0.1E-7, 0.1E+301."""
    value = float(value)
    if value != value:
        return "NaN"
    if value in (float("inf"), float("-inf")):
        return "Infinity" if value > 0 else "-Infinity"
    sign = "-" if np.signbit(value) else ""
    for digits in range(1, 18):
        mantissa, exponent = f"{abs(value):.{digits - 1}e}".split("e")
        figures = mantissa.replace(".", "")
        k = int(exponent) + 1                      # value = 0.figures * 10**k
        if value == 0.0:
            text = sign + "0." + "0" * (digits - 1)
        elif 0 <= k <= digits:                     # F editing, digits - k decimals
            text = sign + figures[:k] + "." + figures[k:]
        else:                                      # E editing: 0.figuresE+k
            text = f"{sign}.{figures}E{'-' if k < 0 else '+'}{abs(k)}"
        if struct.pack("<d", float(text)) == struct.pack("<d", value):
            break
    if text.endswith("."):
        text += "0"
    if text.startswith("."):
        text = "0" + text
    elif text.startswith("-."):
        text = "-0" + text[1:]
    return text


def _exponent_too_long(tail):
    """Whether an exponent (the text after its letter) has more than 6 digits, its leading zeros
    not counted (e+0000001 has one; e0000000 is 0): interphase_text_input's exponent_too_long."""
    first = next((i for i, c in enumerate(tail) if c not in "+-0"), None)
    return first is not None and len(tail) - first > 6


def _overflows(literal):
    """Whether a real literal lies beyond the largest double, decided from its digits and exponent
    as the driver decides it (interphase_text_input's overflows: 1.7976931348623158e308 does)."""
    mark = re.search(r"[eEdD]", literal)
    exponent = 0
    mantissa = literal
    if mark:
        tail = literal[mark.start() + 1:]
        if _exponent_too_long(tail):
            return tail[:1] != "-" and any(c not in "+-0." for c in literal[:mark.start()])
        exponent = int(tail)
        mantissa = literal[:mark.start()]
    whole, _, fraction = mantissa.lstrip("+-").partition(".")
    digits = (whole + fraction).lstrip("0")
    if not digits:
        return False
    magnitude = len(whole.lstrip("0")) if whole.strip("0") else -(len(fraction) - len(fraction.lstrip("0")))
    magnitude += exponent
    leading = digits[:17].ljust(17, "0")
    return magnitude > 309 or (magnitude == 309 and leading > "17976931348623157")


def _parse_real(text):
    """(value, None) when `text` (blanks around it aside) is one finite real literal, else (None,
    why): 'not a number', 'not finite (NaN or Inf)', 'not finite (out of range)' or, for a
    nonzero literal below the smallest normal double 2.2250738585072014e-308 (it would read as 0
    or as a subnormal), _UNDERFLOW_WHY (the driver's parse_real)."""
    field = text.strip(" \t")
    if not _NUMBER.fullmatch(field):
        word = _lower(field[1:] if field[:1] in ("+", "-") else field)
        if word in ("inf", "infinity", "nan") or word.startswith("nan("):
            return None, "not finite (NaN or Inf)"
        return None, "not a number"
    if _overflows(field):
        return None, "not finite (out of range)"
    mark = re.search(r"[eEdD]", field)
    mantissa = field[:mark.start()] if mark else field
    nonzero = any(c not in "+-0." for c in mantissa)
    if mark and field[mark.start() + 1:][:1] == "-" and _exponent_too_long(field[mark.start() + 1:]) and nonzero:
        return None, _UNDERFLOW_WHY
    value = float(field.replace("d", "e").replace("D", "e"))
    if not np.isfinite(value):
        return None, "not finite (out of range)"
    if abs(value) < sys.float_info.min and nonzero:
        return None, _UNDERFLOW_WHY
    return value, None


def _number(text, where, hint=""):
    """The number of a history's field, or ValueError with the driver's message (parse_number),
    `hint` after it."""
    value, why = _parse_real(text)
    if why is None:
        return value
    if "finite" in why:
        raise ValueError(f"{where}: '{_clip(text)}' is not a finite number {why[len('not finite '):]}{hint}")
    if "out of range" in why:
        raise ValueError(f"{where}: '{_clip(text)}' is {why}{hint}")
    raise ValueError(f"{where}: cannot parse '{_clip(text)}' as a number{hint}")


# the names of a `# columns:` line after t (file order): separation, traction
_NAMES = {3: (("s_T", "Sigma_T"), ("s_N", "Sigma_N")),
          4: (("s_T1", "Sigma_T1"), ("s_T2", "Sigma_T2"), ("s_N", "Sigma_N"))}


def _without_parentheses(text):
    """`text` with every character from a '(' to its ')', or a '[' to its ']' (to the end, if
    unclosed) a blank."""
    depth, kept, opening, closing = 0, [], "(", ")"
    for ch in text:
        if depth == 0 and ch in "([":
            opening, closing = ch, ")" if ch == "(" else "]"
        if ch == opening:
            depth += 1
        if depth > 0:
            if ch == closing:
                depth -= 1
            kept.append(" ")
        else:
            kept.append(ch)
    return "".join(kept)


def _column_names(text, where):
    """The traction flags (file order: shear(s), normal) of a `# columns:` comment (`text`: tabs
    as blanks, from the key on; interphase_driver_history's read_column_names)."""
    _check_units(text[len("columns:"):], where)
    words = _words(_without_parentheses(text[len("columns:"):]))
    if len(words) not in (3, 4):
        raise ValueError(f'{where}: "# columns:" names {_counted(len(words), "column")}; expected t and 2 (2-D) or 3 '
                         '(3-D) components, e.g. "# columns: t s_T Sigma_N"')
    # (the driver keeps the first 16 bytes of a word)
    words = [w.encode("utf-8", errors="surrogateescape")[:16].decode("utf-8", errors="surrogateescape")
             for w in words]
    if _lower(words[0]) != "t":
        raise ValueError(f"{where}: \"# columns:\" must start with t, got '{words[0]}'")
    flags = []
    for i, word in enumerate(words[1:]):
        names = _NAMES[len(words)][i]
        if _lower(word) not in (_lower(names[0]), _lower(names[1])):
            raise ValueError(f"{where}: \"# columns:\" column {i + 2} is '{word}'; expected {names[0]} or "
                             f"{names[1]} (t, the shear component(s), then the normal one)")
        flags.append(_lower(word) == _lower(names[1]))
    return len(words), flags


_COLUMN_NAMES = ("t", "s_t", "s_n", "s_t1", "s_t2", "sigma_t", "sigma_n", "sigma_t1", "sigma_t2")


def _column_words(comment):
    """What a comment (lower case) is when its words are two or more column names, after an
    optional first word `column` or `columns`, words in parentheses skipped: "units" when a
    separation's name has a length unit other than mm after it (`_foreign_length_unit`), "tractions" when one
    of them is a traction's (`# t s_T Sigma_N`: read as a plain comment it would run the tractions
    as separations), "order" when they are not in the rows' order (`# t s_N s_T`), else None
    (interphase_driver_history's column_words_kind)."""
    # (commas and semicolons separate the names too: `# t, s_T, Sigma_N`, a spreadsheet's header)
    words = _words(_without_parentheses(comment).replace(",", " ").replace(";", " "))
    if words and words[0] in ("column", "columns"):
        words = words[1:]
    if len(words) < 2 or not all(w in _COLUMN_NAMES for w in words):
        return None
    # (in mm, whatever they are, a caption below a columns line too: `# t s_T (m) s_N (m)` would run
    # metres as millimetres)
    if _foreign_length_unit(comment):
        return "units"
    if any(w.startswith("sigma_") for w in words):
        return "tractions"
    if words[0] == "t":
        words = words[1:]
    return None if words in (["s_t", "s_n"], ["s_t1", "s_t2", "s_n"]) else "order"


# length units other than mm (lower case) a comment of column names may give a separation
# (interphase_text_input's LENGTH_UNIT_WORDS but mm), and micrometres with the micro sign or Greek mu
_LENGTH_UNITS = ("m", "cm", "dm", "km", "um", "nm", "in", "inch", "inches", "ft", "mil", "micron", "microns",
                 "micrometre", "micrometer", "metre", "meter", "metres", "meters", "micrometres",
                 "\u00b5m", "\u03bcm")


def _foreign_length_unit(text):
    """'' when no word in parentheses right after a separation's name in `text` (a comment of
    column names) is a length unit other than mm, any case; else the first such name and unit as
    written ("s_T the unit (m)"): other words in parentheses are a remark (`# t s_T s_N (2-D)`;
    interphase_driver_history's foreign_length_unit)."""
    for name, unit in _parenthesised(text):
        if _lower(name) in ("s_t", "s_t1", "s_t2", "s_n") and _lower(unit) in _LENGTH_UNITS:
            return f"{name} the unit ({unit})"
    return ""


def _parenthesised(text):
    """The groups in parentheses or square brackets of a comment, in order, as (word, content): the
    word right before the group as written (blanks between allowed; a blank, tab, comma, semicolon,
    ')' or ']' ends it), what the group holds (to its ')' or ']', nested groups of its kind counted,
    or to the end; blanks trimmed) (interphase_text_input's next_parenthesised)."""
    i = 0
    while i < len(text):
        if text[i] not in "([":
            i += 1
            continue
        opening, closing = text[i], ")" if text[i] == "(" else "]"
        depth, close = 0, i
        while close < len(text):
            depth += (text[close] == opening) - (text[close] == closing)
            if depth == 0:
                break
            close += 1
        before = text[:i].rstrip(" ")
        start = len(before)
        while start > 0 and before[start - 1] not in " ,;)]\t":
            start -= 1
        yield before[start:], text[i + 1:close].strip(" ")
        i = close + 1


def _separator_hint(line):
    """'' when a data line (without its comment) holds no comma or semicolon, else the note that ends
    a wrong-column-count message; a semicolon is the separator when there is one (`0,5;0;0`: the
    comma a decimal mark, which the note names; interphase_driver_history's separator_hint). A '!'
    does not start a comment here: '#' does."""
    if "!" in line:
        return " ('!' does not start a comment in a history file: '#' does)"
    for separator in (";", ","):
        if separator in line:
            decimal = ", and a point for the decimal comma" if separator == ";" and "," in line else ""
            return (f" (the fields of a line are separated by blanks or tabs, not by '{separator}': write the "
                    f"values with blanks between them{decimal})")
    return ""


_UNITS = {"t": "s", "s_t": "mm", "s_t1": "mm", "s_t2": "mm", "s_n": "mm",
          "sigma_t": "MPa", "sigma_t1": "MPa", "sigma_t2": "MPa", "sigma_n": "MPa"}


def _check_units(text, where):
    """Refuse a unit in parentheses right after a column name of a `columns:` line (`text`, after
    the key, tabs as blanks) that is not the driver's: (mm) after s_X, (MPa) after Sigma_X, (s)
    after t (any case); parentheses after anything else are skipped (interphase_driver_history's
    check_units)."""
    for name, unit in _parenthesised(text):
        wanted = _UNITS.get(_lower(name))
        if wanted is not None and _lower(unit) != _lower(wanted):
            raise ValueError(f'{where}: "# columns:" gives {name} the unit ({unit}), but the driver reads {name} '
                             f'in {wanted}: convert the column, and write ({wanted}) or no unit')


def read_history(path, control=False):
    """A history file of interphase-point (drivers/README.md): rows `t s_T s_N` or
    `t s_T1 s_T2 s_N`, `#` comments; a comment line `# columns: t s_T Sigma_N` names the columns
    of the rows below it, each component a separation (s_X, mm) or a traction (Sigma_X, MPa).

    Returns (time, separation) (control=False; a file that imposes a traction is then an error)
    or (time, value, control) (control=True; control (nrows, ntens) booleans, true where the
    value is a traction). Values and controls are in the C interface's order, normal first
    ((s_N, s_T) or (s_N, s_T1, s_T2)), ready for Material.run.

    The file is read as the driver reads it (interphase_driver_history): words separated by
    blanks, tabs and carriage returns only (a no-break space is part of the word, which is then
    no number), lines of at most MAX_LINE_LEN bytes; what it refuses raises ValueError with the
    driver's message, naming the file and the line.
    """
    rows, flags, lines = [], [], []
    named, names_line, first_line = None, 0, 0
    for number, line in enumerate(_text_lines(path, "history file"), 1):
        where = f"{path}:{number}"
        if "\r" in line:   # (the one before the newline is dropped: old Mac line ends)
            column = line.encode("utf-8", "surrogateescape").index(b"\r") + 1      # (in bytes, as the driver counts)
            raise ValueError(f"{where}: a carriage return inside the line (column {column}): a carriage return "
                             "alone ends lines on old Macs; save the file with Unix or Windows line ends")
        head, hash_, comment = line.partition("#")
        # (the driver's columns_line_kind: tabs read as blanks, leading blanks dropped, A-Z lowered)
        text = comment.replace("\t", " ").lstrip(" ")
        key = _lower(text)
        shown = comment.rstrip(" ")
        if hash_ and not key.startswith("columns:") and re.match(r"columns?[ ]*:", key):
            raise ValueError(f'{where}: "#{shown}" looks like a "# columns:" line, but is not one: '
                             'write the key "columns:" (one word, the colon right after it), e.g. '
                             '"# columns: t s_T Sigma_N"')
        kind = _column_words(key) if hash_ else None
        if kind == "order":
            raise ValueError(f'{where}: "#{shown}" names the columns in another order than the rows '
                             'are read (t, the shear component(s), then the normal one: t s_T s_N or t s_T1 s_T2 '
                             's_N): reorder the columns and the comment')
        if kind == "units":
            raise ValueError(f'{where}: "#{shown}" gives {_foreign_length_unit(comment.replace(chr(9), " "))}, but '
                             'the driver reads separations in mm: convert the columns, and write (mm) or no unit')
        if kind == "tractions" and named is None:   # (a caption below a columns line is no mistake)
            raise ValueError(f'{where}: "#{shown}" names traction columns, but is not a "# columns:" '
                             'line, so every column would be read as a separation: write the key "columns:" '
                             'first, e.g. "# columns: t s_T Sigma_N"')
        if hash_ and key.startswith("columns:"):
            if head.strip(" \t"):
                raise ValueError(f'{where}: a "# columns:" line holds nothing before the \'#\' (here '
                                 f"'{head.strip(' ')}'): put the data row on a line of its own")
            ncolumns, named = _column_names(text, where)
            if rows and ncolumns != len(rows[0]):
                raise ValueError(f'{where}: the "# columns:" line names {_counted(ncolumns, "column")}, but the data '
                                 f'lines have {len(rows[0])}')
            names_line = number
            named = (ncolumns, named)
            continue
        words = _words(head)
        if not words:
            continue
        if not rows:
            if len(words) not in (3, 4):
                raise ValueError(f"{where}: found {_counted(len(words), 'column')}; expected 3 (t s_T s_N, 2-D) or 4 "
                                 f"(t s_T1 s_T2 s_N, 3-D){_separator_hint(head)}")
            first_line = number
            if named is not None and named[0] != len(words):
                raise ValueError(f'{where}: found {_counted(len(words), "column")}, but the "# columns:" line (line '
                                 f'{names_line}) names {named[0]}')
        elif len(words) != len(rows[0]):
            raise ValueError(f"{where}: found {_counted(len(words), 'column')}, but line {first_line} has "
                             f"{len(rows[0])}; every data line must have the same number of columns"
                             + _separator_hint(head))
        row = [_number(w, f"{where}: column {i}", _separator_hint("!") if "!" in w else "")
               for i, w in enumerate(words, 1)]
        controls = named[1] if named is not None else [False] * (len(words) - 1)
        # (the driver's checks: a separation beyond the update's range, a time step not finite)
        for i, value in enumerate(row[1:], 2):
            if controls[i - 2] and abs(value) > TRACTION_MAX:
                raise ValueError(f"{where}: column {i}: traction {_real_text(value)} MPa is beyond the range the "
                                 f"replay admits, |Sigma| <= {_real_text(TRACTION_MAX)} MPa")
            if not controls[i - 2] and abs(value) > SEPARATION_MAX:
                raise ValueError(f"{where}: column {i}: separation {_real_text(value)} mm is beyond the range the "
                                 f"update admits, |s| <= {_real_text(SEPARATION_MAX)} mm")
        if rows and not row[0] > rows[-1][0]:
            raise ValueError(f"{where}: time {_real_text(row[0])} is not greater than the previous time "
                             f"{_real_text(rows[-1][0])} (line {lines[-1]}); times must increase strictly")
        if rows and not abs(0.5 * row[0] - 0.5 * rows[-1][0]) <= 0.5 * np.finfo(np.float64).max:
            raise ValueError(f"{where}: time {_real_text(row[0])}: the time step from the previous time "
                             f"{_real_text(rows[-1][0])} (line {lines[-1]}) is not finite (beyond the largest double)")
        rows.append(row)
        flags.append(controls)
        lines.append(number)
    if len(rows) < 2:
        raise ValueError(f"{path}: needs at least 2 data rows, found {len(rows)}")
    table = np.array(rows)
    time = table[:, 0]
    value = np.concatenate([table[:, -1:], table[:, 1:-1]], axis=1)
    f = np.array(flags, dtype=bool)
    traction = np.concatenate([f[:, -1:], f[:, :-1]], axis=1)
    if control:
        return time, value, traction
    if traction.any():
        raise ValueError(f"{path}: the history imposes tractions (Sigma_ columns): read it with "
                         "read_history(path, control=True), which returns (time, value, control)")
    return time, value


_INTEGER = re.compile(r"[+-]?[0-9]+")


def _unquoted(text):
    """The text of a quoted string as written (its quotes around it, a doubled quote for one)."""
    return text[1:-1].replace(text[0] * 2, text[0])


def _untyped(quoted, text, where):
    """A value of read_namelist: a string, a logical, an int when written as an integer, else a
    float."""
    if quoted:
        return _unquoted(text)
    if _lower(text) in (".true.", "t", ".t."):
        return True
    if _lower(text) in (".false.", "f", ".f."):
        return False
    if _INTEGER.fullmatch(text):
        return int(text)
    return _number(text, where)


def _typed(kind, quoted, text, where):
    """The value of an entry of `kind`, checked as the driver's pre-check checks it (its
    finish_entry): ValueError with its message ('file:line: &group: entry = text is not ...')."""
    if kind == "real":
        value, why = (None, "not a number") if quoted else _parse_real(text)
        if why is not None:
            raise ValueError(f"{where} = {_clip(text)} is {why}")
        return value
    if kind == "integer":
        if quoted or not _INTEGER.fullmatch(text):
            raise ValueError(f"{where} = {_clip(text)} is not an integer")
        if len(text.lstrip("+-0")) > 9:
            raise ValueError(f"{where} = {_clip(text)} is too large: an integer of at most 9 digits")
        return int(text)
    if kind == "logical":
        if quoted or _lower(text) not in (".true.", ".false.", "t", "f", ".t.", ".f."):
            raise ValueError(f"{where} = {_clip(text)} is not .true. or .false.")
        return _lower(text) in (".true.", "t", ".t.")
    if not quoted:
        raise ValueError(f"{where} = {_clip(text)} is not a quoted string")
    length = len(_unquoted(text).encode("utf-8", "surrogateescape"))
    if length > ENTRY_LEN:
        raise ValueError(f"{where} = {_clip(text)} is {length} characters long: this entry takes at most "
                         f"{ENTRY_LEN} (a longer one would be cut short)")
    return _unquoted(text)


#: '&' or '$' and the name after it (a Fortran name: letters, digits, underscores)
_GROUP_MARKER = re.compile(r"[&$]([A-Za-z0-9_]+)")
#: a line that opens a group: blanks, '&' and the group's name
_GROUP_OPENER = re.compile(r"[ \t]*&([A-Za-z0-9_]+)")


def _values_shown(values, comma_after_first, real):
    """The values of an entry that takes one but got several, as written (': 0 and 75', ': 1, 2
    and 3 more'), and, where a comma split a real in two ('mu = 0,75'), the number meant with a
    decimal point; '' for no value (the driver's values_shown)."""
    if len(values) < 2:
        return ""
    (quoted_1, first), (quoted_2, second) = values[:2]
    text = f": {_clip(first)} and {_clip(second)}" if len(values) == 2 else \
        f": {_clip(first)}, {_clip(second)} and {len(values) - 2} more"
    if not real or len(values) != 2 or not comma_after_first or quoted_1 or quoted_2:
        return text
    if not re.fullmatch(r"[+-]?[0-9]+", first) or not second[:1].isdigit() or not second[:1].isascii():
        return text
    joined = f"{first}.{second}"
    if _parse_real(joined)[1] is not None:
        return text
    return (text + f" (a comma separates two values in a namelist; for the number {_clip(first)},{_clip(second)} "
            f"write a decimal point: {_clip(joined)})")


def _namelist_entries(path, known=None):
    """{group: {entry: (value, line)}} of a namelist file, read as strictly as the
    driver's pre-check reads it (drivers/interphase_driver_namelist.f90): one group of each name,
    each entry once and with a value (a quoted string, a number, .true./.false.), nothing outside
    a group, a group closed by "/" (or &end) before the next one. With `known` ({group: {entry:
    kind}}, the kinds "string", "real", "integer", "logical", and "reals", a list of 1 to
    PROPS_ENTRY_MAX reals), a group or an entry not in it, an entry of one value given several and
    a value not of its entry's kind are refused as well, where and as the driver refuses them, and
    the values are of their kinds; without, numbers are int when written as integers, else float,
    and an entry given several values is their list."""
    groups = {}
    group, name, values, entry_line, number = None, None, [], 0, 0
    after_comma = False     # the last token was a comma (an empty value follows a second one)
    comma_after_first = False   # a comma between the entry's first and second values ('mu = 0,75')
    lines = _text_lines(path, "case file")
    # the groups a '&name' inside a string could be taken for: those read (known), else those the
    # file opens
    if known is not None:
        group_names = set(known)
    else:
        group_names = {_lower(m.group(1)) for line in lines
                       for m in [_GROUP_OPENER.match(line)] if m is not None} - {"end"}

    def fail(text):
        raise ValueError(f"{path}:{number}: {text}")

    def finish():
        """Check the entry just ended (its name, its values) and keep it."""
        if name is None:
            return
        kinds = None if known is None else known[group]
        if kinds is not None and name not in kinds:
            raise ValueError(f"{path}:{entry_line}: &{group}: {_clip(name)} is not an entry of &{group}; its "
                             "entries: " + ", ".join(kinds))
        where = f"{path}:{entry_line}: &{group}: {name}"
        if kinds is not None and kinds[name] == "reals":
            # (a list of reals: each value named by its place, 'props = abc (value 3) is not a number')
            if not 1 <= len(values) <= PROPS_ENTRY_MAX:
                raise ValueError(f"{where} takes 1 to {PROPS_ENTRY_MAX} values, got {len(values)}")
            reals = []
            for j, (quoted, text) in enumerate(values, 1):
                value, why = (None, "not a number") if quoted else _parse_real(text)
                if why is not None:
                    raise ValueError(f"{where} = {_clip(text)} (value {j}) is {why}")
                reals.append(value)
            groups[group][name] = (reals, entry_line)
            return
        if kinds is None and len(values) > 1:
            # (read_namelist: an entry given several values, as props = 1, 1, 0.75, ..., is their list)
            groups[group][name] = ([_untyped(quoted, text, where) for quoted, text in values], entry_line)
            return
        if len(values) != 1:
            raise ValueError(f"{where} needs one value, got {len(values)}"
                             + _values_shown(values, comma_after_first, kinds is not None and kinds[name] == "real"))
        quoted, text = values[0]
        value = _untyped(quoted, text, where) if kinds is None else _typed(kinds[name], quoted, text, where)
        groups[group][name] = (value, entry_line)

    def add(quoted, text, column=0):
        if name is None:
            fail(f"&{group}: a value without an entry name: {_clip(text)}")
        # gfortran's namelist read, looking for a group, takes '&name' or '$name' for its start inside
        # quotes too (the driver's add_value, group_marker): column, in bytes, of the string's
        # opening quote
        marked = next((m for m in _GROUP_MARKER.finditer(text) if _lower(m.group(1)) in group_names),
                      None) if quoted else None
        if marked is not None:
            at = column + len(text[:marked.start()].encode("utf-8", "surrogateescape"))
            fail(f'&{group}: {name} = {_clip(text)} holds "{marked.group(0)}" (column {at}), which Fortran\'s '
                 'namelist read takes for the start of that group even inside quotes: a string value cannot hold '
                 '"&" or "$" followed by the name of a group')
        values.append((quoted, text))

    for number, line in enumerate(lines, 1):
        i, n = 0, len(line)
        text = _before_comment(line)     # (a comment's text is not read; a '!' inside quotes is the string's)
        bad = next((k for k, ch in enumerate(text) if ord(ch) < 32 and ch != "\t"), None)
        if bad is not None:
            fail(f"a control character (code {ord(line[bad])}) in column {bad + 1}: only blanks and tabs may "
                 "separate the text (a carriage return alone ends lines on old Macs: save the file with Unix "
                 "or Windows line ends)")
        while i < n:
            c = line[i]
            if c not in ", \t!":
                after_comma = False
            if c in " \t":
                i += 1
            elif c == "!":
                break
            elif group is None:
                if c != "&":
                    fail(f'text outside a group: "{_clip(line[i:])}"')
                j = i + 1
                while j < n and line[j] not in " \t,/=!":
                    j += 1
                group = _lower(line[i + 1:j])
                if known is not None and group not in known:
                    fail(f"&{_clip(group)} is not a group of this case file; its groups: "
                         + ", ".join("&" + g for g in known))
                if group in groups:
                    fail(f"&{group} given twice: a case file has one group of each name")
                groups[group] = {}
                name, values = None, []
                i = j
            elif c in "/&":
                if c == "&" and _lower(line[i:i + 4]) != "&end":
                    fail(f'&{group} is not closed by "/" before "{_clip(line[i:])}"')
                finish()
                group, name, values = None, None, []
                i += 1 if c == "/" else 4
            elif c == ",":
                if name is not None and (not values or after_comma):
                    where = 'right after "="' if not values else "after a comma"
                    fail(f"&{group}: {name} has an empty value (a comma {where}): give one value")
                after_comma = True
                if name is not None and len(values) == 1:
                    comma_after_first = True
                i += 1
            elif c == "=":
                fail(f'&{group}: "=" without an entry name')
            elif c in "'\"":
                j = i + 1
                while j < n:
                    if line[j] == c:
                        if j + 1 < n and line[j + 1] == c:
                            j += 2
                            continue
                        break
                    j += 1
                if j >= n:
                    fail(f"&{group}: a string that does not end on its line: {_clip(line[i:])}")
                add(True, line[i:j + 1], len(line[:i].encode("utf-8", "surrogateescape")) + 1)
                i = j + 1
            else:
                j = i
                while j < n and line[j] not in " \t,=/!":
                    j += 1
                k = j
                while k < n and line[k] in " \t":
                    k += 1
                if k < n and line[k] == "=":
                    finish()
                    name, values, entry_line = _lower(line[i:j]), [], number
                    comma_after_first = False
                    if name in groups[group]:
                        fail(f"&{group}: entry {name} given twice")
                    i = k + 1
                    continue
                add(False, line[i:j])
                i = j
    if group is not None:
        raise ValueError(f'{path}: &{group} is not closed by "/"')
    if known is not None and not groups:
        # (an empty file, or one of comments only: said so, not as a first group not found)
        names = ["&" + g for g in known]
        expected = names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]
        raise ValueError(f"{path}: no namelist group in the file (expected {expected})")
    return groups


def read_namelist(path):
    """{group: {entry: value}} of a namelist file: quoted strings (str), numbers (int when written
    as integers, else float) and logicals (bool); an entry given several values (`props = 1, 1,
    0.75, ...`) their list. The file is read as strictly as the driver's pre-check reads it (a
    group or an entry given twice, an entry with no value, text outside a group: ValueError naming
    the file and the line)."""
    return {g: {k: v for k, (v, _) in entries.items()} for g, entries in _namelist_entries(path).items()}


# the entries of interphase-point's groups and their kinds, in the driver's order (its messages
# list them so: drivers/interphase_driver_case.f90, material_entry_kinds and LOADING_ENTRIES)
_MATERIAL_WORDS = ("model", "damage_law", "table", "rcurve", "rcurve_file", "growth_slip", "stiffness")
_MATERIAL_REALS = ("mu", "s0_n", "sf_n", "s0_t", "sf_t", "k_n", "k_t", "d0", "g_ci", "g_cii", "contact_band",
                   "viscosity")
# (props: the material as the UMAT's PROPS, 1 to PROPS_ENTRY_MAX reals, the driver's
# entry_kind_type count; the longest PROPS the UMAT decodes)
PROPS_ENTRY_MAX = 20
_KINDS = {
    "material": dict([(k, "string") for k in _MATERIAL_WORDS] + [(k, "real") for k in _MATERIAL_REALS]
                     + [("props", "reals")]),
    "loading": {"history": "string", "output": "string", "increments": "integer", "plot": "logical",
                "traction_tolerance": "real", "output_every": "integer", "tangent_check": "real",
                "tangent_step": "real"},
}


def _at_entry(path, group, text, lines):
    """The message 'path: &group: text' of a check after the namelist read, with the line of the
    entry whose name `text` starts with when the file gives it: 'path:line: &group: text' (the
    driver's with_entry_line)."""
    word = re.match(r"[a-z0-9_]+", text)
    if word and word.group() in lines.get(group, {}):
        return f"{path}:{lines[group][word.group()]}: &{group}: {text}"
    return f"{path}: &{group}: {text}"


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


# the entries that PROPS hold, in the driver's order (props_material): none of them beside props
_PROPS_HELD = ("model", "damage_law", "mu", "s0_n", "sf_n", "s0_t", "sf_t", "k_n", "k_t", "d0", "rcurve", "g_ci",
               "g_cii", "growth_slip", "contact_band", "viscosity", "stiffness")


def _props_material(path, entries, base, lines):
    """The material of a &material group that gives it as the UMAT's PROPS (the entry props), as
    interphase-point's props_material checks it: no entry that PROPS hold beside props, the values
    decoded by the library (its message, under props), the files PROPS cannot name (table where
    they select a custom RVE table, rcurve_file where they select a tabulated R-curve) given
    exactly there. The files are not loaded (read_case loads them after the history). The UMAT's
    own options (layer thickness and normal, host) are refused, as the driver refuses them."""
    def blank(v):
        return isinstance(v, str) and v.strip(" ") == ""
    given = [k for k in _PROPS_HELD if k in entries and not blank(entries[k])]
    if given:
        raise ValueError(_at_entry(
            path, "material", "props gives the whole material as the UMAT's PROPS: leave out " + ", ".join(given)
            + " (or give the material by its entries, without props)", lines))
    material, custom_table, tabulated, rcurve_at = Material._of_props(entries["props"], "read_case")
    try:
        material._check_props()
    except InterphaseError as error:
        # (the library's check is the C API's, which refuses the UMAT's own options naming itself;
        # the driver names itself: 'this driver takes separations')
        detail = error.detail
        if error.status == _status.STATUS_BAD_OPTION:
            detail = detail.replace("; the C API takes separations: leave it 0",
                                    "; this driver takes separations: leave it 0")
        raise InterphaseError(error.status, _at_entry(path, "material", f"props: {detail}", lines)) from None
    table = entries.get("table", "")
    rcurve_file = entries.get("rcurve_file", "")
    if custom_table:
        if blank(table):
            raise InterphaseError(_status.STATUS_TABLE_NOT_LOADED, _at_entry(
                path, "material", "props: PROPS(8) = 1 selects a custom RVE table: give its file as the entry table",
                lines))
        material.table_path = _path("table", table, base, trim=True)
    elif not blank(table):
        raise InterphaseError(_status.STATUS_BAD_TABLE_SELECTOR, _at_entry(
            path, "material", "table is read only where props select a custom RVE table (the micromechanical model "
            "with PROPS(8) = 1)", lines))
    if tabulated:
        if blank(rcurve_file):
            raise InterphaseError(_status.STATUS_RCURVE_NOT_LOADED, _at_entry(
                path, "material", f"props: PROPS({rcurve_at + 1}) = 3 selects a tabulated R-curve: give its file as "
                "the entry rcurve_file", lines))
        material.rcurve_path = _path("rcurve_file", rcurve_file, base, trim=True)
    elif not blank(rcurve_file):
        raise InterphaseError(_status.STATUS_BAD_RCURVE, _at_entry(
            path, "material", "rcurve_file is read only where props select a tabulated R-curve (the fracture law "
            "with its R-curve code 3)", lines))
    return material


class Case:
    """A case file of interphase-point: `material` (Material), `time`, `value` and `control` (the
    history, normal first: separations, or tractions where `control` is true), `increments`,
    `traction_tolerance`, `output_every` and `output` (the CSV name the driver writes), and the
    driver's tangent check `tangent_check` and `tangent_step` (`check_tangent` makes the check on
    a result of `run`). `separation` is `value` (a history without traction control holds
    separations only)."""

    def __init__(self, material, time, value, increments, output, control=None,
                 traction_tolerance=DEFAULT_TRACTION_TOLERANCE, output_every=1, tangent_check=0.0,
                 tangent_step=DEFAULT_TANGENT_STEP):
        self.material, self.time, self.value = material, time, value
        self.control = np.zeros(value.shape, dtype=bool) if control is None else control
        self.increments, self.output = _count("increments", increments, "Case"), output
        self.traction_tolerance = traction_tolerance
        self.output_every = _count("output_every", output_every, "Case")
        self.tangent_check, self.tangent_step = tangent_check, tangent_step

    @property
    def separation(self):
        return self.value

    def run(self, tangent=False):
        """Material.run on the case's history, as interphase-point replays it."""
        return self.material.run(self.value, self.time, self.increments, tangent=tangent,
                                 control=self.control if self.control.any() else None,
                                 traction_tolerance=self.traction_tolerance, output_every=self.output_every)

    def check_tangent(self, result=None):
        """The case's tangent check (tangent_check > 0, tangent_step): Material.tangent_check on
        `result`, a run of the case with output_every = 1, or, without `result`, on a replay of
        the case made with output_every = 1 whatever the case's own (the driver checks every step,
        whatever rows it writes). Raises ValueError when the case sets no check (tangent_check =
        0)."""
        if not self.tangent_check > 0.0:
            raise ValueError("the case sets no tangent check (&loading: tangent_check = 0, the default)")
        if result is None:
            result = self.material.run(self.value, self.time, self.increments,
                                       control=self.control if self.control.any() else None,
                                       traction_tolerance=self.traction_tolerance, output_every=1)
        return self.material.tangent_check(result, self.tangent_check, step=self.tangent_step)


def read_case(path):
    """Read an interphase-point case file (drivers/README.md): its &material and &loading.

    The file is checked as the driver checks it, in its order, with its messages (naming the file,
    and the line and the entry where there is one): the pre-check (bounded lines, one group of each
    name, each entry once, known and with one value of its kind: ValueError), &material's entries
    (a missing one: TypeError; a word or an entry the model or the law does not take:
    InterphaseError), &loading's (missing, or out of range: ValueError), the constants' ranges
    (the library's check: InterphaseError), the history (read_history), then the table and the
    R-curve (InterphaseError). Paths are read without the blanks around them, and the paths it
    names (history, table, rcurve_file) are taken relative to its folder, as the driver takes them.
    The history may impose tractions (`# columns:` lines).
    """
    groups = _namelist_entries(path, _KINDS)
    values = {g: {k: v for k, (v, _) in entries.items()} for g, entries in groups.items()}
    lines = {g: {k: line for k, (_, line) in entries.items()} for g, entries in groups.items()}
    base = os.path.dirname(os.path.abspath(path))

    def found(group):
        if group not in groups:
            raise ValueError(f'{path}: &{group}: group not found (expected "&{group} ... /")')
        return values[group]

    # &material: which entries are given, and their words (the driver's material_props), or the
    # material as the UMAT's PROPS (its props_material)
    if "props" in found("material"):
        material = _props_material(path, values["material"], base, lines)
    else:
        material = None
    try:
        if material is None:
            material = Material._unchecked(found("material"), base)
    except TypeError as error:          # a missing entry
        text = str(error)
        raise TypeError(_at_entry(path, "material", text[len("Material: "):] if text.startswith("Material: ")
                                  else text, lines)) from None
    except InterphaseError as error:
        raise InterphaseError(error.status, _at_entry(path, "material", error.detail, lines)) from None

    # &loading (the driver's read_loading)
    loading = found("loading")

    def refuse(text):
        raise ValueError(_at_entry(path, "loading", text, lines))

    history = loading.get("history", "").strip(" ")
    output = loading.get("output", "").strip(" ")
    missing = [k for k, given in (("history", history != ""), ("increments", "increments" in loading),
                                  ("output", output != "")) if not given]
    if missing:
        refuse(f"missing entr{'ies' if len(missing) > 1 else 'y'} " + ", ".join(missing))
    increments = loading["increments"]
    if increments < 1:
        refuse(f"increments must be at least 1, got {increments}")
    tolerance = loading.get("traction_tolerance", DEFAULT_TRACTION_TOLERANCE)
    if not (0.0 < tolerance <= TRACTION_TOLERANCE_MAX):
        refuse(f"traction_tolerance must be a finite number > 0 and at most 1e-3 (MPa), got {_real_text(tolerance)}: "
               f"Newton meets an imposed traction only to within it (joints carry tractions of 0.01 to 10 MPa)")
    output_every = loading.get("output_every", 1)
    if output_every < 1:
        refuse(f"output_every must be at least 1, got {output_every}")
    tangent_check = loading.get("tangent_check", 0.0)
    if not (tangent_check >= 0.0 and np.isfinite(tangent_check)):
        refuse(f"tangent_check must be a finite number >= 0 (0: no check), got {_real_text(tangent_check)}")
    if tangent_check >= 1.0:
        # (the relative error max|FD - DDSDDE|/max|DDSDDE| of a tangent off by its own size is 1)
        refuse(f"tangent_check = {_real_text(tangent_check)} would pass a tangent wrong by its own size or more (a "
               "relative error >= 1): it must be < 1 (e.g. 1e-5; 0: no check)")
    tangent_step = loading.get("tangent_step", DEFAULT_TANGENT_STEP)
    if "tangent_step" in loading and not tangent_check > 0.0:
        # (the step of a check that is not made: refused, not ignored)
        refuse("tangent_step is an entry of the tangent check only: set tangent_check > 0 too, or drop "
               "tangent_step")
    if not (tangent_step > 0.0 and np.isfinite(tangent_step)):
        refuse(f"tangent_step must be a finite number > 0 (mm), got {_real_text(tangent_step)}")

    # the constants' ranges (the library's decoder), named with their entry and its line
    try:
        material._check_props()
    except InterphaseError as error:
        entry = _props_entry(error)
        if entry is None:
            raise InterphaseError(error.status, f"{path}: &material: {error.detail}") from None
        raise InterphaseError(error.status, _at_entry(path, "material", f"{entry}: {error.detail}", lines)) from None

    try:
        time, value, control = read_history(os.path.join(base, history), control=True)
    except OSError as error:
        # (a history that cannot be opened: named after the entry that names it, with its line)
        raise type(error)(_at_entry(path, "loading", f"history: {error}", lines)) from None
    # the table and the R-curve, loaded and checked (as the driver does before the replay), a
    # refusal named with the case file, the entry that names the file and its line, as the driver
    # names it; a tabulated R-curve that does not cover D0 (the update's check of the data loaded)
    # under the entry d0, with the file's D range and D0
    try:
        material.update(np.zeros(2), dt=0.0)
    except InterphaseError as error:
        entry = {"table": "table", "rcurve": "rcurve_file"}.get(getattr(error, "file_kind", None))
        if entry is None and error.status == _status.STATUS_RCURVE_OUT_OF_RANGE:
            # (D0 is the entry d0's, or props' where the material is given as PROPS)
            entry = "props" if "props" in values["material"] else "d0"
        if entry is None:
            raise
        # (detail: the driver's line; the text: the status named once, as for any InterphaseError)
        wrapped = InterphaseError(error.status, _at_entry(path, "material", f"{entry}: {error.reason}: "
                                                                            f"{error.detail}", lines))
        wrapped.args = (_at_entry(path, "material", f"{entry}: {error}", lines),)
        raise wrapped from None
    return Case(material, time, value, increments, output, control=control, traction_tolerance=float(tolerance),
                output_every=output_every, tangent_check=float(tangent_check), tangent_step=float(tangent_step))
