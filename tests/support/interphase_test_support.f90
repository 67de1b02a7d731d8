!> Shared helpers of the interphase test suites: the paper's data and a finite-difference tangent.
module interphase_test_support
   use interphase_kinds, only: dp
   use interphase_layout, only: MODEL_SIMPLIFIED, MODEL_MICROMECHANICAL, DAMAGE_DISPLACEMENT, &
      DAMAGE_FRACTURE, TABLE_DEFAULT_CODE, RCURVE_TABULATED, NPROPS_SIMPLIFIED, NPROPS_MICROMECHANICAL, &
      NPROPS_FRACTURE_EXTRA, LFM_D0, LFM_RCURVE, LFM_GC_I, LFM_GC_II
   use interphase_params, only: law_params_type, params_from_values
   use interphase_state, only: interface_state_type
   use interphase_kernel, only: interface_update
   use interphase_status, only: MESSAGE_LEN
   use interphase_coefficients, only: coefficient_set_type
   implicit none
   private
   public :: paper_params, paper_k_n, paper_k_t, fd_tangent, linear_path, micro_params, source_path, &
      scratch_path, paper_props, micro_props, tabulated_rcurve_props, coefficient_array

   !> RVE data of the paper's section 5 (mm, MPa).
   real(dp), parameter :: H_M = 2.0_dp, H_B = 3.0_dp, E_M = 1000.0_dp, E_B = 16000.0_dp, NU = 0.15_dp

