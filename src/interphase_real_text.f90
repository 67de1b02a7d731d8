!> Text of a real(dp) for messages, the same whatever the compiler.
!>
!> Fortran leaves two details of formatted output to the processor: the zero before the decimal
!> point of a magnitude below 1 (gfortran writes 0.5, flang .5) and the spelling of an infinity
!> in a wide enough field (gfortran Infinity, flang Inf). interphase's messages name values the
!> user gave or the host passed, and tests and scripts read them, so they are written here with
!> the leading zero always and an infinity always as Infinity (docs/compilers.md).
module interphase_real_text
   use interphase_kinds, only: dp
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_finite, only: is_finite, EXPONENT_MASK, MAGNITUDE_MASK
   implicit none
   private

   public :: real_text, es_field, es_fields, es_list, literal_overflows, exponent_too_long

   !> Digits of an exponent (leading zeros not counted) beyond which a literal is out of range
   !> whatever its mantissa (10**6 > any line's digits).
   integer, parameter :: MAX_EXPONENT_DIGITS = 6

contains

   !> The value in `g0.<digits>` editing, no blanks, with the leading zero of a magnitude below 1
   !> (0.5, -0.5, 0.1E-4), a digit after a final point (-1.0, not -1.) and a non-finite value as
   !> NaN, Infinity or -Infinity. Without `digits`, the fewest significant digits (at most 17)
   !> whose text reads back as the same double: 0.75, 0.5625E-1, 0.1E-4, -1.0, not
   !> 0.75000000000000000 or 0.10000000000000001E-4 (every double still told apart).
   pure function real_text(value, digits) result(text)
      real(dp), intent(in) :: value               !! the number
      integer, intent(in), optional :: digits     !! significant digits, 1..17 (default: the fewest exact)
      character(len=:), allocatable :: text
      character(len=40) :: buffer
      character(len=12) :: edit
      integer :: d, ios
      real(dp) :: back

      if (.not. is_finite(value)) then
         text = non_finite_text(value)
         return
      end if
      if (present(digits)) then
         d = max(1, min(17, digits))
         write (edit, '(a,i0,a)') '(g0.', d, ')'
         write (buffer, edit, iostat=ios) value
      else
         do d = 1, 17
            write (edit, '(a,i0,a)') '(g0.', d, ')'
            write (buffer, edit, iostat=ios) value
            if (ios /= 0) exit
            ! (a value near huge() rounded to few digits can lie beyond it, 0.2E+309: not read
            ! back, which would overflow and trap under -ffpe-trap=overflow)
            if (literal_overflows(trim(adjustl(buffer)))) cycle
            read (buffer, *, iostat=ios) back
            if (ios /= 0) exit
            if (transfer(back, 0_int64) == transfer(value, 0_int64)) exit
         end do
      end if
      if (ios /= 0) then
         text = '?'
         return
      end if
      text = trim(adjustl(buffer))
      if (text(len(text):len(text)) == '.') text = text//'0'
      if (text(1:1) == '.') then
         text = '0'//text
      else if (len(text) > 1) then
         if (text(1:2) == '-.') text = '-0'//text(2:)
      end if
   end function real_text

   !> The value in an `es<width>.<decimals>` field, right-justified to `width`, with a
   !> non-finite value as NaN, Infinity or -Infinity (asterisks when even that does not fit).
   !> An exponent of three digits (|exponent| >= 100) is written with its letter, as
   !> `es<width>.<decimals>e3` writes it (1.250E+307, -2.2E-308; a plain es field drops the E:
   !> 1.250+307), and so takes one character more than a two-digit one (1.250E+30): a width
   !> of decimals + 7 fits a positive value, decimals + 8 a negative one, decimals + 9 keeps a
   !> blank before every field.
   pure function es_field(value, width, decimals) result(text)
      real(dp), intent(in) :: value               !! the number
      integer, intent(in) :: width                !! field width (characters), 1..60
      integer, intent(in) :: decimals             !! digits after the point, 0..60
      character(len=max(1, min(60, width))) :: text
      character(len=:), allocatable :: word
      character(len=24) :: edit
      character(len=80) :: wide
      integer :: ios, d

      if (is_finite(value)) then
         d = max(0, min(60, decimals))
         ! the exponent as the field rounds it (9.99e99 in es8.1 is 1.0E+100)
         write (edit, '(a,i0,a,i0,a)') '(es', d + 12, '.', d, 'e3)'
         write (wide, edit, iostat=ios) value
         if (ios == 0) then
            if (wide(d + 10:d + 10) == '0') then
               ! two exponent digits: the usual es field (1.0E+20, not 1.0E+020)
               write (edit, '(a,i0,a,i0,a)') '(es', len(text), '.', d, ')'
            else
               write (edit, '(a,i0,a,i0,a)') '(es', len(text), '.', d, 'e3)'
            end if
            write (text, edit, iostat=ios) value
         end if
         if (ios /= 0) text = repeat('*', len(text))
         return
      end if
      word = non_finite_text(value)
      if (len(word) > len(text)) then
         text = repeat('*', len(text))
      else
         text = repeat(' ', len(text) - len(word))//word
      end if
   end function es_field

   !> es_field of each value, one after the other.
   pure function es_fields(values, width, decimals) result(text)
      real(dp), intent(in) :: values(:)           !! the numbers
      integer, intent(in) :: width                !! width of each field (characters), 1..60
      integer, intent(in) :: decimals             !! digits after the point
      character(len=:), allocatable :: text
      integer :: i, w
      w = max(1, min(60, width))
      allocate (character(len=w*size(values)) :: text)
      do i = 1, size(values)
         text((i - 1)*w + 1:i*w) = es_field(values(i), w, decimals)
      end do
   end function es_fields

   !> The values as ' v1 v2 ...': each in es(decimals + 12).(decimals)e3 with its leading blanks
   !> dropped and one blank before it, so that a field never runs into the one before (a negative
   !> value fills a fixed-width es field to its first column: '-2.0000E-003-1.0000E-001'); NaN
   !> and the infinities in words, as es_field writes them.
   pure function es_list(values, decimals) result(text)
      real(dp), intent(in) :: values(:)           !! the numbers
      integer, intent(in) :: decimals             !! digits after the point, 0..60
      character(len=:), allocatable :: text
      character(len=80) :: field
      character(len=24) :: edit
      integer :: i, d, ios
      d = max(0, min(60, decimals))
      write (edit, '(a,i0,a,i0,a)') '(es', d + 12, '.', d, 'e3)'
      text = ''
      do i = 1, size(values)
         if (is_finite(values(i))) then
            write (field, edit, iostat=ios) values(i)
            if (ios /= 0) field = repeat('*', d + 12)
         else
            field = non_finite_text(values(i))
         end if
         text = text//' '//trim(adjustl(field))
      end do
   end function es_list

   !> NaN, Infinity or -Infinity.
   pure function non_finite_text(value) result(text)
      real(dp), intent(in) :: value               !! a value that is not finite
      character(len=:), allocatable :: text
      ! (bit tests: a NaN's magnitude bits lie above the exponent mask, an infinity's equal it)
      if (iand(transfer(value, 0_int64), MAGNITUDE_MASK) > EXPONENT_MASK) then
         text = 'NaN'
      else if (transfer(value, 0_int64) >= 0_int64) then
         text = 'Infinity'
      else
         text = '-Infinity'
      end if
   end function non_finite_text

   !> Whether a real literal (interphase_text_input's is_real_literal) lies beyond huge(1.0_dp),
   !> decided from its digits and exponent, so that it is never read (reading it would raise an
   !> overflow, which traps under -ffpe-trap=overflow): the number readers' test, and real_text's
   !> for its own shorter texts of a value near huge().
   pure logical function literal_overflows(literal) result(overflows)
      character(len=*), intent(in) :: literal
      character(len=*), parameter :: HUGE_DIGITS = '17976931348623157'   ! huge(1.0_dp) = 0.1797...e309
      integer, parameter :: HUGE_MAGNITUDE = 309
      character(len=len(HUGE_DIGITS)) :: digits
      integer :: i, n, magnitude, exponent, mark, ndigits, ios
      logical :: before_point, significant
      n = len(literal)
      mark = scan(literal, 'eEdD')
      exponent = 0
      if (mark > 0) then
         if (exponent_too_long(literal(mark + 1:))) then
            overflows = literal(mark + 1:mark + 1) /= '-' .and. verify(literal(1:mark - 1), '+-0.') > 0
            return
         end if
         read (literal(mark + 1:), *, iostat=ios) exponent
         n = mark - 1
      end if
      digits = repeat('0', len(digits))
      ndigits = 0
      magnitude = 0
      before_point = .true.
      significant = .false.
      do i = 1, n
         if (literal(i:i) == '.') then
            before_point = .false.
         else if (literal(i:i) >= '0' .and. literal(i:i) <= '9') then
            if (literal(i:i) /= '0') significant = .true.
            if (significant) then
               if (before_point) magnitude = magnitude + 1
               if (ndigits < len(digits)) then
                  ndigits = ndigits + 1
                  digits(ndigits:ndigits) = literal(i:i)
               end if
            else if (.not. before_point) then
               magnitude = magnitude - 1
            end if
         end if
      end do
      overflows = .false.
      if (.not. significant) return
      magnitude = magnitude + exponent
      overflows = magnitude > HUGE_MAGNITUDE .or. (magnitude == HUGE_MAGNITUDE .and. digits > HUGE_DIGITS)
   end function literal_overflows

   !> Whether the exponent of a real literal (the text after its letter: sign and digits) has
   !> more than MAX_EXPONENT_DIGITS digits, its leading zeros not counted (e+0000001 has one),
   !> so that its magnitude (at least 10**MAX_EXPONENT_DIGITS) lies beyond what any line's
   !> mantissa could make up for (a line holds at most 65536 characters): the literal is out of
   !> range unless its digits are all zero.
   pure logical function exponent_too_long(exponent_text)
      character(len=*), intent(in) :: exponent_text
      integer :: first_significant
      first_significant = verify(exponent_text, '+-0')
      exponent_too_long = .false.
      if (first_significant == 0) return           ! all zeros: the exponent is 0
      exponent_too_long = len(exponent_text) - first_significant + 1 > MAX_EXPONENT_DIGITS
   end function exponent_too_long

end module interphase_real_text
