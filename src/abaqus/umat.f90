!> Abaqus/Standard UMAT, for two kinds of element (docs/abaqus.md):
!> - cohesive elements (RESPONSE=TRACTION SEPARATION, constitutive thickness 1): STRAN and DSTRAN
!>   are separations (mm), normal first, then the shear(s); STRESS are tractions (MPa); DDSDDE =
!>   d(traction)/d(separation) (MPa/mm);
!> - thin continuum joint layers (the layer mode: option constants layer thickness t and normal
!>   axis; CPE4, C3D8, or cohesive elements with a continuum response): STRAN and DSTRAN are the
!>   layer's strains, s_N = t eps_nn, s_T = t gamma (interphase_layer); STRESS holds the tractions
!>   on the layer's plane and zero in-plane stress; DDSDDE = t dT/ds there, zero elsewhere.
!> DDSDDE is unsymmetric (use *USER MATERIAL, UNSYMM), unless the stiffness option asks for a
!> symmetric one (hosts that assemble only a symmetric stiffness, such as CalculiX). PROPS and
!> STATEV are documented in docs/abaqus.md.
!>
!> This adapter only packs arguments and calls the pure kernel; its most common calls (the simplified
!> or the micromechanical model with either damage law and no option constants, 2-D or 3-D
!> cohesive element, every input in range) take a path of their own, the same update compiled for
!> that material and element alone (interphase_umat_simplified, interphase_umat_micromechanical
!> and their fracture-law twins interphase_umat_simplified_fracture,
!> interphase_umat_micromechanical_fracture for the 2-D element, the same names with _3d for the
!> 3-D one: the same numbers, bit for bit). On a failed update it asks for a
!> cut-back through PNEWDT (0.25 unless the host already holds a smaller positive request: Abaqus
!> passes PNEWDT large, CalculiX -1), reports through `interphase_host_message` and returns before
!> touching STRESS, STATEV, DDSDDE, SSE or SPD (with the CalculiX host option DDSDDE is set to
!> zero then: CalculiX passes it uninitialised and stores it even so). Setup errors (sizes, PROPS, data not loaded, a
!> tabulated R-curve that does not cover D0 or the damage reached) and host inputs out of range (a
!> NaN, an Inf or a magnitude beyond HOST_VALUE_MAX = 1e150 in the incoming STRESS, SSE or SPD) are
!> reported as fatal, other failures as warnings (the increment is cut back); with
!> INTERPHASE_REPLAY_DIR set, a failed call's inputs are written there first
!> (interphase_replay_file). Thread-safe: no SAVE, COMMON or module data is written.
!> SSE returns the stored energy and SPD accumulates the dissipated energy, per unit area of a
!> cohesive element (N/mm) or per unit volume of a layer (N/mm^2 = MPa):
!> SPD += 1/2 (sigma_n + sigma).deps - (psi - psi_n), with psi_n the SSE passed in. With the host
!> option CalculiX (which neither initialises nor keeps them) SSE and SPD are neither read nor
!> written.
subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, &
      stran, dstran, time, dtime, temp, dtemp, predef, dpred, cmname, ndi, nshr, ntens, &
      nstatv, props, nprops, coords, drot, pnewdt, celent, dfgrd0, dfgrd1, noel, npt, &
      layer, kspt, jstep, kinc)
   use, intrinsic :: iso_fortran_env, only: int64
   use interphase_kinds, only: dp
   use interphase_finite, only: is_finite, HIGH_HALF, LOW_HALF, LOW_HALF_MASK, MAGNITUDE_MASK
   use interphase_real_text, only: real_text, es_fields
   use interphase_status, only: STATUS_OK, STATUS_RCURVE_OUT_OF_RANGE, MESSAGE_LEN, SEVERITY_WARNING, &
      SEVERITY_FATAL, STATUS_BAD_HOST_INPUT, STATUS_NONFINITE_SEPARATION, STATUS_SEPARATION_OUT_OF_RANGE, &
      STATUS_BAD_TIME_INCREMENT, STATUS_BAD_NTENS, STATUS_BAD_OPTION, STATUS_TABLE_NOT_LOADED, STATUS_RCURVE_NOT_LOADED, &
      STATUS_BAD_STATE, STATUS_BAD_NSTATV, separation_text
   use interphase_params, only: law_params_type, HOST_VALUE_MAX, HOST_INCREMENT_MAX, SLIP_MAX, check_constants, &
      decode_options, DEFAULT_PARAMS, WINDOW_MIN_BITS, WINDOW_MAX_BITS, TWO_BITS, THREE_BITS, &
      D0_MIN_BITS
   use interphase_layer, only: layer_map_type
   use interphase_layout, only: HOST_CALCULIX, NPROPS_SIMPLIFIED, NPROPS_MICROMECHANICAL, NPROPS_FRACTURE_EXTRA, &
      OPT_LAYER_THICKNESS, OPT_LAYER_NORMAL, MODEL_MICROMECHANICAL, DAMAGE_FRACTURE, PROP_TABLE, TABLE_CUSTOM_CODE, &
      PROP_MODEL, PROP_DAMAGE_LAW, PROP_MU, PROP_S0_N, PROP_SF_N, PROP_S0_T, PROP_SF_T, PROP_K_N, PROP_K_T, &
      NPROPS_OPTIONS, LFM_D0, LFM_RCURVE, LFM_GC_I, LFM_GC_II, OPT_GROWTH_SLIP, OPT_CONTACT_BAND, OPT_VISCOSITY, &
      OPT_STIFFNESS, OPT_HOST, OPTION_DEFAULTS, MODEL_SIMPLIFIED, DAMAGE_DISPLACEMENT, TABLE_DEFAULT_CODE, &
      RCURVE_TABULATED, SV_DAMAGE, SV_SLIP_1, SV_SLIP_2, SV_REGIME, SV_DAMAGE_INVISCID, NSTATV_REQUIRED, &
      NSTATV_VISCOUS, REGIME_INTACT, REGIME_SLIP, STIFFNESS_FIXED_DAMAGE
   use interphase_state, only: interface_state_type, ONE_BITS, SLIP_MAX_BITS, SIGN_BIT, REGIME_BITS
   use interphase_kernel, only: update_point
   use interphase_umat_simplified, only: simplified_cohesive_path => cohesive_path, NTENS_2D => PATH_NTENS
   use interphase_umat_micromechanical, only: micromechanical_cohesive_path => cohesive_path
   use interphase_umat_simplified_fracture, only: simplified_fracture_path => cohesive_path
   use interphase_umat_micromechanical_fracture, only: micromechanical_fracture_path => cohesive_path
   use interphase_umat_simplified_3d, only: simplified_cohesive_path_3d => cohesive_path, NTENS_3D => PATH_NTENS
   use interphase_umat_micromechanical_3d, only: micromechanical_cohesive_path_3d => cohesive_path
   use interphase_umat_simplified_fracture_3d, only: simplified_fracture_path_3d => cohesive_path
   use interphase_umat_micromechanical_fracture_3d, only: micromechanical_fracture_path_3d => cohesive_path
   use interphase_rcurve, only: rcurve_coverage, rcurve_loaded, rcurve_covers, rcurve_overrun
   use interphase_micro_coefficients, only: custom_table_loaded
   use interphase_umat_failure, only: umat_fail
   implicit none
   integer, intent(in) :: ndi, nshr, ntens, nstatv, nprops, noel, npt, layer, kspt, kinc
   integer, intent(in) :: jstep(4)
   real(dp), intent(inout) :: stress(ntens), statev(nstatv), ddsdde(ntens, ntens)
   real(dp), intent(inout) :: sse, spd, scd, rpl, pnewdt
   real(dp), intent(inout) :: ddsddt(ntens), drplde(ntens), drpldt
   real(dp), intent(in) :: stran(ntens), dstran(ntens), time(2), dtime, temp, dtemp
   real(dp), intent(in) :: predef(*), dpred(*), props(nprops), coords(3), drot(3, 3)
   real(dp), intent(in) :: celent, dfgrd0(3, 3), dfgrd1(3, 3)
   character(len=80), intent(in) :: cmname

   real(dp) :: s(3), traction(3), tangent(3, 3), psi, sigma(6), work, s_old(3)
   integer :: status, severity, nsep, i, j
   logical :: host_energies, within, taken
   !> the host is CalculiX (known once PROPS are decoded): its DDSDDE is uninitialised, and it
   !> symmetrises and stores it even from a call that asks for a cut-back
   logical :: calculix
   character(len=MESSAGE_LEN) :: message
   !> DSTRAN's or STRESS's fields in a message: up to NTENS = 6 of es_fields' width 12
   character(len=6*12) :: stress_text

   ! the simplified and the micromechanical model with either damage law and no option constants
   ! on a 2-D or a 3-D cohesive element, every input in range (each path's cohesive_path
   ! decides): a path of its own, the same update specialised to that material and element
   ! (interphase_umat_simplified, interphase_umat_micromechanical, interphase_umat_simplified_fracture,
   ! interphase_umat_micromechanical_fracture, and for NTENS = 3 the same names with _3d); every
   ! other call, every call the general path would refuse and every call whose update fails there
   ! takes the general path. NPROPS and NTENS are tested here too, so that other calls do not pay
   ! a call: NTENS = 2 or 3, then NPROPS <= 9 (the displacement-driven law without options: 9 to
   ! the simplified model's path, anything below to the micromechanical model's, whose decision
   ! takes only NPROPS = 8; fewer are refused by the general path), else 13 and 12 (the fracture
   ! law without options, the simplified and the micromechanical model; also the
   ! displacement-driven law with option constants, 12 or 13 PROPS in all, which those paths'
   ! decisions leave to the general path, after the one-pass PROPS test they make). The two
   ! elements' dispatches are the same but for the paths they call: one dispatch for both, by a
   ! path index and one select, cost 2-6 instructions a call more (docs/performance.md).
   if (ntens == NTENS_2D) then
      if (nprops <= NPROPS_SIMPLIFIED) then
         if (nprops == NPROPS_SIMPLIFIED) then
            call simplified_cohesive_path(nprops, props, ndi, nshr, ntens, nstatv, statev, stran, dstran, stress, &
               ddsdde, sse, spd, taken)
         else
            call micromechanical_cohesive_path(nprops, props, ndi, nshr, ntens, nstatv, statev, stran, dstran, &
               stress, ddsdde, sse, spd, taken)
         end if
         if (taken) return
      else if (nprops == NPROPS_SIMPLIFIED + NPROPS_FRACTURE_EXTRA) then
         call simplified_fracture_path(nprops, props, ndi, nshr, ntens, nstatv, statev, stran, dstran, stress, &
            ddsdde, sse, spd, taken)
         if (taken) return
      else if (nprops == NPROPS_MICROMECHANICAL + NPROPS_FRACTURE_EXTRA) then
         call micromechanical_fracture_path(nprops, props, ndi, nshr, ntens, nstatv, statev, stran, dstran, &
            stress, ddsdde, sse, spd, taken)
         if (taken) return
      end if
   else if (ntens == NTENS_3D) then
      if (nprops <= NPROPS_SIMPLIFIED) then
         if (nprops == NPROPS_SIMPLIFIED) then
            call simplified_cohesive_path_3d(nprops, props, ndi, nshr, ntens, nstatv, statev, stran, dstran, stress, &
               ddsdde, sse, spd, taken)
         else
            call micromechanical_cohesive_path_3d(nprops, props, ndi, nshr, ntens, nstatv, statev, stran, dstran, &
               stress, ddsdde, sse, spd, taken)
         end if
         if (taken) return
      else if (nprops == NPROPS_SIMPLIFIED + NPROPS_FRACTURE_EXTRA) then
         call simplified_fracture_path_3d(nprops, props, ndi, nshr, ntens, nstatv, statev, stran, dstran, stress, &
            ddsdde, sse, spd, taken)
         if (taken) return
      else if (nprops == NPROPS_MICROMECHANICAL + NPROPS_FRACTURE_EXTRA) then
         call micromechanical_fracture_path_3d(nprops, props, ndi, nshr, ntens, nstatv, statev, stran, dstran, &
            stress, ddsdde, sse, spd, taken)
         if (taken) return
      end if
   end if

   calculix = .false.
   ! every failure leaves this block with status, severity and message set (reported below,
   ! out of line, before STRESS, STATEV, DDSDDE, SSE or SPD are touched)
   update: block
      ! (declared here, where their default initialisation runs: not on the paths above)
      type(law_params_type) :: params
      type(layer_map_type) :: map
      type(interface_state_type) :: old, new
      severity = SEVERITY_FATAL
      call decode_props(nprops, props, params, status, message)
      if (status /= STATUS_OK) exit update
      ! which components carry the separation: a cohesive element's, or a thin layer's
      call layer_map(params, ndi, nshr, ntens, map, status, message)
      if (status /= STATUS_OK) exit update
      nsep = map%nsep
      host_energies = params%host /= HOST_CALCULIX
      calculix = .not. host_energies
      ! a custom table or R-curve that was not loaded at start-up: no smaller increment can help
      call check_run_time_data(params, status, message)
      if (status /= STATUS_OK) exit update
      call unpack_statev(nstatv, statev, nsep, params%viscosity > 0.0_dp, old, status, message)
      if (status /= STATUS_OK) exit update

      ! the host's values, before any arithmetic on them (so that none can raise an exception):
      ! STRAN and DSTRAN as the separation is checked (within HOST_INCREMENT_MAX; a smaller
      ! increment may help), STRESS, SSE and SPD within HOST_VALUE_MAX (the values the UMAT
      ! returned last: fatal otherwise). STRAN, DSTRAN and STRESS in one pass; which of them
      ! failed is looked at only on failure.
      ! (NTENS >= 2 once the layer map is set: the first two components written out)
      within = is_within(stran(1), HOST_INCREMENT_MAX) .and. is_within(stran(2), HOST_INCREMENT_MAX) .and. &
         is_within(dstran(1), HOST_INCREMENT_MAX) .and. is_within(dstran(2), HOST_INCREMENT_MAX) .and. &
         is_within(stress(1), HOST_VALUE_MAX) .and. is_within(stress(2), HOST_VALUE_MAX)
      do i = 3, ntens
         within = within .and. is_within(stran(i), HOST_INCREMENT_MAX) .and. is_within(dstran(i), HOST_INCREMENT_MAX) &
            .and. is_within(stress(i), HOST_VALUE_MAX)
      end do
      if (.not. within) then
         if (.not. (all_within(ntens, stran, HOST_INCREMENT_MAX) .and. all_within(ntens, dstran, HOST_INCREMENT_MAX))) then
            ! (es_fields: an infinity reads Infinity with every compiler; widths with room for a sign,
            ! a three-digit exponent and a blank before each field)
            message = 'STRAN '//es_fields(stran, 13, 4)
            stress_text = es_fields(dstran, 12, 3)
            message = trim(message)//', DSTRAN'//trim(stress_text)
            status = merge(STATUS_SEPARATION_OUT_OF_RANGE, STATUS_NONFINITE_SEPARATION, &
               all(is_finite(stran)) .and. all(is_finite(dstran)))
            severity = SEVERITY_WARNING
            exit update
         end if
         ! STRAN and DSTRAN in range: STRESS is not
         stress_text = es_fields(stress, 12, 3)
         write (message, '(a,a,a,es8.1e3,a)') 'incoming STRESS (MPa)', trim(stress_text), &
            ': the host must pass finite values within ', HOST_VALUE_MAX, ' (those the UMAT returned last)'
         status = STATUS_BAD_HOST_INPUT
         exit update
      end if
      if (host_energies) then
         if (.not. (is_within(sse, HOST_VALUE_MAX) .and. is_within(spd, HOST_VALUE_MAX))) then
            write (message, '(a,a,a,a,a,es8.1e3,a)') 'incoming SSE ', es_fields([sse], 12, 3), ', SPD ', &
               es_fields([spd], 12, 3), ': the host must pass finite values within ', HOST_VALUE_MAX, &
               ' (those the UMAT returned last; a host that does not keep them, such as CalculiX, needs the '// &
               'host option 1)'
            status = STATUS_BAD_HOST_INPUT
            exit update
         end if
      else if (params%stiffness /= STIFFNESS_FIXED_DAMAGE) then
         ! (the CalculiX host: only its branch pays for the test)
         write (message, '(a,i0,a,i0,a)') 'PROPS(', options_base(params) + OPT_STIFFNESS, ') stiffness = ', &
            params%stiffness, ' is not allowed with the host option 1 (CalculiX): CalculiX assembles only the '// &
            'symmetric part of DDSDDE, with which Newton stalls where damage grows (docs/calculix.md): set it to 2'
         status = STATUS_BAD_OPTION
         exit update
      else if (jstep(3) /= 0) then
         ! NLGEOM (JSTEP(3) = 1): ccx then passes Green-Lagrange strains, and a thin layer's t E is
         ! not its separation once s_T is comparable with t (E_nn gains (s_T/t)**2/2)
         write (message, '(a,i0,a,i0,a)') 'PROPS(', options_base(params) + OPT_HOST, &
            ') host = 1 (CalculiX) in a step with NLGEOM (JSTEP(3) = ', jstep(3), '): ccx then passes '// &
            'Green-Lagrange strains, whose t*E_nn is not the separation once s_T nears t: run the step without '// &
            'NLGEOM (docs/calculix.md)'
         status = STATUS_BAD_OPTION
         exit update
      end if
      ! (s_old: the separation at the start of the increment, for a crack that closes within it)
      if (map%identity) then
         ! a cohesive element: the separations themselves (NTENS = 2 or 3; written out, as below)
         s(1) = stran(1) + dstran(1)
         s(2) = stran(2) + dstran(2)
         if (ntens == 3) s(3) = stran(3) + dstran(3)
         s_old(1) = stran(1)
         s_old(2) = stran(2)
         s_old(3) = 0.0_dp
         if (ntens == 3) s_old(3) = stran(3)
      else
         do i = 1, nsep
            s(i) = map%thickness*(stran(map%component(i)) + dstran(map%component(i)))
         end do
         s_old = 0.0_dp
         do i = 1, nsep
            s_old(i) = map%thickness*stran(map%component(i))
         end do
      end if
      call update_point(params, old, nsep, s, traction, tangent, new, psi, status, dtime, s_old)
      if (status == STATUS_BAD_TIME_INCREMENT) then
         write (message, '(a,es12.4e3,a)') 'DTIME = ', dtime, ' s: viscous regularisation needs a finite DTIME >= 0'
         exit update
      else if (status == STATUS_RCURVE_OUT_OF_RANGE) then
         ! the R-curve file does not reach the damage this point needs: a setup error
         message = rcurve_overrun(76, max(old%d, params%d0), s(1:nsep))
         exit update
      else if (status /= STATUS_OK) then
         message = 'update failed at separation '//separation_text(s(1:nsep))
         severity = SEVERITY_WARNING
         exit update
      end if

      ! every term bounded (|STRESS|, |SSE|, |SPD| <= HOST_VALUE_MAX, |DSTRAN| <= HOST_INCREMENT_MAX,
      ! the kernel's outputs by the admissible ranges, t >= 1e-6 mm): no overflow
      if (map%identity) then
         call cohesive_outputs(ntens, host_energies, traction, tangent, psi, dstran, stress, ddsdde, sse, spd)
      else
         ! the layer: tractions on its plane, no in-plane stress; energies per unit volume
         sigma(1:ntens) = 0.0_dp
         sigma(map%component(1:nsep)) = traction(1:nsep)
         if (host_energies) then
            work = 0.0_dp
            do i = 1, ntens
               work = work + (stress(i) + sigma(i))*dstran(i)
            end do
            spd = spd + 0.5_dp*work - (psi/map%thickness - sse)
            sse = psi/map%thickness
         end if
         stress = sigma(1:ntens)
         ddsdde = 0.0_dp
         do j = 1, nsep
            do i = 1, nsep
               ddsdde(map%component(i), map%component(j)) = map%thickness*tangent(i, j)
            end do
         end do
      end if
      call pack_statev(new, nstatv, statev, params%viscosity > 0.0_dp)
      return
   end block update

   call umat_fail(status, severity, message, calculix, pnewdt, ddsdde, cmname, noel, npt, kinc, &
      props, statev, stress, sse, spd, stran, dstran, time, dtime, ndi, nshr)

contains

   ! the range tests of the host's values, the components' map, the run-time data check, the
   ! STATEV reader and writer and the PROPS decoder's common path, here where the compiler inlines
   ! them (interphase_finite's tests, interphase_layer's map, interphase_provider's check,
   ! interphase_state's reader and interphase_params' decoder, from the same source)
   include 'interphase_binary64_bits.inc'
   include 'interphase_within.inc'
   include 'interphase_layer_map.inc'
   include 'interphase_run_time_data.inc'
   include 'interphase_statev.inc'
   include 'interphase_decode_props.inc'
   include 'interphase_props_stores.inc'
   include 'interphase_cohesive_outputs.inc'

end subroutine umat
