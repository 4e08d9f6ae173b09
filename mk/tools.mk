# pfsweep's and pfbench's option parsing and output files (issue 11, item 8):
# run by fork/exec from the test, so it needs the programs and the library.
TESTS += $(BUILD)/tests/test_tools_cli
$(BUILD)/tests/test_tools_cli: | $(BUILD)/pfsweep $(BUILD)/pfbench $(BUILD)/libpfmath.so
