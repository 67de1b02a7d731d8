"""The package's Material: its entries and the library's checks, one-point updates in 2-D and
3-D against closed forms and finite differences, the run's contract (rows, halvings, failures),
table and R-curve loading, and concurrent use from threads."""

import ctypes
import fractions
import os
import pathlib
import re
import subprocess
import sys
import threading
import time
import warnings

import numpy as np
import pytest

import interphase

K_N, K_T = 482.69742679680568, 198.75776397515528
SIMPLIFIED = dict(model="simplified", damage_law="displacement", mu=0.75, s0_n=0.00044, sf_n=0.04,
                  s0_t=0.00072, sf_t=0.06, k_n=K_N, k_t=K_T)
MICRO = dict(model="micromechanical", damage_law="displacement", mu=0.75, s0_n=0.00044, sf_n=0.04,
             s0_t=0.00072, sf_t=0.06)


def test_props_are_the_umat_layout():
    m = interphase.Material(**SIMPLIFIED)
    assert m.props.tolist() == [1, 1, 0.75, 0.00044, 0.04, 0.00072, 0.06, K_N, K_T]
    assert m.nstate == interphase.NSTATE
    f = interphase.Material(**dict(MICRO, damage_law="fracture", d0=0.02, rcurve="constant", g_ci=0.01,
                                   g_cii=0.02, stiffness="fixed-damage"))
    assert f.props.tolist() == [2, 2, 0.75, 0.00044, 0.04, 0.00072, 0.06, 0, 0.02, 1, 0.01, 0.02, 0, 0, 0, 2]
    v = interphase.Material(**dict(SIMPLIFIED, viscosity=0.1))
    assert v.props.tolist()[9:] == [0, 0, 0.1] and v.nstate == interphase.NSTATE_VISCOUS
    same = interphase.Material.from_props(f.props)
    assert np.array_equal(same.props, f.props) and same.nstate == 4


@pytest.mark.parametrize("change, status, words", [
    (dict(sf_n=1e-4), interphase.STATUS_BAD_SF_N, "PROPS(5) sf_N = 0.1E-3 is out of range: must be > s0_N = PROPS(4) = 0.44E-3 mm"),
    (dict(mu=-1.0), interphase.STATUS_BAD_MU, "PROPS(3) mu = -1.0 is out of range"),
    (dict(k_t=float("nan")), interphase.STATUS_BAD_K_T, "PROPS(9)"),
    (dict(s0_t=0.0), interphase.STATUS_BAD_S0_T, "PROPS(6)"),
    (dict(model="spring"), interphase.STATUS_BAD_MODEL, "model 'spring' is unknown"),
    (dict(damage_law="plastic"), interphase.STATUS_BAD_DAMAGE_LAW, "damage_law 'plastic' is unknown"),
    (dict(stiffness="secant"), interphase.STATUS_BAD_OPTION,
     "stiffness must be 'consistent' (the default), 'symmetric' or 'fixed-damage', got 'secant'"),
    (dict(growth_slip="free"), interphase.STATUS_BAD_OPTION, "growth_slip must be 'fixed-pi' (the default) or"),
    (dict(contact_band=0.01), interphase.STATUS_BAD_OPTION, "PROPS(11) contact band chi"),
    (dict(viscosity=-1.0), interphase.STATUS_BAD_OPTION, "PROPS(12) viscosity eta"),
    (dict(table="x.dat"), interphase.STATUS_BAD_TABLE_SELECTOR, "table is an entry of model = 'micromechanical'"),
    (dict(d0=0.1), interphase.STATUS_BAD_NPROPS, "d0 is an entry of damage_law = 'fracture' only"),
    (dict(damage_law="fracture"), interphase.STATUS_BAD_D0, "missing entry d0"),
    (dict(damage_law="fracture", d0=1.5, rcurve="equivalent"), interphase.STATUS_BAD_D0, "PROPS(10) D0"),
    (dict(damage_law="fracture", d0=0.1, rcurve="constant", g_ci=0.01), interphase.STATUS_BAD_GC_II,
     "rcurve = 'constant' needs the entry g_cii (N/mm; g_ci is given)"),
    (dict(damage_law="fracture", d0=0.1, rcurve="constant", g_cii=0.01), interphase.STATUS_BAD_GC_I,
     "rcurve = 'constant' needs the entry g_ci (N/mm; g_cii is given)"),
    (dict(damage_law="fracture", d0=0.1, rcurve="constant"), interphase.STATUS_BAD_GC_I,
     "rcurve = 'constant' needs the entries g_ci and g_cii (N/mm)"),
    (dict(damage_law="fracture", d0=0.1, rcurve="equivalent", g_ci=0.01), interphase.STATUS_BAD_GC_I,
     "rcurve = 'constant' only"),
    (dict(damage_law="fracture", d0=0.1, rcurve="measured"), interphase.STATUS_BAD_RCURVE, "rcurve must be"),
    (dict(damage_law="fracture", d0=0.1, g_ci=0.01, g_cii=0.02), interphase.STATUS_BAD_RCURVE,
     "missing entry rcurve"),
    (dict(damage_law="fracture", d0=0.1, rcurve=" "), interphase.STATUS_BAD_RCURVE, "missing entry rcurve"),
    (dict(damage_law="fracture", d0=0.1, rcurve="equivalent", viscosity=1.0), interphase.STATUS_BAD_OPTION,
     "displacement-driven law"),
])
def test_bad_entries_raise_the_library_status(change, status, words):
    with pytest.raises(interphase.InterphaseError) as caught:
        interphase.Material(**dict(SIMPLIFIED, **change))
    error = caught.value
    assert error.status == status, str(error)
    assert words in str(error)
    assert error.reason == interphase.status_message(status)
    assert isinstance(error, ValueError)


def test_missing_and_unknown_entries_are_type_errors():
    with pytest.raises(TypeError, match="missing entries k_n, k_t"):
        interphase.Material(**{k: v for k, v in SIMPLIFIED.items() if k not in ("k_n", "k_t")})
    with pytest.raises(TypeError, match="unknown entries s0"):
        interphase.Material(s0=1.0, **SIMPLIFIED)
    with pytest.raises(interphase.InterphaseError, match="k_n and k_t are entries of model = 'simplified'"):
        interphase.Material(**dict(MICRO, k_n=1.0))


@pytest.mark.parametrize("ntens", [2, 3])
def test_elastic_update_is_the_spring_law(ntens):
    m = interphase.Material(**SIMPLIFIED)
    s = np.array([1e-4, 2e-4, -1.5e-4][:ntens])
    u = m.update(s)
    k = np.diag([K_N] + [K_T] * (ntens - 1))
    assert np.allclose(u.traction, k @ s, rtol=1e-15, atol=0)
    assert np.array_equal(u.tangent, k)
    assert u.stored_energy == pytest.approx(0.5 * s @ k @ s, rel=1e-14)
    assert u.state.tolist() == [0, 0, 0, 0]
    traction, tangent, state, psi = u       # an Update unpacks
    assert psi == u.stored_energy


@pytest.mark.parametrize("material", [SIMPLIFIED, MICRO], ids=["simplified", "micro"])
@pytest.mark.parametrize("ntens", [2, 3])
def test_tangent_is_the_derivative(material, ntens):
    """Consistent tangent against central differences on a damaging, slipping step."""
    m = interphase.Material(**material)
    start = m.run(np.array([[0.0, 0.0, 0.0][:ntens], [-0.002, 0.01, 0.004][:ntens]]), increments=50)
    state = start.state[-1]
    s = start.separation[-1] + np.array([-0.0001, 0.001, 0.0005][:ntens])
    u = m.update(s, state)
    h = 1e-8
    for j in range(ntens):
        e = np.zeros(ntens)
        e[j] = h
        fd = (m.update(s + e, state).traction - m.update(s - e, state).traction) / (2 * h)
        assert np.allclose(u.tangent[:, j], fd, rtol=1e-4, atol=1e-3 * np.abs(u.tangent).max()), (j, u.tangent, fd)


def test_run_rows_and_energies():
    m = interphase.Material(**SIMPLIFIED)
    r = m.run([[0.0, 0.0], [0.05, 0.0]], increments=100, tangent=True)
    assert len(r) == 101 and r.ntens == 2
    assert r.time[0] == 0 and r.time[-1] == 1
    assert r.damage[0] == 0 and r.damage[-1] == 1
    assert r.regime_names[0] == "intact" and r.regime_names[-1] == "open"
    assert np.all(np.diff(r.damage) >= 0)
    # the whole mode-I fracture energy 1/2 K_N s0_N sf_N is dissipated at full damage (to the
    # trapezoidal rule's error of the increments)
    assert r.dissipated_energy[-1] == pytest.approx(0.5 * K_N * 0.00044 * 0.04, rel=2e-2)
    assert r.stored_energy[-1] == 0
    assert np.isnan(r.tangent[0]).all() and r.tangent.shape == (101, 2, 2)
    # each row's tangent is that of a one-point update from the previous row
    u = m.update(r.separation[40], r.state[39])
    assert np.array_equal(u.tangent, r.tangent[40]) and np.array_equal(u.traction, r.traction[40])


def test_run_starts_away_from_zero_after_a_preload():
    m = interphase.Material(**SIMPLIFIED)
    r = m.run([[-0.005, 0.0], [-0.005, 0.01]], time=[2.0, 3.0], increments=10)
    assert len(r) == 11 and r.time[0] == 2.0
    assert r.separation[0].tolist() == [-0.005, 0.0]
    assert r.traction[0][0] == pytest.approx(-0.005 * K_N)


def test_run_refuses_a_separation_beyond_the_range_before_any_update():
    # (it ran, and gave up after 10 halvings at an interpolated separation)
    m = interphase.Material(**SIMPLIFIED)
    with pytest.raises(interphase.InterphaseError, match=re.escape("value[2] (row 1, component 0: s_N) = 0.2E+21 mm")) \
            as caught:
        m.run([[0.0, 0.0], [2e20, 0.0]])
    assert caught.value.status == interphase.STATUS_SEPARATION_OUT_OF_RANGE and caught.value.result is None


def test_run_input_checks():
    m = interphase.Material(**SIMPLIFIED)
    with pytest.raises(ValueError, match="time must increase"):
        m.run([[0, 0], [0.01, 0]], time=[1.0, 1.0])
    # the row and the values named; a time that is not finite is said to be so
    with pytest.raises(ValueError, match=re.escape("time[2] = 1.0 is not greater than time[1] = 2.0")):
        m.run([[0, 0], [0.01, 0], [0.02, 0]], time=[0.0, 2.0, 1.0])
    with pytest.raises(ValueError, match=re.escape("time[1] = nan is not finite")):
        m.run([[0, 0], [0.01, 0]], time=[0.0, float("nan")])
    # a time increment is finite and >= 0 whatever the material (only viscosity reads it)
    for dt, text in ((float("nan"), "NaN"), (-1.0, "-1.0000E+000"), (float("inf"), "Infinity")):
        with pytest.raises(interphase.InterphaseError, match=re.escape(f"dt = {text} s: the time increment must be "
                                                                       "finite and >= 0")) as caught:
            m.update([0.001, 0.0], dt=dt)
        assert caught.value.status == interphase.STATUS_BAD_TIME_INCREMENT
    assert m.update([0.001, 0.0], dt=0.0).traction[0] == m.update([0.001, 0.0]).traction[0]
    with pytest.raises(ValueError, match="shape"):
        m.run([0.0, 0.01])
    with pytest.raises(ValueError, match="increments"):
        m.run([[0, 0], [0.01, 0]], increments=0)
    # a value that is not finite: refused before any update, naming its row and component
    with pytest.raises(interphase.InterphaseError,
                       match=re.escape("value[2] (row 1, component 0: s_N) = NaN is not finite")) as caught:
        m.run([[0, 0], [float("nan"), 0]])
    assert caught.value.status == interphase.STATUS_BAD_HISTORY
    with pytest.raises(ValueError, match="state must hold 4"):
        m.update([0.0, 0.0], np.zeros(5))


def test_viscous_material_needs_time_increments():
    m = interphase.Material(**dict(SIMPLIFIED, viscosity=0.5))
    with pytest.raises(interphase.InterphaseError, match=re.escape("Material.update(separation, state, dt=...)")) \
            as caught:
        m.update([0.001, 0.0], m.initial_state())
    assert caught.value.status == interphase.STATUS_BAD_TIME_INCREMENT
    # a state of the model without regularisation (4 values) says what the 5th is
    with pytest.raises(ValueError, match=re.escape("state must hold 5 values (viscous regularisation: the 5th is "
                                                   "the inviscid damage D_v, STATEV(5); initial_state() makes one), "
                                                   "got shape (4,)")):
        m.update([0.001, 0.0], np.zeros(4), dt=0.1)
    assert m.run([[0, 0], [0.01, 0]], tangent=np.True_).tangent.shape == (2, 2, 2)
    slow = m.run([[0, 0], [0.01, 0]], time=[0, 100.0], increments=50)
    fast = m.run([[0, 0], [0.01, 0]], time=[0, 0.01], increments=50)
    assert fast.damage[-1] < slow.damage[-1]          # the damage lags behind when loaded fast


def test_tables_and_rcurves(source_dir, tmp_path):
    builtin = interphase.Material(**MICRO)
    custom = interphase.Material(**dict(MICRO, table=source_dir / "tables" / "paper-resolution.dat"))
    s = [0.001, 0.002]
    # the two tables are different data: different numbers past first cracking
    assert not np.array_equal(builtin.run([[0, 0], s], increments=20).traction,
                              custom.run([[0, 0], s], increments=20).traction)
    bad = tmp_path / "bad.dat"
    bad.write_text("# b = 1\n0 1 2\n")
    with pytest.raises(interphase.InterphaseError) as caught:
        interphase.Material(**dict(MICRO, table=bad))
    assert 50 <= caught.value.status <= 59 and "bad.dat" in str(caught.value)
    rcurve = tmp_path / "rcurve.txt"
    rcurve.write_text("# D G_cI G_cII\n0.0 0.005 0.0085\n1.0 0.005 0.0085\n")
    tab = interphase.Material(**dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="tabulated",
                                     rcurve_file=rcurve))
    const = interphase.Material(**dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="constant",
                                       g_ci=0.005, g_cii=0.0085))
    a = tab.run([[0, 0], [0.02, 0.01]], increments=40)
    b = const.run([[0, 0], [0.02, 0.01]], increments=40)
    assert np.allclose(a.traction, b.traction, rtol=1e-9, atol=1e-12)
    with pytest.raises(interphase.InterphaseError) as caught:
        interphase.Material(**dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="tabulated",
                                   rcurve_file=tmp_path / "none.txt"))
    assert caught.value.status == interphase.STATUS_RCURVE_UNREADABLE


