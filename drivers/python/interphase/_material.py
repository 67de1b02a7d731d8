"""Material, one-point update and history replay over the C interface (include/interphase.h)."""

import math
import numbers
import os
import struct
import ctypes
import functools

import numpy as np

from . import _status as st
from . import _library
from ._library import (lib, InterphaseError, detail_buffer, text_of, DETAIL_LEN, ensure_loaded, loaded_path,
                       _path_text)

# ---- the codes of the PROPS layout (src/interphase_enums.f90, docs/abaqus.md) --------------
MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL = 1, 2
DAMAGE_DISPLACEMENT, DAMAGE_FRACTURE = 1, 2
TABLE_DEFAULT, TABLE_CUSTOM = 0, 1
RCURVE_CONSTANT, RCURVE_EQUIVALENT, RCURVE_TABULATED = 1, 2, 3
GROWTH_FIXED_PI, GROWTH_FIXED_LAMBDA = 0, 1
STIFFNESS_CONSISTENT, STIFFNESS_SYMMETRIC, STIFFNESS_FIXED_DAMAGE = 0, 1, 2
#: the regime codes of the state's fourth slot and their names (the driver's CSV `state` column)
REGIME_NAMES = ("intact", "open", "stick", "slip")
#: state doubles: without / with viscous regularisation (INTERPHASE_NSTATE[_VISCOUS])
NSTATE, NSTATE_VISCOUS = 4, 5
#: halvings of one sub-increment before a replay gives up (interphase_mixed_control's MAX_HALVINGS)
MAX_HALVINGS = 10
#: Newton iterations (updates) of one mixed-control step at most (MAX_NEWTON)
MAX_NEWTON = 25
#: interphase-point's default traction_tolerance (MPa)
DEFAULT_TRACTION_TOLERANCE = 1.0e-12
#: the loosest traction_tolerance a replay takes (MPa; interphase_mixed_control's TRACTION_TOLERANCE_MAX)
TRACTION_TOLERANCE_MAX = 1.0e-3
#: interphase-point's default tangent_step (mm): the perturbation of the tangent check
DEFAULT_TANGENT_STEP = 1.0e-8

# the keyword entries of the driver's &material (drivers/interphase_driver_case.f90)
_REQUIRED = ("model", "damage_law", "mu", "s0_n", "sf_n", "s0_t", "sf_t")
_ENTRIES = _REQUIRED + ("k_n", "k_t", "table", "d0", "rcurve", "rcurve_file", "g_ci", "g_cii",
                        "growth_slip", "contact_band", "viscosity", "stiffness")


def _nstate_of(props):
    """The state size the library takes from PROPS: NSTATE_VISCOUS when the viscosity option
    PROPS(nb + 3) is > 0 (nb: the law's own PROPS, 9 simplified / 8 micromechanical, 4 more with the
    fracture law), else NSTATE."""
    n = len(props)
    nb = 9 if n > 0 and props[0] == MODEL_SIMPLIFIED else 8
    if n > 1 and props[1] == DAMAGE_FRACTURE:
        nb += 4
    return NSTATE_VISCOUS if n >= nb + 3 and props[nb + 2] > 0.0 else NSTATE


def _setstate_read_only_props(self, state):
    """Material's and Result's __setstate__: PROPS read-only again after unpickling (numpy does not
    pickle an array's writeable flag: a Material sent to a worker process came back with PROPS that
    could be changed in place, its nstate no longer theirs)."""
    self.__dict__.update(state)
    if isinstance(self.__dict__.get("props"), np.ndarray):
        self.props.flags.writeable = False


def _as_c(array):
    """A C-contiguous float64 array (a copy only when needed) and its address."""
    a = np.ascontiguousarray(array, dtype=np.float64)
    return a, a.ctypes.data


def _same_bits(a, b):
    return struct.pack("<d", a) == struct.pack("<d", b)


def _real(name, value, who="Material"):
    """The float of a numeric entry: a real number (int, float, a numpy scalar), not a string or a
    bool (interphase-point refuses a quoted number as well)."""
    if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "fiu":
        return float(value)
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (numbers.Real, np.floating, np.integer)):
        raise TypeError(f"{who}: {name} must be a number, got {value!r} ({type(value).__name__})")
    try:
        return float(value)
    except OverflowError:
        # an int (or Fraction) beyond the double range: named, as the library names a value
        # out of its range
        raise ValueError(f"{who}: {name} = {value} is beyond the range of a double (about 1.8e308)") from None


#: the largest count the C interface takes (a C int)
_INT_MAX = 2**31 - 1


def _count(name, value, who, minimum=1):
    """The int of a count (increments, output_every): an integer (int, a numpy integer), not a bool,
    a float or a string (2.5 is not 2), at least `minimum` (None: the library checks it) and at
    most a C int."""
    if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iu":
        value = value[()]
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (numbers.Integral, np.integer)):
        raise TypeError(f"{who}: {name} must be an integer, got {value!r} ({type(value).__name__})")
    value = int(value)
    if minimum is not None and value < minimum:
        raise ValueError(f"{who}: {name} must be at least {minimum}, got {value}")
    if value > _INT_MAX:
        raise ValueError(f"{who}: {name} = {value} is too large: at most {_INT_MAX} (a C int)")
    return value


def _is_real(v):
    """Whether `v` is one real number: an int or a float (Python's, numpy's, or another
    numbers.Real such as a Fraction), not a bool."""
    return isinstance(v, numbers.Real) and not isinstance(v, (bool, np.bool_))


def _kind_text(dtype):
    """What an array of `dtype` holds, in words, for a message."""
    kind = {"b": "booleans", "c": "complex numbers", "U": "strings", "S": "strings (bytes)",
            "M": "dates", "m": "time spans"}.get(dtype.kind, "values")
    return f"{kind} (dtype {dtype})"


def _bool_at(value, index=()):
    """The index of the first bool in `value` and the lists and tuples it nests, None if none."""
    if isinstance(value, (bool, np.bool_)):
        return index
    if isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            found = _bool_at(v, index + (i,))
            if found is not None:
                return found
    elif isinstance(value, np.ndarray) and value.dtype.kind == "b":
        return index
    return None


