/**
 * @file interphase.h
 * @brief C interface of interphase: the brick-mortar interface law (damage, unilateral contact,
 *        Coulomb friction) at one integration point, for C and C++ finite-element codes.
 *
 * Link with the core library `libinterphase` (CMake: `find_package(interphase)` and
 * `target_link_libraries(app PRIVATE interphase::interphase)`, or the shared
 * `libinterphase.so`, `interphase::shared`), plus the Fortran runtime (`-lgfortran`) and LAPACK
 * when linking the static library by hand. interphase_update, interphase_update_dt,
 * interphase_update_increment, interphase_run, interphase_run_history and interphase_status_message are re-entrant and
 * thread-safe: they keep no state; the caller owns every array. The loaders
 * interphase_load_table and interphase_load_rcurve are not: they write library-wide data (the
 * custom RVE table, the tabulated R-curve) that every later update reads. Call them once, from
 * one thread, before any thread calls interphase_update (and never while an update runs).
 *
 * Units: separations mm, tractions MPa, stiffness MPa/mm, energy per unit area N/mm.
 * Component order: normal first, then the shear(s): (s_N, s_T) in 2-D, (s_N, s_T1, s_T2) in
 * 3-D (the law is isotropic in the interface plane). Shear separations are plain relative
 * displacements (no factor 2).
 *
 * Matrices are **row-major** (C order): tangent[i * ntens + j] = d traction[i] / d separation[j].
 * The tangent is not symmetric while damage grows or the crack slips.
 *
 * PROPS and the state are the arrays of the Abaqus UMAT (docs/abaqus.md): 9 PROPS for the
 * simplified model; INTERPHASE_NSTATE doubles of state (damage D, slip lambda_1, slip lambda_2,
 * regime code), all zero for a virgin point. Messages number PROPS and STATEV from 1, as the
 * tables of docs/abaqus.md do: "PROPS(5)" is props[4], "STATEV(4)" is state_old[3].
 *
 * The state, slot by slot (docs/abaqus.md, 'STATEV'): [0] D in [0, 1]; [1], [2] the slips
 * lambda_1, lambda_2 (mm, |lambda_i| <= 1e30; in 2-D [2] is not read and is written 0); [3] the
 * regime of the last update, 0 intact, 1 open, 2 stick, 3 slip: an output, but checked on
 * input (exactly 0, 1, 2 or 3, and not -0.0); with viscous regularisation [4] the damage law's
 * own D, in [state[0], 1]. An incoming state outside these ranges, or with a slip at D = 0 (an
 * intact point has no crack, so no slip), is INTERPHASE_STATUS_BAD_STATE, naming the slot.
 *
 * Restart: an update depends on props, state_old, the separation and (interphase_update_dt) dt
 * only, and on the custom RVE table or tabulated R-curve the material selects; the library keeps
 * nothing else. To restart a point, store its state doubles exactly (printf "%.17g" and strtod
 * give them back bit for bit), load the same table or R-curve files again, and go on; the
 * separation, the traction and the energies are the host's to keep.
 *
 * Energies: stored_energy is the recoverable energy psi at the end of the update. The dissipated
 * energy (damage and friction) is not an output of interphase_update: accumulate it over the
 * converged increments as the UMAT accumulates SPD,
 *   W = W_old + 1/2 sum_i (traction_old[i] + traction[i]) (separation[i] - separation_old[i])
 *       - (psi - psi_old),
 * which interphase_run and interphase_run_history return as dissipated_energy. A host that sums
 * in that order, forms the separation as separation_old + (separation - separation_old) (the
 * UMAT's STRAN + DSTRAN) and does not contract multiply-adds (gcc -ffp-contract=off, as the
 * library is built) gets interphase_run's numbers bit for bit (and, from the same build,
 * interphase-point's W_dis); otherwise equal to rounding.
 */
#ifndef INTERPHASE_H
#define INTERPHASE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Number of doubles in a state array (STATEV slots 1..4 of the UMAT). */
#define INTERPHASE_NSTATE 4
/** State doubles of a material with viscous regularisation (its viscosity option > 0): the
 *  four above and the damage law's own (inviscid) D; use interphase_update_dt for it. */