def test_from_props_keeps_its_table_and_rcurve(source_dir, tmp_path):
    """PROPS select a custom table or a tabulated R-curve but cannot name it: from_props takes the
    file named (table=, rcurve_file=) or the one loaded when it is made, and keeps it when another
    material loads another file (the library keeps one of each)."""
    history = [[0, 0], [0.05, 0.01]]
    resolution = source_dir / "tables" / "paper-resolution.dat"
    custom = interphase.Material(**dict(MICRO, table=resolution))
    expected = custom.run(history, increments=50).traction
    bound = interphase.Material.from_props(custom.props)          # the table loaded now
    named = interphase.Material.from_props(custom.props, table=resolution)
    assert bound.table_path == named.table_path == str(resolution)
    assert "table=" in repr(bound)
    other = interphase.Material(**dict(MICRO, table=source_dir / "tables" / "paper-dense.dat"))
    assert not np.array_equal(other.run(history, increments=50).traction, expected)
    assert np.array_equal(bound.run(history, increments=50).traction, expected)
    assert np.array_equal(named.run(history, increments=50).traction, expected)
    first, second = tmp_path / "first.txt", tmp_path / "second.txt"
    first.write_text("0.0 0.01 0.02\n1.0 0.015 0.03\n")
    second.write_text("0.0 0.05 0.10\n1.0 0.06 0.12\n")
    tab = interphase.Material(**dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="tabulated",
                                     rcurve_file=first))
    w_first = tab.run(history, increments=50).dissipated_energy[-1]
    same = interphase.Material.from_props(tab.props)
    interphase.load_rcurve(second)
    assert same.rcurve_path == str(first)
    assert same.run(history, increments=50).dissipated_energy[-1] == w_first
    # a file for PROPS that select none, and none loaded in a fresh process
    with pytest.raises(interphase.InterphaseError, match="table = 'x.dat' is given, but the PROPS do not select "
                       "a custom RVE table") as caught:
        interphase.Material.from_props(interphase.Material(**MICRO).props, table="x.dat")
    assert caught.value.status == interphase.STATUS_BAD_TABLE_SELECTOR
    with pytest.raises(interphase.InterphaseError, match="rcurve_file = 'x.txt' is given"):
        interphase.Material.from_props(custom.props, rcurve_file="x.txt")
    code = ("import interphase\n"
            "for props in ([2, 1, 0.75, 0.00044, 0.04, 0.00072, 0.06, 1],\n"
            "              [2, 2, 0.75, 0.00044, 0.04, 0.00072, 0.06, 0, 0.02, 3, 0, 0]):\n"
            "    try:\n"
            "        interphase.Material.from_props(props)\n"
            "    except interphase.InterphaseError as e:\n"
            "        print(e.status, e.detail)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.splitlines() == [
        f"{interphase.STATUS_TABLE_NOT_LOADED} Material.from_props: PROPS(8) = 1.0 selects the custom RVE table, "
        "but none is loaded: name it, Material.from_props(props, table=path), or load it first, "
        "interphase.load_table(path)",
        f"{interphase.STATUS_RCURVE_NOT_LOADED} Material.from_props: PROPS(10) = 3.0 selects the tabulated "
        "R-curve, but none is loaded: name it, Material.from_props(props, rcurve_file=path), or load it "
        "first, interphase.load_rcurve(path)"]


def test_an_edited_file_is_loaded_again(tmp_path):
    """An R-curve or table edited and saved under the same name is read again by the next material
    that names it (not the copy loaded before), and refused if the edit broke it."""
    rcurve = tmp_path / "edited.txt"
    entries = dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="tabulated", rcurve_file=rcurve)
    history = [[0, 0], [0.05, 0.02]]
    first, second = "0.0 0.01 0.02\n1.0 0.015 0.03\n", "0.0 0.05 0.10\n1.0 0.06 0.12\n"
    rcurve.write_text(first)
    w_first = interphase.Material(**entries).run(history, increments=100).dissipated_energy[-1]
    rcurve.write_text(second)
    w_second = interphase.Material(**entries).run(history, increments=100).dissipated_energy[-1]
    (tmp_path / "fresh.txt").write_text(second)
    w_fresh = interphase.Material(**dict(entries, rcurve_file=tmp_path / "fresh.txt")).run(
        history, increments=100).dissipated_energy[-1]
    assert w_second == w_fresh and w_second != w_first
    rcurve.write_text("0.0 nan 0.10\n1.0 0.06 0.12\n")
    with pytest.raises(interphase.InterphaseError) as caught:
        interphase.Material(**entries)
    assert "edited.txt" in str(caught.value)
    # the same for a table: a copy of the built-in one, then broken
    table = tmp_path / "table.dat"
    table.write_text((pathlib.Path(os.environ["INTERPHASE_SOURCE_DIR"]) / "tables" / "paper.dat").read_text())
    interphase.Material(**dict(MICRO, table=table)).update([0.001, 0.0])
    table.write_text(table.read_text().replace("# columns:", "# columns: extra", 1))
    with pytest.raises(interphase.InterphaseError) as caught:
        interphase.Material(**dict(MICRO, table=table))
    assert "table.dat" in str(caught.value)


def test_run_sizes_its_output_for_the_rows_it_writes():
    """output_every: the output arrays hold the rows written, not every sub-increment (10**6
    sub-increments written every 10**5: 12 rows, not 11 MB of rows)."""
    import tracemalloc
    m = interphase.Material(**SIMPLIFIED)
    tracemalloc.start()
    r = m.run([[0, 0], [0.001, 0]], increments=10**6, output_every=10**5)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert len(r) == 11 and r.time[-1] == 1.0
    assert peak < 10**6, f"peak {peak} bytes"


def test_blank_text_entries_are_left_out(source_dir, tmp_path):
    """A case file's table = '' (or blanks) is no table, as interphase-point reads it from a
    namelist: the built-in one for the micromechanical model; its rcurve_file = '' is no file. A
    word keyword left empty is its default. (A path keyword is a path: the next test.)"""
    s = [[0, 0], [0.001, 0.002]]
    builtin = interphase.Material(**MICRO).run(s, increments=10).traction
    interphase.Material(**dict(SIMPLIFIED, growth_slip="", stiffness=" "))
    case = (source_dir / "drivers" / "cases" / "micro" / "h1I.nml").read_text()
    assert "&material" in case
    (tmp_path / "h1I.txt").write_text((source_dir / "drivers" / "cases" / "h1I.txt").read_text())
    case = case.replace("'../h1I.txt'", "'h1I.txt'")
    for blank in ("''", "'  '"):
        blanked = case.replace("\n&material\n", f"\n&material\n  table = {blank}\n", 1)
        assert "'h1I.txt'" in blanked and f"table = {blank}" in blanked
        (tmp_path / "blank.nml").write_text(blanked)
        read = interphase.read_case(tmp_path / "blank.nml")
        assert read.material.table_path is None
        assert np.array_equal(read.material.run(s, increments=10).traction, builtin)
    fracture = CASE.replace("'displacement'", "'fracture', d0 = 0.1, rcurve = 'tabulated', rcurve_file = '  '")
    with pytest.raises(interphase.InterphaseError, match="rcurve = 'tabulated' needs the entry rcurve_file"):
        interphase.read_case(write_case(tmp_path, fracture))


@pytest.mark.parametrize("name, given", [
    ("x.dat ", "x.dat "), ("x.dat ", b"x.dat "), ("x.dat ", pathlib.Path("x.dat ")),
    ("x.dat", "  "), ("x.dat", ""), ("x.dat", b"  "), ("x.dat", b"")],
    ids=["str", "bytes", "PathLike", "blank", "empty", "blank-bytes", "empty-bytes"])
