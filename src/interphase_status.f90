!> Status codes of interphase and their messages. Library code never stops: every failure is a
!> status that the caller (an adapter, the driver) turns into a cut-back, a host error or an exit.
module interphase_status
   use interphase_kinds, only: dp
   use interphase_real_text, only: es_fields
   implicit none
   private
   public :: status_message, severity_label, file_loader, message_path, separation_text

   !> Length of the message strings that go with a status.
   integer, parameter, public :: MESSAGE_LEN = 256

   integer, parameter, public :: STATUS_OK = 0
   ! ---- PROPS and size validation (setup errors) ----
   integer, parameter, public :: STATUS_BAD_NPROPS = 1
   integer, parameter, public :: STATUS_BAD_MODEL = 2
   integer, parameter, public :: STATUS_BAD_DAMAGE_LAW = 3
   integer, parameter, public :: STATUS_BAD_MU = 4
   integer, parameter, public :: STATUS_BAD_S0_N = 5
   integer, parameter, public :: STATUS_BAD_SF_N = 6
   integer, parameter, public :: STATUS_BAD_S0_T = 7
   integer, parameter, public :: STATUS_BAD_SF_T = 8
   integer, parameter, public :: STATUS_BAD_K_N = 9
   integer, parameter, public :: STATUS_BAD_K_T = 10
   integer, parameter, public :: STATUS_BAD_NTENS = 11
   integer, parameter, public :: STATUS_BAD_NSTATV = 12
   integer, parameter, public :: STATUS_MODEL_UNAVAILABLE = 13
   integer, parameter, public :: STATUS_BAD_TABLE_SELECTOR = 14
   integer, parameter, public :: STATUS_BAD_D0 = 15
   integer, parameter, public :: STATUS_BAD_RCURVE = 16
   integer, parameter, public :: STATUS_BAD_GC_I = 17
   integer, parameter, public :: STATUS_BAD_GC_II = 18
   integer, parameter, public :: STATUS_BAD_OPTION = 19
   ! ---- update failures (the increment may be retried smaller) ----
   integer, parameter, public :: STATUS_NONFINITE_SEPARATION = 20
   integer, parameter, public :: STATUS_BAD_STATE = 21
   integer, parameter, public :: STATUS_BAD_COEFFICIENTS = 22
   integer, parameter, public :: STATUS_STAGGER_NOT_CONVERGED = 23
   integer, parameter, public :: STATUS_RCURVE_NOT_LOADED = 24
   integer, parameter, public :: STATUS_SEPARATION_OUT_OF_RANGE = 25
   integer, parameter, public :: STATUS_BAD_HOST_INPUT = 26
   integer, parameter, public :: STATUS_BAD_TIME_INCREMENT = 27
   ! ---- history replays (interphase_mixed_control, the C entry interphase_run_history) ----
   integer, parameter, public :: STATUS_BEYOND_PEAK = 28
   integer, parameter, public :: STATUS_MIXED_NOT_CONVERGED = 29
   integer, parameter, public :: STATUS_BAD_HISTORY = 30
   integer, parameter, public :: STATUS_OUTPUT_FULL = 31
   ! ---- arguments of the C entry points (interphase_capi) ----
   integer, parameter, public :: STATUS_NULL_ARGUMENT = 32
   ! ---- interpolation tables (interphase_spline): construction, then evaluation ----
   integer, parameter, public :: STATUS_SPLINE_TOO_FEW_POINTS = 40
   integer, parameter, public :: STATUS_SPLINE_BAD_SHAPE = 41
   integer, parameter, public :: STATUS_SPLINE_BAD_METHOD = 42
   integer, parameter, public :: STATUS_SPLINE_NONFINITE_DATA = 43
   integer, parameter, public :: STATUS_SPLINE_BAD_KNOTS = 44
   integer, parameter, public :: STATUS_SPLINE_SOLVER_FAILED = 45
   integer, parameter, public :: STATUS_SPLINE_NOT_BUILT = 46
   integer, parameter, public :: STATUS_SPLINE_OUT_OF_RANGE = 47
   integer, parameter, public :: STATUS_SPLINE_NONFINITE_ARGUMENT = 48
   ! ---- RVE coefficient tables (interphase_rve_table): reading and checking ----
   integer, parameter, public :: STATUS_TABLE_UNREADABLE = 50
   integer, parameter, public :: STATUS_TABLE_BAD_HEADER = 51
   integer, parameter, public :: STATUS_TABLE_MISSING_COLUMN = 52
   integer, parameter, public :: STATUS_TABLE_MISSING_KEY = 53
   integer, parameter, public :: STATUS_TABLE_BAD_ROW = 54
   integer, parameter, public :: STATUS_TABLE_NONFINITE = 55
   integer, parameter, public :: STATUS_TABLE_NOT_INCREASING = 56
   integer, parameter, public :: STATUS_TABLE_BAD_RANGE = 57
   integer, parameter, public :: STATUS_TABLE_IDENTITY = 58
   integer, parameter, public :: STATUS_TABLE_NOT_LOADED = 59
   !> (49, beside the spline codes: the table's rows pass, but its interpolant between two rows
   !> is not a law there)
   integer, parameter, public :: STATUS_TABLE_INTERPOLANT = 49
   ! ---- R-curve files (interphase_rcurve) ----
   integer, parameter, public :: STATUS_RCURVE_UNREADABLE = 60
   integer, parameter, public :: STATUS_RCURVE_MALFORMED = 61
   integer, parameter, public :: STATUS_RCURVE_NEGATIVE = 62
   integer, parameter, public :: STATUS_RCURVE_BAD_RANGE = 63
   integer, parameter, public :: STATUS_RCURVE_OUT_OF_RANGE = 64
   !> (a toughness > 0 outside the window of the PROPS toughness, [1e-20, 1e20] N/mm)
   integer, parameter, public :: STATUS_RCURVE_BAD_TOUGHNESS = 65

   !> Severity of a host message: information, warning (the increment is cut back), fatal.
   integer, parameter, public :: SEVERITY_INFO = 1
   integer, parameter, public :: SEVERITY_WARNING = 2
   integer, parameter, public :: SEVERITY_FATAL = 3


   abstract interface
      !> A start-up loader of a data file (the custom RVE table, the tabulated R-curve): STATUS_OK
      !> or a STATUS_* code with a message that names the file, the line and the failed check.
      subroutine file_loader(path, status, message)
         import :: MESSAGE_LEN
         implicit none
         character(len=*), intent(in) :: path
         integer, intent(out) :: status
         character(len=MESSAGE_LEN), intent(out) :: message
      end subroutine file_loader
   end interface

