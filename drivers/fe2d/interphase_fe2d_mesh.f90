!> Mesh, degrees of freedom and element matrices of `interphase-fe2d`.
!>
!> Bricks are stacked along y (brick 1 at the bottom, joints along y = const) and meshed with
!> bilinear plane-strain quadrilaterals (Q4, 2x2 Gauss). Every brick has its own nodes; the
!> nodes of two bricks facing each other across a joint coincide and are connected by
!> zero-thickness 4-node interface elements (2 nodes on each face), one per brick element
!> along the joint. Node numbering: brick by brick, row by row (left to right, bottom to top),
!> so that the interface elements connect consecutive rows and the band stays narrow.
!>
!> Degrees of freedom are mapped to equation numbers; several DOFs may share one equation,
!> which is how ties are made (the horizontal DOFs of the loaded face share the equation of
!> the prescribed shear displacement u; periodic lateral faces share the equations of their
!> left nodes). Free equations are 1..nfree; then EQ_ZERO (every fixed DOF, value 0) and
!> EQ_SHEAR (the tied loaded face, value u).
module interphase_fe2d_mesh
   use interphase_kinds, only: dp
   use interphase_fe2d_case, only: fe2d_case_type, SIDES_PERIODIC, INTEGRATION_LOBATTO
   implicit none
   private
   public :: fe2d_mesh_type, build_mesh, q4_stiffness, interface_b_matrix, node_id

   !> The discretised specimen.
   type :: fe2d_mesh_type
      integer :: nnode = 0                        !! nodes
      real(dp), allocatable :: x(:, :)            !! x(1:2, node) coordinates (mm)
      integer :: nquad = 0                        !! brick elements
      integer, allocatable :: quad(:, :)          !! quad(1:4, e) counter-clockwise nodes
      integer :: nintf = 0                        !! interface elements (all joints)
      integer, allocatable :: intf(:, :)          !! intf(1:4, e): bottom-face a1, a2; top-face b1, b2
      integer, allocatable :: intf_joint(:)       !! joint number (1 = lowest) of each element
      integer :: njoint = 0                       !! joints
      integer :: npoint = 2                       !! integration points per interface element
      real(dp) :: xi(2) = 0.0_dp                  !! their natural coordinates
      real(dp) :: weight(2) = 0.0_dp              !! their weights
      integer, allocatable :: eq(:, :)            !! eq(1:2, node) equation of each DOF
      integer :: nfree = 0                        !! free equations
      integer :: neq = 0                          !! all equations (nfree + 2)
      integer :: eq_zero = 0                      !! the equation of the fixed DOFs
      integer :: eq_shear = 0                     !! the equation of the prescribed shear u
      integer :: bandwidth = 0                    !! max |i - j| over coupled free equations
      real(dp), allocatable :: f_pressure(:)      !! nodal forces of a unit pressure (N/MPa), by equation
      integer, allocatable :: top_face(:)         !! nodes of the top face of the top brick
      real(dp) :: thickness = 1.0_dp              !! out-of-plane thickness (mm)
      real(dp) :: d_matrix(3, 3) = 0.0_dp         !! plane-strain elasticity of the bricks (MPa)
   end type fe2d_mesh_type

