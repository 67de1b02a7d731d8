!> The 3-D twin of interphase_umat_micromechanical_fracture
!> (src/abaqus/interphase_umat_micromechanical_fracture.f90 describes the material, the decision and
!> the update): the same source, interphase_umat_cohesive_path.inc, compiled here for the 3-D
!> cohesive element (NDI = 1, NSHR = 2, NTENS = 3), in a unit of its own (with both elements in one
!> unit the response is called from two places and not inlined).
module interphase_umat_micromechanical_fracture_3d
   ! (the names the shared path source needs: one list, interphase_umat_path_names)
   use interphase_umat_path_names
   ! (the material: the 2-D twin's, so that the two serve the same one)
   use interphase_umat_micromechanical_fracture, only: PATH_MODEL, PATH_DAMAGE_LAW, PATH_NPROPS, PROVIDER_MODEL
   implicit none
   private
   public :: cohesive_path

   !> The element the path serves: 3-D cohesive (NDI = 1, NSHR = 2).
   integer, parameter, public :: PATH_NTENS = 3

contains

   ! (the decision, the update and the procedures they call: one source for the eight paths)
   include 'interphase_umat_cohesive_path.inc'

end module interphase_umat_micromechanical_fracture_3d
