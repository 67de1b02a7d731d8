!> The 3-D twin of interphase_umat_simplified_fracture
!> (src/abaqus/interphase_umat_simplified_fracture.f90 describes the material, the decision and the
!> update): the same source, interphase_umat_cohesive_path.inc, compiled here for the 3-D cohesive
!> element (NDI = 1, NSHR = 2, NTENS = 3), in a unit of its own (with both elements in one unit the
!> response is called from two places and not inlined).
module interphase_umat_simplified_fracture_3d
   ! (the names the shared path source needs: one list, interphase_umat_path_names)
   use interphase_umat_path_names
   ! (the material: the 2-D twin's, so that the two serve the same one)
   use interphase_umat_simplified_fracture, only: PATH_MODEL, PATH_DAMAGE_LAW, PATH_NPROPS
   implicit none
   private
   public :: cohesive_path

   !> The element the path serves: 3-D cohesive (NDI = 1, NSHR = 2).
   integer, parameter, public :: PATH_NTENS = 3
   !> The model the path's coefficient providers serve (interphase_coefficients_at.inc): every
   !> model (the one PROPS select, which the decision has made this path's). Folded to the
   !> simplified model, as in the 2-D twin, GCC 12's -O3 uninitialised-use analysis took the
   !> response for unset where the update writes the outputs from it (-Werror builds failed).
   integer, parameter :: PROVIDER_MODEL = 0

contains

   ! (the decision, the update and the procedures they call: one source for the eight paths)
   include 'interphase_umat_cohesive_path.inc'

end module interphase_umat_simplified_fracture_3d
