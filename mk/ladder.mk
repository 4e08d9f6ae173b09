# The accuracy ladder (issue 13, item 2; gen/float/ladder.h): pfmathgen --max-ulp.
# Its confirming sweep runs on every core, and atan2's is pfsweep --all's
# pair set (tests/pfsweep_pairs.c), linked in here.
$(BUILD)/obj/gen/float/ladder.o: ALL_CFLAGS += -fopenmp
$(BUILD)/pfmathgen: $(BUILD)/obj/tests/pfsweep_pairs.o

# `make ladder`: every float function at five levels, 1, 2 and 4 ULP and the
# relative levels 2^-16 (128 ULP) and 2^-10 (8192 ULP) (gen/float/ladder.h: a
# relative level E is the ULP level E 2^23), as pf_<f>f_l<U> in
# build/libpfladder.so, for pfbench's ladder rows (`make bench` depends on
# it).  Each level is confirmed by an exhaustive sweep: 55 of them, about
# 2-3 minutes each on 2 idle cores, so the first `make ladder` takes about
# two hours (later runs only redo what is missing: the sources depend on
# pfmathgen order-only, so `rm -r build/ladder` after changing a template).
# LADDER_SAMPLE=1 confirms on a sample instead (about a minute in all; the
# files, in build/ladder-sample/, say so in their provenance).
LADDER_FUNCS  := log log2 exp exp2 sin cos tan asin acos atan atan2
LADDER_LEVELS := 1 2 4 128 8192
# A function may add levels where a peer sits between them (LADDER_EXTRA_log
# := 0.6); tests/pfbench_ladder.c lists the levels it looks for.  In file and
# symbol names the point is a 'p' (pf_logf_l0p6).
# log, log2: sleef-u10 sits at 0.58 ULP (the mid-double rows); log2: sleef-u35 at 2.5
LADDER_EXTRA_log  := 0.55 0.6
LADDER_EXTRA_log2 := 0.55 0.6 3
ladder_levels = $(LADDER_LEVELS) $(LADDER_EXTRA_$(1))
# acos: SLEEF u35 sits at 1.28 ULP, between 1 and 1.5 (the mid scheme's floor
# is about 1.1: gen/templates/acos_mid.c.in)
LADDER_EXTRA_acos := 1.25
# asin: SLEEF u35 sits at 2.4 ULP; the lite row reaches 2.1 at order 11
# (gen/templates/asin_lite.c.in), above the 2 level
LADDER_EXTRA_asin  := 2.5
# atan2: libmvec sits at 3.2 ULP and SLEEF u35 at 2.5, between the 2 and 4
# levels; at 3 the lean row (one fmaf, pi/2 and pi as one float:
# gen/templates/atan2_lean.c.in) takes order 17, about 2.1 ULP.  (atan's 3
# would take the lite row at order 15, 2.5 ULP: no peer between.)
LADDER_EXTRA_atan2 := 3
ladder_tag    = $(subst .,p,$(1))
# trig: the mid rows (float Cody-Waite, gen/float/funcs_trig.c) reach 3 ULP;
# sin, cos: sleef-u10 sits at 0.78-0.79 ULP, below the float-lane exact row's
# 0.83, so the exact-double row (0.60) takes a 0.75 level
LADDER_EXTRA_sin := 0.75 3
LADDER_EXTRA_cos := 0.75 3
LADDER_EXTRA_tan := 3
# `make bench` times a ladder confirmed on a sample (a few minutes to build;
# the bench measures every point's error itself, like the peers'); `make
# bench LADDER_SAMPLE=0` times the exhaustively confirmed one of `make ladder`.
ifneq ($(filter bench bench-float,$(MAKECMDGOALS)),)
LADDER_SAMPLE ?= 1
endif
LADDER_SAMPLE ?= 0
LADDER_TAG    := $(if $(filter 1,$(LADDER_SAMPLE)),-sample,)
LADDER_DIR    := $(BUILD)/ladder$(LADDER_TAG)
LADDER_LIB    := $(BUILD)/libpfladder$(LADDER_TAG).so
LADDER_SRCS   := $(foreach f,$(LADDER_FUNCS),$(foreach l,$(call ladder_levels,$(f)),$(LADDER_DIR)/pf_$(f)f_l$(call ladder_tag,$(l)).c))

