"""Status codes of the C interface: every INTERPHASE_STATUS_* of include/interphase.h, same
names and values (tests/python/test_status_codes.py checks that they never differ). The library
gives each its message (interphase.status_message)."""

STATUS_OK = 0  # success
STATUS_BAD_NPROPS = 1  # wrong number of PROPS
STATUS_BAD_MODEL = 2  # PROPS[0]: unknown model
STATUS_BAD_DAMAGE_LAW = 3  # PROPS[1]: unknown damage law
STATUS_BAD_MU = 4  # PROPS[2]: mu out of range
STATUS_BAD_S0_N = 5  # PROPS[3]: s0_N out of range
STATUS_BAD_SF_N = 6  # PROPS[4]: sf_N out of range
STATUS_BAD_S0_T = 7  # PROPS[5]: s0_T out of range
STATUS_BAD_SF_T = 8  # PROPS[6]: sf_T out of range
STATUS_BAD_K_N = 9  # PROPS[7]: K_N out of range
STATUS_BAD_K_T = 10  # PROPS[8]: K_T out of range
STATUS_BAD_NTENS = 11  # ntens is not 2 or 3
STATUS_BAD_NSTATV = 12  # too few state variables (NSTATV, adapters)
STATUS_MODEL_UNAVAILABLE = 13  # model not available in this build
STATUS_BAD_TABLE_SELECTOR = 14  # micromechanical PROPS[7]: table not 0 or 1
STATUS_BAD_D0 = 15  # fracture law: initial crack D0 out of [1e-30, 1)
STATUS_BAD_RCURVE = 16  # fracture law: R-curve selector not 1, 2 or 3
STATUS_BAD_GC_I = 17  # fracture law: G_cI out of range
STATUS_BAD_GC_II = 18  # fracture law: G_cII out of range
STATUS_BAD_OPTION = 19  # option constant out of range, missing, or not allowed with this element or host
STATUS_NONFINITE_SEPARATION = 20  # separation NaN or Inf
STATUS_BAD_STATE = 21  # state_old out of range or not finite
STATUS_BAD_COEFFICIENTS = 22  # coefficient set not admissible
STATUS_STAGGER_NOT_CONVERGED = 23  # damage-friction iteration did not converge
STATUS_RCURVE_NOT_LOADED = 24  # tabulated R-curve selected, none loaded
STATUS_SEPARATION_OUT_OF_RANGE = 25  # a separation component |s_i| > 1e20 mm
STATUS_BAD_HOST_INPUT = 26  # a host value (stress, energy, increment, time) not finite or out of range
STATUS_BAD_TIME_INCREMENT = 27  # time increment missing, negative or not finite (viscosity)
STATUS_BEYOND_PEAK = 28  # an imposed traction beyond the peak the material can carry
STATUS_MIXED_NOT_CONVERGED = 29  # imposed traction not met (Newton), even in halved steps
STATUS_BAD_HISTORY = 30  # history (times, controls) or replay setting not admissible
STATUS_OUTPUT_FULL = 31  # output arrays too short: call again with more rows
STATUS_NULL_ARGUMENT = 32  # a required pointer argument is NULL (detail names it)
STATUS_SPLINE_TOO_FEW_POINTS = 40  # too few table points
STATUS_SPLINE_BAD_SHAPE = 41  # table values do not match the knots
STATUS_SPLINE_BAD_METHOD = 42  # unknown interpolation method
STATUS_SPLINE_NONFINITE_DATA = 43  # table knots or values NaN or Inf
STATUS_SPLINE_BAD_KNOTS = 44  # table knots not strictly increasing
STATUS_SPLINE_SOLVER_FAILED = 45  # spline system not solved (LAPACK)
STATUS_SPLINE_NOT_BUILT = 46  # interpolation table not built
STATUS_SPLINE_OUT_OF_RANGE = 47  # argument outside the table
STATUS_SPLINE_NONFINITE_ARGUMENT = 48  # interpolation argument NaN or Inf
STATUS_TABLE_UNREADABLE = 50  # table file cannot be opened or read
STATUS_TABLE_BAD_HEADER = 51  # header not valid (a line not "# key = value", a key given twice, an unknown format or column)
STATUS_TABLE_MISSING_COLUMN = 52  # table lacks a required column
STATUS_TABLE_MISSING_KEY = 53  # header lacks a required key (b, h)
STATUS_TABLE_BAD_ROW = 54  # row does not hold one number per column
STATUS_TABLE_NONFINITE = 55  # table value NaN or Inf
STATUS_TABLE_NOT_INCREASING = 56  # crack half-lengths a not increasing
STATUS_TABLE_BAD_RANGE = 57  # table does not run from a = 0 to a = b
STATUS_TABLE_IDENTITY = 58  # table violates an exact RVE identity
STATUS_TABLE_NOT_LOADED = 59  # custom RVE table selected, none loaded
STATUS_TABLE_INTERPOLANT = 49  # RVE table's interpolant inadmissible between two rows
STATUS_RCURVE_UNREADABLE = 60  # R-curve file cannot be opened or read
STATUS_RCURVE_MALFORMED = 61  # a line is not "D G_cI G_cII", or a comment gives a column another unit
STATUS_RCURVE_NEGATIVE = 62  # toughness not positive (see also 65)
STATUS_RCURVE_BAD_RANGE = 63  # D not increasing in [0, 1], or too few rows
STATUS_RCURVE_OUT_OF_RANGE = 64  # tabulated R-curve does not cover D0 or the D reached
STATUS_RCURVE_BAD_TOUGHNESS = 65  # toughness > 0 but outside [1e-20, 1e20] N/mm

#: every status code by name
STATUS_CODES = {name: value for name, value in globals().items() if name.startswith("STATUS_")}
