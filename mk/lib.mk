# libpfmath/: the library, built from generated sources in libpfmath/generated/.
# `make regen` rewrites them with pfmathgen; `make test` checks they are current
# (tests/check-regen.sh), so nothing in the library is typed by hand.
LIB_SRCS += $(sort $(wildcard libpfmath/generated/*.c))
$(BUILD)/pic/libpfmath/generated/%.o: ALL_CFLAGS += -O3

# The function set is declared once, in libpfmath/functions.def; make reads
# its rows with mk/funcset.awk.  LIB_GEN: the function:variant pairs the
# library ships (each becomes libpfmath/generated/pf_<f>f[_fast].c).
FUNCSET := libpfmath/functions.def
funcset = $(shell awk -v want=$(1) -f mk/funcset.awk $(FUNCSET))
LIB_GEN += $(call funcset,lib_gen)

regen: $(BUILD)/pfmathgen
	@mkdir -p libpfmath/generated
	@set -e; for fv in $(LIB_GEN); do \
	  f=$${fv%%:*}; v=$${fv##*:}; s=""; [ $$v = fast ] && s=_fast; \
	  out=libpfmath/generated/pf_$${f}f$$s.c; echo "  GEN $$out"; \
	  $(BUILD)/pfmathgen --func $$f --variant $$v -o $$out 2>/dev/null; \
	done

TESTS += $(BUILD)/tests/check-regen
$(BUILD)/tests/check-regen: tests/check-regen.sh $(BUILD)/pfmathgen $(FUNCSET) mk/funcset.awk
	@mkdir -p $(dir $@)
	sed -e 's|@PFMATHGEN@|$(abspath $(BUILD)/pfmathgen)|' -e 's|@LIBGEN@|$(LIB_GEN)|' $< > $@ && chmod +x $@

TESTS += $(BUILD)/tests/test_special
$(BUILD)/tests/test_special: $(BUILD)/libpfmath.so

TESTS += $(BUILD)/tests/check-vectorize
$(BUILD)/tests/check-vectorize: tests/check-vectorize.sh
	@mkdir -p $(dir $@)
	cp $< $@ && chmod +x $@

TESTS += $(BUILD)/tests/check-install
$(BUILD)/tests/check-install: tests/check-install.sh
	@mkdir -p $(dir $@)
	printf '#!/usr/bin/env bash\nexec bash tests/check-install.sh "%s"\n' '$(BUILD)' > $@ && chmod +x $@

# The headers, libpfmath/generated/ and the make lists against the table
# (the lists as make derived them, for the C side to compare).
TESTS += $(BUILD)/tests/test_funcset
$(BUILD)/tests/test_funcset: $(BUILD)/libpfmath.so $(FUNCSET) mk/funcset.awk
$(BUILD)/tests/test_funcset: private CPPFLAGS += -DPF_ROOT='"$(CURDIR)"' -DPF_MK_LIB_GEN='"$(LIB_GEN)"' -DPF_MK_FX_LIB='"$(FX_LIB)"'
