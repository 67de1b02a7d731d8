!> C entry points of interphase (declared in include/interphase.h): one interface update from a
!> PROPS array, the old state and the separation, with an integer status, and the message of a
!> status (no I/O, no module data; re-entrant); and the start-up loaders of the custom RVE table
!> and of the tabulated R-curve (they read a file and write the loaders' `protected` data, so a
!> host calls them once, from one thread, before any update). Part of the core library, no host
!> hook.
!>
!> Array conventions for C: separation and traction in the order (s_N, s_T[, s_T2]); the
!> tangent is returned **row-major**, tangent[i*ntens + j] = d traction[i] / d separation[j];
!> the state is the UMAT's STATEV slots 1..4, or 1..5 with viscous regularisation (state_slots;
!> docs/abaqus.md). interphase_run updates one point along a whole path of separations in one call
!> (for hosts that replay histories, where a call per increment would cost more than the update:
!> the Python package, docs/python.md).
module interphase_capi
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_size_t, c_ptr, c_null_char, &
      c_associated, c_f_pointer
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_value, ieee_quiet_nan
   use interphase_kinds, only: dp
   use interphase_real_text, only: real_text, es_field, es_fields, es_list
   use interphase_layout, only: NSTATV_REQUIRED, NSTATV_VISCOUS, PROP_TABLE, LFM_RCURVE
   use interphase_provider, only: check_run_time_data
   use interphase_status, only: STATUS_OK, STATUS_BAD_NTENS, STATUS_BAD_NPROPS, MESSAGE_LEN, &
      STATUS_TABLE_UNREADABLE, STATUS_RCURVE_UNREADABLE, STATUS_TABLE_NOT_LOADED, STATUS_RCURVE_NOT_LOADED, &
      STATUS_RCURVE_OUT_OF_RANGE, STATUS_BAD_TIME_INCREMENT, STATUS_NULL_ARGUMENT, status_message, file_loader
   use interphase_micro_coefficients, only: load_custom_table
   use interphase_rcurve, only: load_rcurve, rcurve_overrun
   use interphase_params, only: law_params_type, from_props, refuse_umat_options, constants_count, SEPARATION_MAX, HOST_VALUE_MAX
   use interphase_finite, only: is_within, is_finite, is_finite_nonnegative, difference_is_finite
   use interphase_status, only: STATUS_BAD_HOST_INPUT, STATUS_BAD_STATE
   use interphase_state, only: interface_state_type, state_unpack, state_pack, state_slots
   use interphase_kernel, only: interface_update, update_point
   use interphase_mixed_control, only: point_law_type, path_point_type, path_failure_type, replay_history_path, &
      describe_failure, component_name, FAILURE_OUTPUT, TRACTION_TOLERANCE_MAX
   use interphase_status, only: STATUS_BAD_HISTORY, STATUS_OUTPUT_FULL, separation_text, STATUS_NONFINITE_SEPARATION, &
      STATUS_SEPARATION_OUT_OF_RANGE
   implicit none
   private
   public :: interphase_update_c, interphase_update_dt_c, interphase_update_increment_c, interphase_status_message_c, &
      interphase_load_table_c, interphase_load_rcurve_c, interphase_run_c, interphase_run_history_c

   !> The update of interphase_run_history: the kernel as the Abaqus UMAT calls it (the update at
   !> STRAN + DSTRAN with DTIME, the dissipated energy accumulated as its SPD, the state carried
   !> through its STATEV slots), and the output rows written into the caller's arrays.
   type, extends(point_law_type) :: capi_law_type
      type(law_params_type) :: params
      integer :: nsv = NSTATV_REQUIRED                 !! state slots (state_slots)
      logical :: viscous = .false.
      integer(c_size_t) :: capacity = 0                !! rows the output arrays hold
      integer(c_size_t) :: rows = 0                    !! rows written
      real(c_double), pointer :: out_time(:) => null(), out_separation(:) => null(), &
         out_traction(:) => null(), out_state(:) => null(), out_stored_energy(:) => null(), &
         out_dissipated_energy(:) => null(), out_tangent(:) => null()
      real(dp) :: last_tangent(3, 3) = 0.0_dp          !! the tangent of the last converged step
      logical :: stepped = .false.                     !! a step has converged
      character(len=MESSAGE_LEN) :: detail = ''        !! the last failed update's message
   contains
      procedure :: step => capi_step
      procedure :: accept => capi_accept
      procedure :: output => capi_output
   end type capi_law_type

   !> Longest path (bytes, without the NUL) the loaders accept from C.
   integer, parameter :: MAX_PATH_LEN = 4096
   !> Most rows (nrows, capacity) the replays accept: an array of more rows of ntens*ntens
   !> doubles (72 bytes in 3-D) would not fit in 2**63 bytes. A size_t of 2**63 or more reads as
   !> a negative integer(c_size_t) here: it is refused too, shown as the unsigned value (size_text).
   ! (the largest multiple of 72 first: a division that truncates is a compiler warning)
   integer(c_size_t), parameter :: MAX_ROWS = (huge(0_c_size_t) - mod(huge(0_c_size_t), 72_c_size_t))/72_c_size_t