#define INTERPHASE_NSTATE_VISCOUS 5
/** Number of PROPS of the simplified (spring) model. */
#define INTERPHASE_NPROPS_SIMPLIFIED 9
/** Number of PROPS of the micromechanical model (the RVE table's selector last). */
#define INTERPHASE_NPROPS_MICROMECHANICAL 8
/** PROPS the fracture-mechanics damage law appends to either model's (D0, R-curve, G_cI, G_cII). */
#define INTERPHASE_NPROPS_FRACTURE_EXTRA 4
/** Option constants that may follow a material's PROPS: at most this many (docs/abaqus.md). */
#define INTERPHASE_NPROPS_OPTIONS 7
/** Largest admissible separation component (mm): SEPARATION_MAX of src/interphase_params.f90. */
#define INTERPHASE_SEPARATION_MAX 1.0e20

/* Status codes: every STATUS_* of src/interphase_status.f90, same names and values (the ctest
 * capi_status_codes_match fails if they ever differ). interphase_status_message gives the text. */
#define INTERPHASE_STATUS_OK 0                           /**< success */
/* PROPS and size validation (setup errors) */
#define INTERPHASE_STATUS_BAD_NPROPS 1                   /**< wrong number of PROPS */
#define INTERPHASE_STATUS_BAD_MODEL 2                    /**< PROPS[0]: unknown model */
#define INTERPHASE_STATUS_BAD_DAMAGE_LAW 3               /**< PROPS[1]: unknown damage law */
#define INTERPHASE_STATUS_BAD_MU 4                       /**< PROPS[2]: mu out of range */
#define INTERPHASE_STATUS_BAD_S0_N 5                     /**< PROPS[3]: s0_N out of range */
#define INTERPHASE_STATUS_BAD_SF_N 6                     /**< PROPS[4]: sf_N out of range */
#define INTERPHASE_STATUS_BAD_S0_T 7                     /**< PROPS[5]: s0_T out of range */
#define INTERPHASE_STATUS_BAD_SF_T 8                     /**< PROPS[6]: sf_T out of range */
#define INTERPHASE_STATUS_BAD_K_N 9                      /**< PROPS[7]: K_N out of range */
#define INTERPHASE_STATUS_BAD_K_T 10                     /**< PROPS[8]: K_T out of range */
#define INTERPHASE_STATUS_BAD_NTENS 11                   /**< ntens is not 2 or 3 */
#define INTERPHASE_STATUS_BAD_NSTATV 12                  /**< too few state variables (NSTATV, adapters) */
#define INTERPHASE_STATUS_MODEL_UNAVAILABLE 13           /**< model not available in this build */
#define INTERPHASE_STATUS_BAD_TABLE_SELECTOR 14          /**< micromechanical PROPS[7]: table not 0 or 1 */
#define INTERPHASE_STATUS_BAD_D0 15                      /**< fracture law: initial crack D0 not in 1e-30 <= D0 < 1 */
#define INTERPHASE_STATUS_BAD_RCURVE 16                  /**< fracture law: R-curve selector not 1, 2 or 3 */
#define INTERPHASE_STATUS_BAD_GC_I 17                    /**< fracture law: G_cI out of range */
#define INTERPHASE_STATUS_BAD_GC_II 18                   /**< fracture law: G_cII out of range */
#define INTERPHASE_STATUS_BAD_OPTION 19                  /**< option constant out of range, missing, or not allowed with this element or host */
/* update failures (the increment may be retried smaller) */
#define INTERPHASE_STATUS_NONFINITE_SEPARATION 20        /**< separation NaN or Inf */
#define INTERPHASE_STATUS_BAD_STATE 21                   /**< state_old out of range or not finite */
#define INTERPHASE_STATUS_BAD_COEFFICIENTS 22            /**< coefficient set not admissible */
#define INTERPHASE_STATUS_STAGGER_NOT_CONVERGED 23       /**< damage-friction iteration did not converge */
#define INTERPHASE_STATUS_RCURVE_NOT_LOADED 24           /**< tabulated R-curve selected, none loaded */
#define INTERPHASE_STATUS_SEPARATION_OUT_OF_RANGE 25     /**< a separation component |s_i| > 1e20 mm */
#define INTERPHASE_STATUS_BAD_HOST_INPUT 26              /**< a host value (stress, energy, increment, time) not finite or out of range */
#define INTERPHASE_STATUS_BAD_TIME_INCREMENT 27          /**< time increment negative or not finite, or missing (viscosity) */
/* history replays (interphase_run_history) */
#define INTERPHASE_STATUS_BEYOND_PEAK 28                 /**< an imposed traction beyond the peak the material can carry */
#define INTERPHASE_STATUS_MIXED_NOT_CONVERGED 29         /**< imposed traction not met (Newton), even in halved steps */
#define INTERPHASE_STATUS_BAD_HISTORY 30                 /**< history (times, controls) or replay setting not admissible */
#define INTERPHASE_STATUS_OUTPUT_FULL 31                 /**< output arrays too short: call again with more rows */
/* arguments of the C entry points */
#define INTERPHASE_STATUS_NULL_ARGUMENT 32               /**< a required pointer argument is NULL (detail names it) */
/* interpolation tables: construction, then evaluation */
#define INTERPHASE_STATUS_SPLINE_TOO_FEW_POINTS 40       /**< too few table points */
#define INTERPHASE_STATUS_SPLINE_BAD_SHAPE 41            /**< table values do not match the knots */
#define INTERPHASE_STATUS_SPLINE_BAD_METHOD 42           /**< unknown interpolation method */
#define INTERPHASE_STATUS_SPLINE_NONFINITE_DATA 43       /**< table knots or values NaN or Inf */
#define INTERPHASE_STATUS_SPLINE_BAD_KNOTS 44            /**< table knots not strictly increasing */
#define INTERPHASE_STATUS_SPLINE_SOLVER_FAILED 45        /**< spline system not solved (LAPACK) */
#define INTERPHASE_STATUS_SPLINE_NOT_BUILT 46            /**< interpolation table not built */
#define INTERPHASE_STATUS_SPLINE_OUT_OF_RANGE 47         /**< argument outside the table */
#define INTERPHASE_STATUS_SPLINE_NONFINITE_ARGUMENT 48   /**< interpolation argument NaN or Inf */
/* RVE coefficient tables (interphase_load_table): reading and checking */
#define INTERPHASE_STATUS_TABLE_UNREADABLE 50            /**< table file cannot be opened or read */
#define INTERPHASE_STATUS_TABLE_BAD_HEADER 51            /**< header not valid (a line not "# key = value", a key given twice, an unknown format or column) */
#define INTERPHASE_STATUS_TABLE_MISSING_COLUMN 52        /**< table lacks a required column */
#define INTERPHASE_STATUS_TABLE_MISSING_KEY 53           /**< header lacks a required key (b, h) */
#define INTERPHASE_STATUS_TABLE_BAD_ROW 54               /**< row does not hold one number per column */
#define INTERPHASE_STATUS_TABLE_NONFINITE 55             /**< table value NaN or Inf */
#define INTERPHASE_STATUS_TABLE_NOT_INCREASING 56        /**< crack half-lengths a not increasing */
#define INTERPHASE_STATUS_TABLE_BAD_RANGE 57             /**< table does not run from a = 0 to a = b */
#define INTERPHASE_STATUS_TABLE_IDENTITY 58              /**< table violates an exact RVE identity */
#define INTERPHASE_STATUS_TABLE_NOT_LOADED 59            /**< custom RVE table selected, none loaded */
#define INTERPHASE_STATUS_TABLE_INTERPOLANT 49           /**< RVE table's interpolant inadmissible between two rows */
/* R-curve files (interphase_load_rcurve) */
#define INTERPHASE_STATUS_RCURVE_UNREADABLE 60           /**< R-curve file cannot be opened or read */
#define INTERPHASE_STATUS_RCURVE_MALFORMED 61            /**< a line is not "D G_cI G_cII", or a comment gives a column another unit */
#define INTERPHASE_STATUS_RCURVE_NEGATIVE 62             /**< toughness not positive (see also 65) */
#define INTERPHASE_STATUS_RCURVE_BAD_RANGE 63            /**< D not increasing in [0, 1], or too few rows */
#define INTERPHASE_STATUS_RCURVE_OUT_OF_RANGE 64         /**< tabulated R-curve does not cover D0 or the D reached */
#define INTERPHASE_STATUS_RCURVE_BAD_TOUGHNESS 65        /**< toughness > 0 but outside [1e-20, 1e20] N/mm */