def _numbers(name, value, who):
    """A float64 array of `value`, which holds real numbers only: ints and floats (numpy's too).
    Anything else raises TypeError naming the argument, where numpy would convert it in silence or
    with a mere warning: a string ('0.5' read as 0.5), a bool (True as 1.0), a complex number (its
    imaginary part dropped), a date or a time span (as a count of days or seconds), None (as NaN)
    or another object. Rows of different lengths (a ragged list) raise ValueError naming the
    argument. A masked array with masked entries raises ValueError: numpy would drop the mask and
    the library would take the values under it."""
    _refuse_masked(name, value, who)
    try:
        a = np.asarray(value)
    except ValueError:
        # (numpy's own words, "inhomogeneous shape after 1 dimensions", name no argument)
        raise ValueError(f"{who}: {name} is ragged: its rows (or their entries) do not all have the same "
                         "length") from None
    if a.dtype.kind in "fiu":
        # (a bool among numbers in a list, [0.001, True], comes out of numpy as a number)
        index = None if isinstance(value, np.ndarray) else _bool_at(value)
        if index is not None:
            at = f" at index {index[0] if len(index) == 1 else index}" if index else ""
            raise TypeError(f"{who}: {name} must hold real numbers (ints or floats), got a bool{at}")
        return np.asarray(a, dtype=np.float64)
    if a.dtype.kind != "O":
        raise TypeError(f"{who}: {name} must hold real numbers (ints or floats), got {_kind_text(a.dtype)}")
    for index, v in np.ndenumerate(a):
        if not _is_real(v):
            at = f" at index {index[0] if len(index) == 1 else index}" if index else ""
            raise TypeError(f"{who}: {name} must hold real numbers (ints or floats), got {v!r} "
                            f"({type(v).__name__}){at}")
    try:
        return np.asarray(a, dtype=np.float64)
    except OverflowError:
        # (an int beyond the double range, as _real names it)
        raise ValueError(f"{who}: {name} holds a number beyond the range of a double (about 1.8e308)") from None


def _masked_at(value):
    """The index of the first masked entry of value (a masked array, or a list or tuple holding
    masked arrays, at any depth), () for a masked scalar, or None where nothing is masked."""
    if np.ma.isMaskedArray(value):
        if not np.ma.is_masked(value):
            return None
        return tuple(int(i) for i in np.argwhere(np.ma.getmaskarray(value))[0])
    if isinstance(value, (list, tuple)):
        for i, v in enumerate(value):
            if isinstance(v, (list, tuple)) or np.ma.isMaskedArray(v):
                at = _masked_at(v)
                if at is not None:
                    return (i,) + at
    return None


def _refuse_masked(name, value, who):
    """ValueError where value holds masked entries: numpy drops a mask in silence, and the library
    would take the values under it."""
    at = _masked_at(value)
    if at is None:
        return
    where = f" (the first at index {at[0] if len(at) == 1 else at})" if at else ""
    raise ValueError(f"{who}: {name} is a masked array with masked entries{where}: the library would take "
                     "the values under the mask; remove the masked rows (np.ma.compress_rows) or fill them")


def _shape_text(a):
    """How a message names what was given instead of the expected shape: a scalar and its value,
    or the array's shape."""
    if a.ndim == 0:
        return f"a scalar ({a[()]!r})"
    return f"shape {a.shape}"


def _ascii_lower(text):
    """`text` with A-Z in lower case, nothing else changed (the drivers' to_lower)."""
    return text.translate(_LOWER)


_LOWER = str.maketrans("ABCDEFGHIJKLMNOPQRSTUVWXYZ", "abcdefghijklmnopqrstuvwxyz")


def _word(value):
    """A word entry as the driver reads it: blanks (spaces, not tabs or other white space) around
    it dropped, A-Z in lower case."""
    return _ascii_lower(str(value).strip(" "))


# the entries that name a file (a blank or empty one given from Python is a path, not an entry left out)
_PATH_ENTRIES = ("table", "rcurve_file")


def _path(name, value, base=None, trim=False):
    """A path entry `name`, taken in the folder `base` when relative (None: the current folder).

    trim: the entry of a case file (read_case), read as the driver reads its namelist: blanks
    around it dropped (`table = 'x.dat '`). A path given from Python (a keyword, from_props) is
    taken as given, as load_table and the C API take it: one that is empty, blank or ends in a
    blank is returned as it is (not made absolute, which would make '' the folder), for the loader
    to refuse it with its message, naming it (tables/README.md)."""
    path = _path_text(name, value)
    if trim and isinstance(path, str):
        path = path.strip(" ")
    if len(path) == 0 or path[-1:] in (" ", b" "):
        return path
    return os.path.abspath(path if base is None else os.path.join(os.fspath(base), path))


def _keyword(name, value, choices, status, listed):
    """The code of an option entry given as one of `choices` (name -> code; None or blank: the
    first); another word raises with the driver's message (`listed`: the words it takes)."""
    words = list(choices)
    word = words[0] if value is None or _word(value) == "" else _word(value)
    if word not in choices:
        raise InterphaseError(status, f"{name} must be {listed}, got '{str(value).strip(' ')}'")
    return choices[word]


def _holding_files(method):
    """A Material method that loads the material's table or R-curve and calls the library holds
    the package's data lock throughout, when the material reads such a file (data_lock,
    interphase._library, looked up at each call: a forked child has a new one): threads may then
    use materials with different files at once."""
    @functools.wraps(method)
    def holding(self, *args, **kwargs):
        if self.table_path is None and self.rcurve_path is None:
            return method(self, *args, **kwargs)
        with _library.data_lock:
            return method(self, *args, **kwargs)
    return holding