contains

   !> C: `int interphase_update(const double *props, int nprops, int ntens,
   !>    const double *state_old, const double *separation, double *traction, double *tangent,
   !>    double *state_new, double *stored_energy, char *detail, size_t detail_len)`.
   !> Returns STATUS_OK (0) or a status code; on a non-zero status the outputs are untouched and,
   !> when `detail` is not NULL, it receives the detailed message (which value, which range; for a
   !> table or R-curve not loaded, which loader to call; for an R-curve that does not cover D0 or
   !> the damage reached, the file, its range and the D). A NULL array is STATUS_NULL_ARGUMENT,
   !> the detail naming it.
   function interphase_update_c(props, nprops, ntens, state_old, separation, traction, tangent, &
         state_new, stored_energy, detail, detail_len) result(status) bind(C, name="interphase_update")
      integer(c_int), value, intent(in) :: nprops          !! number of PROPS (docs/abaqus.md)
      type(c_ptr), value, intent(in) :: props              !! nprops doubles: PROPS, docs/abaqus.md
      integer(c_int), value, intent(in) :: ntens           !! 2 (2-D) or 3 (3-D)
      type(c_ptr), value, intent(in) :: state_old          !! NSTATV_REQUIRED doubles (state_slots)
      type(c_ptr), value, intent(in) :: separation         !! ntens doubles (mm)
      type(c_ptr), value, intent(in) :: traction           !! out: ntens doubles (MPa)
      type(c_ptr), value, intent(in) :: tangent            !! out: ntens*ntens doubles, row-major (MPa/mm)
      type(c_ptr), value, intent(in) :: state_new          !! out: NSTATV_REQUIRED doubles (state_slots)
      type(c_ptr), value, intent(in) :: stored_energy      !! out: one double, stored energy per unit area (N/mm)
      type(c_ptr), value, intent(in) :: detail             !! char buffer or NULL
      integer(c_size_t), value, intent(in) :: detail_len   !! its size in bytes
      integer(c_int) :: status
      status = capi_update(props, nprops, ntens, state_old, separation, traction, tangent, state_new, &
         stored_energy, detail, detail_len)
   end function interphase_update_c

   !> C: `int interphase_update_dt(const double *props, int nprops, int ntens,
   !>    const double *state_old, const double *separation, double dt, double *traction,
   !>    double *tangent, double *state_new, double *stored_energy, char *detail, size_t detail_len)`:
   !> interphase_update with the time increment dt (s), which viscous regularisation needs; the
   !> state is then INTERPHASE_NSTATE_VISCOUS (5) doubles.
   function interphase_update_dt_c(props, nprops, ntens, state_old, separation, dt, traction, tangent, &
         state_new, stored_energy, detail, detail_len) result(status) bind(C, name="interphase_update_dt")
      integer(c_int), value, intent(in) :: nprops          !! number of PROPS (docs/abaqus.md)
      type(c_ptr), value, intent(in) :: props              !! nprops doubles: PROPS, docs/abaqus.md
      integer(c_int), value, intent(in) :: ntens           !! 2 (2-D) or 3 (3-D)
      type(c_ptr), value, intent(in) :: state_old          !! state_slots(params) doubles
      type(c_ptr), value, intent(in) :: separation         !! ntens doubles (mm)
      real(c_double), value, intent(in) :: dt              !! time increment (s)
      type(c_ptr), value, intent(in) :: traction           !! out: ntens doubles (MPa)
      type(c_ptr), value, intent(in) :: tangent            !! out: ntens*ntens doubles, row-major (MPa/mm)
      type(c_ptr), value, intent(in) :: state_new          !! out: state_slots(params) doubles
      type(c_ptr), value, intent(in) :: stored_energy      !! out: one double, stored energy per unit area (N/mm)
      type(c_ptr), value, intent(in) :: detail             !! char buffer or NULL
      integer(c_size_t), value, intent(in) :: detail_len   !! its size in bytes
      integer(c_int) :: status
      status = capi_update(props, nprops, ntens, state_old, separation, traction, tangent, state_new, &
         stored_energy, detail, detail_len, dt)
   end function interphase_update_dt_c

   !> C: `int interphase_update_increment(const double *props, int nprops, int ntens,
   !>    const double *state_old, const double *separation_old, const double *separation,
   !>    const double *dt, double *traction, double *tangent, double *state_new,
   !>    double *stored_energy, char *detail, size_t detail_len)`: interphase_update (dt NULL) or
   !> interphase_update_dt (*dt) given also the separation at the start of the increment, which
   !> a crack that closes within the increment needs: its friction starts from the slip where the
   !> faces met (docs/theory.md, 'An increment across which the crack closes'), as in the UMAT,
   !> the VUMAT and interphase_run.
   function interphase_update_increment_c(props, nprops, ntens, state_old, separation_old, separation, dt, &
         traction, tangent, state_new, stored_energy, detail, detail_len) result(status) &
         bind(C, name="interphase_update_increment")
      integer(c_int), value, intent(in) :: nprops          !! number of PROPS (docs/abaqus.md)
      type(c_ptr), value, intent(in) :: props              !! nprops doubles: PROPS, docs/abaqus.md
      integer(c_int), value, intent(in) :: ntens           !! 2 (2-D) or 3 (3-D)
      type(c_ptr), value, intent(in) :: state_old          !! state_slots(params) doubles
      type(c_ptr), value, intent(in) :: separation_old     !! ntens doubles: at the start of the increment (mm)
      type(c_ptr), value, intent(in) :: separation         !! ntens doubles: at its end (mm)
      type(c_ptr), value, intent(in) :: dt                 !! one double, the time increment (s), or NULL
      type(c_ptr), value, intent(in) :: traction           !! out: ntens doubles (MPa)
      type(c_ptr), value, intent(in) :: tangent            !! out: ntens*ntens doubles, row-major (MPa/mm)
      type(c_ptr), value, intent(in) :: state_new          !! out: state_slots(params) doubles
      type(c_ptr), value, intent(in) :: stored_energy      !! out: one double, stored energy per unit area (N/mm)
      type(c_ptr), value, intent(in) :: detail             !! char buffer or NULL
      integer(c_size_t), value, intent(in) :: detail_len   !! its size in bytes
      integer(c_int) :: status
      real(c_double), pointer :: dt_value
      if (c_associated(dt)) then
         call c_f_pointer(dt, dt_value)
         status = capi_update(props, nprops, ntens, state_old, separation, traction, tangent, state_new, &
            stored_energy, detail, detail_len, dt_value, separation_old)
      else
         status = capi_update(props, nprops, ntens, state_old, separation, traction, tangent, state_new, &
            stored_energy, detail, detail_len, separation_old_c=separation_old)
      end if
   end function interphase_update_increment_c

   !> The update behind the C entry points; `dt` absent: interphase_update (no time increment,
   !> which a material with viscous regularisation refuses); `separation_old_c` present:
   !> interphase_update_increment (the separation at the start of the increment).
   function capi_update(props_c, nprops, ntens, state_old_c, separation_c, traction_c, tangent_c, &
         state_new_c, stored_energy_c, detail, detail_len, dt, separation_old_c) result(status)
      integer(c_int), intent(in) :: nprops
      type(c_ptr), intent(in) :: props_c, state_old_c, separation_c, traction_c, tangent_c, state_new_c, &
         stored_energy_c                                   !! the C arrays (NULL refused)
      integer(c_int), intent(in) :: ntens
      type(c_ptr), intent(in) :: detail
      integer(c_size_t), intent(in) :: detail_len
      real(c_double), intent(in), optional :: dt
      type(c_ptr), intent(in), optional :: separation_old_c   !! the C array (NULL refused)
      integer(c_int) :: status

      real(c_double), pointer :: props(:), state_old(:), separation(:), traction(:), tangent(:), state_new(:), &
         stored_energy, separation_old(:)
      type(law_params_type) :: params
      type(interface_state_type) :: old, new
      real(dp) :: s(3), t(3), k(3, 3), psi, sv(NSTATV_VISCOUS), s_old(3)
      integer :: code, i, j, n, nsv
      logical :: viscous
      character(len=MESSAGE_LEN) :: message

      message = ''
      ! every array is dereferenced: a NULL one is named, not followed
      call refuse_null([props_c, state_old_c, separation_c, traction_c, tangent_c, state_new_c, stored_energy_c], &
         [character(len=13) :: 'props', 'state_old', 'separation', 'traction', 'tangent', 'state_new', &
         'stored_energy'], code, message)
      if (code /= STATUS_OK) then
         call finish()
         return
      end if
      if (present(separation_old_c)) then
         call refuse_null([separation_old_c], [character(len=14) :: 'separation_old'], code, message)
         if (code /= STATUS_OK) then
            call finish()
            return
         end if
      end if
      call c_f_pointer(props_c, props, [max(nprops, 0_c_int)])
      call decode_material(props, nprops, ntens, 'the C API', params, code, message)
      if (code /= STATUS_OK) then
         call finish()
         return
      end if
      n = ntens
      viscous = params%viscosity > 0.0_dp
      ! interphase_update (no dt) refuses a viscous material before it reads the state: its
      ! caller passes INTERPHASE_NSTATE doubles, and the fifth slot would be read beyond them
      if (viscous .and. .not. present(dt)) then
         code = STATUS_BAD_TIME_INCREMENT
         message = 'the material has viscous regularisation (its viscosity option): call '// &
            'interphase_update_dt with the time increment'
         call finish()
         return
      end if
      nsv = state_slots(params)
      call c_f_pointer(state_old_c, state_old, [nsv])
      call c_f_pointer(separation_c, separation, [n])
      call state_unpack(state_old(1:nsv), n, old, code, message, viscous)
      if (code /= STATUS_OK) then
         call finish()
         return
      end if
      ! a time increment, where given, is a finite dt >= 0 whatever the material (only viscous
      ! regularisation reads it)
      if (present(dt)) then
         if (.not. is_finite_nonnegative(dt)) then
            code = STATUS_BAD_TIME_INCREMENT
            message = 'dt ='//es_list([dt], 4)//' s: the time increment must be finite and >= 0'
            call finish()
            return
         end if
      end if
      s(1:n) = separation(1:n)
      if (present(separation_old_c)) then
         call c_f_pointer(separation_old_c, separation_old, [n])
         if (.not. all(is_within(separation_old(1:n), SEPARATION_MAX))) then
            code = merge(STATUS_SEPARATION_OUT_OF_RANGE, STATUS_NONFINITE_SEPARATION, &
               all(is_finite(separation_old(1:n))))
            message = 'separation_old: '//separation_failure(code, separation_old(1:n))
            call finish()
            return
         end if
         s_old = 0.0_dp
         s_old(1:n) = separation_old(1:n)
         call update_point(params, old, n, s, t, k, new, psi, code, dt, s_old)
      else
         call update_point(params, old, n, s, t, k, new, psi, code, dt)
      end if
      ! (a viscous material without dt was refused above, and a dt given was checked: the update
      ! returns no STATUS_BAD_TIME_INCREMENT here)
      if (code == STATUS_RCURVE_OUT_OF_RANGE) then
         message = rcurve_overrun(76, max(old%d, params%d0), separation(1:n))
         call finish()
         return
      else if (code /= STATUS_OK) then
         message = separation_failure(code, separation(1:n))
         call finish()
         return
      end if

      call c_f_pointer(traction_c, traction, [n])
      call c_f_pointer(tangent_c, tangent, [n*n])
      call c_f_pointer(state_new_c, state_new, [nsv])
      call c_f_pointer(stored_energy_c, stored_energy)
      traction(1:n) = t(1:n)
      do i = 1, n
         do j = 1, n
            tangent((i - 1)*n + j) = k(i, j)
         end do
      end do
      sv(1:nsv) = state_old(1:nsv)
      call state_pack(new, sv(1:nsv), viscous)
      state_new(1:nsv) = sv(1:nsv)
      stored_energy = psi
      call finish()

   contains

      !> Set the result and copy the detailed message into the caller's buffer (NUL-terminated).
      subroutine finish()
         status = int(code, c_int)
         if (code /= STATUS_OK) call copy_to_c(trim(message), detail, detail_len)
      end subroutine finish

   end function capi_update

   !> C: `int interphase_run(const double *props, int nprops, int ntens, size_t nrows,
   !>    const double *separation, const double *time, double *traction, double *tangent,
   !>    double *state, double *stored_energy, double *dissipated_energy, size_t *rows_done,
   !>    char *detail, size_t detail_len)`: one point along a path of `nrows` separations, each
   !> step as the UMAT takes an increment. Every array holds one row per point of the path,
   !> row-major: separation and traction nrows*ntens, tangent nrows*ntens*ntens (or NULL), state
   !> nrows*state_slots (4, or 5 with viscous regularisation), the energies nrows. Row 0 is the
   !> start (given: separation, traction, state, energies); rows 1 .. nrows-1 are computed. Step i
   !> updates at s = s[i-1] + (s[i] - s[i-1]) (the UMAT's STRAN + DSTRAN) with dt = time[i] -
   !> time[i-1] (time NULL: no time increment, as interphase_update), and accumulates the
   !> dissipated energy as the UMAT does its SPD: W[i] = W[i-1] + 1/2 (t[i-1] + t[i]).(s[i] -
   !> s[i-1]) - (psi[i] - psi[i-1]). Returns STATUS_OK, or the status of the first step that fails
   !> (rows_done, when not NULL, is then the number of rows that hold results, the start
   !> included; the rows after them are untouched) with the UMAT's detail message and the row.
   function interphase_run_c(props, nprops, ntens, nrows, separation, time, traction, tangent, state, &
         stored_energy, dissipated_energy, rows_done, detail, detail_len) result(status) &
         bind(C, name="interphase_run")
      type(c_ptr), value, intent(in) :: props              !! nprops doubles: PROPS, docs/abaqus.md
      integer(c_int), value, intent(in) :: nprops          !! number of PROPS
      integer(c_int), value, intent(in) :: ntens           !! 2 (2-D) or 3 (3-D)
      integer(c_size_t), value, intent(in) :: nrows        !! rows of the path, the start included (>= 1)
      type(c_ptr), value, intent(in) :: separation         !! nrows*ntens doubles (mm)
      type(c_ptr), value, intent(in) :: time               !! nrows doubles (s) or NULL
      type(c_ptr), value, intent(in) :: traction           !! nrows*ntens doubles (MPa); row 0 given
      type(c_ptr), value, intent(in) :: tangent            !! nrows*ntens*ntens doubles or NULL
      type(c_ptr), value, intent(in) :: state              !! nrows*state_slots doubles; row 0 given
      type(c_ptr), value, intent(in) :: stored_energy      !! nrows doubles (N/mm); [0] given
      type(c_ptr), value, intent(in) :: dissipated_energy  !! nrows doubles (N/mm); [0] given
      type(c_ptr), value, intent(in) :: rows_done          !! size_t out, or NULL
      type(c_ptr), value, intent(in) :: detail             !! char buffer or NULL
      integer(c_size_t), value, intent(in) :: detail_len   !! its size in bytes
      integer(c_int) :: status

      type(law_params_type) :: params
      type(interface_state_type) :: old, new
      real(c_double), pointer :: props_f(:), separations(:), tractions(:), states(:), stored(:), dissipated(:), &
         times(:), tangents(:)
      integer(c_size_t), pointer :: done
      real(dp) :: s(3), ds(3), t(3), k(3, 3), psi, sv(NSTATV_VISCOUS), dt, s_old(3)
      integer(c_size_t) :: row, n_done, at
      integer :: code, i, j, n, nsv, ios
      logical :: viscous, timed, dt_ok
      character(len=MESSAGE_LEN) :: message
      character(len=32) :: row_text

      message = ''
      n_done = 0
      n = ntens
      timed = c_associated(time)
      nullify (times, tangents)
      ! every array that is not documented as 'or NULL' is dereferenced: a NULL one is named
      call refuse_null([props, separation, traction, state, stored_energy, dissipated_energy], &
         [character(len=17) :: 'props', 'separation', 'traction', 'state', 'stored_energy', 'dissipated_energy'], &
         code, message)
      if (code /= STATUS_OK) then
         call finish()
         return
      end if
      call c_f_pointer(props, props_f, [max(nprops, 0_c_int)])
      call decode_material(props_f, nprops, ntens, 'interphase_run', params, code, message)
      if (code /= STATUS_OK) then
         call finish()
         return
      end if
      if (nrows == 0_c_size_t) then
         code = STATUS_BAD_HISTORY
         message = 'nrows = 0: the path needs at least its starting row (row 0, the state to start from)'
         call finish()
         return
      end if
      if (nrows < 0_c_size_t .or. nrows > MAX_ROWS) then
         code = STATUS_BAD_HISTORY
         message = 'nrows = '//size_text(nrows)//' is too large: no array holds so many rows (at most '// &
            size_text(MAX_ROWS)//')'
         call finish()
         return
      end if
      viscous = params%viscosity > 0.0_dp
      nsv = state_slots(params)
      call c_f_pointer(separation, separations, [nrows*n])
      call c_f_pointer(traction, tractions, [nrows*n])
      call c_f_pointer(state, states, [nrows*nsv])
      call c_f_pointer(stored_energy, stored, [nrows])
      call c_f_pointer(dissipated_energy, dissipated, [nrows])
      ! the starting row, as the UMAT checks what a host passes in
      call state_unpack(states(1:nsv), n, old, code, message, viscous)
      if (code /= STATUS_OK) then
         message = 'row 0: '//trim(message)
         call finish()
         return
      end if
      if (.not. (all(is_within(separations(1:n), SEPARATION_MAX)) .and. all(is_within(tractions(1:n), HOST_VALUE_MAX)) &
            .and. is_within(stored(1), HOST_VALUE_MAX) .and. is_within(dissipated(1), HOST_VALUE_MAX))) then
         code = STATUS_BAD_HOST_INPUT
         ! (fields of width decimals + 9: a blank before each, three-digit exponents too)
         message = 'row 0: separation (mm)'//trim(es_fields(separations(1:n), 12, 3))//', traction (MPa)'// &
            trim(es_fields(tractions(1:n), 12, 3))//', stored and dissipated energy (N/mm)'// &
            trim(es_fields([stored(1), dissipated(1)], 12, 3))//': the starting values must be '// &
            'finite, the separation within '//trim(adjustl(es_field(SEPARATION_MAX, 8, 1)))//' mm, the rest '// &
            'within '//trim(adjustl(es_field(HOST_VALUE_MAX, 9, 1)))
         call finish()
         return
      end if
      if (timed) call c_f_pointer(time, times, [nrows])
      if (c_associated(tangent)) call c_f_pointer(tangent, tangents, [nrows*int(n*n, c_size_t)])
      n_done = 1
      s_old = 0.0_dp
      do row = 2, nrows
         at = (row - 1)*n                 ! offset of this row in the ntens-wide arrays
         ! the UMAT's increment: DSTRAN = s[i] - s[i-1], the separation STRAN + DSTRAN
         ds(1:n) = separations(at + 1:at + n) - separations(at - n + 1:at)
         s(1:n) = separations(at - n + 1:at) + ds(1:n)
         ! (the row before: the start of the increment, for a crack that closes within it)
         s_old(1:n) = separations(at - n + 1:at)
         if (timed) then
            ! the times finite, their step finite (a step beyond the largest double is not
            ! formed) and not negative, whatever the material (only viscous regularisation reads
            ! them)
            dt_ok = all(is_finite(times(row - 1:row)))
            if (dt_ok) dt_ok = difference_is_finite(times(row), times(row - 1))
            if (dt_ok) then
               dt = times(row) - times(row - 1)
               dt_ok = dt >= 0.0_dp
            end if
            if (.not. dt_ok) then
               code = STATUS_BAD_TIME_INCREMENT
               write (message, '(a,i0,a,es12.4e3,a,es12.4e3,a)', iostat=ios) 'row ', row - 1, ': time ', times(row), &
                  ' s after ', times(row - 1), ' s: the times must be finite, with finite steps, and must not decrease'
               call finish()
               return
            end if
            call update_point(params, old, n, s, t, k, new, psi, code, dt, s_old)
         else
            call update_point(params, old, n, s, t, k, new, psi, code, s_old=s_old)
         end if
         if (code /= STATUS_OK) then
            ! (the messages name the row's separation as given: s is the previous row's plus the
            ! increment, which may differ from it in the last bit)
            if (code == STATUS_BAD_TIME_INCREMENT) then
               ! (timed: a finite dt >= 0 was checked above)
               write (message, '(a,i0,a)') 'row ', row - 1, ': the material has viscous regularisation (its '// &
                  'viscosity option): pass the times (time is NULL)'
            else if (code == STATUS_RCURVE_OUT_OF_RANGE) then
               write (message, '(a,i0,a,a)', iostat=ios) 'row ', row - 1, ': ', &
                  rcurve_overrun(50, max(old%d, params%d0), separations(at + 1:at + n))
            else
               write (message, '(a,i0,a,a)', iostat=ios) 'row ', row - 1, ': ', &
                  separation_failure(code, separations(at + 1:at + n))
            end if
            call finish()
            return
         end if
         tractions(at + 1:at + n) = t(1:n)
         if (associated(tangents)) then
            do i = 1, n
               do j = 1, n
                  tangents(at*n + (i - 1)*n + j) = k(i, j)
               end do
            end do
         end if
         ! the state through its STATEV slots, as the UMAT carries it from one increment to the next
         sv(1:nsv) = states((row - 2)*nsv + 1:(row - 1)*nsv)
         call state_pack(new, sv(1:nsv), viscous)
         states((row - 1)*nsv + 1:row*nsv) = sv(1:nsv)
         call state_unpack(sv(1:nsv), n, old, code, message, viscous)
         if (code /= STATUS_OK) then
            write (row_text, '(a,i0,a)') 'row ', row - 1, ': '
            message = trim(row_text)//' '//trim(message)
            call finish()
            return
         end if
         stored(row) = psi
         dissipated(row) = dissipated(row - 1) + 0.5_dp*sum((tractions(at - n + 1:at) + t(1:n))*ds(1:n)) &
            - (psi - stored(row - 1))
         n_done = row
      end do
      code = STATUS_OK
      call finish()

   contains

      !> Set the result and rows_done; the detailed message into the caller's buffer on failure.
      subroutine finish()
         status = int(code, c_int)
         if (c_associated(rows_done)) then
            call c_f_pointer(rows_done, done)
            done = n_done
         end if
         if (code /= STATUS_OK) call copy_to_c(trim(message), detail, detail_len)
      end subroutine finish

   end function interphase_run_c

   !> C: `int interphase_run_history(const double *props, int nprops, int ntens, size_t nrows,
   !>    const double *time, const double *value, const int *control, int increments,
   !>    double traction_tolerance, int output_every, size_t capacity, double *out_time,
   !>    double *out_separation, double *out_traction, double *out_state, double *out_stored_energy,
   !>    double *out_dissipated_energy, double *out_tangent, size_t *rows_done, char *detail,
   !>    size_t detail_len)`: a whole loading history replayed at one point as interphase-point
   !> replays it (interphase_mixed_control: mixed control, sub-increments, halvings), with the
   !> numbers of the UMAT. Inputs row-major, one row per history row: value nrows*ntens (mm, or
   !> MPa where control is 1), control nrows*ntens (0: separation, 1: traction; NULL: all 0).
   !> Outputs (each may be NULL) row-major, `capacity` rows: time, separation and traction
   !> (ntens per row), state (state_slots per row), the energies, the tangent (ntens*ntens per
   !> row, row-major; NaN for a start that no step reached). Returns STATUS_OK, or the status of
   !> the failure that ended the replay, with its message; rows_done (may be NULL) the rows written.
   function interphase_run_history_c(props, nprops, ntens, nrows, time, value, control, increments, &
         traction_tolerance, output_every, capacity, out_time, out_separation, out_traction, out_state, &
         out_stored_energy, out_dissipated_energy, out_tangent, rows_done, detail, detail_len) result(status) &
         bind(C, name="interphase_run_history")
      type(c_ptr), value, intent(in) :: props              !! nprops doubles: PROPS, docs/abaqus.md
      integer(c_int), value, intent(in) :: nprops          !! number of PROPS
      integer(c_int), value, intent(in) :: ntens           !! 2 (2-D) or 3 (3-D)
      integer(c_size_t), value, intent(in) :: nrows        !! rows of the history (>= 1)
      type(c_ptr), value, intent(in) :: time               !! nrows doubles, strictly increasing, each step finite (s)
      type(c_ptr), value, intent(in) :: value              !! nrows*ntens doubles (mm or MPa)
      type(c_ptr), value, intent(in) :: control            !! nrows*ntens ints (0, 1) or NULL
      integer(c_int), value, intent(in) :: increments      !! sub-increments per segment (>= 1)
      real(c_double), value, intent(in) :: traction_tolerance  !! MPa (> 0)
      integer(c_int), value, intent(in) :: output_every    !! a row every k-th converged step (>= 1)
      integer(c_size_t), value, intent(in) :: capacity     !! rows the output arrays hold
      type(c_ptr), value, intent(in) :: out_time, out_separation, out_traction, out_state, &
         out_stored_energy, out_dissipated_energy, out_tangent   !! output arrays or NULL
      type(c_ptr), value, intent(in) :: rows_done          !! size_t out, or NULL
      type(c_ptr), value, intent(in) :: detail             !! char buffer or NULL
      integer(c_size_t), value, intent(in) :: detail_len   !! its size in bytes
      integer(c_int) :: status

      type(capi_law_type) :: law
      type(path_point_type) :: point
      type(path_failure_type) :: failure
      real(c_double), pointer :: props_f(:), times(:), values(:, :)
      integer(c_int), pointer :: controls(:, :)
      logical :: imposed                          !! the non-finite value is an imposed traction
      logical, allocatable :: traction_control(:, :)
      integer(c_size_t), pointer :: done
      integer(c_size_t) :: row
      integer :: code, n, ios, i
      character(len=MESSAGE_LEN) :: message

      message = ''
      n = ntens
      ! the arrays that are not documented as 'or NULL': a NULL one is named, not followed
      call refuse_null([props, time, value], [character(len=5) :: 'props', 'time', 'value'], code, message)
      if (code /= STATUS_OK) then
         call finish()
         return
      end if
      call c_f_pointer(props, props_f, [max(nprops, 0_c_int)])
      call decode_material(props_f, nprops, ntens, 'interphase_run_history', law%params, code, message)
      if (code /= STATUS_OK) then
         call finish()
         return
      end if
      code = STATUS_BAD_HISTORY
      if (nrows == 0_c_size_t) then
         message = 'nrows = 0: the history needs at least one row'
      else if (nrows < 0_c_size_t .or. nrows > MAX_ROWS) then
         message = 'nrows = '//size_text(nrows)//' is too large: no array holds so many rows (at most '// &
            size_text(MAX_ROWS)//')'
      else if (capacity < 0_c_size_t .or. capacity > MAX_ROWS) then
         message = 'capacity = '//size_text(capacity)//' rows is too large: no array holds so many rows (at most '// &
            size_text(MAX_ROWS)//')'
      else if (increments < 1) then
         write (message, '(a,i0,a)') 'increments = ', increments, ' must be at least 1'
      else if (output_every < 1) then
         write (message, '(a,i0,a)') 'output_every = ', output_every, ' must be at least 1'
      else if (.not. (traction_tolerance > 0.0_dp .and. traction_tolerance <= TRACTION_TOLERANCE_MAX)) then
         ! (1e-3: TRACTION_TOLERANCE_MAX)
         write (message, '(a,es12.4e3,a)') 'traction_tolerance = ', traction_tolerance, &
            ' MPa must be a finite number > 0 and at most 1e-3 MPa: Newton meets an imposed traction only to within '// &
            'it (joints carry tractions of 0.01 to 10 MPa)'
      else
         code = STATUS_OK
      end if
      if (code /= STATUS_OK) then
         call finish()
         return
      end if
      call c_f_pointer(time, times, [nrows])
      call c_f_pointer(value, values, [int(n, c_size_t), nrows])
      ! (an nrows no array can hold, a wrong or uninitialised size_t as a rule, must come back as a
      ! status: without stat= the run time would print its error and end the host's process)
      allocate (traction_control(n, nrows), stat=ios)
      if (ios /= 0) then
         code = STATUS_BAD_HISTORY
         message = 'nrows = '//size_text(nrows)//': no memory for so many rows (the replay''s '// &
            'controls take 4 bytes a component): is nrows the number of rows of time and value?'
         call finish()
         return
      end if
      traction_control = .false.
      do row = 1, nrows
         if (.not. ieee_is_finite(times(row))) then
            write (message, '(a,i0,a,es12.4,a)', iostat=ios) 'time[', row - 1, '] = ', times(row), ' is not finite'
         else if (.not. all(ieee_is_finite(values(:, row)))) then
            i = findloc(ieee_is_finite(values(:, row)), .false., dim=1)
            ! (named as the range check below names it: Sigma_ where the row imposes a traction)
            ! (the controls associated where they are read: an optimising build's flow analysis
            ! does not carry one test of c_associated over to another)
            imposed = .false.
            if (c_associated(control)) then
               call c_f_pointer(control, controls, [int(n, c_size_t), nrows])
               imposed = controls(i, row) == 1
            end if
            write (message, '(a,i0,a,i0,a,i0,a)', iostat=ios) 'value[', (row - 1)*n + i - 1, '] (row ', &
               row - 1, ', component ', i - 1, ': '
            message = trim(message)//' '//component_name(i, imposed, n)//') = '//real_text(values(i, row))// &
               ' is not finite'
         else if (row > 1) then
            if (.not. times(row) > times(row - 1)) then
               write (message, '(a,i0,a,g0.10,a,g0.10,a)', iostat=ios) &
                  'time[', row - 1, '] = ', times(row), ' is not greater than the previous time ', times(row - 1), &
                  '; times must increase strictly'
            else if (.not. difference_is_finite(times(row), times(row - 1))) then
               ! (the replay interpolates the time within the step: time[i] - time[i-1] must be a number)
               write (message, '(a,i0,a,g0.10,a,i0,a,g0.10,a)', iostat=ios) 'time[', row - 1, '] = ', times(row), &
                  ': the time step from time[', row - 2, '] = ', times(row - 1), &
                  ' is not finite (beyond the largest double)'
            end if
         end if
         if (len_trim(message) > 0) exit
      end do
      if (len_trim(message) == 0 .and. c_associated(control)) then
         call c_f_pointer(control, controls, [int(n, c_size_t), nrows])
         if (any(controls /= 0 .and. controls /= 1)) then
            row = int(findloc(any(controls /= 0 .and. controls /= 1, dim=1), .true., dim=1), c_size_t)
            write (message, '(a,i0,a)', iostat=ios) 'control row ', row - 1, &
               ' holds a value other than 0 (separation) and 1 (traction)'
         else
            traction_control = controls == 1
         end if
      end if
      if (len_trim(message) > 0) then
         code = STATUS_BAD_HISTORY
         call finish()
         return
      end if
      ! as the driver's history reader: a separation beyond the range the update admits would fail
      ! only in the middle of the replay, after halvings, at an interpolated value; an imposed
      ! traction beyond the UMAT's bound on STRESS would overflow the steps between the rows
      do row = 1, nrows
         do i = 1, n
            if (traction_control(i, row)) then
               if (abs(values(i, row)) > HOST_VALUE_MAX) then
                  code = STATUS_BAD_HISTORY
                  write (message, '(a,i0,a,i0,a,i0,a)', iostat=ios) 'value[', (row - 1)*n + i - 1, '] (row ', &
                     row - 1, ', component ', i - 1, ': '
                  message = trim(message)//' '//component_name(i, .true., n)//') = '//real_text(values(i, row))// &
                     ' MPa is beyond the range the replay admits, |Sigma| <= '// &
                     trim(adjustl(es_field(HOST_VALUE_MAX, 9, 1)))//' MPa'
               end if
            else if (abs(values(i, row)) > SEPARATION_MAX) then
               code = STATUS_SEPARATION_OUT_OF_RANGE
               write (message, '(a,i0,a,i0,a,i0,a)', iostat=ios) 'value[', (row - 1)*n + i - 1, '] (row ', &
                  row - 1, ', component ', i - 1, ': '
               message = trim(message)//' '//component_name(i, .false., n)//') = '//real_text(values(i, row))// &
                  ' mm is beyond the range the update admits, |s| <= '//trim(adjustl(es_field(SEPARATION_MAX, 8, 1)))// &
                  ' mm'
            end if
            if (code /= STATUS_OK) then
               call finish()
               return
            end if
         end do
      end do

      law%viscous = law%params%viscosity > 0.0_dp
      law%nsv = state_slots(law%params)
      law%capacity = capacity
      if (c_associated(out_time)) call c_f_pointer(out_time, law%out_time, [capacity])
      if (c_associated(out_separation)) call c_f_pointer(out_separation, law%out_separation, [capacity*n])
      if (c_associated(out_traction)) call c_f_pointer(out_traction, law%out_traction, [capacity*n])
      if (c_associated(out_state)) call c_f_pointer(out_state, law%out_state, [capacity*law%nsv])
      if (c_associated(out_stored_energy)) call c_f_pointer(out_stored_energy, law%out_stored_energy, [capacity])
      if (c_associated(out_dissipated_energy)) &
         call c_f_pointer(out_dissipated_energy, law%out_dissipated_energy, [capacity])
      if (c_associated(out_tangent)) call c_f_pointer(out_tangent, law%out_tangent, [capacity*n*n])

      call replay_history_path(law, times, values, traction_control, int(increments), traction_tolerance, &
         int(output_every), point, failure)
      code = failure%status
      if (failure%kind == FAILURE_OUTPUT) then
         write (message, '(a,i0,a)', iostat=ios) 'the output arrays hold capacity = ', capacity, &
            ' rows, and the replay has more: call again with longer arrays'
      else if (code /= STATUS_OK) then
         message = describe_failure(failure, point, traction_tolerance, law%detail)
      end if
      call finish()

   contains

      !> Set the result and rows_done; the detailed message into the caller's buffer on failure.
      subroutine finish()
         status = int(code, c_int)
         if (c_associated(rows_done)) then
            call c_f_pointer(rows_done, done)
            done = law%rows
         end if
         if (code /= STATUS_OK) call copy_to_c(trim(message), detail, detail_len)
      end subroutine finish

   end function interphase_run_history_c

   !> interphase_run_history's update: one kernel update as the UMAT makes it.
   subroutine capi_step(law, point, separation_new, time_new, tangent, status, fatal)
      class(capi_law_type), intent(inout) :: law
      type(path_point_type), intent(inout) :: point
      real(dp), intent(in) :: separation_new(:)   !! mm
      real(dp), intent(in) :: time_new            !! s
      real(dp), intent(out) :: tangent(:, :)      !! MPa/mm
      integer, intent(out) :: status
      logical, intent(out) :: fatal
      type(interface_state_type) :: old, new
      real(dp) :: s(3), ds(3), t(3), psi, dt
      integer :: n

      n = point%ntens
      fatal = .false.
      tangent = 0.0_dp
      call state_unpack(point%state(1:law%nsv), n, old, status, law%detail, law%viscous)
      if (status /= STATUS_OK) then
         fatal = .true.
         return
      end if
      ! the UMAT's increment: DSTRAN = s_new - s, the update at STRAN + DSTRAN, DTIME
      ds(1:n) = separation_new - point%separation(1:n)
      s(1:n) = point%separation(1:n) + ds(1:n)
      dt = time_new - point%time
      call interface_update(law%params, old, s(1:n), t(1:n), tangent, new, psi, status, dt, point%separation(1:n))
      if (status == STATUS_BAD_TIME_INCREMENT) then
         law%detail = 'dt ='//es_list([dt], 4)//' s: viscous regularisation needs a finite dt >= 0'
         fatal = .true.
         return
      else if (status == STATUS_RCURVE_OUT_OF_RANGE) then
         law%detail = rcurve_overrun(76, max(old%d, law%params%d0), s(1:n))
         fatal = .true.
         return
      else if (status /= STATUS_OK) then
         law%detail = separation_failure(status, s(1:n))
         return
      end if
      ! the UMAT's SPD and SSE
      point%dissipated_energy = point%dissipated_energy + 0.5_dp*sum((point%traction(1:n) + t(1:n))*ds(1:n)) &
         - (psi - point%stored_energy)
      point%stored_energy = psi
      point%traction(1:n) = t(1:n)
      call state_pack(new, point%state(1:law%nsv), law%viscous)
      point%separation(1:n) = separation_new
      point%time = time_new
      point%updates = point%updates + 1
   end subroutine capi_step

   !> interphase_run_history: keep the converged step's tangent for its row.
   subroutine capi_accept(law, old, new, tangent, output_part)
      class(capi_law_type), intent(inout) :: law
      type(path_point_type), intent(in) :: old, new
      real(dp), intent(in) :: tangent(:, :)
      logical, intent(in) :: output_part
      integer :: n
      n = new%ntens
      law%last_tangent(1:n, 1:n) = tangent
      law%stepped = .true.
      associate (unused_old => old, unused_output_part => output_part)   ! every row has its step's tangent
      end associate
   end subroutine capi_accept

   !> interphase_run_history: one output row into the caller's arrays (STATUS_OUTPUT_FULL when
   !> they hold no more).
   subroutine capi_output(law, point, status)
      class(capi_law_type), intent(inout) :: law
      type(path_point_type), intent(in) :: point
      integer, intent(out) :: status
      integer(c_size_t) :: r, at, n, nsv, i, j
      if (law%rows >= law%capacity) then
         status = STATUS_OUTPUT_FULL
         return
      end if
      status = STATUS_OK
      r = law%rows
      n = int(point%ntens, c_size_t)
      nsv = int(law%nsv, c_size_t)
      if (associated(law%out_time)) law%out_time(r + 1) = point%time
      if (associated(law%out_separation)) law%out_separation(r*n + 1:r*n + n) = point%separation(1:n)
      if (associated(law%out_traction)) law%out_traction(r*n + 1:r*n + n) = point%traction(1:n)
      if (associated(law%out_state)) law%out_state(r*nsv + 1:r*nsv + nsv) = point%state(1:nsv)
      if (associated(law%out_stored_energy)) law%out_stored_energy(r + 1) = point%stored_energy
      if (associated(law%out_dissipated_energy)) law%out_dissipated_energy(r + 1) = point%dissipated_energy
      if (associated(law%out_tangent)) then
         at = r*n*n
         do i = 1, n
            do j = 1, n
               if (law%stepped) then
                  law%out_tangent(at + (i - 1)*n + j) = law%last_tangent(i, j)
               else
                  law%out_tangent(at + (i - 1)*n + j) = ieee_value(0.0_dp, ieee_quiet_nan)
               end if
            end do
         end do
      end if
      law%rows = r + 1
   end subroutine capi_output

   !> C: `size_t interphase_status_message(int status, char *buf, size_t len)`. Writes the
   !> generic message of `status` into `buf` (at most len - 1 characters and a NUL; nothing if
   !> `buf` is NULL or `len` is 0) and returns the full length of the message, like snprintf.
   function interphase_status_message_c(status, buf, len) result(full_len) &
         bind(C, name="interphase_status_message")
      integer(c_int), value, intent(in) :: status          !! a status code
      type(c_ptr), value, intent(in) :: buf                !! char buffer or NULL
      integer(c_size_t), value, intent(in) :: len          !! its size in bytes
      integer(c_size_t) :: full_len
      character(len=:), allocatable :: text
      text = status_message(int(status))
      full_len = int(len_trim(text), c_size_t)
      call copy_to_c(trim(text), buf, len)
   end function interphase_status_message_c

   !> C: `int interphase_load_table(const char *path, char *detail, size_t detail_len)`. Reads,
   !> checks and stores the custom RVE table (tables/README.md format) that the micromechanical
   !> model uses where PROPS[7] = 1, as UEXTERNALDB does with INTERPHASE_TABLE. Writes shared data:
   !> call once, from one thread, before any update. Returns STATUS_OK or a STATUS_TABLE_* /
   !> STATUS_SPLINE_* code; on failure `detail` (may be NULL) names the file, the line and the
   !> failed check, and the table loaded before (if any) stays in use.
   function interphase_load_table_c(path, detail, detail_len) result(status) &
         bind(C, name="interphase_load_table")
      type(c_ptr), value, intent(in) :: path               !! NUL-terminated file name
      type(c_ptr), value, intent(in) :: detail             !! char buffer or NULL
      integer(c_size_t), value, intent(in) :: detail_len   !! its size in bytes
      integer(c_int) :: status
      status = load_file(path, 'RVE table', STATUS_TABLE_UNREADABLE, load_custom_table, detail, detail_len)
   end function interphase_load_table_c

   !> C: `int interphase_load_rcurve(const char *path, char *detail, size_t detail_len)`. Reads,
   !> checks and stores the tabulated R-curve ("D G_cI G_cII" rows) of the fracture-mechanics law
   !> where the R-curve selector is 3, as UEXTERNALDB does with INTERPHASE_RCURVE. Writes shared
   !> data: call once, from one thread, before any update. Returns STATUS_OK or a STATUS_RCURVE_*
   !> / STATUS_SPLINE_* code; on failure `detail` (may be NULL) names the file, the line and the
   !> failed check, and the R-curve loaded before (if any) stays in use.
   function interphase_load_rcurve_c(path, detail, detail_len) result(status) &
         bind(C, name="interphase_load_rcurve")
      type(c_ptr), value, intent(in) :: path               !! NUL-terminated file name
      type(c_ptr), value, intent(in) :: detail             !! char buffer or NULL
      integer(c_size_t), value, intent(in) :: detail_len   !! its size in bytes
      integer(c_int) :: status
      status = load_file(path, 'R-curve', STATUS_RCURVE_UNREADABLE, load_rcurve, detail, detail_len)
   end function interphase_load_rcurve_c

   !> Convert the C path, call `loader` on it and copy its message to `detail` on failure. A NULL,
   !> empty or over-long path is `unreadable` with a message that says so.
   function load_file(path, what, unreadable, loader, detail, detail_len) result(status)
      type(c_ptr), intent(in) :: path                      !! NUL-terminated file name or NULL
      character(len=*), intent(in) :: what                 !! kind of file, for messages
      integer, intent(in) :: unreadable                    !! status of a path that cannot be used
      procedure(file_loader) :: loader                  !! the loader to call
      type(c_ptr), intent(in) :: detail                    !! char buffer or NULL
      integer(c_size_t), intent(in) :: detail_len          !! its size in bytes
      integer(c_int) :: status

      character(kind=c_char), pointer :: chars(:)
      character(len=:), allocatable :: fpath
      character(len=MESSAGE_LEN) :: message
      integer :: code, i, n

      if (.not. c_associated(path)) then
         status = int(unreadable, c_int)
         call copy_to_c(what//' path is NULL', detail, detail_len)
         return
      end if
      ! the C string is read byte by byte up to its NUL, never past it
      call c_f_pointer(path, chars, [MAX_PATH_LEN + 1])
      n = 0
      do while (n <= MAX_PATH_LEN)
         if (chars(n + 1) == c_null_char) exit
         n = n + 1
      end do
      if (n == 0) then
         status = int(unreadable, c_int)
         call copy_to_c(what//' path is empty', detail, detail_len)
         return
      end if
      if (n > MAX_PATH_LEN) then
         status = int(unreadable, c_int)
         write (message, '(a,i0,a)') what//' path is longer than ', MAX_PATH_LEN, &
            ' bytes (or not NUL-terminated)'
         call copy_to_c(trim(message), detail, detail_len)
         return
      end if
      allocate (character(len=n) :: fpath)
      do i = 1, n
         fpath(i:i) = chars(i)
      end do
      call loader(fpath, code, message)
      status = int(code, c_int)
      if (code /= STATUS_OK) call copy_to_c(trim(message), detail, detail_len)
   end function load_file

   !> What an update that failed at separation s says (the detail of interphase_update, of each
   !> row of interphase_run and of interphase_run_history's steps): not finite, beyond the range
   !> the update admits (|s_i| <= SEPARATION_MAX), or another failure there.
   function separation_failure(code, s) result(text)
      integer, intent(in) :: code                     !! the update's status
      real(dp), intent(in) :: s(:)                    !! separation (mm)
      character(len=:), allocatable :: text
      select case (code)
      case (STATUS_NONFINITE_SEPARATION)
         text = 'separation '//separation_text(s)//': not finite'
      case (STATUS_SEPARATION_OUT_OF_RANGE)
         text = 'separation '//separation_text(s)//': beyond |s_i| <='//es_field(SEPARATION_MAX, 8, 1)//' mm'
      case default
         text = 'update failed at separation '//separation_text(s)
      end select
   end function separation_failure

   !> Copy `text` into the C buffer `buf` of `len` bytes, truncated, NUL-terminated (nothing for a
   !> NULL `buf` or `len` 0). `len` is a C size_t: one of 2**63 or more (negative here) holds any
   !> text.
   subroutine copy_to_c(text, buf, len)
      character(len=*), intent(in) :: text
      type(c_ptr), intent(in) :: buf
      integer(c_size_t), intent(in) :: len
      character(kind=c_char), pointer :: chars(:)
      integer :: i, n
      if (.not. c_associated(buf)) return
      if (len == 0_c_size_t) return
      n = len_trim(text)
      if (len > 0_c_size_t) n = int(min(int(n, c_size_t), len - 1_c_size_t))
      call c_f_pointer(buf, chars, [n + 1])
      do i = 1, n
         chars(i) = text(i:i)
      end do
      chars(n + 1) = c_null_char
   end subroutine copy_to_c

   !> The decimal text of a C size_t held in `n` (integer(c_size_t) is signed: a size_t of 2**63
   !> or more is negative here, and is written as the unsigned value C passed).
   pure function size_text(n) result(text)
      integer(c_size_t), intent(in) :: n
      character(len=:), allocatable :: text
      character(len=24) :: buffer
      integer(c_size_t) :: half, quotient
      integer :: digit
      if (n >= 0_c_size_t) then
         write (buffer, '(i0)') n
      else
         ! u = n + 2**64 = 2 half + bit, half = u/2 < 2**63; u/10 = half/5, the last digit
         ! 2 (half mod 5) + bit (no signed overflow on the way)
         half = ishft(n, -1)
         quotient = half/5_c_size_t
         digit = int(2_c_size_t*(half - 5_c_size_t*quotient) + iand(n, 1_c_size_t))
         write (buffer, '(i0,i1)') quotient, digit
      end if
      text = trim(buffer)
   end function size_text

   !> STATUS_NULL_ARGUMENT and a message naming the first NULL of `pointers` (names: theirs, in
   !> the C prototype's words), or STATUS_OK.
   subroutine refuse_null(pointers, names, code, message)
      type(c_ptr), intent(in) :: pointers(:)
      character(len=*), intent(in) :: names(:)
      integer, intent(out) :: code
      character(len=MESSAGE_LEN), intent(inout) :: message
      integer :: i
      code = STATUS_OK
      do i = 1, size(pointers)
         if (.not. c_associated(pointers(i))) then
            code = STATUS_NULL_ARGUMENT
            message = trim(names(i))//' is NULL: it must point to the array the header describes'
            return
         end if
      end do
   end subroutine refuse_null

   !> What every C entry point checks of its material before an update: nprops and ntens, PROPS
   !> (the library's decoder; the UMAT's own options refused, naming `entry`), and the data a
   !> material needs loaded (a custom table or tabulated R-curve: the message names the C call
   !> that loads it), with the status and message the entry point returns.
   subroutine decode_material(props, nprops, ntens, entry, params, code, message)
      real(c_double), intent(in) :: props(*)
      integer(c_int), intent(in) :: nprops, ntens
      character(len=*), intent(in) :: entry
      type(law_params_type), intent(out) :: params
      integer, intent(out) :: code
      character(len=MESSAGE_LEN), intent(out) :: message
      integer :: slot, nm, needed       !! the R-curve selector's PROPS index; the constants' counts
      message = ''
      if (nprops < 0) then
         code = STATUS_BAD_NPROPS
         write (message, '(a,i0,a)') 'nprops = ', nprops, ' is negative'
         return
      end if
      if (ntens /= 2 .and. ntens /= 3) then
         code = STATUS_BAD_NTENS
         write (message, '(a,i0,a)') 'ntens = ', ntens, ' but interphase takes 2 (2-D) or 3 (3-D)'
         return
      end if
      call from_props(props(1:nprops), params, code, message)
      if (code == STATUS_OK) call refuse_umat_options(params, entry, code, message)
      if (code /= STATUS_OK) return
      ! data loaded at start-up: a missing table or R-curve, or one that does not cover D0
      call check_run_time_data(params, code, message)
      if (code == STATUS_TABLE_NOT_LOADED) then
         ! (PROPS numbered from 1 as in every other message and in docs/abaqus.md: props[7] in C)
         write (message, '(a,i0,a,i0,a)') 'PROPS(', PROP_TABLE, ') = 1 (props[', PROP_TABLE - 1, &
            '] in C) selects the custom RVE table, but none is loaded: call interphase_load_table(path, ...) '// &
            'before any update'
      else if (code == STATUS_RCURVE_NOT_LOADED) then
         call constants_count(params%model, params%damage_law, nm, needed)
         slot = nm + LFM_RCURVE
         write (message, '(a,i0,a,i0,a)') 'PROPS(', slot, ') = 3 (props[', slot - 1, &
            '] in C) selects the tabulated R-curve, but none is loaded: call interphase_load_rcurve(path, ...) '// &
            'before any update'
      end if
   end subroutine decode_material

end module interphase_capi
