!> Replay of a loading history at one material point under mixed control: each component of the
!> history is given either as its separation (mm) or as its traction (MPa), and that choice may
!> change from one segment to the next. The one algorithm of the single-point driver
!> interphase-point (which updates through the Abaqus UMAT) and of the C entry
!> interphase_run_history (which updates through the kernel, as the UMAT does): they differ only
!> in the update and in what they do with a converged step, which they give as the type-bound
!> procedures of an extension of `point_law_type`.
!>
!> The point starts virgin (D = 0, no slip, zero traction and energies) at zero separation at the
!> first time. If the history's first row is not zero, the point is first taken from zero to it
!> in `increments` sub-increments at that time (dt = 0); those steps give no output row. The
!> first output row is then the state at the first time. Each history segment is split into
!> `increments` equal sub-increments.
!>
!> A traction-controlled component is solved for: its separation is the unknown of Newton's
!> method on the update's tangent (the traction-controlled block of d traction / d separation),
!> from the separation of the last converged state, each iteration one update from that state;
!> a step has converged when every traction-controlled component is within `tolerance` (MPa) of
!> its imposed value, in at most MAX_NEWTON updates. The imposed values run linearly over the
!> segment from its start value: the previous row's value where the component had the same
!> control there (a constant traction stays exactly constant), else the point's current value.
!>
!> Sub-stepping: when an update fails (a status other than STATUS_OK) or Newton does not
!> converge, the step is halved and retried, up to MAX_HALVINGS times within one sub-increment.
!> When that is not enough and an imposed traction is being raised beyond the largest the point
!> reached, no solution exists: STATUS_BEYOND_PEAK. Nor is a state where Newton meets a non-zero
!> imposed traction on a numerically flat tangent (a pivot of the traction-controlled block at
!> most FLAT_STIFFNESS times the largest tangent entry met in the replay, the virgin point's
!> first: a zero increment before the first step) a solution (a zero one
!> is: a traction-free crack is one at any opening). There the traction is carried by round-off,
!> as on a fully damaged open micromechanical crack, whose table stiffnesses would otherwise meet
!> any imposed traction at a separation of 1e11 mm or more (drivers/README.md, 'Mixed control').
!> Newton may pass through such states; it may not stop there. An open crack with a flat normal
!> stiffness under an imposed compression (s_N > 0, Sigma_N < 0 imposed) is taken to its closure
!> point s_N = 0 in one iteration, from where Newton goes on in contact (`newton_step`). A step that still fails after the
!> halvings on such a state is STATUS_BEYOND_PEAK too, with failure%flat. A compression imposed on
!> the normal component has no peak (contact carries any): a step whose Newton iterate still
!> leaves the separation range the updates admit (|s_i| <= SEPARATION_MAX, 1e20 mm) after the
!> halvings is STATUS_SEPARATION_OUT_OF_RANGE, the imposed traction needing a separation beyond it
!> (failure%component, failure%iterate). An update failure that the update marks as
!> fatal (a setup error found during the run: no smaller step can cure it) ends the replay at
!> once.
!>
!> No I/O, no module data: the outcome is a status and a `path_failure_type` that says where and
!> why; each caller words its own message (`describe_failure` words the library's).
module interphase_mixed_control
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use interphase_kinds, only: dp
   use interphase_real_text, only: real_text, es_field
   use interphase_layout, only: NSTATV_VISCOUS
   use interphase_status, only: STATUS_OK, STATUS_BEYOND_PEAK, STATUS_MIXED_NOT_CONVERGED, MESSAGE_LEN, &
      STATUS_SEPARATION_OUT_OF_RANGE
   use interphase_params, only: SEPARATION_MAX
   implicit none
   private
   public :: path_point_type, point_law_type, path_failure_type, replay_history_path, virgin_point, solve_small, &
      describe_failure, component_name, beyond_peak_reason, beyond_range_reason, range_traction_component

   !> Largest number of halvings of one sub-increment before the replay gives up.
   integer, parameter, public :: MAX_HALVINGS = 10
   !> Largest number of Newton iterations (updates) of one mixed-control step.
   integer, parameter, public :: MAX_NEWTON = 25
   !> A converged state whose traction-controlled block of the tangent has a pivot at most
   !> FLAT_STIFFNESS times the largest |tangent entry| the replay has met (the intact point's
   !> stiffness, as a rule) is no solution (-). The fully damaged micromechanical point's
   !> stiffnesses are round-off of zero: on the built-in table 4.5e-16 of the intact ones open
   !> (k_n at D = 1) and about 5e-15
   !> when the closed crack slips at sigma = 0, where C^f_T lambda cancels (k_t + kc_t) s_T. A
   !> stiffness of 1e-12 K would need a separation of 1e10 times s0 or more to carry a traction of
   !> the order of the strength.
   real(dp), parameter, public :: FLAT_STIFFNESS = 1.0e-12_dp
   !> The loosest traction tolerance (MPa) a replay takes: Newton accepts an iterate whose
   !> traction-controlled components are within the tolerance of their imposed values, so a
   !> looser one leaves an imposed traction unmet by as much (at 1 MPa a precompression of
   !> 0.5 MPa is not applied at all), against joint tractions of 0.01 to 10 MPa. Defaults:
   !> 1e-12 MPa (interphase-point, the C API's callers).
   real(dp), parameter, public :: TRACTION_TOLERANCE_MAX = 1.0e-3_dp

   !> What ended a replay that did not reach the end of its history.
   integer, parameter, public :: FAILURE_NONE = 0      !! the history was replayed to its end
   integer, parameter, public :: FAILURE_FATAL = 1     !! an update failed with a fatal status
   integer, parameter, public :: FAILURE_HALVINGS = 2  !! a step still failed after MAX_HALVINGS halvings
   integer, parameter, public :: FAILURE_OUTPUT = 3    !! the `output` procedure stopped the replay

   !> The state of the material point between two updates. Arrays hold 3 components; the first
   !> `ntens` count, normal first (the UMAT's and the C interface's order).
   type :: path_point_type
      integer :: ntens = 2                        !! 2 (2-D) or 3 (3-D)
      real(dp) :: time = 0.0_dp                   !! t of the state
      real(dp) :: separation(3) = 0.0_dp          !! s (mm)
      real(dp) :: traction(3) = 0.0_dp            !! traction (MPa)
      real(dp) :: state(NSTATV_VISCOUS) = 0.0_dp  !! the UMAT's STATEV slots (docs/abaqus.md)
      real(dp) :: stored_energy = 0.0_dp          !! psi, the UMAT's SSE (N/mm)
      real(dp) :: dissipated_energy = 0.0_dp      !! the UMAT's SPD (N/mm)
      integer :: updates = 0                      !! updates made so far (the UMAT's KINC)
   end type path_point_type

   !> Where and why a replay stopped early; `status` is STATUS_OK when it did not.
   type :: path_failure_type
      integer :: status = STATUS_OK               !! the replay's status
      integer :: kind = FAILURE_NONE              !! FAILURE_*
      !> the last update's status (STATUS_OK when the last attempt failed in Newton, not in an update)
      integer :: update_status = STATUS_OK
      real(dp) :: time_to = 0.0_dp                !! the time of the step that failed
      real(dp) :: target(3) = 0.0_dp              !! its imposed values (mm or MPa)
      logical :: controls(3) = .false.            !! true where `target` is a traction
      real(dp) :: residual = 0.0_dp               !! Newton: max |traction - imposed| left (MPa)
      integer :: iterations = 0                   !! Newton: updates of the last attempt
      !> STATUS_BEYOND_PEAK: the component (UMAT order) whose imposed traction is beyond the peak
      integer :: component = 0
      real(dp) :: peak(3) = 0.0_dp                !! largest |traction| reached per component (MPa)
      integer :: converged_steps = 0              !! steps kept (output or not)
      !> the last attempt met the imposed traction(s) only on a flat tangent (FLAT_STIFFNESS):
      !> with STATUS_BEYOND_PEAK, the point no longer carries load in failure%component
      logical :: flat = .false.
      !> STATUS_SEPARATION_OUT_OF_RANGE (in failure%component): the separation of the last
      !> attempt's Newton iterate there, beyond SEPARATION_MAX (mm)
      real(dp) :: iterate = 0.0_dp
   end type path_failure_type

   !> A material point's update and what to do with each converged step: extended by each caller.
   type, abstract :: point_law_type
   contains
      !> One update of `point` to `separation_new` at `time_new` (deferred).
      procedure(law_step), deferred :: step
      !> A converged step, before it is kept (default: nothing).
      procedure :: accept => accept_nothing
      !> A row of the replay's output (default: nothing).
      procedure :: output => output_nothing
      !> The end of a history segment (default: nothing).
      procedure :: segment_done => segment_done_nothing
   end type point_law_type

   abstract interface
      !> Update `point` from its separation and time to `separation_new` at `time_new` (the
      !> increment separation_new - separation); on STATUS_OK `point` holds the state at the end
      !> and `tangent` d traction / d separation (MPa/mm). On another status `point` is not used;
      !> `fatal` true says that no smaller step can help.
      subroutine law_step(law, point, separation_new, time_new, tangent, status, fatal)
         import :: point_law_type, path_point_type, dp
         class(point_law_type), intent(inout) :: law
         type(path_point_type), intent(inout) :: point
         real(dp), intent(in) :: separation_new(:)
         real(dp), intent(in) :: time_new
         real(dp), intent(out) :: tangent(:, :)
         integer, intent(out) :: status
         logical, intent(out) :: fatal
      end subroutine law_step
   end interface

contains

   subroutine accept_nothing(law, old, new, tangent, output_part)
      class(point_law_type), intent(inout) :: law
      type(path_point_type), intent(in) :: old     !! the state before the step
      type(path_point_type), intent(in) :: new     !! the state after it
      real(dp), intent(in) :: tangent(:, :)       !! the step's tangent (MPa/mm)
      logical, intent(in) :: output_part           !! false during the preload (no rows)
      associate (unused => law, u2 => old, u3 => new, u4 => tangent, u5 => output_part)
      end associate
   end subroutine accept_nothing

   subroutine output_nothing(law, point, status)
      class(point_law_type), intent(inout) :: law
      type(path_point_type), intent(in) :: point   !! the row's state
      integer, intent(out) :: status               !! not STATUS_OK: stop the replay with it
      associate (unused => law, u2 => point)
      end associate
      status = STATUS_OK
   end subroutine output_nothing

   subroutine segment_done_nothing(law, segment, point)
      class(point_law_type), intent(inout) :: law
      integer, intent(in) :: segment               !! history segments done
      type(path_point_type), intent(in) :: point   !! the state at its end
      associate (unused => law, u2 => segment, u3 => point)
      end associate
   end subroutine segment_done_nothing

   !> A virgin point with NTENS components at time t0: zero separation, traction, state, energies.
   pure function virgin_point(ntens, t0) result(point)
      integer, intent(in) :: ntens                 !! 2 or 3
      real(dp), intent(in) :: t0                   !! initial time
      type(path_point_type) :: point
      point%ntens = ntens
      point%time = t0
   end function virgin_point

   !> Replay the history (`time(k)`, `value(:, k)`, `traction_control(:, k)`; UMAT order, normal
   !> first; the segment that ends at row k is controlled as row k says) from a virgin point.
   !> `law%output` receives the first row and then every `output_every`-th converged step (counted
   !> from the first step, the preload's included) and the end of every segment. On return
   !> `point` is the last converged state and `failure%status` STATUS_OK, or the status of the
   !> failure that ended the replay (the rows up to it were output).
   subroutine replay_history_path(law, time, value, traction_control, increments, tolerance, output_every, point, &
         failure)
      class(point_law_type), intent(inout) :: law
      real(dp), intent(in) :: time(:)              !! nrows times, strictly increasing, each step time(k+1) - time(k) finite
      real(dp), intent(in) :: value(:, :)          !! (ntens, nrows): mm, or MPa where traction-controlled
      logical, intent(in) :: traction_control(:, :)  !! (ntens, nrows): true where a traction
      integer, intent(in) :: increments            !! sub-increments per segment (>= 1)
      real(dp), intent(in) :: tolerance            !! traction tolerance (MPa, > 0)
      integer, intent(in) :: output_every          !! output every k-th converged step (>= 1)
      type(path_point_type), intent(out) :: point
      type(path_failure_type), intent(out) :: failure
      real(dp) :: zero(size(value, 1)), start(size(value, 1))
      !> the largest |tangent entry| of the virgin point and the converged steps so far (MPa/mm)
      real(dp) :: stiffness_scale
      integer :: ntens, nrows, k, j, i
      logical :: ok

      ntens = size(value, 1)
      nrows = size(value, 2)
      zero = 0.0_dp
      point = virgin_point(ntens, time(1))
      ! the scale of the flat tests starts at the virgin point's tangent (a zero increment): the
      ! first converged step may already be flat (an opening that breaks the crack through), and
      ! a flat tangent's round-off is no scale (the micromechanical model's fully damaged crack
      ! keeps entries of order 1e-13 of its virgin ones). An update that fails here fails again
      ! in the first step, which reports it.
      stiffness_scale = 0.0_dp
      block
         type(path_point_type) :: probe
         real(dp) :: probe_tangent(3, 3)
         integer :: probe_status
         logical :: probe_fatal
         probe = point
         call law%step(probe, zero, time(1), probe_tangent(:ntens, :ntens), probe_status, probe_fatal)
         if (probe_status == STATUS_OK) stiffness_scale = maxval(abs(probe_tangent(:ntens, :ntens)))
      end block
      if (any(abs(value(:, 1)) > 0.0_dp)) then
         do j = 1, increments
            call advance(zero, value(:, 1), traction_control(:, 1), time(1), time(1), &
               real(j - 1, dp)/real(increments, dp), real(j, dp)/real(increments, dp), .false., .false., ok)
            if (.not. ok) return
         end do
      end if
      call law%output(point, failure%status)
      if (failure%status /= STATUS_OK) then
         failure%kind = FAILURE_OUTPUT
         return
      end if

      do k = 1, nrows - 1
         ! the segment's start values: the previous row's where the control is the same
         do i = 1, ntens
            if (traction_control(i, k) .eqv. traction_control(i, k + 1)) then
               start(i) = value(i, k)
            else if (traction_control(i, k + 1)) then
               start(i) = point%traction(i)
            else
               start(i) = point%separation(i)
            end if
         end do
         do j = 1, increments
            call advance(start, value(:, k + 1), traction_control(:, k + 1), time(k), time(k + 1), &
               real(j - 1, dp)/real(increments, dp), real(j, dp)/real(increments, dp), .true., &
               j == increments, ok)
            if (.not. ok) return
         end do
         call law%segment_done(k, point)
      end do

   contains

      !> Move the point from fraction theta_from to theta_to of the segment from (time_a, v_a)
      !> to (time_b, v_b), halving the step when an update fails or Newton does not converge.
      subroutine advance(v_a, v_b, controls, time_a, time_b, theta_from, theta_to, output_part, &
            segment_end, success)
         real(dp), intent(in) :: v_a(:)           !! values at the segment start (mm or MPa)
         real(dp), intent(in) :: v_b(:)           !! values at the segment end (mm or MPa)
         logical, intent(in) :: controls(:)       !! true where the value is a traction
         real(dp), intent(in) :: time_a           !! time at the segment start
         real(dp), intent(in) :: time_b           !! time at the segment end
         real(dp), intent(in) :: theta_from       !! fraction of the segment already done
         real(dp), intent(in) :: theta_to         !! fraction to reach
         logical, intent(in) :: output_part       !! rows are output (thinned by output_every)
         logical, intent(in) :: segment_end       !! theta_to closes the history segment
         logical, intent(out) :: success          !! false: `failure` set
         type(path_point_type) :: trial
         real(dp) :: done, step, attempt, theta, time_new, residual
         ! fixed sizes, the first ntens used: no allocation per step
         real(dp) :: target(3), tangent(3, 3)
         integer :: halvings, iterations, status, flat_component, range_component
         real(dp) :: range_separation
         logical :: converged, fatal

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
               target(:ntens) = v_b
               time_new = time_b
            else
               target(:ntens) = v_a + theta*(v_b - v_a)
               time_new = time_a + theta*(time_b - time_a)
            end if
            call solve_step(law, point, target(:ntens), controls, time_new, tolerance, stiffness_scale, trial, &
               tangent(:ntens, :ntens), converged, status, fatal, residual, iterations, flat_component, &
               range_component, range_separation)
            if (.not. converged) then
               if (status /= STATUS_OK .and. fatal) then
                  call record_failure(failure, FAILURE_FATAL, status, time_new, target(:ntens), controls, residual, &
                     iterations, point, 0, 0, 0.0_dp)
                  return
               end if
               halvings = halvings + 1
               if (halvings > MAX_HALVINGS) then
                  call record_failure(failure, FAILURE_HALVINGS, status, time_new, target(:ntens), controls, residual, &
                     iterations, point, flat_component, range_component, range_separation)
                  return
               end if
               step = 0.5_dp*step
               cycle
            end if
            call law%accept(point, trial, tangent(:ntens, :ntens), output_part)
            point = trial
            stiffness_scale = max(stiffness_scale, maxval(abs(tangent(:ntens, :ntens))))
            where (abs(point%traction(:ntens)) > failure%peak(:ntens)) failure%peak(:ntens) = abs(point%traction(:ntens))
            done = attempt
            failure%converged_steps = failure%converged_steps + 1
            if (output_part) then
               if (mod(failure%converged_steps, output_every) == 0 .or. (segment_end .and. done >= 1.0_dp)) then
                  call law%output(point, failure%status)
                  if (failure%status /= STATUS_OK) then
                     failure%kind = FAILURE_OUTPUT
                     return
                  end if
               end if
            end if
         end do
         success = .true.


      end subroutine advance

   end subroutine replay_history_path

   !> Record the failure of the step to `target` at `time_new` from `point`: its status is the
   !> update's, or, for a mixed-control step still failing after the halvings, STATUS_BEYOND_PEAK
   !> (an imposed traction raised beyond the largest one reached, or met only on a flat tangent:
   !> `flat_component` > 0, has no solution; an imposed compression on the normal component never
   !> is: contact carries any), STATUS_SEPARATION_OUT_OF_RANGE (the last attempt's Newton iterate
   !> left |s_i| <= SEPARATION_MAX in `range_component`: the imposed traction needs a separation
   !> beyond the range) or STATUS_MIXED_NOT_CONVERGED (Newton failed, no update did).
   pure subroutine record_failure(failure, kind, update_status, time_new, target, controls, residual, &
         iterations, point, flat_component, range_component, range_separation)
      type(path_failure_type), intent(inout) :: failure
      integer, intent(in) :: kind, update_status, iterations
      integer, intent(in) :: flat_component     !! the flat component of the last attempt, or 0
      integer, intent(in) :: range_component    !! the component out of range in the last attempt, or 0
      real(dp), intent(in) :: range_separation  !! its separation there (mm)
      real(dp), intent(in) :: time_new, target(:), residual
      logical, intent(in) :: controls(:)
      type(path_point_type), intent(in) :: point
      integer :: c, ntens
      ntens = size(target)
      failure%kind = kind
      failure%update_status = update_status
      failure%time_to = time_new
      failure%target(:ntens) = target
      failure%controls(:ntens) = controls
      failure%residual = residual
      failure%iterations = iterations
      failure%status = update_status
      failure%flat = .false.
      if (kind /= FAILURE_HALVINGS .or. .not. any(controls)) return
      if (flat_component > 0 .and. update_status == STATUS_OK) then
         failure%component = flat_component
         failure%status = STATUS_BEYOND_PEAK
         failure%flat = .true.
         return
      end if
      do c = 1, ntens
         if (.not. controls(c)) cycle
         ! (a compression, Sigma_N < 0, has no peak: the closed crack's contact carries any)
         if (c == 1 .and. target(c) < 0.0_dp) cycle
         if (abs(target(c)) > failure%peak(c) .and. target(c)*point%traction(c) >= 0.0_dp) then
            failure%component = c
            failure%status = STATUS_BEYOND_PEAK
            return
         end if
      end do
      if (range_component > 0) then
         failure%component = range_component
         failure%iterate = range_separation
         failure%status = STATUS_SEPARATION_OUT_OF_RANGE
         return
      end if
      if (update_status == STATUS_OK) failure%status = STATUS_MIXED_NOT_CONVERGED
   end subroutine record_failure

   !> One step from `point` to the targets at `time_new`; `trial` holds the result. Without a
   !> traction-controlled component, one update; with one, Newton's method on the
   !> traction-controlled block of the tangent; where it meets the targets, the block's pivots must
   !> exceed FLAT_STIFFNESS times the larger of `stiffness_scale` and that state's largest
   !> |tangent entry| (else no convergence, and `flat_component` names the flat one). `converged`
   !> false: a smaller step is needed (`status` the failed update's, or STATUS_OK when Newton
   !> failed; `range_component` > 0 where the failed update was at an iterate beyond
   !> SEPARATION_MAX in that component).
   subroutine solve_step(law, point, target, controls, time_new, tolerance, stiffness_scale, trial, tangent, &
         converged, status, fatal, residual, iterations, flat_component, range_component, range_separation)
      class(point_law_type), intent(inout) :: law
      type(path_point_type), intent(in) :: point   !! the last converged state
      real(dp), intent(in) :: target(:)           !! separation (mm) or traction (MPa) per component
      logical, intent(in) :: controls(:)          !! true where `target` is a traction
      real(dp), intent(in) :: time_new            !! time at the end of the step
      real(dp), intent(in) :: tolerance           !! MPa
      !> the largest |tangent entry| of the virgin point and the replay's converged steps (MPa/mm;
      !> 0 when the virgin point's update failed)
      real(dp), intent(in) :: stiffness_scale
      type(path_point_type), intent(inout) :: trial  !! the state at the end of the step
      real(dp), intent(out) :: tangent(:, :)      !! its tangent (MPa/mm)
      logical, intent(out) :: converged
      integer, intent(out) :: status              !! the last update's status
      logical, intent(out) :: fatal               !! the last update failed for good
      real(dp), intent(out) :: residual           !! max |traction - imposed| of the last iteration (MPa)
      integer, intent(out) :: iterations          !! updates made
      !> where the targets were met only on a flat tangent: the first flat component (a flat
      !> diagonal entry; any, when the block is singular through its coupling) whose target is
      !> not zero; else 0
      integer, intent(out) :: flat_component
      !> where the last update failed at an iterate beyond SEPARATION_MAX: the first such
      !> component, else 0; and the iterate's separation there (mm)
      integer, intent(out) :: range_component
      real(dp), intent(out) :: range_separation
      ! fixed sizes, the first ntens (nfree) used: no allocation per iteration
      real(dp) :: s(3), r(3), delta(3), block(3, 3), flat_bound
      integer :: free(3)
      integer :: nfree, i, ntens
      logical :: solved
      real(dp) :: zero_traction

      ntens = size(target)
      converged = .false.
      fatal = .false.
      status = STATUS_OK
      residual = 0.0_dp
      iterations = 0
      flat_component = 0
      range_component = 0
      range_separation = 0.0_dp
      s(:ntens) = point%separation(:ntens)
      where (.not. controls) s(:ntens) = target
      nfree = 0
      do i = 1, ntens
         if (.not. controls(i)) cycle
         nfree = nfree + 1
         free(nfree) = i
      end do
      do
         trial = point
         call law%step(trial, s(:ntens), time_new, tangent, status, fatal)
         iterations = iterations + 1
         if (status /= STATUS_OK) then
            do i = 1, ntens
               if (abs(s(i)) > SEPARATION_MAX) then
                  range_component = i
                  range_separation = s(i)
                  exit
               end if
            end do
            return
         end if
         if (nfree == 0) exit
         r(:nfree) = trial%traction(free(:nfree)) - target(free(:nfree))
         residual = maxval(abs(r(:nfree)))
         block(:nfree, :nfree) = tangent(free(:nfree), free(:nfree))
         if (residual <= tolerance) then
            ! met: a solution only where the tangent carries the traction (not round-off), or
            ! where the traction met on a flat tangent is zero (a traction-free crack is one at
            ! any opening)
            flat_bound = FLAT_STIFFNESS*max(stiffness_scale, maxval(abs(tangent)))
            call solve_small(block(:nfree, :nfree), r(:nfree), delta(:nfree), solved, flat_bound)
            if (solved) exit
            ! the flat components: those with a flat diagonal entry (all of them when the block
            ! is singular only through its coupling); a solution when each has a zero target:
            ! at most the tolerance, or what a flat stiffness carries at the last converged
            ! separation (round-off, not the separation Newton may have reached on it)
            zero_traction = max(tolerance, flat_bound*maxval(abs(point%separation(:ntens))))
            call flat_target(nfree, free, block, target, flat_bound, zero_traction, flat_component)
            ! every flat component traction-free: a solution
            if (flat_component == 0) exit
            return
         end if
         if (iterations >= MAX_NEWTON) return
         call newton_step(nfree, free, block, r, target, stiffness_scale, s, solved)
         if (.not. solved) then
            ! no Newton step: the block is singular, as where a stiffness is exactly zero (the
            ! simplified model's fully damaged open crack, a friction plateau): a flat component
            ! whose target is not zero is one the point cannot carry (flat_component, as above)
            flat_bound = FLAT_STIFFNESS*max(stiffness_scale, maxval(abs(tangent)))
            zero_traction = max(tolerance, flat_bound*maxval(abs(point%separation(:ntens))))
            call flat_target(nfree, free, block, target, flat_bound, zero_traction, flat_component)
            return
         end if
      end do
      converged = .true.
   end subroutine solve_step

   !> The first flat component of the traction-controlled block whose target is not zero, or 0:
   !> flat are those with a diagonal entry at most flat_bound (all of them when the block is
   !> singular only through its coupling); zero a target at most zero_traction (MPa).
   pure subroutine flat_target(nfree, free, block, target, flat_bound, zero_traction, flat_component)
      integer, intent(in) :: nfree                !! traction-controlled components (>= 1)
      integer, intent(in) :: free(3)              !! which (UMAT order)
      real(dp), intent(in) :: block(3, 3)         !! their block of the tangent (MPa/mm)
      real(dp), intent(in) :: target(:)           !! imposed values, all components
      real(dp), intent(in) :: flat_bound          !! the largest flat |stiffness| (MPa/mm)
      real(dp), intent(in) :: zero_traction       !! the largest zero |traction| (MPa)
      integer, intent(out) :: flat_component
      logical :: flat(3)
      integer :: i
      do i = 1, nfree
         flat(i) = .not. abs(block(i, i)) > flat_bound
      end do
      if (.not. any(flat(:nfree))) flat(:nfree) = .true.   ! singular through the coupling only
      ! (a loop, not findloc over a masked section: GCC 12's LTO fails on that form, an internal
      ! compiler error)
      flat_component = 0
      do i = nfree, 1, -1
         if (flat(i) .and. abs(target(free(i))) > zero_traction) flat_component = free(i)
      end do
   end subroutine flat_target

   !> One Newton step of `solve_step` on the traction-controlled block: s(free) - delta with
   !> block delta = r, or the closure step. The closure step: an open crack whose normal stiffness
   !> is flat (fully damaged) under an imposed compression. Every interphase law closes its crack
   !> at s_N = 0 (contact, the full normal stiffness, for s_N <= 0), and a fully damaged open crack
   !> carries no compression (with the contact band, the band's share near s_N = 0 is not flat and
   !> Newton steps as usual); a flat stiffness gives Newton no step there (exactly zero
   !> in the simplified model; round-off in the micromechanical one, whose step would overshoot by
   !> ~1e13 mm), so the next iterate is the closure point itself, from where Newton goes on in
   !> contact. Flat: at most FLAT_STIFFNESS times the replay's largest stiffness so far.
   pure subroutine newton_step(nfree, free, block, r, target, stiffness_scale, s, solved)
      integer, intent(in) :: nfree                !! traction-controlled components (>= 1)
      integer, intent(in) :: free(3)              !! which (UMAT order)
      real(dp), intent(in) :: block(3, 3)         !! their block of the tangent (MPa/mm)
      real(dp), intent(in) :: r(3)                !! traction - imposed (MPa)
      real(dp), intent(in) :: target(:)           !! imposed values, all components
      real(dp), intent(in) :: stiffness_scale     !! the replay's largest |tangent entry| (MPa/mm)
      real(dp), intent(inout) :: s(3)             !! separation (mm): the next iterate on return
      logical, intent(out) :: solved              !! false: no step (a singular block)
      real(dp) :: delta(3)
      ! (the normal component, when traction-controlled, is the block's first)
      if (free(1) == 1 .and. s(1) > 0.0_dp .and. target(1) < 0.0_dp .and. &
         abs(block(1, 1)) <= FLAT_STIFFNESS*stiffness_scale) then
         s(1) = 0.0_dp
         solved = .true.
         return
      end if
      call solve_small(block(:nfree, :nfree), r(:nfree), delta(:nfree), solved)
      if (solved) s(free(:nfree)) = s(free(:nfree)) - delta(:nfree)
   end subroutine newton_step

   !> Solve the small system a x = b (n <= 3) by Gaussian elimination with partial pivoting;
   !> `solved` false when a pivot is not above `pivot_min` in magnitude (default 0) or the result
   !> is not finite.
   pure subroutine solve_small(a, b, x, solved, pivot_min)
      real(dp), intent(in) :: a(:, :)             !! the matrix (MPa/mm)
      real(dp), intent(in) :: b(:)                !! right-hand side (MPa)
      real(dp), intent(out) :: x(:)               !! solution (mm), size(b)
      logical, intent(out) :: solved
      real(dp), intent(in), optional :: pivot_min !! the largest |pivot| taken as zero (MPa/mm)
      real(dp) :: m(3, 3), row(3)   ! the first n x n used (n <= 3): no allocation
      real(dp) :: factor, smallest
      integer :: n, i, p, r

      smallest = 0.0_dp
      if (present(pivot_min)) smallest = pivot_min
      n = size(b)
      m(:n, :n) = a
      x = b
      solved = .false.
      do i = 1, n
         p = i - 1 + maxloc(abs(m(i:n, i)), 1)
         if (.not. abs(m(p, i)) > smallest) return
         if (p /= i) then
            row(:n) = m(i, :n)
            m(i, :n) = m(p, :n)
            m(p, :n) = row(:n)
            factor = x(i)
            x(i) = x(p)
            x(p) = factor
         end if
         do r = i + 1, n
            factor = m(r, i)/m(i, i)
            m(r, i:n) = m(r, i:n) - factor*m(i, i:n)
            x(r) = x(r) - factor*x(i)
         end do
      end do
      do i = n, 1, -1
         x(i) = (x(i) - sum(m(i, i + 1:n)*x(i + 1:n)))/m(i, i)
      end do
      solved = all(ieee_is_finite(x))
   end subroutine solve_small

   !> The name of component i (UMAT order) in a history's words: s_N, Sigma_T, s_T1, ...
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

   !> Why a STATUS_BEYOND_PEAK step has no solution, as the messages word it after 'the imposed
   !> traction X = ... MPa is ', up to an opened parenthesis that the caller closes.
   pure function beyond_peak_reason(failure, ntens) result(text)
      type(path_failure_type), intent(in) :: failure
      integer, intent(in) :: ntens                !! 2 or 3
      character(len=:), allocatable :: text
      character(len=:), allocatable :: name
      if (.not. failure%flat) then
         text = 'beyond the peak the material can carry ('
         return
      end if
      name = component_name(failure%component, .true., ntens)
      text = 'met only on a flat tangent in '//name//' (a stiffness at most 1e-12 of the largest met): the '// &
         'point carries no more load in '//name//', or its separation there is undetermined ('
   end function beyond_peak_reason

   !> Why a STATUS_SEPARATION_OUT_OF_RANGE step has no solution, as the messages word it after
   !> 'the imposed traction X = ... MPa ' (the component named in it may be another one where
   !> the coupling moved it): the separation needed, the range and Newton's iterate.
   pure function beyond_range_reason(failure, ntens) result(text)
      type(path_failure_type), intent(in) :: failure
      integer, intent(in) :: ntens                !! 2 or 3
      character(len=:), allocatable :: text
      character(len=:), allocatable :: name
      name = component_name(failure%component, .false., ntens)
      text = 'needs a separation beyond the admissible range |'//name//'| <= '//trim(adjustl(es_field(SEPARATION_MAX, 8, 1)))// &
         ' mm (SEPARATION_MAX; Newton''s iterate '//name//' = '//real_text(failure%iterate, 6)//' mm)'
   end function beyond_range_reason

   !> The imposed traction that a STATUS_SEPARATION_OUT_OF_RANGE message names: the component out
   !> of range where it is traction-controlled, else the first traction-controlled one.
   pure function range_traction_component(failure, ntens) result(c)
      type(path_failure_type), intent(in) :: failure
      integer, intent(in) :: ntens
      integer :: c
      c = failure%component
      if (failure%controls(c)) return
      do c = 1, ntens
         if (failure%controls(c)) return
      end do
      c = failure%component
   end function range_traction_component

   !> The library's message of a failed replay (at most MESSAGE_LEN characters): the step's
   !> times, then why; `update_detail` is the failed update's own message ('' for none).
   pure function describe_failure(failure, point, tolerance, update_detail) result(text)
      type(path_failure_type), intent(in) :: failure
      type(path_point_type), intent(in) :: point   !! the last converged state
      real(dp), intent(in) :: tolerance            !! the traction tolerance (MPa)
      character(len=*), intent(in) :: update_detail
      character(len=MESSAGE_LEN) :: text
      character(len=2*MESSAGE_LEN) :: long
      character(len=:), allocatable :: times       !! 'from t = ... to t = ...:'
      character(len=:), allocatable :: name
      integer :: c, ios

      ! (real_text: the same text whatever the compiler, a leading zero included)
      times = 'from t = '//real_text(point%time, 10)//' to t = '//real_text(failure%time_to, 10)//':'
      select case (failure%kind)
      case (FAILURE_FATAL)
         long = times//' '//trim(update_detail)
      case (FAILURE_HALVINGS)
         if (failure%status == STATUS_BEYOND_PEAK) then
            c = failure%component
            name = component_name(c, .true., point%ntens)
            long = times//' the imposed traction '//name//' = '//real_text(failure%target(c), 6)//' MPa is '// &
               beyond_peak_reason(failure, point%ntens)//'the largest |'//name//'| reached is '// &
               real_text(failure%peak(c), 6)//' MPa)'
         else if (failure%status == STATUS_SEPARATION_OUT_OF_RANGE .and. failure%component > 0) then
            c = range_traction_component(failure, point%ntens)
            name = component_name(c, .true., point%ntens)
            long = times//' the imposed traction '//name//' = '//real_text(failure%target(c), 6)//' MPa '// &
               beyond_range_reason(failure, point%ntens)
         else if (failure%status == STATUS_MIXED_NOT_CONVERGED) then
            write (long, '(a,1x,a,i0,a,es10.3e3,a,i0,a,es9.2e3,a,i0,a)', iostat=ios) times, &
               'no converged step even after ', MAX_HALVINGS, ' halvings of the sub-increment: Newton on the '// &
               'tangent left a traction residual of ', failure%residual, ' MPa after ', failure%iterations, &
               ' iteration(s) (traction tolerance ', tolerance, ' MPa, at most ', MAX_NEWTON, ')'
         else
            write (long, '(a,1x,a,a,i0,a)', iostat=ios) times, trim(update_detail), &
               '; no convergence even after ', MAX_HALVINGS, ' halvings of the sub-increment'
         end if
      case default
         long = times//' '//trim(update_detail)
      end select
      ! a message longer than MESSAGE_LEN (a long update message behind the times) ends in '...',
      ! so that a reader sees it was cut
      if (len_trim(long) > MESSAGE_LEN) then
         text = long(:MESSAGE_LEN - 3)//'...'
      else
         text = long(:MESSAGE_LEN)
      end if
   end function describe_failure

end module interphase_mixed_control