contains

   !> Generic text of a status code (callers add the offending value and where it came from).
   pure function status_message(status) result(message)
      integer, intent(in) :: status          !! a STATUS_* code
      character(len=:), allocatable :: message
      character(len=12) :: code_text

      select case (status)
      case (STATUS_OK);                    message = 'success'
      case (STATUS_BAD_NPROPS);            message = 'wrong number of material constants (NPROPS)'
      case (STATUS_BAD_MODEL);             message = 'unknown model selector'
      case (STATUS_BAD_DAMAGE_LAW);        message = 'unknown damage-law selector'
      case (STATUS_BAD_MU);                message = 'friction coefficient mu out of range'
      case (STATUS_BAD_S0_N);              message = 'first-cracking normal separation s0_N out of range'
      case (STATUS_BAD_SF_N);              message = 'full-crack normal separation sf_N out of range'
      case (STATUS_BAD_S0_T);              message = 'first-cracking tangential separation s0_T out of range'
      case (STATUS_BAD_SF_T);              message = 'full-crack tangential separation sf_T out of range'
      case (STATUS_BAD_K_N);               message = 'normal stiffness K_N out of range'
      case (STATUS_BAD_K_T);               message = 'tangential stiffness K_T out of range'
      case (STATUS_BAD_NTENS);             message = 'unsupported number of traction components (NTENS)'
      case (STATUS_BAD_NSTATV);            message = 'too few state variables (NSTATV)'
      case (STATUS_MODEL_UNAVAILABLE);     message = 'model not available in this build'
      case (STATUS_BAD_TABLE_SELECTOR);    message = 'unknown RVE table selector'
      case (STATUS_BAD_D0);                message = 'initial crack D0 = a0/b out of range'
      case (STATUS_BAD_RCURVE);            message = 'unknown R-curve selector'
      case (STATUS_BAD_GC_I);              message = 'mode-I toughness G_cI out of range'
      case (STATUS_BAD_GC_II);             message = 'mode-II toughness G_cII out of range'
      case (STATUS_BAD_OPTION);            message = 'option constant out of range, missing, or not '// &
         'allowed with this element or host'
      case (STATUS_STAGGER_NOT_CONVERGED); message = 'staggered damage-friction iteration did not converge'
      case (STATUS_RCURVE_NOT_LOADED);     message = 'tabulated R-curve selected but none loaded'
      case (STATUS_RCURVE_UNREADABLE);     message = 'R-curve file cannot be opened or read'
      case (STATUS_RCURVE_MALFORMED);      message = 'R-curve file malformed: a line that is not "D G_cI G_cII" '// &
         '(three finite numbers), or a comment that gives a column another unit'
      case (STATUS_RCURVE_NEGATIVE);       message = 'R-curve toughness not positive'
      case (STATUS_RCURVE_BAD_RANGE);      message = 'R-curve D values not strictly increasing within [0, 1], or too few'
      case (STATUS_RCURVE_OUT_OF_RANGE);   message = 'tabulated R-curve does not cover the damage reached (or D0)'
      case (STATUS_RCURVE_BAD_TOUGHNESS);  message = 'R-curve toughness outside [1e-20, 1e20] N/mm'
      case (STATUS_NONFINITE_SEPARATION);  message = 'separation is not finite (NaN or Inf)'
      case (STATUS_SEPARATION_OUT_OF_RANGE); message = 'separation outside the admissible range |s_i| <= 1e20 mm'
      case (STATUS_BAD_HOST_INPUT);        message = 'a value from the host (stress, energy, separation '// &
         'increment or time) not finite or out of range, or the energy it gives overflows'
      case (STATUS_BAD_TIME_INCREMENT);    message = 'time increment missing, negative or not finite (viscous regularisation)'
      case (STATUS_BAD_STATE);             message = 'state variables out of range or not finite'
      case (STATUS_BEYOND_PEAK);           message = 'imposed traction beyond the peak the material can carry'
      case (STATUS_MIXED_NOT_CONVERGED);   message = 'imposed traction not met: Newton on the tangent did not '// &
         'converge, even in halved steps'
      case (STATUS_BAD_HISTORY);           message = 'loading history or replay setting not admissible'
      case (STATUS_OUTPUT_FULL);           message = 'output arrays too short for the rows of the replay'
      case (STATUS_NULL_ARGUMENT);         message = 'a required pointer argument is NULL'
      case (STATUS_BAD_COEFFICIENTS);      message = 'coefficient set not admissible at this damage'
      case (STATUS_SPLINE_TOO_FEW_POINTS); message = 'too few table points for the interpolation method'
      case (STATUS_SPLINE_BAD_SHAPE);      message = 'table values do not match the knots (rows) or have no column'
      case (STATUS_SPLINE_BAD_METHOD);     message = 'unknown interpolation method'
      case (STATUS_SPLINE_NONFINITE_DATA); message = 'table knots or values not finite (NaN or Inf)'
      case (STATUS_SPLINE_BAD_KNOTS);      message = 'table knots not strictly increasing'
      case (STATUS_SPLINE_SOLVER_FAILED);  message = 'spline system could not be solved (LAPACK dgtsv)'
      case (STATUS_SPLINE_NOT_BUILT);      message = 'interpolation table not built'
      case (STATUS_SPLINE_OUT_OF_RANGE);   message = 'argument outside the interpolation table'
      case (STATUS_SPLINE_NONFINITE_ARGUMENT); message = 'interpolation argument not finite (NaN or Inf)'
      case (STATUS_TABLE_UNREADABLE);      message = 'RVE table file cannot be opened or read'
      case (STATUS_TABLE_BAD_HEADER);      message = 'RVE table header is not valid'
      case (STATUS_TABLE_MISSING_COLUMN);  message = 'RVE table lacks a required column'
      case (STATUS_TABLE_MISSING_KEY);     message = 'RVE table header lacks a required key'
      case (STATUS_TABLE_BAD_ROW);         message = 'RVE table row does not hold one number per column'
      case (STATUS_TABLE_NONFINITE);       message = 'RVE table value not finite (NaN or Inf)'
      case (STATUS_TABLE_NOT_INCREASING);  message = 'RVE table crack half-lengths a not strictly increasing'
      case (STATUS_TABLE_BAD_RANGE);       message = 'RVE table does not run from a = 0 to a = b'
      case (STATUS_TABLE_IDENTITY);        message = 'RVE table violates an exact identity of the RVE problems'
      case (STATUS_TABLE_NOT_LOADED);      message = 'custom RVE table selected but none loaded'
      case (STATUS_TABLE_INTERPOLANT);     message = 'RVE table interpolant inadmissible between two rows'
      case default
         ! (the value named: a code from another version, or not a status at all)
         write (code_text, '(i0)') status
         message = 'unknown status code '//trim(code_text)
      end select
   end function status_message

   !> Label of a SEVERITY_* code for printed messages.
   pure function severity_label(severity) result(label)
      integer, intent(in) :: severity        !! a SEVERITY_* code
      character(len=:), allocatable :: label

      select case (severity)
      case (SEVERITY_INFO);    label = 'info'
      case (SEVERITY_WARNING); label = 'warning'
      case (SEVERITY_FATAL);   label = 'error'
      case default;            label = 'message'
      end select
   end function severity_label

   !> A file name as messages show it: whole when it is short, else '...' and its last
   !> characters (the end of a path names the file): at most MESSAGE_PATH_LEN, so that a message
   !> of MESSAGE_LEN characters keeps room for the line number and what is wrong, or at most
   !> `room` (not below MIN_PATH_LEN) where the caller knows the rest of its message
   !> (MESSAGE_LEN - len(rest): the whole message then fits, and nothing at its end is cut).
   pure function message_path(path, room) result(shown)
      character(len=*), intent(in) :: path
      integer, intent(in), optional :: room       !! characters the path may take
      character(len=:), allocatable :: shown
      integer, parameter :: MESSAGE_PATH_LEN = 120, MIN_PATH_LEN = 24
      integer :: n, most
      n = len_trim(path)
      most = MESSAGE_PATH_LEN
      if (present(room)) most = min(most, max(room, MIN_PATH_LEN))
      if (n <= most) then
         shown = path(1:n)
      else
         shown = '...'//path(n - most + 4:n)
      end if
   end function message_path

   !> A separation for messages, its components named, normal first (the UMAT's and the C
   !> interface's order): 's_N, s_T (mm)   1.0000E-03  0.0000E+00' in 2-D, with s_T1, s_T2 in 3-D.
   pure function separation_text(s) result(text)
      real(dp), intent(in) :: s(:)      !! the separation (mm), 2 or 3 components
      character(len=:), allocatable :: text
      ! (es_fields: a three-digit exponent keeps its E, 1.2346E+301, where es12.4 drops it)
      text = 's_N, s_T'
      if (size(s) == 3) text = 's_N, s_T1, s_T2'
      text = text//' (mm) '//trim(es_fields(s(1:min(3, size(s))), 12, 4))
   end function separation_text

end module interphase_status
