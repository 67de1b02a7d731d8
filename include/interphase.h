/**
 * @file interphase.h
 * @brief C interface of interphase: the brick-mortar interface law (damage, unilateral contact,
 *        Coulomb friction) at one integration point, for C and C++ finite-element codes.
 *
 * Link with the core library `libinterphase` (CMake: `find_package(interphase)` and
 * `target_link_libraries(app PRIVATE interphase::interphase)`), plus the Fortran runtime
 * (`-lgfortran`) and LAPACK when linking by hand. The functions are re-entrant and thread-safe:
 * they keep no state; the caller owns every array.
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
 * regime code), all zero for a virgin point.
 */
#ifndef INTERPHASE_H
#define INTERPHASE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/** Number of doubles in a state array (STATEV slots 1..4 of the UMAT). */
#define INTERPHASE_NSTATE 4
/** Number of PROPS of the simplified (spring) model. */
#define INTERPHASE_NPROPS_SIMPLIFIED 9

/* Status codes (the values of interphase_status in src/interphase_status.f90). */
#define INTERPHASE_STATUS_OK 0                   /**< success */
#define INTERPHASE_STATUS_BAD_NPROPS 1           /**< wrong number of PROPS */
#define INTERPHASE_STATUS_BAD_MODEL 2            /**< PROPS[0]: unknown model */
#define INTERPHASE_STATUS_BAD_DAMAGE_LAW 3       /**< PROPS[1]: unknown damage law */
#define INTERPHASE_STATUS_BAD_MU 4               /**< PROPS[2]: mu out of range */
#define INTERPHASE_STATUS_BAD_S0_N 5             /**< PROPS[3]: s0_N out of range */
#define INTERPHASE_STATUS_BAD_SF_N 6             /**< PROPS[4]: sf_N out of range */
#define INTERPHASE_STATUS_BAD_S0_T 7             /**< PROPS[5]: s0_T out of range */
#define INTERPHASE_STATUS_BAD_SF_T 8             /**< PROPS[6]: sf_T out of range */
#define INTERPHASE_STATUS_BAD_K_N 9              /**< PROPS[7]: K_N out of range */
#define INTERPHASE_STATUS_BAD_K_T 10             /**< PROPS[8]: K_T out of range */
#define INTERPHASE_STATUS_BAD_NTENS 11           /**< ntens is not 2 or 3 */
#define INTERPHASE_STATUS_MODEL_UNAVAILABLE 13   /**< model not available in this build */
#define INTERPHASE_STATUS_NONFINITE_SEPARATION 20 /**< separation NaN or Inf */
#define INTERPHASE_STATUS_BAD_STATE 21           /**< state_old out of range or not finite */
#define INTERPHASE_STATUS_BAD_COEFFICIENTS 22    /**< coefficient set not admissible */

/**
 * Update one interface point: traction, consistent tangent, new state and stored energy at
 * the separation @p separation, starting from the state @p state_old.
 *
 * @param props          material constants, @p nprops doubles (docs/abaqus.md, PROPS table)
 * @param nprops         number of PROPS (9 simplified, 8 micromechanical; 4 more with the
 *                       fracture-mechanics damage law: docs/abaqus.md)
 * @param ntens          2 (2-D: s_N, s_T) or 3 (3-D: s_N, s_T1, s_T2)
 * @param state_old      INTERPHASE_NSTATE doubles: the state at the start of the increment
 * @param separation     @p ntens doubles: total separation at the end of the increment (mm)
 * @param traction       out, @p ntens doubles: traction (MPa)
 * @param tangent        out, @p ntens * @p ntens doubles, row-major: d traction / d separation (MPa/mm)
 * @param state_new      out, INTERPHASE_NSTATE doubles: state at the end (may alias nothing else)
 * @param stored_energy  out: recoverable energy per unit area (N/mm)
 * @param detail         out, may be NULL: on failure, a NUL-terminated message naming the bad
 *                       value (e.g. "PROPS(5) sf_N = 1.00000E-04 is out of range: ...")
 * @param detail_len     size of @p detail in bytes (256 is always enough)
 * @return INTERPHASE_STATUS_OK (0), or a status code; on failure traction, tangent, state_new
 *         and stored_energy are left untouched.
 */
int interphase_update(const double *props, int nprops, int ntens, const double *state_old,
                      const double *separation, double *traction, double *tangent,
                      double *state_new, double *stored_energy, char *detail, size_t detail_len);

/**
 * The generic message of a status code (e.g. "full-crack normal separation sf_N out of range").
 *
 * @param status  a status code returned by interphase_update
 * @param buf     out, may be NULL: receives at most @p len - 1 characters and a NUL
 * @param len     size of @p buf in bytes
 * @return the length of the full message (without the NUL), as snprintf does
 */
size_t interphase_status_message(int status, char *buf, size_t len);

#ifdef __cplusplus
}
#endif

#endif /* INTERPHASE_H */