/**
 * Update one interface point: traction, consistent tangent, new state and stored energy at
 * the separation @p separation, starting from the state @p state_old.
 *
 * @param props          material constants, @p nprops doubles (docs/abaqus.md, PROPS table)
 * @param nprops         number of PROPS (9 simplified, 8 micromechanical; 4 more with the
 *                       fracture-mechanics damage law; then up to 7 option constants:
 *                       docs/abaqus.md)
 * @param ntens          2 (2-D: s_N, s_T) or 3 (3-D: s_N, s_T1, s_T2)
 * @param state_old      INTERPHASE_NSTATE doubles: the state at the start of the increment
 * @param separation     @p ntens doubles: total separation at the end of the increment (mm);
 *                       admissible |separation[i]| <= 1e20 mm (INTERPHASE_SEPARATION_MAX), larger
 *                       is INTERPHASE_STATUS_SEPARATION_OUT_OF_RANGE, NaN/Inf
 *                       INTERPHASE_STATUS_NONFINITE_SEPARATION
 * @param traction       out, @p ntens doubles: traction (MPa)
 * @param tangent        out, @p ntens * @p ntens doubles, row-major: d traction / d separation (MPa/mm)
 * @param state_new      out, INTERPHASE_NSTATE doubles: state at the end; may be @p state_old
 *                       itself (an update in place, which a failure leaves as it was)
 * @param stored_energy  out: recoverable energy per unit area (N/mm)
 * @param detail         out, may be NULL: on failure, a NUL-terminated message naming the bad
 *                       value (e.g. "PROPS(5) sf_N = 0.1E-3 is out of range: ...")
 * @param detail_len     size of @p detail in bytes (257 holds any message: at most 256 characters;
 *                       every value is read as the size_t it is, SIZE_MAX too)
 * @return INTERPHASE_STATUS_OK (0), or a status code; on failure traction, tangent, state_new
 *         and stored_energy are left untouched. Every pointer but @p detail must not be NULL: a
 *         NULL one is INTERPHASE_STATUS_NULL_ARGUMENT, @p detail naming it ("state_old is NULL: ..."). Admissible ranges (docs/abaqus.md, 'Admissible
 *         ranges'): the lengths s0, sf, the stiffnesses K and the toughnesses G_c of PROPS in
 *         [1e-20, 1e20] (mm, MPa/mm, N/mm), mu in [0, 1e20], the slip in state_old within
 *         |lambda_i| <= 1e30 mm; inside them every output is finite and the same in every build.
 */
