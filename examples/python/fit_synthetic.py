#!/usr/bin/env python3
"""Fitting the simplified model to test curves, on synthetic data whose true parameters are
known: how well a least-squares fit recovers them and how well the data determine them (the
condition number of the Jacobian), for the sampling stated below. The figures quoted in
docs/python.md, 'Fitting your own test data', are this script's output.

The data are the simplified model's own curves with Gaussian noise (numpy's default_rng, seeds
0 ... SEEDS - 1):
  - a tension test: Sigma_N against s_N, s_N every TENSION_STEP mm from TENSION_STEP to
    TENSION_TO, noise TENSION_NOISE MPa (standard deviation);
  - shear tests of a couplet under the precompressions p of PRECOMPRESSIONS: Sigma_N = -p held by
    mixed control, Sigma_T against s_T every SHEAR_STEP mm from SHEAR_STEP to SHEAR_TO, noise
    SHEAR_NOISE MPa.
The model's curve is run to the test's largest separation (INCREMENTS per segment) and
interpolated at the measured separations (docs/python.md). The tension fit finds K_N, s0_N and
sf_N; the shear fit finds K_T, s0_T, sf_T and mu from the three shear tests at once, with the
normal entries of the tension fit. The parameters are fitted as logarithms of positive numbers
(sf - s0 for sf), and the condition number is that of fit.jac in them. Then the same tension test
sampled every COARSE_STEP mm from the first points COARSE_FIRST (one point at or below the
peak), and the simplified model
fitted to the micromechanical model's tension curve (built-in table, the paper's Table 1 data, to
MICRO_TO mm): a fitted sf beyond the test's end.

    PYTHONPATH=drivers/python INTERPHASE_LIBRARY=build/release/libinterphase.so \\
        /usr/bin/python3 examples/python/fit_synthetic.py [--seeds N]
"""

import argparse

import numpy as np
from scipy.optimize import least_squares

import interphase

TRUE = dict(k_n=400.0, s0_n=0.0005, sf_n=0.03, k_t=180.0, s0_t=0.0008, sf_t=0.05, mu=0.7)
TENSION_STEP, TENSION_TO, TENSION_NOISE = 0.0001, 0.03, 0.003           # mm, mm, MPa
SHEAR_STEP, SHEAR_TO, SHEAR_NOISE = 0.0002, 0.06, 0.005                 # mm, mm, MPa
PRECOMPRESSIONS = (0.2, 0.5, 1.0)                                       # MPa
COARSE_STEP = 0.0005                                                    # mm
COARSE_FIRST = (0.0001, 0.0002, 0.0003, 0.0004, 0.0005)                  # mm
MICRO_TO = 0.045                                                        # mm
INCREMENTS = 400
SEEDS = 5
TENSION_START = np.log([300.0, 0.0007, 0.04])          # K_N, s0_N, sf_N - s0_N
SHEAR_START = np.log([200.0, 0.0007, 0.06, 0.75])      # K_T, s0_T, sf_T - s0_T, mu


def material(p):
    return interphase.Material(model="simplified", damage_law="displacement", mu=p["mu"],
                               k_n=p["k_n"], s0_n=p["s0_n"], sf_n=p["sf_n"],
                               k_t=p["k_t"], s0_t=p["s0_t"], sf_t=p["sf_t"])


def tension_curve(m, s):
    """Sigma_N of material m at the separations s (increasing), s_T = 0."""
    r = m.run([[0.0, 0.0], [s.max(), 0.0]], increments=INCREMENTS)
    return np.interp(s, r.separation[:, 0], r.traction[:, 0])


def shear_curve(m, p, s):
    """Sigma_T of material m at the shear separations s under Sigma_N = -p (mixed control)."""
    r = m.run([[0.0, 0.0], [-p, 0.0], [-p, s.max()]], increments=INCREMENTS, control=[True, False])
    shear = r.time >= 1
    return np.interp(s, r.separation[shear, 1], r.traction[shear, 1])


def fit_tension(s, sigma, fixed):
    def residual(x):
        k_n, s0_n, d = np.exp(x)
        return tension_curve(material(dict(fixed, k_n=k_n, s0_n=s0_n, sf_n=s0_n + d)), s) - sigma
    fit = least_squares(residual, TENSION_START)
    k_n, s0_n, d = np.exp(fit.x)
    return dict(k_n=k_n, s0_n=s0_n, sf_n=s0_n + d), fit


def fit_shear(s, sigmas, normal):
    def residual(x):
        k_t, s0_t, d, mu = np.exp(x)
        m = material(dict(normal, k_t=k_t, s0_t=s0_t, sf_t=s0_t + d, mu=mu))
        return np.concatenate([shear_curve(m, p, s) - sigma for p, sigma in zip(PRECOMPRESSIONS, sigmas)])
    fit = least_squares(residual, SHEAR_START)
    k_t, s0_t, d, mu = np.exp(fit.x)
    return dict(k_t=k_t, s0_t=s0_t, sf_t=s0_t + d, mu=mu), fit


