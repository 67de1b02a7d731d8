!> Replay of a history through the UMAT at one material point.
!>
!> The material starts virgin (D = 0, no slip, zero traction and energies) at zero separation.
!> If the history's first row is not at zero, the driver first loads the point from zero to it,
!> in `increments` sub-increments at time t0 with DTIME = 0; those steps are not written. The
!> first CSV row is then the state at t0. Each history segment is split into `increments` equal
!> sub-increments and the UMAT is called once per sub-increment, carrying STRESS, STATEV, SSE and
!> SPD.
!>
!> Mixed control: a component the history gives as a traction (`Sigma_N`, ...) is solved for.
!> Its separation is the unknown of Newton's method on the UMAT's tangent (the traction-controlled
!> block of DDSDDE), from the separation of the last converged state, each iteration one UMAT call
!> from that state; an increment has converged when every traction-controlled component is within
!> `traction_tolerance` (MPa) of its imposed value. The imposed values run linearly over the
!> segment from the segment's start value: the previous row's value when the component had the
!> same control there (so that a constant traction stays exactly constant), else the current
!> value of the point.
!>
!> Sub-stepping: when the UMAT asks for a smaller increment (PNEWDT < 1), or Newton does not
!> converge in MAX_NEWTON iterations, the step is halved and retried, up to MAX_HALVINGS times
!> within one sub-increment. When that is not enough and a traction-controlled value is being
!> raised beyond the largest the point reached, the message says that no solution exists (the
!> traction is beyond the peak). A fatal message of the UMAT (a setup error found during the
!> run, e.g. a tabulated R-curve that does not cover the damage reached) ends the replay at once
!> with that message: no smaller step can cure it.
!>
!> Tangent check (`tangent_check` > 0): after every converged step DDSDDE is compared with the
!> central finite difference of the traction over the same increment (each separation component
!> moved by +-`tangent_step` mm, from the same incoming state); the relative error
!> max|FD - DDSDDE| / max|DDSDDE| goes into the CSV column `tangent_error` and the worst one is
!> kept in the summary. Where the forward and backward differences of a column disagree by more
!> than the tolerance, the incremental map has a kink within +-tangent_step (a change of regime,
!> the onset or the end of damage, a reversal): the central difference is no derivative there,
!> and the column is compared with the nearer one-sided difference instead (the step is counted
!> as a kink in the summary).
module interphase_driver_replay
   use, intrinsic :: iso_fortran_env, only: error_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use interphase_kinds, only: dp
   use interphase_layout, only: NSTATV_VISCOUS, SV_DAMAGE
   use interphase_abaqus_interfaces, only: umat
   use interphase_driver_case, only: case_type
   use interphase_driver_history, only: history_type
   use interphase_driver_output, only: write_csv_row
   use interphase_driver_text, only: int_to_string, real_to_string
   use interphase_driver_host, only: reset_fatal_message, fatal_message_reported, last_fatal_message
   use interphase_replay_file, only: write_replay_group
   use interphase_text_input, only: tried_path
   implicit none
   private
   public :: replay_history, MAX_HALVINGS, MAX_NEWTON, point_state_type, new_point, call_umat, &
      replay_report_type

   !> Largest number of halvings of one sub-increment before the driver gives up.
   integer, parameter :: MAX_HALVINGS = 10
   !> Largest number of Newton iterations (UMAT calls) of one mixed-control step.
   integer, parameter :: MAX_NEWTON = 25
   !> Seconds between two progress lines (and before the first).
   real(dp), parameter :: PROGRESS_SECONDS = 2.0_dp

   !> Converged state of the material point between UMAT calls.
   type :: point_state_type
      real(dp) :: time = 0.0_dp                   !! t of the state
      real(dp), allocatable :: separation(:)      !! s, normal first (mm)
      real(dp), allocatable :: stress(:)          !! traction, normal first (MPa)
      real(dp), allocatable :: statev(:)          !! UMAT state variables
      real(dp) :: sse = 0.0_dp                    !! stored energy per unit area (N/mm)
      real(dp) :: spd = 0.0_dp                    !! dissipated energy per unit area (N/mm)
      integer :: kinc = 0                         !! number of UMAT calls so far
   end type point_state_type

   !> What the replay measured beyond the CSV rows: the tangent check's worst error.
   type :: replay_report_type
      integer :: converged_steps = 0              !! UMAT steps kept (written or not)
      integer :: umat_calls = 0                   !! every UMAT call, Newton and checks included
      real(dp) :: worst_tangent_error = 0.0_dp    !! largest relative error of the check
      real(dp) :: worst_tangent_time = 0.0_dp     !! t of that step
      integer :: checked_steps = 0                !! steps whose tangent was checked
      integer :: unchecked_steps = 0              !! steps where a perturbed call failed
      integer :: kink_steps = 0                   !! steps with a kink within +-tangent_step
      !> UMAT order: whether the component's separation or traction changed during the written
      !> part of the replay by more than 1e-9 of its size (else its panel is dropped)
      logical :: moving(3) = .false.
   end type replay_report_type

