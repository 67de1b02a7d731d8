"""Material.run reproduces interphase-point's CSV files bit for bit: the paper's five histories
(h1I, h2I, h1II, h2II, mixed) and the 3-D mixed case with every case file of
tools/run-paper-cases.sh (simplified and micromechanical models, displacement-driven and
fracture-mechanics laws), the shear tests under an imposed precompression (drivers/cases/shear,
mixed control), and further combinations written here (the simplified model with the fracture
law, a custom RVE table, the options, viscous regularisation in time; mixed-control histories
that switch control between segments, in 2-D and 3-D, with output_every; a failure beyond the
peak). The driver
of the same build writes its CSV; the package writes the same table with Result.to_csv; the two
files must be equal byte for byte (17 significant digits: every number equal to the last bit)."""

import re
import subprocess

import numpy as np
import pytest

import interphase
from interphase._files import _real_text

SIMPLIFIED = dict(model="simplified", mu=0.75, s0_n=0.00044, sf_n=0.04, s0_t=0.00072, sf_t=0.06,
                  k_n=482.69742679680568, k_t=198.75776397515528)
MICRO = dict(model="micromechanical", mu=0.75, s0_n=0.00044, sf_n=0.04, s0_t=0.00072, sf_t=0.06)


def shipped_cases(source_dir):
    cases = source_dir / "drivers" / "cases"
    return sorted(cases.glob("*.nml")) + sorted((cases / "micro").glob("*.nml")) + \
        sorted((cases / "fracture").glob("*.nml")) + sorted((cases / "shear").glob("*.nml"))


