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
   use interphase_params, only: law_params_type, constants_count
   use interphase_status, only: STATUS_OK, STATUS_BAD_NTENS, STATUS_BAD_OPTION, MESSAGE_LEN
   use interphase_layout, only: OPT_LAYER_THICKNESS, OPT_LAYER_NORMAL
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

   ! (the source is shared with the UMAT, which includes it where it can be inlined)
   include 'interphase_layer_map.inc'

end module interphase_layer
