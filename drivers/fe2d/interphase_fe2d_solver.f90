!> The analysis of `interphase-fe2d`: assembly, Newton-Raphson on the consistent tangent,
!> automatic increments with cut-back, and the rows of the load-displacement curve.
!>
!> Two steps, as in an Abaqus input: step 1 ramps the precompression pressure from 0 to its
!> value over the pseudo-time 0..1 (the shear displacement held at 0); step 2 replays the shear
!> history t / u_shear piecewise linearly with the pressure held. Each history segment is
!> split into `increments` nominal increments. Within an increment, Newton-Raphson iterates on
!> the free equations with the tangent assembled from the brick stiffness and the interface
!> elements' B^T DDSDDE B (unsymmetric; banded LAPACK dgbsv). The prescribed displacement
!> increment enters the first iteration through the stiffness coupling (K_fp du_p), so the
!> first iteration is a consistent linearised predictor. Every UMAT call starts from the last
!> converged state of its point (STRAN = separation there, DSTRAN = total increment), exactly
!> as Abaqus/Standard calls it.
!>
!> Convergence: ||R_f|| <= tolerance * F_ref, F_ref = max(||F_ext||, |reaction on u|, a floor), and
!> ||du|| <= displacement_tolerance * ||u_f|| (the second test is waived once the residual is
!> a thousand times below its tolerance). The residual test is also met where ||R_f|| is at the
!> round-off of its own assembly, ROUNDOFF_FACTOR * epsilon * ||sum_e |K_e| |u_e| + |f_joint|||
!> (a load that vanishes, e.g. a shear force falling to mu * 0 without precompression, would
!> otherwise ask for a residual below what double precision can form); such increments are
!> counted and logged. Cut-back: a UMAT asking PNEWDT < 1 cuts the increment by
!> max(PNEWDT, 0.1); no convergence in max_iterations (or a singular/non-finite system) halves
!> it; after an increment that needed at most GROW_ITERATIONS iterations the increment grows by
!> GROW_FACTOR, never beyond the nominal one. Below min_increment times
!> the nominal increment the analysis stops with a message.
module interphase_fe2d_solver
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
   use, intrinsic :: iso_fortran_env, only: error_unit
   use interphase_kinds, only: dp
   use interphase_layout, only: NSTATV_VISCOUS, SV_DAMAGE, SV_SLIP_1
   use interphase_abaqus_interfaces, only: umat
   use interphase_fe2d_case, only: fe2d_case_type
   use interphase_fe2d_mesh, only: fe2d_mesh_type, q4_stiffness, interface_b_matrix
   use interphase_driver_text, only: int_to_string, real_to_string
   implicit none
   private
   public :: fe2d_options_type, fe2d_increment_type, fe2d_result_type, run_analysis, &
      CSV_COLUMNS, NCOLUMNS, COL_STEP, COL_T, COL_U, COL_SHEAR, COL_NORMAL, COL_JOINT_SHEAR, &
      COL_V_TOP, COL_MEAN_D, COL_MAX_D, COL_MEAN_SLIP, COL_JOINT_STORED, COL_JOINT_DISSIPATED, &
      MAX_ITERATIONS_LIMIT

   !> Columns of the load-displacement table (CSV header). joint_stored and joint_dissipated
   !> are the UMAT's SSE and SPD integrated over the joint (N mm).
   character(len=*), parameter :: CSV_COLUMNS = &
      'step,t,u,shear_force,normal_force,joint_shear_force,v_top,mean_D,max_D,mean_slip,'// &
      'joint_stored,joint_dissipated'
   integer, parameter :: NCOLUMNS = 12
   integer, parameter :: COL_STEP = 1, COL_T = 2, COL_U = 3, COL_SHEAR = 4, COL_NORMAL = 5, &
      COL_JOINT_SHEAR = 6, COL_V_TOP = 7, COL_MEAN_D = 8, COL_MAX_D = 9, COL_MEAN_SLIP = 10, &
      COL_JOINT_STORED = 11, COL_JOINT_DISSIPATED = 12
   !> Largest max_iterations (size of the residual record).
   integer, parameter :: MAX_ITERATIONS_LIMIT = 50
   !> Increments growth after easy convergence.
   real(dp), parameter :: GROW_FACTOR = 1.5_dp
   integer, parameter :: GROW_ITERATIONS = 5
   !> Floor of the residual's reference force, as a strain of the bricks (a load-free state
   !> has F_ext = 0 and no reaction): F_ref >= FORCE_FLOOR * E_b * L * thickness.
   real(dp), parameter :: FORCE_FLOOR = 1.0e-12_dp
   !> Residual accepted as round-off: this many epsilon of the absolute internal forces
   !> (the norm of sum_e |K_e| |u_e| over the bricks plus |B^T| |Sigma| over the joints).
   real(dp), parameter :: ROUNDOFF_FACTOR = 64.0_dp
   !> Largest number of step halvings of the line search.
   integer, parameter :: MAX_LINE_SEARCH = 6
   !> Cut-back factors: non-convergence, and the smallest PNEWDT honoured.
   real(dp), parameter :: CUT_FACTOR = 0.5_dp
   real(dp), parameter :: MIN_PNEWDT_FACTOR = 0.1_dp

   interface
      !> LAPACK: solve a general banded system (LU with partial pivoting).
      subroutine dgbsv(n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb, info)
         import :: dp
         integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb
         real(dp), intent(inout) :: ab(ldab, *), b(ldb, *)
         integer, intent(out) :: ipiv(*), info
      end subroutine dgbsv
   end interface

   !> Solver options that are not case data.
   type :: fe2d_options_type
      !> Write the iteration log to log_unit.
      logical :: log = .false.
      !> Unit of the iteration log (open, formatted) when log is true.
      integer :: log_unit = 0
      !> Test hook: the interface tangent used in the global matrix is DDSDDE times this
      !> factor (1 = consistent Newton). Only the tests change it, to show that their
      !> convergence-rate check fails with a wrong tangent.
      real(dp) :: tangent_scale = 1.0_dp
      !> Test hook: in an increment longer than this (pseudo-time) every interface UMAT call gets
      !> a NaN normal separation increment, which the UMAT refuses like any failed update: it
      !> returns PNEWDT = 0.25 with its outputs untouched (docs/abaqus.md, Failures). No physical
      !> separation makes the interphase UMAT fail (README, Verification), so only the tests set
      !> it, to drive the PNEWDT cut-back. Default: never.
      real(dp) :: umat_failure_above = huge(1.0_dp)
      !> Print a progress line to standard error every PROGRESS_SECONDS once the run has lasted
      !> that long (the program sets it; the in-process tests do not).
      logical :: progress = .false.
      !> The name in the progress lines (the case).
      character(len=:), allocatable :: name
   end type fe2d_options_type

   !> Seconds between two progress lines (and before the first).
   real(dp), parameter :: PROGRESS_SECONDS = 2.0_dp

   !> One converged increment and its Newton history.
   type :: fe2d_increment_type
      integer :: step = 0                         !! 1 precompression, 2 shear
      integer :: number = 0                       !! increment number within the step
      real(dp) :: t = 0.0_dp                      !! time at its end
      real(dp) :: dt = 0.0_dp                     !! its size
      integer :: iterations = 0                   !! linear solves
      !> relative residual norms: (0) the linearised predictor residual, (k) after k solves
      real(dp) :: residual(0:MAX_ITERATIONS_LIMIT) = 0.0_dp
      real(dp) :: mean_d_start = 0.0_dp           !! mean damage before
      real(dp) :: mean_d_end = 0.0_dp             !! mean damage after
   end type fe2d_increment_type

   !> What an analysis produced.
   type :: fe2d_result_type
      logical :: ok = .false.                     !! completed
      character(len=:), allocatable :: message    !! why not
      integer :: nrows = 0                        !! rows of the curve
      real(dp), allocatable :: rows(:, :)         !! rows(NCOLUMNS, nrows)
      integer :: nincrements = 0                  !! converged increments
      type(fe2d_increment_type), allocatable :: increments(:)
      integer :: cutbacks = 0                     !! increments cut back
      !> increments accepted with the residual at the round-off of the assembly, above
      !> tolerance x F_ref (a vanishing load, or an ill-conditioned brick such as nu -> 0.5)
      integer :: roundoff_increments = 0
      integer :: iterations = 0                   !! linear solves in all
      integer :: neq = 0                          !! free equations
      integer :: bandwidth = 0                    !! half bandwidth
   end type fe2d_result_type