def test_a_keyword_path_is_taken_as_given(source_dir, tmp_path, monkeypatch, name, given):
    """A table or rcurve_file given as a keyword (or to from_props) is a path, as load_table and
    the C API take it (tables/README.md): one that ends in a blank, or a blank or empty one, is
    refused with load_table's own message, whether str, bytes or os.PathLike; not trimmed into
    another file's name, nor the built-in table (or no R-curve) in silence. Only read_case trims
    (the previous tests)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / name).write_bytes((source_dir / "tables" / "paper-resolution.dat").read_bytes())
    (tmp_path / f"r{name}").write_text("# D G_cI G_cII\n0.0 0.005 0.0085\n1.0 0.005 0.0085\n")
    text = os.fsdecode(os.fspath(given))
    for kind, make, load in (
            ("table", lambda: interphase.Material(**dict(MICRO, table=given)), interphase.load_table),
            ("table", lambda: interphase.Material.from_props(interphase.Material(**dict(MICRO, table=name)).props,
                                                             table=given), interphase.load_table),
            ("rcurve_file", lambda: interphase.Material(**dict(SIMPLIFIED, damage_law="fracture", d0=0.1,
                                                               rcurve="tabulated", rcurve_file=given)),
             interphase.load_rcurve)):
        with pytest.raises(interphase.InterphaseError) as refused:
            load(given)
        with pytest.raises(interphase.InterphaseError) as caught:
            make()
        assert (caught.value.status, str(caught.value)) == (refused.value.status, str(refused.value)), kind
        if text.strip(" "):
            assert f'the path "{text}" ends in a blank' in str(caught.value), kind
        else:
            assert ("is empty" if text == "" else f'the path is blank ("{text}")') in str(caught.value), kind
    # a path entry of a material that takes none is refused as given, not dropped as blank
    with pytest.raises(interphase.InterphaseError, match="table is an entry of model = 'micromechanical' only"):
        interphase.Material(**dict(SIMPLIFIED, table=given))
    with pytest.raises(interphase.InterphaseError, match="rcurve_file is an entry of damage_law = 'fracture' only"):
        interphase.Material(**dict(SIMPLIFIED, rcurve_file=given))


def test_an_rcurve_that_runs_out_stops_the_run(source_dir):
    case = interphase.read_case(source_dir / "tests" / "driver" / "inputs" / "rcurve_runs_out.nml")
    with pytest.raises(interphase.InterphaseError, match="covers D from 0.00000 to 0.300000") as caught:
        case.run()
    assert caught.value.status == interphase.STATUS_RCURVE_OUT_OF_RANGE


def test_read_history(source_dir, tmp_path):
    t, s = interphase.read_history(source_dir / "drivers" / "cases" / "mixed.txt")
    assert t.tolist() == [0, 1, 2, 3, 4, 5, 6]
    assert s.shape == (7, 2) and np.all(s[:, 0] == -0.005) and s[2, 1] == 0.05
    t3, s3 = interphase.read_history(source_dir / "drivers" / "cases" / "mixed3d.txt")
    assert s3.shape[1] == 3
    bad = tmp_path / "bad.txt"
    bad.write_text("0 0 0\n1 0 1-2\n")
    with pytest.raises(ValueError, match="bad.txt:2: column 3: cannot parse '1-2' as a number"):
        interphase.read_history(bad)
    # old Mac line ends (a carriage return alone): the driver's message, which names the column
    cr = tmp_path / "cr.txt"
    cr.write_bytes(b"0 0 0\r1 0.01 0\r")
    with pytest.raises(ValueError, match=re.escape("cr.txt:1: a carriage return inside the line (column 6): a "
                                                   "carriage return alone ends lines on old Macs")):
        interphase.read_history(cr)


def test_read_case_takes_the_material_as_props(source_dir, tmp_path):
    """A &material given as the UMAT's PROPS (props = ...) is the material its entries give: the
    same PROPS, bit for bit, and the same run; the micromechanical fracture law of
    drivers/cases/fracture/mixed-constant.nml too, with the growth-slip option constant appended at
    its default."""
    by_entries = interphase.read_case(write_case(tmp_path, CASE))
    by_props = interphase.read_case(write_case(tmp_path, CASE.replace(CASE_MATERIAL, PROPS_MATERIAL), name="p.nml"))
    assert by_props.material.props.tobytes() == by_entries.material.props.tobytes()
    assert interphase.read_namelist(tmp_path / "p.nml")["material"]["props"] == [
        1, 1, 0.75, 0.00044, 0.04, 0.00072, 0.06, 482.69742679680568, 198.75776397515528]
    assert np.array_equal(by_props.run().traction, by_entries.run().traction)
    named = interphase.read_case(source_dir / "drivers" / "cases" / "fracture" / "mixed-constant.nml")
    given = interphase.read_case(source_dir / "tests" / "driver" / "inputs" / "props_fracture.nml")
    assert given.material.props.tolist() == named.material.props.tolist() + [0.0]
    s = [[0, 0], [0.004, -0.005]]
    assert np.array_equal(given.material.run(s, increments=20).traction, named.material.run(s, increments=20).traction)


def test_read_case_checks_as_the_driver_does(source_dir, tmp_path):
    """read_case refuses what interphase-point refuses, with the same file, line and entry."""
    good = (source_dir / "drivers" / "cases" / "h1I.nml").read_text()
    (tmp_path / "h1I.txt").write_text((source_dir / "drivers" / "cases" / "h1I.txt").read_text())
    mu_line = next(i for i, line in enumerate(good.splitlines(), 1) if line.strip() == "mu = 0.75")
    cases = {
        "comma": (good.replace("mu = 0.75", "mu = 2,5"), r"comma.nml:\d+: &material: mu needs one value, got 2: 2 and 5 "
                                                         r"\(a comma separates two values in a namelist; for the "
                                                         r"number 2,5 write a decimal point: 2\.5\)"),
        "two": (good.replace("mu = 0.75", "mu = 0.75 0.5"), r"two.nml:\d+: &material: mu needs one value, got 2: 0\.75 "
                                                            r"and 0\.5$"),
        "typo": (good.replace("sf_t", "sf_tt"), r"typo.nml:\d+: &material: sf_tt is not an entry of &material; "
                                                r"its entries: model, damage_law"),
        "group": (good.replace("&loading", "&load"), r"group.nml:\d+: &load is not a group of this case file"),
        "integer": (good.replace("increments = ", "increments = 2.5 !"), r"increments = 2.5 is not an integer"),
        "string": (good.replace("mu = 0.75", "mu = '0.75'"), r"mu = '0.75' is not a number"),
        # an empty value (the namelist read misreads it or keeps the default)
        "empty": (good.replace("mu = 0.75", "mu = ,0.75"), r"empty.nml:\d+: &material: mu has an empty value"),
        "control": (good.replace("mu = 0.75", "mu = 0.75\r  s0_n = 0.00044"),
                    r"control.nml:\d+: a control character \(code 13\) in column 12"),
        "empty2": (good.replace("mu = 0.75", "mu = 0.75,,"), r"&material: mu has an empty value \(a comma after"),
        # a '!' inside quotes starts no comment: the control character after it is refused too
        "bang": (good.replace("output = 'h1I.csv'", "output = 'o!\x01.csv'"),
                 r"bang.nml:\d+: a control character \(code 1\) in column 15"),
        # a constant the PROPS check refuses: named with its entry's line, as by interphase-point
        "range": (good.replace("mu = 0.75", "mu = -0.75"),
                  rf"range.nml:{mu_line}: &material: mu: PROPS\(3\) mu = -0.75 is out of range"),
        # the step of a tangent check that is not made
        "tangent_step": (good.replace("increments = ", "tangent_step = 1e-7\n  increments = "),
                         r"tangent_step.nml:\d+: &loading: tangent_step is an entry of the tangent check only"),
    }
    assert "mu = 0.75" in good and "sf_t" in good and "&loading" in good and "increments = " in good
    assert "output = 'h1I.csv'" in good
    for name, (text, message) in cases.items():
        path = tmp_path / f"{name}.nml"
        path.write_text(text)
        with pytest.raises(ValueError, match=message):
            interphase.read_case(path)
    (tmp_path / "ok.nml").write_text(good)
    assert interphase.read_case(tmp_path / "ok.nml").increments >= 1
    # a control character in a comment is not read (review)
    (tmp_path / "ff.nml").write_text(good.replace("mu = 0.75", "mu = 0.75 ! page\f"))
    assert interphase.read_case(tmp_path / "ff.nml").increments >= 1
    # a history named with non-ASCII characters (UTF-8), and a comment in another encoding
    (tmp_path / "h\u00e9.txt").write_text((source_dir / "drivers" / "cases" / "h1I.txt").read_text())
    (tmp_path / "accent.nml").write_bytes(b"! s\xb5m\n" + good.replace("'h1I.txt'", "'h\u00e9.txt'").encode("utf-8"))
    assert "'h1I.txt'" in good
    assert interphase.read_case(tmp_path / "accent.nml").increments >= 1


def test_numbers_are_read_as_the_driver_reads_them():
    """_parse_real: a nonzero literal below the smallest normal double is out of range (not 0, not
    a subnormal); leading zeros of an exponent do not count towards its length."""
    from interphase._files import _parse_real
    for text in ("1e-400", "-1e-400", "1e-310", "4.9e-324", "2.2250738585072e-308", "1e-9999999",
                 "1e-00000000000400", "000.00001e-304"):
        assert _parse_real(text) == (None, "out of range (|x| < 2.2e-308)"), text
    for text in ("0", "-0.0", "0e-400", "0.000e-9999999", "0d99999999"):
        assert _parse_real(text) == (0.0, None), text
    assert _parse_real("2.2250738585072014e-308") == (2.2250738585072014e-308, None)
    assert _parse_real("1e0000000") == (1.0, None)
    assert _parse_real("1.5E+000000000000002") == (150.0, None)
    assert _parse_real("2.5d-0000001") == (0.25, None)
    assert _parse_real("1e1000000") == (None, "not finite (out of range)")
    assert _parse_real("1e+00001000000") == (None, "not finite (out of range)")


def test_numeric_entries_must_be_numbers():
    for value in ("0.75", "1.0e", True):
        with pytest.raises(TypeError, match="mu must be a number"):
            interphase.Material(**dict(SIMPLIFIED, mu=value))
    assert interphase.Material(**dict(SIMPLIFIED, mu=np.float64(0.5))).props[2] == 0.5
    # an integer beyond the double range is named, not a bare OverflowError
    with pytest.raises(ValueError, match="mu = 1000+ is beyond the range of a double"):
        interphase.Material(**dict(SIMPLIFIED, mu=10**400))


REAL = "must hold real numbers \\(ints or floats\\), got "
TWO_ROWS = np.array([[0.0, 0.0], [0.001, 0.0]])


@pytest.mark.parametrize("call, message", [
    # a complex number was cast to its real part (a ComplexWarning only), a date to a count of days,
    # None to NaN (then reported as a separation that is not finite), a bool to 0/1, a string parsed
    (lambda m: m.update(np.array([1e-3 + 1j, 0])), "Material.update: separation " + REAL + "complex numbers"),
    (lambda m: m.update(np.array(["2000-01-01", "2000-01-02"], dtype="datetime64[D]")),
     "Material.update: separation " + REAL + r"dates \(dtype datetime64\[D\]\)"),
    (lambda m: m.update(np.array([1, 2], dtype="timedelta64[s]")), "separation " + REAL + "time spans"),
    (lambda m: m.update(None), r"Material.update: separation " + REAL + r"None \(NoneType\)$"),
    (lambda m: m.update(np.array([None, 0.0], dtype=object)), "separation " + REAL + r"None \(NoneType\) at index 0"),
    (lambda m: m.update([0.001, "0"]), "separation " + REAL + "strings"),
    (lambda m: m.update([0.001, True]), "separation " + REAL + "a bool at index 1$"),
    (lambda m: m.run([[0, 0], (0.001, np.True_)]), "history " + REAL + r"a bool at index \(1, 1\)$"),
    (lambda m: m.update([0.001, np.array(False)]), "separation " + REAL + "a bool at index 1$"),
    (lambda m: m.update([True, False]), "separation " + REAL + "booleans"),
    (lambda m: m.update([0.001, 0.0], [0, 0, 0, 1j]), "Material.update: state " + REAL + "complex numbers"),
    (lambda m: m.run(np.array([[0, 0], [0.001 + 0.5j, 0]])), "Material.run: history " + REAL + "complex numbers"),
    (lambda m: m.run(TWO_ROWS, np.array([0, 1 + 1j])), "Material.run: time " + REAL + "complex numbers"),
    (lambda m: m.run(TWO_ROWS, np.array(["2000-01-01", "2000-01-02"], dtype="datetime64[D]")),
     "Material.run: time " + REAL + "dates"),
    (lambda m: m.run(TWO_ROWS, [0.0, None]), "Material.run: time " + REAL + r"None \(NoneType\) at index 1"),
    (lambda m: m.run([[0, 0], [0.001, None]]), r"Material.run: history " + REAL + r"None \(NoneType\) at index \(1, 1\)"),
    (lambda m: m.run(TWO_ROWS, control=np.array([0.0, 1.0])), "Material.run: control must hold booleans"),
    (lambda m: m.run(TWO_ROWS, control=[True, None]), "Material.run: control must hold booleans"),
    (lambda m: interphase.Material.from_props([str(p) for p in m.props]),
     "Material.from_props: PROPS " + REAL + "strings"),
    (lambda m: interphase.Material.from_props([True] * m.props.size), "Material.from_props: PROPS " + REAL + "booleans"),
    (lambda m: interphase.Material.from_props(m.props.astype(complex)),
     "Material.from_props: PROPS " + REAL + "complex numbers"),
    (lambda m: interphase.Material.from_props(list(m.props[:-1]) + [None]),
     "Material.from_props: PROPS " + REAL + r"None \(NoneType\) at index 8"),
])
def test_array_arguments_hold_real_numbers(call, message):
    """Every array argument (separation, state, history, time, control, PROPS) takes what Material's
    numeric keywords take: real numbers (ints and floats), booleans for control; anything numpy would
    convert in silence or with a mere warning is a TypeError naming the argument, raised before any
    conversion (no ComplexWarning)."""
    m = interphase.Material(**SIMPLIFIED)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(TypeError, match=message):
            call(m)


def test_array_arguments_take_ints_and_floats():
    m = interphase.Material(**SIMPLIFIED)
    reference = m.update([2.0**-10, 0.0]).traction
    for separation in (np.array([2.0**-10, 0], dtype=np.float32), [2.0**-10, 0], (2.0**-10, np.int8(0)),
                       np.array([2.0**-10, 0], dtype=object), [fractions.Fraction(1, 1024), 0]):
        assert np.array_equal(m.update(separation).traction, reference)
    assert np.array_equal(m.run(TWO_ROWS, np.array([0, 1], dtype=np.uint8)).traction, m.run(TWO_ROWS).traction)
    same = interphase.Material.from_props([int(p) if p == int(p) else p for p in m.props.tolist()])
    assert np.array_equal(same.props, m.props)
    with pytest.raises(ValueError, match="Material.run: history holds a number beyond the range of a double"):
        m.run([[0, 0], [10**400, 0]])


@pytest.mark.parametrize("props, shape", [(np.ones((3, 3)), "shape (3, 3)"), (1.0, "a scalar (1.0)"),
                                          ([[1.0, 1.0]], "shape (1, 2)")])
def test_props_must_be_one_dimensional(props, shape):
    with pytest.raises(ValueError, match=re.escape(f"Material.from_props: PROPS must be one-dimensional, got {shape}")):
        interphase.Material.from_props(props)


@pytest.mark.parametrize("entries, error, message", [
    (dict(MICRO, table="x\0y"), ValueError, r"Material: table = 'x\\x00y' holds a null character"),
    (dict(MICRO, table=5), TypeError, r"Material: table must be a path \(str, bytes or os.PathLike\), got 5 \(int\)"),
    (dict(MICRO, table=b"x\0y"), ValueError, r"Material: table = b'x\\x00y' holds a null character"),
    (dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="tabulated", rcurve_file=5), TypeError,
     r"Material: rcurve_file must be a path \(str, bytes or os.PathLike\), got 5 \(int\)"),
    (dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="tabulated", rcurve_file="r\0.txt"), ValueError,
     r"Material: rcurve_file = 'r\\x00.txt' holds a null character"),
    (dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="equivalent", rcurve_file=5), TypeError,
     r"Material: rcurve_file must be a path"),
])
def test_paths_that_are_no_file_names_are_named(entries, error, message):
    """A table or R-curve path that is not text, or holds a null character: the entry named, not
    os.fspath's or os.stat's bare message."""
    with pytest.raises(error, match=message):
        interphase.Material(**entries)


def test_loaders_name_a_path_that_is_no_file_name():
    with pytest.raises(TypeError, match=r"load_table: path must be a path .*got 5 \(int\)"):
        interphase.load_table(5)
    with pytest.raises(ValueError, match=r"load_rcurve: path = 'a\\x00b' holds a null character"):
        interphase.load_rcurve("a\0b")


def test_tangent_check_names_a_result_of_another_material():
    """A result of another material fails the row comparison at once: said so (which PROPS differs),
    not "run the history with output_every=1" (the run did); output_every > 1 is named as such."""
    m = interphase.Material(**SIMPLIFIED)
    other = interphase.Material(**dict(SIMPLIFIED, k_n=400.0))
    history = [[0.0, 0.0], [0.001, 0.0005]]
    r = other.run(history, increments=5)
    with pytest.raises(ValueError, match=re.escape("Material.tangent_check: the result is the run of another material "
                                                   "(its PROPS(8) = 400.0, this material's 482.6974267968057): "
                                                   "check it with the material that ran it")):
        m.tangent_check(r, 1e-5)
    assert other.tangent_check(r, 1e-5).passed
    # the same entries make the same material: its results are checked
    assert interphase.Material(**dict(SIMPLIFIED, k_n=400.0)).tangent_check(r, 1e-5).passed
    fracture = interphase.Material(**dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="equivalent"))
    with pytest.raises(ValueError, match=r"another material \(13 PROPS, this material 9\)"):
        m.tangent_check(fracture.run(history, increments=5), 1e-5)
    # a run that kept one step in 3 over a path where the skipped steps count (friction after a reversal)
    path = [[0.0, 0.0], [0.0, 0.01], [-0.001, -0.01]]
    with pytest.raises(ValueError, match=r"row \d+ .*is not the update of row \d+'s state: the run kept one step in 3 "
                                         r"\(output_every=3\), and the steps it skipped count: run the history with "
                                         r"output_every=1"):
        m.tangent_check(m.run(path, increments=30, output_every=3), 1e-5)
    # a Result made by hand (no material known) whose rows are not this material's
    bare = interphase.Result(r.time, r.separation, r.traction, r.state, r.stored_energy, r.dissipated_energy)
    with pytest.raises(ValueError, match="row 1 .*is not the update of row 0's state: pass a result of this "
                                         "material's run made with output_every=1"):
        m.tangent_check(bare, 1e-5)


def test_tangent_check_tolerance_below_one_and_no_step_compared():
    """A tolerance of 1 or more passes a tangent wrong by its own size: refused. A check where every
    perturbed update failed (a step beyond the separations the update admits) compared nothing: not
    passed, with the driver's words."""
    m = interphase.Material(**SIMPLIFIED)
    r = m.run([[0.0, 0.0], [0.01, 0.0]], increments=4)
    for tolerance in (1.0, 1e300):
        with pytest.raises(ValueError, match="tolerance = .* would pass a tangent wrong by its own size or more "
                                             r"\(a relative error >= 1\): it must be < 1"):
            m.tangent_check(r, tolerance)
    assert m.tangent_check(r, 0.999).passed
    check = m.tangent_check(r, 1e-5, step=1e300)
    assert (check.checked, check.unchecked, check.passed) == (0, 4, False)
    assert check.failure == ("the tangent check compared no step: a perturbed call failed at every step (4 not "
                             "checked; tangent_step = 0.1E+301 mm)")
    assert m.tangent_check(r, 1e-5).failure is None
    one_row = interphase.Result(r.time[:1], r.separation[:1], r.traction[:1], r.state[:1], r.stored_energy[:1],
                                r.dissipated_energy[:1])
    check = m.tangent_check(one_row, 1e-5)
    assert not check.passed and check.failure == ("the tangent check compared no step: the result has no step after "
                                                  "its first row")