int interphase_update(const double *props, int nprops, int ntens, const double *state_old,
                      const double *separation, double *traction, double *tangent,
                      double *state_new, double *stored_energy, char *detail, size_t detail_len);

/**
 * interphase_update with the time increment @p dt (s) of the increment, which viscous
 * regularisation of the damage needs (the viscosity option constant, docs/abaqus.md); for a
 * material with it, @p state_old and @p state_new hold INTERPHASE_NSTATE_VISCOUS doubles (the
 * fifth: the damage law's own D), else INTERPHASE_NSTATE. interphase_update refuses such a
 * material with INTERPHASE_STATUS_BAD_TIME_INCREMENT; so does this function for a @p dt that is
 * negative or not finite, whatever the material. Otherwise as interphase_update.
 */
int interphase_update_dt(const double *props, int nprops, int ntens, const double *state_old,
                         const double *separation, double dt, double *traction, double *tangent,
                         double *state_new, double *stored_energy, char *detail, size_t detail_len);

/**
 * interphase_update (@p dt NULL) or interphase_update_dt (@p dt pointing at the time increment,
 * s) given also @p separation_old, the separation at the start of the increment (mm, @p ntens
 * doubles), where @p state_old was reached. A crack open in @p state_old that is closed at
 * @p separation (s_N <= 0) met its faces during the increment, on the straight path from
 * @p separation_old: its friction then starts from the slip it had there, not from the state's
 * slip (and, with the displacement-driven law, from the damage it had grown to there), so that
 * the closed state does not depend on where the increment began (docs/theory.md,
 * 'An increment across which the crack closes'). The UMAT (STRAN), the VUMAT and interphase_run
 * do the same. @p separation_old is checked as @p separation is (not NULL:
 * INTERPHASE_STATUS_NULL_ARGUMENT; finite, within INTERPHASE_SEPARATION_MAX, the detail naming
 * it). Otherwise as interphase_update_dt.
 */
