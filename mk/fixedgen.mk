# Generated fixed-point functions (issue 5, second half): pfmathgen with
# fixed<size,exp> types (gen/fixed/fixedgen.c, gen/fixed/fixed_*.c, templates
# gen/templates/fx_*.c.in), the fixed-point sweep (ref/sweep_fixed.c,
# pfsweep --type/--out-type in tests/pfsweep_fixed.c), the per-step
# coefficient rounding (fit/round_fixed.c) and the library's default set
# libpfmath/generated/pf_fx_*.c.  See docs/fixed.md.
FIT_SRCS += fit/round_fixed.c
REF_SRCS += ref/sweep_fixed.c
$(BUILD)/obj/ref/sweep_fixed.o: ALL_CFLAGS += -fopenmp

# gen/fixed/*.c go into libpfgen.a next to gen.mk's sources ($^ there).
FIXEDGEN_SRCS := $(sort $(wildcard gen/fixed/*.c))
$(BUILD)/libpfgen.a: $(FIXEDGEN_SRCS:%.c=$(BUILD)/obj/%.o)
# pfsweep's fixed-point half parses types (fit/fixedtype.c)
$(BUILD)/pfsweep: $(BUILD)/libpffit.a

# Tests: the command line and the issue's sin example (test_fixedgen).
TESTS += $(BUILD)/tests/test_fixedgen
$(BUILD)/tests/test_fixedgen: $(BUILD)/pfmathgen $(BUILD)/pfsweep
# Every function, exact and fast, for many 16-bit and 8-bit types, swept
# exhaustively against MPFR (test_fixedgen_funcs).
TESTS += $(BUILD)/tests/test_fixedgen_funcs

# The library's default fixed-point set, the PF_FIXED rows of
# libpfmath/functions.def as NAME/FUNC/INPUT/OUTPUT, each giving
# libpfmath/generated/pf_fx_NAME.c (pf_NAME, exact) and pf_fx_NAME_fast.c
# (pf_NAME_fast), written by exactly
#   pfmathgen --func FUNC --type 'INPUT' --out-type 'OUTPUT' [--variant fast] \
#             -o libpfmath/generated/pf_fx_NAME[_fast].c
# from the repository root (`make regen-fixed`; tests/check-regen-fixed.sh
# re-runs the commands and compares).  Declarations: libpfmath/pfmath_fixed.h.
# (funcset: mk/lib.mk; recursive, as that file is read after this one)
FX_LIB = $(call funcset,fx_lib)
FX_LIB_QUOTED = $(foreach e,$(FX_LIB),'$(e)')

.PHONY: regen-fixed
regen: regen-fixed
regen-fixed: $(BUILD)/pfmathgen
	@mkdir -p libpfmath/generated
	@set -e; for e in $(FX_LIB_QUOTED); do \
	  n=$${e%%/*}; r=$${e#*/}; f=$${r%%/*}; r=$${r#*/}; in=$${r%%/*}; out=$${r#*/}; \
	  for v in exact fast; do s=""; [ $$v = fast ] && s=_fast; \
	    o=libpfmath/generated/pf_fx_$$n$$s.c; echo "  GEN $$o"; \
	    $(BUILD)/pfmathgen --func $$f --type "$$in" --out-type "$$out" $${s:+--variant fast} -o $$o 2>/dev/null; \
	  done; \
	done

# The 16-bit sqrt takes its square root from sqrtf (gen/templates/fx_sqrtf16.c.in),
# whose loop GCC vectorizes (vsqrtps) only without errno semantics; the same
# bits either way (the flag changes speed; a pragma cannot, see lib-atrig.mk)
$(BUILD)/pic/libpfmath/generated/pf_fx_sqrt_uq8_uq12.o $(BUILD)/pic/libpfmath/generated/pf_fx_sqrt_uq8_uq12_fast.o: ALL_CFLAGS += -fno-math-errno

TESTS += $(BUILD)/tests/check-regen-fixed
$(BUILD)/tests/check-regen-fixed: tests/check-regen-fixed.sh $(BUILD)/pfmathgen mk/fixedgen.mk libpfmath/functions.def mk/funcset.awk
	@mkdir -p $(dir $@)
	sed -e 's|@PFMATHGEN@|$(abspath $(BUILD)/pfmathgen)|' -e "s|@FXLIB@|$(FX_LIB_QUOTED)|" $< > $@ && chmod +x $@
# The library's set: sweeps, saturation, exact values (test_fixed_lib).
TESTS += $(BUILD)/tests/test_fixed_lib
# The 16-bit functions compiled with -O0 ... -O3 -march=native: identical
# output tables (test_fixed_hash).
TESTS += $(BUILD)/tests/test_fixed_hash

# make sweep: the default fixed-point set over every input (2^32 for the
# Q16.16 functions: minutes each); exact below its row's exact_lsb (1), fast within
# max(2^-10 relative, 4 LSB) or pfsweep exits 1.  Writes build/sweep-fixed.md.
.PHONY: sweep-fixed
sweep: sweep-fixed
sweep-fixed: $(BUILD)/pfsweep $(BUILD)/libpfmath.so
	@echo "| function | input -> output | max LSB | mean LSB | worst input (stored) | inputs |" > $(BUILD)/sweep-fixed.md
	@echo "|---|---|---|---|---|---|" >> $(BUILD)/sweep-fixed.md
	@set -e; for e in $(foreach e,$(call funcset,fx_sweep),'$(e)'); do \
	  n=$${e%%/*}; r=$${e#*/}; f=$${r%%/*}; r=$${r#*/}; in=$${r%%/*}; r=$${r#*/}; out=$${r%%/*}; lsb=$${r#*/}; \
	  for v in exact fast; do s=""; b="--max-lsb $$lsb"; [ $$v = fast ] && s=_fast && b=""; \
	    $(BUILD)/pfsweep --func $$f --type "$$in" --out-type "$$out" --variant $$v --all $$b \
	      > $(BUILD)/sweep-fixed-$$n$$s.txt; \
	    tail -1 $(BUILD)/sweep-fixed-$$n$$s.txt; \
	    awk -v fn="pf_$$n$$s" -v io="$$in -> $$out" '/^TOTAL/ { for (i=1;i<=NF;i++) { split($$i,a,"="); v[a[1]]=a[2] } \
	      printf "| %s | %s | %.4f | %.4f | %s | %s |\n", fn, io, v["max_lsb"], v["mean_lsb"], v["worst"], v["count"] }' \
	      $(BUILD)/sweep-fixed-$$n$$s.txt >> $(BUILD)/sweep-fixed.md; \
	  done; \
	done
	@cat $(BUILD)/sweep-fixed.md

# ns/element of the fixed-point set beside the float exact/fast variants
# (not a test): $(BUILD)/bench_fixed
PROGS += $(BUILD)/bench_fixed
# -O3 -fno-math-errno: the sqrtf peer's loop vectorizes (issue 14's peer)
$(BUILD)/bench_fixed: tests/bench_fixed.c $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -O3 -fno-math-errno -MMD -MP $< -o $@ $(LDFLAGS) $(BUILD)/libpfmath.a -lm

# The same table as on a CPU with AVX2 but no AVX-512 (this machine has
# both, and the arrays dispatch at run time): every generated file compiled
# again into $(BUILD)/v3/ and linked ahead of libpfmath.a (so the archive's
# members for them are never pulled in).  Each target_clones attribute
# becomes target("arch=x86-64-v3") by a macro, so the float forms are the
# v3 clone alone; the 16-bit kernels that carry their own AVX2 loop get
# PF_FX_TEST_AVX2, which makes their dispatch take it; every other file is
# built as x86-64-v3 code, which drops its AVX-512-only loop as the v3
# clone does.
BENCH_V3_SRCS := $(sort $(wildcard libpfmath/generated/*.c))
BENCH_V3_OWN := $(shell grep -l PF_FX_TEST_AVX2 $(BENCH_V3_SRCS) 2>/dev/null)
BENCH_V3_OBJS := $(BENCH_V3_SRCS:%.c=$(BUILD)/v3/%.o)
# (built by make bench only: 50 more -O3 compiles that make all need not pay)
$(BUILD)/v3/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -O3 -fno-math-errno '-Dtarget_clones(...)=target("arch=x86-64-v3")' \
	  $(if $(filter $<,$(BENCH_V3_OWN)),-DPF_FX_TEST_AVX2,-march=x86-64-v3) -MMD -MP -c $< -o $@
$(BUILD)/bench_fixed_avx2: tests/bench_fixed.c $(BENCH_V3_OBJS) $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -O3 -fno-math-errno -march=x86-64-v3 -DPF_BENCH_AVX2 -MMD -MP $< -o $@ \
	  $(BENCH_V3_OBJS) $(LDFLAGS) $(BUILD)/libpfmath.a -lm
-include $(BENCH_V3_OBJS:.o=.d)

# make bench: the fixed-point table above (issue 14's ratios in its last two
# columns) in $(BUILD)/bench-fixed.md, after the other benches (two timing
# at once on two cores would disturb each other)
.PHONY: bench-fixed
bench: bench-fixed
bench-fixed: $(BUILD)/bench_fixed $(BUILD)/bench_fixed_avx2 | bench-float bench-noise
	{ $(BUILD)/bench_fixed 40 && echo && $(BUILD)/bench_fixed_avx2 40; } | tee $(BUILD)/bench-fixed.md
