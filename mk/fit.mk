# fit/: the fitting engine (a library, no main).
FIT_SRCS += fit/linalg.c fit/lsq.c fit/measure.c fit/round.c fit/minimax.c
