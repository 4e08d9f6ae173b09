# tests/test_clones.c: every target_clones clone of every float function
# (scalar and array, exact and fast) gives the dispatched scalar form's bits.
# It dlopens build/libpfmath.so and reads its .symtab for the clones.
TESTS += $(BUILD)/tests/test_clones
$(BUILD)/tests/test_clones: $(BUILD)/libpfmath.so
