!> The UMAT's eight paths, the simplified and the micromechanical model with the
!> displacement-driven law (interphase_umat_simplified, interphase_umat_micromechanical) and with
!> the fracture-mechanics law (interphase_umat_simplified_fracture,
!> interphase_umat_micromechanical_fracture), each for the 2-D cohesive element and, the same
!> names with _3d, for the 3-D one, against its general path, bit for bit, over many random
!> materials, histories and host inputs, half of them on the 2-D element, half on the 3-D one.
!>
!> Every call is made twice from the same inputs: with the material's PROPS without options
!> (NPROPS = 9 for the simplified model, 8 for the micromechanical one, 13 and 12 with the
!> fracture law, a 2-D or 3-D cohesive element: the calls the paths may take) and with the same
!> PROPS followed by the growth-slip option constant at its default, 0 (NPROPS one more: the same
!> material, which only the general path serves). STRESS, DDSDDE, STATEV (every slot of NSTATV),
!> SSE, SPD and PNEWDT, and the message the call reports (its count, severity and text), must
!> agree bit for bit. Each path is also asked directly which calls it takes: every call the
!> general path accepts for a material and element a path is for (its model and law, no options,
!> mu, G_cI and G_cII not -0), but for a crack that closes within the increment (closes_within:
!> the general path forms its start slip), must be that path's, and the other element's path
!> must take none.
!>
!> Materials: half simplified, half micromechanical (the built-in table, or the custom table: the
!> paper's, loaded from the source tree after part 0); half with the displacement-driven law,
!> half with the fracture law (initial crack D0 mostly 1e-4 to 0.5, sometimes 1e-30 to 1e-5 or
!> within 1e-15 of 1; the constant R-curve with G_cI, G_cII from 0.03 to 30 times K s0^2, the
!> equivalent R-curve, or, after part 0, the tabulated R-curve of a file written here, which
!> covers D up to 0.9 only, with s0 then drawn to suit its toughness).
!> Part 0, the micromechanical model on the custom table and the fracture law on the tabulated
!> R-curve before either is loaded: refused by both.
!> Part 1, histories: NMATERIALS random materials (mu exactly 0, tiny or up to 1.5; s0 and sf
!> over three decades with sf/s0 from 1 + 2 eps to 100; K_N, K_T over six decades), each with a
!> random history of NSTEPS steps built from segments that reach every regime: intact loading,
!> damage growth, open, closed stick and slip, shear reversals (a slip much larger than the
!> result: the return mapping's second step), holds and round-off-sized steps after a slip (the
!> slip onset's round-off bound, docs/theory.md 'Slip onset'), closing at the slip, breaking to
!> D = 1, and on the 3-D element shear in any direction, turned from the current one, or along an
!> axis (the other component +0 or -0). The 3-D histories must reach slip in both components.
!> Part 2, single calls from random incoming states: D in {+0, -0, 1, 1 - ulp, random}, slips,
!> separations and increments (on the 3-D element a shear component sometimes +0 or -0),
!> regime codes, STRESS, SSE and SPD, PNEWDT as Abaqus (large) and CalculiX (-1) pass it,
!> NSTATV 4 to 8 with the slots beyond 4 random (left alone by both paths).
!> Part 3, refused calls: one input of a valid call spoilt (NaN, Inf or out of range STRAN,
!> DSTRAN, STRESS, SSE, SPD; a separation beyond 1e20 mm; STATEV's D, slip or regime; NSTATV;
!> NDI, NSHR, NTENS; each PROPS value, -0 for mu and the table selector included; the fracture law's
!> D0, R-curve selector and G_c, -0 included): both report the same, and leave the same.
!>
!> A failure prints the material, the step and what differed; the program ends with exit
!> status 1. It prints what it covered.
program test_umat_simplified_path
   use, intrinsic :: iso_fortran_env, only: int64, output_unit, error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
   use interphase_kinds, only: dp
   use interphase_layout, only: NSTATV_REQUIRED, SV_DAMAGE, SV_SLIP_1, SV_SLIP_2, SV_REGIME, REGIME_INTACT, &
      REGIME_OPEN, REGIME_STICK, REGIME_SLIP
   use interphase_adapter_calls, only: call_umat_element
   use interphase_kernel, only: closes_within
   use interphase_umat_simplified, only: simplified_cohesive_path => cohesive_path
   use interphase_umat_micromechanical, only: micromechanical_cohesive_path => cohesive_path
   use interphase_umat_simplified_fracture, only: simplified_fracture_path => cohesive_path
   use interphase_umat_micromechanical_fracture, only: micromechanical_fracture_path => cohesive_path
   use interphase_umat_simplified_3d, only: simplified_cohesive_path_3d => cohesive_path
   use interphase_umat_micromechanical_3d, only: micromechanical_cohesive_path_3d => cohesive_path
   use interphase_umat_simplified_fracture_3d, only: simplified_fracture_path_3d => cohesive_path
   use interphase_umat_micromechanical_fracture_3d, only: micromechanical_fracture_path_3d => cohesive_path
   use interphase_micro_coefficients, only: load_custom_table
   use interphase_rcurve, only: load_rcurve
   use interphase_status, only: STATUS_OK, MESSAGE_LEN
   use interphase_test_support, only: source_path, scratch_path
   use host_recorder, only: recorder_reset, recorded_count, recorded_severity, recorded_message
   implicit none

   !> The paths' cohesive_path (interphase_umat_cohesive_path.inc), for a pointer to any of them.
   abstract interface
      pure subroutine cohesive_path_interface(nprops, props, ndi, nshr, ntens, nstatv, statev, stran, dstran, &
            stress, ddsdde, sse, spd, taken)
         import :: dp
         integer, intent(in) :: nprops, ndi, nshr, ntens, nstatv
         real(dp), intent(in) :: props(nprops)
         real(dp), intent(inout) :: statev(nstatv)
         real(dp), intent(in) :: stran(ntens), dstran(ntens)
         real(dp), intent(inout) :: stress(ntens)
         real(dp), intent(inout) :: ddsdde(ntens, ntens)
         real(dp), intent(inout) :: sse, spd
         logical, intent(out) :: taken
      end subroutine cohesive_path_interface
   end interface

   integer, parameter :: NMATERIALS = 12000, NSTEPS = 60, NSINGLE = 80000, NSPOILT = 24000, NUNLOADED = 200
   !> The largest NSTATV the test passes.
   integer, parameter :: NSTATV_MAX = 8
   !> The most PROPS without options (the simplified model with the fracture law).
   integer, parameter :: NP_MAX = 13
   !> The paths, by the NPROPS of their materials: 9, 8, 13, 12.
   integer, parameter :: PATH_NP(4) = [9, 8, 13, 12]
   character(len=*), parameter :: PATH_NAME(4) = [character(len=33) :: 'simplified, displacement law', &
      'micromechanical, displacement law', 'simplified, fracture law', 'micromechanical, fracture law']
   !> The tabulated R-curve's file: D (-), G_cI, G_cII (N/mm per unit crack area), rising, covering
   !> D up to 0.9 only (a D0 beyond it, or a crack grown beyond it, is refused by both paths); and
   !> the toughness the tabulated materials' s0 is drawn for (N/mm).
   real(dp), parameter :: RCURVE_ROWS(3, 4) = reshape([0.0_dp, 0.005_dp, 0.0085_dp, 0.3_dp, 0.006_dp, 0.010_dp, &
      0.6_dp, 0.008_dp, 0.013_dp, 0.9_dp, 0.009_dp, 0.015_dp], [3, 4])
   real(dp), parameter :: RCURVE_GC(2) = [0.005_dp, 0.0085_dp]
   !> the micromechanical model's stiffness scale for G_c and s0 (MPa/mm): the paper's K_N, K_T,
   !> which the built-in table's stiffnesses are of the order of
   real(dp), parameter :: MICRO_K(2) = [544000.0_dp/1127.0_dp, 32000.0_dp/161.0_dp]

   !> Everything one UMAT call reads and writes that the test varies or compares.
   type :: call_type
      integer :: ndi = 1, nshr = 1, ntens = 2, nstatv = NSTATV_REQUIRED
      real(dp) :: stress(3) = 0.0_dp, ddsdde(3, 3) = 0.0_dp, statev(NSTATV_MAX) = 0.0_dp
      real(dp) :: sse = 0.0_dp, spd = 0.0_dp, pnewdt = 1.0e36_dp
      real(dp) :: stran(3) = 0.0_dp, dstran(3) = 0.0_dp
      ! what the call reported
      integer :: reported = 0, severity = 0
      character(len=1024) :: message = ''
   end type call_type

   integer(int64) :: seed = 20261206_int64
   integer :: nfailed = 0, ncalls = 0, nrefused = 0
   !> calls each path takes (asked directly, on a copy of the inputs), and calls the general path
   !> accepts that the path is for (its model and law, mu, G_cI, G_cII not -0; its element, 2-D
   !> or 3-D, the second index): each path must take all of them; calls a path took that were the
   !> other element's path's (none may be)
   integer :: ntaken(4, 2) = 0, ntakeable(4, 2) = 0, nwrong_element = 0
   !> the current material's NPROPS without options (9: simplified, 8: micromechanical, 13 and 12
   !> with the fracture law), and the stiffness scale (MPa/mm) of the random incoming STRESS
   integer :: np = 9
   real(dp) :: stiffness(2) = 1.0_dp
   !> the tabulated R-curve is loaded (part 0 is over): random materials may draw it
   logical :: rcurve_ready = .false.
   !> calls of each path's materials (PATH_NP's order), of the micromechanical model on the
   !> custom table, and of the fracture law on each R-curve (constant, equivalent, tabulated); of
   !> those, accepted
   integer :: nmodel(4) = 0, nmodel_ok(4) = 0, ncustom = 0, ncustom_ok = 0, nrcurve(3) = 0, nrcurve_ok(3) = 0
   integer :: status
   character(len=MESSAGE_LEN) :: message
   !> coverage: accepted steps of part 1 ending in each regime, growing, reaching D = 1, holds,
   !> reversals, round-off steps
   integer :: nregime(REGIME_INTACT:REGIME_SLIP) = 0, ngrowth = 0, nbroken = 0, nhold = 0, nreversal = 0, &
      nroundoff = 0, nclosing = 0, nsingle_ok = 0, ngrowth_fracture = 0, nbroken_fracture = 0
   !> coverage of the 3-D element: accepted steps of part 1 ending in slip with both slip
   !> components non-zero, steps whose shear direction turned (by more than 1e-3 rad) from the
   !> step before, and single calls with a shear component +0 or -0 (part 2)
   integer :: nslip_3d = 0, nturned_3d = 0, nzero_shear = 0
   integer :: imat, k, e, unit
   real(dp) :: props(NP_MAX)

   ! ---- part 0: the custom table and the tabulated R-curve before either is loaded --------------
   do k = 1, NUNLOADED
      props = random_props()
      props(1) = 2.0_dp
      props(2) = 1.0_dp
      props(8) = 1.0_dp
      np = 8
      call single_call(k, props)
   end do
   do k = 1, NUNLOADED
      props = random_props(tabulated=.true.)
      call single_call(k, props)
   end do
   call load_custom_table(source_path('tables/paper.dat'), status, message)
   if (status /= STATUS_OK) then
      write (error_unit, '(a)') 'test_umat_simplified_path: '//trim(message)
      error stop 1
   end if
   open (newunit=unit, file=scratch_path('path_test_rcurve.txt'), status='replace', action='write')
   write (unit, '(a)') '# D  G_cI  G_cII (N/mm per unit crack area)'
   write (unit, '(3es25.17)') RCURVE_ROWS
   close (unit)
   call load_rcurve(scratch_path('path_test_rcurve.txt'), status, message)
   if (status /= STATUS_OK) then
      write (error_unit, '(a)') 'test_umat_simplified_path: '//trim(message)
      error stop 1
   end if
   rcurve_ready = .true.

   ! ---- part 1: histories -----------------------------------------------------------------
   do imat = 1, NMATERIALS
      props = random_props()
      call run_history(imat, props)
   end do

   ! ---- part 2: single calls from random states --------------------------------------------
   do k = 1, NSINGLE
      props = random_props()
      call single_call(k, props)
   end do

   ! ---- part 3: refused calls ----------------------------------------------------------------
   do k = 1, NSPOILT
      props = random_props()
      call spoilt_call(k, props)
   end do

   write (output_unit, '(a,i0,a,i0,a)') 'test_umat_simplified_path: ', ncalls, ' calls compared (', nrefused, &
      ' refused by both)'
   write (output_unit, '(a,4(i0,a))') 'test_umat_simplified_path: histories: ', nregime(REGIME_INTACT), &
      ' intact, ', nregime(REGIME_OPEN), ' open, ', nregime(REGIME_STICK), ' stick, ', nregime(REGIME_SLIP), ' slip steps'
   write (output_unit, '(a,6(i0,a))') 'test_umat_simplified_path: ', ngrowth, ' growing, ', nbroken, &
      ' at D = 1, ', nreversal, ' reversals, ', nhold, ' holds, ', nroundoff, ' round-off steps, ', nclosing, &
      ' closings'
   write (output_unit, '(a,2(i0,a))') 'test_umat_simplified_path: fracture law: ', ngrowth_fracture, &
      ' growing, ', nbroken_fracture, ' at D = 1'
   write (output_unit, '(a,i0,a,i0,a)') 'test_umat_simplified_path: single calls: ', nsingle_ok, ' of ', NSINGLE, &
      ' accepted'
   write (output_unit, '(a,3(i0,a))') 'test_umat_simplified_path: 3-D element: ', nslip_3d, &
      ' slip steps with both slip components non-zero, ', nturned_3d, ' steps with the shear turned; ', &
      nzero_shear, ' single calls with a shear component +0 or -0'
   do k = 1, size(PATH_NP)
      write (output_unit, '(a,7(i0,a))') 'test_umat_simplified_path: '//trim(PATH_NAME(k))//' (NPROPS = ', &
         PATH_NP(k), '): ', nmodel(k), ' calls (', nmodel_ok(k), ' accepted), the 2-D path took ', ntaken(k, 1), &
         ' of the ', ntakeable(k, 1), ' it is for, the 3-D path ', ntaken(k, 2), ' of ', ntakeable(k, 2)
   end do
   write (output_unit, '(a,i0,a,i0,a)') 'test_umat_simplified_path: custom table: ', ncustom, ' calls (', &
      ncustom_ok, ' accepted)'
   write (output_unit, '(a,3(i0,a,i0,a))') 'test_umat_simplified_path: R-curves: constant ', nrcurve(1), ' calls (', &
      nrcurve_ok(1), ' accepted), equivalent ', nrcurve(2), ' (', nrcurve_ok(2), '), tabulated ', nrcurve(3), ' (', &
      nrcurve_ok(3), ')'
   write (output_unit, '(a,i0,a)') 'test_umat_simplified_path: ', nfailed, ' differences'
   if (nfailed > 0) error stop 1
   ! (every accepted call a path is for is the path's: a decision that stopped taking calls would
   ! leave the test comparing the general path with itself)
   do k = 1, size(PATH_NP)
      do e = 1, 2
         if (ntaken(k, e) /= ntakeable(k, e) .or. ntaken(k, e) < NMATERIALS/8) then
            write (error_unit, '(a,i0,a)') 'test_umat_simplified_path: the path for the '//trim(PATH_NAME(k))// &
               ', NTENS = ', e + 1, ', did not take every call it should'
            error stop 1
         end if
      end do
   end do
   ! (the 3-D element's histories reach what a 2-D one cannot: a generator that lost the second
   ! shear component would compare the 3-D paths on 2-D loading only)
   if (nslip_3d < NMATERIALS/10 .or. nturned_3d < NMATERIALS .or. nzero_shear < NSINGLE/20) then
      write (error_unit, '(a)') 'test_umat_simplified_path: the 3-D element''s slip in two components, turning '// &
         'shear or zero shear components were not reached'
      error stop 1
   end if
   if (nwrong_element > 0) then
      write (error_unit, '(a,i0,a)') 'test_umat_simplified_path: ', nwrong_element, &
         ' calls taken by the path of the other element'
      error stop 1
   end if

