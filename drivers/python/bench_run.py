#!/usr/bin/env python3
"""Benchmark of the Python package: a history replayed with the loop inside the library
(Material.run over interphase_run) against a Python loop with one Material.update (one ctypes
call of interphase_update_dt) per increment, on the same separations; the numbers must agree.

    PYTHONPATH=drivers/python INTERPHASE_LIBRARY=build/release/libinterphase.so \\
        /usr/bin/python3 drivers/python/bench_run.py [INCREMENTS] [REPEATS]

Prints the best and the median time per increment of each (ns) and the ratio of the medians
(docs/performance.md).
"""

import ctypes
import pathlib
import sys
import time

import numpy as np

import interphase

MATERIALS = {
    "simplified": dict(model="simplified", damage_law="displacement", mu=0.75, s0_n=0.00044, sf_n=0.04,
                       s0_t=0.00072, sf_t=0.06, k_n=482.69742679680568, k_t=198.75776397515528),
    "micromechanical": dict(model="micromechanical", damage_law="displacement", mu=0.75, s0_n=0.00044,
                            sf_n=0.04, s0_t=0.00072, sf_t=0.06),
}


def python_loop(material, result):
    """One ctypes call of interphase_update_dt per increment from `result`'s first row over its
    separations, with buffers allocated once (the leanest Python loop; Material.update, which
    checks its arguments and allocates its results, costs more); the dissipated energy
    accumulated as the UMAT's SPD."""
    lib = interphase._library.lib
    separation = result.separation
    n = separation.shape[1]
    props = np.ascontiguousarray(material.props)
    old, new = result.state[0].copy(), np.empty(material.nstate)
    traction, tangent = np.empty(n), np.empty((n, n))
    s = np.empty(n)
    psi = ctypes.c_double()
    detail = ctypes.create_string_buffer(257)
    t_old = result.traction[0].copy()
    psi_old, w = result.stored_energy[0], result.dissipated_energy[0]
    out = np.empty((separation.shape[0] - 1, n))
    args = (props.ctypes.data, props.size, n, old.ctypes.data, s.ctypes.data)
    outs = (traction.ctypes.data, tangent.ctypes.data, new.ctypes.data, ctypes.byref(psi), detail, 257)
    for i in range(1, separation.shape[0]):
        ds = separation[i] - separation[i - 1]
        s[:] = separation[i - 1] + ds
        dt = result.time[i] - result.time[i - 1]
        if lib.interphase_update_dt(*args, dt, *outs) != 0:
            raise RuntimeError(detail.value)
        w = w + 0.5 * float(np.sum((t_old + traction) * ds)) - (psi.value - psi_old)
        t_old[:] = traction
        old[:] = new
        psi_old = psi.value
        out[i - 1] = traction
    return out, w


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 20000
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    # the paper's mixed history (cyclic shear under compression), n increments in all
    t, s = interphase.read_history(pathlib.Path(__file__).resolve().parents[1] / "cases" / "mixed.txt")
    per_segment = max(1, n // (len(t) - 1))
    print(f"{per_segment * (len(t) - 1)} increments, median of {repeats} runs; library {interphase.library_path}")
    for name, entries in MATERIALS.items():
        m = interphase.Material(**entries)
        r = m.run(s, t, increments=per_segment)
        loop_traction, loop_w = python_loop(m, r)
        same = np.array_equal(loop_traction, r.traction[1:])
        timings = {"library loop (run)": [], "Python loop (update)": []}
        for _ in range(repeats):
            t0 = time.perf_counter()
            m.run(s, t, increments=per_segment)
            t1 = time.perf_counter()
            python_loop(m, r)
            t2 = time.perf_counter()
            timings["library loop (run)"].append(t1 - t0)
            timings["Python loop (update)"].append(t2 - t1)
        steps = len(r) - 1
        best = {k: 1e9 * min(v) / steps for k, v in timings.items()}
        med = {k: 1e9 * float(np.median(v)) / steps for k, v in timings.items()}
        lib_key, py_key = "library loop (run)", "Python loop (update)"
        print(f"{name:16s} run: best {best[lib_key]:6.0f}, median {med[lib_key]:6.0f} ns/increment;  "
              f"update loop: best {best[py_key]:6.0f}, median {med[py_key]:6.0f} ns/increment;  "
              f"ratio of the medians {med[py_key] / med[lib_key]:5.1f};  same tractions: {same}, "
              f"same W_dis: {loop_w == r.dissipated_energy[-1]}")


if __name__ == "__main__":
    main()
