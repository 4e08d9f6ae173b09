# ref/: correctly rounded MPFR references and ULP/LSB error measurement.
REF_SRCS += ref/pfref_env.c ref/pfref_func.c ref/pfref_f.c ref/pfref_glibc.c \
            ref/pfref_ulp.c ref/pfref_dd.c
TESTS += $(BUILD)/tests/test_ref
