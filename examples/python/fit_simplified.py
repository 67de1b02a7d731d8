#!/usr/bin/env python3
"""Calibrate the simplified (spring) model on the micromechanical model, two ways.

1. Least squares (scipy.optimize.least_squares): s0 and sf of the simplified model's normal and
   tangential laws fitted to the micromechanical traction-separation curves of the monotonic
   mode-I (h1I) and mode-II (h1II) tests, with the spring stiffnesses K_N, K_T taken from the
   micromechanical model's tangent at the origin.
2. The paper's energy equivalence (section 5.2, interphase-calibrate): the same K and sf, and s0
   set so that the fracture energies 1/2 K s0 sf equal the micromechanical ones.

Prints both parameter sets with their fracture energies and misfits, and plots the curves
(matplotlib) into OUTPUT_DIR/fit_simplified.png.

    PYTHONPATH=drivers/python INTERPHASE_LIBRARY=build/release/libinterphase.so \\
        /usr/bin/python3 examples/python/fit_simplified.py [--output-dir DIR] [--calibrate EXE]
"""

import argparse
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from scipy.optimize import least_squares
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from example_output import output_dir
import interphase

HERE = pathlib.Path(__file__).resolve().parent
SOURCE = HERE.parents[1]
# the paper's Table 1 data (drivers/cases/micro/h1I.nml); mu = 0.75 is an assumption there
MICRO = dict(model="micromechanical", damage_law="displacement", mu=0.75,
             s0_n=0.00044, sf_n=0.04, s0_t=0.00072, sf_t=0.06)
INCREMENTS = 400
HISTORIES = [interphase.read_history(SOURCE / "drivers" / "cases" / f"{h}.txt") for h in ("h1I", "h1II")]


def curves(material):
    """The paper's monotonic mode-I (h1I: Sigma_N vs s_N to 0.05 mm) and mode-II (h1II:
    Sigma_T vs s_T to 0.07 mm) tests, past full damage of the micromechanical model."""
    return [material.run(separation, time, increments=INCREMENTS) for time, separation in HISTORIES]


def simplified(k_n, k_t, s0_n, sf_n, s0_t, sf_t):
    return interphase.Material(model="simplified", damage_law="displacement", mu=MICRO["mu"],
                               s0_n=s0_n, sf_n=sf_n, s0_t=s0_t, sf_t=sf_t, k_n=k_n, k_t=k_t)


def find_calibrate(given):
    """interphase-calibrate: the one given (--calibrate, or INTERPHASE_CALIBRATE), which must be an
    executable file, else the one on PATH or in build/release, else None."""
    for name, chosen in (("--calibrate", given), ("INTERPHASE_CALIBRATE", os.environ.get("INTERPHASE_CALIBRATE"))):
        if chosen:
            if not (os.path.isfile(chosen) and os.access(chosen, os.X_OK)):
                sys.exit(f"fit_simplified.py: error: {name} {chosen}: not an executable file")
            return str(chosen)
    for candidate in (shutil.which("interphase-calibrate"),
                      SOURCE / "build" / "release" / "drivers" / "interphase-calibrate"):
        if candidate and os.access(candidate, os.X_OK):
            return str(candidate)
    return None


