!> Which of a host's strain and stress components carry the interface's separation and traction
!> (docs/abaqus.md, 'Thin continuum layers'). The UMAT serves two kinds of element through one
!> entry point:
!>
!> - a cohesive element (NDI = 1, NSHR = 1 or 2): the components are normal first, then the
!>   shear(s); with the layer thickness option t = 0 they are the separations themselves
!>   (constitutive thickness 1), with t > 0 nominal strains of a layer of thickness t (Abaqus's
!>   cohesive elements with a continuum response, constitutive thickness t);
!> - a thin continuum layer (NDI = 2 or 3: CPE4/CPS4/CAX4 with NTENS = 4 or 3, C3D8 with
!>   NTENS = 6; CalculiX passes NTENS = 6 for every element): the layer's normal is the axis n
!>   given by the option; s_N = t eps_nn and s_T = t gamma_nk for the axes k /= n, engineering
!>   shears in the host's order (11, 22, 33, 12, 13, 23).
!>
!> In both the traction is the stress on the layer's plane, sigma_nn and tau_nk, and
!> d(sigma)/d(eps) = t dT/ds. Every other component (the layer's in-plane direct strains and its
!> in-plane shear) carries no stress and no stiffness: the interface is a zero-thickness joint in
!> which the mortar's in-plane stiffness is lumped into the bricks, as in the paper's RVE, and a
!> layer stiffness there would be a second, unmodelled mortar.
module interphase_layer
   use interphase_kinds, only: dp
   use interphase_params, only: law_params_type
   use interphase_status, only: STATUS_OK, STATUS_BAD_NTENS, STATUS_BAD_OPTION, MESSAGE_LEN
   use interphase_layout, only: NPROPS_SIMPLIFIED, NPROPS_MICROMECHANICAL, NPROPS_FRACTURE_EXTRA, &
      OPT_LAYER_THICKNESS, OPT_LAYER_NORMAL, MODEL_MICROMECHANICAL, DAMAGE_FRACTURE
   implicit none
   private
   public :: layer_map

   !> Where the separation lives in a host's component arrays.
   type, public :: layer_map_type
      !> number of separation components: 2 (s_N, s_T) or 3 (s_N, s_T1, s_T2)
      integer :: nsep
      !> component index (1 .. NTENS) of s_N, s_T1 and s_T2 in STRAN, STRESS and DDSDDE
      integer :: component(3)
      !> separation per unit strain (mm): 1 for a cohesive element with constitutive thickness
      !> 1, else the layer thickness t
      real(dp) :: thickness
      !> the components are the separations themselves (component = 1, 2, 3 and thickness 1)
      logical :: identity
   end type layer_map_type

contains

   !> The map for a host's NDI, NSHR, NTENS and a material's layer options; a host layout that
   !> does not fit the options is STATUS_BAD_NTENS or STATUS_BAD_OPTION with a message that says
   !> what to set.
   pure subroutine layer_map(params, ndi, nshr, ntens, map, status, message)
      type(law_params_type), intent(in) :: params
      integer, intent(in) :: ndi, nshr, ntens        !! as the host passes them
      type(layer_map_type), intent(out) :: map
      integer, intent(out) :: status
      character(len=MESSAGE_LEN), intent(out) :: message
      integer :: n

      status = STATUS_OK
      map%nsep = 0
      map%component = 0
      map%thickness = 1.0_dp
      map%identity = .false.
      n = params%layer_normal
      if (ntens /= ndi + nshr) then
         status = STATUS_BAD_NTENS
         write (message, '(a,i0,a,i0,a,i0,a)') 'NTENS = ', ntens, ' but NDI = ', ndi, ', NSHR = ', nshr, &
            ': NTENS must be NDI + NSHR'
         return
      end if

      if (ndi == 1 .and. (nshr == 1 .or. nshr == 2)) then
         ! a cohesive element: normal first
         if (n /= 0) then
            status = STATUS_BAD_OPTION
            write (message, '(a,i0,a,i0,a)') 'PROPS(', options_base(params) + OPT_LAYER_NORMAL, &
               ') layer normal axis = ', n, &
               ' but the element is a cohesive one (NDI = 1, normal first): set it to 0'
            return
         end if
         map%nsep = ntens
         map%component = [1, 2, 3]
         if (params%layer_thickness > 0.0_dp) then
            map%thickness = params%layer_thickness
         else
            map%identity = .true.
         end if
         return
      end if

      if (.not. ((ndi == 3 .and. (nshr == 1 .or. nshr == 3)) .or. (ndi == 2 .and. nshr == 1))) then
         status = STATUS_BAD_NTENS
         write (message, '(a,i0,a,i0,a,i0,a)') 'NTENS = ', ntens, ', NDI = ', ndi, ', NSHR = ', nshr, &
            ': interphase needs a cohesive element (NDI = 1, NSHR = 1 or 2) or a continuum one '// &
            '(NDI = 3, NSHR = 1 or 3; NDI = 2, NSHR = 1) for its thin-layer mode'
         return
      end if
      if (.not. (params%layer_thickness > 0.0_dp)) then
         status = STATUS_BAD_OPTION
         write (message, '(a,i0,a,i0,a,i0,a,i0,a)') 'a continuum element (NDI = ', ndi, ', NSHR = ', nshr, &
            ') needs the thin-layer mode: set the layer thickness t > 0 (mm) in PROPS(', &
            options_base(params) + OPT_LAYER_THICKNESS, ') and its normal axis in PROPS(', &
            options_base(params) + OPT_LAYER_NORMAL, ')'
         return
      end if
      map%thickness = params%layer_thickness
      if (nshr == 1) then
         ! 2-D (plane strain, axisymmetric: 11, 22, 33, 12; plane stress: 11, 22, 12): the
         ! layer's normal lies in the plane, the one shear is 12
         if (n /= 1 .and. n /= 2) then
            status = STATUS_BAD_OPTION
            write (message, '(a,i0,a,i0,a)') 'PROPS(', options_base(params) + OPT_LAYER_NORMAL, &
               ') layer normal axis = ', n, &
               ' but a 2-D continuum element (NSHR = 1) needs the in-plane axis 1 or 2'
            return
         end if
         map%nsep = 2
         map%component = [n, ndi + 1, 0]
      else
         ! 3-D: 11, 22, 33, 12, 13, 23; the shears 12, 13, 23 are ndi + 1, + 2, + 3
         select case (n)
         case (1)
            map%component = [1, ndi + 1, ndi + 2]     ! gamma_12, gamma_13
         case (2)
            map%component = [2, ndi + 1, ndi + 3]     ! gamma_12 (along 1), gamma_23 (along 3)
         case (3)
            map%component = [3, ndi + 2, ndi + 3]     ! gamma_13, gamma_23
         case default
            status = STATUS_BAD_OPTION
            write (message, '(a,i0,a,i0,a)') 'PROPS(', options_base(params) + OPT_LAYER_NORMAL, &
               ') layer normal axis = ', n, &
               ' but a 3-D continuum element needs the axis 1, 2 or 3 of the layer''s normal'
            return
         end select
         map%nsep = 3
      end if
   end subroutine layer_map

   !> The PROPS index before the option constants (for the messages; found only when one is
   !> written).
   pure integer function options_base(params) result(base)
      type(law_params_type), intent(in) :: params
      base = merge(NPROPS_MICROMECHANICAL, NPROPS_SIMPLIFIED, params%model == MODEL_MICROMECHANICAL)
      if (params%damage_law == DAMAGE_FRACTURE) base = base + NPROPS_FRACTURE_EXTRA
   end function options_base

end module interphase_layer
