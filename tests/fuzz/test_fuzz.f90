!> The drivers' readers as a start-up loader for test_fuzz (below), in a module of its own: an
!> internal procedure of the program passed as an actual argument would need a trampoline on the
!> stack, and the program an executable stack.
module test_fuzz_loaders
   use interphase_status, only: STATUS_OK, MESSAGE_LEN
   use interphase_driver_history, only: history_type, read_history
   use interphase_driver_case, only: case_type, read_case
   implicit none
   private
   public :: driver_file_loader

contains

   !> The drivers' readers as a start-up loader (status 1 when they refuse the file): a case
   !> file (*.nml) through read_case, any other through read_history.
   subroutine driver_file_loader(path, status, text)
      character(len=*), intent(in) :: path
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: text
      type(history_type) :: history
      type(case_type) :: run
      character(len=:), allocatable :: why
      logical :: ok
      if (index(path, '.nml', back=.true.) == len(path) - 3) then
         call read_case(path, run, ok, why)
      else
         call read_history(path, history, ok, why)
      end if
      status = merge(STATUS_OK, 1, ok)
      text = ''
      if (.not. ok) text = why
   end subroutine driver_file_loader
end module test_fuzz_loaders

!> The fuzz test of interphase (ctest `test_fuzz`, bounded: a few seconds in Release, well under
!> its 30 s timeout in Debug). A fixed seed and a portable generator (Park-Miller, the same
!> numbers with every compiler), so that every run is the same and a failure is reproducible.
!>
!> Part 1, random histories: for every model (simplified, micromechanical), damage law
!> (displacement-driven; fracture mechanics with the constant and the equivalent R-curve), RVE
!> table (built-in; tables/paper-resolution.dat loaded as the custom table) and dimension (2-D,
!> 3-D), random materials (mu, s0, sf, K, G_c, the growth-slip and contact-band options) and one random
!> piecewise-linear history per point (some of them at separations up to 1e19 mm, and a few
!> steps beyond the admissible 1e20 mm) run through the UMAT (point by point), the VUMAT (all
!> points of a material as one block) and the C entry point. After every step it asserts:
!>   - the three adapters agree bit for bit (traction, state; the UMAT's DDSDDE and SSE with the
!>     C API's tangent and stored energy) and fail together (a failed step leaves every one of
!>     them at its old values);
!>   - no NaN or Inf (traction, tangent, state, SSE, SPD, the VUMAT's energies);
!>   - D in [0, 1] and never decreasing;
!>   - the dissipation (the UMAT's SPD) never decreases where the law promises it: with the
!>     default growth-slip rule (pi = D ufbar lambda conserved; the paper's fixed-lambda form
!>     can return energy), within round-off, and for the micromechanical model not on a step
!>     across s_N = 0 (its traction jumps there, docs/theory.md 'Open and closed at s_N = 0');
!>   - continuity at s_N = 0 for the simplified model and for the micromechanical one with the
!>     contact band (half its materials; displacement law and equivalent R-curve): from the state
!>     reached, the traction at s_N = +delta and -delta differs by no more than the tangent
!>     allows over 2 delta.
!> Part 2, malformed files: valid RVE tables, R-curves, history files and case files, each
!> broken at one random line (a field replaced by text that is not a number, a field deleted,
!> text appended, an entry given twice), through their readers (load_custom_table, load_rcurve,
!> read_history, read_case): each must be refused with a message naming the file and the line.
!>
!> A failure prints the material, the point, the step and what differed, and the program ends
!> with exit status 1.
program test_fuzz
   use, intrinsic :: iso_fortran_env, only: int64, error_unit, output_unit
   use interphase_kinds, only: dp
   use interphase_finite, only: is_finite
   use interphase_layout, only: MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, DAMAGE_DISPLACEMENT, DAMAGE_FRACTURE, &
      TABLE_DEFAULT_CODE, TABLE_CUSTOM_CODE, RCURVE_CONSTANT, RCURVE_EQUIVALENT, NSTATV_REQUIRED, SV_DAMAGE, &
      SV_FAILED, SV_REGIME, SV_SEP_N, REGIME_OPEN, REGIME_SLIP, GROWTH_FIXED_PI, GROWTH_FIXED_LAMBDA
   use interphase_status, only: STATUS_OK, MESSAGE_LEN, SEVERITY_FATAL, file_loader
   use interphase_params, only: SEPARATION_MAX, law_params_type, from_props
   use interphase_coefficients, only: coefficient_set_type
   use interphase_provider, only: coefficients_at
   use interphase_micro_coefficients, only: load_custom_table
   use interphase_rcurve, only: load_rcurve
   use test_fuzz_loaders, only: driver_file_loader
   use interphase_driver_text, only: int_to_string
   use interphase_test_support, only: paper_k_n, paper_k_t, source_path, scratch_path
   use interphase_adapter_calls, only: umat_point_type, call_umat_point, vumat_block_type, vumat_block_init, &
      call_vumat_block, call_capi
   use host_recorder, only: recorder_reset, recorded_severity, recorded_message
   implicit none

   !> Points (histories) per material and dimension, materials per law and model, and the
   !> density of the VUMAT block (tonne/mm^3).
   integer, parameter :: NPOINTS = 32, NMATERIALS = 6
   real(dp), parameter :: RHO = 2.0e-9_dp
   !> Broken files per reader.
   integer, parameter :: NBROKEN = 40
   !> Round-off allowance of the dissipation and continuity checks, in units of the relative
   !> precision: the terms of SPD += 1/2 (t_n + t).ds - (psi - psi_n) are summed with at most a
   !> handful of roundings each, so a loss of more than 64 ulps of their magnitudes is not
   !> round-off.
   real(dp), parameter :: ROUNDOFF = 64.0_dp*epsilon(1.0_dp)

   !> One point's history: separations (ntens, steps), UMAT order (mm).
   type :: path_holder
      real(dp), allocatable :: s(:, :)
   end type path_holder

   integer(int64) :: seed = 20261201_int64
   integer :: nfailed = 0, nchecked = 0, nsteps_run = 0
   !> What part 1 covered: steps every adapter refused, dissipation and continuity checks made.
   integer :: nrefused = 0, nelastic = 0, nopen = 0, ncontinuity = 0, nrising = 0, ninverted = 0
   !> A digest of every result of part 1 (bit patterns), printed so that builds can be compared.
   integer(int64) :: digest = 0_int64
   !> Broken files refused (part 2).
   integer :: nbroken_refused = 0
   integer :: model, law, rcurve, table, ntens, imat, load_status
   character(len=MESSAGE_LEN) :: message

   ! the custom table of the micromechanical cases: the paper's RVE at the paper's resolution (a
   ! table over the whole range of D, unlike tables/paper-small-d.dat, the short-crack reference,
   ! whose interpolant between its rows at D = 0.09 and D = 1 is not a law: see stiffness_rises)
   call load_custom_table(source_path('tables/paper-resolution.dat'), load_status, message)
   if (load_status /= STATUS_OK) then
      write (error_unit, '(a)') 'test_fuzz: cannot load tables/paper-resolution.dat: '//trim(message)
      error stop 1
   end if

   ! ---- part 1: random histories over every model, law, table and dimension ----------------
   do model = MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL
      do table = TABLE_DEFAULT_CODE, merge(TABLE_DEFAULT_CODE, TABLE_CUSTOM_CODE, model == MODEL_SIMPLIFIED)
         do law = 1, 3      ! displacement-driven; fracture with the constant / equivalent R-curve
            do ntens = 2, 3
               do imat = 1, NMATERIALS
                  rcurve = merge(RCURVE_CONSTANT, RCURVE_EQUIVALENT, law == 2)
                  call run_material(model, law, rcurve, table, ntens, imat)
               end do
            end do
         end do
      end do
   end do

   ! ---- part 2: malformed files through every reader ---------------------------------------
   call broken_tables()
   call broken_rcurves()
   call broken_histories()
   call broken_cases()

   write (output_unit, '(a,i0,a,i0,a,i0,a,i0,a,i0,a)') 'test_fuzz: ', nsteps_run, ' point updates (', nrefused, &
      ' refused by all three adapters), ', nelastic, ' steps without evolution, ', nopen, ' open steps, ', &
      ncontinuity, ' continuity probes'
   if (nrising > 0) write (output_unit, '(a,i0,a)') 'test_fuzz: note: ', nrising, ' open steps not checked for '// &
      'dissipation: the open crack''s stiffness rises with D there (or is negative): a table''s interpolant, '// &
      'not the law (see stiffness_rises)'
   if (ninverted > 0) write (output_unit, '(a,i0,a)') 'test_fuzz: note: ', ninverted, ' continuity probes skipped: '// &
      'the table''s interpolant has dbar_N <= 0 there (see continuity_at_zero)'
   write (output_unit, '(a,i0,a)') 'test_fuzz: digest of the results ', digest, ' (compare builds: it is the same '// &
      'when every result is)'
   write (output_unit, '(a,i0,a,i0,a)') 'test_fuzz: ', nbroken_refused, ' of ', 4*NBROKEN, &
      ' broken files refused (RVE tables, R-curves, histories, case files)'
   write (output_unit, '(a,i0,a,i0,a)') 'test_fuzz: ', nchecked, ' checks, ', nfailed, ' failed'
   if (nfailed > 0) error stop 1

contains

   ! ======================================================================================
   ! random numbers
   ! ======================================================================================

   !> Uniform in (0, 1): the Park-Miller minimal standard generator (products stay below 2^47).
   real(dp) function uniform()
      seed = mod(48271_int64*seed, 2147483647_int64)
      uniform = real(seed, dp)/2147483647.0_dp
   end function uniform

   !> Uniform in [lo, hi].
   real(dp) function between(lo, hi)
      real(dp), intent(in) :: lo, hi
      between = lo + (hi - lo)*uniform()
   end function between

   !> Uniform integer in [lo, hi].
   integer function pick(lo, hi)
      integer, intent(in) :: lo, hi
      pick = min(hi, lo + int(real(hi - lo + 1, dp)*uniform()))
   end function pick

   !> Mix bit patterns into the digest (modulo the Park-Miller prime, no overflow).
   subroutine add_to_digest(values)
      real(dp), intent(in) :: values(:)
      integer :: i
      integer(int64) :: bits
      do i = 1, size(values)
         bits = transfer(values(i), 0_int64)
         digest = modulo(digest*31_int64 + modulo(bits, 2147483647_int64) + modulo(ishft(bits, -32), 2147483647_int64), &
            2147483647_int64)
      end do
   end subroutine add_to_digest

   ! ======================================================================================
   ! checks
   ! ======================================================================================

   !> Count a check; on failure print what and where.
   subroutine check(condition, where, what)
      logical, intent(in) :: condition
      character(len=*), intent(in) :: where, what
      nchecked = nchecked + 1
      if (condition) return
      nfailed = nfailed + 1
      if (nfailed <= 40) write (error_unit, '(a)') 'test_fuzz: FAILED: '//where//': '//what
   end subroutine check

   !> The same binary64 numbers, bit for bit.
   pure logical function same_bits(a, b)
      real(dp), intent(in) :: a(:), b(:)
      same_bits = all(transfer(a, 0_int64, size(a)) == transfer(b, 0_int64, size(b)))
   end function same_bits

   ! ======================================================================================
   ! part 1
   ! ======================================================================================

   !> PROPS of a random material of the given model, law, R-curve and table; the paper's data
   !> scaled by random factors (mu from 0 to 1.5), the growth-slip option random, and for half
   !> the micromechanical materials the contact band chi from 0.3 to 2 (0 otherwise).
   function random_props(model, law, rcurve, table, growth_slip, chi) result(props)
      integer, intent(in) :: model, law, rcurve, table
      integer, intent(out) :: growth_slip
      real(dp), intent(out) :: chi
      real(dp), allocatable :: props(:)
      real(dp) :: mu, scale_n, scale_t, eta_n, eta_t, s0_n, s0_t, draw, draw_band
      mu = merge(0.0_dp, between(0.0_dp, 1.5_dp), uniform() < 0.15_dp)
      scale_n = between(0.5_dp, 2.0_dp)
      scale_t = between(0.5_dp, 2.0_dp)
      s0_n = 0.00044_dp*scale_n
      s0_t = 0.00072_dp*scale_t
      eta_n = between(0.005_dp, 0.5_dp)
      eta_t = between(0.005_dp, 0.5_dp)
      if (model == MODEL_SIMPLIFIED) then
         props = [real(MODEL_SIMPLIFIED, dp), real(DAMAGE_DISPLACEMENT, dp), mu, s0_n, s0_n/eta_n, s0_t, s0_t/eta_t, &
            paper_k_n()*between(0.3_dp, 3.0_dp), paper_k_t()*between(0.3_dp, 3.0_dp)]
      else
         props = [real(MODEL_MICROMECHANICAL, dp), real(DAMAGE_DISPLACEMENT, dp), mu, s0_n, s0_n/eta_n, s0_t, &
            s0_t/eta_t, real(table, dp)]
      end if
      if (law /= 1) then
         props(2) = real(DAMAGE_FRACTURE, dp)
         if (rcurve == RCURVE_CONSTANT) then
            props = [props, between(0.02_dp, 0.3_dp), real(RCURVE_CONSTANT, dp), 0.005_dp*between(0.3_dp, 3.0_dp), &
               0.0085_dp*between(0.3_dp, 3.0_dp)]
         else
            props = [props, between(0.02_dp, 0.3_dp), real(RCURVE_EQUIVALENT, dp), 0.0_dp, 0.0_dp]
         end if
      end if
      growth_slip = merge(GROWTH_FIXED_LAMBDA, GROWTH_FIXED_PI, uniform() < 0.25_dp)
      ! the option constant given (always for the paper's form, half the time for the default)
      draw = uniform()
      chi = 0.0_dp
      draw_band = uniform()
      if (model == MODEL_MICROMECHANICAL .and. draw_band < 0.5_dp) chi = between(0.3_dp, 2.0_dp)
      if (growth_slip == GROWTH_FIXED_LAMBDA .or. draw < 0.5_dp .or. chi > 0.0_dp) &
         props = [props, real(growth_slip, dp)]
      if (chi > 0.0_dp) props = [props, chi]
   end function random_props

   !> A random piecewise-linear history of `ntens` components from zero: 3 to 5 segments, each
   !> split into 4 to 12 steps; targets within an amplitude (0.05 to 1.2) of sf (s_N in
   !> compression or opening, crossing 0, sometimes exactly 0), one history in six scaled up to
   !> 1e3..1e19 mm, and now and then a step beyond the admissible range (which every adapter
   !> must refuse).
   function random_history(ntens, sf_n, sf_t) result(path)
      integer, intent(in) :: ntens
      real(dp), intent(in) :: sf_n, sf_t
      real(dp), allocatable :: path(:, :)
      real(dp), parameter :: AMPLITUDES(4) = [0.05_dp, 0.2_dp, 0.5_dp, 1.2_dp]
      real(dp) :: target(3), from(3), scale
      integer :: nseg, iseg, nsub, j, n
      nseg = pick(3, 5)
      ! most histories stay below full damage; one in six is scaled up to 1e3..1e19 mm
      scale = AMPLITUDES(pick(1, size(AMPLITUDES)))
      if (uniform() < 1.0_dp/6.0_dp) scale = 10.0_dp**pick(3, 19)
      allocate (path(ntens, 0))
      from = 0.0_dp
      do iseg = 1, nseg
         target(1) = between(-0.6_dp, 1.2_dp)*sf_n*scale
         target(2) = between(-1.5_dp, 1.5_dp)*sf_t*scale
         target(3) = between(-1.5_dp, 1.5_dp)*sf_t*scale
         if (uniform() < 0.2_dp) target(1) = 0.0_dp
         nsub = pick(4, 12)
         do j = 1, nsub
            n = size(path, 2)
            path = reshape([path, from(1:ntens) + (real(j, dp)/real(nsub, dp))*(target(1:ntens) - from(1:ntens))], &
               [ntens, n + 1])
         end do
         from = target
      end do
      if (uniform() < 0.1_dp) then
         ! one step beyond the admissible range, then back
         j = pick(1, size(path, 2))
         path(pick(1, ntens), j) = sign(2.0_dp*SEPARATION_MAX, between(-1.0_dp, 1.0_dp))
      end if
   end function random_history

   !> NPOINTS random histories of one random material through the three adapters.
   subroutine run_material(model, law, rcurve, table, ntens, imat)
      integer, intent(in) :: model, law, rcurve, table, ntens, imat
      real(dp), allocatable :: props(:)
      type(umat_point_type) :: points(NPOINTS), before
      type(vumat_block_type) :: vblock
      type(path_holder) :: paths(NPOINTS)
      real(dp) :: cstate(NSTATV_REQUIRED, NPOINTS), cnew(NSTATV_REQUIRED), ct(3), ck(3, 3), cpsi
      real(dp) :: sep(3, NPOINTS), s_new(3), ds(NPOINTS, 3), d_old, spd_old, scale_terms, vstress_old(3)
      real(dp) :: vstate_old(NSTATV_REQUIRED), kscale(NPOINTS)
      integer :: growth_slip, k, step, nstep, status
      real(dp) :: chi
      logical :: umat_ok, vumat_ok, capi_ok, rises, evolved, open_step
      real(dp) :: draw
      character(len=MESSAGE_LEN) :: detail
      character(len=:), allocatable :: name, where
      type(law_params_type) :: params

      ! (allocated before the assignment: gfortran -O2 otherwise warns that the descriptor of the
      ! reallocated array is used uninitialised)
      allocate (props(0))
      props = random_props(model, law, rcurve, table, growth_slip, chi)
      call from_props(props, params, status, detail)
      call check(status == STATUS_OK, 'random material', 'PROPS refused: '//trim(detail))
      name = trim(merge('simplified     ', 'micromechanical', model == MODEL_SIMPLIFIED))//' '// &
         trim(merge('displacement        ', 'fracture, constant  ', law == 1))
      if (law == 3) name = name(1:index(name, 'fracture') - 1)//'fracture, equivalent'
      if (model == MODEL_MICROMECHANICAL) name = name//trim(merge(', built-in table ', ', custom table   ', &
         table == TABLE_DEFAULT_CODE))
      name = name//', '//int_to_string(ntens)//'-D, material '//int_to_string(imat)//', growth slip '// &
         int_to_string(growth_slip)//trim(merge(', contact band', '              ', chi > 0.0_dp))
      call vumat_block_init(vblock, NPOINTS, ntens - 1, RHO)
      nstep = 0
      do k = 1, NPOINTS
         points(k)%ntens = ntens
         paths(k)%s = random_history(ntens, props(5), props(7))
         nstep = max(nstep, size(paths(k)%s, 2))
      end do
      cstate = 0.0_dp
      sep = 0.0_dp
      kscale = 0.0_dp
      do step = 1, nstep
         ! the increments of this step (a history that has ended stays where it is)
         ds = 0.0_dp
         do k = 1, NPOINTS
            if (step <= size(paths(k)%s, 2)) ds(k, 1:ntens) = paths(k)%s(:, step) - sep(1:ntens, k)
         end do
         ! the VUMAT: the whole block at once (SV_FAILED cleared, so that it says this step's outcome)
         vblock%state(:, SV_FAILED) = 0.0_dp
         call recorder_reset()
         call call_vumat_block(vblock, props, ds(:, 1:ntens), 'FUZZ')
         call check(recorded_severity /= SEVERITY_FATAL, name//', step '//int_to_string(step), &
            'the VUMAT reported a fatal error: '//trim(recorded_message))
         do k = 1, NPOINTS
            nsteps_run = nsteps_run + 1
            where = name//', point '//int_to_string(k)//', step '//int_to_string(step)
            before = points(k)
            d_old = points(k)%statev(SV_DAMAGE)
            spd_old = points(k)%spd
            s_new(1:ntens) = sep(1:ntens, k) + ds(k, 1:ntens)
            ! the UMAT
            points(k)%pnewdt = 1.0_dp
            call call_umat_point(points(k), props, ds(k, 1:ntens), 'FUZZ')
            umat_ok = .not. (points(k)%pnewdt < 1.0_dp)
            ! the C entry point, from the same state and separation
            ct = 0.0_dp
            ck = 0.0_dp
            cpsi = 0.0_dp
            cnew = cstate(:, k)
            call call_capi(props, ntens, cstate(:, k), s_new(1:ntens), ct(1:ntens), ck(1:ntens, 1:ntens), cnew, &
               cpsi, status, detail, sep(1:ntens, k))
            capi_ok = status == STATUS_OK
            vumat_ok = .not. (vblock%state(k, SV_FAILED) > 0.0_dp)
            call check(umat_ok .eqv. capi_ok, where, 'UMAT ok = '//trim(merge('T', 'F', umat_ok))// &
               ' but C API status '//int_to_string(status)//' '//trim(detail))
            call check(umat_ok .eqv. vumat_ok, where, 'UMAT ok = '//trim(merge('T', 'F', umat_ok))// &
               ' but VUMAT ok = '//trim(merge('T', 'F', vumat_ok)))
            if (.not. (umat_ok .and. capi_ok .and. vumat_ok)) then
               ! a failed step: every adapter at its old values
               nrefused = nrefused + 1
               call check(same_bits(before%statev, points(k)%statev) .and. same_bits(before%stress, points(k)%stress), &
                  where, 'the UMAT changed its outputs on a failed step')
               if (.not. vumat_ok) then
                  call check(same_bits(vblock%state(k, 1:NSTATV_REQUIRED), before%statev) .and. &
                     same_bits(vblock%state(k, SV_SEP_N:SV_SEP_N + ntens - 1), sep(1:ntens, k)), where, &
                     'the VUMAT changed the state of a failed point')
               end if
               cycle
            end if
            sep(1:ntens, k) = s_new(1:ntens)
            ! the three adapters bit for bit
            vstate_old = vblock%state(k, 1:NSTATV_REQUIRED)
            vstress_old(1:ntens) = vblock%stress(k, 1:ntens)
            call check(same_bits(points(k)%statev, cnew), where, 'UMAT and C API states differ')
            call check(same_bits(points(k)%statev, vstate_old), where, 'UMAT and VUMAT states differ')
            call check(same_bits(points(k)%stress(1:ntens), ct(1:ntens)), where, 'UMAT and C API tractions differ')
            call check(same_bits(points(k)%stress(1:ntens), vstress_old(1:ntens)), where, &
               'UMAT and VUMAT tractions differ')
            call check(same_bits(reshape(points(k)%ddsdde(1:ntens, 1:ntens), [ntens*ntens]), &
               reshape(ck(1:ntens, 1:ntens), [ntens*ntens])), where, 'UMAT DDSDDE and C API tangent differ')
            call check(same_bits([points(k)%sse], [cpsi]), where, 'UMAT SSE and C API stored energy differ')
            cstate(:, k) = cnew
            call add_to_digest([points(k)%statev, points(k)%stress(1:ntens), points(k)%sse, points(k)%spd])
            ! finite, damage monotone in [0, 1]
            call check(all(is_finite([points(k)%stress(1:ntens), points(k)%statev, points(k)%sse, points(k)%spd, &
               reshape(points(k)%ddsdde(1:ntens, 1:ntens), [ntens*ntens]), vblock%ener_intern(k), &
               vblock%ener_inelas(k)])), where, 'a result is not finite')
            call check(points(k)%statev(SV_DAMAGE) >= d_old .and. points(k)%statev(SV_DAMAGE) <= 1.0_dp, where, &
               'damage left [D_n, 1]')
            ! dissipation (the UMAT's SPD, by the trapezoid rule) where the law promises it, within
            ! round-off of the terms it is formed from: no dissipation on a step without evolution
            ! (D and slip unchanged, no slip regime: SPD unchanged); never less on a step that ends
            ! as it starts, open or intact (t = C(D) s with C non-increasing in D, so that
            ! dSPD = 1/2 s_n.(C(D_n) - C(D)) s >= 0 when no component changes sign)
            kscale(k) = max(kscale(k), maxval(abs(points(k)%ddsdde(1:ntens, 1:ntens))))
            scale_terms = sum(abs(before%stress(1:ntens)*ds(k, 1:ntens))) + &
               sum(abs(points(k)%stress(1:ntens)*ds(k, 1:ntens))) + abs(points(k)%sse) + abs(before%sse) + &
               abs(spd_old) + kscale(k)*(sum(abs(s_new(1:ntens))) + sum(abs(points(k)%statev(2:3))))**2
            write (detail, '(a,es12.4,a,es12.4,a,i0,a,i0)') 'by ', points(k)%spd - spd_old, ' (round-off bound ', &
               ROUNDOFF*scale_terms, '); regime ', nint(before%statev(SV_REGIME)), ' -> ', &
               nint(points(k)%statev(SV_REGIME))
            evolved = .not. (same_bits(before%statev(1:3), points(k)%statev(1:3)) .and. &
               same_bits(before%statev(SV_REGIME:SV_REGIME), points(k)%statev(SV_REGIME:SV_REGIME)) .and. &
               nint(points(k)%statev(SV_REGIME)) /= REGIME_SLIP)
            ! (not where the contact band's energy, not quadratic in s, acts at either end of the
            ! step: the trapezoid is exact there only for small steps, docs/theory.md)
            open_step = nint(before%statev(SV_REGIME)) <= REGIME_OPEN .and. &
               nint(points(k)%statev(SV_REGIME)) <= REGIME_OPEN .and. all(before%stran(1:ntens)*s_new(1:ntens) >= 0.0_dp) &
               .and. .not. (in_band(chi, ntens, before%stran) .or. in_band(chi, ntens, s_new))
            if (.not. evolved) then
               nelastic = nelastic + 1
               call check(abs(points(k)%spd - spd_old) <= ROUNDOFF*scale_terms, where, &
                  'dissipation on a step without evolution '//trim(detail))
            else if (open_step) then
               rises = stiffness_rises(params, d_old, points(k)%statev(SV_DAMAGE))
               if (rises) then
                  nrising = nrising + 1
               else
                  nopen = nopen + 1
                  call check(points(k)%spd - spd_old >= -ROUNDOFF*scale_terms, where, &
                     'the dissipation decreased on an open step '//trim(detail))
               end if
            end if
            ! continuity at s_N = 0 where the law is continuous: the simplified model, and the
            ! micromechanical one with the contact band (docs/theory.md, 'The contact band') with the
            ! displacement-driven law or the equivalent R-curve. (With a given R-curve, constant or
            ! tabulated, the band's D on either side agrees only to the residue of the table's
            ! identity C^f_T = -D ufbar tc_t in the stored energy, up to 2e-3 near D = 1: more than
            ! this check's Lipschitz bound over 2e-9 s0_N.)
            draw = uniform()
            if ((model == MODEL_SIMPLIFIED .or. (chi > 0.0_dp .and. (law == 1 .or. rcurve == RCURVE_EQUIVALENT))) &
               .and. draw < 0.3_dp) then
               call continuity_at_zero(params, props, ntens, cstate(:, k), s_new, kscale(k), where)
            end if
         end do
      end do
      write (output_unit, '(a,f6.3,a,f6.3)') '  '//name//': largest D ', maxval(cstate(SV_DAMAGE, :)), &
         ', smallest ', minval(cstate(SV_DAMAGE, :))
   end subroutine run_material

   !> Whether the separation s lies in the contact band 0 < s_N < chi |s_T| (chi > 0).
   pure logical function in_band(chi, ntens, s)
      real(dp), intent(in) :: chi
      integer, intent(in) :: ntens
      real(dp), intent(in) :: s(:)
      in_band = chi > 0.0_dp .and. s(1) > 0.0_dp .and. s(1) < chi*norm2(s(2:ntens))
   end function in_band

   !> Whether the open crack's stiffness rises from D_n to D (k_n or k_t larger at D): the law's
   !> promise of a non-negative dissipation on open steps rests on C(D) non-increasing. A table
   !> whose interpolant breaks that (tables/paper-small-d.dat has no rows between D = 0.09 and
   !> D = 1: its spline gives k_t < 0 from D = 0.867 and a rising k_t above D = 0.996; the
   !> built-in table's k has a small positive slope at D = 0) is counted and reported, not checked.
   logical function stiffness_rises(params, d_from, d_to) result(rises)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: d_from, d_to
      type(coefficient_set_type) :: c_from, c_to, dc
      integer :: status
      rises = .false.
      if (.not. (d_to > d_from)) return
      call coefficients_at(params, d_from, c_from, dc, status)
      if (status /= STATUS_OK) return
      call coefficients_at(params, d_to, c_to, dc, status)
      if (status /= STATUS_OK) return
      rises = c_to%k_n > c_from%k_n .or. c_to%k_t > c_from%k_t .or. c_to%k_t < 0.0_dp .or. c_to%k_n < 0.0_dp
   end function stiffness_rises

   !> From `state`, the traction at (+delta, s_T) and (-delta, s_T) through the C entry point:
   !> the difference must stay within what the tangents allow over 2 delta (plus round-off).
   subroutine continuity_at_zero(params, props, ntens, state, s, kscale, where)
      type(law_params_type), intent(in) :: params
      real(dp), intent(in) :: props(:)
      integer, intent(in) :: ntens
      real(dp), intent(in) :: state(NSTATV_REQUIRED), s(3)
      real(dp), intent(in) :: kscale         !! largest tangent entry met on this point (MPa/mm)
      character(len=*), intent(in) :: where
      real(dp) :: delta, sp(3), sm(3), tp(3), tm(3), kp(3, 3), km(3, 3), newp(NSTATV_REQUIRED), newm(NSTATV_REQUIRED)
      real(dp) :: psi, bound, closed_scale
      integer :: status_p, status_m, status_c
      type(coefficient_set_type) :: c, dc
      character(len=MESSAGE_LEN) :: detail
      delta = 1.0e-9_dp*props(4)
      sp = s
      sm = s
      sp(1) = delta
      sm(1) = -delta
      tp = 0.0_dp
      tm = 0.0_dp
      kp = 0.0_dp
      km = 0.0_dp
      newp = state
      newm = state
      call call_capi(props, ntens, state, sp(1:ntens), tp(1:ntens), kp(1:ntens, 1:ntens), newp, psi, status_p, detail)
      call call_capi(props, ntens, state, sm(1:ntens), tm(1:ntens), km(1:ntens, 1:ntens), newm, psi, status_m, detail)
      if (status_p /= STATUS_OK .or. status_m /= STATUS_OK) return
      ncontinuity = ncontinuity + 1
      ! the closed crack's traction is formed from terms of the size of its intact stiffness
      ! (k + kc) s and C^f lambda, which nearly cancel near D = 1: its round-off scales with them,
      ! not with the (small) tangent there
      call coefficients_at(params, newm(SV_DAMAGE), c, dc, status_c)
      closed_scale = 0.0_dp
      if (status_c == STATUS_OK) closed_scale = max(c%k_n + c%kc_n, c%k_t + c%kc_t, abs(c%cf_t))
      ! a cracked point (D > 0) where the interpolant's mean opening coefficient dbar_N <= 0
      ! (tables/paper-small-d.dat between its rows at D = 0.09 and D = 1 has that) puts the open
      ! crack on the side s_N < 0: no law is continuous there; counted and reported, as
      ! stiffness_rises does
      if (status_c == STATUS_OK .and. params%model == MODEL_MICROMECHANICAL .and. newm(SV_DAMAGE) > 0.0_dp .and. &
         .not. (c%dbar_n > 0.0_dp)) then
         ninverted = ninverted + 1
         ncontinuity = ncontinuity - 1
         return
      end if
      ! Lipschitz over 2 delta, and round-off of the terms the tractions are formed from (K s, C^f lambda)
      bound = 2.0_dp*delta*max(maxval(abs(kp(1:ntens, 1:ntens))), maxval(abs(km(1:ntens, 1:ntens))))*real(ntens, dp) &
         + ROUNDOFF*max(kscale, closed_scale)*(sum(abs(s(1:ntens))) + sum(abs(state(2:3))) + sum(abs(newp(2:3))) &
         + sum(abs(newm(2:3))))
      write (detail, '(a,es12.4,a,es12.4,a,2es12.4,a,2es12.4)') 'by ', maxval(abs(tp(1:ntens) - tm(1:ntens))), &
         ' (bound ', bound, '), D ', newp(1), newm(1), ' regime ', newp(4), newm(4)
      call check(maxval(abs(tp(1:ntens) - tm(1:ntens))) <= bound, where//' (continuity at s_N = 0)', &
         'the traction jumps across s_N = 0 '//trim(detail))
   end subroutine continuity_at_zero

   ! ======================================================================================
   ! part 2
   ! ======================================================================================

   !> Break one data line of `lines` (those for which `data(i)`): a field replaced by a token that
   !> is no number, deleted, or text appended; `separator` joins the fields again. Returns the
   !> line number broken.
   integer function break_one_line(lines, data, separator) result(broken)
      character(len=*), intent(inout) :: lines(:)
      logical, intent(in) :: data(:)
      character(len=*), intent(in) :: separator
      character(len=*), parameter :: JUNK(12) = [character(len=8) :: 'abc', '1-2', '1+2', '2*0.01', '1.2.3', &
         '--1', '1e', 'e5', '+-1', '0.5x', 'nan', '1e999']
      character(len=64) :: fields(32)
      integer :: candidates(size(lines)), n, nf, f, i, how
      character(len=len(lines)) :: joined
      n = 0
      do i = 1, size(lines)
         if (data(i)) then
            n = n + 1
            candidates(n) = i
         end if
      end do
      broken = candidates(pick(1, n))
      call split(lines(broken), fields, nf)
      how = pick(1, 3)
      f = pick(1, nf)
      select case (how)
      case (1)
         fields(f) = JUNK(pick(1, size(JUNK)))
      case (2)
         fields(f:nf - 1) = fields(f + 1:nf)
         nf = nf - 1
      case (3)
         nf = nf + 1
         fields(nf) = JUNK(pick(1, 10))
      end select
      joined = ''
      do i = 1, nf
         if (i == 1) then
            joined = trim(fields(i))
         else
            joined = trim(joined)//separator//trim(fields(i))
         end if
      end do
      lines(broken) = joined
   end function break_one_line

   !> The blank-separated fields of a line.
   subroutine split(line, fields, n)
      character(len=*), intent(in) :: line
      character(len=*), intent(out) :: fields(:)
      integer, intent(out) :: n
      integer :: i, start
      n = 0
      i = 1
      do while (i <= len_trim(line) .and. n < size(fields))
         if (line(i:i) == ' ') then
            i = i + 1
            cycle
         end if
         start = i
         do while (i <= len_trim(line))
            if (line(i:i) == ' ') exit
            i = i + 1
         end do
         n = n + 1
         fields(n) = line(start:i - 1)
      end do
   end subroutine split

   !> Write lines to a file.
   subroutine write_lines(path, lines)
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: lines(:)
      integer :: unit, i
      open (newunit=unit, file=path, status='replace', action='write')
      do i = 1, size(lines)
         write (unit, '(a)') trim(lines(i))
      end do
      close (unit)
   end subroutine write_lines

   !> The lines of a file (at most 200, of at most 4096 characters: the test's own files).
   subroutine read_lines(path, lines)
      character(len=*), intent(in) :: path
      character(len=4096), allocatable, intent(out) :: lines(:)
      character(len=4096) :: buffer(200)
      integer :: unit, n, ios
      open (newunit=unit, file=path, status='old', action='read')
      n = 0
      do
         read (unit, '(a)', iostat=ios) buffer(n + 1)
         if (ios /= 0) exit
         n = n + 1
      end do
      close (unit)
      lines = buffer(1:n)
   end subroutine read_lines

   !> The refusal names the file and the line.
   subroutine expect_refused(refused, text, file, line, what)
      logical, intent(in) :: refused
      character(len=*), intent(in) :: text, file, what
      integer, intent(in) :: line
      call check(refused, what//' '//file//' (line '//int_to_string(line)//' broken)', 'accepted')
      if (refused) nbroken_refused = nbroken_refused + 1
      if (refused) call check(index(text, file//':'//int_to_string(line)//':') > 0, what//' '//file, &
         'the message does not name the file and line '//int_to_string(line)//': '//trim(text))
   end subroutine expect_refused

   subroutine broken_tables()
      character(len=4096), allocatable :: good(:)
      logical, allocatable :: data(:)
      integer :: i
      call read_lines(source_path('tables/paper-small-d.dat'), good)
      allocate (data(size(good)))
      do i = 1, size(good)
         data(i) = len_trim(good(i)) > 0 .and. good(i)(1:1) /= '#'
      end do
      call broken_loader_files(good, data, 'fuzz_table_', '.dat', 'RVE table', load_custom_table)
   end subroutine broken_tables

   subroutine broken_rcurves()
      character(len=4096) :: good(6)
      integer :: k
      good = [character(len=4096) :: '# D G_cI G_cII (N/mm)', '0.0 0.005 0.0085', '0.25 0.006 0.009', &
         '0.5 0.007 0.0095', '0.75 0.008 0.01', '1.0 0.009 0.011']
      call broken_loader_files(good, [.false., (.true., k=1, 5)], 'fuzz_rcurve_', '.txt', 'R-curve', load_rcurve)
   end subroutine broken_rcurves

   !> NBROKEN copies of `good`, each broken at one of its data lines, through a start-up loader.
   subroutine broken_loader_files(good, data, stem, extension, what, loader)
      character(len=*), intent(in) :: good(:)
      logical, intent(in) :: data(:)
      character(len=*), intent(in) :: stem, extension, what
      procedure(file_loader) :: loader
      character(len=4096), allocatable :: lines(:)
      integer :: i, line
      allocate (lines(size(good)))
      do i = 1, NBROKEN
         lines = good
         line = break_one_line(lines, data, ' ')
         call expect_broken_refused(lines, line, stem//int_to_string(i)//extension, what, loader)
      end do
   end subroutine broken_loader_files

   !> Write `lines` (broken at `line`) to scratch file `name` and read it with `loader`: it must
   !> be refused with a message naming the file and the line.
   subroutine expect_broken_refused(lines, line, name, what, loader)
      character(len=*), intent(in) :: lines(:), name, what
      integer, intent(in) :: line
      procedure(file_loader) :: loader
      character(len=:), allocatable :: path
      integer :: status
      path = scratch_path(name)
      call write_lines(path, lines)
      call loader(path, status, message)
      call expect_refused(status /= STATUS_OK, message, path, line, what)
   end subroutine expect_broken_refused

   subroutine broken_histories()
      character(len=4096) :: good(6)
      character(len=4096), allocatable :: lines(:)
      integer :: i, line, k
      good = [character(len=4096) :: '# t  s_T  s_N', '0  0  0', '1  0.001  0.0005', '2  0.002  -0.001', &
         '3  -0.001  0.003', '4  0  0']
      do i = 1, NBROKEN
         lines = good
         line = break_one_line(lines, [.false., (.true., k=1, 5)], '  ')
         call expect_broken_refused(lines, line, 'fuzz_history_'//int_to_string(i)//'.txt', 'history', driver_file_loader)
      end do
   end subroutine broken_histories

   !> Case files: a value of a real entry made text, or an entry given twice.
   subroutine broken_cases()
      character(len=4096) :: good(17)
      character(len=4096), allocatable :: lines(:)
      character(len=*), parameter :: JUNK(6) = [character(len=8) :: 'abc', '1-2', '1+2', '2*0.01', '1.2.3', '--1']
      integer :: i, line, eq
      good = [character(len=4096) :: '! a valid case of interphase-point', '&material', "  model = 'simplified'", &
         "  damage_law = 'displacement'", '  mu = 0.75', '  s0_n = 0.00044', '  sf_n = 0.04', '  s0_t = 0.00072', &
         '  sf_t = 0.06', '  k_n = 482.69742679680568', '  k_t = 198.75776397515528', '/', '&loading', &
         "  history = 'fuzz_case_history.txt'", '  increments = 10', "  output = 'fuzz_case.csv'", '/']
      do i = 1, NBROKEN
         lines = good
         line = pick(5, 11)
         if (uniform() < 0.7_dp) then
            eq = index(lines(line), '=')
            lines(line) = lines(line)(1:eq)//' '//JUNK(pick(1, size(JUNK)))
         else
            ! the entry again on the next line: refused there
            lines = [lines(1:line), lines(line:)]
            line = line + 1
         end if
         call expect_broken_refused(lines, line, 'fuzz_case_'//int_to_string(i)//'.nml', 'case file', driver_file_loader)
      end do
   end subroutine broken_cases

end program test_fuzz
