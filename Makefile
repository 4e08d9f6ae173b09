# pfmath — one Makefile for everything.  Build outputs go to $(BUILD).
# Each part of the tree contributes through mk/<part>.mk, which appends to
#   FIT_SRCS   fitting engine (build/libpffit.a: no main)
#   REF_SRCS   MPFR references and error measurement (build/libpfref.a)
#   LIB_SRCS   libpfmath sources (build/libpfmath.a, build/libpfmath.so)
#   TESTS      test programs run by `make test` (each prints cmocka's summary)
#   PROGS      other programs built by `make`
BUILD    ?= build
CC       ?= gcc
ifeq ($(origin CC),default)
CC := gcc
endif
OPT      ?= -O2 -g
SAN      ?=
CFLAGS   ?=
WFLAGS   := -std=c17 -Wall -Wextra -Werror
ALL_CFLAGS = $(WFLAGS) $(OPT) $(SAN) $(CFLAGS)
CPPFLAGS += -D_GNU_SOURCE -Ifit -Iref -Igen -Ilibpfmath -Itests -I$(BUILD)/include
LDFLAGS  += $(SAN)
LIBS_NUM := -lmpfr -lgmp -lnlopt -lm -ldl
PF_SOVERSION := 0
PREFIX   ?= /usr/local

FIT_SRCS :=
REF_SRCS :=
LIB_SRCS :=
TESTS    :=
PROGS    :=
LIB_GEN  :=

.PHONY: all test test-asan asan-build sweep bench regen clean install
all:

include $(sort $(wildcard mk/*.mk))

FIT_OBJS := $(FIT_SRCS:%.c=$(BUILD)/obj/%.o)
REF_OBJS := $(REF_SRCS:%.c=$(BUILD)/obj/%.o)
LIB_OBJS := $(LIB_SRCS:%.c=$(BUILD)/pic/%.o)

all: $(BUILD)/libpffit.a $(BUILD)/libpfref.a $(BUILD)/libpfmath.a $(BUILD)/libpfmath.so $(PROGS) $(TESTS)

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/pic/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -fPIC -MMD -MP -c $< -o $@

$(BUILD)/libpffit.a: $(FIT_OBJS)
	@mkdir -p $(dir $@)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/libpfref.a: $(REF_OBJS)
	@mkdir -p $(dir $@)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/libpfmath.a: $(LIB_OBJS)
	@mkdir -p $(dir $@)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/libpfmath.so: $(LIB_OBJS)
	@mkdir -p $(dir $@)
	$(CC) -shared -Wl,-soname,libpfmath.so.$(PF_SOVERSION) $(LDFLAGS) -o $@ $^ -lm

# Test programs: one .c each under tests/, linked with every project library.
TEST_LIBS = $(BUILD)/libpfgen.a $(BUILD)/libpffit.a $(BUILD)/libpfref.a $(BUILD)/libpfmath.a
$(BUILD)/tests/%: tests/%.c $(TEST_LIBS)
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) $(ALL_CFLAGS) -MMD -MP $< -o $@ $(LDFLAGS) -fopenmp $(TEST_LIBS) -lcmocka $(LIBS_NUM)

# `make test`: every test program, then the same unit tests once under
# AddressSanitizer + UBSan (a second build tree, build/asan), with
# LeakSanitizer on (its default), as `make test-asan`: a leak in the
# generator, the references or the library fails the run (every sanitized
# program was leak-free on 2026-12-08, `make test-asan`: 263 passed).
# ASAN_SAME: programs whose sanitized copy runs no sanitized code of its own
# beyond what other sanitized tests run on the same inputs; all its time is
# in children built without sanitizers, repeating the plain copy's work input
# for input and assertion for assertion, so only the plain copy runs:
#   check-vectorize: the same script ($(CC) -fopt-info-vec over
#     libpfmath/generated/*.c); it never looks at the build tree.
#   test_fixed_hash: compiles libpfmath/generated/pf_fx_*.c with $(CC) (no
#     sanitizer; the sanitized copy took two of the plain copy's nine flag
#     sets, -O0 and -O3 -march=native) and hashes those .so files' tables.
#     The sanitized code it ran besides (pf_fx_stats_add over each 16-bit
#     function's 2^16 inputs, pffixed.h's pf_fx_sqrt over ufixed<16,8>) runs
#     on the same inputs in the sanitized test_fixed_lib (pf_fx_sweep_range,
#     its sqrt check).
# And one whose sanitized copy is left out for its cost (not the rule above;
# mk/emul.mk does not build it there either):
#   test_fx_bw_emul: sanitizing SIMDe's inlined lane loops took 26 s CPU
#     of compiling (the plain copy's whole build: 11 s); its guard pages
#     catch a read or write past the arrays without ASan, and UBSan stops
#     in SIMDe's own int16_t vector adds (tests/test_fx_bw_emul.c).
ASAN_FLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all
ASAN_SAME := $(BUILD)/tests/check-vectorize $(BUILD)/tests/test_fixed_hash $(BUILD)/tests/test_fx_bw_emul
ASAN_TESTS = $(patsubst $(BUILD)/%,$(BUILD)/asan/%,$(filter-out $(ASAN_SAME),$(TESTS)))
test: all asan-build
	bash tests/run-tests.sh $(TESTS) $(ASAN_TESTS)

asan-build:
	$(MAKE) BUILD=$(BUILD)/asan SAN="$(ASAN_FLAGS)" OPT="-O1 -g" all

test-asan: asan-build
	bash tests/run-tests.sh $(ASAN_TESTS)

# make install PREFIX=...: headers, static and shared library (soname
# libpfmath.so.$(PF_SOVERSION)), pkg-config's pfmath.pc, and the programs
# pfmathgen and pfsweep in PREFIX/bin.  Both are self-contained (the
# templates are embedded; MPFR, GMP and nlopt are the system's shared
# libraries); pfmathgen runs $CC (default cc) on the C it emits, and an
# installed pfsweep finds PREFIX/lib/libpfmath.so.0 by itself.
PF_HEADERS = $(wildcard libpfmath/pfmath.h libpfmath/pfmath_fixed.h libpfmath/pffixed.h libpfmath/pfnoise.h)
install: $(BUILD)/libpfmath.a $(BUILD)/libpfmath.so $(BUILD)/pfmathgen $(BUILD)/pfsweep
	install -d $(DESTDIR)$(PREFIX)/include/pfmath $(DESTDIR)$(PREFIX)/lib/pkgconfig $(DESTDIR)$(PREFIX)/bin
	install -m 755 $(BUILD)/pfmathgen $(BUILD)/pfsweep $(DESTDIR)$(PREFIX)/bin/
	install -m 644 $(PF_HEADERS) $(DESTDIR)$(PREFIX)/include/pfmath/
	install -m 644 $(BUILD)/libpfmath.a $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(BUILD)/libpfmath.so $(DESTDIR)$(PREFIX)/lib/libpfmath.so.$(PF_SOVERSION)
	ln -sf libpfmath.so.$(PF_SOVERSION) $(DESTDIR)$(PREFIX)/lib/libpfmath.so
	sed -e 's|@PREFIX@|$(PREFIX)|' libpfmath/pfmath.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/pfmath.pc

clean:
	rm -rf $(BUILD)

-include $(shell find $(BUILD)/obj $(BUILD)/pic $(BUILD)/tests -name '*.d' 2>/dev/null)