def test_tangent_check_failure_says_where():
    """A failed check names the worst row, its time and its separation; away from s_N = 0 it says
    nothing of the closed crack's exception (the exception itself: test_paper_cases.py, h2I)."""
    m = interphase.Material(**SIMPLIFIED)
    r = m.run([[0.0, 0.0], [0.002, 0.001]], increments=20)
    check = m.tangent_check(r, 1e-5)
    assert check.passed and check.exception_rows.size == 0
    strict = m.tangent_check(r, 1e-14)
    assert not strict.passed and strict.worst_row == int(np.nanargmax(strict.errors))
    s_n, s_t = (interphase._files._real_text(v) for v in r.separation[strict.worst_row])
    assert strict.failure.startswith(f"the tangent check failed: worst relative error "
                                     f"{interphase._files._real_text(strict.worst)} at t = "
                                     f"{interphase._files._real_text(strict.worst_time)} (row {strict.worst_row}, "
                                     f"s_N = {s_n}, s_T = {s_t} mm) is above the tolerance 0.1E-13")
    assert "exception" not in strict.failure


def test_update_refuses_a_3d_state_in_2d():
    """The dimension comes from the separation's length: a state with a second slip lambda_2 (a
    3-D one) given to a 2-D update is refused, naming the value, where the library's 2-D update
    (as the UMAT's) would not read it and return it as 0. lambda_2 = 0 (or -0) is a 2-D state, and
    a 2-D state goes on in 3-D as the state with lambda_2 = 0 it is."""
    m = interphase.Material(**SIMPLIFIED)
    three = m.update([-0.001, 0.002, 0.003])
    assert three.state[2] != 0.0
    for lam2, text in ((three.state[2], repr(float(three.state[2]))), (float("nan"), "nan"), (-1e-300, "-1e-300")):
        state = three.state.copy()
        state[2] = lam2
        with pytest.raises(interphase.InterphaseError, match=re.escape(
                f"Material.update: STATEV(3) lambda_2 = {text} mm (state[2], the slip in the second shear "
                "direction) is not zero, but the separation (s_N, s_T) is 2-D")) as caught:
            m.update([-0.001, 0.002], state)
        assert caught.value.status == interphase.STATUS_BAD_STATE
    for zero in (0.0, -0.0):
        state = three.state.copy()
        state[2] = zero
        assert m.update([-0.001, 0.002], state).state[2] == 0.0
    two = m.update([-0.001, 0.002])
    assert np.array_equal(m.update([-0.001, 0.002, 0.0], two.state).traction[:2],
                          m.update([-0.001, 0.002], two.state).traction)


def test_an_update_in_place_of_its_state_is_named():
    """m.update(s, u) for m.update(s, u.state), the usual slip in a loop: a TypeError that says
    which attribute to pass, not the Update's whole repr."""
    m = interphase.Material(**SIMPLIFIED)
    u = m.update([0.001, 0.0])
    with pytest.raises(TypeError) as caught:
        m.update([0.002, 0.0], u)
    assert str(caught.value) == ("Material.update: state must be the state array, got an Update: pass its state, "
                                 "update(separation, u.state)")
    assert np.array_equal(m.update([0.002, 0.0], u.state).state, m.update([0.002, 0.0], list(u.state)).state)


def test_a_slip_without_damage_is_refused():
    """D = 0 (or -0) with a slip, which no update writes (an intact point has no crack, so no
    slip), is refused as the UMAT's STATEV reader refuses it, naming the values; D = 0 with a slip
    of +-0 is the virgin state (docs/python.md, 'One point')."""
    for model in (SIMPLIFIED, dict(SIMPLIFIED, growth_slip="fixed-lambda")):
        m = interphase.Material(**model)
        for d, slip, separation in ((0.0, [0.01, 0.0], [0.0001, 0.0001]), (-0.0, [-1e-300, 0.0], [0.0001, 0.0001]),
                                    (0.0, [0.0, 0.002], [-0.001, 0.002, 0.0])):
            with pytest.raises(interphase.InterphaseError, match="an intact point has no crack, so no slip") as caught:
                m.update(separation, [d, slip[0], slip[1], 0.0])
            assert caught.value.status == interphase.STATUS_BAD_STATE
        virgin = m.update([0.0001, 0.0001])
        assert np.array_equal(m.update([0.0001, 0.0001], [0.0, -0.0, 0.0, 0.0]).traction, virgin.traction)


def test_shapes_and_ragged_arrays_are_named():
    m = interphase.Material(**SIMPLIFIED)
    for call, message in (
            (lambda: m.update(0.001), "Material.update: separation must hold 2 (2-D) or 3 (3-D) components, got a "
                                      "scalar (0.001)"),
            (lambda: m.update([[0.001, 0.0]]), "Material.update: separation must hold 2 (2-D) or 3 (3-D) "
                                               "components, got shape (1, 2)"),
            (lambda: m.update([0.001, 0.0], 0.0), "Material.update: state must hold 4 values, got a scalar (0.0)"),
            (lambda: m.update([0.001, 0.0], np.zeros(5)), "Material.update: state must hold 4 values, got shape (5,)"),
            (lambda: m.run(0.5), "Material.run: history must be an (nrows, 2) or (nrows, 3) array, got a scalar "
                                 "(0.5)"),
            (lambda: m.run([0.0, 0.01]), "Material.run: history must be an (nrows, 2) or (nrows, 3) array, got "
                                         "shape (2,)"),
            (lambda: m.run(np.zeros((2, 50))), "Material.run: history must be an (nrows, 2) or (nrows, 3) array, "
                                               "got shape (2, 50): one row per point, (s_N, s_T) or (s_N, s_T1, "
                                               "s_T2); for the components stacked as rows, as np.array([s_n, s_t]) "
                                               "makes them, pass the transpose (history.T, shape (50, 2))"),
            (lambda: m.run(TWO_ROWS, time=1.0), "Material.run: time must hold 2 values, got a scalar (1.0)"),
            (lambda: m.run(TWO_ROWS, control=[True]), "Material.run: control must have shape (2,) or (2, 2), got "
                                                      "shape (1,)"),
            (lambda: m.run([[0.0, 0.0], [0.001]]), "Material.run: history is ragged: its rows (or their entries) "
                                                   "do not all have the same length"),
            (lambda: m.run([[0.0, 0.0], [0.001, 0.0, 0.0]]), "Material.run: history is ragged"),
            (lambda: m.run(TWO_ROWS, time=[0.0, [1.0, 2.0]]), "Material.run: time is ragged"),
            (lambda: m.run(TWO_ROWS, control=[[True, False], [True]]), "Material.run: control is ragged"),
            (lambda: m.update([0.001, [0.0, 0.0]]), "Material.update: separation is ragged"),
            (lambda: interphase.Material.from_props(1.0), "Material.from_props: PROPS must be one-dimensional, got "
                                                          "a scalar (1.0)")):
        with pytest.raises(ValueError, match=re.escape(message)):
            call()
    # a value that is not finite is named as the out-of-range one is: the component's name
    for history, control, name in (([[0, 0], [0, float("inf")]], None, "component 1: s_T) = Infinity"),
                                   ([[0, 0, 0], [0, 0, float("nan")]], None, "component 2: s_T2) = NaN"),
                                   ([[0, 0], [float("nan"), 0]], [True, False], "component 0: Sigma_N) = NaN")):
        with pytest.raises(interphase.InterphaseError, match=re.escape(name + " is not finite")):
            m.run(history, control=control)


def test_masked_entries_are_refused():
    # numpy drops a mask in silence: the values under it (a 999 marking a bad sample) were replayed
    m = interphase.Material(**SIMPLIFIED)
    history = np.ma.masked_array([[0.0, 0.0], [0.001, 0.0], [999.0, 0.0]], mask=[[0, 0], [0, 0], [1, 0]])
    with pytest.raises(ValueError, match=re.escape("Material.run: history is a masked array with masked entries "
                                                   "(the first at index (2, 0))")):
        m.run(history)
    with pytest.raises(ValueError, match=re.escape("Material.update: separation is a masked array with masked "
                                                   "entries (the first at index 1)")):
        m.update(np.ma.masked_array([0.001, 5.0], mask=[0, 1]))
    # control too, and masked arrays inside a list
    with pytest.raises(ValueError, match=re.escape("Material.run: control is a masked array with masked entries "
                                                   "(the first at index 1)")):
        m.run([[0.0, 0.0], [0.001, 0.0]], control=np.ma.masked_array([False, True], mask=[0, 1]))
    with pytest.raises(ValueError, match=re.escape("Material.run: history is a masked array with masked entries "
                                                   "(the first at index (1, 1))")):
        m.run([[0.0, 0.0], np.ma.masked_array([0.001, 5.0], mask=[0, 1])])
    # a masked array without masked entries is its values
    unmasked = np.ma.masked_array([[0.0, 0.0], [0.001, 0.0]], mask=False)
    assert np.array_equal(m.run(unmasked).traction, m.run(np.array([[0.0, 0.0], [0.001, 0.0]])).traction)


def test_errors_cross_process_boundaries():
    """An InterphaseError pickles as itself, its status, detail and the rows of a failed run with
    it, so that an error raised in a worker process (multiprocessing, concurrent.futures, scipy's
    workers=) is raised in the caller: unpicklable, it broke a ProcessPoolExecutor and hung
    multiprocessing.Pool's map."""
    import multiprocessing
    import pickle
    m = interphase.Material(**SIMPLIFIED)
    with pytest.raises(interphase.InterphaseError) as caught:
        m.run([[0, 0], [0.5, 0]], increments=100, control=[True, False])
    error = caught.value
    again = pickle.loads(pickle.dumps(error))
    assert type(again) is interphase.InterphaseError and str(again) == str(error)
    assert (again.status, again.name, again.reason, again.detail) == (error.status, error.name, error.reason,
                                                                      error.detail)
    assert np.array_equal(again.result.traction, error.result.traction)
    bad = list(m.props)
    bad[2] = -1.0
    with multiprocessing.get_context("fork").Pool(1) as pool:
        pending = pool.apply_async(interphase.Material.from_props, (bad,))
        with pytest.raises(interphase.InterphaseError, match=r"PROPS\(3\) mu = -1\.0 is out of range") as caught:
            pending.get(timeout=120)
    assert caught.value.status == interphase.STATUS_BAD_MU


@pytest.mark.parametrize("example", ["fit_simplified", "sweep_shear"])
def test_an_example_refuses_an_output_dir_it_cannot_make(source_dir, tmp_path, example):
    """--output-dir naming a file, or a path through one: the usage error of argparse (exit status
    2), not a traceback."""
    afile = tmp_path / "afile"
    afile.write_text("")
    for given, why in ((afile, "not a directory"), (afile / "sub", "cannot make the directory: Not a directory")):
        done = subprocess.run([sys.executable, str(source_dir / "examples" / "python" / f"{example}.py"),
                               "--output-dir", str(given)], capture_output=True, text=True)
        assert done.returncode == 2 and "Traceback" not in done.stderr
        assert done.stderr.strip().endswith(f"{example}.py: error: --output-dir {given}: {why}")


def test_threads_give_the_numbers_of_one():
    """The C entry points keep no state: threads running at once get the serial numbers."""
    m = interphase.Material(**MICRO)
    path = np.array([[0, 0], [-0.005, 0.05], [0.01, -0.03], [0.0, 0.08]])
    expected = m.run(path, increments=300)
    results = [None] * 8

    def work(k):
        results[k] = m.run(path, increments=300)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(len(results))]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    for r in results:
        assert np.array_equal(r.traction, expected.traction) and np.array_equal(r.state, expected.state)


def test_output_that_does_not_fit_names_what_asked_for_it(monkeypatch):
    """A run whose rows of output cannot be allocated says how many rows, how much memory and which
    arguments asked for them, not only numpy's shape (numpy's allocation is made to fail here for
    large arrays: a real one of this size would depend on the machine's overcommit policy)."""
    m = interphase.Material(**SIMPLIFIED)
    real_empty = np.empty

    def empty(shape, *args, **kwargs):
        if (shape if isinstance(shape, int) else shape[0]) > 10**6:
            raise MemoryError("Unable to allocate (numpy's message)")
        return real_empty(shape, *args, **kwargs)

    monkeypatch.setattr(np, "empty", empty)
    with pytest.raises(MemoryError, match=r"Material.run: 11250018 rows of output \(.* GiB\) do not fit in memory: "
                                          r"1 segment\(s\) x increments = 10000000 / output_every = 1 rows; ask for "
                                          r"fewer rows"):
        m.run([[0.0, 0.0], [0.01, 0.0]], increments=10**7)