contains

   !> Node number of column i (0..nx), row j (0..ny) of brick b (1..bricks).
   pure integer function node_id(run, b, i, j)
      type(fe2d_case_type), intent(in) :: run     !! the case (mesh density)
      integer, intent(in) :: b, i, j              !! brick, column, row

      node_id = (b - 1)*(run%nx + 1)*(run%ny + 1) + j*(run%nx + 1) + i + 1
   end function node_id

   !> Build the mesh, the DOF map and the unit-pressure load of the case.
   !> Boundary conditions (the masonry shear test):
   !>  - couplet (2 bricks): bottom face of brick 1 fixed; top face of brick 2 loaded by the
   !>    precompression pressure, its horizontal DOFs tied to the prescribed shear u, vertical free;
   !>  - triplet (3 bricks): bottom face of brick 1 fixed; top face of brick 3 loaded by the
   !>    pressure, horizontally fixed, vertically free; the left face of the middle brick 2
   !>    (the face the actuator pushes) tied horizontally to u.
   !>  - sides = 'periodic': the right face of every brick tied to its left face (both DOFs).
   subroutine build_mesh(run, mesh)
      type(fe2d_case_type), intent(in) :: run     !! the case
      type(fe2d_mesh_type), intent(out) :: mesh   !! the mesh
      integer :: b, i, j, e, n, k, m, nx, ny, dir, master
      integer, parameter :: UNSET = 0
      real(dp) :: hx, hy, fac, nu

      nx = run%nx
      ny = run%ny
      hx = run%brick_length/nx
      hy = run%brick_height/ny
      mesh%thickness = run%thickness
      mesh%nnode = run%bricks*(nx + 1)*(ny + 1)
      allocate (mesh%x(2, mesh%nnode))
      do b = 1, run%bricks
         do j = 0, ny
            do i = 0, nx
               n = node_id(run, b, i, j)
               mesh%x(1, n) = i*hx
               mesh%x(2, n) = (b - 1)*run%brick_height + j*hy
            end do
         end do
      end do
      mesh%nquad = run%bricks*nx*ny
      allocate (mesh%quad(4, mesh%nquad))
      e = 0
      do b = 1, run%bricks
         do j = 0, ny - 1
            do i = 0, nx - 1
               e = e + 1
               mesh%quad(:, e) = [node_id(run, b, i, j), node_id(run, b, i + 1, j), &
                  node_id(run, b, i + 1, j + 1), node_id(run, b, i, j + 1)]
            end do
         end do
      end do
      mesh%njoint = run%bricks - 1
      mesh%nintf = mesh%njoint*nx
      allocate (mesh%intf(4, mesh%nintf), mesh%intf_joint(mesh%nintf))
      e = 0
      do b = 1, mesh%njoint
         do i = 0, nx - 1
            e = e + 1
            mesh%intf(:, e) = [node_id(run, b, i, ny), node_id(run, b, i + 1, ny), &
               node_id(run, b + 1, i, 0), node_id(run, b + 1, i + 1, 0)]
            mesh%intf_joint(e) = b
         end do
      end do
      if (run%integration == INTEGRATION_LOBATTO) then
         mesh%xi = [-1.0_dp, 1.0_dp]
      else
         mesh%xi = [-1.0_dp, 1.0_dp]/sqrt(3.0_dp)
      end if
      mesh%weight = 1.0_dp

      ! ---- DOF map: fixed and tied DOFs first (negative markers), then free numbering ----
      ! mark: 0 free, -1 fixed (EQ_ZERO), -2 shear (EQ_SHEAR), > 0 tied to DOF mark of that node
      allocate (mesh%eq(2, mesh%nnode))
      mesh%eq = UNSET
      do i = 0, nx
         mesh%eq(:, node_id(run, 1, i, 0)) = -1
      end do
      if (run%bricks == 2) then
         do i = 0, nx
            mesh%eq(1, node_id(run, 2, i, ny)) = -2
         end do
      else
         do i = 0, nx
            mesh%eq(1, node_id(run, 3, i, ny)) = -1
         end do
         do j = 0, ny
            mesh%eq(1, node_id(run, 2, 0, j)) = -2
         end do
      end if
      ! free equations, in node order
      k = 0
      do n = 1, mesh%nnode
         do dir = 1, 2
            if (mesh%eq(dir, n) == UNSET .and. .not. is_periodic_slave(n)) then
               k = k + 1
               mesh%eq(dir, n) = k
            end if
         end do
      end do
      mesh%nfree = k
      mesh%eq_zero = k + 1
      mesh%eq_shear = k + 2
      mesh%neq = k + 2
      do n = 1, mesh%nnode
         do dir = 1, 2
            if (mesh%eq(dir, n) == -1) mesh%eq(dir, n) = mesh%eq_zero
            if (mesh%eq(dir, n) == -2) mesh%eq(dir, n) = mesh%eq_shear
         end do
      end do
      ! periodic slaves take their master's equation (after the master is numbered)
      if (run%sides == SIDES_PERIODIC) then
         do b = 1, run%bricks
            do j = 0, ny
               n = node_id(run, b, nx, j)
               master = node_id(run, b, 0, j)
               do dir = 1, 2
                  if (mesh%eq(dir, n) == UNSET) mesh%eq(dir, n) = mesh%eq(dir, master)
               end do
            end do
         end do
      end if

      ! ---- bandwidth over the free equations of every element ----
      mesh%bandwidth = 0
      do e = 1, mesh%nquad
         call widen(mesh%quad(:, e))
      end do
      do e = 1, mesh%nintf
         call widen(mesh%intf(:, e))
      end do

      ! ---- unit pressure on the top face of the top brick (consistent nodal forces) ----
      allocate (mesh%f_pressure(mesh%neq), mesh%top_face(nx + 1))
      mesh%f_pressure = 0.0_dp
      do i = 0, nx
         mesh%top_face(i + 1) = node_id(run, run%bricks, i, ny)
      end do
      do i = 1, nx
         do m = 0, 1
            n = mesh%top_face(i + m)
            mesh%f_pressure(mesh%eq(2, n)) = mesh%f_pressure(mesh%eq(2, n)) - 0.5_dp*hx*run%thickness
         end do
      end do

      nu = run%poisson
      fac = run%young/((1.0_dp + nu)*(1.0_dp - 2.0_dp*nu))
      mesh%d_matrix = 0.0_dp
      mesh%d_matrix(1, 1) = fac*(1.0_dp - nu)
      mesh%d_matrix(2, 2) = fac*(1.0_dp - nu)
      mesh%d_matrix(1, 2) = fac*nu
      mesh%d_matrix(2, 1) = fac*nu
      mesh%d_matrix(3, 3) = fac*(1.0_dp - 2.0_dp*nu)/2.0_dp

   contains

      logical function is_periodic_slave(node)
         integer, intent(in) :: node
         integer :: bb, jj
         is_periodic_slave = .false.
         if (run%sides /= SIDES_PERIODIC) return
         do bb = 1, run%bricks
            do jj = 0, ny
               if (node == node_id(run, bb, nx, jj)) is_periodic_slave = .true.
            end do
         end do
      end function is_periodic_slave

      subroutine widen(nodes)
         integer, intent(in) :: nodes(:)
         integer :: p, q, dp1, dq, ep, eqq
         do p = 1, size(nodes)
            do dp1 = 1, 2
               ep = mesh%eq(dp1, nodes(p))
               if (ep > mesh%nfree) cycle
               do q = 1, size(nodes)
                  do dq = 1, 2
                     eqq = mesh%eq(dq, nodes(q))
                     if (eqq > mesh%nfree) cycle
                     mesh%bandwidth = max(mesh%bandwidth, abs(ep - eqq))
                  end do
               end do
            end do
         end do
      end subroutine widen

   end subroutine build_mesh

   !> Stiffness of a bilinear plane-strain quadrilateral, 2x2 Gauss; DOF order
   !> (u1, v1, u2, v2, u3, v3, u4, v4) for the counter-clockwise nodes.
   pure subroutine q4_stiffness(xy, d_matrix, thickness, ke)
      real(dp), intent(in) :: xy(2, 4)            !! node coordinates (mm)
      real(dp), intent(in) :: d_matrix(3, 3)      !! plane-strain elasticity (MPa)
      real(dp), intent(in) :: thickness           !! out-of-plane thickness (mm)
      real(dp), intent(out) :: ke(8, 8)           !! element stiffness (N/mm)
      real(dp), parameter :: XI_NODE(4) = [-1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp]
      real(dp), parameter :: ETA_NODE(4) = [-1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp]
      real(dp) :: g, xi, eta, dn(2, 4), jac(2, 2), jinv(2, 2), detj, dndx(2, 4), bm(3, 8)
      integer :: p, q, a

      g = 1.0_dp/sqrt(3.0_dp)
      ke = 0.0_dp
      do p = 1, 2
         do q = 1, 2
            xi = merge(-g, g, p == 1)
            eta = merge(-g, g, q == 1)
            do a = 1, 4
               dn(1, a) = 0.25_dp*XI_NODE(a)*(1.0_dp + ETA_NODE(a)*eta)
               dn(2, a) = 0.25_dp*ETA_NODE(a)*(1.0_dp + XI_NODE(a)*xi)
            end do
            jac = matmul(dn, transpose(xy))
            detj = jac(1, 1)*jac(2, 2) - jac(1, 2)*jac(2, 1)
            jinv(1, :) = [jac(2, 2), -jac(1, 2)]/detj
            jinv(2, :) = [-jac(2, 1), jac(1, 1)]/detj
            dndx = matmul(jinv, dn)
            bm = 0.0_dp
            do a = 1, 4
               bm(1, 2*a - 1) = dndx(1, a)
               bm(2, 2*a) = dndx(2, a)
               bm(3, 2*a - 1) = dndx(2, a)
               bm(3, 2*a) = dndx(1, a)
            end do
            ke = ke + matmul(transpose(bm), matmul(d_matrix, bm))*detj*thickness
         end do
      end do
   end subroutine q4_stiffness

   !> Separation operator of a 4-node interface element at natural coordinate xi:
   !> s = (s_N, s_T) = B d with d = (u_a1, v_a1, u_a2, v_a2, u_b1, v_b1, u_b2, v_b2), the jump
   !> of the top face (b) over the bottom face (a) in the local frame t = (a2 - a1)/|a2 - a1|,
   !> n = t rotated by +90 degrees (pointing into the upper brick). Normal first, as the UMAT.
   !> `half_length` is the Jacobian |a2 - a1|/2 (mm).
   pure subroutine interface_b_matrix(xy, xi, bm, half_length)
      real(dp), intent(in) :: xy(2, 4)            !! coordinates of a1, a2, b1, b2 (mm)
      real(dp), intent(in) :: xi                  !! natural coordinate in [-1, 1]
      real(dp), intent(out) :: bm(2, 8)           !! separation operator (-)
      real(dp), intent(out) :: half_length        !! Jacobian (mm)
      real(dp) :: t(2), n(2), shape(2), length
      integer :: a

      t = xy(:, 2) - xy(:, 1)
      length = sqrt(sum(t**2))
      t = t/length
      n = [-t(2), t(1)]
      half_length = 0.5_dp*length
      shape = [0.5_dp*(1.0_dp - xi), 0.5_dp*(1.0_dp + xi)]
      bm = 0.0_dp
      do a = 1, 2
         bm(1, 2*a - 1:2*a) = -shape(a)*n
         bm(2, 2*a - 1:2*a) = -shape(a)*t
         bm(1, 2*a + 3:2*a + 4) = shape(a)*n
         bm(2, 2*a + 3:2*a + 4) = shape(a)*t
      end do
   end subroutine interface_b_matrix

end module interphase_fe2d_mesh
