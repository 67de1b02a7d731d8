!> Abaqus/Explicit VUMAT for cohesive elements (RESPONSE=TRACTION SEPARATION, constitutive
!> thickness 1), over the same pure kernel as the UMAT.
!>
!> Conventions (docs/abaqus.md, "VUMAT"):
!> - ndir = 1 and nshr = 1 (2-D) or 2 (3-D): component 1 is the normal one, then the shear(s) in
!>   the order Abaqus passes them (the law is isotropic in the interface plane).
!> - Abaqus/Explicit passes strain *increments* with *tensor* shear components, strain =
!>   separation / constitutive thickness. With the thickness THICKNESS = 1 (required):
!>   ds_N = THICKNESS * strainInc(:, 1), ds_T = 2 * THICKNESS * strainInc(:, 2:).
!>   The total separation is accumulated in STATEV(SV_SEP_N:SV_SEP_T2).
!> - stressNew = tractions (MPa), same order.
!> - Energies per unit mass (`*Density` is required, > 0): enerInternNew is the work done on the
!>   point (stored + dissipated), enerInelasNew the dissipated part, both per unit area divided
!>   by density * THICKNESS; (enerInternNew - enerInelasNew) * density is the stored energy psi
!>   of the kernel (the UMAT's SSE) and enerInelasNew * density the UMAT's SPD.
!> - Packaging call (totalTime = 0 and stepTime = 0): the elastic response
!>   stressNew = stressOld + K ds with K the model's coefficients at D = 0, state and energies
!>   copied unchanged. An annealing call (lanneal = 1) copies stress, state and energies
!>   unchanged.
!>
!> The materials `block_supports` accepts (the displacement-driven law, either model; not with
!> viscous regularisation, nor the micromechanical contact band) run the vectorised block update
!> (interphase_block, column by column); the others the point update
!> (interphase_kernel) point by point. Both return the UMAT's numbers bit for bit.
!>
!> Failures: bad sizes (a negative nblock too), PROPS, density (outside [1e-50, 1e50]) or
!> incoming STATEV (the separations STATEV(6:8) not finite or beyond 1e20 mm where that makes a
!> point's update fail), a stepTime or totalTime that is not finite, with viscous
!> regularisation a dt that is negative or not finite (STATUS_BAD_TIME_INCREMENT), a NaN or Inf
!> in stressOld, the old energies or a point's separation increment, or one of them beyond 1e150
!> (the increment: 1e50 mm) (STATUS_BAD_HOST_INPUT), a custom RVE table or R-curve
!> selected but not loaded (VEXTERNALDB), and a tabulated R-curve that does not cover D0 or the
!> damage a point reaches, are fatal (the whole block is held at
!> its old values and the host hook is called with SEVERITY_FATAL; Abaqus then stops). A point
!> whose update fails on admissible inputs (a separation s_old + ds beyond |s_i| = 1e20 mm,
!> inadmissible coefficients) keeps its old stress, state and energies,
!> gets STATEV(SV_FAILED) = 1, and one warning per call names the number of failed points and
!> the first one; the other points of the block are updated (Abaqus/Explicit has no PNEWDT).
!> With INTERPHASE_REPLAY_DIR set, the first failed point's call is written there as a UMAT call
!> (interphase_replay_file; `interphase-point FILE` repeats it through the same kernel).
!> Thread-safe: no SAVE, COMMON or module data is written.
subroutine vumat(nblock, ndir, nshr, nstatev, nfieldv, nprops, lanneal, steptime, totaltime, &
      dt, cmname, coordmp, charlength, props, density, straininc, relspininc, tempold, &
      stretchold, defgradold, fieldold, stressold, stateold, enerinternold, enerinelasold, &
      tempnew, stretchnew, defgradnew, fieldnew, stressnew, statenew, enerinternnew, &
      enerinelasnew)
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   use interphase_layout, only: NSTATV_VUMAT, SV_DAMAGE, SV_SLIP_1, SV_SLIP_2, &
      SV_REGIME, SV_SEP_N, SV_SEP_T1, SV_SEP_T2, SV_FAILED, SV_DAMAGE_INVISCID, NSTATV_SHARED, NSTATV_VISCOUS
   use interphase_status, only: STATUS_OK, STATUS_BAD_NTENS, STATUS_BAD_NSTATV, MESSAGE_LEN, &
      SEVERITY_WARNING, SEVERITY_FATAL, STATUS_RCURVE_OUT_OF_RANGE, status_message, STATUS_BAD_HOST_INPUT, &
      STATUS_BAD_STATE, STATUS_BAD_TIME_INCREMENT
   use interphase_finite, only: is_within, is_finite, is_finite_nonnegative
   use interphase_params, only: HOST_VALUE_MAX, HOST_INCREMENT_MAX, SEPARATION_MAX
   use interphase_params, only: law_params_type, from_props, refuse_umat_options
   use interphase_state, only: interface_state_type, unpack_statev, pack_statev, count_invalid_states, state_slots
   use interphase_kernel, only: update_point, closes_within
   use interphase_coefficients, only: coefficient_set_type
   use interphase_provider, only: coefficients_at, check_run_time_data
   use interphase_block, only: block_update, density_counts, block_supports, block_energies
   use interphase_rcurve, only: rcurve_overrun
   use interphase_abaqus_interfaces, only: interphase_host_message
   use interphase_replay_file, only: write_replay, replay_note
   use interphase_real_text, only: es_list
   implicit none
   integer, intent(in) :: nblock                    !! number of material points in this call
   integer, intent(in) :: ndir                      !! direct components: 1 (cohesive elements)
   integer, intent(in) :: nshr                      !! shear components: 1 (2-D) or 2 (3-D)
   integer, intent(in) :: nstatev                   !! state variables per point, >= NSTATV_VUMAT
   integer, intent(in) :: nfieldv                   !! field variables (unused)
   integer, intent(in) :: nprops                    !! number of PROPS (docs/abaqus.md)
   integer, intent(in) :: lanneal                   !! 1: annealing call
   real(dp), intent(in) :: steptime, totaltime, dt  !! step time, total time, time increment
   character(len=80), intent(in) :: cmname          !! material name
   real(dp), intent(in) :: coordmp(nblock, *), charlength(nblock)
   real(dp), intent(in) :: props(nprops)            !! PROPS, docs/abaqus.md
   real(dp), intent(in) :: density(nblock)          !! density (`*Density`), > 0
   real(dp), intent(in) :: straininc(nblock, ndir + nshr)  !! strain increments, tensor shears
   real(dp), intent(in) :: relspininc(nblock, nshr), tempold(nblock)
   real(dp), intent(in) :: stretchold(nblock, ndir + nshr), defgradold(nblock, ndir + nshr + nshr)
   real(dp), intent(in) :: fieldold(nblock, nfieldv)
   real(dp), intent(in) :: stressold(nblock, ndir + nshr)  !! tractions at the start (MPa)
   real(dp), intent(in) :: stateold(nblock, nstatev)       !! STATEV at the start
   real(dp), intent(in) :: enerinternold(nblock), enerinelasold(nblock)  !! per unit mass
   real(dp), intent(in) :: tempnew(nblock), stretchnew(nblock, ndir + nshr)
   real(dp), intent(in) :: defgradnew(nblock, ndir + nshr + nshr), fieldnew(nblock, nfieldv)
   real(dp), intent(out) :: stressnew(nblock, ndir + nshr)  !! tractions at the end (MPa)
   real(dp), intent(out) :: statenew(nblock, nstatev)       !! STATEV at the end
   real(dp), intent(out) :: enerinternnew(nblock)           !! work done per unit mass
   real(dp), intent(out) :: enerinelasnew(nblock)           !! dissipated energy per unit mass

   !> Constitutive thickness of the cohesive section (mm); interphase requires 1.
   real(dp), parameter :: THICKNESS = 1.0_dp
   !> Separation per tensor shear strain: engineering shear = 2 x tensor shear.
   real(dp), parameter :: SHEAR_FACTOR = 2.0_dp

   !> Points updated per pass. The passes' working arrays are local (on the stack, 144 KB, of the
   !> call's ~170 KB: docs/abaqus.md, 'Thread safety'; an
   !> automatic array sized by nblock would be allocated on the heap per call). Long passes let
   !> the hardware prefetchers follow the ~25 columns a VUMAT reads and writes: at nblock = 4096,
   !> 7.0 ns per point with passes of 256, 6.0 with 2048, 5.1 with 4096 (docs/performance.md).
   integer, parameter :: CHUNK = 4096

   type(law_params_type) :: params
   type(interface_state_type) :: old, new
   type(coefficient_set_type) :: intact, intact_rate
   real(dp) :: ds(CHUNK, 3), psi(CHUNK)
   logical :: ok(CHUNK)
   !> the block's points whose crack closes within the increment (they take the point update)
   logical :: closing(CHUNK)
   real(dp) :: s_point(3), s_point_old(3), sv(NSTATV_VISCOUS)
   real(dp) :: traction(3), tangent(3, 3), psi_first
   logical :: blocked, packaging, viscous, bad_state, by_point
   integer(int64) :: ncross   !! points whose s_N passes from positive to not positive
   integer :: nsv   !! STATEV slots of the state (state_slots)
   integer :: ntens, nt, km, k, k0, k1, n, j, nbad, status, nfailed, first_failed, first_status, nbad_energy
   integer :: fatal_code   !! a STATUS_* code, or < 0 when `message` says it all
   integer :: fatal_point  !! the block point a fatal error is about (its coordMp named), or 0
   integer :: ios
   character(len=MESSAGE_LEN) :: message, first_message

   ntens = ndir + nshr
   nt = nshr
   fatal_point = 0

   ! Setup errors leave the block construct with fatal_code set: the whole block is then held
   ! at its old values and a fatal message is reported (no internal procedure: host-associated
   ! arrays cost the vectorised loops ~2.5 ns per point with gfortran, docs/performance.md).
   update: block
      ! ---- setup checks: fatal, the whole block is held ----------------------------------------
      if (nblock < 0) then
         write (message, '(a,i0,a)') 'nblock = ', nblock, ': the number of points in a call cannot be negative'
         fatal_code = -1
         exit update
      end if
      ! the host's times: finite (they are compared below; a NaN would raise the invalid flag)
      if (.not. (is_finite(steptime) .and. is_finite(totaltime))) then
         write (message, '(a,es12.4e3,a,es12.4e3,a)', iostat=ios) 'stepTime = ', steptime, ', totalTime = ', &
            totaltime, ' s: the host must pass finite times'
         fatal_code = STATUS_BAD_HOST_INPUT
         exit update
      end if
      if (ndir /= 1 .or. (nshr /= 1 .and. nshr /= 2)) then
         write (message, '(a,i0,a,i0,a)') 'ndir = ', ndir, ', nshr = ', nshr, &
            ': interphase needs a cohesive element with ndir = 1 and nshr = 1 (2-D) or 2 (3-D)'
         fatal_code = STATUS_BAD_NTENS
         exit update
      end if
      if (nstatev < NSTATV_VUMAT) then
         write (message, '(a,i0,a,i0,a)') 'nstatev = ', nstatev, ' but the VUMAT needs at least ', &
            NSTATV_VUMAT, ' (*DEPVAR; since 2026-12 slots 6-9 hold the separations and the failure flag)'
         fatal_code = STATUS_BAD_NSTATV
         exit update
      end if
      call from_props(props, params, status, message)
      if (status == STATUS_OK) call refuse_umat_options(params, 'the VUMAT', status, message)
      if (status /= STATUS_OK) then
         fatal_code = status
         exit update
      end if
      viscous = params%viscosity > 0.0_dp
      nsv = state_slots(params)
      ! viscous regularisation needs dt: one value for the whole block, the host's (as the UMAT's
      ! DTIME: fatal)
      if (viscous .and. .not. is_finite_nonnegative(dt)) then
         write (message, '(a,es12.4e3,a)', iostat=ios) 'dt = ', dt, ' s: viscous regularisation needs a finite dt >= 0'
         fatal_code = STATUS_BAD_TIME_INCREMENT
         exit update
      end if
      ! a custom table or R-curve that was not loaded at start-up (VEXTERNALDB)
      call check_run_time_data(params, status, message)
      if (status /= STATUS_OK) then
         fatal_code = status
         exit update
      end if
      ! user slots beyond interphase's are carried over
      if (nstatev > NSTATV_VUMAT) then
         statenew(:, NSTATV_VUMAT + 1:nstatev) = stateold(:, NSTATV_VUMAT + 1:nstatev)
      end if

      ! ---- packaging call (time zero) and annealing: no state change ---------------------------
      packaging = lanneal == 1 .or. (totaltime <= 0.0_dp .and. steptime <= 0.0_dp)
      if (packaging .and. lanneal /= 1) then
         ! the elastic response of the intact interface (either model: its coefficients at D = 0)
         ! is returned, for Abaqus's stable-time-increment estimate
         call coefficients_at(params, 0.0_dp, intact, intact_rate, status)
         if (status /= STATUS_OK) then
            message = 'the intact coefficients (D = 0) could not be evaluated'
            fatal_code = status
            exit update
         end if
      end if

      ! ---- the update, CHUNK points at a time ---------------------------------------------
      ! The materials block_supports admits run the vectorised block update (interphase_block);
      ! the others run the point update (interphase_kernel). Both give the same numbers (bit for
      ! bit). Results go straight into
      ! the new arrays; a failed point is put back to its old values afterwards.
      blocked = block_supports(params)
      nfailed = 0
      first_failed = 0
      first_status = STATUS_OK
      first_message = ''
      do k0 = 1, nblock, CHUNK
         n = min(CHUNK, nblock - k0 + 1)
         k1 = k0 + n - 1
         ! densities and incoming states of the chunk: one branch-free pass each, the culprit
         ! searched for only on error (then the whole block is held, the chunks before too)
         call density_counts(n, density(k0:k1), nbad)
         if (nbad > 0) then
            do km = k0, k1
               call density_counts(1, density(km:km), nbad)
               if (nbad > 0) exit
            end do
            write (message, '(a,i0,a,es13.5e3,a)') 'density at block point ', km, ' = ', density(km), &
               ': the VUMAT needs *Density > 0, within [1e-50, 1e50], on the material (its energies are per unit mass)'
            fatal_code = -1
            fatal_point = km
            exit update
         end if
         ! (in 2-D the slip-2 column is not looked at: slip 1 stands in, so that it is not read)
         ! (with viscous regularisation the point update reads STATEV(SV_DAMAGE_INVISCID) too: every
         ! point is checked by unpack_statev then)
         bad_state = count_invalid_states(n, nt, stateold(k0:k1, SV_DAMAGE), stateold(k0:k1, SV_SLIP_1), &
            stateold(k0:k1, SV_SLIP_1 + nt - 1), stateold(k0:k1, SV_REGIME)) > 0
         if (viscous .and. .not. bad_state) then
            do km = k0, k1
               sv(1:nsv) = stateold(km, 1:nsv)
               call unpack_statev(nsv, sv, ntens, viscous, old, status, message)
               if (status /= STATUS_OK) bad_state = .true.
               if (bad_state) exit
            end do
         end if
         if (bad_state) then
            do km = k0, k1
               sv(1:nsv) = stateold(km, 1:nsv)
               call unpack_statev(nsv, sv, ntens, viscous, old, status, message)
               if (status /= STATUS_OK) exit
            end do
            write (first_message, '(a,i0,a,a)') 'block point ', km, ': ', trim(message)
            message = first_message
            fatal_code = status
            fatal_point = km
            exit update
         end if

         if (packaging) then
            if (lanneal /= 1) then
               ! the host's values are checked as in an update: a NaN, an Inf or a magnitude out of
               ! range would otherwise come back as the traction Abaqus estimates wave speeds from
               ! (a scalar pass: this call comes once per analysis)
               do km = k0, k1
                  s_point(1) = THICKNESS*straininc(km, 1)
                  s_point(2:ntens) = SHEAR_FACTOR*THICKNESS*straininc(km, 2:ntens)
                  if (all(is_within(s_point(1:ntens), HOST_INCREMENT_MAX)) .and. &
                     all(is_within(stressold(km, :), HOST_VALUE_MAX)) .and. &
                     is_within(enerinternold(km), HOST_VALUE_MAX) .and. is_within(enerinelasold(km), HOST_VALUE_MAX)) cycle
                  write (message, '(a,i0,a,a,a,a,a,a,a,es8.1e3,a,es8.1e3,a)', iostat=ios) 'block point ', km, &
                     ' (packaging call): stressOld (MPa)', es_list(stressold(km, :), 3), &
                     ', energies', es_list([enerinternold(km), enerinelasold(km)], 3), ', increment (mm)', &
                     es_list(s_point(1:ntens), 3), ': the host must pass finite values within ', HOST_VALUE_MAX, &
                     ', increments within ', HOST_INCREMENT_MAX, ' mm'
                  fatal_code = STATUS_BAD_HOST_INPUT
                  fatal_point = km
                  exit update
               end do
            end if
            stressnew(k0:k1, :) = stressold(k0:k1, :)
            statenew(k0:k1, 1:NSTATV_VUMAT) = stateold(k0:k1, 1:NSTATV_VUMAT)
            enerinternnew(k0:k1) = enerinternold(k0:k1)
            enerinelasnew(k0:k1) = enerinelasold(k0:k1)
            if (lanneal /= 1) then
               stressnew(k0:k1, 1) = stressold(k0:k1, 1) + intact%k_n*THICKNESS*straininc(k0:k1, 1)
               stressnew(k0:k1, 2:ntens) = stressold(k0:k1, 2:ntens) &
                  + intact%k_t*SHEAR_FACTOR*THICKNESS*straininc(k0:k1, 2:ntens)
            end if
            cycle
         end if

         ! separation increments ds = T0 strainInc (x 2 for the tensor shears) and the separations
         ! at the end of the increment, s = s_old + ds, stored in STATEV (one pass per dimension,
         ! every column read and written once)
         if (ntens == 2) then
            do k = 1, n
               km = k0 + k - 1
               ds(k, 1) = THICKNESS*straininc(km, 1)
               ds(k, 2) = SHEAR_FACTOR*THICKNESS*straininc(km, 2)
               statenew(km, SV_SEP_N) = stateold(km, SV_SEP_N) + ds(k, 1)
               statenew(km, SV_SEP_T1) = stateold(km, SV_SEP_T1) + ds(k, 2)
               statenew(km, SV_FAILED) = stateold(km, SV_FAILED)
               statenew(km, SV_DAMAGE_INVISCID) = stateold(km, SV_DAMAGE_INVISCID)
            end do
         else
            do k = 1, n
               km = k0 + k - 1
               ds(k, 1) = THICKNESS*straininc(km, 1)
               ds(k, 2) = SHEAR_FACTOR*THICKNESS*straininc(km, 2)
               ds(k, 3) = SHEAR_FACTOR*THICKNESS*straininc(km, 3)
               statenew(km, SV_SEP_N) = stateold(km, SV_SEP_N) + ds(k, 1)
               statenew(km, SV_SEP_T1) = stateold(km, SV_SEP_T1) + ds(k, 2)
               statenew(km, SV_SEP_T2) = stateold(km, SV_SEP_T2) + ds(k, 3)
               statenew(km, SV_FAILED) = stateold(km, SV_FAILED)
               statenew(km, SV_DAMAGE_INVISCID) = stateold(km, SV_DAMAGE_INVISCID)
            end do
         end if

         if (blocked) then
            ! the outputs go straight into stressNew and stateNew; in 2-D the block's zero second
            ! tangential traction fills STATEV(SV_SEP_T2), which is 0 in 2-D (and its unused
            ! second tangential inputs are the first ones: no column is read for nothing)
            if (ntens == 3) then
               call block_update(params, n, nt, statenew(k0:k1, SV_SEP_N), &
                  statenew(k0:k1, SV_SEP_T1), statenew(k0:k1, SV_SEP_T2), stateold(k0:k1, SV_DAMAGE), &
                  stateold(k0:k1, SV_SLIP_1), stateold(k0:k1, SV_SLIP_2), stressnew(k0:k1, 1), &
                  stressnew(k0:k1, 2), stressnew(k0:k1, 3), statenew(k0:k1, SV_DAMAGE), &
                  statenew(k0:k1, SV_SLIP_1), statenew(k0:k1, SV_SLIP_2), statenew(k0:k1, SV_REGIME), &
                  psi(1:n), ok(1:n), nbad)
            else
               call block_update(params, n, nt, statenew(k0:k1, SV_SEP_N), &
                  statenew(k0:k1, SV_SEP_T1), statenew(k0:k1, SV_SEP_T1), stateold(k0:k1, SV_DAMAGE), &
                  stateold(k0:k1, SV_SLIP_1), stateold(k0:k1, SV_SLIP_1), stressnew(k0:k1, 1), &
                  stressnew(k0:k1, 2), statenew(k0:k1, SV_SEP_T2), statenew(k0:k1, SV_DAMAGE), &
                  statenew(k0:k1, SV_SLIP_1), statenew(k0:k1, SV_SLIP_2), statenew(k0:k1, SV_REGIME), &
                  psi(1:n), ok(1:n), nbad)
            end if
            ! a crack that closes within the increment starts its friction step from the slip
            ! where the faces met (interphase_closing), which the block does not form:
            ! such points take the point update below, which replaces the block's values (the
            ! kernel's closes_within decides, for the block as for every update)
            ! (a screen first, in a pass of its own, which vectorises: the points whose s_N passed
            ! from positive to not positive, on bit patterns as the block's checks, so that a NaN
            ! raises no flag; only where there is one, closes_within, the decision)
            ncross = 0
            do k = 1, n
               km = k0 + k - 1
               ncross = ncross + merge(1_int64, 0_int64, transfer(stateold(km, SV_SEP_N), 0_int64) > 0_int64 &
                  .and. transfer(statenew(km, SV_SEP_N), 0_int64) <= 0_int64)
            end do
            by_point = ncross > 0
            if (by_point) then
               closing(1:n) = closes_within(stateold(k0:k1, SV_REGIME), stateold(k0:k1, SV_DAMAGE), &
                  stateold(k0:k1, SV_SEP_N), statenew(k0:k1, SV_SEP_N))
               by_point = any(closing(1:n))
            end if
         else
            if (ntens == 2) statenew(k0:k1, SV_SEP_T2) = 0.0_dp
            nbad = 0
            by_point = .true.
         end if
         s_point_old = 0.0_dp
         if (by_point) then
            do k = 1, n
               if (blocked) then
                  if (.not. closing(k)) cycle
                  ! (the block's count of failed points without this one's: the point update counts it)
                  if (.not. ok(k)) nbad = nbad - 1
               end if
               km = k0 + k - 1
               ! checked above, cannot fail here
               sv(1:nsv) = stateold(km, 1:nsv)
               call unpack_statev(nsv, sv, ntens, viscous, old, status, message)
               s_point(1:ntens) = statenew(km, SV_SEP_N:SV_SEP_N + ntens - 1)
               s_point_old(1:ntens) = stateold(km, SV_SEP_N:SV_SEP_N + ntens - 1)
               call update_point(params, old, ntens, s_point, traction, tangent, new, psi(k), status, dt, s_point_old)
               if (status == STATUS_RCURVE_OUT_OF_RANGE) then
                  ! the R-curve file does not reach the damage this point needs: a setup error
                  write (message, '(a,i0,a,a)', iostat=status) 'block point ', km, ': ', &
                     rcurve_overrun(60, max(old%d, params%d0), s_point(1:ntens))
                  fatal_code = STATUS_RCURVE_OUT_OF_RANGE
                  fatal_point = km
                  exit update
               end if
               ok(k) = status == STATUS_OK
               if (.not. ok(k)) then
                  nbad = nbad + 1
                  if (first_status == STATUS_OK) first_status = status
                  traction = 0.0_dp
                  new = interface_state_type()
                  psi(k) = 0.0_dp
               end if
               stressnew(km, 1:ntens) = traction(1:ntens)
               ! (through a contiguous copy: a row of the block is strided; pack_statev writes
               ! every one of the nsv slots, the damage law's D exactly when viscous)
               call pack_statev(new, nsv, sv, viscous)
               statenew(km, 1:nsv) = sv(1:nsv)
            end do
         end if

         if (nbad > 0) then
            if (first_failed == 0) then
               first_failed = k0 - 1 + findloc(ok(1:n), .false., dim=1)
               ! the block update reports no status: the point update on that point says why
               if (blocked) then
                  sv(1:nsv) = stateold(first_failed, 1:nsv)
                  call unpack_statev(nsv, sv, ntens, viscous, old, status, message)
                  s_point(1:ntens) = statenew(first_failed, SV_SEP_N:SV_SEP_N + ntens - 1)
                  s_point_old(1:ntens) = stateold(first_failed, SV_SEP_N:SV_SEP_N + ntens - 1)
                  call update_point(params, old, ntens, s_point, traction, tangent, new, psi_first, first_status, dt, &
                     s_point_old)
               end if
               write (first_message, '(a,3es13.4e3)') 'separation (mm) ', &
                  statenew(first_failed, SV_SEP_N:SV_SEP_N + ntens - 1)
            end if
            nfailed = nfailed + nbad
            ! a failed point whose increment, or incoming separation STATEV(6:8) (the VUMAT's own
            ! output, within SEPARATION_MAX), is not finite or out of range failed on the host's
            ! data, not on the law: fatal, as the energies' check below is for the other points
            do k = 1, n
               if (ok(k)) cycle
               km = k0 + k - 1
               if (.not. all(is_within(ds(k, 1:ntens), HOST_INCREMENT_MAX))) then
                  write (message, '(a,i0,a,a,a,es8.1e3,a)', iostat=ios) 'block point ', km, &
                     ': separation increment (mm)', es_list(ds(k, 1:ntens), 4), &
                     ' (T0 strainInc, tensor shears x 2): the host must pass finite increments within ', &
                     HOST_INCREMENT_MAX, ' mm'
                  fatal_code = STATUS_BAD_HOST_INPUT
                  fatal_point = km
                  exit update
               end if
               if (.not. all(is_within(stateold(km, SV_SEP_N:SV_SEP_N + ntens - 1), SEPARATION_MAX))) then
                  write (message, '(a,i0,a,i0,a,i0,a,a,a,es8.1e3,a)', iostat=ios) 'block point ', km, &
                     ': incoming STATEV(', SV_SEP_N, ':', SV_SEP_N + ntens - 1, ') separation (mm)', &
                     es_list(stateold(km, SV_SEP_N:SV_SEP_N + ntens - 1), 4), ': must be finite within ', SEPARATION_MAX, &
                     ' mm (what the VUMAT returned last)'
                  fatal_code = STATUS_BAD_STATE
                  fatal_point = km
                  exit update
               end if
            end do
            ! (no work is counted on a failed point: its increment is zeroed for the energies' pass)
            do j = 1, ntens
               ds(1:n, j) = merge(ds(1:n, j), 0.0_dp, ok(1:n))
            end do
         end if

         ! the energies per unit mass, with the check of the host's values (block_energies: one
         ! vectorised pass without branches)
         ! (column ntens is the third in 3-D, the second again in 2-D, where it only is checked)
         call block_energies(n, nt, THICKNESS, density(k0:k1), stressold(k0:k1, 1), &
            stressold(k0:k1, 2), stressold(k0:k1, ntens), ds(1:n, 1), ds(1:n, 2), ds(1:n, ntens), &
            stressnew(k0:k1, 1), stressnew(k0:k1, 2), stressnew(k0:k1, ntens), psi(1:n), enerinternold(k0:k1), &
            enerinelasold(k0:k1), enerinternnew(k0:k1), enerinelasnew(k0:k1), nbad_energy)
         if (nbad_energy > 0) then
            do k = 1, n
               km = k0 + k - 1
               if (.not. (all(is_within(stressold(km, :), HOST_VALUE_MAX)) .and. &
                  is_within(enerinternold(km), HOST_VALUE_MAX) .and. is_within(enerinelasold(km), HOST_VALUE_MAX) &
                  .and. all(is_within(ds(k, 1:ntens), HOST_INCREMENT_MAX)))) exit
            end do
            k = min(k, n)
            km = k0 + k - 1
            ! (es_list: e3 exponents, values up to 1e150 and beyond are printed, each after a blank)
            write (message, '(a,i0,a,a,a,a,a,a,a,es8.1e3,a,es8.1e3,a)', iostat=ios) 'block point ', km, &
               ': stressOld (MPa)', es_list(stressold(km, :), 3), ', energies', &
               es_list([enerinternold(km), enerinelasold(km)], 3), ', increment (mm)', es_list(ds(k, 1:ntens), 3), &
               ': the host must pass finite values within ', &
               HOST_VALUE_MAX, ', increments within ', HOST_INCREMENT_MAX, ' mm'
            fatal_code = STATUS_BAD_HOST_INPUT
            fatal_point = km
            exit update
         end if

         ! a failed point is held at its old values and flagged
         if (nbad > 0) then
            do k = 1, n
               if (ok(k)) cycle
               km = k0 + k - 1
               stressnew(km, :) = stressold(km, :)
               statenew(km, 1:NSTATV_VUMAT) = stateold(km, 1:NSTATV_VUMAT)
               statenew(km, SV_FAILED) = 1.0_dp
               enerinternnew(km) = enerinternold(km)
               enerinelasnew(km) = enerinelasold(km)
            end do
         end if
      end do

      if (nfailed > 0) then
         block
            character(len=2*MESSAGE_LEN) :: full
            character(len=:), allocatable :: replay, why
            real(dp) :: sep_old(3), dsep(3), rho_first
            integer :: kinc     !! the increment's number for the replay file's name, totalTime/dt
            write (full, '(a,a,i0,a,i0,a,i0,a,i0,a,a,a,a)') trim(cmname), ': ', nfailed, ' of ', nblock, &
               ' points failed and were held at their old stress and state (STATEV(', SV_FAILED, &
               ') = 1); first at block point ', first_failed, ': ', status_message(first_status), ': ', trim(first_message)
            ! (Abaqus passes no element number to a VUMAT: the point's coordinates say where it is)
            full = trim(full)//' (block point at coordMp'//es_list(coordmp(first_failed, 1:ntens), 3)//')'
            ! with INTERPHASE_REPLAY_DIR set: the first failed point's call as a UMAT call (its
            ! separation and increment, the shared STATEV, the energies per unit area)
            sep_old = [stateold(first_failed, SV_SEP_N), stateold(first_failed, SV_SEP_T1), &
               stateold(first_failed, SV_SEP_T2)]
            dsep(1) = THICKNESS*straininc(first_failed, 1)
            dsep(2:ntens) = SHEAR_FACTOR*THICKNESS*straininc(first_failed, 2:ntens)
            rho_first = density(first_failed)*THICKNESS
            ! (0 where dt is not a positive finite number, or the quotient would not be below
            ! 999999999, the 9 digits a replay file's integers have: no comparison with a NaN, no
            ! overflow; totalTime is finite, checked at the start)
            kinc = 0
            if (is_finite(dt)) then
               if (dt > 0.0_dp .and. totaltime >= 0.0_dp) then
                  if (totaltime/999999999.0_dp < dt) kinc = nint(totaltime/dt)
               end if
            end if
            call write_replay('vumat', trim(full), props, stateold(first_failed, 1:NSTATV_SHARED), &
               stressold(first_failed, :), (enerinternold(first_failed) - enerinelasold(first_failed))*rho_first, &
               enerinelasold(first_failed)*rho_first, sep_old(1:ntens), dsep(1:ntens), [steptime, totaltime], dt, &
               first_failed, 0, kinc, replay, why=why)
            call interphase_host_message(SEVERITY_WARNING, trim(full)//replay_note(replay, why))
         end block
      end if
      return
   end block update

   ! ---- setup error: hold the whole block at its old values and report ------------------
   stressnew = stressold
   statenew = stateold
   enerinternnew = enerinternold
   enerinelasnew = enerinelasold
   block
      character(len=2*MESSAGE_LEN) :: full
      if (fatal_code >= 0) then
         write (full, '(a,a,a,a,a)') trim(cmname), ': ', status_message(fatal_code), ': ', trim(message)
      else
         write (full, '(a,a,a)') trim(cmname), ': ', trim(message)
      end if
      ! where the point is: Abaqus passes no element number to a VUMAT, but its coordinates (one a
      ! dimension: 2 for ndir = 1, nshr = 1, 3 for nshr = 2)
      if (fatal_point >= 1 .and. fatal_point <= nblock) &
         full = trim(full)//' (block point at coordMp'//es_list(coordmp(fatal_point, 1:ntens), 3)//')'
      call interphase_host_message(SEVERITY_FATAL, trim(full))
   end block

end subroutine vumat