def test_threads_with_different_tables_get_their_own_numbers(source_dir):
    """Materials on different custom tables used from threads at once: each run gets the numbers of
    its own table, as when run alone (the package's data lock holds a material's table from its
    loading through the library call; without it a thread's table was replaced under another's
    run, and two loads at once could fail with a unit already open)."""
    tables = [source_dir / "tables" / name for name in ("paper.dat", "paper-resolution.dat", "paper-dense.dat")]
    materials = [interphase.Material(**dict(MICRO, table=t)) for t in tables]
    path = np.array([[0, 0], [0.002, 0.004], [-0.001, 0.01]])
    expected = [m.run(path, increments=40) for m in materials]
    # (the tables' numbers differ, so a run on another's table would be seen)
    assert not np.array_equal(expected[0].traction, expected[1].traction)
    assert not np.array_equal(expected[1].traction, expected[2].traction)
    failures = []

    def work(k):
        try:
            for _ in range(30):
                r = materials[k % 3].run(path, increments=40)
                if not np.array_equal(r.traction, expected[k % 3].traction):
                    failures.append(f"thread {k}: the numbers of another table")
        except Exception as error:          # (reported below, not lost in the thread)
            failures.append(f"thread {k}: {error!r}")

    threads = [threading.Thread(target=work, args=(k,)) for k in range(6)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    assert not failures, failures[:3]


def test_every_library_call_of_a_material_with_a_table_holds_the_data_lock(source_dir, monkeypatch):
    """A material that reads a custom table calls the library only under the package's data lock,
    the check of its values at construction (_check_props, which reads the loaded table at D = 0)
    included: another thread's load would otherwise replace the table under that call."""
    from interphase import _library, _material
    unlocked = []

    class Checked:
        def __getattr__(self, name):
            function = getattr(_library.lib, name)

            def call(*args):
                if not _library.data_lock._is_owned():
                    unlocked.append(name)
                return function(*args)
            return call

    monkeypatch.setattr(_material, "lib", Checked())
    m = interphase.Material(**dict(MICRO, table=source_dir / "tables" / "paper.dat"))
    m.run(np.array([[0, 0], [0.002, 0.004]]), increments=4)
    interphase.Material.from_props(m.props, table=source_dir / "tables" / "paper.dat")
    assert not unlocked, unlocked


def test_a_child_forked_while_another_thread_holds_the_data_lock_can_use_a_table(source_dir):
    """A process forked while another thread holds the data lock (loading a table, or running a
    material with one) starts with a free lock: its materials with tables run (the inherited lock,
    held by a thread the child does not have, would make it wait for ever)."""
    from interphase import _library
    holding, release = threading.Event(), threading.Event()

    def hold():
        with _library.data_lock:
            holding.set()
            release.wait(60)

    holder = threading.Thread(target=hold)
    holder.start()
    try:
        assert holding.wait(10)
        pid = os.fork()
        if pid == 0:                                    # the child: a material with a table, then out
            code = 1
            try:
                m = interphase.Material(**dict(MICRO, table=source_dir / "tables" / "paper.dat"))
                code = 0 if m.run([[0, 0], [0.002, 0.004]], increments=4).traction.shape == (5, 2) else 1
            finally:
                os._exit(code)
        deadline = time.monotonic() + 60
        while True:
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                break
            if time.monotonic() > deadline:
                os.kill(pid, 9)
                os.waitpid(pid, 0)
                pytest.fail("the forked child waited for the data lock for 60 s")
            time.sleep(0.05)
        assert os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0, status
    finally:
        release.set()
        holder.join()


def test_the_umats_own_options_are_refused():
    """The thin-layer mode and the host conventions are options of the UMAT only: the C entry
    points, and so the package, take separations and refuse them (STATUS_BAD_OPTION)."""
    props = interphase.Material(**SIMPLIFIED).props.tolist() + [0, 0, 0, 0, 2.0]   # layer thickness t
    with pytest.raises(interphase.InterphaseError, match="PROPS.14. layer thickness t is an option of the UMAT only") \
            as caught:
        interphase.Material.from_props(props)
    assert caught.value.status == interphase.STATUS_BAD_OPTION


def test_mixed_control_from_arrays():
    """control=: the normal traction imposed (a precompression held while the shear separation
    is driven), met to the tolerance at every row; the same run as a case file's."""
    m = interphase.Material(**SIMPLIFIED)
    history = [[0.0, 0.0], [-0.5, 0.0], [-0.5, 0.1]]            # (Sigma_N, s_T)
    r = m.run(history, increments=100, control=[True, False], traction_tolerance=1e-15)
    assert len(r) == 201
    assert np.abs(r.traction[100:, 0] + 0.5).max() <= 1e-15
    assert r.separation[-1, 1] == 0.1 and r.separation[-1, 0] < 0
    assert r.traction[-1, 1] == pytest.approx(0.75 * 0.5, rel=1e-12)    # the friction plateau mu p
    # the same, with the control given row by row
    per_row = np.array([[True, False]] * 3)
    same = m.run(history, increments=100, control=per_row, traction_tolerance=1e-15)
    assert np.array_equal(same.traction, r.traction) and np.array_equal(same.separation, r.separation)
    # output_every thins the rows (and keeps the ends of the segments)
    thin = m.run(history, increments=100, control=per_row, traction_tolerance=1e-15, output_every=7)
    assert thin.time[-1] == 2.0 and 1.0 in thin.time.tolist()
    kept = np.isin(r.time, thin.time)
    assert np.array_equal(r.traction[kept], thin.traction)


def test_mixed_control_errors_carry_the_library_status():
    m = interphase.Material(**SIMPLIFIED)
    peak = K_N * 0.00044                                       # the mode-I peak K_N s0_N (MPa)
    with pytest.raises(interphase.InterphaseError, match="beyond the peak the material can carry") as caught:
        m.run([[0.0, 0.0], [1.2 * peak, 0.0]], increments=20, control=[True, True])
    error = caught.value
    assert error.status == interphase.STATUS_BEYOND_PEAK and "Sigma_N" in error.detail
    assert error.result is not None and error.result.traction[-1, 0] <= peak
    assert np.all(np.diff(error.result.time) > 0)
    with pytest.raises(interphase.InterphaseError, match="traction_tolerance") as caught:
        m.run([[0.0, 0.0], [0.1, 0.0]], control=[True, False], traction_tolerance=0.0)
    assert caught.value.status == interphase.STATUS_BAD_HISTORY
    # a tolerance as large as the imposed traction would leave it unapplied: refused, and the
    # loosest one taken meets it to within itself
    with pytest.raises(interphase.InterphaseError, match="at most 1e-3 MPa") as caught:
        m.run([[0.0, 0.0], [-0.5, 0.0], [-0.5, 0.1]], increments=200, control=[True, False], traction_tolerance=1.0)
    assert caught.value.status == interphase.STATUS_BAD_HISTORY
    loose = m.run([[0.0, 0.0], [-0.5, 0.0], [-0.5, 0.1]], increments=200, control=[True, False],
                  traction_tolerance=interphase.TRACTION_TOLERANCE_MAX)
    assert np.abs(loose.traction[1:, 0] - np.interp(loose.time[1:], [0.0, 1.0, 2.0], [0.0, -0.5, -0.5])).max() \
        <= interphase.TRACTION_TOLERANCE_MAX
    with pytest.raises(interphase.InterphaseError, match="output_every") as caught:
        m.run([[0.0, 0.0], [0.1, 0.0]], output_every=0)
    assert caught.value.status == interphase.STATUS_BAD_HISTORY
    with pytest.raises(ValueError, match="control must have shape"):
        m.run([[0.0, 0.0], [0.1, 0.0]], control=[True, False, False])
    with pytest.raises(TypeError, match=re.escape("Material.run: control must hold booleans (true: traction-controlled), "
                                                  "got values (dtype int64)")):
        m.run([[0.0, 0.0], [0.1, 0.0]], control=[1, 0])


def test_separations_beyond_the_range_are_named():
    """An imposed compression has no peak: one whose contact needs a separation beyond 1e20 mm
    raises STATUS_SEPARATION_OUT_OF_RANGE saying so (it said 'beyond the peak ... 0.00000 MPa');
    a separation beyond 1e20 mm in the history is refused before any update, naming its row and
    component (it ran, halved 10 times and named an interpolated value)."""
    m = interphase.Material(**SIMPLIFIED)
    with pytest.raises(interphase.InterphaseError) as caught:
        m.run([[0, 0], [-1e30, 0]], control=[True, False])
    error = caught.value
    assert error.status == interphase.STATUS_SEPARATION_OUT_OF_RANGE, str(error)
    assert "beyond the peak" not in error.detail
    assert "needs a separation beyond the admissible range |s_N| <= 1.0E+20 mm" in error.detail
    with pytest.raises(interphase.InterphaseError) as caught:
        m.run([[0, 0], [0, 1e21], [0, 0]], increments=10)
    error = caught.value
    assert error.status == interphase.STATUS_SEPARATION_OUT_OF_RANGE and error.result is None
    assert error.detail == ("value[3] (row 1, component 1: s_T) = 0.1E+22 mm is beyond the range the update "
                            "admits, |s| <= 1.0E+20 mm")


def test_an_rcurve_toughness_out_of_range_has_its_own_status(tmp_path):
    """A toughness outside [1e-20, 1e20] N/mm: STATUS_RCURVE_BAD_TOUGHNESS, whose message says so
    (it was 63, whose message speaks of D values)."""
    for text, name in (("0 1e21 0.0085\n1 0.005 0.0085\n", "G_cI = 1e21"),
                       ("0 0.005 1e-21\n1 0.005 0.0085\n", "G_cII = 1e-21")):
        rcurve = tmp_path / "gc.txt"
        rcurve.write_text(text)
        with pytest.raises(interphase.InterphaseError) as caught:
            interphase.Material(**dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="tabulated",
                                       rcurve_file=rcurve))
        error = caught.value
        assert error.status == interphase.STATUS_RCURVE_BAD_TOUGHNESS
        assert error.name == "STATUS_RCURVE_BAD_TOUGHNESS"
        assert str(error).startswith("R-curve toughness outside [1e-20, 1e20] N/mm")
        assert f"gc.txt:1: {name} lies outside [1e-20, 1e20] N/mm" in error.detail


def test_a_fully_damaged_micromechanical_point_carries_no_more_load():
    """Sigma_N raised to 5 MPa: the point stops at its peak (0.281 MPa, below sf_N), not at the
    separation where the table's round-off stiffness at D = 1 would carry 5 MPa (2e13 mm)."""
    m = interphase.Material(**MICRO)
    with pytest.raises(interphase.InterphaseError, match="beyond the peak") as caught:
        m.run([[0.0, 0.0], [5.0, 0.0]], increments=100, control=[True, True])
    last = caught.value.result
    assert caught.value.status == interphase.STATUS_BEYOND_PEAK
    assert 0.2 < last.traction[-1, 0] < 0.3 and last.separation[-1, 0] < 0.04


def test_run_history_c_entry(tmp_path):
    """interphase_run_history directly: arrays that are too short give STATUS_OUTPUT_FULL with
    the first rows of the replay in them; NULL outputs are not written; a control value other
    than 0 and 1 is refused."""
    lib = interphase._library.lib
    m = interphase.Material(**SIMPLIFIED)
    full = m.run([[0.0, 0.0], [-0.3, 0.05]], increments=30, control=[True, False])
    props = np.ascontiguousarray(m.props)
    time = np.array([0.0, 1.0])
    value = np.array([[0.0, 0.0], [-0.3, 0.05]])
    control = np.array([[1, 0], [1, 0]], dtype=np.intc)
    out = np.empty((5, 2))
    done = ctypes.c_size_t(0)
    detail = ctypes.create_string_buffer(257)
    status = lib.interphase_run_history(props.ctypes.data, props.size, 2, 2, time.ctypes.data, value.ctypes.data,
                                        control.ctypes.data, 30, 1e-12, 1, 5, None, None, out.ctypes.data, None,
                                        None, None, None, ctypes.byref(done), detail, 257)
    assert status == interphase.STATUS_OUTPUT_FULL and done.value == 5, detail.value
    assert np.array_equal(out, full.traction[:5])
    control[1, 1] = 2
    status = lib.interphase_run_history(props.ctypes.data, props.size, 2, 2, time.ctypes.data, value.ctypes.data,
                                        control.ctypes.data, 30, 1e-12, 1, 5, None, None, None, None,
                                        None, None, None, ctypes.byref(done), detail, 257)
    assert status == interphase.STATUS_BAD_HISTORY and done.value == 0
    assert b"control row 1" in detail.value


