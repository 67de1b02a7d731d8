"""interphase from Python: the brick-mortar interface law at one point, over its C interface.

    import numpy as np
    import interphase
    m = interphase.Material(model='simplified', damage_law='displacement', mu=0.75,
                            s0_n=0.00044, sf_n=0.04, s0_t=0.00072, sf_t=0.06,
                            k_n=482.69742679680568, k_t=198.75776397515528)
    u = m.update([0.001, 0.0])                # (s_N, s_T) in mm, from a virgin point
    r = m.run(np.array([[0.0, 0.0], [0.05, 0.0]]), increments=200)
    r.traction[:, 0], r.damage, r.dissipated_energy

The numbers are those of the Abaqus UMAT and of interphase-point, bit for bit (docs/python.md).
The package loads the shared library libinterphase (see interphase._library for where it looks).
"""

from ._library import InterphaseError, status_message, load_table, load_rcurve, path as library_path
from ._material import (Material, Update, Result, TangentCheck, format_csv, REGIME_NAMES, NSTATE, NSTATE_VISCOUS,
                        MAX_HALVINGS, MAX_NEWTON, DEFAULT_TRACTION_TOLERANCE, TRACTION_TOLERANCE_MAX,
                        DEFAULT_TANGENT_STEP)
from ._files import read_history, read_case, read_namelist, Case
from ._status import *  # noqa: F401,F403  (the STATUS_* codes)
from ._status import STATUS_CODES

__version__ = "0.1.0"

__all__ = ["Material", "Update", "Result", "TangentCheck", "InterphaseError", "status_message", "load_table",
           "load_rcurve", "read_history", "read_case", "read_namelist", "Case", "format_csv", "REGIME_NAMES",
           "NSTATE", "NSTATE_VISCOUS", "MAX_HALVINGS", "MAX_NEWTON", "DEFAULT_TRACTION_TOLERANCE",
           "STATUS_CODES", "library_path", "DEFAULT_TANGENT_STEP", "TRACTION_TOLERANCE_MAX"]
