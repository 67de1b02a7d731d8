#!/usr/bin/env python3
"""Benchmark of the Python package: a history replayed with the loop inside the library
(Material.run over interphase_run_history, the driver's algorithm) against a Python loop with one
Material.update (one ctypes call of interphase_update_dt) per increment, and against one call of
interphase_run (the plain path of separations, no sub-stepping logic) on the same separations;
the numbers must agree. Then the shear test under an imposed precompression (mixed control:
Newton on the tangent at every increment).

    PYTHONPATH=drivers/python INTERPHASE_LIBRARY=build/release/libinterphase.so \\
        /usr/bin/python3 drivers/python/bench_run.py [INCREMENTS] [REPEATS]

Prints the best and the median time per increment of each (ns) and the ratios of the medians
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


def path_call(material, result):
    """One ctypes call of interphase_run over `result`'s separations from its first row."""
    lib = interphase._library.lib
    n = result.separation.shape[1]
    m = result.separation.shape[0]
    props = np.ascontiguousarray(material.props)
    sep = np.ascontiguousarray(result.separation)
    times = np.ascontiguousarray(result.time)
    traction = np.empty((m, n))
    traction[0] = result.traction[0]
    state = np.empty((m, material.nstate))
    state[0] = result.state[0]
    psi, w = np.empty(m), np.empty(m)
    psi[0], w[0] = result.stored_energy[0], result.dissipated_energy[0]
    done = ctypes.c_size_t(0)
    detail = ctypes.create_string_buffer(257)
    if lib.interphase_run(props.ctypes.data, props.size, n, m, sep.ctypes.data, times.ctypes.data,
                          traction.ctypes.data, None, state.ctypes.data, psi.ctypes.data, w.ctypes.data,
                          ctypes.byref(done), detail, 257) != 0:
        raise RuntimeError(detail.value)
    return traction, w[-1]


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
        path_traction, path_w = path_call(m, r)
        same = same and np.array_equal(path_traction, r.traction)
        keys = ("run", "update loop", "interphase_run")
        timings = {k: [] for k in keys}
        for _ in range(repeats):
            t0 = time.perf_counter()
            m.run(s, t, increments=per_segment)
            t1 = time.perf_counter()
            python_loop(m, r)
            t2 = time.perf_counter()
            path_call(m, r)
            t3 = time.perf_counter()
            timings["run"].append(t1 - t0)
            timings["update loop"].append(t2 - t1)
            timings["interphase_run"].append(t3 - t2)
        steps = len(r) - 1
        best = {k: 1e9 * min(v) / steps for k, v in timings.items()}
        med = {k: 1e9 * float(np.median(v)) / steps for k, v in timings.items()}
        print(f"{name:16s} " + ";  ".join(f"{k}: best {best[k]:6.0f}, median {med[k]:6.0f} ns/increment" for k in keys)
              + f";  update loop / run {med['update loop'] / med['run']:5.1f}, run / interphase_run "
              f"{med['run'] / med['interphase_run']:5.2f};  same tractions: {same}, same W_dis: "
              f"{loop_w == r.dissipated_energy[-1] and path_w == r.dissipated_energy[-1]}")
        # mixed control: Sigma_N = -0.5 MPa imposed, s_T driven to 0.1 mm, the same number of increments
        shear = ([[0.0, 0.0], [-0.5, 0.0], [-0.5, 0.1]], [0.0, 1.0, 2.0])
        k = max(1, n // 2)
        mixed = []
        for _ in range(repeats):
            t0 = time.perf_counter()
            rm = m.run(shear[0], shear[1], increments=k, control=[True, False], traction_tolerance=1e-15)
            mixed.append(time.perf_counter() - t0)
        print(f"{name:16s} mixed control (shear under Sigma_N = -0.5 MPa, {len(rm) - 1} increments): best "
              f"{1e9 * min(mixed) / (len(rm) - 1):6.0f}, median {1e9 * float(np.median(mixed)) / (len(rm) - 1):6.0f} "
              "ns/increment")

if __name__ == "__main__":
    main()
