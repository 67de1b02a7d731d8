!> One call of each adapter with the arguments a test varies: the UMAT for one point, the VUMAT
!> for a block of points (separation increments turned into Abaqus/Explicit strain increments)
!> and the C entry point. The arguments Abaqus passes but interphase does not read are set to
!> neutral values here, once.
module interphase_adapter_calls
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_char, c_null_char, c_loc, c_null_ptr
   use interphase_kinds, only: dp
   use interphase_layout, only: NSTATV_REQUIRED, NSTATV_VUMAT
   use interphase_abaqus_interfaces, only: umat, vumat
   use interphase_capi, only: interphase_update_c, interphase_update_increment_c
   implicit none
   private
   public :: umat_point_type, call_umat_point, call_umat_element, vumat_block_type, vumat_block_init, call_vumat_block, &
      call_capi

   !> What one UMAT point carries from one increment to the next.
   type :: umat_point_type
      integer :: ntens = 2
      real(dp) :: stran(3) = 0.0_dp          !! separation at the start of the increment (mm)
      real(dp) :: stress(3) = 0.0_dp         !! traction (MPa)
      real(dp) :: statev(NSTATV_REQUIRED) = 0.0_dp
      real(dp) :: ddsdde(3, 3) = 0.0_dp      !! tangent (MPa/mm)
      real(dp) :: sse = 0.0_dp, spd = 0.0_dp !! stored and dissipated energy (N/mm)
      real(dp) :: pnewdt = 1.0_dp
   end type umat_point_type

   !> What a block of VUMAT points carries from one call to the next.
   type :: vumat_block_type
      integer :: nblock = 0, nshr = 1
      real(dp), allocatable :: stress(:, :)         !! (nblock, 1 + nshr) tractions (MPa)
      real(dp), allocatable :: state(:, :)          !! (nblock, NSTATV_VUMAT)
      real(dp), allocatable :: ener_intern(:), ener_inelas(:)   !! per unit mass
      real(dp), allocatable :: density(:)
   end type vumat_block_type