int interphase_update_increment(const double *props, int nprops, int ntens, const double *state_old,
                                const double *separation_old, const double *separation, const double *dt,
                                double *traction, double *tangent, double *state_new, double *stored_energy,
                                char *detail, size_t detail_len);

/**
 * One point along a whole path of separations in one call: the loop over the increments runs
 * inside the library (for hosts that replay loading histories, where a call per increment costs
 * more than the update itself: the Python package, docs/python.md). Each step is the increment
 * the Abaqus UMAT would take, with the same numbers: DSTRAN = s[i] - s[i-1], the update at
 * STRAN + DSTRAN, dt = time[i] - time[i-1], and the dissipated energy accumulated as the UMAT's
 * SPD. Re-entrant and thread-safe, as interphase_update.
 *
 * Every array holds one row per point of the path, rows contiguous (row-major): row 0 is the
 * start, which the caller fills (a virgin point: all zero); rows 1 .. nrows-1 are computed.
 *
 * @param props              material constants, @p nprops doubles (as interphase_update)
 * @param nprops             number of PROPS
 * @param ntens              2 (2-D) or 3 (3-D)
 * @param nrows              rows of the path, the start included (>= 1)
 * @param separation         @p nrows * @p ntens doubles: the separation at each row (mm)
 * @param time               @p nrows doubles (s), finite, not decreasing and with finite steps (else
 *                           INTERPHASE_STATUS_BAD_TIME_INCREMENT at the first row that breaks it,
 *                           whatever the material), or NULL (no time increment: a material with
 *                           viscous regularisation is then refused, as by interphase_update)
 * @param traction           in/out, @p nrows * @p ntens doubles (MPa): row 0 given
 * @param tangent            out, NULL or @p nrows * @p ntens * @p ntens doubles, each row's
 *                           matrix row-major (MPa/mm); row 0 is not written
 * @param state              in/out, @p nrows * nstate doubles, nstate = INTERPHASE_NSTATE, or
 *                           INTERPHASE_NSTATE_VISCOUS with viscous regularisation: row 0 given
 * @param stored_energy      in/out, @p nrows doubles (N/mm): [0] given
 * @param dissipated_energy  in/out, @p nrows doubles (N/mm): [0] given; W[i] = W[i-1] +
 *                           1/2 (t[i-1] + t[i]).(s[i] - s[i-1]) - (psi[i] - psi[i-1])
 * @param rows_done          out, may be NULL: the number of rows that hold results (the start
 *                           included): @p nrows on success, the failed row on failure
 * @param detail             out, may be NULL: on failure, the message, which names the row
 * @param detail_len         size of @p detail in bytes
 * @return INTERPHASE_STATUS_OK (0), or the status of the first step that fails (the rows from
 *         it on are untouched; a host may retry that step in smaller ones); the checks of row 0
 *         are those of interphase_update on its inputs (INTERPHASE_STATUS_BAD_STATE,
 *         INTERPHASE_STATUS_BAD_HOST_INPUT for a separation, traction or energy out of range);
 *         @p nrows = 0, or one too large for any array (2^63 / 72 or more, SIZE_MAX included:
 *         named as the unsigned value it is), gives INTERPHASE_STATUS_BAD_HISTORY, as in
 *         interphase_run_history; a NULL @p props, @p separation, @p traction, @p state,
 *         @p stored_energy or @p dissipated_energy INTERPHASE_STATUS_NULL_ARGUMENT, naming it.
 */
int interphase_run(const double *props, int nprops, int ntens, size_t nrows, const double *separation,
                   const double *time, double *traction, double *tangent, double *state,
                   double *stored_energy, double *dissipated_energy, size_t *rows_done, char *detail,
                   size_t detail_len);

