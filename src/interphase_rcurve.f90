!> Tabulated R-curves of the fracture-mechanics damage law: G_cI(D) and G_cII(D) read from a
!> file once at start-up (Abaqus: UEXTERNALDB with INTERPHASE_RCURVE; the driver: its case
!> file) into `protected` data, and evaluated by pure code.
!>
!> File format: plain text, `#` comments and blank lines allowed; one row per point,
!> `D G_cI G_cII` with D = a/b strictly increasing in [0, 1] (at least two rows) and the
!> toughnesses > 0 in N/mm (energy per unit crack area, as measured; the eq-20 release rate G is twice it;
!> docs/theory.md). Between the rows a monotone cubic (Fritsch-Carlson) interpolates, so the
!> R-curve keeps the shape of the data; outside the rows it is an error, never an extrapolation.
module interphase_rcurve
   use interphase_finite, only: is_finite
   use interphase_kinds, only: dp
   use interphase_status, only: message_path, STATUS_OK, STATUS_RCURVE_UNREADABLE, STATUS_RCURVE_MALFORMED, &
      STATUS_RCURVE_NEGATIVE, STATUS_RCURVE_BAD_RANGE, STATUS_RCURVE_NOT_LOADED, MESSAGE_LEN, &
      status_message
   use interphase_spline, only: spline_type, spline_build, spline_export, cubic_locate, cubic_eval, &
      SPLINE_MONOTONE
   implicit none
   private
   public :: load_rcurve, tabulated_rcurve, rcurve_source, rcurve_loaded

   real(dp), allocatable, protected :: rcurve_knots(:)          !! D of the rows
   real(dp), allocatable, protected :: rcurve_coef(:, :, :)     !! monotone cubic, 2 columns
   character(len=:), allocatable, protected :: loaded_source    !! file it came from

contains

   !> Read and check an R-curve file; call once at start-up, before any update.
   subroutine load_rcurve(path, status, message)
      character(len=*), intent(in) :: path
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message

      character(len=1024) :: line
      character(len=256) :: iomsg
      real(dp), allocatable :: rows(:, :), grown(:, :)
      real(dp) :: v(3)
      integer :: unit, ios, lineno, n, last_line
      type(spline_type) :: spline
      character(len=8) :: extra

      status = STATUS_OK
      open (newunit=unit, file=path, status='old', action='read', iostat=ios, iomsg=iomsg)
      if (ios /= 0) then
         status = STATUS_RCURVE_UNREADABLE
         message = message_path(path)//': cannot open: '//trim(iomsg)
         return
      end if
      allocate (rows(3, 32))
      n = 0
      lineno = 0
      last_line = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (is_iostat_end(ios)) exit
         lineno = lineno + 1
         if (ios /= 0) then
            call fail(STATUS_RCURVE_UNREADABLE, 'read error')
            return
         end if
         line = adjustl(line)
         if (len_trim(line) == 0 .or. line(1:1) == '#') cycle
         read (line, *, iostat=ios) v
         if (ios == 0) then
            ! exactly three numbers: a fourth field is an error
            extra = ''
            read (line, *, iostat=ios) v, extra
            if (ios == 0 .and. len_trim(extra) > 0) ios = 1
            if (is_iostat_end(ios)) ios = 0
         end if
         if (ios /= 0 .or. .not. all(is_finite(v))) then
            call fail(STATUS_RCURVE_MALFORMED, 'expected three finite numbers "D G_cI G_cII": '// &
               trim(line(1:80)))
            return
         end if
         if (.not. (v(2) > 0.0_dp .and. v(3) > 0.0_dp)) then
            call fail(STATUS_RCURVE_NEGATIVE, 'toughness must be > 0 N/mm: '//trim(line(1:80)))
            return
         end if
         if (v(1) < 0.0_dp .or. v(1) > 1.0_dp) then
            call fail(STATUS_RCURVE_BAD_RANGE, 'D must lie in [0, 1]: '//trim(line(1:80)))
            return
         end if
         if (n > 0) then
            if (.not. (v(1) > rows(1, n))) then
               call fail(STATUS_RCURVE_BAD_RANGE, 'D does not increase: '//trim(line(1:80)))
               return
            end if
         end if
         n = n + 1
         if (n > size(rows, 2)) then
            allocate (grown(3, 2*size(rows, 2)))
            grown(:, 1:n - 1) = rows(:, 1:n - 1)
            call move_alloc(grown, rows)
         end if
         rows(:, n) = v
         last_line = lineno
      end do
      close (unit)
      if (n < 2) then
         status = STATUS_RCURVE_BAD_RANGE
         message = message_path(path)//': fewer than two rows "D G_cI G_cII"'
         return
      end if
      call spline_build(rows(1, 1:n), transpose(rows(2:3, 1:n)), SPLINE_MONOTONE, spline, status)
      if (status /= STATUS_OK) then
         message = message_path(path)//': '//status_message(status)
         return
      end if
      call spline_export(spline, rcurve_knots, rcurve_coef)
      loaded_source = path

   contains

      subroutine fail(code, text)
         integer, intent(in) :: code
         character(len=*), intent(in) :: text
         status = code
         write (message, '(a,a,i0,a,a)', iostat=ios) message_path(path), ':', lineno, ': ', text
         close (unit)
      end subroutine fail

   end subroutine load_rcurve

   !> G_cI, G_cII (N/mm) and their D-derivatives from the loaded R-curve at D.
   pure subroutine tabulated_rcurve(d, gc, dgc_dd, status)
      real(dp), intent(in) :: d              !! damage D = a/b
      real(dp), intent(out) :: gc(2)         !! (G_cI, G_cII)
      real(dp), intent(out) :: dgc_dd(2)     !! their derivatives d/dD
      integer, intent(out) :: status
      integer :: interval
      if (.not. allocated(rcurve_coef)) then
         status = STATUS_RCURVE_NOT_LOADED
         return
      end if
      call cubic_locate(rcurve_knots, d, interval, status)
      if (status /= STATUS_OK) return
      call cubic_eval(rcurve_knots, rcurve_coef, interval, d, gc, dgc_dd)
   end subroutine tabulated_rcurve

   !> Whether a tabulated R-curve has been loaded (R-curve selector 3 needs one).
   pure logical function rcurve_loaded()
      rcurve_loaded = allocated(rcurve_coef)
   end function rcurve_loaded

   !> The file the tabulated R-curve came from ('' when none is loaded).
   function rcurve_source() result(source)
      character(len=:), allocatable :: source
      source = ''
      if (allocated(loaded_source)) source = loaded_source
   end function rcurve_source

end module interphase_rcurve
