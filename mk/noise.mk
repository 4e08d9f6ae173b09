# Band-limited gradient noise (issue 6): libpfmath/pfnoise*.c, its tests,
# the picture demo and the speed bench.
LIB_SRCS += $(sort $(wildcard libpfmath/pfnoise*.c))

NOISE_TESTS := test_noise test_noise_spectrum test_noise_fixed test_noise_fbm test_noise_fixed_fast
TESTS += $(NOISE_TESTS:%=$(BUILD)/tests/%)
PROGS += $(BUILD)/pfnoise-demo $(BUILD)/pfnoise-bench

# test_noise and the bench also link the plain port of Perlin's reference;
# they need nothing but libpfmath.  (test_noise_fixed uses the generic rule:
# it re-derives the fade's formats with fit/bitwidth.c.)  test_noise_fixed_fast
# uses the port as its 3D double reference.
$(BUILD)/tests/test_noise $(BUILD)/tests/test_noise_fixed_fast: $(BUILD)/tests/%: tests/%.c tests/noise_baseline.c tests/noise_baseline.h $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< tests/noise_baseline.c -o $@ $(LDFLAGS) $(BUILD)/libpfmath.a -lcmocka -lm

$(BUILD)/pfnoise-bench: tests/pfnoise_bench.c tests/noise_baseline.c tests/noise_baseline.h $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< tests/noise_baseline.c -o $@ $(LDFLAGS) $(BUILD)/libpfmath.a -lm

$(BUILD)/pfnoise-demo: tests/pfnoise_demo.c $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< -o $@ $(LDFLAGS) $(BUILD)/libpfmath.a -lm

# Speed table (not part of `make test`): ns per sample, median of 21 runs.
.PHONY: bench-noise noise-pictures
bench: bench-noise
bench-noise: $(BUILD)/pfnoise-bench
	$(BUILD)/pfnoise-bench

# Pictures for the README: $(BUILD)/noise/*.png
noise-pictures: $(BUILD)/pfnoise-demo
	$(BUILD)/pfnoise-demo $(BUILD)/noise