/**
 * A whole loading history replayed at one point as the single-point driver interphase-point
 * replays it (drivers/README.md), with the numbers of the Abaqus UMAT, the loop inside the
 * library: each component of each row is given either as its separation (mm) or as its traction
 * (MPa) (mixed control: e.g. a normal compression held while the shear separation is driven),
 * and the control may change from one row to the next. Re-entrant and thread-safe, as
 * interphase_update (the same interphase_mixed_control algorithm as the driver's).
 *
 * The point starts virgin at zero separation at time[0]; a first row away from zero is reached
 * first in @p increments steps at time[0] (dt = 0; no output row). Each segment between two rows
 * is split into @p increments equal sub-increments, controlled as the segment's end row says; an
 * imposed traction runs linearly from the previous row's value (same control there) or from the
 * point's traction. A traction-controlled component's separation is found by Newton's method on
 * the tangent, from the last converged state, to within @p traction_tolerance (MPa), in at most
 * 25 updates. A step whose update fails or whose Newton iteration does not converge is halved
 * and retried, up to 10 times; a failure that no smaller step can cure (a bad time increment, a
 * tabulated R-curve that does not cover the damage reached) ends the replay at once. Each step is
 * the increment the UMAT would take (DSTRAN = s - s_old, the update at STRAN + DSTRAN, DTIME =
 * t - t_old) and the dissipated energy is accumulated as its SPD.
 *
 * The output is one row for the start (time[0]) and one for every @p output_every -th converged
 * step (counted from the first, the preload's included) and for the end of every segment: the
 * rows of the driver's CSV file.
 *
 * @param props                material constants, @p nprops doubles (as interphase_update)
 * @param nprops               number of PROPS
 * @param ntens                2 (2-D) or 3 (3-D)
 * @param nrows                 rows of the history (>= 1)
 * @param time                  @p nrows doubles, finite and strictly increasing, each step
 *                              time[i] - time[i-1] finite (s)
 * @param value                 @p nrows * @p ntens doubles, row-major, each row normal first:
 *                              the separation (mm), or the traction (MPa) where control is 1
 * @param control               NULL (every component separation-controlled) or @p nrows * @p ntens
 *                              ints, row-major: 0 separation, 1 traction
 * @param increments            sub-increments per segment (>= 1)
 * @param traction_tolerance    MPa, finite, > 0 and at most 1e-3 (interphase-point's default: 1e-12;
 *                              outside, INTERPHASE_STATUS_BAD_HISTORY)
 * @param output_every          a row every k-th converged step (>= 1; 1: every step)
 * @param capacity              rows each output array holds
 * @param out_time              out, NULL or @p capacity doubles: t of each row
 * @param out_separation        out, NULL or @p capacity * @p ntens doubles (mm)
 * @param out_traction          out, NULL or @p capacity * @p ntens doubles (MPa)
 * @param out_state             out, NULL or @p capacity * nstate doubles (INTERPHASE_NSTATE, or
 *                              INTERPHASE_NSTATE_VISCOUS with viscous regularisation)
 * @param out_stored_energy     out, NULL or @p capacity doubles (N/mm): the UMAT's SSE
 * @param out_dissipated_energy out, NULL or @p capacity doubles (N/mm): the UMAT's SPD
 * @param out_tangent           out, NULL or @p capacity * @p ntens * @p ntens doubles: the
 *                              tangent of the step that reached each row, row-major; NaN for a
 *                              start at zero (no step reached it)
 * @param rows_done             out, may be NULL: the rows written (also on failure: the rows up
 *                              to it, those of the driver's incomplete CSV)
 * @param detail                out, may be NULL: on failure, the message (the step's times, the
 *                              imposed values or the update's detail)
 * @param detail_len            size of @p detail in bytes (257 holds any message)
 * @return INTERPHASE_STATUS_OK; a material status as interphase_update;
 *         INTERPHASE_STATUS_NULL_ARGUMENT (a NULL @p props, @p time or @p value, named);
 *         INTERPHASE_STATUS_BAD_HISTORY (nrows 0, nrows or capacity too large for any array
 *         (2^63 / 72 or more, SIZE_MAX included: named as the unsigned value), an nrows whose
 *         4 * ntens * nrows bytes of controls the library cannot allocate, times, a value
 *         that is not finite or an imposed traction beyond 1e150 MPa, controls, increments,
 *         output_every, traction_tolerance: checked before any update);
 *         INTERPHASE_STATUS_SEPARATION_OUT_OF_RANGE (before any update: a separation of the
 *         history beyond 1e20 mm, naming its row and component; during the replay: an imposed
 *         traction, a compression as a rule, that needs a separation beyond 1e20 mm: compression
 *         has no peak);
 *         INTERPHASE_STATUS_BEYOND_PEAK (an imposed traction is raised beyond the largest the
 *         point reached, or is met only on a flat tangent, where the point carries no more load
 *         in its direction or its separation is undetermined: no solution), INTERPHASE_STATUS_MIXED_NOT_CONVERGED
 *         (Newton failed even after the halvings), or the status of an update that failed even
 *         after the halvings or for good; INTERPHASE_STATUS_OUTPUT_FULL when the replay has more
 *         rows than @p capacity (the arrays hold the first @p capacity rows: call again with
 *         longer ones; without halvings 1 + (nrows - 1) * increments rows suffice).
 */