def energy_calibration(calibrate, micro, k_n, k_t):
    """The paper's calibration: interphase-calibrate when found, else the same steps here."""
    if calibrate:
        with tempfile.TemporaryDirectory() as work:
            case = pathlib.Path(work) / "micro.nml"
            case.write_text("&material\n" + "".join(f"  {k} = {v!r}\n" for k, v in MICRO.items()) + "/\n")
            written = pathlib.Path(work) / "calibrated.nml"
            subprocess.run([calibrate, str(case), "--write", str(written)], check=True, capture_output=True)
            m = interphase.read_namelist(written)["material"]
        return "interphase-calibrate", (m["k_n"], m["k_t"], m["s0_n"], m["sf_n"], m["s0_t"], m["sf_t"])
    # the tool's procedure: monotonic tests to 1.01 sf in 20000 increments, G = W_dis at the end
    sf_n, sf_t = MICRO["sf_n"], MICRO["sf_t"]
    g_i = micro.run([[0, 0], [1.01 * sf_n, 0]], increments=20000).dissipated_energy[-1]
    g_ii = micro.run([[0, 0], [0, 1.01 * sf_t]], increments=20000).dissipated_energy[-1]
    return "energy equivalence computed here (interphase-calibrate not found)", \
        (k_n, k_t, 2 * g_i / (k_n * sf_n), sf_n, 2 * g_ii / (k_t * sf_t), sf_t)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output-dir", default=".", help="where the figure goes (default: .)")
    parser.add_argument("--calibrate", help="the interphase-calibrate executable")
    args = parser.parse_args()
    out = output_dir(parser, args.output_dir)

    micro = interphase.Material(**MICRO)
    # undamaged stiffnesses: the tangent at the origin
    k0 = micro.update([0.0, 0.0]).tangent
    k_n, k_t = k0[0, 0], k0[1, 1]
    ref_i, ref_ii = curves(micro)

    # least squares on each mode: x = (log s0, log(sf - s0)) keeps 0 < s0 < sf
    def fit(mode, reference):
        target = reference.traction[:, mode]
        time, path = HISTORIES[mode]

        def residual(x):
            s0, sf = np.exp(x[0]), np.exp(x[0]) + np.exp(x[1])
            p = (k_n, k_t, s0, sf, MICRO["s0_t"], MICRO["sf_t"]) if mode == 0 else \
                (k_n, k_t, MICRO["s0_n"], MICRO["sf_n"], s0, sf)
            r = simplified(*p).run(path, time, increments=INCREMENTS)
            return r.traction[:, mode] - target
        s0_start = (MICRO["s0_n"], MICRO["s0_t"])[mode]
        sf_start = (MICRO["sf_n"], MICRO["sf_t"])[mode]
        x = least_squares(residual, [np.log(s0_start), np.log(sf_start - s0_start)], x_scale=1.0).x
        return np.exp(x[0]), np.exp(x[0]) + np.exp(x[1])

    s0_n, sf_n = fit(0, ref_i)
    s0_t, sf_t = fit(1, ref_ii)
    fitted = (k_n, k_t, s0_n, sf_n, s0_t, sf_t)
    how, calibrated = energy_calibration(find_calibrate(args.calibrate), micro, k_n, k_t)

    rows = []
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    for label, mode, ref, ax in (("mode I (h1I)", 0, ref_i, axes[0]), ("mode II (h1II)", 1, ref_ii, axes[1])):
        ax.plot(ref.separation[:, mode], ref.traction[:, mode], "k-", lw=2.5, label="micromechanical")
        for name, params, style in (("least squares", fitted, "C0--"), ("energy equivalence", calibrated, "C3-.")):
            r = curves(simplified(*params))[mode]
            misfit = np.sqrt(np.mean((r.traction[:, mode] - ref.traction[:, mode]) ** 2))
            ax.plot(r.separation[:, mode], r.traction[:, mode], style, lw=1.8, label=f"simplified, {name}")
            rows.append((label, name, params[2 + 2 * mode], params[3 + 2 * mode], r.dissipated_energy[-1],
                         r.traction[:, mode].max(), misfit))
        rows.append((label, "micromechanical", MICRO[("s0_n", "s0_t")[mode]], MICRO[("sf_n", "sf_t")[mode]],
                     ref.dissipated_energy[-1], ref.traction[:, mode].max(), 0.0))
        ax.set_xlabel(("s_N", "s_T")[mode] + " (mm)")
        ax.set_ylabel(("Σ_N", "Σ_T")[mode] + " (MPa)")
        ax.set_title(label)
        ax.grid(True)
        ax.legend()
    fig.suptitle("Simplified model calibrated on the micromechanical model")
    fig.tight_layout()
    fig.savefig(out / "fit_simplified.png", dpi=110)

    print(f"K_N = {k_n:.8g} MPa/mm, K_T = {k_t:.8g} MPa/mm (micromechanical tangent at the origin)")
    print(f"energy equivalence: {how}")
    print(f"{'test':15s} {'calibration':20s} {'s0 (mm)':>12s} {'sf (mm)':>12s} {'G (N/mm)':>12s} "
          f"{'peak (MPa)':>11s} {'rms misfit':>11s}")
    for r in rows:
        print(f"{r[0]:15s} {r[1]:20s} {r[2]:12.5g} {r[3]:12.5g} {r[4]:12.5g} {r[5]:11.4g} {r[6]:11.3g}")
    print("figure:", out / "fit_simplified.png")


if __name__ == "__main__":
    main()