# the report and the search's log go to FILE.log; a failure shows its last line
define ladder_rule
$(LADDER_DIR)/pf_$(1)f_l$(call ladder_tag,$(2)).c: | $(BUILD)/pfmathgen
	@mkdir -p $$(dir $$@)
	@echo "  LADDER $(1) $(2) ULP"
	@$(BUILD)/pfmathgen --func $(1) --max-ulp $(2) --name pf_$(1)f_l$(call ladder_tag,$(2)) \
	  $(if $(LADDER_TAG),--confirm sample,) -o $$@ 2> $$@.log || { tail -1 $$@.log; exit 1; }
endef
$(foreach f,$(LADDER_FUNCS),$(foreach l,$(call ladder_levels,$(f)),$(eval $(call ladder_rule,$(f),$(l)))))

# -fno-math-errno: asin/acos call sqrtf, which GCC vectorizes only without
# errno (their files' "Build flags:" line; harmless for the others)
$(LADDER_DIR)/%.o: $(LADDER_DIR)/%.c
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -O3 -fno-math-errno -fPIC -c $< -o $@

$(LADDER_LIB): $(LADDER_SRCS:.c=.o)
	$(CC) -shared $(LDFLAGS) -o $@ $^ -lm

.PHONY: ladder
ladder: $(LADDER_LIB)

# --max-ulp's options, and what it emits, against MPFR (sampled confirmation)
# and pfbench's Pareto check on made-up points
TESTS += $(BUILD)/tests/test_ladder
$(BUILD)/tests/test_ladder: tests/test_ladder.c $(BUILD)/obj/tests/pfbench_ladder_pareto.o $(TEST_LIBS) | $(BUILD)/pfmathgen
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< $(BUILD)/obj/tests/pfbench_ladder_pareto.o -o $@ $(LDFLAGS) \
	  -fopenmp $(TEST_LIBS) -lcmocka $(LIBS_NUM)

# the log and log2 rows between exact and fast against MPFR (tests/test_ladder_log.c)
TESTS += $(BUILD)/tests/test_ladder_log

# the trig mid rows at --max-ulp 3 against MPFR on the reduction's hard inputs
TESTS += $(BUILD)/tests/test_ladder_trig
$(BUILD)/tests/test_ladder_trig: tests/test_ladder_trig.c $(TEST_LIBS) | $(BUILD)/pfmathgen
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< -o $@ $(LDFLAGS) -fopenmp $(TEST_LIBS) -lcmocka $(LIBS_NUM)

# what the search chose, one row per level (from the files' provenance)
$(LADDER_DIR)/ladder.md: $(LADDER_SRCS) mk/ladder-table.awk
	@{ echo "| function | level, ULP | template | order | cost | confirmed max ULP | worst input | sweep |"; \
	   echo "|---|---|---|---|---|---|---|---|"; \
	   for f in $(LADDER_SRCS); do awk -f mk/ladder-table.awk $$f; done; } > $@
	@echo "  wrote $@"
ladder: $(LADDER_DIR)/ladder.md

# the atrig mid rows on the ladder (asin, acos, atan, atan2), against MPFR
TESTS += $(BUILD)/tests/test_ladder_atrig
$(BUILD)/tests/test_ladder_atrig: tests/test_ladder_atrig.c $(TEST_LIBS) | $(BUILD)/pfmathgen
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< -o $@ $(LDFLAGS) -fopenmp $(TEST_LIBS) -lcmocka $(LIBS_NUM)
