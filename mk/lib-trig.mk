# trig family: sin, cos, tan (gen/float/funcs_trig.c, gen/templates/sin_pio2_ff.c.in, sin_pi_fast*.c.in,
# tan_pio2*.c.in).  Library sources libpfmath/generated/pf_{sin,cos,tan}f*.c.
# (listed in libpfmath/functions.def, read by mk/lib.mk into LIB_GEN)

TESTS += $(BUILD)/tests/test_trig
$(BUILD)/tests/test_trig: $(BUILD)/pfmathgen

# ns/element of the array forms against glibc (not part of `make test`)
PROGS += $(BUILD)/bench_trig
$(BUILD)/bench_trig: tests/bench_trig.c $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) $< -o $@ $(LDFLAGS) $(BUILD)/libpfmath.a -lm
