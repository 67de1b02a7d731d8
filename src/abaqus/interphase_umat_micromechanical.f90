!> The UMAT's path for the micromechanical model's common call: the displacement-driven law and
!> no option constants (NPROPS = 8; the built-in table, or a custom table loaded at start-up) on
!> a 2-D cohesive element (NDI = 1, NSHR = 1, NTENS = 2). The same decision and update as the
!> simplified model's path (interphase_umat_simplified), from the same source
!> (interphase_umat_cohesive_path.inc), in a unit of its own so that the compiler inlines the
!> response here too; the decision adds the general path's run-time data check (a custom table
!> must be loaded). The table lookups (micro_values, micro_coefficients) are the general path's
!> own procedures, called out of line. The numbers are the general path's, bit for bit
!> (tests/test_umat_simplified_path.f90); every other call, and every call the general path
!> would refuse, is left to the general path, which decides and reports. No module data; pure.
module interphase_umat_micromechanical
   ! (the names the shared path source needs: one list, interphase_umat_path_names)
   use interphase_umat_path_names
   implicit none
   private
   public :: cohesive_path

   !> The material the path serves: the micromechanical model, the displacement-driven law, no
   !> option constants.
   integer, parameter, public :: PATH_MODEL = MODEL_MICROMECHANICAL, PATH_DAMAGE_LAW = DAMAGE_DISPLACEMENT, &
      PATH_NPROPS = NPROPS_MICROMECHANICAL
   !> The element the path serves: 2-D cohesive (NDI = 1, NSHR = 1), as the simplified model's (the 3-D
   !> element: interphase_umat_micromechanical_3d).
   integer, parameter, public :: PATH_NTENS = 2
   !> The model the path's coefficient providers serve (interphase_coefficients_at.inc): the
   !> path's, a constant (interphase_umat_simplified).
   integer, parameter, public :: PROVIDER_MODEL = PATH_MODEL

contains

   ! (the decision, the update and the procedures they call: one source for the eight paths)
   include 'interphase_umat_cohesive_path.inc'

end module interphase_umat_micromechanical