contains

   !> The 11 coefficients of a set as an array, in the type's order (for comparisons).
   pure function coefficient_array(c) result(v)
      type(coefficient_set_type), intent(in) :: c
      real(dp) :: v(11)
      v = [c%k_n, c%k_t, c%kc_n, c%kc_t, c%dbar_n, c%dbar_t, c%tc_t, c%sc_n, c%cf_t, c%tf, c%ufbar]
   end function coefficient_array

   !> K_T = C^_TT/h from the laminate closed form of docs/rve.md, 'Exact identities' (MPa/mm).
   pure real(dp) function paper_k_t()
      real(dp) :: g_m, g_b
      g_m = E_M/(2.0_dp*(1.0_dp + NU))
      g_b = E_B/(2.0_dp*(1.0_dp + NU))
      paper_k_t = 1.0_dp/(H_M/g_m + H_B/g_b)
   end function paper_k_t

   !> K_N = C^_NN/h, with the constrained moduli M = E(1-nu)/((1+nu)(1-2nu)) (MPa/mm).
   pure real(dp) function paper_k_n()
      real(dp) :: m_m, m_b
      m_m = E_M*(1.0_dp - NU)/((1.0_dp + NU)*(1.0_dp - 2.0_dp*NU))
      m_b = E_B*(1.0_dp - NU)/((1.0_dp + NU)*(1.0_dp - 2.0_dp*NU))
      paper_k_n = 1.0_dp/(H_M/m_m + H_B/m_b)
   end function paper_k_n

   !> The simplified model with the paper's Table 1 and mu (default 0.75, our assumption).
   function paper_params(mu) result(params)
      real(dp), intent(in), optional :: mu
      type(law_params_type) :: params
      integer :: status
      character(len=MESSAGE_LEN) :: message
      real(dp) :: mu_used
      mu_used = 0.75_dp
      if (present(mu)) mu_used = mu
      call params_from_values(MODEL_SIMPLIFIED, DAMAGE_DISPLACEMENT, mu_used, 0.00044_dp, 0.04_dp, &
         0.00072_dp, 0.06_dp, params, status, message, k_n=paper_k_n(), k_t=paper_k_t())
      if (status /= 0) error stop 'paper_params: invalid test data'
   end function paper_params

   !> PROPS (docs/abaqus.md) of the simplified model with the paper's Table 1 data, mu = 0.75.
   pure function paper_props() result(props)
      real(dp) :: props(NPROPS_SIMPLIFIED)
      props = [real(MODEL_SIMPLIFIED, dp), real(DAMAGE_DISPLACEMENT, dp), 0.75_dp, 0.00044_dp, &
         0.04_dp, 0.00072_dp, 0.06_dp, paper_k_n(), paper_k_t()]
   end function paper_props

   !> PROPS of the micromechanical model with the paper's Table 1 damage data, mu = 0.75, on
   !> the table `table` (TABLE_*_CODE).
   pure function micro_props(table) result(props)
      integer, intent(in) :: table
      real(dp) :: props(NPROPS_MICROMECHANICAL)
      props = [real(MODEL_MICROMECHANICAL, dp), real(DAMAGE_DISPLACEMENT, dp), 0.75_dp, 0.00044_dp, &
         0.04_dp, 0.00072_dp, 0.06_dp, real(table, dp)]
   end function micro_props

   !> PROPS of the simplified model with the fracture-mechanics law on the tabulated R-curve
   !> (D0 = 0.1; the R-curve itself is loaded at start-up).
   pure function tabulated_rcurve_props() result(props)
      real(dp) :: props(NPROPS_SIMPLIFIED + NPROPS_FRACTURE_EXTRA)
      props(1:NPROPS_SIMPLIFIED) = paper_props()
      props(2) = real(DAMAGE_FRACTURE, dp)
      props(NPROPS_SIMPLIFIED + LFM_D0) = 0.1_dp
      props(NPROPS_SIMPLIFIED + LFM_RCURVE) = real(RCURVE_TABULATED, dp)
      props(NPROPS_SIMPLIFIED + LFM_GC_I) = 0.0_dp
      props(NPROPS_SIMPLIFIED + LFM_GC_II) = 0.0_dp
   end function tabulated_rcurve_props

   !> The micromechanical model with the paper's Table 1 damage data and mu = 0.75 on the given
   !> table (default: the built-in one).
   function micro_params(table) result(params)
      integer, intent(in), optional :: table
      type(law_params_type) :: params
      integer :: status, table_used
      character(len=MESSAGE_LEN) :: message
      table_used = TABLE_DEFAULT_CODE
      if (present(table)) table_used = table
      call params_from_values(MODEL_MICROMECHANICAL, DAMAGE_DISPLACEMENT, 0.75_dp, 0.00044_dp, 0.04_dp, &
         0.00072_dp, 0.06_dp, params, status, message, table=table_used)
      if (status /= 0) error stop 'micro_params: invalid test data'
   end function micro_params

   !> A path inside the source tree (INTERPHASE_SOURCE_DIR, set by ctest).
   function source_path(relative) result(path)
      character(len=*), intent(in) :: relative
      character(len=:), allocatable :: path
      character(len=4096) :: root
      integer :: status
      call get_environment_variable('INTERPHASE_SOURCE_DIR', root, status=status)
      if (status /= 0) error stop 'source_path: INTERPHASE_SOURCE_DIR is not set (run the test through ctest)'
      path = trim(root)//'/'//relative
   end function source_path

   !> A scratch file name in the test's working directory.
   function scratch_path(name) result(path)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path
      path = 'scratch_'//name
   end function scratch_path

   !> Central finite-difference tangent of the update at fixed old state (MPa/mm), from the
   !> separation s_old at the start of the increment where given (interface_update's).
   function fd_tangent(params, old, s, step, s_old) result(tangent)
      type(law_params_type), intent(in) :: params
      type(interface_state_type), intent(in) :: old
      real(dp), intent(in) :: s(:)
      real(dp), intent(in) :: step           !! separation step (mm)
      real(dp), intent(in), optional :: s_old(:)
      real(dp) :: tangent(size(s), size(s))
      real(dp) :: sp(size(s)), tp(size(s)), tm(size(s)), k(size(s), size(s)), psi
      type(interface_state_type) :: new
      integer :: j, status
      do j = 1, size(s)
         sp = s
         sp(j) = s(j) + step
         call interface_update(params, old, sp, tp, k, new, psi, status, s_old=s_old)
         sp(j) = s(j) - step
         call interface_update(params, old, sp, tm, k, new, psi, status, s_old=s_old)
         tangent(:, j) = (tp - tm)/(2.0_dp*step)
      end do
   end function fd_tangent

   !> Points of a piecewise-linear path through `knots(:, k)` with `nsub` equal steps per segment
   !> (the first column is the first knot).
   pure function linear_path(knots, nsub) result(path)
      real(dp), intent(in) :: knots(:, :)
      integer, intent(in) :: nsub
      real(dp) :: path(size(knots, 1), (size(knots, 2) - 1)*nsub + 1)
      integer :: k, i
      path(:, 1) = knots(:, 1)
      do k = 1, size(knots, 2) - 1
         do i = 1, nsub
            path(:, (k - 1)*nsub + i + 1) = knots(:, k) + (knots(:, k + 1) - knots(:, k))*real(i, dp)/real(nsub, dp)
         end do
      end do
   end function linear_path

end module interphase_test_support
