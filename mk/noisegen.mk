# Gradient noise for any fixed-point type pair (issue 6's generator half):
# pfmathgen --func noise1..noise4|noise --type T --out-type U
# (gen/noise/fixed_noise.c, put into libpfgen.a below), the exact
# MPFR reference ref/pfref_noise.c, and tests/test_noisegen.c.  See
# docs/fixed.md, "Noise for any type pair".
REF_SRCS += ref/pfref_noise.c
# gen/noise/*.c go into libpfgen.a next to gen.mk's sources ($^ there).
NOISEGEN_SRCS := $(sort $(wildcard gen/noise/*.c))
$(BUILD)/libpfgen.a: $(NOISEGEN_SRCS:%.c=$(BUILD)/obj/%.o)

# the generator dumps the lattice tables from libpfmath's pf_noise_table
# (appended to pfmathgen's link line, after the other libraries)
$(BUILD)/pfmathgen: $(BUILD)/libpfmath.a

TESTS += $(BUILD)/tests/test_noisegen
$(BUILD)/tests/test_noisegen: $(BUILD)/pfmathgen
