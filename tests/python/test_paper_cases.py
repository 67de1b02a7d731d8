"""Material.run reproduces interphase-point's CSV files bit for bit: the paper's five histories
(h1I, h2I, h1II, h2II, mixed) and the 3-D mixed case with every case file of
tools/run-paper-cases.sh (simplified and micromechanical models, displacement-driven and
fracture-mechanics laws), and with further combinations written here (the simplified model with
the fracture law, a custom RVE table, the options, viscous regularisation in time). The driver
of the same build writes its CSV; the package writes the same table with Result.to_csv; the two
files must be equal byte for byte (17 significant digits: every number equal to the last bit)."""

import subprocess

import numpy as np
import pytest

import interphase

SIMPLIFIED = dict(model="simplified", mu=0.75, s0_n=0.00044, sf_n=0.04, s0_t=0.00072, sf_t=0.06,
                  k_n=482.69742679680568, k_t=198.75776397515528)
MICRO = dict(model="micromechanical", mu=0.75, s0_n=0.00044, sf_n=0.04, s0_t=0.00072, sf_t=0.06)


def shipped_cases(source_dir):
    cases = source_dir / "drivers" / "cases"
    return sorted(cases.glob("*.nml")) + sorted((cases / "micro").glob("*.nml")) + \
        sorted((cases / "fracture").glob("*.nml"))


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
    assert {"h1I", "h2I", "h1II", "h2II", "mixed", "mixed3d"} <= names
    assert len(shipped_cases(source_dir)) >= 5 + 1 + 5 + 10


@pytest.mark.parametrize("index", range(21))
def test_shipped_case(point_driver, source_dir, tmp_path, index):
    cases = shipped_cases(source_dir)
    if index >= len(cases):
        pytest.skip("fewer case files")
    assert_same_csv(point_driver, cases[index], tmp_path)


def entry(value):
    if isinstance(value, str):
        return "'" + value + "'"
    return repr(float(value))


def write_case(tmp_path, name, history, material, increments=200):
    text = "&material\n" + "".join(f"  {k} = {entry(v)}\n" for k, v in material.items()) + "/\n"
    text += f"&loading\n  history = '{history}'\n  increments = {increments}\n  output = '{name}.csv'\n" \
            "  plot = .false.\n/\n"
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


def test_halvings_as_the_driver(point_driver, tmp_path):
    """A sub-increment that fails is halved: a halved step converges (its row is written), the
    rest fails until the tenth halving, as in interphase-point."""
    (tmp_path / "beyond.txt").write_text("0 0 0\n1 0 2e20\n2 0 0\n")
    case = write_case(tmp_path, "beyond", tmp_path / "beyond.txt", dict(SIMPLIFIED, damage_law="displacement"),
                      increments=3)
    error = assert_same_partial_csv(point_driver, case, tmp_path, interphase.STATUS_SEPARATION_OUT_OF_RANGE,
                                    "even after 10 halvings")
    assert error.result.separation[-1, 0] == 1e20 and len(error.result) == 3


def test_a_fatal_failure_as_the_driver(point_driver, source_dir, tmp_path):
    """A tabulated R-curve that runs out: no halving, the run stops at once (driver: the same rows)."""
    case = source_dir / "tests" / "driver" / "inputs" / "rcurve_runs_out.nml"
    assert_same_partial_csv(point_driver, case, tmp_path, interphase.STATUS_RCURVE_OUT_OF_RANGE, "covers D from")
