# Speed against error (issue 7): build/pfbench times every libpfmath function
# beside glibc, libmvec and SLEEF and measures everyone's ULP error against
# ref/; `make bench` runs it and draws one SVG per function with gnuplot.
PFBENCH_SRCS := tests/pfbench.c tests/pfbench_err.c tests/pfbench_peers.c \
                tests/pfbench_ours.c tests/pfbench_fixed.c tests/pfbench_ladder.c \
                tests/pfbench_ladder_pareto.c
PFBENCH_OBJS = $(PFBENCH_SRCS:%.c=$(BUILD)/obj/%.o)
PROGS += $(BUILD)/pfbench

# the error pass runs on every core (the timing is single-threaded)
$(BUILD)/obj/tests/pfbench_err.o: ALL_CFLAGS += -fopenmp

# output files by pfmathgen's rules, from its own object (tests/pfcli_out.h)
$(BUILD)/pfbench: $(PFBENCH_OBJS) $(BUILD)/obj/gen/front/output.o $(BUILD)/libpfref.a
	$(CC) $(LDFLAGS) -fopenmp -o $@ $^ -lsleef -lmvec $(LIBS_NUM)

# bench.md, bench.csv and bench-<func>.svg in $(BUILD).  PFBENCH_ARGS passes
# options through, e.g. make bench PFBENCH_ARGS='--func log,exp --reps 21'.
.PHONY: bench-float
bench: bench-float
# The accuracy ladder's library (mk/ladder.mk; LADDER_SAMPLE=1 for a quick one)
# gives the rows pfmath-L<U> and takes part in the Pareto checks.
bench-float: $(BUILD)/pfbench $(BUILD)/libpfmath.so ladder
	$(BUILD)/pfbench --lib $(BUILD)/libpfmath.so --ladder $(LADDER_LIB) --out $(BUILD) $(PFBENCH_ARGS)
	bash tests/bench-plot.sh $(BUILD)/bench.csv $(BUILD)

# Two benches timing at once on two cores would disturb each other: the
# noise bench (mk/noise.mk) runs after this one.
bench-noise: | bench-float

# the error column's code against the sweep machinery (tests/test_bench.c)
TESTS += $(BUILD)/tests/test_bench
PFBENCH_TESTED = $(BUILD)/obj/tests/pfbench_err.o $(BUILD)/obj/tests/pfbench_fixed.o
$(BUILD)/tests/test_bench: tests/test_bench.c $(PFBENCH_TESTED) $(BUILD)/libpfref.a $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< $(PFBENCH_TESTED) -o $@ $(LDFLAGS) -fopenmp \
	  $(BUILD)/libpfref.a $(BUILD)/libpfmath.a -lcmocka $(LIBS_NUM)

# The scalar exact forms against glibc by how predictable the inputs are
# (tests/bench_scalar.c: n = 4096, 65536 and 2^20 distinct inputs), in
# $(BUILD)/bench-scalar.md, after the other benches (one timing at a time)
PROGS += $(BUILD)/bench_scalar
# pfbench's domains, sampler and candidates: its objects but its main
BENCH_SCALAR_OBJS = $(filter-out $(BUILD)/obj/tests/pfbench.o,$(PFBENCH_OBJS))
$(BUILD)/bench_scalar: tests/bench_scalar.c $(BENCH_SCALAR_OBJS) $(BUILD)/obj/gen/front/output.o $(BUILD)/libpfref.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< -o $@ $(BENCH_SCALAR_OBJS) $(BUILD)/obj/gen/front/output.o \
	  $(LDFLAGS) -fopenmp $(BUILD)/libpfref.a -lsleef -lmvec $(LIBS_NUM)
.PHONY: bench-scalar
bench: bench-scalar
bench-scalar: $(BUILD)/bench_scalar $(BUILD)/libpfmath.so | bench-float bench-noise bench-fixed
	$(BUILD)/bench_scalar $(BUILD)/libpfmath.so | tee $(BUILD)/bench-scalar.md