def test_read_mixed_history(source_dir, tmp_path):
    path = source_dir / "drivers" / "cases" / "shear" / "shear-0.5.txt"
    with pytest.raises(ValueError, match="imposes tractions"):
        interphase.read_history(path)
    t, v, c = interphase.read_history(path, control=True)
    assert t.tolist() == [0, 1, 2] and v[:, 0].tolist() == [0, -0.5, -0.5] and v[:, 1].tolist() == [0, 0, 0.1]
    assert c[:, 0].all() and not c[:, 1].any()
    switch = tmp_path / "switch.txt"
    switch.write_text("# columns: t s_T1 s_T2 s_N\n0 0 0 0\n1 0 0 0.001\n# columns: t Sigma_T1 s_T2 Sigma_N\n"
                      "2 0.01 0.002 0.001\n")
    t, v, c = interphase.read_history(switch, control=True)
    assert c.tolist() == [[False] * 3, [False] * 3, [True, True, False]]
    assert v[2].tolist() == [0.001, 0.01, 0.002]
    bad = tmp_path / "bad.txt"
    bad.write_text("# columns: t s_T Tau_N\n0 0 0\n1 0 1\n")
    with pytest.raises(ValueError, match="bad.txt:1: .*column 3 is 'Tau_N'; expected s_N or Sigma_N"):
        interphase.read_history(bad, control=True)
    # a misspelt key (read as a plain comment it would leave every column a separation), and a
    # columns line behind a data row (the row was dropped with the comment)
    for text, line, match in [("# column: t s_T Sigma_N\n0 0 0\n1 0 1\n", 1, 'looks like a "# columns:" line'),
                              ("#  Columns : t s_T Sigma_N\n0 0 0\n1 0 1\n", 1, 'looks like a "# columns:" line'),
                              ("# columns t s_T Sigma_N\n0 0 0\n1 0 1\n", 1, "names traction columns, but is not"),
                              # a spreadsheet's header: commas and semicolons separate the names
                              ("# t, s_T, Sigma_N\n0 0 0\n1 0 -0.5\n", 1, "names traction columns, but is not"),
                              ("# t (s);s_T (mm);Sigma_N (MPa)\n0 0 0\n1 0 -0.5\n", 1, "names traction columns"),
                              ("# t, s_N, s_T\n0 0 0\n1 0.01 0\n", 1, "in another order"),
                              # separations named in another length unit than mm
                              ("# t s_T (m) s_N (m)\n0 0 0\n1 0.001 0\n", 1,
                               "gives s_T the unit \\(m\\), but the driver reads separations in mm"),
                              ("# t, s_T(mm), s_N(CM)\n0 0 0\n1 0.001 0\n", 1, "gives s_N the unit \\(CM\\)"),
                              ("# columns: t s_T Sigma_N\n# t s_T (\u00b5m) Sigma_N (MPa)\n0 0 0\n1 0 1\n", 2,
                               "gives s_T the unit \\(\u00b5m\\)"),
                              ("# t, s_T, s_N\n0,0,0\n1,0,0.01\n", 2, "found 1 column; expected 3 .* \\(the "
                               "fields of a line are separated by blanks or tabs, not by ','"),
                              ("0,5;0;0\n1;0;0,01\n", 1, "not by ';': write the values with blanks between them, "
                               "and a point for the decimal comma\\)"),
                              ("0 0 0 ! start\n1 0 0.01\n", 1, "found 5 columns; expected 3 .* \\('!' does not start "
                               "a comment in a history file: '#' does\\)"),
                              ("0 0 0 !start\n1 0 0.01\n", 1, "column 4: cannot parse '!start' as a number \\('!' "
                               "does not start a comment in a history file: '#' does\\)"),
                              ("0 0 0\n#\tt  s_T (mm)  SIGMA_N (MPa)\n1 0 1\n", 2, "names traction columns"),
                              ("# t s_N s_T\n0 0 0\n1 0.01 0\n", 1, "names the columns in another order"),
                              ("#  t  s_N (mm)  s_T (mm)\n0 0 0\n1 0.01 0\n", 1, "in another order"),
                              ("# columns: t (ms) s_T (m) Sigma_N (kPa)\n0 0 0\n1 0 1\n", 1,
                               "gives t the unit \\(ms\\), but the driver reads t in s"),
                              ("# columns: t s_T (m) Sigma_N (kPa)\n0 0 0\n1 0 1\n", 1,
                               "gives s_T the unit \\(m\\), but the driver reads s_T in mm"),
                              ("# columns: t s_T Sigma_N(kPa)\n0 0 0\n1 0 1\n", 1, "gives Sigma_N the unit"),
                              ("0 0 0 # columns: t s_T Sigma_N\n1 0 1\n2 0 2\n", 1,
                               "holds nothing before the '#' \\(here '0 0 0'\\)")]:
        bad.write_text(text)
        with pytest.raises(ValueError, match=f"bad.txt:{line}: .*{match}"):
            interphase.read_history(bad, control=True)
    # a UTF-8 byte-order mark is named, as by the driver
    bad.write_bytes(b"\xef\xbb\xbf# columns: t s_T s_N\n0 0 0\n1 0 1\n")
    with pytest.raises(ValueError, match="bad.txt:1: cannot read the line: the file starts with a UTF-8 byte-order"):
        interphase.read_history(bad, control=True)
    # a plain comment that starts with the word stays a comment
    fine = tmp_path / "fine.txt"
    fine.write_text("# column 2 is the shear separation\n# t s_T s_N\n# columns t s_T s_N\n"
                    "# Sigma_N held at t = 1\n# t s_T s_N (2-D)\n# columns: t (s) s_T (MM) s_N (mm) (separations)\n"
                    "0 0 0\n1 0.001 0\n")
    t, v, c = interphase.read_history(fine, control=True)
    assert t.tolist() == [0, 1] and not c.any()
    # a caption below a columns line is no mistake
    fine.write_text("# columns: t s_T Sigma_N\n# t (s) s_T (mm) Sigma_N (MPa)\n0 0 0\n1 0 1\n")
    t, v, c = interphase.read_history(fine, control=True)
    assert c[1, 0] and not c[1, 1]


# A small case file (its &loading from line 6 on) and its history, for the checks below.
CASE = """&material
  model = 'simplified', damage_law = 'displacement',
  mu = 0.75, s0_n = 0.00044, sf_n = 0.04, s0_t = 0.00072, sf_t = 0.06,
  k_n = 482.69742679680568, k_t = 198.75776397515528
/
&loading
  history = 'h.txt'
  increments = 20
  output = 'h.csv'
/
"""
HISTORY = "# t s_T s_N\n0 0 0\n1 0 0.01\n"
# CASE's material entries, and the same material as the UMAT's PROPS (the entry props)
CASE_MATERIAL = ("  model = 'simplified', damage_law = 'displacement',\n"
                 "  mu = 0.75, s0_n = 0.00044, sf_n = 0.04, s0_t = 0.00072, sf_t = 0.06,\n"
                 "  k_n = 482.69742679680568, k_t = 198.75776397515528\n")
PROPS_MATERIAL = "  props = 1, 1, 0.75, 0.00044, 0.04, 0.00072, 0.06, 482.69742679680568, 198.75776397515528\n"
assert CASE_MATERIAL in CASE


def write_case(tmp_path, case=CASE, history=HISTORY, name="case.nml"):
    """The case file `name` in tmp_path, its history h.txt beside it; the case's path."""
    (tmp_path / "h.txt").write_text(history)
    path = tmp_path / name
    path.write_text(case)
    return path


def test_paths_are_read_without_the_blanks_around_them(source_dir, tmp_path, monkeypatch):
    """history, table and rcurve_file = ' file ' name the file, and output = ' x.csv ' the CSV
    x.csv, as interphase-point trims them; Material's keywords table and rcurve_file are taken as
    given (test_a_keyword_path_is_taken_as_given), a leading blank part of the name."""
    for history in ("'h.txt '", "' h.txt'", "'  h.txt  '"):
        case = interphase.read_case(write_case(tmp_path, CASE.replace("'h.txt'", history)))
        assert case.time.tolist() == [0.0, 1.0]
    assert interphase.read_case(write_case(tmp_path, CASE.replace("'h.csv'", "' h.csv '"))).output == "h.csv"
    table = tmp_path / "paper-resolution.dat"
    table.write_bytes((source_dir / "tables" / "paper-resolution.dat").read_bytes())
    rcurve = tmp_path / "rcurve.txt"
    rcurve.write_text("# D G_cI G_cII\n0.0 0.005 0.0085\n1.0 0.005 0.0085\n")
    micro = CASE.replace("'simplified'", "'micromechanical', table = ' paper-resolution.dat '").replace(
        "  k_n = 482.69742679680568, k_t = 198.75776397515528\n", "")
    assert interphase.read_case(write_case(tmp_path, micro)).material.table_path == str(table)
    fracture = CASE.replace("'displacement'", "'fracture', d0 = 0.1, rcurve = 'tabulated', "
                                              "rcurve_file = 'rcurve.txt  '")
    assert interphase.read_case(write_case(tmp_path, fracture)).material.rcurve_path == str(rcurve)
    assert interphase.Material(**dict(MICRO, table=str(table))).table_path == str(table)
    assert interphase.Material(**dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="tabulated",
                                      rcurve_file=str(rcurve))).rcurve_path == str(rcurve)
    for given, entries, load in (
            (f"{table} ", dict(MICRO, table=f"{table} "), interphase.load_table),
            (f"{rcurve} ", dict(SIMPLIFIED, damage_law="fracture", d0=0.1, rcurve="tabulated",
                                rcurve_file=f"{rcurve} "), interphase.load_rcurve)):
        with pytest.raises(interphase.InterphaseError) as refused:
            load(given)
        with pytest.raises(interphase.InterphaseError) as caught:
            interphase.Material(**entries)
        assert str(caught.value) == str(refused.value)
        # (the library shows the end of a long path)
        assert f'{os.path.basename(given)}" ends in a blank' in str(caught.value)
    monkeypatch.chdir(tmp_path)
    (tmp_path / " lead.dat").write_bytes(table.read_bytes())
    assert interphase.Material(**dict(MICRO, table=" lead.dat")).table_path == str(tmp_path / " lead.dat")


def test_a_table_named_in_another_encoding_is_opened(source_dir, tmp_path):
    """A table whose name is not UTF-8 (Latin-1 'é', byte E9) is the file of those bytes, as for
    the driver: not a UnicodeEncodeError."""
    name = b"t\xe9.dat"
    (tmp_path / os.fsdecode(name)).write_bytes((source_dir / "tables" / "paper-resolution.dat").read_bytes())
    micro = CASE.replace("'simplified'", "'micromechanical', table = 'TABLE'").replace(
        "  k_n = 482.69742679680568, k_t = 198.75776397515528\n", "")
    path = tmp_path / "case.nml"
    (tmp_path / "h.txt").write_text(HISTORY)
    path.write_bytes(micro.encode().replace(b"TABLE", name))
    assert interphase.read_case(path).material.table_path == os.fsdecode(bytes(tmp_path) + b"/" + name)


@pytest.mark.parametrize("old, new, message", [
    ("'h.txt'", "''", "missing entry history"),
    ("'h.txt'", "'   '", "missing entry history"),
    ("'h.csv'", "''", "missing entry output"),
    ("'h.csv'", "' '", "missing entry output"),
    ("increments = 20\n  output = 'h.csv'", "output = ''", "missing entries increments, output"),
])
def test_an_empty_history_or_output_is_a_missing_entry(tmp_path, old, new, message):
    """history = '' (or blanks) and output = '' are entries left out, as interphase-point reads
    them: its message, not a directory opened as the history or an empty CSV name."""
    path = write_case(tmp_path, CASE.replace(old, new))
    with pytest.raises(ValueError) as caught:
        interphase.read_case(path)
    assert str(caught.value) == f"{path}: &loading: {message}"


def test_lines_longer_than_the_drivers_limit_are_refused(tmp_path):
    """A line of more than 65536 bytes (its carriage return counted, a comment too) in a case
    file or a history file is refused as the driver refuses it, naming the file and the line; a
    line of 65536 is read."""
    limit = interphase._files.MAX_LINE_LEN
    assert limit == 65536
    for tail in ("!" + "x" * (limit - 1) + "\n", "!" + "x" * (limit - 2) + "\r\n"):
        interphase.read_case(write_case(tmp_path, CASE.replace("/\n&loading", "/\n" + tail + "&loading")))
    for tail in ("!" + "x" * limit + "\n", "!" + "x" * (limit - 1) + "\r\n"):
        path = write_case(tmp_path, CASE.replace("/\n&loading", "/\n" + tail + "&loading"))
        for read in (interphase.read_case, interphase.read_namelist):
            with pytest.raises(ValueError) as caught:
                read(path)
            assert str(caught.value) == f"{path}:6: cannot read the line: line longer than 65536 characters"
    history = tmp_path / "h.txt"
    history.write_text("# " + "x" * (limit - 2) + "\n" + HISTORY)
    assert interphase.read_history(history)[0].tolist() == [0.0, 1.0]
    history.write_text("0 0 0\n# " + "x" * (limit - 1) + "\n1 0 0.01\n")
    with pytest.raises(ValueError) as caught:
        interphase.read_history(history)
    assert str(caught.value) == f"{history}:2: cannot read the line: line longer than 65536 characters"
    path = write_case(tmp_path, history=history.read_text())
    with pytest.raises(ValueError, match=r"h\.txt:2: cannot read the line: line longer than 65536 characters$"):
        interphase.read_case(path)


def test_words_are_split_at_blanks_and_tabs_only(tmp_path):
    """A no-break space (U+00A0) or another white-space character is part of a word, as for the
    driver: '0.01<NBSP>' is no number, 'simplified<NBSP>' no model; blanks, tabs and carriage
    returns separate words."""
    history = tmp_path / "h.txt"
    history.write_text("0 0 0\n1 0 0.01\u00a0\n", encoding="utf-8")
    with pytest.raises(ValueError) as caught:
        interphase.read_history(history)
    assert str(caught.value) == f"{history}:2: column 3: cannot parse '0.01\u00a0' as a number"
    for text, message in [("0 0 0\n1 0\x0b0.01\n", "2: found 2 columns, but line 1 has 3"),
                          ("0\u20030 0\n1 0 0.01\n", "1: found 2 columns; expected 3"),
                          ("# columns: t s_T\u00a0Sigma_N\n0 0 0\n1 0 0.01\n", '1: "# columns:" names 2 columns')]:
        history.write_text(text, encoding="utf-8")
        with pytest.raises(ValueError) as caught:
            interphase.read_history(history, control=True)
        assert str(caught.value).startswith(f"{history}:{message}")
    # a '#<NBSP>columns:' comment is a plain comment (every column a separation), as for the driver
    history.write_text("#\u00a0columns: t s_T Sigma_N\n0 0 0\n1 0 0.01\n", encoding="utf-8")
    assert not interphase.read_history(history, control=True)[2].any()
    history.write_text("0\t0 0\r\n1 0\t0.01\r\n")
    assert interphase.read_history(history)[1].tolist() == [[0.0, 0.0], [0.01, 0.0]]
    path = write_case(tmp_path, CASE.replace("'simplified'", "'simplified\u00a0'"))
    with pytest.raises(interphase.InterphaseError) as caught:
        interphase.read_case(path)
    # (the entry's line named, as interphase-point names it)
    assert caught.value.detail == (f"{path}:2: &material: model 'simplified\u00a0' is unknown (available: 'simplified', "
                                   "'micromechanical')")
    with pytest.raises(interphase.InterphaseError, match="model 'simplified\t' is unknown"):
        interphase.Material(**dict(SIMPLIFIED, model="simplified\t"))
    with pytest.raises(interphase.InterphaseError, match="stiffness must be"):
        interphase.Material(**dict(SIMPLIFIED, stiffness="symmetric\u00a0"))