class Material:
    """An interface material from the entries of interphase-point's `&material` (drivers/README.md).

    Material(model='simplified', damage_law='displacement', mu=0.75, s0_n=0.00044, sf_n=0.04,
             s0_t=0.00072, sf_t=0.06, k_n=482.7, k_t=198.8)

    Keywords (units: mm, MPa/mm, N/mm, s):
      model        'simplified' or 'micromechanical'
      damage_law   'displacement' (eqs 13-18) or 'fracture' (eqs 20-24)
      mu, s0_n, sf_n, s0_t, sf_t   friction coefficient and the damage law's separations
      k_n, k_t     spring stiffnesses (simplified model only)
      table        a custom RVE table file (micromechanical only; default: the built-in table);
                   table and rcurve_file are taken as given: one that ends in a blank, or a blank
                   or empty one, is refused as load_table refuses it
      d0, rcurve ('constant', 'equivalent', 'tabulated'), rcurve_file, g_ci, g_cii
                   the fracture-mechanics law's entries
      growth_slip ('fixed-pi', 'fixed-lambda'), contact_band, viscosity,
      stiffness ('consistent', 'symmetric', 'fixed-damage')   the options (default: off)

    The values are checked by the library itself (the UMAT's decoder): a value out of range raises
    InterphaseError with the library's status code and message (which PROPS, which range). The
    table and the R-curve files are loaded (and checked) when the material is made, and again
    whenever another file was loaded since or the file changed (they are library-wide data: a
    material that reads one holds the package's lock from loading it through its library call, so
    threads may use materials with different files at once).
    """

    def __init__(self, **entries):
        self._pack(entries)
        # the library checks every value (from_props), as interphase-point does before it reads the
        # table and the R-curve, then the data files: a zero increment on a virgin point
        self._check_props()
        self.update(np.zeros(2), dt=0.0)

    @classmethod
    def _unchecked(cls, entries, base):
        """A material whose entries are packed into PROPS, but whose values the library has not
        checked yet and whose files are not loaded (read_case checks them in the driver's order:
        _check_props, then the files at the first update); relative paths are taken in `base`."""
        self = cls.__new__(cls)
        self._pack(entries, base, trim=True)
        return self

    def _pack(self, entries, base=None, trim=False):
        """Check the entries as interphase-point's material_props does (which are given, which
        words) and pack PROPS; the values are left to the library (_check_props). Relative paths
        are taken in the folder `base` (None: the current one). trim: the entries of a case file
        (read_case), whose paths are read without the blanks around them, as the driver reads
        them; the keywords' paths are taken as given (_path)."""
        unknown = sorted(set(entries) - set(_ENTRIES))
        if unknown:
            raise TypeError("Material: unknown entries " + ", ".join(unknown) + " (the entries of "
                            "&material are " + ", ".join(_ENTRIES) + ")")
        # (None, or a text entry that is empty or blank, is an entry left out: a namelist cannot
        # tell `table = ''` from no table, and interphase-point reads both alike; blanks are spaces,
        # as for the driver: a tab is text. A keyword's path is no namelist entry: an empty or
        # blank one is a path, refused by the loader as load_table refuses it, not the built-in
        # table or no R-curve in silence)
        e = {k: v for k, v in entries.items()
             if v is not None and not (isinstance(v, str) and v.strip(" ") == "" and (trim or k not in _PATH_ENTRIES))}
        model = _word(e.get("model", ""))
        law = _word(e.get("damage_law", ""))
        missing = [k for k in _REQUIRED if k not in e]
        if model == "simplified":
            missing += [k for k in ("k_n", "k_t") if k not in e]
        if missing:
            raise TypeError("Material: missing " + ("entries " if len(missing) > 1 else "entry ")
                            + ", ".join(missing))
        self.entries = dict(e)
        self.table_path = None
        self.rcurve_path = None
        values = [_real(k, e[k]) for k in ("mu", "s0_n", "sf_n", "s0_t", "sf_t")]
        if model == "simplified":
            if "table" in e:
                raise InterphaseError(st.STATUS_BAD_TABLE_SELECTOR,
                                      "table is an entry of model = 'micromechanical' only")
            props = [MODEL_SIMPLIFIED, 0.0] + values + [_real("k_n", e["k_n"]), _real("k_t", e["k_t"])]
        elif model == "micromechanical":
            if "k_n" in e or "k_t" in e:
                raise InterphaseError(st.STATUS_BAD_NPROPS, "k_n and k_t are entries of model = "
                                      "'simplified' only (the micromechanical model takes its "
                                      "stiffness from the RVE table)")
            if "table" in e:
                self.table_path = _path("table", e["table"], base, trim)
            props = [MODEL_MICROMECHANICAL, 0.0] + values + [TABLE_CUSTOM if self.table_path else TABLE_DEFAULT]
        else:
            raise InterphaseError(st.STATUS_BAD_MODEL, f"model '{str(e['model']).strip(' ')}' is unknown "
                                  "(available: 'simplified', 'micromechanical')")
        fracture_only = ("d0", "rcurve", "rcurve_file", "g_ci", "g_cii")
        if law == "displacement":
            props[1] = DAMAGE_DISPLACEMENT
            given = [k for k in fracture_only if k in e]
            if given:       # (the first given named first, as the driver names it)
                raise InterphaseError(st.STATUS_BAD_NPROPS, f"{given[0]} is an entry of damage_law = 'fracture' "
                                      "only (as are d0, rcurve, rcurve_file, g_ci and g_cii)")
        elif law == "fracture":
            props[1] = DAMAGE_FRACTURE
            if "d0" not in e:
                raise InterphaseError(st.STATUS_BAD_D0, "missing entry d0 (initial crack a0/b, needed "
                                      "by damage_law = 'fracture')")
            if "rcurve" not in e:
                raise InterphaseError(st.STATUS_BAD_RCURVE, "missing entry rcurve ('constant', 'equivalent' or "
                                      "'tabulated', needed by damage_law = 'fracture')")
            # (the driver's order: the selected R-curve's own entries, then the other R-curves')
            rcurve = _keyword("rcurve", e["rcurve"],
                              {"constant": RCURVE_CONSTANT, "equivalent": RCURVE_EQUIVALENT,
                               "tabulated": RCURVE_TABULATED}, st.STATUS_BAD_RCURVE,
                              "'constant', 'equivalent' or 'tabulated'")
            gc = [0.0, 0.0]
            if rcurve == RCURVE_CONSTANT:
                # (the toughnesses left out named, not both when one is given: the driver's words)
                if "g_ci" not in e and "g_cii" not in e:
                    raise InterphaseError(st.STATUS_BAD_GC_I, "rcurve = 'constant' needs the entries g_ci and g_cii "
                                          "(N/mm)")
                if "g_ci" not in e or "g_cii" not in e:
                    missing, given = ("g_ci", "g_cii") if "g_ci" not in e else ("g_cii", "g_ci")
                    raise InterphaseError(st.STATUS_BAD_GC_I if missing == "g_ci" else st.STATUS_BAD_GC_II,
                                          f"rcurve = 'constant' needs the entry {missing} (N/mm; {given} is given)")
                gc = [_real("g_ci", e["g_ci"]), _real("g_cii", e["g_cii"])]
            if rcurve == RCURVE_TABULATED:
                if "rcurve_file" not in e:
                    raise InterphaseError(st.STATUS_BAD_RCURVE, "rcurve = 'tabulated' needs the entry rcurve_file")
                self.rcurve_path = _path("rcurve_file", e["rcurve_file"], base, trim)
            if rcurve != RCURVE_CONSTANT and ("g_ci" in e or "g_cii" in e):
                raise InterphaseError(st.STATUS_BAD_GC_I if "g_ci" in e else st.STATUS_BAD_GC_II,
                                      "g_ci and g_cii are entries of rcurve = 'constant' only")
            if rcurve != RCURVE_TABULATED and "rcurve_file" in e:
                raise InterphaseError(st.STATUS_BAD_RCURVE, "rcurve_file is an entry of rcurve = 'tabulated' only "
                                      f"(rcurve = '{_word(e['rcurve'])}' would not read "
                                      f"'{str(_path_text('rcurve_file', e['rcurve_file'])).strip(' ')}')")
            props += [_real("d0", e["d0"]), float(rcurve)] + gc
        else:
            raise InterphaseError(st.STATUS_BAD_DAMAGE_LAW, f"damage_law '{str(e['damage_law']).strip(' ')}' is "
                                  "unknown (available: 'displacement', 'fracture')")
        # the option constants, written up to the last one not at its default (to_props)
        options = [
            float(_keyword("growth_slip", e.get("growth_slip"), {"fixed-pi": GROWTH_FIXED_PI,
                           "fixed-lambda": GROWTH_FIXED_LAMBDA}, st.STATUS_BAD_OPTION,
                           "'fixed-pi' (the default) or 'fixed-lambda' (the paper's form)")),
            _real("contact_band", e.get("contact_band", 0.0)),
            _real("viscosity", e.get("viscosity", 0.0)),
            float(_keyword("stiffness", e.get("stiffness"), {"consistent": STIFFNESS_CONSISTENT,
                           "symmetric": STIFFNESS_SYMMETRIC, "fixed-damage": STIFFNESS_FIXED_DAMAGE},
                           st.STATUS_BAD_OPTION, "'consistent' (the default), 'symmetric' or 'fixed-damage'"))]
        nlast = max((k + 1 for k, v in enumerate(options) if not _same_bits(v, 0.0)), default=0)
        self.props = np.array([float(p) for p in props] + options[:nlast], dtype=np.float64)
        self.props.flags.writeable = False
        self.viscous = options[2] > 0.0
        self.nstate = NSTATE_VISCOUS if self.viscous else NSTATE
        self.model, self.damage_law = model, law

    @_holding_files
    def _check_props(self):
        """The library's check of the values (its decoder, from_props), before any file is loaded:
        an update of a virgin point without loading the table or the R-curve. What only the loaded
        data can tell (none loaded, an R-curve that does not cover D0) is left to the first update."""
        props, props_p = self._props_c("Material")
        s, s_p = _as_c(np.zeros(2))
        old, old_p = _as_c(self.initial_state())
        traction, tangent, new = np.empty(2), np.empty((2, 2)), np.empty(self.nstate)
        psi = ctypes.c_double()
        detail = detail_buffer()
        status = lib.interphase_update_dt(props_p, props.size, 2, old_p, s_p, 0.0, traction.ctypes.data,
                                          tangent.ctypes.data, new.ctypes.data, ctypes.byref(psi), detail,
                                          DETAIL_LEN)
        if status not in (st.STATUS_OK, st.STATUS_TABLE_NOT_LOADED, st.STATUS_RCURVE_NOT_LOADED,
                          st.STATUS_RCURVE_OUT_OF_RANGE):
            raise InterphaseError(status, text_of(detail))

    @classmethod
    def from_props(cls, props, table=None, rcurve_file=None):
        """A material from a PROPS array (docs/abaqus.md), checked by the library: a
        one-dimensional array of real numbers (ints and floats; a string, a bool or a complex
        number raises TypeError, another shape ValueError).

        table, rcurve_file: the custom RVE table and the tabulated R-curve the PROPS select
        (PROPS(8) = 1 of the micromechanical model; the R-curve selector 3 of the fracture law),
        which PROPS cannot name. Without them such a material takes the file loaded when it is
        made (by another material or by load_table / load_rcurve) and keeps it, as a material made
        with the keywords keeps its files: another file loaded later does not change its numbers.
        None loaded: InterphaseError (STATUS_TABLE_NOT_LOADED, STATUS_RCURVE_NOT_LOADED). A file
        given for PROPS that do not select one: InterphaseError (STATUS_BAD_TABLE_SELECTOR,
        STATUS_BAD_RCURVE)."""
        self, custom_table, tabulated, rcurve_at = cls._of_props(props, "Material.from_props")
        n = len(self.props)
        for name, given, selected, status, what in (
                ("table", table, custom_table, st.STATUS_BAD_TABLE_SELECTOR,
                 "a custom RVE table (PROPS(8) = 1 of the micromechanical model)"),
                ("rcurve_file", rcurve_file, tabulated, st.STATUS_BAD_RCURVE,
                 "a tabulated R-curve (the fracture law's R-curve selector 3)")):
            if given is not None and not selected:
                raise InterphaseError(status, f"Material.from_props: {name} = "
                                      f"{str(_path_text(name, given, 'Material.from_props'))!r} is given, but the "
                                      f"PROPS do not select {what}")
        if custom_table:
            self.table_path = _path("table", table) if table is not None else loaded_path("table")
        if tabulated:
            self.rcurve_path = (_path("rcurve_file", rcurve_file) if rcurve_file is not None
                                else loaded_path("rcurve"))
        # the library checks the values first (as for a material of keywords), then the files
        self._check_props()
        for path, selected, status, slot, value, what, loader, name in (
                (self.table_path, custom_table, st.STATUS_TABLE_NOT_LOADED, 8, self.props[7] if n > 7 else 0.0,
                 "the custom RVE table", "load_table", "table"),
                (self.rcurve_path, tabulated, st.STATUS_RCURVE_NOT_LOADED, rcurve_at + 1,
                 self.props[rcurve_at] if n > rcurve_at else 0.0, "the tabulated R-curve", "load_rcurve",
                 "rcurve_file")):
            if selected and path is None:
                raise InterphaseError(status, f"Material.from_props: PROPS({slot}) = {float(value)!r} selects {what}, "
                                      f"but none is loaded: name it, Material.from_props(props, {name}=path), or "
                                      f"load it first, interphase.{loader}(path)")
        self.update(np.zeros(2), dt=0.0)
        return self

    @classmethod
    def _of_props(cls, props, who):
        """A material of the PROPS array `props` (checked to be one-dimensional real numbers,
        naming `who`), its values not checked by the library and no file named: the material,
        whether PROPS select a custom RVE table and a tabulated R-curve, and the R-curve
        selector's index (0-based)."""
        props = _numbers("PROPS", props, who)
        if props.ndim != 1:
            raise ValueError(f"{who}: PROPS must be one-dimensional, got {_shape_text(props)}")
        self = cls.__new__(cls)
        self.entries = {}
        self.props = props.copy()
        self.props.flags.writeable = False
        self.table_path = self.rcurve_path = None
        n = len(self.props)
        nb = 9 if n > 0 and self.props[0] == MODEL_SIMPLIFIED else 8
        # the selectors of the files (PROPS(8) of the micromechanical model; the fracture law's
        # R-curve selector, PROPS(nb + 2))
        custom_table = n > 7 and self.props[0] == MODEL_MICROMECHANICAL and self.props[7] == TABLE_CUSTOM
        rcurve_at = nb + 1
        tabulated = n > rcurve_at and self.props[1] == DAMAGE_FRACTURE and self.props[rcurve_at] == RCURVE_TABULATED
        self.nstate = _nstate_of(self.props)
        self.viscous = self.nstate == NSTATE_VISCOUS
        self.model = self.damage_law = None
        return self, custom_table, tabulated, rcurve_at

    def __repr__(self):
        if not self.entries:
            files = "".join(f", {name}={path!r}" for name, path in (("table", self.table_path),
                                                                      ("rcurve_file", self.rcurve_path)) if path)
            return f"Material.from_props({self.props.tolist()!r}{files})"
        return "Material(" + ", ".join(f"{k}={v!r}" for k, v in self.entries.items()) + ")"

    __setstate__ = _setstate_read_only_props

    def _props_c(self, who):
        """PROPS as the library takes them, and their address; ValueError when they ask for another
        state size than this material's buffers hold (PROPS changed after the material was made:
        the library would write past the state arrays)."""
        props, props_p = _as_c(self.props)
        if _nstate_of(props) != self.nstate:
            raise ValueError(f"{who}: the material's PROPS were changed after it was made (their viscosity "
                             f"option asks for {_nstate_of(props)} state variables, the material has {self.nstate}): "
                             "make a new material, Material.from_props(props)")
        return props, props_p

    def initial_state(self):
        """The state of a virgin point: nstate zeros (D, slip_1, slip_2, regime[, inviscid D])."""
        return np.zeros(self.nstate)

    def _prepare(self):
        ensure_loaded("table", self.table_path)
        ensure_loaded("rcurve", self.rcurve_path)

    @_holding_files
    def update(self, separation, state=None, dt=None, separation_old=None):
        """One update at `separation` (s_N, s_T) or (s_N, s_T1, s_T2) (mm) from `state`.

        Returns an Update (traction (MPa), tangent (MPa/mm, tangent[i, j] = d t_i/d s_j),
        state, stored_energy (N/mm)); `dt` (s) is the time increment, which viscous
        regularisation needs; `separation_old` (mm, the separation's shape) is the separation
        at the start of the increment, where `state` was reached: a crack that closes within the
        increment then starts its friction from the slip where the faces met, as in the UMAT and
        in run() (without it, from the state's slip: docs/theory.md, 'An increment across which
        the crack closes'). Raises InterphaseError on a failed update; TypeError when the
        separation, separation_old or the state holds anything but real numbers (ints and floats).

        The separation's length makes the update 2-D or 3-D. A state whose second slip
        state[2] (lambda_2) is not zero is a 3-D one: a 2-D update refuses it (InterphaseError,
        STATUS_BAD_STATE), where the library's 2-D update (as the UMAT's) would ignore it and
        return it as 0. A 2-D state goes on in 3-D as the state with lambda_2 = 0 it is. A state
        with D = 0 and a slip is refused as the UMAT's STATEV reader refuses it (InterphaseError,
        STATUS_BAD_STATE: an intact point has no crack, so no slip; docs/python.md).
        """
        self._prepare()
        s = _numbers("separation", separation, "Material.update")
        if s.ndim != 1 or s.size not in (2, 3):
            raise ValueError("Material.update: separation must hold 2 (2-D) or 3 (3-D) components, got "
                             f"{_shape_text(s)}")
        s, s_p = _as_c(s)
        n = s.size
        if isinstance(state, Update):
            # (the update itself in place of its state: the usual slip of a loop u = m.update(s, u))
            raise TypeError("Material.update: state must be the state array, got an Update: pass its state, "
                            "update(separation, u.state)")
        old = self.initial_state() if state is None else _numbers("state", state, "Material.update")
        if old.shape != (self.nstate,):
            why = (" (viscous regularisation: the 5th is the inviscid damage D_v, STATEV(5); initial_state() "
                   "makes one)" if self.viscous else "")
            raise ValueError(f"Material.update: state must hold {self.nstate} values{why}, got {_shape_text(old)}")
        old, old_p = _as_c(old)
        if n == 2 and not old[2] == 0.0:
            # (the library's 2-D update, as the UMAT's, does not read STATEV(3) and writes it 0: a 3-D
            # state would lose its second slip in silence)
            raise InterphaseError(st.STATUS_BAD_STATE, f"Material.update: STATEV(3) lambda_2 = {float(old[2])!r} mm "
                                  "(state[2], the slip in the second shear direction) is not zero, but the "
                                  "separation (s_N, s_T) is 2-D: a 2-D update does not read lambda_2 and would "
                                  "return it as 0. Go on in 3-D, separation (s_N, s_T1, s_T2), or pass a 2-D state "
                                  "(state[2] = 0)")
        props, props_p = self._props_c("Material.update")
        traction = np.empty(n)
        tangent = np.empty((n, n))
        new = np.empty(self.nstate)
        psi = ctypes.c_double()
        detail = detail_buffer()
        if separation_old is not None:
            s_old = _numbers("separation_old", separation_old, "Material.update")
            if s_old.shape != (n,):
                raise ValueError(f"Material.update: separation_old must hold {n} components, as the separation, "
                                 f"got {_shape_text(s_old)}")
            s_old, s_old_p = _as_c(s_old)
            dt_c = None if dt is None else ctypes.byref(ctypes.c_double(_real("dt", dt, "Material.update")))
            status = lib.interphase_update_increment(props_p, props.size, n, old_p, s_old_p, s_p, dt_c,
                                                     traction.ctypes.data, tangent.ctypes.data, new.ctypes.data,
                                                     ctypes.byref(psi), detail, DETAIL_LEN)
        elif dt is None:
            status = lib.interphase_update(props_p, props.size, n, old_p, s_p, traction.ctypes.data,
                                           tangent.ctypes.data, new.ctypes.data, ctypes.byref(psi),
                                           detail, DETAIL_LEN)
        else:
            status = lib.interphase_update_dt(props_p, props.size, n, old_p, s_p, _real("dt", dt, "Material.update"),
                                              traction.ctypes.data, tangent.ctypes.data, new.ctypes.data,
                                              ctypes.byref(psi), detail, DETAIL_LEN)
        if status != st.STATUS_OK:
            if status == st.STATUS_BAD_TIME_INCREMENT and dt is None:
                # (the library's message names its C entries)
                raise InterphaseError(status, "the material has viscous regularisation (its viscosity option): "
                                      "pass the time increment, Material.update(separation, state, dt=...)")
            raise InterphaseError(status, text_of(detail))
        return Update(traction, tangent, new, psi.value)

    @_holding_files
    def run(self, history, time=None, increments=1, tangent=False, control=None,
            traction_tolerance=DEFAULT_TRACTION_TOLERANCE, output_every=1):
        """Replay a history at one point, as interphase-point does (drivers/README.md).

        history: (nrows, ntens) array, each row normal first as in the C interface, (s_N, s_T) or
        (s_N, s_T1, s_T2): the separation (mm), or the traction (MPa) where `control` is true (a
        history file lists the shear first: read_history turns it). control: None (every component
        separation-controlled), or booleans of shape (ntens,) (the same for every row) or (nrows,
        ntens), true where the component is traction-controlled; the segment that ends at a row is
        controlled as that row says (mixed control: a traction-controlled component's separation is
        found by Newton's method on the tangent, to within traction_tolerance (MPa), in at most 25
        updates per step). time: nrows strictly increasing times (default 0, 1, 2, ...);
        increments: equal sub-increments per segment; output_every: a row every k-th converged step
        (and at the end of every segment); tangent: True to return each row's tangent (a bool:
        anything else raises TypeError). The history has at least 2 rows (ValueError), as the
        driver's; the counts are integers (an int or a numpy integer: a bool, a float or a string
        raises TypeError, not rounded), increments at least 1 (ValueError), output_every at least 1
        (InterphaseError, STATUS_BAD_HISTORY); history, time and traction_tolerance hold real
        numbers (ints and floats: a string, a bool, a complex number, a date, None raises
        TypeError), control booleans (TypeError).

        The point starts virgin at zero separation; a first row away from zero is reached first in
        `increments` steps at time[0] (not returned). A step that fails is halved and retried, up to
        MAX_HALVINGS times, each converged step giving a row. The whole loop runs inside the library
        (interphase_run_history, the algorithm of interphase-point).

        Returns a Result with one row per converged step, the start (time[0]) first. On a failure
        the InterphaseError raised carries the library's status and message (e.g.
        STATUS_BEYOND_PEAK: an imposed traction beyond the peak the material can carry) and the rows
        computed until then as its `result` (None when there are none), as the driver's CSV holds
        them.
        """
        self._prepare()
        value = _numbers("history", history, "Material.run")
        if value.ndim != 2 or value.shape[1] not in (2, 3):
            hint = ""
            if value.ndim == 2 and value.shape[0] in (2, 3):
                # (the components stacked as rows, np.array([s_n, s_t]): one column per row)
                hint = (f": one row per point, (s_N, s_T) or (s_N, s_T1, s_T2); for the components stacked as "
                        f"rows, as np.array([s_n, s_t]) makes them, pass the transpose (history.T, shape "
                        f"{value.shape[::-1]})")
            raise ValueError(f"Material.run: history must be an (nrows, 2) or (nrows, 3) array, got "
                             f"{_shape_text(value)}{hint}")
        nrows, n = value.shape
        if nrows < 2:
            raise ValueError(f"Material.run: history must have at least 2 rows (one segment; interphase-point "
                             f"needs 2 data rows too), got {nrows}")
        t = np.arange(nrows, dtype=np.float64) if time is None else _numbers("time", time, "Material.run")
        if t.shape != (nrows,):
            raise ValueError(f"Material.run: time must hold {nrows} values, got {_shape_text(t)}")
        bad = np.flatnonzero(~np.isfinite(t))
        if bad.size:
            raise ValueError(f"Material.run: time[{bad[0]}] = {float(t[bad[0]])!r} is not finite")
        with np.errstate(over="ignore"):     # (a step beyond the largest double: the library refuses it)
            bad = np.flatnonzero(~(np.diff(t) > 0.0))
        if bad.size:
            i = bad[0] + 1
            raise ValueError(f"Material.run: time must increase strictly: time[{i}] = {float(t[i])!r} is not "
                             f"greater than time[{i - 1}] = {float(t[i - 1])!r}")
        if not isinstance(tangent, (bool, np.bool_)):
            # (not truth-tested: tangent='no' or tangent=0.0 would be taken as a wish, either way)
            raise TypeError(f"Material.run: tangent must be True or False, got {tangent!r}")
        increments = _count("increments", increments, "Material.run")
        # (output_every < 1 and traction_tolerance are checked by the library: STATUS_BAD_HISTORY)
        output_every = _count("output_every", output_every, "Material.run", minimum=None)
        traction_tolerance = _real("traction_tolerance", traction_tolerance, "Material.run")
        if control is None:
            ctrl = None
        else:
            _refuse_masked("control", control, "Material.run")
            try:
                c = np.asarray(control)
            except ValueError:
                raise ValueError("Material.run: control is ragged: its rows do not all have the same length") from None
            if c.dtype != np.bool_:
                raise TypeError(f"Material.run: control must hold booleans (true: traction-controlled), got "
                                f"{_kind_text(c.dtype)}")
            if c.shape not in ((n,), (nrows, n)):
                raise ValueError(f"Material.run: control must have shape ({n},) or ({nrows}, {n}), got "
                                 f"{_shape_text(c)}")
            ctrl = np.ascontiguousarray(np.broadcast_to(c, (nrows, n)), dtype=np.intc)
        value = np.ascontiguousarray(value)
        t = np.ascontiguousarray(t)
        props, props_p = self._props_c("Material.run")
        # rows: the start, one per output_every-th sub-increment and the end of every segment; more
        # where steps are halved (the library then says STATUS_OUTPUT_FULL, and the run is made
        # again with 4 times the room)
        capacity = 1 + ((nrows - 1) * increments) // output_every + (nrows - 1) if output_every >= 1 else 1
        capacity += capacity // 8 + 16
        while True:
            try:
                out_t = np.empty(capacity)
                out_s = np.empty((capacity, n))
                out_tr = np.empty((capacity, n))
                out_state = np.empty((capacity, self.nstate))
                out_psi = np.empty(capacity)
                out_w = np.empty(capacity)
                out_k = np.empty((capacity, n, n)) if tangent else None
            except MemoryError:
                # (numpy's message names a shape, not what asked for it)
                per_row = 8 * (1 + 2 * n + self.nstate + 2 + (n * n if tangent else 0))
                raise MemoryError(f"Material.run: {capacity} rows of output ({capacity * per_row / 2**30:.3g} GiB) "
                                  f"do not fit in memory: {nrows - 1} segment(s) x increments = {increments} / "
                                  f"output_every = {output_every} rows; ask for fewer rows (a larger output_every "
                                  f"or fewer increments)") from None
            done = ctypes.c_size_t(0)
            detail = detail_buffer()
            status = lib.interphase_run_history(
                props_p, props.size, n, nrows, t.ctypes.data, value.ctypes.data,
                None if ctrl is None else ctrl.ctypes.data, increments, traction_tolerance,
                output_every, capacity, out_t.ctypes.data, out_s.ctypes.data, out_tr.ctypes.data,
                out_state.ctypes.data, out_psi.ctypes.data, out_w.ctypes.data,
                None if out_k is None else out_k.ctypes.data, ctypes.byref(done), detail, DETAIL_LEN)
            if status != st.STATUS_OUTPUT_FULL:
                break
            capacity *= 4
        k = done.value
        result = None
        if k > 0:
            result = Result(out_t[:k].copy(), out_s[:k].copy(), out_tr[:k].copy(), out_state[:k].copy(),
                            out_psi[:k].copy(), out_w[:k].copy(), None if out_k is None else out_k[:k].copy(),
                            material=self, output_every=output_every)
        if status != st.STATUS_OK:
            error = InterphaseError(status, text_of(detail))
            error.result = result
            raise error
        return result


    @_holding_files
    def tangent_check(self, result, tolerance, step=DEFAULT_TANGENT_STEP):
        """interphase-point's tangent check (`tangent_check`, drivers/README.md) over a Result of
        this material's `run` made with output_every=1: at every step after the first the update
        from the previous row's state to the row's separation is repeated, and its tangent is
        compared with the central finite difference of the traction (each component moved by
        +-step, mm) from that same state; where the forward and backward differences disagree by
        more than tolerance x the tangent's scale (a kink within +-step: a change of regime, a
        reversal, s_N = 0) with the nearer one-sided one. The error of a step is
        max|FD - tangent| / max|tangent| (the driver's CSV column tangent_error, the same numbers).

        The first row is not checked (the steps that reach it, when the history starts away from
        zero, are not returned; the driver checks them too). Returns a TangentCheck; a check that
        compared no step (every perturbed update failed, e.g. a step that takes the separation
        beyond the range the update admits) has not passed, as the driver's fails. Raises
        ValueError when the result is the run of another material (other PROPS, table or
        R-curve file), when a row is not the update of the previous row's state, bit for bit (a
        run with output_every > 1 skips steps; where the law is path-independent over them, as in
        a monotonic segment, the rows still are, and are checked as the larger increments they
        are), or when tolerance is not a finite number > 0 and < 1 (a relative error of 1 is a
        tangent wrong by its own size) or step not a finite number > 0.
        """
        self._prepare()
        tolerance = _real("tolerance", tolerance, "Material.tangent_check")
        step = _real("step", step, "Material.tangent_check")
        if not (tolerance > 0.0 and math.isfinite(tolerance)):
            raise ValueError(f"Material.tangent_check: tolerance must be a finite number > 0, got {tolerance!r}")
        if tolerance >= 1.0:
            raise ValueError(f"Material.tangent_check: tolerance = {tolerance!r} would pass a tangent wrong by its "
                             "own size or more (a relative error >= 1): it must be < 1 (e.g. 1e-5)")
        if not (step > 0.0 and math.isfinite(step)):
            raise ValueError(f"Material.tangent_check: step must be a finite number > 0 (mm), got {step!r}")
        other = self._other_material(result)
        if other is not None:
            raise ValueError(f"Material.tangent_check: the result is the run of another material ({other}): "
                             "check it with the material that ran it")
        nrows, n = result.separation.shape
        errors = np.full(nrows, np.nan)
        checked = kinks = unchecked = 0
        for k in range(1, nrows):
            old = result.state[k - 1]
            s = result.separation[k].copy()
            dt = result.time[k] - result.time[k - 1]
            # (from the row before, as the run took the step: a crack that closes within it starts
            # its friction from the slip where its faces met)
            s_old = result.separation[k - 1]
            base = self.update(s, old, dt=dt, separation_old=s_old)
            if not (np.array_equal(base.traction, result.traction[k]) and np.array_equal(base.state, result.state[k])):
                every = getattr(result, "output_every", None)
                if every is None:
                    why = "pass a result of this material's run made with output_every=1"
                elif every > 1:
                    why = (f"the run kept one step in {every} (output_every={every}), and the steps it skipped "
                           "count: run the history with output_every=1")
                else:
                    why = "the result's arrays are not those its run returned"
                raise ValueError(f"Material.tangent_check: row {k} (t = {float(result.time[k])!r}) is not the update "
                                 f"of row {k - 1}'s state: {why}")
            tangent = base.tangent
            scale = float(np.max(np.abs(tangent)))
            column_error = np.zeros(n)
            kink = False
            failed = False
            for j in range(n):
                probe = s.copy()
                try:
                    probe[j] = s[j] + step
                    plus = self.update(probe, old, dt=dt, separation_old=s_old).traction
                    probe[j] = s[j] - step
                    minus = self.update(probe, old, dt=dt, separation_old=s_old).traction
                except InterphaseError:
                    failed = True
                    break
                central = (plus - minus) / (2.0 * step)
                forward = (plus - base.traction) / step
                backward = (base.traction - minus) / step
                scale = max(scale, float(np.max(np.abs(central))))
                column_error[j] = np.max(np.abs(central - tangent[:, j]))
                if np.max(np.abs(forward - backward)) > tolerance * max(scale, np.finfo(float).tiny):
                    kink = True
                    one_sided = min(np.max(np.abs(forward - tangent[:, j])), np.max(np.abs(backward - tangent[:, j])))
                    column_error[j] = min(column_error[j], one_sided)
            if failed:
                unchecked += 1
                continue
            errors[k] = float(np.max(column_error)) / scale if scale > 0.0 else 0.0
            checked += 1
            kinks += int(kink)
        return TangentCheck(result.time, errors, tolerance, step, checked, kinks, unchecked,
                            separation=result.separation, state=result.state, mu=float(self.props[2]))


    def _other_material(self, result):
        """How the material that ran `result` differs from this one (its PROPS, table or R-curve
        file), or None: the same, or not known (a Result made by hand)."""
        props = getattr(result, "props", None)
        if props is None:
            return None
        if props.shape != self.props.shape or not np.array_equal(props.view(np.uint64), self.props.view(np.uint64)):
            if props.shape != self.props.shape:
                return f"{props.size} PROPS, this material {self.props.size}"
            i = int(np.flatnonzero(props.view(np.uint64) != self.props.view(np.uint64))[0])
            return f"its PROPS({i + 1}) = {float(props[i])!r}, this material's {float(self.props[i])!r}"
        for what, theirs, mine in (("table", result.table_path, self.table_path),
                                   ("rcurve_file", result.rcurve_path, self.rcurve_path)):
            if theirs != mine:
                return f"its {what} {theirs!r}, this material's {mine!r}"
        return None


