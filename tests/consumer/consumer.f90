!> Links against the installed package and makes one UMAT call through the public interface.
program consumer
   use interphase_kinds, only: dp
   use interphase_layout, only: NPROPS_SIMPLIFIED, NSTATV_REQUIRED, SV_DAMAGE
   use interphase_abaqus_interfaces, only: umat
   implicit none
   real(dp) :: stress(2), statev(NSTATV_REQUIRED), ddsdde(2, 2), sse, spd, scd, rpl, pnewdt
   real(dp) :: ddsddt(2), drplde(2), drpldt, props(NPROPS_SIMPLIFIED), d3(3, 3), z(1), c(3)
   character(len=80) :: cmname = 'CONSUMER'

   props = [1.0_dp, 1.0_dp, 0.75_dp, 0.00044_dp, 0.04_dp, 0.00072_dp, 0.06_dp, 482.7_dp, 198.8_dp]
   stress = 0.0_dp; statev = 0.0_dp; ddsdde = 0.0_dp; sse = 0.0_dp; spd = 0.0_dp
   scd = 0.0_dp; rpl = 0.0_dp; pnewdt = 1.0_dp; ddsddt = 0.0_dp; drplde = 0.0_dp
   drpldt = 0.0_dp; d3 = 0.0_dp; z = 0.0_dp; c = 0.0_dp
   call umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, [0.0_dp, 0.0_dp], &
      [0.01_dp, 0.0_dp], [0.0_dp, 0.0_dp], 1.0_dp, 0.0_dp, 0.0_dp, z, z, cmname, 1, 1, 2, &
      NSTATV_REQUIRED, props, NPROPS_SIMPLIFIED, c, d3, pnewdt, 1.0_dp, d3, d3, 1, 1, 1, 1, [1, 1, 0, 0], 1)
   if (pnewdt < 1.0_dp .or. .not. (statev(SV_DAMAGE) > 0.0_dp)) then
      write (*, '(a)') 'consumer: unexpected UMAT result'
      error stop 1
   end if
   write (*, '(a,2es14.6,a,f8.5)') 'consumer: traction ', stress, '  D = ', statev(SV_DAMAGE)
end program consumer