@pytest.mark.parametrize("entries, message", [
    ("tangent_check = -1", "7: &loading: tangent_check must be a finite number >= 0 (0: no check), got -1.0"),
    ("tangent_check = 1", "7: &loading: tangent_check = 1.0 would pass a tangent wrong by its own size or more (a "
                          "relative error >= 1): it must be < 1 (e.g. 1e-5; 0: no check)"),
    ("tangent_check = 1e300", "7: &loading: tangent_check = 0.1E+301 would pass a tangent wrong by its own size or "
                              "more (a relative error >= 1): it must be < 1 (e.g. 1e-5; 0: no check)"),
    ("tangent_check = 1e-5\n  tangent_step = 0",
     "8: &loading: tangent_step must be a finite number > 0 (mm), got 0.0"),
    ("tangent_check = 1e-5\n  tangent_step = -1e-8",
     "8: &loading: tangent_step must be a finite number > 0 (mm), got -0.1E-7"),
    ("tangent_step = 1e-7", "7: &loading: tangent_step is an entry of the tangent check only: set tangent_check > 0 "
                            "too, or drop tangent_step"),
    ("traction_tolerance = 0", "7: &loading: traction_tolerance must be a finite number > 0 and at most 1e-3 (MPa), "
                               "got 0.0: Newton meets an imposed traction only to within it (joints carry tractions "
                               "of 0.01 to 10 MPa)"),
    ("traction_tolerance = -2.5e-300",
     "7: &loading: traction_tolerance must be a finite number > 0 and at most 1e-3 (MPa), got -0.25E-299: Newton "
     "meets an imposed traction only to within it (joints carry tractions of 0.01 to 10 MPa)"),
    # (a tolerance as large as the tractions: Newton would accept an imposed 0.5 MPa never applied)
    ("traction_tolerance = 0.1",
     "7: &loading: traction_tolerance must be a finite number > 0 and at most 1e-3 (MPa), got 0.1: Newton meets "
     "an imposed traction only to within it (joints carry tractions of 0.01 to 10 MPa)"),
    ("output_every = 0", "7: &loading: output_every must be at least 1, got 0"),
    ("output_every = -3", "7: &loading: output_every must be at least 1, got -3"),
    ("increments = -2", "7: &loading: increments must be at least 1, got -2"),
])
def test_read_case_makes_the_drivers_loading_checks(tmp_path, entries, message):
    """Every check interphase-point's read_loading makes, with its message and the entry's line;
    made before the constants' ranges are checked, as by the driver."""
    text = CASE
    for entry in re.findall(r"(\w+) =", entries):      # (given once: the case's own line dropped)
        text = re.sub(rf"  {entry} = .*\n", "", text)
    text = text.replace("  history = 'h.txt'\n", "  " + entries + "\n  history = 'h.txt'\n")
    for case in (text, text.replace("mu = 0.75", "mu = -0.75")):
        path = write_case(tmp_path, case)
        with pytest.raises(ValueError) as caught:
            interphase.read_case(path)
        assert str(caught.value) == f"{path}:{message}"
    given = "  tangent_check = 1e-5, tangent_step = 1e-7, output_every = 3\n"
    case = interphase.read_case(write_case(tmp_path, CASE.replace("  history", given + "  history")))
    assert (case.tangent_check, case.tangent_step, case.output_every) == (1e-5, 1e-7, 3)
    assert interphase.read_case(write_case(tmp_path)).tangent_step == 1e-8


def test_reals_in_messages_are_written_as_the_driver_writes_them():
    """_real_text: Fortran's g0.d with the fewest digits that read back as the same double."""
    real_text = interphase._files._real_text
    assert [real_text(x) for x in (-1.0, 0.0, 0.75, -1e-8, 1e300, -1.5e-300, 0.099999, 12.5, 100.0, 0.05625,
                                   1.7976931348623157e308, 5e-324)] == \
        ["-1.0", "0.0", "0.75", "-0.1E-7", "0.1E+301", "-0.15E-299", "0.99999E-1", "12.5", "0.1E+3", "0.5625E-1",
         "0.17976931348623157E+309", "0.5E-323"]


@pytest.mark.parametrize("arguments, error, message", [
    (dict(increments=2.5), TypeError, "increments must be an integer, got 2.5"),
    (dict(increments="3"), TypeError, "increments must be an integer, got '3'"),
    (dict(increments=True), TypeError, "increments must be an integer, got True"),
    (dict(increments=3.0), TypeError, "increments must be an integer, got 3.0"),
    (dict(increments=0), ValueError, "increments must be at least 1, got 0"),
    (dict(increments=2**31), ValueError, "increments = 2147483648 is too large"),
    (dict(output_every=1.9), TypeError, "output_every must be an integer, got 1.9"),
    (dict(output_every=np.True_), TypeError, "output_every must be an integer"),
    (dict(output_every=2**32), ValueError, "output_every = 4294967296 is too large"),
    (dict(traction_tolerance="1e-12"), TypeError, "traction_tolerance must be a number"),
    (dict(tangent="no"), TypeError, "tangent must be True or False, got 'no'"),
    (dict(tangent=0), TypeError, "tangent must be True or False, got 0"),
    (dict(tangent=None), TypeError, "tangent must be True or False, got None"),
    (dict(history=[[0.0, 0.0]]), ValueError, "history must have at least 2 rows .*, got 1"),
    (dict(history=[["0", "0"], ["0.01", "0"]]), TypeError, "history must hold real numbers"),
    (dict(time=["0", "1"]), TypeError, "time must hold real numbers"),
])
def test_run_refuses_what_it_would_convert(arguments, error, message):
    """Counts are integers (a numpy integer too), at least 1, a C int; no bool, float or string is
    rounded or parsed; a history has 2 rows at least, as the driver's."""
    m = interphase.Material(**SIMPLIFIED)
    arguments = dict(dict(history=[[0.0, 0.0], [0.01, 0.0]]), **arguments)
    with pytest.raises(error, match=message):
        m.run(**arguments)
    if "increments" in arguments or "output_every" in arguments:
        with pytest.raises(error, match=message):
            interphase.Case(m, np.array([0.0, 1.0]), np.array([[0.0, 0.0], [0.01, 0.0]]), output="x.csv",
                            **dict(dict(increments=1), **{k: v for k, v in arguments.items()
                                                          if k in ("increments", "output_every")}))


def test_run_takes_numpy_integers():
    m = interphase.Material(**SIMPLIFIED)
    history = [[0.0, 0.0], [0.01, 0.0]]
    plain = m.run(history, increments=6, output_every=2)
    numpy = m.run(history, increments=np.int32(6), output_every=np.uint8(2))
    assert len(plain) == 4 and np.array_equal(plain.traction, numpy.traction)
    with pytest.raises(TypeError, match="dt must be a number"):
        m.update([0.001, 0.0], dt="0.1")


# case files that interphase-point and read_case must refuse (or take) alike, each a change of CASE
# (old, new) and, where given, another history
DRIVER_CASES = {
    "history_blank_after": ("'h.txt'", "'h.txt '", None),
    "history_blank_before": ("'h.txt'", "' h.txt'", None),
    "history_empty": ("'h.txt'", "''", None),
    "output_empty": ("'h.csv'", "''", None),
    "long_comment": ("/\n&loading", "/\n!" + "x" * 65536 + "\n&loading", None),
    "long_history_comment": ("'h.txt'", "'h.txt'", "# " + "x" * 65535 + "\n" + HISTORY),
    "nbsp_in_history": ("'h.txt'", "'h.txt'", "0 0 0\n1 0 0.01\u00a0\n"),
    "one_row": ("'h.txt'", "'h.txt'", "0 0 0\n"),
    "tangent_check": ("increments = 20", "increments = 20, tangent_check = -1", None),
    "tangent_check_one": ("increments = 20", "increments = 20, tangent_check = 1", None),
    "tangent_check_huge": ("increments = 20", "increments = 20, tangent_check = 1e300", None),
    "tangent_check_below_one": ("increments = 20", "increments = 20, tangent_check = 0.999", None),
    "tangent_step_zero": ("increments = 20", "increments = 20, tangent_check = 1e-5, tangent_step = 0", None),
    "tangent_step_negative": ("increments = 20", "increments = 20\n  tangent_check = 1e-5, tangent_step = -1e-8",
                              None),
    "traction_tolerance": ("increments = 20", "increments = 20, traction_tolerance = -1e-3", None),
    "traction_tolerance_loose": ("increments = 20", "increments = 20, traction_tolerance = 1.0", None),
    "output_every": ("increments = 20", "increments = 20, output_every = 0", None),
    "mu_and_one_row": ("mu = 0.75", "mu = -0.75", "0 0 0\n"),
    "model_nbsp": ("'simplified'", "'simplified\u00a0'", None),
    "unclosed_group": ("/\n&loading", "&loading", None),
    "fracture_entry": ("mu = 0.75", "mu = 0.75, g_cii = 0.1", None),
    "time": ("'h.txt'", "'h.txt'", "0 0 0\n1 0 0\n0.5 0 0\n"),
    "vertical_tab_in_row": ("'h.txt'", "'h.txt'", "0 0 0\n1 0\x0b0.01\n"),
    "carriage_return_in_row": ("'h.txt'", "'h.txt'", "0 0\r0\n1\t0 0.01\r\n"),
    "columns_header_commas": ("'h.txt'", "'h.txt'", "# t, s_T, Sigma_N\n0 0 0\n1 0 -0.5\n"),
    "columns_header_metres": ("'h.txt'", "'h.txt'", "# t s_T (m) s_N (m)\n0 0 0\n1 0.001 0\n"),
    "columns_header_micro_sign": ("'h.txt'", "'h.txt'", "# t\ts_T (\u00b5m)  s_N\n0 0 0\n1 0.001 0\n"),
    # (the micro sign with an upper-case M: both readers lower A-Z, and name the unit as written)
    "columns_header_micro_upper": ("'h.txt'", "'h.txt'", "# t s_T (\u00b5M) s_N\n0 0 0\n1 0.001 0\n"),
    "rows_commas": ("'h.txt'", "'h.txt'", "0,0,0\n1,0,0.01\n"),
    "rows_semicolons": ("'h.txt'", "'h.txt'", "0;0;0\n1;0;0.01\n"),
    "rows_semicolons_decimal_comma": ("'h.txt'", "'h.txt'", "0,5;0;0\n1;0;0,01\n"),
    "columns_upper_t": ("'h.txt'", "'h.txt'", "# columns: T s_T Sigma_N\n0 0 0\n1 0 0.01\n"),
    "table_simplified": ("'simplified'", "'simplified', table = 'x.dat'", None),
    "increments_word": ("increments = 20", "increments = abc", None),
    "entry_unknown": ("increments = 20", "increments = 20, tangent = 1", None),
    # a string holding a group marker ('&' or '$': gfortran's namelist read takes either for the
    # start of a group inside quotes too), a string longer than the driver's ENTRY_LEN (bytes)
    "group_in_string": ("'h.csv'", "'d&material model=\"micromechanical\" mu=0.1 /o.csv'", None),
    "dollar_in_string": ("'h.txt'", "'h$material.txt'", None),
    # a marker not followed by a group's name is read as it is (the driver runs the case)
    "marker_not_a_group": ("'h.csv'", "'R&D-a$b-&materials.csv'", None),
    "model_too_long": ("'simplified'", "'simplified" + " " * 1100 + "junk'", None),
    "output_of_entry_len": ("'h.csv'", "'h.csv" + " " * 1019 + "'", None),
    "output_one_byte_too_long": ("'h.csv'", "'h.csv" + "x" * 1018 + "\u00e9'", None),
    # history rows beyond the update's range: a time step that is not finite, |s| > 1e20 mm
    "time_step_not_finite": ("'h.txt'", "'h.txt'", "-1e308 0 0\n1e308 0 0.001\n"),
    "separation_beyond_range": ("'h.txt'", "'h.txt'", "0 0 0\n1 -2e20 0.01\n"),
    "traction_beyond_range": ("'h.txt'", "'h.txt'", "# columns: t s_T Sigma_N\n0 0 -1e308\n1 0 1e308\n"),
    # a nonzero number below the smallest normal double (read as 0 or a subnormal before): refused
    "mu_underflow": ("mu = 0.75", "mu = 1e-400", None),
    "mu_subnormal": ("mu = 0.75", "mu = 1d-310", None),
    "mu_exponent_zeros": ("mu = 0.75", "mu = 0.75e0000000", None),
    "history_underflow": ("'h.txt'", "'h.txt'", "0 0 0\n1 0 1e-400\n"),
    "history_exponent_zeros": ("'h.txt'", "'h.txt'", "0 0 0\n1 0 0.01E+000000000\n"),
    # files that cannot be used: named as the driver names them (its absolute path; the entry)
    "history_missing": ("history = 'h.txt'", "history = 'missing.txt'", None),
    "rcurve_file_refused": ("damage_law = 'displacement'", "damage_law = 'fracture', d0 = 0.05, rcurve = 'tabulated', "
                            "rcurve_file = 'h.txt'", None),
    # the material as the UMAT's PROPS (the entry props): taken; refused beside an entry PROPS
    # hold, with a value the decoder refuses, without the file PROPS select or with one they do
    # not select, with more values than the longest PROPS, with a value that is not a number
    "props": (CASE_MATERIAL, PROPS_MATERIAL, None),
    "props_with_entries": (CASE_MATERIAL, PROPS_MATERIAL + "  mu = 0.6, stiffness = 'symmetric'\n", None),
    "props_bad_value": (CASE_MATERIAL, PROPS_MATERIAL.replace("0.04,", "0.0001,"), None),
    "props_custom_table": (CASE_MATERIAL, "  props = 2, 1, 0.75, 0.00044, 0.04, 0.00072, 0.06, 1\n", None),
    "props_table_not_read": (CASE_MATERIAL, "  props = 2, 1, 0.75, 0.00044, 0.04, 0.00072, 0.06, 0\n"
                             "  table = 'x.dat'\n", None),
    "props_tabulated_without_file": (CASE_MATERIAL, PROPS_MATERIAL.replace("1, 1,", "1, 2,").replace(
        "198.75776397515528", "198.75776397515528, 0.05, 3, 0, 0"), None),
    "props_rcurve_file_not_read": (CASE_MATERIAL, PROPS_MATERIAL + "  rcurve_file = 'h.txt'\n", None),
    "props_too_many": (CASE_MATERIAL, PROPS_MATERIAL.replace("198.75776397515528", "198.75776397515528" + ", 0" * 12),
                       None),
    "props_not_a_number": (CASE_MATERIAL, PROPS_MATERIAL.replace("0.75,", "abc,"), None),
    # the UMAT's own options (layer thickness, layer normal, host): refused, as the C API refuses them
    "props_layer_thickness": (CASE_MATERIAL, PROPS_MATERIAL.replace("198.75776397515528",
                                                                    "198.75776397515528, 0, 0, 0, 0, 2.0"), None),
    "props_host": (CASE_MATERIAL, PROPS_MATERIAL.replace("198.75776397515528",
                                                         "198.75776397515528, 0, 0, 0, 0, 0, 0, 1"), None),
    # a value equal to the drivers' marker of an entry left out (-huge) is a value all the same
    "props_huge_negative": (CASE_MATERIAL, PROPS_MATERIAL.replace("0.75,", "-1.7976931348623157e308,"), None),
    "props_huge_negative_last": (CASE_MATERIAL, PROPS_MATERIAL.replace("198.75776397515528",
                                                                       "198.75776397515528, -1.7976931348623157e308"),
                                 None),
}


