# exp family: pf_expf, pf_exp2f and their _fast and _array forms, generated
# from the rows in gen/float/funcs_exp.c (templates gen/templates/exp*_*.c.in).
# (listed in libpfmath/functions.def, read by mk/lib.mk into LIB_GEN)

# end-to-end tests (they run pfmathgen and sweep its output against MPFR)
TESTS += $(BUILD)/tests/test_exp
$(BUILD)/tests/test_exp: $(BUILD)/pfmathgen

# ns/element of the array forms against glibc's expf/exp2f (not a test):
#   $(BUILD)/bench_exp
PROGS += $(BUILD)/bench_exp
$(BUILD)/bench_exp: tests/bench_exp.c $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< -o $@ $(LDFLAGS) $(BUILD)/libpfmath.a -lm
