# ref/sweep.c: error sweeps against ref/ (used by pfsweep, pfmathgen, tests).
REF_SRCS += ref/sweep.c
PROGS += $(BUILD)/pfsweep
$(BUILD)/obj/ref/sweep.o: ALL_CFLAGS += -fopenmp

$(BUILD)/pfsweep: $(BUILD)/obj/tests/pfsweep.o $(BUILD)/obj/tests/pfsweep_fixed.o $(BUILD)/libpfgen.a $(BUILD)/libpfref.a
	$(CC) $(LDFLAGS) -fopenmp -o $@ $^ $(LIBS_NUM)

# make sweep: every library function over all 2^32 floats; exact variants
# must stay within their exact_ulp (1 ULP) of libpfmath/functions.def.  Writes build/sweep.md.
sweep: $(BUILD)/pfsweep $(BUILD)/libpfmath.so
	@echo "| function | max ULP | mean ULP | correctly rounded | worst input |" > $(BUILD)/sweep.md
	@echo "|---|---|---|---|---|" >> $(BUILD)/sweep.md
	@set -e; for fvb in $(call funcset,float_sweep); do \
	  f=$${fvb%%:*}; r=$${fvb#*:}; v=$${r%%:*}; u=$${r#*:}; b=""; [ -n "$$u" ] && b="--max-ulp $$u"; \
	  $(BUILD)/pfsweep --func $$f --variant $$v --all $$b > $(BUILD)/sweep-$$f-$$v.txt; \
	  tail -1 $(BUILD)/sweep-$$f-$$v.txt; \
	  awk -v fv="$$f $$v" '/^TOTAL/ { for (i=1;i<=NF;i++) { split($$i,a,"="); v[a[1]]=a[2] } \
	    printf "| %s | %.4f | %.4f | %s | %s |\n", fv, v["max_ulp"], v["mean_ulp"], v["cr"], v["worst"] }' \
	    $(BUILD)/sweep-$$f-$$v.txt >> $(BUILD)/sweep.md; \
	done
	@cat $(BUILD)/sweep.md
