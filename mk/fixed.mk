# Fixed-point types: fit/fixedtype.c (parse/format pf_type), fit/bitwidth.c
# (Olano 4.3.3 two-pass bit-width analysis) and the header-only
# libpfmath/pffixed.h arithmetic.
FIT_SRCS += fit/fixedtype.c fit/bitwidth.c
TESTS += $(BUILD)/tests/test_fixedtype $(BUILD)/tests/test_bitwidth \
         $(BUILD)/tests/test_pffixed $(BUILD)/tests/test_pffixed_portable

# pffixed.h again with its portable two-limb 128-bit integers instead of
# unsigned __int128 (what 32-bit targets get).  It uses nothing from the
# libraries; depending on the ordinary build of the same test gets them
# built first (TEST_LIBS is defined after the fragments are included).
$(BUILD)/tests/test_pffixed_portable: tests/test_pffixed.c $(BUILD)/tests/test_pffixed
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -DPF_FX_NO_INT128 $(ALL_CFLAGS) -MMD -MP $< -o $@ $(LDFLAGS) $(TEST_LIBS) -lcmocka $(LIBS_NUM)
