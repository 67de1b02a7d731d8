!> The UMAT's path for its most common call: the simplified model with the displacement-driven
!> law and no option constants (NPROPS = 9) on a 2-D cohesive element (NDI = 1, NSHR = 1,
!> NTENS = 2). The UMAT calls this module's `cohesive_path` first (where NPROPS = 9 and NTENS = 2);
!> it decides, in one place, whether the call is served here: only where every check of the
!> general path passes, made by the same procedures (the PROPS decoder's one-pass test, the
!> STATEV reader, the range tests of the host's values and of the separation). It then runs
!> update_point's displacement-driven update (the same statements and procedures, from the same
!> sources, in the same order: interphase_displacement_damage.inc, respond, update_outputs) and
!> writes the general path's outputs (cohesive_outputs, pack_statev), compiled here for that
!> material alone: NTENS and the option parameters are constants, the response is inlined, the
!> parameters and the state never leave this unit. The decision and the update are one source
!> with the other seven paths (interphase_umat_cohesive_path.inc, included in
!> interphase_umat_micromechanical, in the fracture law's interphase_umat_simplified_fracture
!> and interphase_umat_micromechanical_fracture, and in the four's 3-D twins too). The numbers
!> are the general path's, bit for bit (tests/test_umat_simplified_path.f90); every other call,
!> and every call the general path would refuse, is left to the general path, which decides and
!> reports. No module data; pure.
module interphase_umat_simplified
   ! (the names the shared path source needs: one list, interphase_umat_path_names)
   use interphase_umat_path_names
   implicit none
   private
   public :: cohesive_path

   !> The material the path serves: the simplified model, the displacement-driven law, no option
   !> constants.
   integer, parameter, public :: PATH_MODEL = MODEL_SIMPLIFIED, PATH_DAMAGE_LAW = DAMAGE_DISPLACEMENT, &
      PATH_NPROPS = NPROPS_SIMPLIFIED
   !> The element the path serves: 2-D cohesive (NDI = 1, NSHR = 1). (The 3-D element in the
   !> same unit, measured: the response is then called from two places and no longer inlined,
   !> which costs the 2-D path about 170 instructions a call; docs/performance.md. The 3-D
   !> element has its twin, interphase_umat_simplified_3d.)
   integer, parameter, public :: PATH_NTENS = 2
   !> The model the path's coefficient providers serve (interphase_coefficients_at.inc): the
   !> path's, a constant, so that the compiler drops the other model's branch (measured: with the
   !> micromechanical lookup beside it, GCC stopped inlining the update into this path in the
   !> one-file source, 78 instructions a call more; docs/performance.md).
   integer, parameter, public :: PROVIDER_MODEL = PATH_MODEL

contains

   ! (the decision, the update and the procedures they call: one source for the eight paths)
   include 'interphase_umat_cohesive_path.inc'

end module interphase_umat_simplified
