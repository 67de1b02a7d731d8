/* The load-time hook of libINTERPHASE.so for CalculiX (examples/calculix/build-calculix.sh):
 * ccx opens the library with dlopen when it reads a material named @ABAQUS_INTERPHASE_UMAT...,
 * before the analysis starts; the dynamic loader runs this constructor then (after those of the
 * libraries it depends on, libgfortran among them), and it loads the custom RVE table and the
 * R-curve named in the environment (calculix_start.f90), as UEXTERNALDB does in Abaqus. */
void interphase_calculix_start(void);

__attribute__((constructor)) static void interphase_calculix_load(void)
{
    interphase_calculix_start();
}
