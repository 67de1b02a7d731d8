!> The UMAT's path for the simplified model's fracture-law call: the fracture-mechanics damage
!> law and no option constants (NPROPS = 13: the constant, the equivalent or, if it is loaded
!> and covers D0, the tabulated R-curve) on a 2-D cohesive element (NDI = 1, NSHR = 1,
!> NTENS = 2). The same decision and update as the displacement-driven law's paths
!> (interphase_umat_simplified, interphase_umat_micromechanical), from the same source
!> (interphase_umat_cohesive_path.inc), in a unit of its own: update_point's fracture-law step
!> (fracture_update, interphase_fracture_update.inc, calling the general path's grow_crack out
!> of line), the response where the crack ran to b, and the outputs, compiled for this material
!> with NTENS and the option parameters constants. The numbers are the general path's, bit for
!> bit (tests/test_umat_simplified_path.f90); every other call, every call the general path
!> would refuse, and every call whose update fails (the root search, an R-curve that does not
!> reach the damage) is left to the general path, which decides and reports. No module data;
!> pure.
module interphase_umat_simplified_fracture
   ! (the names the shared path source needs: one list, interphase_umat_path_names)
   use interphase_umat_path_names
   implicit none
   private
   public :: cohesive_path

   !> The material the path serves: the simplified model, the fracture-mechanics law, no option
   !> constants.
   integer, parameter, public :: PATH_MODEL = MODEL_SIMPLIFIED, PATH_DAMAGE_LAW = DAMAGE_FRACTURE, &
      PATH_NPROPS = NPROPS_SIMPLIFIED + NPROPS_FRACTURE_EXTRA
   !> The element the path serves: 2-D cohesive (NDI = 1, NSHR = 1), as the other paths' (the 3-D
   !> element: interphase_umat_simplified_fracture_3d).
   integer, parameter, public :: PATH_NTENS = 2
   !> The model the path's coefficient providers serve (interphase_coefficients_at.inc): the
   !> path's, a constant (interphase_umat_simplified; the 3-D twin has its own).
   integer, parameter, public :: PROVIDER_MODEL = PATH_MODEL

contains

   ! (the decision, the update and the procedures they call: one source for the eight paths)
   include 'interphase_umat_cohesive_path.inc'

end module interphase_umat_simplified_fracture