class Update:
    """The result of Material.update: traction, tangent, state, stored_energy."""

    __slots__ = ("traction", "tangent", "state", "stored_energy")

    def __init__(self, traction, tangent, state, stored_energy):
        self.traction, self.tangent, self.state, self.stored_energy = traction, tangent, state, stored_energy

    def __iter__(self):
        return iter((self.traction, self.tangent, self.state, self.stored_energy))

    def __repr__(self):
        return (f"Update(traction={self.traction!r}, tangent={self.tangent!r}, state={self.state!r}, "
                f"stored_energy={self.stored_energy!r})")


class TangentCheck:
    """Material.tangent_check's outcome: errors (one per row of the Result: the relative error of
    the tangent at that step, NaN for the first row and for a step whose perturbed update failed),
    worst, worst_time and worst_row (the largest error, its row's time and index; 0, NaN and None
    when none was checked), checked, kinks (steps compared one-sided) and unchecked (steps not
    checked), tolerance and step, as interphase-point's summary line reports them; passed (at least
    one step compared, and worst <= tolerance) and, when it has not, failure: why, in the driver's
    words (a check that compared no step fails: every perturbed update failed, or there was no
    step), with the worst row's separation and, where that row is the check's one documented
    exception, that it is.

    exception_rows: the checked rows at the tangent check's one documented exception
    (drivers/README.md, 'The tangent check'; docs/theory.md, 'Slip onset'): a closed, damaged crack
    (D > 0) that sticks at s_N = 0 exactly with mu > 0. There Sigma_N = 0, so a stick state has the
    crack shear stress tau = 0 and phi = mu sigma + |tau| = 0 (the apex of the Coulomb cone): any
    change of s_T makes the crack slip, and the tangent, the stick one, is not the derivative of
    both sides (a crack held at s = 0 after it closed there: relative error 0.36 at the hold; the
    step that closes it there passes, its start slip being where the faces met: docs/theory.md).
    worst_elsewhere and worst_elsewhere_row: the
    largest error of the other checked rows (0 and None when there are none)."""

    def __init__(self, time, errors, tolerance, step, checked, kinks, unchecked, separation=None, state=None,
                 mu=None):
        self.errors, self.tolerance, self.step = errors, tolerance, step
        self.checked, self.kinks, self.unchecked = checked, kinks, unchecked
        valid = ~np.isnan(errors)
        if valid.any():
            k = int(np.flatnonzero(valid)[np.argmax(errors[valid])])
            self.worst, self.worst_time, self.worst_row = float(errors[k]), float(time[k]), k
        else:
            self.worst, self.worst_time, self.worst_row = 0.0, math.nan, None
        apex = np.zeros(errors.shape, dtype=bool)
        if separation is not None and state is not None and mu is not None and mu > 0.0:
            apex = (valid & (separation[:, 0] == 0.0) & (state[:, 0] > 0.0)
                    & (state[:, 3] == REGIME_NAMES.index("stick")))
        self.exception_rows = np.flatnonzero(apex)
        elsewhere = valid & ~apex
        if elsewhere.any():
            j = int(np.flatnonzero(elsewhere)[np.argmax(errors[elsewhere])])
            self.worst_elsewhere, self.worst_elsewhere_row = float(errors[j]), j
        else:
            self.worst_elsewhere, self.worst_elsewhere_row = 0.0, None
        self.passed = checked > 0 and self.worst <= tolerance
        from ._files import _real_text          # (the driver's writing of reals; _files imports this module)
        if checked == 0 and unchecked > 0:
            self.failure = (f"the tangent check compared no step: a perturbed call failed at every step ({unchecked} "
                            f"not checked; tangent_step = {_real_text(step)} mm)")
        elif checked == 0:
            self.failure = "the tangent check compared no step: the result has no step after its first row"
        elif not self.passed:
            k = self.worst_row
            where = f"row {k}"
            if separation is not None:
                names = ("s_N", "s_T") if separation.shape[1] == 2 else ("s_N", "s_T1", "s_T2")
                where += ", " + ", ".join(f"{name} = {_real_text(v)}" for name, v in zip(names, separation[k])) + " mm"
            self.failure = (f"the tangent check failed: worst relative error {_real_text(self.worst)} at t = "
                            f"{_real_text(self.worst_time)} ({where}) is above the tolerance {_real_text(tolerance)}")
            if apex[k]:
                self.failure += (
                    "; that row is the tangent check's one documented exception: a closed, damaged crack that "
                    "sticks at s_N = 0 exactly, where Sigma_N = 0 and tau = 0 (the apex of the Coulomb cone), so "
                    "that any change of s_T makes it slip and its stick tangent is not the derivative of both "
                    "sides (drivers/README.md, 'The tangent check'); ")
                if self.worst_elsewhere_row is None:
                    self.failure += "every row checked is such a row"
                else:
                    j = self.worst_elsewhere_row
                    verdict = "within" if self.worst_elsewhere <= tolerance else "above"
                    self.failure += (f"rows at this exception: {self.exception_rows.size}; away from them the worst "
                                     f"relative error is {_real_text(self.worst_elsewhere)} at t = {_real_text(time[j])} "
                                     f"(row {j}), {verdict} the tolerance")
        else:
            self.failure = None

    def __repr__(self):
        return (f"TangentCheck(worst={self.worst!r} at t = {self.worst_time!r}, checked={self.checked}, "
                f"kinks={self.kinks}, unchecked={self.unchecked}, tolerance={self.tolerance!r}, "
                f"passed={self.passed})")


