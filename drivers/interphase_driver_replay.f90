!> Replay of a separation history through the UMAT at one material point.
!>
!> The material starts virgin (D = 0, no slip, zero traction and energies) at zero separation.
!> If the history's first row is not at zero separation, the driver first loads the point
!> radially from zero to that separation, in `increments` sub-increments at time t0 with
!> DTIME = 0; those steps are not written. The first CSV row is then the state at t0.
!> Each history segment is split into `increments` equal sub-increments and the UMAT is called
!> once per sub-increment, carrying STRESS, STATEV, SSE and SPD. When the UMAT asks for a
!> smaller increment (PNEWDT < 1) the step is halved and retried, up to MAX_HALVINGS times
!> within one sub-increment; every converged step gives one CSV row. A fatal message of the UMAT
!> (a setup error found during the run, e.g. a tabulated R-curve that does not cover the damage
!> reached) ends the replay at once with that message: no smaller step can cure it.
module interphase_driver_replay
   use interphase_kinds, only: dp
   use interphase_layout, only: NSTATV_VISCOUS
   use interphase_abaqus_interfaces, only: umat
   use interphase_driver_case, only: case_type
   use interphase_driver_history, only: history_type
   use interphase_driver_output, only: write_csv_row
   use interphase_driver_text, only: int_to_string, real_to_string
   use interphase_driver_host, only: reset_fatal_message, fatal_message_reported, last_fatal_message
   implicit none
   private
   public :: replay_history, MAX_HALVINGS, point_state_type, new_point, call_umat

   !> Largest number of halvings of one sub-increment before the driver gives up.
   integer, parameter :: MAX_HALVINGS = 10

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

contains

   !> Replay `history` through the UMAT with the case's material, writing the CSV rows (not the
   !> header) to `csv_unit`. On failure `ok` is false and `message` names the case file.
   subroutine replay_history(run, history, csv_unit, nrows_written, ok, message)
      type(case_type), intent(in) :: run         !! material (PROPS) and increments
      type(history_type), intent(in) :: history   !! prescribed separations
      integer, intent(in) :: csv_unit             !! open CSV file, header already written
      integer, intent(out) :: nrows_written       !! number of CSV rows written
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      type(point_state_type) :: point, trial
      real(dp), allocatable :: zero(:)
      real(dp) :: pnewdt
      integer :: ntens, k, j

      ok = .false.
      nrows_written = 0
      ntens = history%ntens
      allocate (zero(ntens))
      zero = 0.0_dp
      point = new_point(ntens, history%time(1))

      ! Probe: a zero increment on the virgin state checks PROPS and sizes before anything else.
      trial = point
      call call_umat(run%props, trial, zero, history%time(1), pnewdt)
      if (pnewdt < 1.0_dp) then
         message = run%path//': the UMAT rejected the material data or sizes (NTENS = '// &
            int_to_string(ntens)//', NPROPS = '//int_to_string(size(run%props))// &
            '); see its message above'
         return
      end if

      if (any(abs(history%separation(:, 1)) > 0.0_dp)) then
         do j = 1, run%increments
            call advance(zero, history%separation(:, 1), history%time(1), history%time(1), &
               real(j - 1, dp)/real(run%increments, dp), real(j, dp)/real(run%increments, dp), &
               .false., ok)
            if (.not. ok) return
         end do
      end if
      call write_csv_row(csv_unit, point%time, point%separation, point%stress, point%statev, &
         point%sse, point%spd, ok, message)
      if (.not. ok) then
         message = run%path//': '//message
         return
      end if
      nrows_written = 1

      do k = 1, history%nrows - 1
         do j = 1, run%increments
            call advance(history%separation(:, k), history%separation(:, k + 1), &
               history%time(k), history%time(k + 1), &
               real(j - 1, dp)/real(run%increments, dp), real(j, dp)/real(run%increments, dp), &
               .true., ok)
            if (.not. ok) return
         end do
      end do
      ok = .true.

   contains

      !> Move the point from fraction theta_from to theta_to of the segment from (time_a, s_a)
      !> to (time_b, s_b), halving the step when the UMAT asks for it.
      subroutine advance(s_a, s_b, time_a, time_b, theta_from, theta_to, write_rows, success)
         real(dp), intent(in) :: s_a(:)           !! separation at the segment start (mm)
         real(dp), intent(in) :: s_b(:)           !! separation at the segment end (mm)
         real(dp), intent(in) :: time_a           !! time at the segment start
         real(dp), intent(in) :: time_b           !! time at the segment end
         real(dp), intent(in) :: theta_from       !! fraction of the segment already done
         real(dp), intent(in) :: theta_to         !! fraction to reach
         logical, intent(in) :: write_rows        !! write a CSV row per converged step
         logical, intent(out) :: success          !! false: message set
         real(dp) :: done, step, attempt, theta, time_new
         real(dp), allocatable :: s_new(:)
         integer :: halvings
         logical :: written

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
               s_new = s_b
               time_new = time_b
            else
               s_new = s_a + theta*(s_b - s_a)
               time_new = time_a + theta*(time_b - time_a)
            end if
            trial = point
            call reset_fatal_message()
            call call_umat(run%props, trial, s_new, time_new, pnewdt)
            if (pnewdt < 1.0_dp .and. fatal_message_reported()) then
               message = run%path//': the UMAT stopped with a setup error from t = '// &
                  real_to_string(point%time)//' to t = '//real_to_string(time_new)// &
                  ' (separation '//separation_text(s_new)//' mm): '//last_fatal_message()
               return
            end if
            if (pnewdt < 1.0_dp) then
               halvings = halvings + 1
               if (halvings > MAX_HALVINGS) then
                  success = .false.
                  message = run%path//': the UMAT did not converge from t = '// &
                     real_to_string(point%time)//' to t = '//real_to_string(time_new)// &
                     ' (separation '//separation_text(s_new)//' mm) even after '// &
                     int_to_string(MAX_HALVINGS)//' halvings of the sub-increment'
                  return
               end if
               step = 0.5_dp*step
               cycle
            end if
            point = trial
            done = attempt
            if (write_rows) then
               call write_csv_row(csv_unit, point%time, point%separation, point%stress, &
                  point%statev, point%sse, point%spd, written, message)
               if (.not. written) then
                  message = run%path//': '//message
                  return
               end if
               nrows_written = nrows_written + 1
            end if
         end do
         success = .true.
      end subroutine advance

   end subroutine replay_history

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

   !> Separation in the CSV/history order for messages: "(s_T, s_N)" or "(s_T1, s_T2, s_N)".
   function separation_text(separation) result(text)
      real(dp), intent(in) :: separation(:)       !! UMAT order: normal first (mm)
      character(len=:), allocatable :: text
      integer :: i

      if (size(separation) == 2) then
         text = '(s_T, s_N) = ('
      else
         text = '(s_T1, s_T2, s_N) = ('
      end if
      do i = 2, size(separation)
         text = text//real_to_string(separation(i))//', '
      end do
      text = text//real_to_string(separation(1))//')'
   end function separation_text

end module interphase_driver_replay
