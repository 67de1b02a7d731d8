!> Abaqus/Explicit VUMAT for cohesive elements (RESPONSE=TRACTION SEPARATION, constitutive
!> thickness 1), over the same pure kernel as the UMAT.
!>
!> Conventions (docs/abaqus.md, "VUMAT"):
!> - ndir = 1 and nshr = 1 (2-D) or 2 (3-D): component 1 is the normal one, then the shear(s) in
!>   the order Abaqus passes them (the law is isotropic in the interface plane).
!> - Abaqus/Explicit passes strain *increments* with *tensor* shear components, strain =
!>   separation / constitutive thickness. With the thickness THICKNESS = 1 (required):
!>   ds_N = THICKNESS * strainInc(:, 1), ds_T = 2 * THICKNESS * strainInc(:, 2:).
!>   The total separation is accumulated in STATEV(SV_SEP_N:SV_SEP_T2).
!> - stressNew = tractions (MPa), same order.
!> - Energies per unit mass (`*Density` is required, > 0): enerInternNew is the work done on the
!>   point (stored + dissipated), enerInelasNew the dissipated part, both per unit area divided
!>   by density * THICKNESS; (enerInternNew - enerInelasNew) * density is the stored energy psi
!>   of the kernel (the UMAT's SSE) and enerInelasNew * density the UMAT's SPD.
!> - Packaging call (totalTime = 0 and stepTime = 0): the elastic response
!>   stressNew = stressOld + K ds, state and energies copied unchanged. An annealing call
!>   (lanneal = 1) copies stress, state and energies unchanged.
!>
!> Failures: bad sizes, PROPS, density or incoming STATEV are fatal (the whole block is held at
!> its old values and the host hook is called with SEVERITY_FATAL; Abaqus then stops). A point
!> whose update fails (e.g. a non-finite increment) keeps its old stress, state and energies,
!> gets STATEV(SV_FAILED) = 1, and one warning per call names the number of failed points and
!> the first one; the other points of the block are updated (Abaqus/Explicit has no PNEWDT).
!> Thread-safe: no SAVE, COMMON or module data is written.
subroutine vumat(nblock, ndir, nshr, nstatev, nfieldv, nprops, lanneal, steptime, totaltime, &
      dt, cmname, coordmp, charlength, props, density, straininc, relspininc, tempold, &
      stretchold, defgradold, fieldold, stressold, stateold, enerinternold, enerinelasold, &
      tempnew, stretchnew, defgradnew, fieldnew, stressnew, statenew, enerinternnew, &
      enerinelasnew)
   use interphase_kinds, only: dp
   use interphase_finite, only: is_finite
   use interphase_layout, only: NSTATV_REQUIRED, NSTATV_VUMAT, SV_SEP_N, SV_FAILED
   use interphase_status, only: STATUS_OK, STATUS_BAD_NTENS, STATUS_BAD_NSTATV, MESSAGE_LEN, &
      SEVERITY_WARNING, SEVERITY_FATAL, status_message
   use interphase_params, only: law_params_type, from_props
   use interphase_state, only: interface_state_type, state_unpack, state_pack
   use interphase_kernel, only: interface_update
   use interphase_abaqus_interfaces, only: interphase_host_message
   implicit none
   integer, intent(in) :: nblock                    !! number of material points in this call
   integer, intent(in) :: ndir                      !! direct components: 1 (cohesive elements)
   integer, intent(in) :: nshr                      !! shear components: 1 (2-D) or 2 (3-D)
   integer, intent(in) :: nstatev                   !! state variables per point, >= NSTATV_VUMAT
   integer, intent(in) :: nfieldv                   !! field variables (unused)
   integer, intent(in) :: nprops                    !! number of PROPS (docs/abaqus.md)
   integer, intent(in) :: lanneal                   !! 1: annealing call
   real(dp), intent(in) :: steptime, totaltime, dt  !! step time, total time, time increment
   character(len=80), intent(in) :: cmname          !! material name
   real(dp), intent(in) :: coordmp(nblock, *), charlength(nblock)
   real(dp), intent(in) :: props(nprops)            !! PROPS, docs/abaqus.md
   real(dp), intent(in) :: density(nblock)          !! density (`*Density`), > 0
   real(dp), intent(in) :: straininc(nblock, ndir + nshr)  !! strain increments, tensor shears
   real(dp), intent(in) :: relspininc(nblock, nshr), tempold(nblock)
   real(dp), intent(in) :: stretchold(nblock, ndir + nshr), defgradold(nblock, ndir + nshr + nshr)
   real(dp), intent(in) :: fieldold(nblock, nfieldv)
   real(dp), intent(in) :: stressold(nblock, ndir + nshr)  !! tractions at the start (MPa)
   real(dp), intent(in) :: stateold(nblock, nstatev)       !! STATEV at the start
   real(dp), intent(in) :: enerinternold(nblock), enerinelasold(nblock)  !! per unit mass
   real(dp), intent(in) :: tempnew(nblock), stretchnew(nblock, ndir + nshr)
   real(dp), intent(in) :: defgradnew(nblock, ndir + nshr + nshr), fieldnew(nblock, nfieldv)
   real(dp), intent(out) :: stressnew(nblock, ndir + nshr)  !! tractions at the end (MPa)
   real(dp), intent(out) :: statenew(nblock, nstatev)       !! STATEV at the end
   real(dp), intent(out) :: enerinternnew(nblock)           !! work done per unit mass
   real(dp), intent(out) :: enerinelasnew(nblock)           !! dissipated energy per unit mass

   !> Constitutive thickness of the cohesive section (mm); interphase requires 1.
   real(dp), parameter :: THICKNESS = 1.0_dp
   !> Separation per tensor shear strain: engineering shear = 2 x tensor shear.
   real(dp), parameter :: SHEAR_FACTOR = 2.0_dp

   type(law_params_type) :: params
   type(interface_state_type) :: old, new
   real(dp) :: sv(NSTATV_VUMAT), s(3), ds(3), traction(3), tangent(3, 3), psi, psi_old
   real(dp) :: rho_t, dissipated
   integer :: ntens, km, status, nfailed, first_failed, first_status
   character(len=MESSAGE_LEN) :: message, first_message

   ntens = ndir + nshr

   ! ---- setup checks: fatal, the whole block is held ----------------------------------------
   if (ndir /= 1 .or. (nshr /= 1 .and. nshr /= 2)) then
      write (message, '(a,i0,a,i0,a)') 'ndir = ', ndir, ', nshr = ', nshr, &
         ': interphase needs a cohesive element with ndir = 1 and nshr = 1 (2-D) or 2 (3-D)'
      call fail_block(STATUS_BAD_NTENS)
      return
   end if
   if (nstatev < NSTATV_VUMAT) then
      write (message, '(a,i0,a,i0,a)') 'nstatev = ', nstatev, ' but the VUMAT needs at least ', &
         NSTATV_VUMAT, ' (*DEPVAR)'
      call fail_block(STATUS_BAD_NSTATV)
      return
   end if
   call from_props(props, params, status, message)
   if (status /= STATUS_OK) then
      call fail_block(status)
      return
   end if
   do km = 1, nblock
      if (.not. positive_finite(density(km))) then
         write (message, '(a,i0,a,es12.5,a)') 'density at block point ', km, ' = ', density(km), &
            ': the VUMAT needs *Density > 0 on the material (its energies are per unit mass)'
         call fail_block(-1)
         return
      end if
   end do

   ! user slots beyond interphase's are carried over
   if (nstatev > NSTATV_VUMAT) then
      statenew(:, NSTATV_VUMAT + 1:nstatev) = stateold(:, NSTATV_VUMAT + 1:nstatev)
   end if

   ! ---- packaging call (time zero) and annealing: no state change ---------------------------
   if (lanneal == 1 .or. (totaltime <= 0.0_dp .and. steptime <= 0.0_dp)) then
      do km = 1, nblock
         call hold_point(km)
      end do
      if (lanneal /= 1) then
         ! elastic response of the intact interface, for Abaqus's stable-time-increment estimate
         stressnew(:, 1) = stressold(:, 1) + params%k_n*THICKNESS*straininc(:, 1)
         stressnew(:, 2:ntens) = stressold(:, 2:ntens) + params%k_t*SHEAR_FACTOR*THICKNESS*straininc(:, 2:ntens)
      end if
      return
   end if

   ! ---- the update, point by point ----------------------------------------------------------
   nfailed = 0
   first_failed = 0
   first_status = STATUS_OK
   first_message = ''
   do km = 1, nblock
      sv = stateold(km, 1:NSTATV_VUMAT)
      call state_unpack(sv(1:NSTATV_REQUIRED), ntens, old, status, message)
      if (status /= STATUS_OK) then
         write (first_message, '(a,i0,a,a)') 'block point ', km, ': ', trim(message)
         message = first_message
         call fail_block(status)
         return
      end if
      ds(1) = THICKNESS*straininc(km, 1)
      ds(2:ntens) = SHEAR_FACTOR*THICKNESS*straininc(km, 2:ntens)
      s(1:ntens) = sv(SV_SEP_N:SV_SEP_N + ntens - 1) + ds(1:ntens)
      call interface_update(params, old, s(1:ntens), traction(1:ntens), &
         tangent(1:ntens, 1:ntens), new, psi, status)
      if (status /= STATUS_OK) then
         nfailed = nfailed + 1
         if (nfailed == 1) then
            first_failed = km
            first_status = status
            write (first_message, '(a,3es12.4)') 'separation (mm) ', s(1:ntens)
         end if
         call hold_point(km)
         statenew(km, SV_FAILED) = 1.0_dp
         cycle
      end if

      rho_t = density(km)*THICKNESS
      psi_old = (enerinternold(km) - enerinelasold(km))*rho_t
      dissipated = 0.5_dp*sum((stressold(km, 1:ntens) + traction(1:ntens))*ds(1:ntens)) - (psi - psi_old)
      enerinelasnew(km) = enerinelasold(km) + dissipated/rho_t
      enerinternnew(km) = enerinelasnew(km) + psi/rho_t
      stressnew(km, 1:ntens) = traction(1:ntens)
      call state_pack(new, sv(1:NSTATV_REQUIRED))
      sv(SV_SEP_N:SV_SEP_N + 2) = 0.0_dp
      sv(SV_SEP_N:SV_SEP_N + ntens - 1) = s(1:ntens)
      statenew(km, 1:NSTATV_VUMAT) = sv
   end do

   if (nfailed > 0) then
      block
         character(len=2*MESSAGE_LEN) :: full
         write (full, '(a,a,i0,a,i0,a,i0,a,a,a,a)') trim(cmname), ': ', nfailed, ' of ', nblock, &
            ' points failed and were held at their old stress and state (STATEV(8) = 1); first at block point ', &
            first_failed, ': ', status_message(first_status), ': ', trim(first_message)
         call interphase_host_message(SEVERITY_WARNING, trim(full))
      end block
   end if

contains

   !> Copy stress, interphase's state slots and energies of point k unchanged.
   subroutine hold_point(k)
      integer, intent(in) :: k
      stressnew(k, :) = stressold(k, :)
      statenew(k, 1:NSTATV_VUMAT) = stateold(k, 1:NSTATV_VUMAT)
      enerinternnew(k) = enerinternold(k)
      enerinelasnew(k) = enerinelasold(k)
   end subroutine hold_point

   !> Setup error: hold the whole block at its old values and report a fatal message.
   subroutine fail_block(code)
      integer, intent(in) :: code     !! a STATUS_* code, or < 0 when `message` says it all
      character(len=2*MESSAGE_LEN) :: full
      stressnew = stressold
      statenew = stateold
      enerinternnew = enerinternold
      enerinelasnew = enerinelasold
      if (code >= 0) then
         write (full, '(a,a,a,a,a)') trim(cmname), ': ', status_message(code), ': ', trim(message)
      else
         write (full, '(a,a,a)') trim(cmname), ': ', trim(message)
      end if
      call interphase_host_message(SEVERITY_FATAL, trim(full))
   end subroutine fail_block

   !> x is finite and > 0 (false for NaN without an invalid-operation exception).
   pure logical function positive_finite(x)
      real(dp), intent(in) :: x
      positive_finite = .false.
      if (is_finite(x)) positive_finite = x > 0.0_dp
   end function positive_finite

end subroutine vumat
