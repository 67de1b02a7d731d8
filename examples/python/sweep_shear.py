#!/usr/bin/env python3
"""The shear test under precompression, swept over the friction coefficient mu and the
precompression p: monotonic shear s_T from 0 to 0.1 mm at a constant normal compression, for
both models, and the envelope of the shear strength (peak shear traction) and of the residual
(frictional) shear traction against p, one curve per mu.

A closed crack has the full normal stiffness back in both models (unilateral contact), so the
normal separation s_N = -p/K_N (K_N: the normal stiffness, the tangent at the origin) holds the
normal traction at -p throughout the test; the script checks that it does.

    PYTHONPATH=drivers/python INTERPHASE_LIBRARY=build/release/libinterphase.so \\
        /usr/bin/python3 examples/python/sweep_shear.py [--output-dir DIR]
"""

import argparse
import pathlib

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import interphase

# the paper's Table 1 data; the simplified model with the calibrated s0 of interphase-calibrate
# on the built-in table (docs/paper.md, section 5.2)
BASE = dict(damage_law="displacement", s0_n=0.00044, sf_n=0.04, s0_t=0.00072, sf_t=0.06)
MODELS = {
    "micromechanical": dict(BASE, model="micromechanical"),
    "simplified": dict(BASE, model="simplified", s0_n=1.0489949145095886e-03, s0_t=3.0478115230459664e-03,
                       k_n=482.69742679680568, k_t=198.75776397515528),
}
MUS = (0.5, 0.75, 1.0)
PRECOMPRESSIONS = np.linspace(0.0, 1.0, 11)        # MPa
SHEAR_TO, INCREMENTS = 0.1, 500                   # mm, increments


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output-dir", default=".", help="where the figure goes (default: .)")
    args = parser.parse_args()
    out = pathlib.Path(args.output_dir)
    out.mkdir(parents=True, exist_ok=True)

    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    print(f"{'model':16s} {'mu':>5s} {'p (MPa)':>8s} {'peak (MPa)':>11s} {'residual':>9s} {'mu p':>7s}")
    for row, (name, entries) in enumerate(MODELS.items()):
        curves_ax, envelope_ax = axes[row]
        for colour, mu in enumerate(MUS):
            material = interphase.Material(mu=mu, **entries)
            k_n = material.update([0.0, 0.0]).tangent[0, 0]
            peak, residual = [], []
            for p in PRECOMPRESSIONS:
                s_n = -p / k_n
                r = material.run([[s_n, 0.0], [s_n, SHEAR_TO]], increments=INCREMENTS)
                drift = np.abs(r.traction[:, 0] + p).max()
                assert drift <= 1e-12 * max(p, 1.0), f"normal traction left -p by {drift} MPa"
                peak.append(r.traction[:, 1].max())
                residual.append(r.traction[-1, 1])
                print(f"{name:16s} {mu:5.2f} {p:8.2f} {peak[-1]:11.4f} {residual[-1]:9.4f} {mu * p:7.3f}")
                if mu == 0.75 and p in (0.0, 0.5, 1.0):
                    curves_ax.plot(r.separation[:, 1], r.traction[:, 1], lw=1.8, label=f"μ = {mu}, p = {p:g} MPa")
            envelope_ax.plot(PRECOMPRESSIONS, peak, f"C{colour}o-", label=f"peak, μ = {mu}")
            envelope_ax.plot(PRECOMPRESSIONS, residual, f"C{colour}s--", label=f"residual, μ = {mu}")
        curves_ax.set(title=f"{name}: shear under precompression", xlabel="s_T (mm)", ylabel="Σ_T (MPa)")
        envelope_ax.set(title=f"{name}: shear strength envelope", xlabel="precompression p (MPa)",
                        ylabel="Σ_T (MPa)")
        for ax in (curves_ax, envelope_ax):
            ax.grid(True)
            ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "sweep_shear.png", dpi=110)
    print("figure:", out / "sweep_shear.png")


if __name__ == "__main__":
    main()