int interphase_run_history(const double *props, int nprops, int ntens, size_t nrows, const double *time,
                           const double *value, const int *control, int increments,
                           double traction_tolerance, int output_every, size_t capacity,
                           double *out_time, double *out_separation, double *out_traction,
                           double *out_state, double *out_stored_energy, double *out_dissipated_energy,
                           double *out_tangent, size_t *rows_done, char *detail, size_t detail_len);

/**
 * Load the custom RVE table that the micromechanical model uses where PROPS[7] = 1 (what
 * UEXTERNALDB does with INTERPHASE_TABLE in Abaqus). Reads the file (format: tables/README.md),
 * checks it (header, columns, numbers, a from 0 to b, the exact identities of the RVE problems)
 * and builds its interpolant. Until a table is loaded, such an update returns
 * INTERPHASE_STATUS_TABLE_NOT_LOADED.
 *
 * NOT thread-safe: it writes library-wide data. Call it once, from one thread, before any thread
 * calls interphase_update; a later call replaces the table and must not overlap any update.
 *
 * @param path        NUL-terminated file name (at most 4096 bytes; NULL is a file that cannot be
 *                    read: INTERPHASE_STATUS_TABLE_UNREADABLE, "RVE table path is NULL")
 * @param detail      out, may be NULL: on failure, a NUL-terminated message naming the file, the
 *                    line and the failed check (e.g. "bad.dat:5: 2 numbers where the ...")
 * @param detail_len  size of @p detail in bytes (257 holds any message: at most 256 characters)
 * @return INTERPHASE_STATUS_OK (0), or INTERPHASE_STATUS_TABLE_* (49-58) or
 *         INTERPHASE_STATUS_SPLINE_* (40-48); on failure the table loaded before (if any) stays.
 */
int interphase_load_table(const char *path, char *detail, size_t detail_len);

/**
 * Load the tabulated R-curve of the fracture-mechanics damage law, used where the R-curve
 * selector (PROPS[nm + 1]) is 3 (what UEXTERNALDB does with INTERPHASE_RCURVE in Abaqus). The
 * file holds rows "D G_cI G_cII" (D strictly increasing in [0, 1], consecutive D at least 1e-9
 * apart, at least two rows, toughnesses in [1e-20, 1e20] N/mm; `#` comments and blank lines
 * allowed). Until one is loaded, such an update
 * returns INTERPHASE_STATUS_RCURVE_NOT_LOADED.
 *
 * NOT thread-safe: it writes library-wide data. Call it once, from one thread, before any thread
 * calls interphase_update; a later call replaces the R-curve and must not overlap any update.
 *
 * @param path        NUL-terminated file name (at most 4096 bytes; NULL is a file that cannot be
 *                    read: INTERPHASE_STATUS_RCURVE_UNREADABLE, "R-curve path is NULL")
 * @param detail      out, may be NULL: on failure, a NUL-terminated message naming the file, the
 *                    line and the failed check
 * @param detail_len  size of @p detail in bytes (257 holds any message: at most 256 characters)
 * @return INTERPHASE_STATUS_OK (0), or INTERPHASE_STATUS_RCURVE_* (60-63; 65, a toughness outside
 *         [1e-20, 1e20] N/mm) or INTERPHASE_STATUS_SPLINE_* (40-48); on failure the R-curve
 *         loaded before (if any) stays.
 */
int interphase_load_rcurve(const char *path, char *detail, size_t detail_len);

/**
 * The generic message of a status code (e.g. "full-crack normal separation sf_N out of range").
 *
 * @param status  a status code returned by interphase_update or a loader
 * @param buf     out, may be NULL: receives at most @p len - 1 characters and a NUL
 * @param len     size of @p buf in bytes
 * @return the length of the full message (without the NUL), as snprintf does
 */
size_t interphase_status_message(int status, char *buf, size_t len);

#ifdef __cplusplus
}
#endif

#endif /* INTERPHASE_H */
