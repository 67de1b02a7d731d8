!> Output of the single-point driver: the CSV table of the replayed history and the gnuplot
!> script that draws its traction-separation curves.
!>
!> CSV columns (2-D): t,s_T,s_N,Sigma_T,Sigma_N,D,slip,state,psi,W_dis
!> CSV columns (3-D): t,s_T1,s_T2,s_N,Sigma_T1,Sigma_T2,Sigma_N,D,slip_1,slip_2,state,psi,W_dis
!> Separations and slips in mm, tractions in MPa, D dimensionless, state one of
!> intact|open|stick|slip, psi the stored energy (UMAT's SSE) and W_dis the dissipated energy
!> (UMAT's SPD), both per unit area (N/mm). Numbers are written with 17 significant digits.
!> Note the order: the UMAT arrays are normal first, the CSV puts the shear(s) first.
module interphase_driver_output
   use interphase_kinds, only: dp
   use interphase_layout, only: SV_DAMAGE, SV_SLIP_1, SV_SLIP_2, SV_REGIME, REGIME_INTACT, &
      REGIME_OPEN, REGIME_STICK, REGIME_SLIP
   use interphase_driver_text, only: int_to_string, real_to_csv, real_to_string, gnuplot_quote
   implicit none
   private
   public :: csv_header, write_csv_row, write_plot_script

contains

   !> The CSV header line for NTENS = 2 or 3.
   pure function csv_header(ntens, tangent_error) result(header)
      integer, intent(in) :: ntens                !! 2 (2-D) or 3 (3-D)
      logical, intent(in), optional :: tangent_error  !! add the tangent check's column
      character(len=:), allocatable :: header

      if (ntens == 2) then
         header = 't,s_T,s_N,Sigma_T,Sigma_N,D,slip,state,psi,W_dis'
      else
         header = 't,s_T1,s_T2,s_N,Sigma_T1,Sigma_T2,Sigma_N,D,slip_1,slip_2,state,psi,W_dis'
      end if
      if (present(tangent_error)) then
         if (tangent_error) header = header//',tangent_error'
      end if
   end function csv_header

   !> Write one CSV row. Fails (ok false) if STATEV holds no known regime code.
   subroutine write_csv_row(unit, time, separation, stress, statev, sse, spd, ok, message, extra)
      integer, intent(in) :: unit                 !! open CSV file
      real(dp), intent(in) :: time                !! t
      real(dp), intent(in) :: separation(:)       !! s, UMAT order: normal first (mm)
      real(dp), intent(in) :: stress(:)           !! traction, UMAT order: normal first (MPa)
      real(dp), intent(in) :: statev(:)           !! UMAT state variables
      real(dp), intent(in) :: sse                 !! stored energy per unit area (N/mm)
      real(dp), intent(in) :: spd                 !! dissipated energy per unit area (N/mm)
      logical, intent(out) :: ok                  !! false on an unknown regime code
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      real(dp), intent(in), optional :: extra(:)  !! more columns at the end of the row
      character(len=:), allocatable :: row, state
      character(len=1), parameter :: SEP = ','
      integer :: i

      call regime_name(statev(SV_REGIME), state, ok)
      if (.not. ok) then
         message = 'unknown regime code STATEV('//int_to_string(SV_REGIME)// &
            ') = '//real_to_string(statev(SV_REGIME))//' at t = '//real_to_string(time)
         return
      end if
      if (size(separation) == 2) then
         row = real_to_csv(time)//SEP//real_to_csv(separation(2))//SEP// &
            real_to_csv(separation(1))//SEP//real_to_csv(stress(2))//SEP// &
            real_to_csv(stress(1))//SEP//real_to_csv(statev(SV_DAMAGE))//SEP// &
            real_to_csv(statev(SV_SLIP_1))//SEP//state//SEP//real_to_csv(sse)//SEP// &
            real_to_csv(spd)
      else
         row = real_to_csv(time)//SEP//real_to_csv(separation(2))//SEP// &
            real_to_csv(separation(3))//SEP//real_to_csv(separation(1))//SEP// &
            real_to_csv(stress(2))//SEP//real_to_csv(stress(3))//SEP// &
            real_to_csv(stress(1))//SEP//real_to_csv(statev(SV_DAMAGE))//SEP// &
            real_to_csv(statev(SV_SLIP_1))//SEP//real_to_csv(statev(SV_SLIP_2))//SEP// &
            state//SEP//real_to_csv(sse)//SEP//real_to_csv(spd)
      end if
      if (present(extra)) then
         do i = 1, size(extra)
            row = row//SEP//real_to_csv(extra(i))
         end do
      end if
      write (unit, '(a)') row
   end subroutine write_csv_row

   !> Name of the regime stored in STATEV(SV_REGIME): intact, open, stick or slip.
   subroutine regime_name(code, name, ok)
      real(dp), intent(in) :: code                !! STATEV(SV_REGIME)
      character(len=:), allocatable, intent(out) :: name  !! the name when ok
      logical, intent(out) :: ok                  !! false if code is not a REGIME_* value
      integer :: icode

      ok = .false.
      name = ''
      if (.not. (abs(code) < 100.0_dp)) return
      icode = nint(code)
      if (abs(code - real(icode, dp)) > 0.0_dp) return
      ok = .true.
      select case (icode)
      case (REGIME_INTACT); name = 'intact'
      case (REGIME_OPEN);   name = 'open'
      case (REGIME_STICK);  name = 'stick'
      case (REGIME_SLIP);   name = 'slip'
      case default;         ok = .false.
      end select
   end subroutine regime_name

   !> Write a gnuplot script that draws the curves of a CSV file into one PNG: one panel of
   !> traction against separation per component that moves (Sigma_N vs s_N, Sigma_T vs s_T in 2-D;
   !> Sigma_T1 vs s_T1, Sigma_T2 vs s_T2 in 3-D; a component whose separation and traction both
   !> stay constant has no panel), and a panel of the damage D(t). The title names the case and its
   !> material (`title`, two lines: the case, then the material). File names in the script are
   !> relative: run it in its directory.
   subroutine write_plot_script(script_path, csv_name, png_name, title, material, ntens, ok, message, moving)
      character(len=*), intent(in) :: script_path !! where to write the script
      character(len=*), intent(in) :: csv_name    !! CSV file name, relative to the script
      character(len=*), intent(in) :: png_name    !! PNG file name, relative to the script
      character(len=*), intent(in) :: title       !! the case name
      character(len=*), intent(in) :: material    !! the material line (model, law, parameters)
      integer, intent(in) :: ntens                !! 2 or 3
      logical, intent(out) :: ok                  !! true on success
      character(len=:), allocatable, intent(out) :: message  !! error text when not ok
      !> UMAT order: false for a component that stays constant (no panel); default all true
      logical, intent(in), optional :: moving(:)
      !> Capital sigma as a gnuplot Unicode escape (double-quoted strings, gnuplot >= 5.2).
      character(len=*), parameter :: SIGMA = '\U+03A3'
      integer :: unit, ios, npanels, width
      logical :: show(3)
      character(len=512) :: iomsg
      character(len=16) :: text

      ok = .false.
      show = .true.
      if (present(moving)) show(:ntens) = moving(:ntens)
      if (.not. any(show(:ntens))) show(1) = .true.
      open (newunit=unit, file=script_path, status='replace', action='write', iostat=ios, &
         iomsg=iomsg)
      if (ios /= 0) then
         message = script_path//': cannot write the gnuplot script: '//trim(iomsg)
         return
      end if
      npanels = count(show(:ntens)) + 1
      width = max(1250, 450*npanels + 100)
      write (text, '(i0)') width
      write (unit, '(a)') '# Curves of '//csv_name//' - generated by interphase-point, do not edit.', &
         'set encoding utf8', &
         'set datafile separator ","', &
         'width = '//trim(text)
      write (unit, '(a)') &
         'if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {', &
         '  set terminal pngcairo enhanced size width, 560 font ",11"', &
         '} else {', &
         '  set terminal png enhanced size width, 560', &
         '}', &
         'set output '//gnuplot_quote(png_name), &
         'set multiplot layout 1,'//achar(iachar('0') + npanels)//' title "'//escape(title)//': '// &
         lines_of(material)//'" noenhanced font ",12"', &
         'set grid', &
         'set key top right box opaque', &
         'set zeroaxis', &
         'set xtics nomirror rotate by -30', &
         'set rmargin 5', &
         'set tmargin 6'
      if (ntens == 2) then
         if (show(1)) call panel('s_N', SIGMA//'_N', 3, 5, 'normal')
         if (show(2)) call panel('s_T', SIGMA//'_T', 2, 4, 'tangential')
         call damage_panel(6)
      else
         if (show(1)) call panel('s_N', SIGMA//'_N', 4, 7, 'normal')
         if (show(2)) call panel('s_{T1}', SIGMA//'_{T1}', 2, 5, 'tangential 1')
         if (show(3)) call panel('s_{T2}', SIGMA//'_{T2}', 3, 6, 'tangential 2')
         call damage_panel(8)
      end if
      write (unit, '(a)') 'unset multiplot'
      close (unit)
      ok = .true.

   contains

      !> One panel: traction (column y) against separation (column x).
      subroutine panel(x_name, y_name, x_column, y_column, label)
         character(len=*), intent(in) :: x_name   !! separation symbol (enhanced text)
         character(len=*), intent(in) :: y_name   !! traction symbol (enhanced text)
         integer, intent(in) :: x_column          !! CSV column of the separation
         integer, intent(in) :: y_column          !! CSV column of the traction
         character(len=*), intent(in) :: label    !! panel title

         character(len=:), allocatable :: columns

         columns = achar(iachar('0') + x_column)//':'//achar(iachar('0') + y_column)
         ! a column that stays (nearly) constant gets a fixed range around its value
         write (unit, '(a)') &
            'set title "'//label//'"', &
            'set xlabel "'//x_name//' (mm)"', &
            'set ylabel "'//y_name//' (MPa)"', &
            'set autoscale xy', &
            'stats '//gnuplot_quote(csv_name)//' using '//columns//' skip 1 nooutput', &
            'flat_x = (STATS_max_x - STATS_min_x <= 1e-9*(abs(STATS_max_x) + abs(STATS_min_x)))', &
            'flat_y = (STATS_max_y - STATS_min_y <= 1e-9*(abs(STATS_max_y) + abs(STATS_min_y)))', &
            'if (flat_x) { set xrange [STATS_min_x - 0.01 : STATS_max_x + 0.01] }', &
            'if (flat_y) { set yrange [STATS_min_y - 0.1 : STATS_max_y + 0.1] }', &
            'if (flat_x || flat_y) {', &
            '  plot '//gnuplot_quote(csv_name)//' using '//columns//' skip 1 with linespoints pt 7 ps 0.6 lw 2 '// &
            'lc rgb "#1f4e9a" title "'//y_name//'('//x_name//')"', &
            '} else {', &
            '  plot '//gnuplot_quote(csv_name)//' using '//columns//' skip 1 with lines lw 2 lc rgb "#1f4e9a" '// &
            'title "'//y_name//'('//x_name//')"', &
            '}'
      end subroutine panel

      !> The damage against time.
      subroutine damage_panel(d_column)
         integer, intent(in) :: d_column          !! CSV column of D
         write (unit, '(a)') &
            'set title "damage"', &
            'set xlabel "t"', &
            'set ylabel "D (-)"', &
            'set autoscale x', &
            'set yrange [-0.05:1.05]', &
            'plot '//gnuplot_quote(csv_name)//' using 1:'//achar(iachar('0') + d_column)// &
            ' skip 1 with lines lw 2 lc rgb "#b03a2e" title "D(t)"'
      end subroutine damage_panel

      !> The material line as two title lines: 'model, law' and the parameters after ': '.
      function lines_of(raw) result(cooked)
         character(len=*), intent(in) :: raw
         character(len=:), allocatable :: cooked
         integer :: colon
         colon = index(raw, ': ')
         if (colon > 0) then
            cooked = escape(raw(:colon - 1))//'\n'//escape(raw(colon + 2:))
         else
            cooked = escape(raw)
         end if
      end function lines_of

      !> Text for a double-quoted gnuplot string: backslashes and quotes escaped.
      function escape(raw) result(cooked)
         character(len=*), intent(in) :: raw
         character(len=:), allocatable :: cooked
         integer :: k
         cooked = ''
         do k = 1, len(raw)
            if (raw(k:k) == '"' .or. raw(k:k) == '\') cooked = cooked//'\'
            cooked = cooked//raw(k:k)
         end do
      end function escape

   end subroutine write_plot_script

end module interphase_driver_output