contains


   !> Replay `history` through the UMAT with the case's material, writing the CSV rows (not the
   !> header) to `csv_unit`. On failure `ok` is false and `message` names the case file.
   subroutine replay_history(run, history, csv_unit, nrows_written, ok, message, report, replay_path)
      type(case_type), intent(in) :: run         !! material (PROPS), increments, options
      type(history_type), intent(in) :: history   !! prescribed separations and tractions
      integer, intent(in) :: csv_unit             !! open CSV file, header already written
      integer, intent(out) :: nrows_written       !! number of CSV rows written
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      type(replay_report_type), intent(out), optional :: report  !! counts and the tangent check
      !> where to write the replay file of a UMAT call that failed for good (none if absent)
      character(len=*), intent(in), optional :: replay_path
      type(point_state_type) :: point, trial
      type(replay_report_type) :: counts
      real(dp), allocatable :: zero(:), start(:), tangent(:, :)
      real(dp), allocatable :: peak(:)     ! largest |traction| reached per component (MPa)
      real(dp), allocatable :: s_low(:), s_high(:), t_low(:), t_high(:)  ! ranges of the written rows
      real(dp) :: pnewdt, last_error
      logical, allocatable :: no_control(:)
      real(dp), allocatable :: failed_s(:)      ! the separation of the last UMAT call that failed (mm)
      real(dp) :: failed_time                   ! and its time
      logical :: umat_failed                    ! whether the last attempt's UMAT call failed
      integer :: ntens, k, j, i, clock_start, clock_last, clock_rate
      logical :: check

      ok = .false.
      nrows_written = 0
      ntens = history%ntens
      allocate (zero(ntens), start(ntens), no_control(ntens), tangent(ntens, ntens), peak(ntens), failed_s(ntens))
      failed_s = 0.0_dp
      failed_time = 0.0_dp
      umat_failed = .false.
      zero = 0.0_dp
      no_control = .false.
      peak = 0.0_dp
      check = run%tangent_check > 0.0_dp
      last_error = 0.0_dp
      point = new_point(ntens, history%time(1))
      call system_clock(clock_start, clock_rate)
      clock_last = clock_start

      ! Probe: a zero increment on the virgin state checks PROPS and sizes before anything else.
      trial = point
      call call_umat(run%props, trial, zero, history%time(1), pnewdt)
      counts%umat_calls = 1
      if (pnewdt < 1.0_dp) then
         message = run%path//': the UMAT rejected the material data or sizes (NTENS = '// &
            int_to_string(ntens)//', NPROPS = '//int_to_string(size(run%props))// &
            '); see its message above'
         if (present(report)) report = counts
         return
      end if

      if (any(abs(history%separation(:, 1)) > 0.0_dp)) then
         do j = 1, run%increments
            call advance(zero, history%separation(:, 1), history%traction(:, 1), history%time(1), &
               history%time(1), real(j - 1, dp)/real(run%increments, dp), &
               real(j, dp)/real(run%increments, dp), .false., .false., ok)
            if (.not. ok) then
               if (present(report)) report = counts
               return
            end if
         end do
      end if
      call write_row(ok)
      if (.not. ok) then
         if (present(report)) report = counts
         return
      end if
      s_low = point%separation
      s_high = point%separation
      t_low = point%stress
      t_high = point%stress

      do k = 1, history%nrows - 1
         ! the segment's start values: the previous row's where the control is the same
         do i = 1, ntens
            if (history%traction(i, k) .eqv. history%traction(i, k + 1)) then
               start(i) = history%separation(i, k)
            else if (history%traction(i, k + 1)) then
               start(i) = point%stress(i)
            else
               start(i) = point%separation(i)
            end if
         end do
         do j = 1, run%increments
            call advance(start, history%separation(:, k + 1), history%traction(:, k + 1), &
               history%time(k), history%time(k + 1), &
               real(j - 1, dp)/real(run%increments, dp), real(j, dp)/real(run%increments, dp), &
               .true., j == run%increments, ok)
            if (.not. ok) then
               if (present(report)) report = counts
               return
            end if
         end do
         call show_progress(k)
      end do
      ok = .true.
      counts%moving(:ntens) = s_high - s_low > 1.0e-9_dp*(abs(s_high) + abs(s_low)) .or. &
         t_high - t_low > 1.0e-9_dp*(abs(t_high) + abs(t_low))
      if (present(report)) report = counts

   contains

      !> Move the point from fraction theta_from to theta_to of the segment from (time_a, v_a)
      !> to (time_b, v_b), halving the step when the UMAT asks for it or Newton fails.
      subroutine advance(v_a, v_b, controls, time_a, time_b, theta_from, theta_to, write_rows, &
            segment_end, success)
         real(dp), intent(in) :: v_a(:)           !! values at the segment start (mm or MPa)
         real(dp), intent(in) :: v_b(:)           !! values at the segment end (mm or MPa)
         logical, intent(in) :: controls(:)       !! true where the value is a traction
         real(dp), intent(in) :: time_a           !! time at the segment start
         real(dp), intent(in) :: time_b           !! time at the segment end
         real(dp), intent(in) :: theta_from       !! fraction of the segment already done
         real(dp), intent(in) :: theta_to         !! fraction to reach
         logical, intent(in) :: write_rows        !! write CSV rows (thinned by output_every)
         logical, intent(in) :: segment_end       !! theta_to closes the history segment
         logical, intent(out) :: success          !! false: message set
         real(dp) :: done, step, attempt, theta, time_new, residual
         real(dp), allocatable :: target(:)
         integer :: halvings, iterations
         logical :: converged

         success = .false.
         done = 0.0_dp
         step = 1.0_dp
         halvings = 0
         do while (done < 1.0_dp)
            ! done and step are dyadic fractions, so done + step reaches 1 exactly.
            attempt = min(1.0_dp, done + step)
            if (attempt >= 1.0_dp) then
               theta = theta_to
            else
               theta = theta_from + attempt*(theta_to - theta_from)
            end if
            ! Exact at both ends of the segment, and constant components stay exactly constant.
            if (theta >= 1.0_dp) then
               target = v_b
               time_new = time_b
            else
               target = v_a + theta*(v_b - v_a)
               time_new = time_a + theta*(time_b - time_a)
            end if
            call solve_step(target, controls, time_new, converged, residual, iterations)
            if (.not. converged .and. fatal_message_reported()) then
               message = run%path//': the UMAT stopped with a setup error from t = '// &
                  real_to_string(point%time)//' to t = '//real_to_string(time_new)// &
                  ' ('//values_text(target, controls)//'): '//last_fatal_message()
               call write_failed_call()
               return
            end if
            if (.not. converged) then
               halvings = halvings + 1
               if (halvings > MAX_HALVINGS) then
                  message = failure_text(target, controls, time_new, residual, iterations)
                  call write_failed_call()
                  return
               end if
               step = 0.5_dp*step
               cycle
            end if
            if (check) call check_tangent()
            if (write_rows) then
               s_low = min(s_low, trial%separation)
               s_high = max(s_high, trial%separation)
               t_low = min(t_low, trial%stress)
               t_high = max(t_high, trial%stress)
            end if
            point = trial
            where (abs(point%stress) > peak) peak = abs(point%stress)
            done = attempt
            counts%converged_steps = counts%converged_steps + 1
            if (write_rows) then
               if (mod(counts%converged_steps, run%output_every) == 0 .or. (segment_end .and. done >= 1.0_dp)) then
                  call write_row(success)
                  if (.not. success) return
                  success = .false.
               end if
            end if
         end do
         success = .true.
      end subroutine advance

      !> One step from `point` to the targets at `time_new`; `trial` holds the result. Without a
      !> traction-controlled component, one UMAT call; with one, Newton's method on the
      !> traction-controlled block of DDSDDE. `converged` false: a smaller step is needed.
      subroutine solve_step(target, controls, time_new, converged, residual, iterations)
         real(dp), intent(in) :: target(:)        !! separation (mm) or traction (MPa) per component
         logical, intent(in) :: controls(:)       !! true where `target` is a traction
         real(dp), intent(in) :: time_new         !! time at the end of the step
         logical, intent(out) :: converged
         real(dp), intent(out) :: residual        !! max |traction - imposed| of the last iteration (MPa)
         integer, intent(out) :: iterations       !! UMAT calls made
         real(dp) :: s(ntens), r(ntens), delta(ntens)
         integer :: free(ntens)
         integer :: nfree, i
         logical :: solved

         converged = .false.
         residual = 0.0_dp
         iterations = 0
         call reset_fatal_message()
         s = point%separation
         where (.not. controls) s = target
         nfree = 0
         do i = 1, ntens
            if (.not. controls(i)) cycle
            nfree = nfree + 1
            free(nfree) = i
         end do
         umat_failed = .false.
         do
            trial = point
            call call_umat(run%props, trial, s, time_new, pnewdt, tangent)
            iterations = iterations + 1
            counts%umat_calls = counts%umat_calls + 1
            if (pnewdt < 1.0_dp) then
               umat_failed = .true.
               failed_s = s
               failed_time = time_new
               return
            end if
            if (nfree == 0) exit
            r(:nfree) = trial%stress(free(:nfree)) - target(free(:nfree))
            residual = maxval(abs(r(:nfree)))
            if (residual <= run%traction_tolerance) exit
            if (iterations >= MAX_NEWTON) return
            call solve_small(tangent(free(:nfree), free(:nfree)), r(:nfree), delta(:nfree), solved)
            if (.not. solved) return
            s(free(:nfree)) = s(free(:nfree)) - delta(:nfree)
         end do
         ! the traction-controlled components' imposed values: the converged tractions are
         ! within the tolerance of them
         converged = .true.
      end subroutine solve_step

      !> Compare the converged step's DDSDDE (`tangent`) with the central finite difference over
      !> the same increment from the same incoming state (`point`, before the step is kept).
      subroutine check_tangent()
         type(point_state_type) :: probe
         real(dp) :: plus(ntens), minus(ntens), s_end(ntens), central(ntens), forward(ntens), backward(ntens)
         real(dp) :: h, pnewdt_probe, scale, error_j
         real(dp) :: column_error(ntens)
         logical :: kink
         integer :: jcol

         s_end = trial%separation
         h = run%tangent_step
         pnewdt_probe = 1.0_dp
         scale = maxval(abs(tangent))
         kink = .false.
         do jcol = 1, ntens
            probe = point
            s_end(jcol) = trial%separation(jcol) + h
            call call_umat(run%props, probe, s_end, trial%time, pnewdt_probe)
            counts%umat_calls = counts%umat_calls + 1
            if (pnewdt_probe < 1.0_dp) exit
            plus = probe%stress
            probe = point
            s_end(jcol) = trial%separation(jcol) - h
            call call_umat(run%props, probe, s_end, trial%time, pnewdt_probe)
            counts%umat_calls = counts%umat_calls + 1
            if (pnewdt_probe < 1.0_dp) exit
            minus = probe%stress
            s_end(jcol) = trial%separation(jcol)
            central = (plus - minus)/(2.0_dp*h)
            forward = (plus - trial%stress)/h
            backward = (trial%stress - minus)/h
            scale = max(scale, maxval(abs(central)))
            column_error(jcol) = maxval(abs(central - tangent(:, jcol)))
            ! one-sided differences that disagree: the map has a kink within +-h (a switch of
            ! regime, the onset or end of damage, a reversal); DDSDDE is then the derivative of
            ! one side, the one the step is on
            if (maxval(abs(forward - backward)) > run%tangent_check*max(scale, tiny(1.0_dp))) then
               kink = .true.
               error_j = min(maxval(abs(forward - tangent(:, jcol))), maxval(abs(backward - tangent(:, jcol))))
               column_error(jcol) = min(column_error(jcol), error_j)
            end if
         end do
         if (pnewdt_probe < 1.0_dp) then
            counts%unchecked_steps = counts%unchecked_steps + 1
            last_error = -1.0_dp
            return
         end if
         if (scale > 0.0_dp) then
            last_error = maxval(column_error)/scale
         else
            last_error = 0.0_dp
         end if
         counts%checked_steps = counts%checked_steps + 1
         if (kink) counts%kink_steps = counts%kink_steps + 1
         if (last_error > counts%worst_tangent_error) then
            counts%worst_tangent_error = last_error
            counts%worst_tangent_time = trial%time
         end if
      end subroutine check_tangent

      !> One CSV row of the current point (with the tangent check's error when it is on).
      subroutine write_row(written)
         logical, intent(out) :: written
         if (check) then
            call write_csv_row(csv_unit, point%time, point%separation, point%stress, point%statev, &
               point%sse, point%spd, written, message, extra=[last_error])
         else
            call write_csv_row(csv_unit, point%time, point%separation, point%stress, point%statev, &
               point%sse, point%spd, written, message)
         end if
         if (.not. written) then
            message = run%path//': '//message
            return
         end if
         nrows_written = nrows_written + 1
      end subroutine write_row

      !> The message of a step that did not converge even after MAX_HALVINGS halvings.
      function failure_text(target, controls, time_new, residual, iterations) result(text)
         real(dp), intent(in) :: target(:)
         logical, intent(in) :: controls(:)
         real(dp), intent(in) :: time_new, residual
         integer, intent(in) :: iterations
         character(len=:), allocatable :: text
         logical :: separations(ntens), tractions(ntens)
         integer :: i

         separations = .false.
         tractions = .true.
         text = run%path//': '
         if (any(controls)) then
            do i = 1, size(controls)
               if (.not. controls(i)) cycle
               if (abs(target(i)) > peak(i) .and. target(i)*point%stress(i) >= 0.0_dp) then
                  text = text//'no solution from t = '//real_to_string(point%time)//' to t = '// &
                     real_to_string(time_new)//': the imposed traction '//component_name(i, .true., ntens)//' = '// &
                     real_to_string(target(i))//' MPa is beyond the peak the material can carry (the '// &
                     'largest |'//component_name(i, .true., ntens)//'| reached is '//real_to_string(peak(i))// &
                     ' MPa; last converged state: '//values_text(point%separation, separations)// &
                     ', '//values_text(point%stress, tractions)//', D = '// &
                     real_to_string(point%statev(SV_DAMAGE))//')'
                  return
               end if
            end do
            text = text//'no converged step from t = '//real_to_string(point%time)//' to t = '// &
               real_to_string(time_new)//' ('//values_text(target, controls)//') even after '// &
               int_to_string(MAX_HALVINGS)//' halvings of the sub-increment: Newton on the UMAT tangent '// &
               'left a traction residual of '//real_to_string(residual)//' MPa after '// &
               int_to_string(iterations)//' iteration(s) (traction_tolerance = '// &
               real_to_string(run%traction_tolerance)//' MPa, at most '//int_to_string(MAX_NEWTON)//')'
         else
            text = text//'the UMAT did not converge from t = '// &
               real_to_string(point%time)//' to t = '//real_to_string(time_new)// &
               ' ('//values_text(target, controls)//') even after '// &
               int_to_string(MAX_HALVINGS)//' halvings of the sub-increment'
         end if
      end function failure_text

      !> The replay file of the UMAT call that failed last (when the step failed in the UMAT and a
      !> path was given): `interphase-point FILE` repeats it.
      subroutine write_failed_call()
         integer :: unit, ios
         if (.not. (present(replay_path) .and. umat_failed)) return
         open (newunit=unit, file=replay_path, status='replace', action='write', iostat=ios)
         if (ios /= 0) return
         call write_replay_group(unit, 'interphase-point', message, run%props, point%statev, point%stress, &
            point%sse, point%spd, point%separation, failed_s - point%separation, [point%time, point%time], &
            failed_time - point%time, 1, 1, point%kinc + 1, ios, table_file=absolute(run%table_path), &
            rcurve_file=absolute(run%rcurve_path))
         close (unit)
         if (ios == 0) message = message//'; the failed UMAT call is in '//replay_path// &
            ' (interphase-point '//replay_path//' repeats it)'
      end subroutine write_failed_call

      !> A path as the absolute path tried ('' stays '').
      function absolute(path) result(full)
         character(len=*), intent(in) :: path
         character(len=:), allocatable :: full
         full = ''
         if (len(path) > 0) full = tried_path(path)
      end function absolute

      !> Progress on standard error, every PROGRESS_SECONDS once a run has lasted that long.
      subroutine show_progress(segment)
         integer, intent(in) :: segment           !! history segments done
         integer :: clock_now
         real(dp) :: elapsed
         call system_clock(clock_now)
         if (real(clock_now - clock_last, dp) < PROGRESS_SECONDS*real(clock_rate, dp)) return
         if (segment >= history%nrows - 1) return
         clock_last = clock_now
         elapsed = real(clock_now - clock_start, dp)/real(clock_rate, dp)
         write (error_unit, '(a,i0,a,i0,a,f0.0,a,i0,a)') run%name//': segment ', segment, ' of ', &
            history%nrows - 1, ' done (t = '//real_to_string(point%time)//'), ', &
            100.0_dp*real(segment, dp)/real(history%nrows - 1, dp), ' %, ', counts%umat_calls, &
            ' UMAT calls, '//real_to_string(real(nint(elapsed), dp))//' s'
         flush (error_unit)
      end subroutine show_progress

   end subroutine replay_history

   !> Solve the small system a x = b (n <= 3) by Gaussian elimination with partial pivoting;
   !> `solved` false when a pivot is zero or the result is not finite.
   pure subroutine solve_small(a, b, x, solved)
      real(dp), intent(in) :: a(:, :)             !! the matrix (MPa/mm)
      real(dp), intent(in) :: b(:)                !! right-hand side (MPa)
      real(dp), intent(out) :: x(:)               !! solution (mm), size(b)
      logical, intent(out) :: solved
      real(dp) :: m(size(b), size(b)), row(size(b))
      real(dp) :: factor
      integer :: n, i, p, r

      n = size(b)
      m = a
      x = b
      solved = .false.
      do i = 1, n
         p = i - 1 + maxloc(abs(m(i:, i)), 1)
         if (.not. abs(m(p, i)) > 0.0_dp) return
         if (p /= i) then
            row = m(i, :)
            m(i, :) = m(p, :)
            m(p, :) = row
            factor = x(i)
            x(i) = x(p)
            x(p) = factor
         end if
         do r = i + 1, n
            factor = m(r, i)/m(i, i)
            m(r, i:) = m(r, i:) - factor*m(i, i:)
            x(r) = x(r) - factor*x(i)
         end do
      end do
      do i = n, 1, -1
         x(i) = (x(i) - sum(m(i, i + 1:)*x(i + 1:)))/m(i, i)
      end do
      solved = all(ieee_is_finite(x))
   end subroutine solve_small

   !> The name of component i (UMAT order) in the history's words, s_N or Sigma_N etc.
   pure function component_name(i, traction, ntens) result(name)
      integer, intent(in) :: i                    !! component, UMAT order (normal first)
      logical, intent(in) :: traction             !! Sigma_ (true) or s_ (false)
      integer, intent(in) :: ntens                !! 2 or 3
      character(len=:), allocatable :: name
      character(len=3), parameter :: SUFFIX(3) = [character(len=3) :: 'N', 'T1', 'T2']
      if (traction) then
         name = 'Sigma_'
      else
         name = 's_'
      end if
      if (ntens == 2 .and. i == 2) then
         name = name//'T'
         return
      end if
      name = name//trim(SUFFIX(i))
   end function component_name

   !> One UMAT call taking `point` from its separation and time to `separation_new` at
   !> `time_new`. `point` is updated in place (callers pass a copy and keep it only if
   !> pnewdt >= 1).
   subroutine call_umat(props, point, separation_new, time_new, pnewdt, tangent)
      real(dp), intent(in) :: props(:)            !! material constants (PROPS layout)
      type(point_state_type), intent(inout) :: point  !! state at the start; at the end on exit
      real(dp), intent(in) :: separation_new(:)   !! separation at the end of the step (mm)
      real(dp), intent(in) :: time_new            !! time at the end of the step
      real(dp), intent(out) :: pnewdt             !! < 1: the UMAT asks for a smaller step
      real(dp), intent(out), optional :: tangent(:, :)   !! DDSDDE of the step (MPa/mm)
      character(len=80), parameter :: CMNAME = 'INTERPHASE'
      real(dp), allocatable :: ddsdde(:, :), ddsddt(:), drplde(:), dstran(:)
      real(dp) :: scd, rpl, drpldt, time(2), temp, dtemp, predef(1), dpred(1), coords(3)
      real(dp) :: drot(3, 3), dfgrd(3, 3)
      integer :: ntens, i, jstep(4)

      ntens = size(point%separation)
      allocate (ddsdde(ntens, ntens), ddsddt(ntens), drplde(ntens), dstran(ntens))
      ddsdde = 0.0_dp
      ddsddt = 0.0_dp
      drplde = 0.0_dp
      dstran = separation_new - point%separation
      scd = 0.0_dp
      rpl = 0.0_dp
      drpldt = 0.0_dp
      ! Step time and total time at the start of the step: one step from t = 0, so both are t.
      time = [point%time, point%time]
      temp = 0.0_dp
      dtemp = 0.0_dp
      predef = 0.0_dp
      dpred = 0.0_dp
      coords = 0.0_dp
      drot = 0.0_dp
      dfgrd = 0.0_dp
      do i = 1, 3
         drot(i, i) = 1.0_dp    ! no rigid rotation
         dfgrd(i, i) = 1.0_dp   ! undeformed (unused by cohesive UMATs)
      end do
      jstep = [1, 0, 0, 0]
      pnewdt = 1.0_dp
      point%kinc = point%kinc + 1
      call umat(point%stress, point%statev, ddsdde, point%sse, point%spd, scd, rpl, ddsddt, &
         drplde, drpldt, point%separation, dstran, time, time_new - point%time, temp, dtemp, &
         predef, dpred, CMNAME, 1, ntens - 1, ntens, size(point%statev), props, size(props), &
         coords, drot, pnewdt, 1.0_dp, dfgrd, dfgrd, 1, 1, 1, 1, jstep, point%kinc)
      point%separation = separation_new
      point%time = time_new
      if (present(tangent)) tangent = ddsdde
   end subroutine call_umat

   !> A virgin material point with NTENS components at time t0: zero separation, traction,
   !> state and energies.
   pure function new_point(ntens, t0) result(point)
      integer, intent(in) :: ntens                !! 2 (2-D) or 3 (3-D)
      real(dp), intent(in) :: t0                  !! initial time
      type(point_state_type) :: point
      point%time = t0
      allocate (point%separation(ntens), point%stress(ntens), point%statev(NSTATV_VISCOUS))
      point%separation = 0.0_dp
      point%stress = 0.0_dp
      point%statev = 0.0_dp
   end function new_point

   !> Values in the history's order for messages: "(s_T, s_N) = (..., ...) mm" or, with a
   !> traction-controlled component, "s_T = ... mm, Sigma_N = ... MPa".
   function values_text(values, controls) result(text)
      real(dp), intent(in) :: values(:)           !! UMAT order: normal first (mm or MPa)
      logical, intent(in) :: controls(:)          !! true where a value is a traction
      character(len=:), allocatable :: text
      integer :: i, n, order(3)

      n = size(values)
      order(:n) = [(i, i=2, n), 1]
      if (.not. any(controls)) then
         if (n == 2) then
            text = 'separation (s_T, s_N) = ('
         else
            text = 'separation (s_T1, s_T2, s_N) = ('
         end if
         do i = 1, n - 1
            text = text//real_to_string(values(order(i)))//', '
         end do
         text = text//real_to_string(values(1))//') mm'
         return
      end if
      text = ''
      do i = 1, n
         if (i > 1) text = text//', '
         if (controls(order(i))) then
            text = text//component_name(order(i), .true., n)//' = '//real_to_string(values(order(i)))//' MPa'
         else
            text = text//component_name(order(i), .false., n)//' = '//real_to_string(values(order(i)))//' mm'
         end if
      end do
   end function values_text

end module interphase_driver_replay