def rms(fit):
    return float(np.sqrt(np.mean(fit.fun**2)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=SEEDS, help=f"noise realisations (default {SEEDS})")
    parser.add_argument("--output-dir", default=".", help="(unused: the script writes no file)")
    args = parser.parse_args()

    truth = material(TRUE)
    s_n = np.arange(1, round(TENSION_TO / TENSION_STEP) + 1) * TENSION_STEP
    s_t = np.arange(1, round(SHEAR_TO / SHEAR_STEP) + 1) * SHEAR_STEP
    clean_n = tension_curve(truth, s_n)
    clean_t = [shear_curve(truth, p, s_t) for p in PRECOMPRESSIONS]
    print(f"true: {TRUE}")
    print(f"tension: {s_n.size} points, every {TENSION_STEP} mm to {TENSION_TO} mm "
          f"({np.count_nonzero(s_n < TRUE['s0_n'])} below the peak at s0_N), noise {TENSION_NOISE} MPa; "
          f"shear: {s_t.size} points each, every {SHEAR_STEP} mm to {SHEAR_TO} mm, p = {PRECOMPRESSIONS} MPa, "
          f"noise {SHEAR_NOISE} MPa; {INCREMENTS} increments per segment")
    names = ("k_n", "s0_n", "sf_n", "k_t", "s0_t", "sf_t", "mu")
    print(f"{'seed':>4s} " + " ".join(f"{n:>7s}" for n in names)
          + "   (relative error, %)  cond tension  cond shear  rms tension  rms shear (MPa)")
    worst = dict.fromkeys(names, 0.0)
    conds_n, conds_t = [], []
    for seed in range(args.seeds):
        rng = np.random.default_rng(seed)
        sigma_n = clean_n + rng.normal(0.0, TENSION_NOISE, s_n.size)
        sigma_t = [c + rng.normal(0.0, SHEAR_NOISE, s_t.size) for c in clean_t]
        normal, fit_n = fit_tension(s_n, sigma_n, TRUE)
        shear, fit_t = fit_shear(s_t, sigma_t, dict(TRUE, **normal))
        found = dict(normal, **shear)
        errors = {n: 100.0 * (found[n] - TRUE[n]) / TRUE[n] for n in names}
        for n in names:
            worst[n] = max(worst[n], abs(errors[n]))
        conds_n.append(np.linalg.cond(fit_n.jac))
        conds_t.append(np.linalg.cond(fit_t.jac))
        print(f"{seed:4d} " + " ".join(f"{errors[n]:+7.2f}" for n in names)
              + f"   {'':20s}  {conds_n[-1]:12.3g}  {conds_t[-1]:10.3g}  {rms(fit_n):11.4f}  {rms(fit_t):9.4f}")
    print(f"largest |relative error| over {args.seeds} seeds (%): "
          + ", ".join(f"{n} {worst[n]:.2f}" for n in names))
    print(f"condition number of fit.jac: tension {min(conds_n):.3g} ... {max(conds_n):.3g}, "
          f"shear {min(conds_t):.3g} ... {max(conds_t):.3g}")

    # the same tension test sampled coarsely, every COARSE_STEP mm from an offset: one point at or
    # below the peak, the rest on the softening branch
    print(f"tension every {COARSE_STEP} mm from the first point s_1 to {TENSION_TO} mm, seeds 0 ... "
          f"{args.seeds - 1}:")
    for first in COARSE_FIRST:
        s = np.arange(first, TENSION_TO + 1e-12, COARSE_STEP)
        clean = tension_curve(truth, s)
        k_n, conds = [], []
        for seed in range(args.seeds):
            rng = np.random.default_rng(seed)
            normal, fit = fit_tension(s, clean + rng.normal(0.0, TENSION_NOISE, s.size), TRUE)
            k_n.append(normal["k_n"])
            conds.append(np.linalg.cond(fit.jac))
        print(f"  s_1 = {first} mm ({s.size} points, {np.count_nonzero(s < TRUE['s0_n'])} below s0_N): "
              f"K_N {min(k_n):.4g} ... {max(k_n):.4g} MPa/mm, condition number {min(conds):.3g} ... {max(conds):.3g}")

    # the simplified model fitted to the micromechanical tension curve (no noise)
    micro = interphase.Material(model="micromechanical", damage_law="displacement", mu=0.75,
                                s0_n=0.00044, sf_n=0.04, s0_t=0.00072, sf_t=0.06)
    s = np.arange(1, round(MICRO_TO / TENSION_STEP) + 1) * TENSION_STEP
    normal, fit = fit_tension(s, tension_curve(micro, s), TRUE)
    print(f"simplified fitted to the micromechanical tension curve to {MICRO_TO} mm (every {TENSION_STEP} mm): "
          f"K_N = {normal['k_n']:.4g} MPa/mm, s0_N = {normal['s0_n']:.4g} mm, sf_N = {normal['sf_n']:.4g} mm, "
          f"rms misfit {rms(fit):.4f} MPa")


if __name__ == "__main__":
    main()