@pytest.mark.parametrize("name", sorted(DRIVER_CASES))
def test_read_case_refuses_what_the_driver_refuses(point_driver, tmp_path, monkeypatch, name):
    """interphase-point itself on the case: what it refuses read_case refuses, with its message
    (an InterphaseError's detail); what it runs read_case reads."""
    old, new, history = DRIVER_CASES[name]
    assert old in CASE
    write_case(tmp_path, CASE.replace(old, new), HISTORY if history is None else history)
    monkeypatch.chdir(tmp_path)
    done = subprocess.run([point_driver, "case.nml", "--no-plot", "--output-dir", "out"], capture_output=True)
    lines = done.stderr.decode("utf-8", errors="surrogateescape").split("\n")
    if done.returncode == 0:
        interphase.read_case("case.nml")
        return
    expected = next(line for line in lines if line.startswith("interphase-point: error: "))
    with pytest.raises((ValueError, TypeError, OSError)) as caught:
        interphase.read_case("case.nml")
    error = caught.value
    got = error.detail if isinstance(error, interphase.InterphaseError) else str(error)
    assert got == expected[len("interphase-point: error: "):]
    if name == "rcurve_file_refused":
        # (the detail holds the driver's line, status text included; str() names the status once)
        assert str(error).count(error.reason) == 1 and error.name in str(error)


# Case files the driver refuses naming where the value came from (the entry and its line, the file
# it names), and the read_case refusal that must give the same text: (the case's text, the files
# written beside it: {name: text}).
RCURVE_TO_03 = "# D G_cI G_cII\n0.0 0.005 0.0085\n0.3 0.005 0.0085\n"
NAMED_CASES = {
    # a history that cannot be opened: the case file, the entry's line, the path tried
    "history_missing": (CASE.replace("'h.txt'", "'missing.txt'"), {}),
    # a tabulated R-curve that does not cover D0: refused with the case, under d0 and its line,
    # with the file's D range and D0 (was: the UMAT's message at the first update)
    "rcurve_not_d0": (CASE.replace("damage_law = 'displacement'", "damage_law = 'fracture'\n  d0 = 0.5, "
                                   "rcurve = 'tabulated', rcurve_file = 'r.txt'"), {"r.txt": RCURVE_TO_03}),
    # a table that cannot be read: the entry's line too
    "table_missing": (CASE.replace("'simplified'", "'micromechanical', table = 'no.dat'").replace(
        "  k_n = 482.69742679680568, k_t = 198.75776397515528\n", ""), {}),
    # rcurve = 'constant' names the toughness left out, only that one
    "constant_gci_only": (CASE.replace("damage_law = 'displacement'", "damage_law = 'fracture'\n  d0 = 0.05, "
                                       "rcurve = 'constant', g_ci = 0.005"), {}),
    "constant_gcii_only": (CASE.replace("damage_law = 'displacement'", "damage_law = 'fracture'\n  d0 = 0.05, "
                                        "rcurve = 'constant', g_cii = 0.005"), {}),
    # the same through props: named under props and its line
    "props_rcurve_not_d0": (CASE.replace(CASE_MATERIAL, PROPS_MATERIAL.replace("1, 1,", "1, 2,").replace(
        "198.75776397515528", "198.75776397515528, 0.5, 3, 0, 0") + "  rcurve_file = 'r.txt'\n"),
                            {"r.txt": RCURVE_TO_03}),
    # one field a line: "1 column", singular
    "one_column": (CASE, {"h.txt": "0,0,0\n1,0,0.01\n"}),
    # no group at all: said so, not "&material: group not found"
    "empty": ("", {}),
    "comments_only": ("! a case file of comments only\n\n   ! and blank lines\n", {}),
}
NAMED_MESSAGES = {
    "history_missing": r"case\.nml:\d+: &loading: history: .*/missing\.txt: cannot open the history file: ",
    "rcurve_not_d0": r"case\.nml:\d+: &material: d0: tabulated R-curve does not cover the damage reached \(or D0\): "
                     r"R-curve .*/r\.txt covers D from 0\.00000 to 0\.300000, not the initial crack D0 = 0\.500000$",
    "table_missing": r"case\.nml:\d+: &material: table: RVE table file cannot be opened or read: .*/no\.dat",
    "constant_gci_only": r"case\.nml:\d+: &material: rcurve = 'constant' needs the entry g_cii \(N/mm; g_ci is given\)$",
    "constant_gcii_only": r"case\.nml:\d+: &material: rcurve = 'constant' needs the entry g_ci \(N/mm; g_cii is given\)$",
    "props_rcurve_not_d0": r"case\.nml:2: &material: props: tabulated R-curve does not cover the damage reached "
                           r"\(or D0\): R-curve .*/r\.txt covers D from 0\.00000 to 0\.300000, not the initial crack "
                           r"D0 = 0\.500000$",
    "one_column": r"h\.txt:1: found 1 column; expected 3 ",
    "empty": r"^case\.nml: no namelist group in the file \(expected &material and &loading\)$",
    "comments_only": r"^case\.nml: no namelist group in the file \(expected &material and &loading\)$",
}


@pytest.mark.parametrize("name", sorted(NAMED_CASES))
def test_read_case_names_where_a_value_came_from_as_the_driver_does(point_driver, tmp_path, monkeypatch, name):
    """interphase-point and read_case on the same case: both refuse it with the same text, which
    names the case file, the entry and its line (or the file named and its line)."""
    case, files = NAMED_CASES[name]
    write_case(tmp_path, case)
    for file_name, text in files.items():
        (tmp_path / file_name).write_text(text)
    monkeypatch.chdir(tmp_path)
    done = subprocess.run([point_driver, "case.nml", "--no-plot", "--output-dir", "out"], capture_output=True)
    lines = done.stderr.decode("utf-8", errors="surrogateescape").split("\n")
    assert done.returncode == 1
    expected = next(line for line in lines if line.startswith("interphase-point: error: "))
    expected = expected[len("interphase-point: error: "):]
    assert re.search(NAMED_MESSAGES[name], expected), expected
    with pytest.raises((ValueError, OSError)) as caught:
        interphase.read_case("case.nml")
    error = caught.value
    got = error.detail if isinstance(error, interphase.InterphaseError) else str(error)
    assert got == expected
    if name in ("rcurve_not_d0", "props_rcurve_not_d0"):
        assert error.status == interphase.STATUS_RCURVE_OUT_OF_RANGE
    if name == "history_missing":
        assert isinstance(error, FileNotFoundError)


def test_read_case_names_a_missing_case_file_as_the_driver_does(point_driver, tmp_path, monkeypatch):
    """A case file that cannot be opened: the driver's message (its absolute path), the OSError of
    open() kept as the exception's type."""
    monkeypatch.chdir(tmp_path)
    done = subprocess.run([point_driver, "missing.nml", "--no-plot"], capture_output=True)
    expected = next(line for line in done.stderr.decode().split("\n") if line.startswith("interphase-point: error: "))
    with pytest.raises(FileNotFoundError) as caught:
        interphase.read_case("missing.nml")
    assert done.returncode != 0 and str(caught.value) == expected[len("interphase-point: error: "):]


def test_run_refuses_a_time_step_beyond_the_largest_double():
    """Finite times whose difference is not (the replay interpolates the time within a step):
    the library refuses them (STATUS_BAD_HISTORY), naming the time and the one before it."""
    m = interphase.Material(**SIMPLIFIED)
    with pytest.raises(interphase.InterphaseError, match=r"time\[1\] = .*: the time step from time\[0\] = .* is not "
                       r"finite") as caught:
        m.run([[0.0, 0.0], [0.01, 0.0]], time=[-1e308, 1e308])
    assert caught.value.status == interphase.STATUS_BAD_HISTORY and caught.value.result is None


def _fortran_parameter(path, name):
    """The value of a Fortran `parameter` NAME = value in the file at path (a real or an integer)."""
    found = re.search(rf"::\s*{name}\s*=\s*([0-9.eEdD+-]+?)(?:_dp)?\s*$", path.read_text(), re.MULTILINE)
    assert found, f"{name} not found in {path}"
    return float(found.group(1).replace("d", "e").replace("D", "e"))


def test_constants_are_the_librarys_and_the_drivers(source_dir):
    # the package's copies of the replay's limits and the driver's defaults, against the Fortran
    # sources they document (a change there must reach the package)
    mixed = source_dir / "src" / "interphase_mixed_control.f90"
    case = source_dir / "drivers" / "interphase_driver_case.f90"
    assert interphase.MAX_HALVINGS == _fortran_parameter(mixed, "MAX_HALVINGS")
    assert interphase.MAX_NEWTON == _fortran_parameter(mixed, "MAX_NEWTON")
    assert interphase.TRACTION_TOLERANCE_MAX == _fortran_parameter(mixed, "TRACTION_TOLERANCE_MAX")
    assert interphase.DEFAULT_TRACTION_TOLERANCE == _fortran_parameter(case, "DEFAULT_TRACTION_TOLERANCE")
    assert interphase.DEFAULT_TANGENT_STEP == _fortran_parameter(case, "DEFAULT_TANGENT_STEP")


def test_pickled_material_keeps_read_only_props_and_its_state_size():
    # a Material sent to a worker process (pickle) kept PROPS writeable (numpy does not pickle the
    # flag): the viscosity option switched on in place then made the library write 5 state
    # variables into the 4 of the material's buffers (heap corruption, "double free or corruption")
    import pickle
    m = interphase.Material(**dict(SIMPLIFIED, stiffness="symmetric"))   # PROPS hold the viscosity slot (0)
    copy = pickle.loads(pickle.dumps(m))
    assert not copy.props.flags.writeable
    with pytest.raises(ValueError, match="read-only"):
        copy.props[11] = 0.5
    r = copy.run([[0.0, 0.0], [0.01, 0.0]], increments=10)
    assert not pickle.loads(pickle.dumps(r)).props.flags.writeable
    assert np.array_equal(r.traction, m.run([[0.0, 0.0], [0.01, 0.0]], increments=10).traction)
    # PROPS replaced by others of another state size: refused before any library call
    viscous = m.props.copy()
    viscous[11] = 0.5
    copy.props = viscous
    for call in (lambda: copy.update([0.01, 0.0], dt=0.1), lambda: copy.run([[0.0, 0.0], [0.01, 0.0]])):
        with pytest.raises(ValueError, match="PROPS were changed after it was made .* asks for 5 state variables, "
                                             "the material has 4"):
            call()


@pytest.mark.parametrize("material", [SIMPLIFIED, MICRO])
def test_update_from_the_start_separation_closes_where_the_faces_met(material):
    """An increment across which the crack closes (docs/theory.md): with separation_old, one
    increment ends where a refined path does; without it, from the state's slip, it does not."""
    m = interphase.Material(**material)
    u = None
    s_old = np.zeros(2)
    for i in range(1, 41):
        s = np.array([0.003, 0.004]) * i / 40
        u = m.update(s, None if u is None else u.state, separation_old=s_old)
        s_old = s
    opened = u.state
    assert opened[3] == 1  # open
    start, end = np.array([0.003, 0.004]), np.array([-0.001, 0.0005])
    one = m.update(end, opened, separation_old=start)
    refined, previous = opened, start
    for i in range(1, 1002):
        s = start + (end - start) * i / 1001
        r = m.update(s, refined, separation_old=previous)
        refined, previous = r.state, s
    assert one.state[3] == 2 and r.state[3] == 2  # stick
    assert one.traction[1] == pytest.approx(r.traction[1], rel=1e-10)
    assert abs(m.update(end, opened).traction[1] - r.traction[1]) > 0.1
    # the tangent is the derivative of that update, the start held
    h = 1e-8
    fd = np.empty((2, 2))
    for j in range(2):
        e = np.zeros(2)
        e[j] = h
        fd[:, j] = (m.update(end + e, opened, separation_old=start).traction
                    - m.update(end - e, opened, separation_old=start).traction) / (2 * h)
    assert np.max(np.abs(one.tangent - fd)) < 1e-6 * np.max(np.abs(one.tangent))


def test_update_checks_the_start_separation():
    m = interphase.Material(**SIMPLIFIED)
    with pytest.raises(ValueError, match="separation_old must hold 2"):
        m.update([0.001, 0.0], separation_old=[0.0, 0.0, 0.0])
    with pytest.raises(interphase.InterphaseError, match="separation_old"):
        m.update([0.001, 0.0], separation_old=[float("nan"), 0.0])
    with pytest.raises(TypeError):
        m.update([0.001, 0.0], separation_old=["a", 0.0])


def test_tangent_check_replays_a_row_that_closes_the_crack():
    """A run whose second step closes the open crack within the increment: tangent_check replays
    it from the row before (its start slip), and the tangent is that update's derivative."""
    m = interphase.Material(**SIMPLIFIED)
    r = m.run([[0.0, 0.0], [0.003, 0.004], [-0.001, 0.0005]])
    assert r.state[1][3] == 1 and r.state[2][3] == 2  # open, then stick
    check = m.tangent_check(r, 1e-5)
    assert check.checked == 2 and check.passed
