/* Fixed-point generation: pfmathgen with a fixed<size,exp> --type or
 * --out-type hands the whole command line to pfmathgen_fixed_main. */
#ifndef PF_FIXEDGEN_H
#define PF_FIXEDGEN_H

/* Same conventions as pfmathgen: 0 ok, 2 bad usage/impossible request
 * (one line on stderr, nothing written), 1 internal failure. */
int pfmathgen_fixed_main(int argc, char **argv);

/* 1 when the command line asks for fixed point (a fixed --type/--out-type). */
int pfmathgen_wants_fixed(int argc, char **argv);

#endif