class Result:
    """A replayed history: one row per converged step, numpy arrays.

    time (nrows), separation and traction (nrows, ntens; normal first, mm and MPa), damage
    (nrows), slip (nrows, ntens - 1; mm), regime (nrows, codes; regime_names their names),
    stored_energy and dissipated_energy (nrows; N/mm: the UMAT's SSE and SPD), state (nrows,
    nstate) and, when asked for, tangent (nrows, ntens, ntens; MPa/mm; NaN in the first row when
    the history starts at zero separation, as no step reached it). props, table_path,
    rcurve_path and output_every say which material's run made it and how (None for a Result made
    by hand from arrays): Material.tangent_check refuses another material's.
    """

    def __init__(self, time, separation, traction, state, stored_energy, dissipated_energy, tangent=None,
                 material=None, output_every=None):
        self.time, self.separation, self.traction, self.state = time, separation, traction, state
        self.props = None if material is None else material.props
        self.table_path = None if material is None else material.table_path
        self.rcurve_path = None if material is None else material.rcurve_path
        self.output_every = output_every
        self.stored_energy, self.dissipated_energy, self.tangent = stored_energy, dissipated_energy, tangent
        self.ntens = separation.shape[1]
        self.damage = state[:, 0]
        self.slip = state[:, 1:self.ntens]
        self.regime = state[:, 3].astype(int)

    __setstate__ = _setstate_read_only_props

    def __len__(self):
        return self.time.size

    @property
    def regime_names(self):
        return [REGIME_NAMES[c] for c in self.regime]

    def csv_rows(self):
        """The rows of interphase-point's CSV (its header first), as text lines."""
        if self.ntens == 2:
            yield "t,s_T,s_N,Sigma_T,Sigma_N,D,slip,state,psi,W_dis"
        else:
            yield "t,s_T1,s_T2,s_N,Sigma_T1,Sigma_T2,Sigma_N,D,slip_1,slip_2,state,psi,W_dis"
        shear_first = list(range(1, self.ntens)) + [0]
        for r in range(len(self)):
            fields = ([self.time[r]] + [self.separation[r, c] for c in shear_first]
                      + [self.traction[r, c] for c in shear_first] + [self.damage[r]]
                      + list(self.slip[r]))
            yield ",".join([format_csv(v) for v in fields] + [REGIME_NAMES[self.regime[r]],
                                                               format_csv(self.stored_energy[r]),
                                                               format_csv(self.dissipated_energy[r])])

    def to_csv(self, path):
        """Write the table as interphase-point writes its CSV (the same text, number for number)."""
        with open(path, "w", encoding="ascii", newline="\n") as f:
            for line in self.csv_rows():
                f.write(line + "\n")


def format_csv(x):
    """A number as the driver writes it: Fortran ES24.16E3 (17 significant digits)."""
    x = float(x)
    if not math.isfinite(x):
        return "Infinity" if x > 0 else ("-Infinity" if x < 0 else "NaN")
    mantissa, exponent = f"{x:.16E}".split("E")
    e = int(exponent)
    return f"{mantissa}E{'-' if e < 0 else '+'}{abs(e):03d}"