contains

   !> Run the two steps of the case on the mesh.
   subroutine run_analysis(run, mesh, options, result)
      type(fe2d_case_type), intent(in) :: run     !! case data
      type(fe2d_mesh_type), intent(in) :: mesh    !! mesh and DOF map
      type(fe2d_options_type), intent(in) :: options  !! log, test hooks
      type(fe2d_result_type), intent(out) :: result   !! curve, increments, status
      character(len=80), parameter :: CMNAME = 'INTERPHASE-FE2D'
      real(dp), allocatable :: ke_quad(:, :, :), u(:), u_n(:), fint(:), fext(:), kfp_dup(:)
      real(dp), allocatable :: fint_abs(:)
      real(dp), allocatable :: ke_abs(:, :, :)   !! |K_e| of each brick element, for fint_abs
      logical :: at_roundoff
      !> why the last Newton attempt failed (named in the message when the increment falls below
      !> the minimum)
      character(len=:), allocatable :: last_failure
      !> the last residual's round-off floor of the assembly, relative as the residual (-)
      real(dp) :: roundoff_rel
      real(dp), allocatable :: ab(:, :), rhs(:), dup(:)
      integer, allocatable :: ipiv(:)
      real(dp), allocatable :: sep_n(:, :), stress_n(:, :), statev_n(:, :), sse_n(:), spd_n(:)
      real(dp), allocatable :: sep(:, :), stress(:, :), statev(:, :), sse(:), spd(:)
      real(dp), allocatable :: area(:), joint_sign(:)
      integer :: nfree, bw, ldab, npts, e, p, ip
      real(dp) :: xy(2, 4), bm(2, 8), jac, t_total_offset, step_time_start
      integer :: current_step, kinc
      integer :: clock_start, clock_last, clock_rate
      logical :: ok

      call system_clock(clock_start, clock_rate)
      clock_last = clock_start
      last_failure = ''
      roundoff_rel = 0.0_dp
      nfree = mesh%nfree
      bw = mesh%bandwidth
      ldab = 3*bw + 1
      result%neq = nfree
      result%bandwidth = bw
      allocate (ke_quad(8, 8, mesh%nquad), ke_abs(8, 8, mesh%nquad))
      do e = 1, mesh%nquad
         xy = 0.0_dp
         xy(:, 1:4) = mesh%x(:, mesh%quad(:, e))
         call q4_stiffness(xy, mesh%d_matrix, mesh%thickness, ke_quad(:, :, e))
         ke_abs(:, :, e) = abs(ke_quad(:, :, e))
      end do
      allocate (u(mesh%neq), u_n(mesh%neq), fint(mesh%neq), fint_abs(mesh%neq), fext(mesh%neq), &
         kfp_dup(nfree), &
         dup(mesh%neq), rhs(nfree), ipiv(nfree), ab(ldab, nfree))
      u = 0.0_dp
      u_n = 0.0_dp
      fint = 0.0_dp
      fint_abs = 0.0_dp
      npts = mesh%npoint*mesh%nintf
      allocate (sep_n(2, npts), stress_n(2, npts), statev_n(NSTATV_VISCOUS, npts), sse_n(npts), &
         spd_n(npts), area(npts), joint_sign(npts))
      sep_n = 0.0_dp
      stress_n = 0.0_dp
      statev_n = 0.0_dp
      sse_n = 0.0_dp
      spd_n = 0.0_dp
      do e = 1, mesh%nintf
         xy = mesh%x(:, mesh%intf(:, e))
         do p = 1, mesh%npoint
            ip = mesh%npoint*(e - 1) + p
            call interface_b_matrix(xy, mesh%xi(p), bm, jac)
            area(ip) = mesh%weight(p)*jac*mesh%thickness
            ! triplet: the pushed middle brick is above joint 1 and below joint 2
            joint_sign(ip) = merge(1.0_dp, -1.0_dp, mesh%intf_joint(e) == 1)
         end do
      end do
      sep = sep_n
      stress = stress_n
      statev = statev_n
      sse = sse_n
      spd = spd_n
      allocate (result%rows(NCOLUMNS, 64), result%increments(64))

      ! ---- probe: one zero-increment UMAT call on a virgin point checks PROPS first ----
      call probe_material(ok)
      if (.not. ok) return
      ! ---- step 1: precompression over pseudo-time 0..1 ----
      current_step = 1
      t_total_offset = 0.0_dp
      step_time_start = 0.0_dp
      call add_row(0.0_dp, 0.0_dp)
      call run_step([0.0_dp, 1.0_dp], run%precompression_increments, ok)
      if (.not. ok) return
      ! ---- step 2: shear history, pressure held ----
      current_step = 2
      t_total_offset = 1.0_dp
      step_time_start = run%history_t(1)
      call run_step(run%history_t, run%increments, ok)
      if (.not. ok) return
      result%ok = .true.
      result%message = ''

   contains

      !> A setup error (bad PROPS) is refused by the UMAT at any increment size: ask once.
      subroutine probe_material(ok)
         logical, intent(out) :: ok
         real(dp) :: stress1(2), statev1(NSTATV_VISCOUS), ddsdde(2, 2), sse1, spd1, scd, rpl
         real(dp) :: ddsddt(2), drplde(2), drpldt, zero2(2), predef(1), dpred(1), eye(3, 3), pnewdt
         integer :: a

         stress1 = 0.0_dp
         statev1 = 0.0_dp
         ddsdde = 0.0_dp
         sse1 = 0.0_dp
         spd1 = 0.0_dp
         scd = 0.0_dp
         rpl = 0.0_dp
         ddsddt = 0.0_dp
         drplde = 0.0_dp
         drpldt = 0.0_dp
         zero2 = 0.0_dp
         predef = 0.0_dp
         dpred = 0.0_dp
         eye = 0.0_dp
         do a = 1, 3
            eye(a, a) = 1.0_dp
         end do
         pnewdt = 1.0_dp
         call umat(stress1, statev1, ddsdde, sse1, spd1, scd, rpl, ddsddt, drplde, drpldt, &
            zero2, zero2, [0.0_dp, 0.0_dp], 0.0_dp, 0.0_dp, 0.0_dp, predef, dpred, CMNAME, 1, 1, &
            2, NSTATV_VISCOUS, run%props, size(run%props), [0.0_dp, 0.0_dp, 0.0_dp], eye, &
            pnewdt, 1.0_dp, eye, eye, 1, 1, 1, 1, [1, 0, 0, 0], 0)
         ok = pnewdt >= 1.0_dp
         if (.not. ok) result%message = '&joint: the UMAT rejected the interface material '// &
            'data (its message above names the PROPS entry)'
      end subroutine probe_material

      !> Pressure factor and prescribed shear displacement at time t of the current step.
      subroutine loads_at(t, factor, u_shear)
         real(dp), intent(in) :: t
         real(dp), intent(out) :: factor, u_shear
         integer :: k
         real(dp) :: w

         if (current_step == 1) then
            factor = t
            u_shear = 0.0_dp
            return
         end if
         factor = 1.0_dp
         u_shear = run%history_u(size(run%history_u))
         do k = 1, size(run%history_t) - 1
            if (t <= run%history_t(k + 1)) then
               w = (t - run%history_t(k))/(run%history_t(k + 1) - run%history_t(k))
               u_shear = (1.0_dp - w)*run%history_u(k) + w*run%history_u(k + 1)
               return
            end if
         end do
      end subroutine loads_at

      !> Increments over the breakpoints tb, `ninc` nominal increments per segment.
      subroutine run_step(tb, ninc, ok)
         real(dp), intent(in) :: tb(:)
         integer, intent(in) :: ninc
         logical, intent(out) :: ok
         real(dp) :: t, dt, dt_try, dt_nominal, remaining, t_new, factor, d_start
         integer :: seg, iterations
         logical :: last, converged
         real(dp) :: residuals(0:MAX_ITERATIONS_LIMIT)

         ok = .false.
         t = tb(1)
         seg = 1
         kinc = 0
         dt = (tb(2) - tb(1))/ninc
         do while (seg < size(tb))
            dt_nominal = (tb(seg + 1) - tb(seg))/ninc
            dt = min(dt, dt_nominal)
            remaining = tb(seg + 1) - t
            last = dt >= remaining*(1.0_dp - 1.0e-9_dp)
            if (last) then
               dt_try = remaining
               t_new = tb(seg + 1)
            else
               dt_try = dt
               t_new = t + dt
            end if
            d_start = mean_damage(statev_n)
            call newton(t, t_new, converged, iterations, residuals, factor)
            if (converged) then
               call commit()
               t = t_new
               if (last) seg = seg + 1
               call add_increment(t_new, dt_try, iterations, residuals, d_start)
               call add_row(t, u(mesh%eq_shear))
               if (iterations <= GROW_ITERATIONS) dt = min(GROW_FACTOR*dt, dt_nominal)
               if (options%progress) call show_progress(t, tb(size(tb)))
            else
               result%cutbacks = result%cutbacks + 1
               dt = dt_try*factor
               call log_line('  cut-back: step '//int_to_string(current_step)//' t = '// &
                  real_to_string(t)//', increment '//real_to_string(dt_try)//' -> '// &
                  real_to_string(dt))
               if (dt < run%min_increment*dt_nominal) then
                  result%message = 'step '//int_to_string(current_step)//': increment '// &
                     real_to_string(dt)//' at t = '//real_to_string(t)// &
                     ' is below the minimum '//real_to_string(run%min_increment*dt_nominal)// &
                     ' (min_increment = '//real_to_string(run%min_increment)// &
                     ' of the nominal increment): the analysis cannot proceed; the last attempt: '// &
                     last_failure
                  call log_line('error: '//result%message)
                  return
               end if
            end if
         end do
         ok = .true.
      end subroutine run_step

      !> Newton-Raphson from the converged state at t to t_new. On failure `factor` is the
      !> cut-back factor.
      subroutine newton(t, t_new, converged, iterations, residuals, factor)
         real(dp), intent(in) :: t, t_new
         logical, intent(out) :: converged
         integer, intent(out) :: iterations
         real(dp), intent(out) :: residuals(0:MAX_ITERATIONS_LIMIT)
         real(dp), intent(out) :: factor
         real(dp) :: load_factor, u_shear, rel, rel_prev, du_rel, unorm, alpha
         real(dp), allocatable :: du(:), u_prev(:)
         integer :: k, info, search
         logical :: ok

         converged = .false.
         iterations = 0
         residuals = 0.0_dp
         factor = CUT_FACTOR
         kinc = kinc + 1
         allocate (du(nfree), u_prev(mesh%neq))
         call loads_at(t_new, load_factor, u_shear)
         fext = load_factor*run%precompression*mesh%f_pressure
         u = u_n
         dup = 0.0_dp
         dup(mesh%eq_shear) = u_shear - u_n(mesh%eq_shear)
         du_rel = huge(1.0_dp)
         ! iteration 0: the linearised predictor residual at the start state
         call residual_at(0, .true., t, t_new - t, rel, ok, factor)
         if (.not. ok) return
         residuals(0) = rel
         call log_iteration(0, t_new, t_new - t, rel, du_rel, 1.0_dp)
         do k = 1, run%max_iterations
            call dgbsv(nfree, bw, bw, 1, ab, ldab, ipiv, rhs, nfree, info)
            if (info /= 0) then
               last_failure = 'iteration '//int_to_string(k)//': singular tangent (dgbsv info = '// &
                  int_to_string(info)//')'
               call log_line('    '//last_failure)
               return
            end if
            if (.not. all(ieee_is_finite(rhs))) then
               last_failure = 'iteration '//int_to_string(k)//': non-finite correction'
               call log_line('    '//last_failure)
               return
            end if
            du = rhs
            u_prev = u
            rel_prev = rel
            ! backtracking line search (k >= 2 only): halve the step while the residual grows;
            ! it breaks the two-cycles that regime switches (open/closed, stick/slip) of
            ! interface points can cause, and never acts where Newton converges quadratically
            alpha = 1.0_dp
            do search = 0, MAX_LINE_SEARCH
               u(1:nfree) = u_prev(1:nfree) + alpha*du
               if (k == 1) u(mesh%eq_shear) = u_shear
               call residual_at(k, .false., t, t_new - t, rel, ok, factor)
               if (.not. ok) return
               if (k == 1 .or. rel < rel_prev .or. search == MAX_LINE_SEARCH) exit
               alpha = 0.5_dp*alpha
            end do
            unorm = max(norm2(u(1:nfree)), tiny(1.0_dp))
            du_rel = alpha*norm2(du)/unorm
            residuals(k) = rel
            call log_iteration(k, t_new, t_new - t, rel, du_rel, alpha)
            if ((rel <= run%tolerance .or. at_roundoff) .and. (du_rel <= run%displacement_tolerance .or. &
               rel <= 1.0e-3_dp*run%tolerance)) then
               converged = .true.
               iterations = k
               if (at_roundoff) then
                  result%roundoff_increments = result%roundoff_increments + 1
                  call log_line('    residual above the tolerance but at the round-off of the '// &
                     'assembly ('//int_to_string(nint(ROUNDOFF_FACTOR))//' eps ||sum |K_e||u_e|||): accepted')
               end if
               return
            end if
         end do
         ! (the residual against its round-off floor tells a tolerance the assembly cannot reach,
         ! as in an ill-conditioned mesh, from a path Newton does not follow)
         last_failure = 'no convergence in '//int_to_string(run%max_iterations)//' iterations, relative '// &
            'residual '//real_to_string(rel)//' (tolerance '//real_to_string(run%tolerance)// &
            ', the assembly''s round-off '//real_to_string(roundoff_rel)//'), ||du||/||u|| '// &
            real_to_string(du_rel)//' (tolerance '//real_to_string(run%displacement_tolerance)//')'
         call log_line('    '//last_failure)

      end subroutine newton

      !> Assemble at u and form the right-hand side and the relative residual; false when
      !> a UMAT asked for a smaller increment or the residual is not finite.
      subroutine residual_at(k, predictor, t, dt, rel, ok, factor)
         integer, intent(in) :: k
         logical, intent(in) :: predictor
         real(dp), intent(in) :: t, dt
         real(dp), intent(inout) :: factor
         real(dp), intent(out) :: rel
         logical, intent(out) :: ok
         real(dp) :: pnewdt, fref, rnorm, roundoff

         ok = .false.
         rel = huge(1.0_dp)
         at_roundoff = .false.
         call assemble(t, dt, predictor, pnewdt)
         if (pnewdt < 1.0_dp) then
            factor = max(pnewdt, MIN_PNEWDT_FACTOR)
            last_failure = 'iteration '//int_to_string(k)//': a UMAT call asked PNEWDT = '//real_to_string(pnewdt)
            call log_line('    '//last_failure)
            return
         end if
         rhs = fext(1:nfree) - fint(1:nfree)
         if (predictor) rhs = rhs - kfp_dup
         fref = max(norm2(fext), abs(fint(mesh%eq_shear)), &
            FORCE_FLOOR*run%young*run%brick_length*run%thickness)
         rnorm = norm2(rhs)
         if (.not. ieee_is_finite(rnorm)) then
            last_failure = 'iteration '//int_to_string(k)//': non-finite residual'
            call log_line('    '//last_failure)
            return
         end if
         rel = rnorm/fref
         ! a residual at the round-off of the assembly meets the residual test
         roundoff = ROUNDOFF_FACTOR*epsilon(1.0_dp)*norm2(fint_abs(1:nfree))
         roundoff_rel = roundoff/fref
         at_roundoff = rnorm <= roundoff .and. rel > run%tolerance
         ok = .true.
      end subroutine residual_at


      !> Internal forces, tangent (band of the free equations) and, in the first iteration,
      !> K_fp * du_p at the displacements u; every interface point calls the UMAT from its
      !> converged state. pnewdt: the smallest PNEWDT the UMAT calls returned.
      subroutine assemble(t, dt, predictor, pnewdt)
         real(dp), intent(in) :: t, dt
         logical, intent(in) :: predictor
         real(dp), intent(out) :: pnewdt
         integer :: eqs(8), a
         real(dp) :: d(8), ke(8, 8), fe(8), ddsdde(2, 2), point_pnewdt
         real(dp) :: ddsddt(2), drplde(2), scd, rpl, drpldt, time(2), predef(1), dpred(1)
         real(dp) :: coords(3), drot(3, 3), dfgrd(3, 3), dstran(2), jac
         integer :: jstep(4)

         fint = 0.0_dp
         fint_abs = 0.0_dp
         ab = 0.0_dp
         kfp_dup = 0.0_dp
         pnewdt = 1.0_dp
         do e = 1, mesh%nquad
            do a = 1, 4
               eqs(2*a - 1:2*a) = mesh%eq(:, mesh%quad(a, e))
            end do
            d = u(eqs)
            fe = matmul(ke_quad(:, :, e), d)
            call scatter_abs(eqs, matmul(ke_abs(:, :, e), abs(d)))
            call scatter(eqs, ke_quad(:, :, e), fe)
         end do
         drot = 0.0_dp
         dfgrd = 0.0_dp
         do a = 1, 3
            drot(a, a) = 1.0_dp
            dfgrd(a, a) = 1.0_dp
         end do
         jstep = [current_step, 0, 0, 0]
         time = [t - step_time_start, t - step_time_start + t_total_offset]
         predef = 0.0_dp
         dpred = 0.0_dp
         do e = 1, mesh%nintf
            do a = 1, 4
               eqs(2*a - 1:2*a) = mesh%eq(:, mesh%intf(a, e))
            end do
            d = u(eqs)
            xy = mesh%x(:, mesh%intf(:, e))
            fe = 0.0_dp
            ke = 0.0_dp
            do p = 1, mesh%npoint
               ip = mesh%npoint*(e - 1) + p
               call interface_b_matrix(xy, mesh%xi(p), bm, jac)
               sep(:, ip) = matmul(bm, d)
               dstran = sep(:, ip) - sep_n(:, ip)
               if (dt > options%umat_failure_above) dstran(1) = ieee_value(1.0_dp, ieee_quiet_nan)
               stress(:, ip) = stress_n(:, ip)
               statev(:, ip) = statev_n(:, ip)
               sse(ip) = sse_n(ip)
               spd(ip) = spd_n(ip)
               ddsdde = 0.0_dp
               ddsddt = 0.0_dp
               drplde = 0.0_dp
               scd = 0.0_dp
               rpl = 0.0_dp
               drpldt = 0.0_dp
               coords = 0.0_dp
               coords(1:2) = 0.5_dp*(1.0_dp - mesh%xi(p))*xy(:, 1) + 0.5_dp*(1.0_dp + mesh%xi(p))*xy(:, 2)
               point_pnewdt = 1.0_dp
               call umat(stress(:, ip), statev(:, ip), ddsdde, sse(ip), spd(ip), scd, rpl, &
                  ddsddt, drplde, drpldt, sep_n(:, ip), dstran, time, dt, 0.0_dp, 0.0_dp, &
                  predef, dpred, CMNAME, 1, 1, 2, NSTATV_VISCOUS, run%props, size(run%props), &
                  coords, drot, point_pnewdt, 2.0_dp*jac, dfgrd, dfgrd, e, p, 1, 1, jstep, kinc)
               if (point_pnewdt < 1.0_dp) then
                  pnewdt = min(pnewdt, point_pnewdt)
                  cycle
               end if
               fe = fe + matmul(transpose(bm), stress(:, ip))*area(ip)
               call scatter_abs(eqs, matmul(abs(transpose(bm)), abs(stress(:, ip)))*area(ip))
               ! a host that assembles only the symmetric part (CalculiX, Abaqus without UNSYMM)
               if (run%symmetric_assembly) ddsdde = 0.5_dp*(ddsdde + transpose(ddsdde))
               ke = ke + matmul(transpose(bm), matmul(options%tangent_scale*ddsdde, bm))*area(ip)
            end do
            if (pnewdt < 1.0_dp) return
            call scatter(eqs, ke, fe)
         end do
         if (.not. predictor) kfp_dup = 0.0_dp
      end subroutine assemble

      !> Add an element's forces and (free-free) stiffness; collect K_fp * du_p.
      subroutine scatter(eqs, ke, fe)
         integer, intent(in) :: eqs(8)
         real(dp), intent(in) :: ke(8, 8), fe(8)
         integer :: a, b, i, j

         do a = 1, 8
            i = eqs(a)
            fint(i) = fint(i) + fe(a)
            if (i > nfree) cycle
            do b = 1, 8
               j = eqs(b)
               if (j <= nfree) then
                  ab(2*bw + 1 + i - j, j) = ab(2*bw + 1 + i - j, j) + ke(a, b)
               else
                  kfp_dup(i) = kfp_dup(i) + ke(a, b)*dup(j)
               end if
            end do
         end do
      end subroutine scatter

      !> Add an element's absolute internal forces (the round-off scale of fint); tied DOFs
      !> share an equation, so the element's entries are added one by one.
      subroutine scatter_abs(eqs, fe_abs)
         integer, intent(in) :: eqs(8)
         real(dp), intent(in) :: fe_abs(8)
         integer :: a

         do a = 1, 8
            fint_abs(eqs(a)) = fint_abs(eqs(a)) + fe_abs(a)
         end do
      end subroutine scatter_abs

      !> Accept the trial state of the last assembly.
      subroutine commit()
         u_n = u
         sep_n = sep
         stress_n = stress
         statev_n = statev
         sse_n = sse
         spd_n = spd
      end subroutine commit

      !> Area-weighted mean damage over all interface points.
      pure real(dp) function mean_damage(state)
         real(dp), intent(in) :: state(:, :)
         mean_damage = sum(state(SV_DAMAGE, :)*area)/sum(area)
      end function mean_damage

      !> Append a row of the curve from the converged state.
      subroutine add_row(t, u_shear)
         real(dp), intent(in) :: t, u_shear
         real(dp), allocatable :: grow(:, :)
         real(dp) :: row(NCOLUMNS)
         integer :: n

         if (result%nrows == size(result%rows, 2)) then
            allocate (grow(NCOLUMNS, 2*result%nrows))
            grow(:, 1:result%nrows) = result%rows
            call move_alloc(grow, result%rows)
         end if
         row(COL_STEP) = real(current_step, dp)
         row(COL_T) = t
         row(COL_U) = u_shear
         row(COL_SHEAR) = fint(mesh%eq_shear)
         if (result%nrows == 0) row(COL_SHEAR) = 0.0_dp
         row(COL_NORMAL) = -sum(stress_n(1, :)*area)
         row(COL_JOINT_SHEAR) = sum(joint_sign*stress_n(2, :)*area)
         row(COL_V_TOP) = 0.0_dp
         do n = 1, size(mesh%top_face)
            row(COL_V_TOP) = row(COL_V_TOP) + u_n(mesh%eq(2, mesh%top_face(n)))
         end do
         row(COL_V_TOP) = row(COL_V_TOP)/size(mesh%top_face)
         row(COL_MEAN_D) = mean_damage(statev_n)
         row(COL_MAX_D) = maxval(statev_n(SV_DAMAGE, :))
         row(COL_MEAN_SLIP) = sum(abs(statev_n(SV_SLIP_1, :))*area)/sum(area)
         row(COL_JOINT_STORED) = sum(sse_n*area)
         row(COL_JOINT_DISSIPATED) = sum(spd_n*area)
         result%nrows = result%nrows + 1
         result%rows(:, result%nrows) = row
      end subroutine add_row

      !> Record a converged increment.
      subroutine add_increment(t_end, dt, iterations, residuals, d_start)
         real(dp), intent(in) :: t_end, dt, d_start
         integer, intent(in) :: iterations
         real(dp), intent(in) :: residuals(0:MAX_ITERATIONS_LIMIT)
         type(fe2d_increment_type), allocatable :: grow(:)
         type(fe2d_increment_type) :: record

         if (result%nincrements == size(result%increments)) then
            allocate (grow(2*result%nincrements))
            grow(1:result%nincrements) = result%increments
            call move_alloc(grow, result%increments)
         end if
         record%step = current_step
         record%number = kinc
         record%t = t_end
         record%dt = dt
         record%iterations = iterations
         record%residual = residuals
         record%mean_d_start = d_start
         record%mean_d_end = mean_damage(statev_n)
         result%nincrements = result%nincrements + 1
         result%increments(result%nincrements) = record
         result%iterations = result%iterations + iterations
         call log_line('  converged: step '//int_to_string(current_step)//' increment '// &
            int_to_string(kinc)//' t = '//real_to_string(t_end)//' in '// &
            int_to_string(iterations)//' iterations; shear force '// &
            real_to_string(fint(mesh%eq_shear))//' N, mean D '// &
            real_to_string(record%mean_d_end))
      end subroutine add_increment

      subroutine log_iteration(k, t_new, dt, rel, du_rel, alpha)
         integer, intent(in) :: k
         real(dp), intent(in) :: t_new, dt, rel, du_rel, alpha
         character(len=160) :: line

         if (.not. options%log) return
         if (k == 0) then
            write (line, '(a,i0,a,i0,a,es12.5,a,es11.4)') 'step ', current_step, ' increment ', &
               kinc, ' t = ', t_new, ' dt = ', dt
            write (options%log_unit, '(a)') trim(line)
            write (line, '(a,i3,a,es11.3e3)') '    iteration', k, '  residual', rel
         else
            write (line, '(a,i3,a,es11.3e3,a,es11.3e3)') '    iteration', k, '  residual', rel, &
               '  correction', du_rel
            if (alpha < 1.0_dp) write (line, '(a,a,es9.2)') trim(line), '  line search ', alpha
         end if
         write (options%log_unit, '(a)') trim(line)
      end subroutine log_iteration

      subroutine log_line(text)
         character(len=*), intent(in) :: text
         if (options%log) write (options%log_unit, '(a)') text
      end subroutine log_line


      !> A progress line on standard error, every PROGRESS_SECONDS once the run lasts that long.
      subroutine show_progress(t_now, t_end)
         real(dp), intent(in) :: t_now, t_end    !! pseudo-time reached, and at the step's end
         integer :: clock_now
         character(len=:), allocatable :: who
         call system_clock(clock_now)
         if (real(clock_now - clock_last, dp) < PROGRESS_SECONDS*real(clock_rate, dp)) return
         clock_last = clock_now
         who = 'interphase-fe2d'
         if (allocated(options%name)) who = options%name
         write (error_unit, '(a)') who//': step '//int_to_string(current_step)//', t = '// &
            real_to_string(t_now)//' of '//real_to_string(t_end)//', '//int_to_string(result%nincrements)// &
            ' increments, '//int_to_string(result%cutbacks)//' cut-backs, '// &
            int_to_string(nint(real(clock_now - clock_start, dp)/real(clock_rate, dp)))//' s'
         flush (error_unit)
      end subroutine show_progress

   end subroutine run_analysis

end module interphase_fe2d_solver
