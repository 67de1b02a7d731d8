!> Replay of a history through the UMAT at one material point. The algorithm (preload,
!> sub-increments, mixed control, halvings) is the library's `interphase_mixed_control`, shared with
!> the C entry interphase_run_history; this module gives it the UMAT as the update and writes the
!> CSV rows, the tangent check, the progress lines and the messages.
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
   use interphase_status, only: STATUS_OK, STATUS_BEYOND_PEAK, STATUS_SEPARATION_OUT_OF_RANGE
   use interphase_mixed_control, only: point_law_type, path_point_type, path_failure_type, replay_history_path, &
      component_name, beyond_peak_reason, beyond_range_reason, range_traction_component, MAX_HALVINGS, MAX_NEWTON, &
      FAILURE_NONE, FAILURE_OUTPUT, FAILURE_FATAL
   implicit none
   private
   public :: replay_history, MAX_HALVINGS, MAX_NEWTON, point_state_type, new_point, call_umat, &
      replay_report_type

   !> The status of `umat_step` when the UMAT asks for a smaller increment (PNEWDT < 1), and of
   !> `umat_output` when a CSV row cannot be written: the driver words those failures itself.
   integer, parameter :: UMAT_CUT_BACK = -1
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

   !> The UMAT as the update of interphase_mixed_control's replay, with what the driver does with
   !> each converged step: the tangent check, the CSV rows, the progress lines.
   type, extends(point_law_type) :: umat_law_type
      type(case_type) :: run                      !! the case
      integer :: csv_unit = 0                     !! open CSV file
      integer :: ntens = 2
      integer :: nsegments = 0                    !! history segments
      logical :: check = .false.                  !! the tangent check is on
      type(replay_report_type) :: counts
      integer :: nrows_written = 0
      real(dp) :: last_error = 0.0_dp             !! the tangent check's error of the last step
      real(dp), allocatable :: s_low(:), s_high(:), t_low(:), t_high(:)  ! ranges of the written rows
      real(dp) :: failed_s(3) = 0.0_dp            !! the separation of the last UMAT call that failed (mm)
      real(dp) :: failed_time = 0.0_dp            !! and its time
      character(len=:), allocatable :: message    !! why a CSV row could not be written
      integer :: clock_start = 0, clock_last = 0, clock_rate = 1
   contains
      procedure :: step => umat_step
      procedure :: accept => umat_accept
      procedure :: output => umat_output
      procedure :: segment_done => umat_segment_done
   end type umat_law_type

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
      type(umat_law_type) :: law
      type(point_state_type) :: trial
      type(path_point_type) :: last
      type(path_failure_type) :: failure
      real(dp), allocatable :: zero(:)
      real(dp) :: pnewdt
      integer :: ntens

      ok = .false.
      nrows_written = 0
      ntens = history%ntens
      allocate (zero(ntens))
      zero = 0.0_dp
      law%run = run
      law%csv_unit = csv_unit
      law%ntens = ntens
      law%nsegments = history%nrows - 1
      law%check = run%tangent_check > 0.0_dp
      call system_clock(law%clock_start, law%clock_rate)
      law%clock_last = law%clock_start

      ! Probe: a zero increment on the virgin state checks PROPS, sizes and the data loaded at
      ! start-up before anything else. Its refusal is the UMAT's fatal message, repeated as it is
      ! (the driver maps no status to a cause of its own: a setup error may be PROPS, the sizes, or
      ! the table or R-curve loaded, e.g. one that does not cover D0).
      trial = new_point(ntens, history%time(1))
      call reset_fatal_message()
      call call_umat(run%props, trial, zero, history%time(1), pnewdt)
      law%counts%umat_calls = 1
      if (pnewdt < 1.0_dp) then
         if (fatal_message_reported()) then
            message = run%path//': the UMAT stopped with a setup error at its first call (the zero increment '// &
               'before the replay, NTENS = '//int_to_string(ntens)//', NPROPS = '//int_to_string(size(run%props))// &
               '): '//last_fatal_message()
         else
            message = run%path//': the UMAT asked for a smaller increment at its first call (the zero increment '// &
               'before the replay, NTENS = '//int_to_string(ntens)//', NPROPS = '//int_to_string(size(run%props))// &
               '); see its message above'
         end if
         if (present(report)) report = law%counts
         return
      end if

      ! the replay itself: interphase_mixed_control, the algorithm of the C API's
      ! interphase_run_history, with the UMAT as the update
      call replay_history_path(law, history%time, history%separation, history%traction, run%increments, &
         run%traction_tolerance, run%output_every, last, failure)
      nrows_written = law%nrows_written
      law%counts%converged_steps = failure%converged_steps
      if (present(report)) report = law%counts
      select case (failure%kind)
      case (FAILURE_NONE)
         ok = .true.
         law%counts%moving(:ntens) = law%s_high - law%s_low > 1.0e-9_dp*(abs(law%s_high) + abs(law%s_low)) .or. &
            law%t_high - law%t_low > 1.0e-9_dp*(abs(law%t_high) + abs(law%t_low))
         if (present(report)) report = law%counts
      case (FAILURE_OUTPUT)
         message = law%message
      case (FAILURE_FATAL)
         message = run%path//': the UMAT stopped with a setup error from t = '// &
            real_to_string(last%time)//' to t = '//real_to_string(failure%time_to)// &
            ' ('//values_text(failure%target(:ntens), failure%controls(:ntens))//'): '//last_fatal_message()
         call write_failed_call()
      case default
         message = failure_text()
         call write_failed_call()
      end select

   contains

      !> The message of a step that did not converge even after MAX_HALVINGS halvings.
      function failure_text() result(text)
         character(len=:), allocatable :: text
         logical :: separations(ntens), tractions(ntens)
         integer :: i

         separations = .false.
         tractions = .true.
         text = run%path//': '
         if (any(failure%controls(:ntens))) then
            if (failure%status == STATUS_BEYOND_PEAK) then
               i = failure%component
               text = text//'no solution from t = '//real_to_string(last%time)//' to t = '// &
                  real_to_string(failure%time_to)//': the imposed traction '//component_name(i, .true., ntens)// &
                  ' = '//real_to_string(failure%target(i))//' MPa is '//beyond_peak_reason(failure, ntens)// &
                  'the largest |'//component_name(i, .true., ntens)//'| reached is '// &
                  real_to_string(failure%peak(i))//' MPa; last converged state: '// &
                  values_text(last%separation(:ntens), separations)//', '// &
                  values_text(last%traction(:ntens), tractions)//', D = '// &
                  real_to_string(last%state(SV_DAMAGE))//')'
               return
            end if
            if (failure%status == STATUS_SEPARATION_OUT_OF_RANGE .and. failure%component > 0) then
               ! (an imposed compression has no peak: contact carries any; what it may need is a
               ! separation beyond the range the UMAT admits)
               i = range_traction_component(failure, ntens)
               text = text//'no solution from t = '//real_to_string(last%time)//' to t = '// &
                  real_to_string(failure%time_to)//': the imposed traction '//component_name(i, .true., ntens)// &
                  ' = '//real_to_string(failure%target(i))//' MPa '//beyond_range_reason(failure, ntens)// &
                  '; last converged state: '//values_text(last%separation(:ntens), separations)//', '// &
                  values_text(last%traction(:ntens), tractions)//', D = '//real_to_string(last%state(SV_DAMAGE))
               return
            end if
            text = text//'no converged step from t = '//real_to_string(last%time)//' to t = '// &
               real_to_string(failure%time_to)//' ('//values_text(failure%target(:ntens), failure%controls(:ntens))// &
               ') even after '//int_to_string(MAX_HALVINGS)//' halvings of the sub-increment: Newton on the '// &
               'UMAT tangent left a traction residual of '//real_to_string(failure%residual)//' MPa after '// &
               int_to_string(failure%iterations)//' iteration(s) (traction_tolerance = '// &
               real_to_string(run%traction_tolerance)//' MPa, at most '//int_to_string(MAX_NEWTON)//')'
         else
            text = text//'the UMAT did not converge from t = '// &
               real_to_string(last%time)//' to t = '//real_to_string(failure%time_to)// &
               ' ('//values_text(failure%target(:ntens), failure%controls(:ntens))//') even after '// &
               int_to_string(MAX_HALVINGS)//' halvings of the sub-increment'
         end if
      end function failure_text

      !> The replay file of the UMAT call that failed last (when the step failed in the UMAT and a
      !> path was given): `interphase-point FILE` repeats it.
      subroutine write_failed_call()
         type(point_state_type) :: point
         integer :: unit, ios
         character(len=256) :: iomsg
         if (.not. (present(replay_path) .and. failure%update_status /= STATUS_OK)) return
         point = driver_point(last)
         iomsg = ''
         open (newunit=unit, file=replay_path, status='replace', action='write', iostat=ios, iomsg=iomsg)
         if (ios /= 0) then
            message = message//'; the failed UMAT call could not be written to '//replay_path//': '//trim(iomsg)
            return
         end if
         call write_replay_group(unit, 'interphase-point', message, run%props, point%statev, point%stress, &
            point%sse, point%spd, point%separation, law%failed_s(:ntens) - point%separation, [point%time, point%time], &
            law%failed_time - point%time, 1, 1, point%kinc + 1, ios, table_file=absolute(run%table_path), &
            rcurve_file=absolute(run%rcurve_path))
         close (unit)
         if (ios == 0) then
            message = message//'; the failed UMAT call is in '//replay_path// &
               ' (interphase-point '//replay_path//' repeats it)'
         else
            message = message//'; the failed UMAT call could not be written to '//replay_path
         end if
      end subroutine write_failed_call

      !> A path as the absolute path tried ('' stays '').
      function absolute(path) result(full)
         character(len=*), intent(in) :: path
         character(len=:), allocatable :: full
         full = ''
         if (len(path) > 0) full = tried_path(path)
      end function absolute

   end subroutine replay_history

   !> The driver's update: one UMAT call (`call_umat`) from `point`.
   subroutine umat_step(law, point, separation_new, time_new, tangent, status, fatal)
      class(umat_law_type), intent(inout) :: law
      type(path_point_type), intent(inout) :: point
      real(dp), intent(in) :: separation_new(:)   !! mm
      real(dp), intent(in) :: time_new
      real(dp), intent(out) :: tangent(:, :)      !! DDSDDE (MPa/mm)
      integer, intent(out) :: status              !! STATUS_OK, or UMAT_CUT_BACK
      logical, intent(out) :: fatal               !! the UMAT reported a fatal (setup) error
      type(point_state_type) :: p
      real(dp) :: pnewdt

      p = driver_point(point)
      call reset_fatal_message()
      call call_umat(law%run%props, p, separation_new, time_new, pnewdt, tangent)
      law%counts%umat_calls = law%counts%umat_calls + 1
      status = STATUS_OK
      fatal = .false.
      if (pnewdt < 1.0_dp) then
         status = UMAT_CUT_BACK
         fatal = fatal_message_reported()
         law%failed_s(:law%ntens) = separation_new
         law%failed_time = time_new
         return
      end if
      point%time = p%time
      point%separation(:law%ntens) = p%separation
      point%traction(:law%ntens) = p%stress
      point%state = p%statev
      point%stored_energy = p%sse
      point%dissipated_energy = p%spd
      point%updates = p%kinc
   end subroutine umat_step

   !> A converged step: the tangent check, the ranges of the written part.
   subroutine umat_accept(law, old, new, tangent, output_part)
      class(umat_law_type), intent(inout) :: law
      type(path_point_type), intent(in) :: old, new
      real(dp), intent(in) :: tangent(:, :)
      logical, intent(in) :: output_part
      integer :: n
      n = law%ntens
      if (law%check) call check_tangent(law, driver_point(old), driver_point(new), tangent)
      if (output_part) then
         law%s_low = min(law%s_low, new%separation(:n))
         law%s_high = max(law%s_high, new%separation(:n))
         law%t_low = min(law%t_low, new%traction(:n))
         law%t_high = max(law%t_high, new%traction(:n))
      end if
   end subroutine umat_accept

   !> One CSV row of the point (with the tangent check's error when it is on).
   subroutine umat_output(law, point, status)
      class(umat_law_type), intent(inout) :: law
      type(path_point_type), intent(in) :: point
      integer, intent(out) :: status
      character(len=:), allocatable :: message
      logical :: written
      integer :: n
      n = law%ntens
      if (law%check) then
         call write_csv_row(law%csv_unit, point%time, point%separation(:n), point%traction(:n), point%state, &
            point%stored_energy, point%dissipated_energy, written, message, extra=[law%last_error])
      else
         call write_csv_row(law%csv_unit, point%time, point%separation(:n), point%traction(:n), point%state, &
            point%stored_energy, point%dissipated_energy, written, message)
      end if
      if (.not. written) then
         law%message = law%run%path//': '//message
         status = UMAT_CUT_BACK
         return
      end if
      status = STATUS_OK
      law%nrows_written = law%nrows_written + 1
      if (.not. allocated(law%s_low)) then
         law%s_low = point%separation(:n)
         law%s_high = point%separation(:n)
         law%t_low = point%traction(:n)
         law%t_high = point%traction(:n)
      end if
   end subroutine umat_output

   !> Progress on standard error, every PROGRESS_SECONDS once a run has lasted that long.
   subroutine umat_segment_done(law, segment, point)
      class(umat_law_type), intent(inout) :: law
      integer, intent(in) :: segment              !! history segments done
      type(path_point_type), intent(in) :: point  !! the state at its end
      integer :: clock_now
      real(dp) :: elapsed
      call system_clock(clock_now)
      if (real(clock_now - law%clock_last, dp) < PROGRESS_SECONDS*real(law%clock_rate, dp)) return
      if (segment >= law%nsegments) return
      law%clock_last = clock_now
      elapsed = real(clock_now - law%clock_start, dp)/real(law%clock_rate, dp)
      write (error_unit, '(a,i0,a,i0,a,f0.0,a,i0,a)') law%run%name//': segment ', segment, ' of ', &
         law%nsegments, ' done (t = '//real_to_string(point%time)//'), ', &
         100.0_dp*real(segment, dp)/real(law%nsegments, dp), ' %, ', law%counts%umat_calls, &
         ' UMAT calls, '//real_to_string(real(nint(elapsed), dp))//' s'
      flush (error_unit)
   end subroutine umat_segment_done

   !> Compare the converged step's DDSDDE (`tangent`) with the central finite difference over
   !> the same increment from the same incoming state (`point`, before the step is kept).
   subroutine check_tangent(law, point, trial, tangent)
      type(umat_law_type), intent(inout) :: law
      type(point_state_type), intent(in) :: point   !! the state before the step
      type(point_state_type), intent(in) :: trial   !! the state after it
      real(dp), intent(in) :: tangent(:, :)         !! the step's DDSDDE
      type(point_state_type) :: probe
      real(dp) :: plus(law%ntens), minus(law%ntens), s_end(law%ntens), central(law%ntens), &
         forward(law%ntens), backward(law%ntens)
      real(dp) :: h, pnewdt_probe, scale, error_j
      real(dp) :: column_error(law%ntens)
      logical :: kink
      integer :: jcol

      associate (counts => law%counts, run => law%run)
         s_end = trial%separation
         h = run%tangent_step
         pnewdt_probe = 1.0_dp
         scale = maxval(abs(tangent))
         kink = .false.
         do jcol = 1, law%ntens
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
            law%last_error = -1.0_dp
            return
         end if
         if (scale > 0.0_dp) then
            law%last_error = maxval(column_error)/scale
         else
            law%last_error = 0.0_dp
         end if
         counts%checked_steps = counts%checked_steps + 1
         if (kink) counts%kink_steps = counts%kink_steps + 1
         if (law%last_error > counts%worst_tangent_error) then
            counts%worst_tangent_error = law%last_error
            counts%worst_tangent_time = trial%time
         end if
      end associate
   end subroutine check_tangent

   !> The driver's form of a point of the replay (arrays of NTENS components, the UMAT's STATEV).
   pure function driver_point(point) result(p)
      type(path_point_type), intent(in) :: point
      type(point_state_type) :: p
      p = new_point(point%ntens, point%time)
      p%separation(:) = point%separation(:point%ntens)
      p%stress(:) = point%traction(:point%ntens)
      p%statev(:) = point%state
      p%sse = point%stored_energy
      p%spd = point%dissipated_energy
      p%kinc = point%updates
   end function driver_point

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
