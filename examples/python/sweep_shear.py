#!/usr/bin/env python3
"""The shear test under precompression, swept over the friction coefficient mu and the
precompression p: monotonic shear s_T from 0 to 0.1 mm at a constant normal compression, for
both models, and the envelope of the shear strength (peak shear traction) and of the residual
(frictional) shear traction against p, one curve per mu.

The precompression is imposed as the laboratory test imposes it, and as drivers/cases/shear/
does: the normal traction Sigma_N = -p is the controlled quantity (mixed control, `control=` of
Material.run: the library finds s_N by Newton's method at every increment), applied first, then
held while s_T is driven. The script checks that Sigma_N stays at -p to the tolerance and that the
residual shear traction after full damage is the Coulomb value mu p.

    PYTHONPATH=drivers/python INTERPHASE_LIBRARY=build/release/libinterphase.so \\
        /usr/bin/python3 examples/python/sweep_shear.py [--output-dir DIR]
"""

import argparse

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

from example_output import output_dir
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
SHEAR_TO, INCREMENTS = 0.1, 500                   # mm, increments per segment
TOLERANCE = 1e-15                                 # MPa: Sigma_N met to round-off (drivers/cases/shear)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output-dir", default=".", help="where the figure goes (default: .)")
    args = parser.parse_args()
    out = output_dir(parser, args.output_dir)

    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    print(f"{'model':16s} {'mu':>5s} {'p (MPa)':>8s} {'peak (MPa)':>11s} {'residual':>9s} {'mu p':>7s}")
    for row, (name, entries) in enumerate(MODELS.items()):
        curves_ax, envelope_ax = axes[row]
        for colour, mu in enumerate(MUS):
            material = interphase.Material(mu=mu, **entries)
            peak, residual = [], []
            for p in PRECOMPRESSIONS:
                # rows (Sigma_N, s_T): the precompression applied at t = 0 -> 1, the shear at 1 -> 2
                r = material.run([[0.0, 0.0], [-p, 0.0], [-p, SHEAR_TO]], increments=INCREMENTS,
                                 control=[True, False], traction_tolerance=TOLERANCE)
                shear = r.time >= 1.0
                drift = np.abs(r.traction[shear, 0] + p).max()
                assert drift <= TOLERANCE, f"normal traction left -p by {drift} MPa"
                assert abs(r.traction[-1, 1] - mu * p) <= 1e-12, "the residual is not mu p"
                peak.append(r.traction[shear, 1].max())
                residual.append(r.traction[-1, 1])
                print(f"{name:16s} {mu:5.2f} {p:8.2f} {peak[-1]:11.4f} {residual[-1]:9.4f} {mu * p:7.3f}")
                if mu == 0.75 and p in (0.0, 0.5, 1.0):
                    curves_ax.plot(r.separation[shear, 1], r.traction[shear, 1], lw=1.8,
                                   label=f"μ = {mu}, p = {p:g} MPa")
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