contains

   !> One UMAT increment of separation ds (size ntens) on point p; STRAN is advanced only when
   !> the call succeeds (PNEWDT not lowered).
   subroutine call_umat_point(p, props, ds, cmname)
      type(umat_point_type), intent(inout) :: p
      real(dp), intent(in) :: props(:)
      real(dp), intent(in) :: ds(:)
      character(len=*), intent(in), optional :: cmname
      real(dp) :: pnewdt_in
      integer :: n
      n = p%ntens
      pnewdt_in = p%pnewdt
      if (present(cmname)) then
         call call_umat_element(p%stress(1:n), p%statev, p%ddsdde(1:n, 1:n), p%sse, p%spd, p%stran(1:n), ds(1:n), 1, &
            n - 1, props, p%pnewdt, cmname)
      else
         call call_umat_element(p%stress(1:n), p%statev, p%ddsdde(1:n, 1:n), p%sse, p%spd, p%stran(1:n), ds(1:n), 1, &
            n - 1, props, p%pnewdt, 'ADAPTER_CALLS')
      end if
      if (.not. (p%pnewdt < pnewdt_in)) p%stran(1:n) = p%stran(1:n) + ds(1:n)
   end subroutine call_umat_point

   !> One UMAT call with the arguments a test varies (NTENS = size(stress), NSTATV = size(statev),
   !> NDI, NSHR and NPROPS = size(props) as given, so also inconsistent ones), the others neutral.
   subroutine call_umat_element(stress, statev, ddsdde, sse, spd, stran, dstran, ndi, nshr, props, pnewdt, cmname)
      real(dp), intent(inout) :: stress(:), statev(:), ddsdde(:, :), sse, spd, pnewdt
      real(dp), intent(in) :: stran(:), dstran(:), props(:)
      integer, intent(in) :: ndi, nshr
      character(len=*), intent(in) :: cmname
      real(dp) :: scd, rpl, ddsddt(size(stress)), drplde(size(stress)), drpldt, time(2), predef(1), dpred(1)
      real(dp) :: coords(3), drot(3, 3), dfgrd(3, 3), tangent(size(stress), size(stress))
      character(len=80) :: name
      integer :: n
      n = size(stress)
      name = cmname
      scd = 0.0_dp
      rpl = 0.0_dp
      ddsddt = 0.0_dp
      drplde = 0.0_dp
      drpldt = 0.0_dp
      time = 1.0_dp
      predef = 0.0_dp
      dpred = 0.0_dp
      coords = 0.0_dp
      drot = 0.0_dp
      dfgrd = 0.0_dp
      tangent = ddsdde
      call umat(stress, statev, tangent, sse, spd, scd, rpl, ddsddt, drplde, drpldt, stran, dstran, time, 1.0_dp, &
         0.0_dp, 0.0_dp, predef, dpred, name, ndi, nshr, n, size(statev), props, size(props), coords, drot, pnewdt, &
         1.0_dp, dfgrd, dfgrd, 1, 1, 1, 1, [1, 1, 0, 0], 1)
      ddsdde = tangent
   end subroutine call_umat_element

   !> A block of nblock intact points (no separation, zero energies) of density rho.
   subroutine vumat_block_init(b, nblock, nshr, rho)
      type(vumat_block_type), intent(out) :: b
      integer, intent(in) :: nblock, nshr
      real(dp), intent(in) :: rho
      b%nblock = nblock
      b%nshr = nshr
      allocate (b%stress(nblock, 1 + nshr), b%state(nblock, NSTATV_VUMAT), b%ener_intern(nblock), &
         b%ener_inelas(nblock), b%density(nblock))
      b%stress = 0.0_dp
      b%state = 0.0_dp
      b%ener_intern = 0.0_dp
      b%ener_inelas = 0.0_dp
      b%density = rho
   end subroutine vumat_block_init

   !> One VUMAT call (total time > 0: not the packaging call) with separation increments
   !> ds(point, component) (mm), passed as strain increments with tensor shears (ds_T/2).
   subroutine call_vumat_block(b, props, ds, cmname)
      type(vumat_block_type), intent(inout) :: b
      real(dp), intent(in) :: props(:)
      real(dp), intent(in) :: ds(:, :)
      character(len=*), intent(in), optional :: cmname
      real(dp) :: strain_inc(b%nblock, 1 + b%nshr), zeros(b%nblock, 3), ones(b%nblock, 5)
      real(dp) :: stress_new(b%nblock, 1 + b%nshr), state_new(b%nblock, NSTATV_VUMAT)
      real(dp) :: ei_new(b%nblock), ep_new(b%nblock)
      character(len=80) :: name
      integer :: n
      n = 1 + b%nshr
      name = 'ADAPTER_CALLS'
      if (present(cmname)) name = cmname
      strain_inc(:, 1) = ds(1:b%nblock, 1)
      strain_inc(:, 2:n) = 0.5_dp*ds(1:b%nblock, 2:n)
      ! what interphase does not read: coordinates, spin, temperatures and field 0; characteristic
      ! length, stretches and deformation gradients 1 (sections of two arrays, read only)
      zeros = 0.0_dp
      ones = 1.0_dp
      call vumat(b%nblock, 1, b%nshr, NSTATV_VUMAT, 1, size(props), 0, 1.0_dp, 1.0_dp, 1.0e-3_dp, name, &
         zeros, ones(:, 1), props, b%density, strain_inc, zeros(:, 1:b%nshr), zeros(:, 1), ones(:, 1:n), &
         ones(:, 1:n + b%nshr), zeros(:, 1:1), b%stress, b%state, b%ener_intern, b%ener_inelas, zeros(:, 1), &
         ones(:, 1:n), ones(:, 1:n + b%nshr), zeros(:, 1:1), stress_new, state_new, ei_new, ep_new)
      b%stress = stress_new
      b%state = state_new
      b%ener_intern = ei_new
      b%ener_inelas = ep_new
   end subroutine call_vumat_block

   !> One call of the C entry point interphase_update, or interphase_update_increment where the
   !> separation at the start of the increment is given (through their Fortran bindings); the
   !> tangent comes back row-major as C returns it, reshaped here to tangent(i, j) = dt_i/ds_j. On
   !> a non-zero status the outputs are left as they were and `detail` holds the message.
   subroutine call_capi(props, ntens, state_old, separation, traction, tangent, state_new, psi, status, detail, &
         separation_old)
      real(dp), intent(in) :: props(:)
      integer, intent(in) :: ntens
      real(dp), intent(in) :: state_old(NSTATV_REQUIRED), separation(ntens)
      real(dp), intent(in), optional :: separation_old(ntens)
      real(dp), intent(inout) :: traction(ntens), tangent(ntens, ntens), state_new(NSTATV_REQUIRED), psi
      integer, intent(out) :: status
      character(len=*), intent(out) :: detail
      integer, parameter :: DETAIL_LEN = 512
      character(kind=c_char), target :: buffer(DETAIL_LEN)
      ! (the C entry takes pointers: targets holding the arguments)
      real(dp), target :: row_major(ntens*ntens), c_props(size(props)), c_old(NSTATV_REQUIRED), c_s(ntens), &
         c_t(ntens), c_new(NSTATV_REQUIRED), c_psi, c_s_old(ntens)
      integer :: i, j
      c_props = props
      c_old = state_old
      c_s = separation
      c_t = traction
      c_new = state_new
      c_psi = psi
      row_major = 0.0_dp
      do i = 1, ntens
         do j = 1, ntens
            row_major((i - 1)*ntens + j) = tangent(i, j)
         end do
      end do
      buffer = c_null_char
      if (present(separation_old)) then
         c_s_old = separation_old
         status = int(interphase_update_increment_c(c_loc(c_props), int(size(props), c_int), int(ntens, c_int), &
            c_loc(c_old), c_loc(c_s_old), c_loc(c_s), c_null_ptr, c_loc(c_t), c_loc(row_major), c_loc(c_new), &
            c_loc(c_psi), c_loc(buffer), int(DETAIL_LEN, c_size_t)))
      else
         status = int(interphase_update_c(c_loc(c_props), int(size(props), c_int), int(ntens, c_int), c_loc(c_old), &
            c_loc(c_s), c_loc(c_t), c_loc(row_major), c_loc(c_new), c_loc(c_psi), c_loc(buffer), int(DETAIL_LEN, c_size_t)))
      end if
      traction = c_t
      state_new = c_new
      psi = c_psi
      do i = 1, ntens
         do j = 1, ntens
            tangent(i, j) = row_major((i - 1)*ntens + j)
         end do
      end do
      detail = ''
      do i = 1, min(DETAIL_LEN, len(detail))
         if (buffer(i) == c_null_char) exit
         detail(i:i) = buffer(i)
      end do
   end subroutine call_capi

end module interphase_adapter_calls