contains

   ! ---- random numbers (the fuzz test's generator: the same cases with every compiler) -------

   real(dp) function uniform()
      seed = ieor(seed, ishft(seed, 13))
      seed = ieor(seed, ishft(seed, -7))
      seed = ieor(seed, ishft(seed, 17))
      uniform = real(ishft(seed, -11), dp)*2.0_dp**(-53)
   end function uniform

   real(dp) function between(lo, hi)
      real(dp), intent(in) :: lo, hi
      between = lo + (hi - lo)*uniform()
   end function between

   integer function pick(lo, hi)
      integer, intent(in) :: lo, hi
      pick = min(hi, lo + int(uniform()*real(hi - lo + 1, dp)))
   end function pick

   !> a random sign
   real(dp) function sgn()
      sgn = merge(1.0_dp, -1.0_dp, uniform() < 0.5_dp)
   end function sgn

   !> a random sign times a random magnitude in [lo, hi], drawn in that order (each statement of
   !> this program draws once at most: the order of function calls within an expression is the
   !> compiler's, and every build must see the same cases)
   real(dp) function signed(lo, hi)
      real(dp), intent(in) :: lo, hi
      real(dp) :: r
      r = sgn()
      signed = r*between(lo, hi)
   end function signed

   !> true with probability p
   logical function chance(p)
      real(dp), intent(in) :: p
      chance = uniform() < p
   end function chance

   ! ---- materials and calls -------------------------------------------------------------------

   !> The PROPS of a random material: the simplified model's nine, or (half of them) the
   !> micromechanical model's eight, with the displacement-driven law, or (half of them) with the
   !> fracture law's four constants after them (13 or 12); the values beyond np unused. Sets np and
   !> the stiffness scale. `tabulated`: the fracture law on the tabulated R-curve (else drawn only
   !> once it is loaded).
   function random_props(tabulated) result(p)
      logical, intent(in), optional :: tabulated
      real(dp) :: p(NP_MAX)
      real(dp) :: r, k_scale(2)
      logical :: micro, fracture
      integer :: nm, rcurve
      micro = chance(0.5_dp)
      fracture = chance(0.5_dp)
      if (present(tabulated)) fracture = .true.
      p(1) = 1.0_dp
      p(2) = 1.0_dp
      r = uniform()
      if (r < 0.1_dp) then
         p(3) = 0.0_dp
      else if (r < 0.2_dp) then
         p(3) = 10.0_dp**between(-20.0_dp, -10.0_dp)
      else
         p(3) = between(0.0_dp, 1.5_dp)
      end if
      p(4) = 10.0_dp**between(-4.0_dp, -1.0_dp)
      p(5) = sf_from(p(4))
      p(6) = 10.0_dp**between(-4.0_dp, -1.0_dp)
      p(7) = sf_from(p(6))
      p(8) = 10.0_dp**between(0.0_dp, 6.0_dp)
      p(9) = 10.0_dp**between(0.0_dp, 6.0_dp)
      stiffness = p(8:9)
      p(10:NP_MAX) = 0.0_dp
      np = 9
      k_scale = p(8:9)
      if (micro) then
         ! the built-in table mostly, the custom one (once loaded) in a third of them
         p(1) = 2.0_dp
         p(8) = merge(1.0_dp, 0.0_dp, chance(1.0_dp/3.0_dp))
         np = 8
         k_scale = MICRO_K
      end if
      if (.not. fracture) return
      ! the fracture law: PROPS(nm + 1:nm + 4) = D0, the R-curve selector, G_cI, G_cII (N/mm)
      p(2) = 2.0_dp
      nm = np
      np = nm + 4
      r = uniform()
      if (r < 0.05_dp) then
         ! (tiny, down to the smallest D0 the PROPS checks accept, D_MIN_CRACK = 1e-30; the spoilt
         ! calls try below it)
         p(nm + 1) = 10.0_dp**between(-30.0_dp, -5.0_dp)
      else if (r < 0.1_dp) then
         p(nm + 1) = 1.0_dp - 10.0_dp**between(-15.0_dp, -2.0_dp)
      else
         p(nm + 1) = 10.0_dp**between(-4.0_dp, log10(0.5_dp))
      end if
      r = uniform()
      if (r < 0.45_dp) then
         rcurve = 1
      else if (r < 0.7_dp .or. .not. rcurve_ready) then
         rcurve = 2
      else
         rcurve = 3
      end if
      if (present(tabulated)) rcurve = 3
      p(nm + 2) = real(rcurve, dp)
      if (rcurve == 1) then
         ! G_c from 0.03 to 30 times K s0^2: cracks that grow at once, later, or only when broken
         p(nm + 3) = k_scale(1)*p(4)**2*10.0_dp**between(-1.5_dp, 1.5_dp)
         p(nm + 4) = k_scale(2)*p(6)**2*10.0_dp**between(-1.5_dp, 1.5_dp)
      else if (rcurve == 3) then
         ! s0 drawn for the file's toughness instead (the same spread of G_c/(K s0^2))
         p(4) = sqrt(RCURVE_GC(1)/k_scale(1)*10.0_dp**between(-1.5_dp, 1.5_dp))
         p(5) = sf_from(p(4))
         p(6) = sqrt(RCURVE_GC(2)/k_scale(2)*10.0_dp**between(-1.5_dp, 1.5_dp))
         p(7) = sf_from(p(6))
      end if
   end function random_props

   !> sf > s0: mostly a ratio up to 100, sometimes s0 (1 + 2 eps)
   real(dp) function sf_from(s0) result(sf)
      real(dp), intent(in) :: s0
      if (uniform() < 0.05_dp) then
         sf = s0*(1.0_dp + 2.0_dp*epsilon(1.0_dp))
      else
         sf = s0*(1.0_dp + 10.0_dp**between(-6.0_dp, 2.0_dp))
      end if
   end function sf_from

   !> One call of the UMAT with PROPS p (their size: NPROPS).
   subroutine call_umat(c, p)
      type(call_type), intent(inout) :: c
      real(dp), intent(in) :: p(:)
      integer :: n
      n = c%ntens
      call recorder_reset()
      call call_umat_element(c%stress(1:n), c%statev(1:c%nstatv), c%ddsdde(1:n, 1:n), c%sse, c%spd, c%stran(1:n), &
         c%dstran(1:n), c%ndi, c%nshr, p, c%pnewdt, 'PATH_TEST')
      c%reported = recorded_count
      c%severity = recorded_severity
      c%message = recorded_message
   end subroutine call_umat

   !> The call with PROPS p(1:np) and with p(1:np) and the default growth-slip option (NPROPS one
   !> more): on return `c` holds the first's results; a difference is reported as a failure.
   subroutine compare_paths(c, p, where)
      type(call_type), intent(inout) :: c
      real(dp), intent(in) :: p(NP_MAX)
      character(len=*), intent(in) :: where
      type(call_type) :: reference
      character(len=16) :: from, to
      integer :: m, rcurve
      reference = c
      call count_taken(c, p(1:np))
      call call_umat(c, p(1:np))
      call call_umat(reference, [p(1:np), 0.0_dp])
      ! (a refusal of the constants' count names NPROPS: the reference's is one more)
      write (from, '(a,i0,a)') 'NPROPS = ', np + 1, ' '
      write (to, '(a,i0,a)') 'NPROPS = ', np, ' '
      call replace_text(reference%message, trim(from)//' ', trim(to)//' ')
      ncalls = ncalls + 1
      if (c%reported > 0) nrefused = nrefused + 1
      m = findloc(PATH_NP, np, dim=1)
      nmodel(m) = nmodel(m) + 1
      if (c%reported == 0) nmodel_ok(m) = nmodel_ok(m) + 1
      if ((np == 8 .or. np == 12) .and. same_bits([p(1), p(8)], [2.0_dp, 1.0_dp])) then
         ncustom = ncustom + 1
         if (c%reported == 0) ncustom_ok = ncustom_ok + 1
      end if
      if (np >= 12 .and. same_bits([p(2)], [2.0_dp])) then
         rcurve = findloc([1.0_dp, 2.0_dp, 3.0_dp], p(np - 2), dim=1)
         if (rcurve > 0) then
            nrcurve(rcurve) = nrcurve(rcurve) + 1
            if (c%reported == 0) nrcurve_ok(rcurve) = nrcurve_ok(rcurve) + 1
         end if
      end if
      if (.not. same_call(c, reference)) then
         nfailed = nfailed + 1
         if (nfailed <= 20) then
            write (error_unit, '(a)') 'test_umat_simplified_path: '//where//': the paths differ'
            write (error_unit, '(a,13es25.17)') '  PROPS ', p(1:np)
            write (error_unit, '(a,i0)') '  NTENS ', c%ntens
            write (error_unit, '(a,3es25.17,a,3es25.17)') '  STRESS ', c%stress, ' general ', reference%stress
            write (error_unit, '(a,9es25.17)') '  DDSDDE ', c%ddsdde
            write (error_unit, '(a,9es25.17)') '  general', reference%ddsdde
            write (error_unit, '(a,4es25.17)') '  STATEV ', c%statev(1:4)
            write (error_unit, '(a,4es25.17)') '  general', reference%statev(1:4)
            write (error_unit, '(a,3es25.17)') '  SSE, SPD, PNEWDT ', c%sse, c%spd, c%pnewdt
            write (error_unit, '(a,3es25.17)') '  general          ', reference%sse, reference%spd, reference%pnewdt
            write (error_unit, '(a,i0,a)') '  reported ', c%reported, ': '//trim(c%message)
            write (error_unit, '(a,i0,a)') '  general  ', reference%reported, ': '//trim(reference%message)
         end if
      end if
   end subroutine compare_paths

   !> Whether the path for the material's NPROPS without options (PATH_NP) and the call's element
   !> (NTENS = 3: the 3-D path, else the 2-D one) takes the call (on a copy of its inputs), counted
   !> against the calls the general path accepts on that cohesive element for the material that
   !> path is for (its model and law selectors; mu, and with the fracture law G_cI and G_cII, not
   !> -0: accepted by the checks, not by the paths' one-pass test), the ones it must take (its
   !> decision: interphase_umat_cohesive_path.inc); and that the other element's path does not take it.
   subroutine count_taken(c, p)
      type(call_type), intent(in) :: c
      real(dp), intent(in) :: p(:)
      type(call_type) :: general
      logical :: taken, its_material
      integer :: m, e
      real(dp), parameter :: SELECTORS(2, 4) = reshape([1.0_dp, 1.0_dp, 2.0_dp, 1.0_dp, 1.0_dp, 2.0_dp, &
         2.0_dp, 2.0_dp], [2, 4])
      m = findloc(PATH_NP, size(p), dim=1)
      e = merge(2, 1, c%ntens == 3)
      taken = path_takes(m, e, c, p)
      if (taken) ntaken(m, e) = ntaken(m, e) + 1
      if (path_takes(m, 3 - e, c, p)) nwrong_element = nwrong_element + 1
      general = c
      call call_umat(general, [p, 0.0_dp])
      its_material = same_bits(p(1:2), SELECTORS(:, m)) .and. .not. minus_zero(p(3))
      if (m >= 3) its_material = its_material .and. .not. (minus_zero(p(size(p) - 1)) .or. minus_zero(p(size(p))))
      ! (a crack that closes within the increment is the general path's: its start slip)
      if (general%reported == 0 .and. c%ndi == 1 .and. c%nshr == c%ntens - 1 .and. c%ntens == e + 1 &
         .and. its_material .and. .not. closes_within(c%statev(SV_REGIME), c%statev(SV_DAMAGE), c%stran(1), &
         c%stran(1) + c%dstran(1))) ntakeable(m, e) = ntakeable(m, e) + 1
   end subroutine count_taken

   !> Whether path m (PATH_NP's order) for element e (1: 2-D, 2: 3-D) takes the call, asked on a
   !> copy of its inputs.
   logical function path_takes(m, e, c, p) result(taken)
      integer, intent(in) :: m, e
      type(call_type), intent(in) :: c
      real(dp), intent(in) :: p(:)
      type(call_type) :: copy
      real(dp) :: ddsdde(c%ntens, c%ntens)   ! (contiguous: no temporary)
      procedure(cohesive_path_interface), pointer :: path
      integer :: n
      select case (m + 4*(e - 1))
      case (1)
         path => simplified_cohesive_path
      case (2)
         path => micromechanical_cohesive_path
      case (3)
         path => simplified_fracture_path
      case (4)
         path => micromechanical_fracture_path
      case (5)
         path => simplified_cohesive_path_3d
      case (6)
         path => micromechanical_cohesive_path_3d
      case (7)
         path => simplified_fracture_path_3d
      case default
         path => micromechanical_fracture_path_3d
      end select
      copy = c
      n = copy%ntens
      ddsdde = c%ddsdde(1:n, 1:n)
      call path(size(p), p, copy%ndi, copy%nshr, n, copy%nstatv, copy%statev(1:copy%nstatv), copy%stran(1:n), &
         copy%dstran(1:n), copy%stress(1:n), ddsdde, copy%sse, copy%spd, taken)
   end function path_takes

   !> x is -0.
   pure logical function minus_zero(x)
      real(dp), intent(in) :: x
      minus_zero = transfer(x, 0_int64) == transfer(-0.0_dp, 0_int64)
   end function minus_zero

   !> text with its first `from` replaced by `to`.
   subroutine replace_text(text, from, to)
      character(len=*), intent(inout) :: text
      character(len=*), intent(in) :: from, to
      integer :: at
      at = index(text, from)
      if (at > 0) text = text(1:at - 1)//to//text(at + len(from):)
   end subroutine replace_text

   !> Every output of the two calls, bit for bit.
   logical function same_call(a, b)
      type(call_type), intent(in) :: a, b
      same_call = same_bits(a%stress, b%stress) .and. same_bits(reshape(a%ddsdde, [9]), reshape(b%ddsdde, [9])) &
         .and. same_bits(a%statev, b%statev) .and. same_bits([a%sse, a%spd, a%pnewdt], [b%sse, b%spd, b%pnewdt]) &
         .and. a%reported == b%reported .and. a%severity == b%severity .and. a%message == b%message
   end function same_call

   pure logical function same_bits(a, b)
      real(dp), intent(in) :: a(:), b(:)
      same_bits = all(transfer(a, 0_int64, size(a)) == transfer(b, 0_int64, size(b)))
   end function same_bits

   ! ---- part 1 ----------------------------------------------------------------------------

   !> A random history of one point on a random element (2-D or 3-D): segments of steps towards
   !> random targets (closed or open, within or beyond the strengths; on the 3-D element the shear
   !> in a random direction, or turned from the current one), reversals of the shear, holds,
   !> round-off-sized steps, a closing at the current shear, a break to D = 1.
   subroutine run_history(imat, p)
      integer, intent(in) :: imat
      real(dp), intent(in) :: p(NP_MAX)
      type(call_type) :: c
      real(dp) :: target(3), s(3), d_old, shear
      integer :: step, nseg, kind, i, n
      character(len=64) :: where

      call random_element(c)
      n = c%ntens
      c%nstatv = pick(NSTATV_REQUIRED, NSTATV_MAX)
      c%statev = 0.0_dp
      c%statev(NSTATV_REQUIRED + 1:) = [(between(-1.0_dp, 1.0_dp), i = NSTATV_REQUIRED + 1, NSTATV_MAX)]
      c%ddsdde = 0.0_dp
      step = 0
      do while (step < NSTEPS)
         s = c%stran
         target = 0.0_dp
         kind = pick(1, 9)
         ! (a break to D = 1 ends a point's interesting history: one segment in about forty)
         if (kind == 7) then
            if (uniform() > 0.2_dp) kind = 1
         end if
         nseg = pick(1, 6)
         select case (kind)
         case (1, 2, 9)  ! towards a random target, mostly closed, mostly within the strengths
            target(1) = merge(-1.0_dp, 1.0_dp, chance(0.7_dp))
            target(1) = target(1)*between(0.0_dp, 1.0_dp)
            target(1) = target(1)*(p(4) + between(0.0_dp, 0.6_dp)*(p(5) - p(4)))
            shear = signed(0.0_dp, 1.0_dp)*p(6)
            shear = shear + sign(between(0.0_dp, 0.6_dp)*(p(7) - p(6)), shear)
            target(2:n) = shear*shear_direction(c, s)
         case (3)        ! shear reversal at the current normal separation
            target = [s(1), -s(2:3)*between(0.0_dp, 1.5_dp)]
            nreversal = nreversal + 1
         case (4)        ! hold
            target = s
            nhold = nhold + 1
         case (5)        ! steps of round-off size
            target(1) = sgn()
            target(2) = sgn()
            target(3) = sgn()
            target = s + target*epsilon(1.0_dp)*max(abs(s), tiny(1.0_dp))*between(0.0_dp, 64.0_dp)
            nroundoff = nroundoff + 1
         case (6)        ! close (or open) at the current shear
            target = [-s(1) - sgn()*1.0e-3_dp*p(4), s(2:3)]
            nclosing = nclosing + 1
         case (7)        ! break: far beyond the strengths
            target(1) = signed(0.0_dp, 3.0_dp)*p(5)
            shear = signed(2.0_dp, 10.0_dp)*p(7)
            target(2:n) = shear*shear_direction(c, s)
         case default    ! small cycles about the current point (stick and slip onset)
            shear = signed(0.0_dp, 0.05_dp)*p(6)
            target(1:n) = s(1:n)
            target(2:n) = target(2:n) + shear*shear_direction(c, s)
         end select
         if (n == 2) target(3) = 0.0_dp
         do i = 1, nseg
            step = step + 1
            c%dstran(1:n) = s(1:n) + (target(1:n) - s(1:n))*(real(i, dp)/real(nseg, dp)) - c%stran(1:n)
            d_old = c%statev(SV_DAMAGE)
            write (where, '(a,i0,a,i0,a,i0)') 'material ', imat, ', NTENS ', n, ', step ', step
            call compare_paths(c, p, trim(where))
            if (c%reported > 0) exit
            if (n == 3) then
               if (nint(c%statev(SV_REGIME)) == REGIME_SLIP .and. abs(c%statev(SV_SLIP_1)) > 0.0_dp &
                  .and. abs(c%statev(SV_SLIP_2)) > 0.0_dp) nslip_3d = nslip_3d + 1
               if (turned(c%stran(2:3), c%dstran(2:3))) nturned_3d = nturned_3d + 1
            end if
            c%stran(1:n) = c%stran(1:n) + c%dstran(1:n)
            nregime(nint(c%statev(SV_REGIME))) = nregime(nint(c%statev(SV_REGIME))) + 1
            if (c%statev(SV_DAMAGE) > d_old) ngrowth = ngrowth + 1
            if (c%statev(SV_DAMAGE) >= 1.0_dp) nbroken = nbroken + 1
            if (np >= 12) then
               if (c%statev(SV_DAMAGE) > d_old) ngrowth_fracture = ngrowth_fracture + 1
               if (c%statev(SV_DAMAGE) >= 1.0_dp) nbroken_fracture = nbroken_fracture + 1
            end if
         end do
      end do
   end subroutine run_history

   !> The element of a call: the 2-D cohesive element (NSHR = 1) or, half of the time, the 3-D
   !> one (NSHR = 2).
   subroutine random_element(c)
      type(call_type), intent(inout) :: c
      c%ndi = 1
      c%nshr = merge(2, 1, chance(0.5_dp))
      c%ntens = 1 + c%nshr
   end subroutine random_element

   !> A unit direction for a shear target (its size, NSHR): 1 on the 2-D element; on the 3-D one a
   !> random direction, or the current shear's turned by a random angle of up to 90 degrees (in
   !> four of ten draws), or the current shear's itself (two of ten; a random one at zero shear),
   !> or an axis with the other component +0 or -0 (one of ten).
   function shear_direction(c, s) result(dir)
      type(call_type), intent(in) :: c
      real(dp), intent(in) :: s(3)
      real(dp) :: dir(c%nshr)
      real(dp) :: angle, r, size_now
      real(dp), parameter :: PI = acos(-1.0_dp)
      if (c%nshr == 1) then
         dir = 1.0_dp
         return
      end if
      r = uniform()
      size_now = hypot(s(2), s(3))
      angle = between(-PI, PI)
      if (r < 0.6_dp .and. size_now > 0.0_dp) then
         angle = atan2(s(3), s(2))
         if (r < 0.4_dp) angle = angle + between(-0.5_dp*PI, 0.5_dp*PI)
      end if
      dir = [cos(angle), sin(angle)]
      if (r > 0.9_dp) then
         ! (one draw a statement: the order of function calls in an expression is the compiler's)
         dir(1) = sgn()
         dir(2) = sgn()
         dir(2) = dir(2)*0.0_dp
         if (chance(0.5_dp)) dir = dir([2, 1])
      end if
   end function shear_direction

   !> The step ds turns the shear s (both the 3-D element's two components): the angle between
   !> s and s + ds exceeds 1e-3 rad.
   pure logical function turned(s, ds)
      real(dp), intent(in) :: s(2), ds(2)
      real(dp) :: e(2), cross, dot
      e = s + ds
      cross = s(1)*e(2) - s(2)*e(1)
      dot = s(1)*e(1) + s(2)*e(2)
      turned = abs(atan2(cross, dot)) > 1.0e-3_dp .and. hypot(s(1), s(2)) > 0.0_dp .and. hypot(e(1), e(2)) > 0.0_dp
   end function turned

   ! ---- part 2 ----------------------------------------------------------------------------

   !> A random admissible incoming state and increment for material p on a random element.
   subroutine random_state(c, p)
      type(call_type), intent(out) :: c
      real(dp), intent(in) :: p(NP_MAX)
      real(dp) :: r
      integer :: i
      call random_element(c)
      c%nstatv = pick(NSTATV_REQUIRED, NSTATV_MAX)
      r = uniform()
      if (r < 0.15_dp) then
         c%statev(SV_DAMAGE) = 0.0_dp
      else if (r < 0.2_dp) then
         c%statev(SV_DAMAGE) = -0.0_dp
      else if (r < 0.3_dp) then
         c%statev(SV_DAMAGE) = 1.0_dp
      else if (r < 0.35_dp) then
         c%statev(SV_DAMAGE) = nearest(1.0_dp, -1.0_dp)
      else
         c%statev(SV_DAMAGE) = uniform()
      end if
      c%statev(SV_SLIP_1) = 0.0_dp
      if (chance(0.7_dp)) c%statev(SV_SLIP_1) = signed(0.0_dp, 3.0_dp)*p(7)
      c%statev(SV_SLIP_2) = 0.0_dp
      if (chance(0.2_dp)) c%statev(SV_SLIP_2) = signed(0.0_dp, 3.0_dp)*p(7)
      c%statev(SV_REGIME) = real(pick(REGIME_INTACT, REGIME_SLIP), dp)
      c%statev(NSTATV_REQUIRED + 1:) = [(between(-1.0_dp, 1.0_dp), i = NSTATV_REQUIRED + 1, NSTATV_MAX)]
      c%stran(1) = signed(0.0_dp, 2.0_dp)*p(5)
      c%stran(2) = signed(0.0_dp, 2.0_dp)*p(7)
      c%dstran(1) = signed(0.0_dp, 0.5_dp)*p(5)
      c%dstran(2) = signed(0.0_dp, 0.5_dp)*p(7)
      c%stress(1) = signed(0.0_dp, 1.0_dp)*stiffness(1)*p(5)
      c%stress(2) = signed(0.0_dp, 1.0_dp)*stiffness(2)*p(7)
      if (c%ntens == 3) then
         c%stran(3) = signed(0.0_dp, 2.0_dp)*p(7)
         c%dstran(3) = signed(0.0_dp, 0.5_dp)*p(7)
         c%stress(3) = signed(0.0_dp, 1.0_dp)*stiffness(2)*p(7)
      end if
      if (chance(0.1_dp)) c%dstran = 0.0_dp
      ! a shear component +0 or -0 (the separation, its increment, the slip: each or all)
      if (chance(0.15_dp)) then
         i = pick(2, c%ntens)
         if (chance(0.6_dp)) c%stran(i) = sgn()*0.0_dp
         if (chance(0.6_dp)) c%dstran(i) = sgn()*0.0_dp
         if (chance(0.6_dp)) c%statev(SV_SLIP_1 + i - 2) = sgn()*0.0_dp
         nzero_shear = nzero_shear + 1
      end if
      c%sse = between(0.0_dp, 10.0_dp)
      c%spd = between(-1.0_dp, 10.0_dp)
      c%pnewdt = merge(1.0e36_dp, -1.0_dp, chance(0.8_dp))
      c%ddsdde = between(-1.0_dp, 1.0_dp)
   end subroutine random_state

   subroutine single_call(k, p)
      integer, intent(in) :: k
      real(dp), intent(in) :: p(NP_MAX)
      type(call_type) :: c
      character(len=64) :: where
      call random_state(c, p)
      write (where, '(a,i0)') 'single call ', k
      call compare_paths(c, p, trim(where))
      if (c%reported == 0) nsingle_ok = nsingle_ok + 1
   end subroutine single_call

   ! ---- part 3 ----------------------------------------------------------------------------

   !> A random state with one input spoilt.
   subroutine spoilt_call(k, p)
      integer, intent(in) :: k
      real(dp), intent(in) :: p(NP_MAX)
      type(call_type) :: c
      real(dp) :: q(NP_MAX), bad
      character(len=64) :: where
      integer :: which, k2, nm
      call random_state(c, p)
      q = p
      select case (pick(1, 4))
      case (1)
         bad = ieee_value(1.0_dp, ieee_quiet_nan)
      case (2)
         bad = sgn()
         bad = bad*ieee_value(1.0_dp, ieee_positive_inf)
      case (3)
         bad = sgn()*1.0e160_dp
      case default
         bad = sgn()*1.0e60_dp
      end select
      which = pick(1, 17)
      select case (which)
      case (1)
         k2 = pick(1, c%ntens)
         c%stran(k2) = bad
      case (2)
         k2 = pick(1, c%ntens)
         c%dstran(k2) = bad
      case (3)
         k2 = pick(1, c%ntens)
         c%stress(k2) = bad
      case (4)
         c%sse = bad
      case (5)
         c%spd = bad
      case (6)        ! a separation beyond 1e20 mm from values within 1e50
         k2 = pick(1, c%ntens)
         c%stran(k2) = signed(1.0e21_dp, 1.0e49_dp)
      case (7)
         c%statev(SV_DAMAGE) = bad
         if (chance(0.5_dp)) c%statev(SV_DAMAGE) = signed(1.0_dp, 2.0_dp)
         if (chance(0.3_dp)) c%statev(SV_DAMAGE) = nearest(1.0_dp, 1.0_dp)
      case (8)
         k2 = SV_SLIP_1 + pick(0, 1)
         c%statev(k2) = bad
         if (chance(0.5_dp)) c%statev(k2) = sgn()*2.0e30_dp
      case (9)
         c%statev(SV_REGIME) = real(pick(-2, 8), dp)
         if (chance(0.5_dp)) c%statev(SV_REGIME) = c%statev(SV_REGIME) + 0.5_dp
         if (chance(0.3_dp)) c%statev(SV_REGIME) = bad
      case (10)
         c%nstatv = pick(1, NSTATV_REQUIRED - 1)
      case (11)       ! other element layouts: a continuum element, NDI = 1 with NSHR = 0
         c%ndi = pick(1, 3)
         c%nshr = pick(0, 2)
         if (c%ndi == 1 .and. c%nshr >= 1) c%ndi = 2
      case (12)       ! mu: negative, -0 (refused by the one-pass test, accepted by the checks) or bad
         q(3) = -between(0.0_dp, 1.0_dp)
         if (chance(0.5_dp)) q(3) = bad
         if (chance(0.5_dp)) q(3) = -0.0_dp
      case (13)       ! sf <= s0
         q(5) = q(4)*between(0.5_dp, 1.0_dp)
      case (14)       ! a constant out of its window or not a number
         k2 = pick(4, np)
         q(k2) = bad
         if (chance(0.5_dp)) q(k2) = between(1.0e-30_dp, 1.0e-21_dp)
         if ((np == 8 .or. np == 12) .and. k2 == 8) then
            ! the micromechanical model's table selector: -0, 2, 0.5 or 1 + ulp (the draw in a
            ! statement of its own: every build makes it)
            if (chance(0.5_dp)) then
               select case (pick(1, 4))
               case (1)
                  q(8) = -0.0_dp
               case (2)
                  q(8) = 2.0_dp
               case (3)
                  q(8) = 0.5_dp
               case default
                  q(8) = nearest(1.0_dp, 1.0_dp)
               end select
            end if
         end if
      case (15)       ! the selectors
         k2 = pick(1, 2)
         q(k2) = real(pick(0, 3), dp)
         ! (the micromechanical model's eight PROPS read as the simplified model's, or its twelve with
         ! the fracture law: the reference's last value, the option 0, would then be its K_T or G_cII,
         ! a different refusal; not compared)
         if ((np == 8 .or. np == 12) .and. k2 == 1 .and. nint(q(1)) == 1) q(1) = 0.0_dp
         if (chance(0.3_dp)) q(k2) = q(k2) + 0.5_dp
      case (17)       ! the fracture law's constants: D0, the R-curve selector, G_cI, G_cII
         if (np < 12) then
            q(2) = 2.0_dp            ! the fracture law without its four constants
         else
            nm = np - 4
            select case (pick(1, 4))
            case (1)    ! D0 at or beyond the ends of [1e-30, 1), -0 or below 0
               select case (pick(1, 7))
               case (1)
                  q(nm + 1) = 0.0_dp
               case (2)
                  q(nm + 1) = -0.0_dp
               case (3)
                  q(nm + 1) = 1.0_dp
               case (4)
                  q(nm + 1) = nearest(1.0_dp, 1.0_dp)
               case (5)
                  ! below the smallest initial crack, D_MIN_CRACK = 1e-30
                  q(nm + 1) = 10.0_dp**between(-300.0_dp, -30.0_dp)
               case (6)
                  q(nm + 1) = nearest(1.0e-30_dp, -1.0_dp)
               case default
                  q(nm + 1) = -between(0.0_dp, 1.0_dp)
               end select
            case (2)    ! the R-curve selector: 0, 4, 1.5, -0, or another of 1, 2, 3 (with G_c that
               ! suit it or not)
               select case (pick(1, 5))
               case (1)
                  q(nm + 2) = 0.0_dp
               case (2)
                  q(nm + 2) = 4.0_dp
               case (3)
                  q(nm + 2) = 1.5_dp
               case (4)
                  q(nm + 2) = -0.0_dp
               case default
                  q(nm + 2) = real(pick(1, 3), dp)
               end select
            case (3)    ! G_c: -0 (accepted by the checks, not by the paths' one-pass test), +0, or
               ! a value (wrong for the equivalent and the tabulated R-curve)
               k2 = nm + 2 + pick(1, 2)
               select case (pick(1, 3))
               case (1)
                  q(k2) = -0.0_dp
               case (2)
                  q(k2) = 0.0_dp
               case default
                  q(k2) = 10.0_dp**between(-3.0_dp, 0.0_dp)
               end select
            case default    ! G_c out of its window or not a number
               k2 = nm + 2 + pick(1, 2)
               q(k2) = bad
               if (chance(0.5_dp)) q(k2) = between(1.0e-30_dp, 1.0e-21_dp)
            end select
         end if
      case default    ! NTENS /= NDI + NSHR on a cohesive element: the other element's NSHR
         c%nshr = 3 - c%nshr
      end select
      if (which /= 16) c%ntens = c%ndi + c%nshr
      if (which == 11) c%ntens = max(1, min(3, c%ntens))
      write (where, '(a,i0,a,i0)') 'spoilt call ', k, ', kind ', which
      call compare_paths(c, q, trim(where))
   end subroutine spoilt_call

end program test_umat_simplified_path