def run_driver(driver, case, out_dir):
    done = subprocess.run([driver, str(case), "--output-dir", str(out_dir), "--no-plot"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    return done


def assert_same_csv(driver, case, tmp_path):
    run_driver(driver, case, tmp_path)
    c = interphase.read_case(case)
    expected = (tmp_path / c.output).read_bytes()
    ours = tmp_path / ("python-" + c.output)
    c.run().to_csv(ours)
    got = ours.read_bytes()
    if got != expected:
        for k, (a, b) in enumerate(zip(got.decode().splitlines(), expected.decode().splitlines())):
            assert a == b, f"{case.name}: CSV line {k + 1} differs:\n python: {a}\n driver: {b}"
        assert len(got) == len(expected), f"{case.name}: the CSV files differ in length"
    # the arrays themselves, parsed back from the driver's CSV, equal to the last bit
    table = np.genfromtxt(tmp_path / c.output, delimiter=",", names=True, dtype=None, encoding="ascii")
    r = c.run()
    assert np.array_equal(table["t"], r.time)
    assert np.array_equal(table["D"], r.damage)
    assert np.array_equal(table["W_dis"], r.dissipated_energy)
    assert list(table["state"]) == r.regime_names


def test_the_shipped_cases_are_all_there(source_dir):
    names = {p.stem for p in shipped_cases(source_dir)}
    assert {"h1I", "h2I", "h1II", "h2II", "mixed", "mixed3d", "shear-0.5", "micro-shear-0.5"} <= names
    assert len(shipped_cases(source_dir)) >= 5 + 1 + 5 + 10 + 6
    assert len(shipped_cases(source_dir)) <= 32, "more shipped cases than test_shipped_case runs"


def test_the_shear_cases_impose_the_precompression(source_dir):
    """The shipped shear cases are mixed-control: Sigma_N imposed (the Python run follows it)."""
    for case in sorted((source_dir / "drivers" / "cases" / "shear").glob("*.nml")):
        c = interphase.read_case(case)
        assert c.control[:, 0].all() and not c.control[:, 1].any(), case.name
        r = c.run()
        p = -c.value[-1, 0]
        assert p > 0 and np.abs(r.traction[r.time >= 1.0, 0] + p).max() <= c.traction_tolerance, case.name


@pytest.mark.parametrize("index", range(32))
def test_shipped_case(point_driver, source_dir, tmp_path, index):
    cases = shipped_cases(source_dir)
    if index >= len(cases):
        pytest.skip("fewer case files")
    assert_same_csv(point_driver, cases[index], tmp_path)


def entry(value):
    if isinstance(value, str):
        return "'" + value + "'"
    return repr(float(value))


def write_case(tmp_path, name, history, material, increments=200, **loading):
    text = "&material\n" + "".join(f"  {k} = {entry(v)}\n" for k, v in material.items()) + "/\n"
    text += f"&loading\n  history = '{history}'\n  increments = {increments}\n  output = '{name}.csv'\n" \
            "  plot = .false.\n" + "".join(f"  {k} = {v}\n" for k, v in loading.items()) + "/\n"
    path = tmp_path / f"{name}.nml"
    path.write_text(text)
    return path


EXTRA = {
    "simplified-fracture-constant": (dict(SIMPLIFIED, damage_law="fracture", d0=0.02, rcurve="constant",
                                          g_ci=0.0089, g_cii=0.0207), ["h1I", "h1II", "mixed", "mixed3d"]),
    "simplified-fracture-equivalent": (dict(SIMPLIFIED, damage_law="fracture", d0=0.02, rcurve="equivalent"),
                                       ["h2I", "h2II", "mixed"]),
    "micro-custom-table": (dict(MICRO, damage_law="displacement", table="TABLE"), ["mixed", "h2II"]),
    "micro-options": (dict(MICRO, damage_law="displacement", growth_slip="fixed-lambda", contact_band=0.6,
                           stiffness="symmetric"), ["mixed", "mixed3d"]),
    "micro-viscous": (dict(MICRO, damage_law="displacement", viscosity=0.05), ["h1I", "mixed"]),
    "simplified-viscous": (dict(SIMPLIFIED, damage_law="displacement", viscosity=0.2), ["h2II", "mixed3d"]),
}


@pytest.mark.parametrize("name", sorted(EXTRA))
def test_more_combinations(point_driver, source_dir, tmp_path, name):
    material, histories = EXTRA[name]
    if material.get("table") == "TABLE":
        material = dict(material, table=str(source_dir / "tables" / "paper-resolution.dat"))
    for h in histories:
        history = source_dir / "drivers" / "cases" / f"{h}.txt"
        assert_same_csv(point_driver, write_case(tmp_path, f"{name}-{h}", history, material, increments=37),
                        tmp_path)


def assert_same_partial_csv(driver, case, tmp_path, status, words):
    """A run that fails: the driver stops with an error, leaves the rows up to the failure in
    OUTPUT.part and does not write OUTPUT; the package raises the same failure, and the rows its
    error carries are that file's, byte for byte."""
    done = subprocess.run([driver, str(case), "--output-dir", str(tmp_path), "--no-plot"],
                          capture_output=True, text=True)
    c = interphase.read_case(case)
    assert done.returncode != 0 and (c.output + ".part") in done.stderr, done.stdout + done.stderr
    assert not (tmp_path / c.output).exists()
    with pytest.raises(interphase.InterphaseError) as caught:
        c.run()
    error = caught.value
    assert error.status == status and words in str(error), str(error)
    ours = tmp_path / "python.csv"
    error.result.to_csv(ours)
    assert ours.read_bytes() == (tmp_path / (c.output + ".part")).read_bytes()
    return error


def test_separations_beyond_the_range_as_the_driver(point_driver, tmp_path):
    """A separation beyond 1e20 mm in a history is refused before any update, naming where it is:
    by Material.run (the library's interphase_run_history; it used to run, halve the failing
    sub-increment ten times and name an interpolated separation) and by both history readers at
    its line."""
    m = interphase.Material(**dict(SIMPLIFIED, damage_law="displacement"))
    with pytest.raises(interphase.InterphaseError,
                       match=re.escape("value[2] (row 1, component 0: s_N) = 0.2E+21 mm is beyond the range the "
                                       "update admits")) as caught:
        m.run([[0.0, 0.0], [2e20, 0.0], [0.0, 0.0]], increments=3)
    error = caught.value
    assert error.status == interphase.STATUS_SEPARATION_OUT_OF_RANGE and error.result is None
    (tmp_path / "beyond.txt").write_text("0 0 0\n1 0 2e20\n2 0 0\n")
    case = write_case(tmp_path, "beyond", tmp_path / "beyond.txt", dict(SIMPLIFIED, damage_law="displacement"),
                      increments=3)
    done = subprocess.run([point_driver, str(case), "--no-plot", "--output-dir", str(tmp_path)], capture_output=True)
    expected = "beyond.txt:2: column 3: separation 0.2E+21 mm is beyond the range the update admits"
    assert done.returncode != 0 and expected in done.stderr.decode()
    with pytest.raises(ValueError, match=re.escape(expected)):
        interphase.read_case(case)


def test_a_fatal_failure_as_the_driver(point_driver, source_dir, tmp_path):
    """A tabulated R-curve that runs out: no halving, the run stops at once (driver: the same rows)."""
    case = source_dir / "tests" / "driver" / "inputs" / "rcurve_runs_out.nml"
    assert_same_partial_csv(point_driver, case, tmp_path, interphase.STATUS_RCURVE_OUT_OF_RANGE, "covers D from")


# mixed-control histories (drivers/README.md, 'Mixed control'): the control switches between
# segments; 3-D with two imposed tractions
MIXED_HISTORIES = {
    "switch": """# tension, then a shear traction on the open crack, then back to separations
# columns: t s_T s_N
0 0 0
1 0 0.002
# columns: t Sigma_T s_N
2 0.02 0.002
3 -0.01 0.002
# columns: t s_T s_N
4 0 0
""",
    "precompressed3d": """# 3-D shear under precompression, the second shear traction held at zero
# columns: t s_T1 Sigma_T2 Sigma_N
0 0 0 0
1 0 0 -0.3
2 0.08 0 -0.3
# columns: t s_T1 s_T2 Sigma_N
3 0.08 0.03 -0.3
""",
    "preloaded": """# a first row away from zero: the precompression reached in the preload steps
# columns: t (s) s_T (mm) Sigma_N (MPa)
0 0 -0.4
1 0.05 -0.4
2 0.0 -0.4
""",
}

MIXED_MATERIALS = {
    "simplified": dict(SIMPLIFIED, damage_law="displacement"),
    "micro-fracture": dict(MICRO, damage_law="fracture", d0=0.02, rcurve="equivalent"),
    "micro-viscous": dict(MICRO, damage_law="displacement", viscosity=0.05),
}


@pytest.mark.parametrize("history", sorted(MIXED_HISTORIES))
@pytest.mark.parametrize("material", sorted(MIXED_MATERIALS))
def test_mixed_control_as_the_driver(point_driver, tmp_path, history, material):
    path = tmp_path / f"{history}.txt"
    path.write_text(MIXED_HISTORIES[history])
    case = write_case(tmp_path, f"{material}-{history}", path, MIXED_MATERIALS[material], increments=40,
                      traction_tolerance="1e-13", output_every=3)
    assert interphase.read_case(case).control.any()
    assert_same_csv(point_driver, case, tmp_path)


def test_beyond_the_peak_as_the_driver(point_driver, source_dir, tmp_path):
    """An imposed normal traction raised beyond the peak: no solution; the library's status and
    message, and the rows up to there as in the driver's OUTPUT.part."""
    case = source_dir / "tests" / "driver" / "inputs" / "beyond_peak.nml"
    error = assert_same_partial_csv(point_driver, case, tmp_path, interphase.STATUS_BEYOND_PEAK,
                                    "the imposed traction Sigma_N = ")
    assert "beyond the peak the material can carry" in error.detail
    assert error.name == "STATUS_BEYOND_PEAK"
    assert error.result.traction[-1, 0] < 0.25


def tangent_case(source_dir, tmp_path, history, extra=""):
    """A case file in tmp_path with the driver's tangent check on `history` (drivers/cases)."""
    case = tmp_path / "tangent.nml"
    case.write_text("&material\n  model = 'simplified', damage_law = 'displacement', mu = 0.75,\n"
                    "  s0_n = 0.00044, sf_n = 0.04, s0_t = 0.00072, sf_t = 0.06,\n"
                    "  k_n = 482.69742679680568, k_t = 198.75776397515528\n/\n"
                    f"&loading\n  history = '{source_dir / 'drivers' / 'cases' / history}', increments = 200,\n"
                    f"  output = 'tangent.csv', plot = .false., tangent_check = 1e-5{extra}\n/\n")
    return case


def test_tangent_check_is_the_drivers(point_driver, source_dir, tmp_path):
    """Material.tangent_check gives interphase-point's tangent_error column, number for number, on
    the paper's mixed history (every row but the first: the driver also checks the steps that
    reach the history's first row, which run does not return), and its worst error and kinks."""
    case = tangent_case(source_dir, tmp_path, "mixed.txt")
    done = subprocess.run([point_driver, str(case), "--output-dir", str(tmp_path), "--no-plot"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    table = np.genfromtxt(tmp_path / "tangent.csv", delimiter=",", names=True, dtype=None, encoding="ascii")
    c = interphase.read_case(case)
    check = c.check_tangent(c.run())
    assert np.isnan(check.errors[0])
    assert np.array_equal(check.errors[1:], table["tangent_error"][1:])
    assert check.passed and check.checked == len(table) - 1 and check.kinks == 2 and check.unchecked == 0
    assert check.worst == np.max(table["tangent_error"][1:])


def test_tangent_check_finds_a_wrong_tangent(source_dir, tmp_path):
    """A closed, damaged crack held at s = 0 after it closed there: its state sticks at the apex of
    the Coulomb cone (Sigma_N = 0, tau = 0), the next update slips on both sides in s_T, and DDSDDE
    is the stick tangent (drivers/README.md, 'The tangent check'): the check reports it, relative
    error 0.36, and fails. The step that closes the crack at s = 0 from its open state passes (its
    friction starts from the slip where the faces met: docs/theory.md, 'An increment across which
    the crack closes'), as h2I's closures at t = 2 and t = 4 do. On the mixed history written
    every 10th step the rows are not each the update of the previous one (friction makes the path
    count): refused."""
    c = interphase.read_case(tangent_case(source_dir, tmp_path, "h2I.txt"))
    check = c.check_tangent(c.run())
    assert check.passed and check.exception_rows.tolist() == [400, 800] and check.worst < 1e-5
    m = c.material
    r = m.run([[0.0, 0.0], [0.003, 0.0], [0.0, 0.0], [0.0, 0.0]])
    check = m.tangent_check(r, 1e-5)
    assert not check.passed
    assert check.worst == pytest.approx(0.355, abs=0.01)
    assert check.worst_time == pytest.approx(3.0)
    # the failure says where, and that it is the documented exception (a closed, damaged crack
    # sticking at s_N = 0: rows 2 and 3, the closing step passing), and what the check measures
    # away from it
    assert check.worst_row == 3 and check.exception_rows.tolist() == [2, 3]
    assert check.errors[2] < 1e-5
    assert check.failure.startswith("the tangent check failed: worst relative error 0.35")
    assert ("at t = 3.0 (row 3, s_N = 0.0, s_T = 0.0 mm) is above the tolerance 0.1E-4; that row is the "
            "tangent check's one documented exception: a closed, damaged crack that sticks at s_N = 0 exactly"
            in check.failure)
    assert check.failure.endswith("rows at this exception: 2; away from them the worst relative error is "
                                  f"{_real_text(check.worst_elsewhere)} at t = 1.0 (row 1), within the tolerance")
    assert check.worst_elsewhere < 1e-5
    c = interphase.read_case(tangent_case(source_dir, tmp_path, "mixed.txt", ", output_every = 10"))
    with pytest.raises(ValueError, match="output_every=1"):
        c.check_tangent(c.run())
    # without a result the check replays the case at every step, as the driver checks it whatever
    # rows it writes: the same numbers as on the case run with output_every = 1
    every = interphase.read_case(tangent_case(source_dir, tmp_path, "mixed.txt"))
    own, full = c.check_tangent(), every.check_tangent(every.run())
    assert own.passed and np.array_equal(own.errors, full.errors, equal_nan=True)
    case = tangent_case(source_dir, tmp_path, "h2I.txt")
    case.write_text(case.read_text().replace(", tangent_check = 1e-5", ""))
    c = interphase.read_case(case)
    with pytest.raises(ValueError, match="no tangent check"):
        c.check_tangent(c.run())


def test_a_tangent_check_that_compared_no_step_fails_as_the_drivers(point_driver, source_dir, tmp_path):
    """tangent_step = 1e300: every perturbed call leaves the separations the update admits and
    fails, so nothing is compared. The driver exits with status 1 (it passed, "over 0 steps") and
    Material.tangent_check does not pass, with the driver's words."""
    case = tangent_case(source_dir, tmp_path, "h1I.txt", ", tangent_step = 1e300")
    done = subprocess.run([point_driver, str(case), "--output-dir", str(tmp_path), "--no-plot"],
                          capture_output=True, text=True)
    assert done.returncode == 1, done.stdout + done.stderr
    assert "over 0 steps" in done.stdout
    error = next(line for line in done.stderr.split("\n") if line.startswith("interphase-point: error: "))
    c = interphase.read_case(case)
    check = c.check_tangent(c.run())
    assert not check.passed and (check.checked, check.unchecked) == (0, 200)
    assert error == f"interphase-point: error: {case}: {check.failure}"
    assert check.failure == ("the tangent check compared no step: a perturbed call failed at every step (200 not "
                             "checked; tangent_step = 0.1E+301 mm)")
