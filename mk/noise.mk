# Band-limited gradient noise (issue 6): libpfmath/pfnoise*.c, its tests,
# the picture demo and the speed bench.
LIB_SRCS += $(sort $(wildcard libpfmath/pfnoise*.c))

# The default table is const data generated at build time (issue 11,
# item 6: no constructor): pfnoise_table.c, built as a program, prints the
# initialiser that the library's pfnoise_table.c then includes.
$(BUILD)/pfnoise-tablegen: libpfmath/pfnoise_table.c libpfmath/pfnoise.h
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -DPF_NOISE_TABLEGEN $< -o $@ $(LDFLAGS)

$(BUILD)/include/pfnoise_default.inc: $(BUILD)/pfnoise-tablegen
	@mkdir -p $(dir $@)
	$(BUILD)/pfnoise-tablegen > $@.tmp && mv $@.tmp $@

$(BUILD)/pic/libpfmath/pfnoise_table.o: $(BUILD)/include/pfnoise_default.inc

NOISE_TESTS := test_noise test_noise_spectrum test_noise_fixed test_noise_fbm test_noise_fixed_fast \
               test_noise_scalar test_noise_ctor
TESTS += $(NOISE_TESTS:%=$(BUILD)/tests/%)
PROGS += $(BUILD)/pfnoise-demo $(BUILD)/pfnoise-bench

# test_noise and the bench also link the plain port of Perlin's reference;
# they need nothing but libpfmath.  (test_noise_fixed uses the generic rule:
# it re-derives the fade's formats with fit/bitwidth.c.)  test_noise_fixed_fast
# uses the port as its 3D double reference.
$(BUILD)/tests/test_noise $(BUILD)/tests/test_noise_fixed_fast: $(BUILD)/tests/%: tests/%.c tests/noise_baseline.c tests/noise_baseline.h $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< tests/noise_baseline.c -o $@ $(LDFLAGS) $(BUILD)/libpfmath.a -lcmocka -lm

# The bench's peer, stb_perlin (Debian's libstb-dev, .ci/deps): its header
# compiled on its own with STB_PERLIN_IMPLEMENTATION and our flags, so stb
# is called across an object boundary like the library.  Without the header
# the bench still builds and prints our times without ratios.
STB_PERLIN_H ?= /usr/include/stb/stb_perlin.h
ifneq ($(wildcard $(STB_PERLIN_H)),)
NOISE_BENCH_STB := $(BUILD)/obj/stb_perlin.o
NOISE_BENCH_DEF := -DPF_HAVE_STB
$(BUILD)/obj/stb_perlin.o: $(STB_PERLIN_H)
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CFLAGS) -Wno-unused-function -DSTB_PERLIN_IMPLEMENTATION -x c -c $< -o $@
endif

# Its own constructor calls the noise before main, linked with the static
# library only (issue 11, item 6).
$(BUILD)/tests/test_noise_ctor: tests/test_noise_ctor.c $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< -o $@ $(LDFLAGS) $(BUILD)/libpfmath.a -lcmocka -lm

$(BUILD)/pfnoise-bench: tests/pfnoise_bench.c tests/noise_baseline.c tests/noise_baseline.h $(BUILD)/libpfmath.a $(NOISE_BENCH_STB)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(NOISE_BENCH_DEF) $(ALL_CFLAGS) -MMD -MP $< tests/noise_baseline.c $(NOISE_BENCH_STB) -o $@ $(LDFLAGS) $(BUILD)/libpfmath.a -lm

$(BUILD)/pfnoise-demo: tests/pfnoise_demo.c $(BUILD)/obj/gen/front/output.o $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< $(BUILD)/obj/gen/front/output.o -o $@ $(LDFLAGS) $(BUILD)/libpfmath.a -lm

# Speed table against stb_perlin (not part of `make test`): ns per sample,
# median of 15 interleaved passes of thread CPU time.
.PHONY: bench-noise noise-pictures
bench: bench-noise
bench-noise: $(BUILD)/pfnoise-bench
	$(BUILD)/pfnoise-bench

# Pictures for the README: $(BUILD)/noise/*.png
noise-pictures: $(BUILD)/pfnoise-demo
	$(BUILD)/pfnoise-demo $(BUILD)/noise
