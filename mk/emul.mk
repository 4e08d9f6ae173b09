# test_fx_bw_emul: the AVX-512BW loops (<name>_array_bw) of the 16-bit
# functions, which only an x86-64-v4 CPU's dispatch runs, run on any x86-64
# through SIMDe (libsimde-dev, header-only) and compared with the scalar
# form on every input (tests/test_fx_bw_emul.c says what it checks).
# Every libpfmath/generated/*.c with an _array_bw is picked up here, no
# list: tests/emul.sed gives its v4 functions SIMDe's intrinsics, the
# exported names become pf_emu_<name> (no clash with libpfmath.a, which the
# test links for the library's scalar forms), an entry pf_emu_bw_<name>
# calling the static loop is appended, and each file is compiled alone
# (the files share static helper names) with tests/simde_fill.h.
# build/emul/emul_list.h lists them, PF_EMU(name, input, output), parsed
# from the loops' signatures (EMUL_SIG: 16-bit input and output, as the
# test sweeps 2^16 stored values; any other signature stops the build).  Compile time is most of the cost: SIMDe and
# <immintrin.h> are parsed once, into a precompiled tests/simde_fill.h
# ($(BUILD)/emul/simde_fill.h.gch, found through -I$(BUILD)/emul before
# tests/; GCC falls back to the header if it cannot use it), and -O1 -g0
# (-O2 and the debug info cost more compile time than the run saves).
# -Wno-psabi: passing 64-byte vectors without AVX-512 is only a note on
# the ABI (these objects call only each other).
EMUL_SRCS := $(sort $(shell grep -l '^static void pf_[a-z0-9_]*_array_bw' libpfmath/generated/*.c 2>/dev/null))
EMUL_OBJS := $(EMUL_SRCS:libpfmath/generated/%.c=$(BUILD)/emul/%.o)
EMUL_CFLAGS = -I$(BUILD)/emul $(CPPFLAGS) $(ALL_CFLAGS) -O1 -g0 -Wno-psabi
EMUL_SIG := ^static void pf_\([a-z0-9_]*\)_array_bw(const \(u\{0,1\}int16_t\) \*x, \(u\{0,1\}int16_t\) \*y, size_t n)$$
# Not in the sanitized tree (SAN set: make test's build/asan), where it
# would cost 26 s of compiling to run nothing (Makefile's ASAN_SAME)
ifeq ($(SAN),)
TESTS += $(BUILD)/tests/test_fx_bw_emul
endif

# the set of files, rewritten only when it changes (a removed file must
# leave the list too)
$(shell mkdir -p $(BUILD)/emul && { echo '$(EMUL_SRCS)' | cmp -s - $(BUILD)/emul/srcs.txt || echo '$(EMUL_SRCS)' > $(BUILD)/emul/srcs.txt; })

$(BUILD)/emul/emul_list.h: $(BUILD)/emul/srcs.txt $(EMUL_SRCS) mk/emul.mk
	@mkdir -p $(dir $@)
	sed -n 's/$(EMUL_SIG)/PF_EMU(\1, \2, \3)/p' $(EMUL_SRCS) > $@.tmp
	@[ $$(wc -l < $@.tmp) -eq $(words $(EMUL_SRCS)) ] || { echo "$@: an _array_bw signature that mk/emul.mk cannot read" >&2; exit 1; }
	mv $@.tmp $@

# the transformed file (kept: it is what the test ran); refused if a v4 target or a native AVX-512 name is left
.PRECIOUS: $(BUILD)/emul/%.c
$(BUILD)/emul/%.c: libpfmath/generated/%.c tests/emul.sed mk/emul.mk
	@mkdir -p $(dir $@)
	@n=$$(sed -n 's/$(EMUL_SIG)/\1/p' $<); [ -n "$$n" ] || { echo "$<: no _array_bw signature mk/emul.mk can read" >&2; exit 1; }; \
	{ sed -f tests/emul.sed -e "s/\bpf_$$n/pf_emu_$$n/g" $<; \
	  printf '\n/* test_fx_bw_emul (mk/emul.mk): the AVX-512BW loop, emulated */\n'; \
	  printf 'void pf_emu_bw_%s(const void *x, void *y, size_t n);\n' $$n; \
	  printf 'void pf_emu_bw_%s(const void *x, void *y, size_t n) { pf_emu_%s_array_bw(x, y, n); }\n' $$n $$n; } > $@.tmp; \
	if grep -nE 'target\("arch=x86-64-v4"|(^|[^A-Za-z0-9_])(_mm512_|__m512|__mmask)' $@.tmp; then \
	  echo "$<: tests/emul.sed left AVX-512 code above" >&2; exit 1; fi; \
	mv $@.tmp $@

$(BUILD)/emul/simde_fill.h.gch: tests/simde_fill.h
	@mkdir -p $(dir $@)
	$(CC) $(EMUL_CFLAGS) -x c-header $< -o $@

$(BUILD)/emul/%.o: $(BUILD)/emul/%.c $(BUILD)/emul/simde_fill.h.gch
	$(CC) $(EMUL_CFLAGS) -include simde_fill.h -c $< -o $@

# (the test includes simde_fill.h first: the precompiled header serves it too)
$(BUILD)/tests/test_fx_bw_emul: tests/test_fx_bw_emul.c $(BUILD)/emul/simde_fill.h.gch $(BUILD)/emul/emul_list.h $(EMUL_OBJS) $(BUILD)/libpfmath.a
	@mkdir -p $(dir $@)
	$(CC) $(EMUL_CFLAGS) -MMD -MP $< -o $@ $(EMUL_OBJS) $(LDFLAGS) $(BUILD)/libpfmath.a -lcmocka -lm

# test_fixedgen_funcs runs the AVX-512BW loops of the kernels it emits the
# same way (its bw_emul_mismatches): tests/emul.sed, then $CC with these
# flags (the precompiled header's; absolute paths, as it runs anywhere).
# Its sanitized copy skips this (tu_sanitized), so needs no header there.
EMUL_CFLAGS_ABS := -I$(abspath $(BUILD)/emul) -I$(abspath tests) $(filter-out -I%,$(EMUL_CFLAGS))
$(BUILD)/tests/test_fixedgen_funcs: CPPFLAGS += -DPF_EMUL_SED='"$(abspath tests/emul.sed)"' -DPF_EMUL_LIB='"$(abspath libpfmath/generated)"' -DPF_EMUL_CFLAGS='"$(EMUL_CFLAGS_ABS)"'
$(BUILD)/tests/test_fixedgen_funcs: tests/emul.sed
ifeq ($(SAN),)
$(BUILD)/tests/test_fixedgen_funcs: $(BUILD)/emul/simde_fill.h.gch
endif
