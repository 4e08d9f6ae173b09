/* pfsweep for fixed-point functions (--type/--out-type): error in LSBs of the
 * output type against ref/ (MPFR). */
#include <stdio.h>

int pfsweep_fixed_main(int argc, char **argv);

int pfsweep_fixed_main(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "pfsweep: fixed-point sweeps are not available in this build\n");
    return 2;
}
