# ref/sweep.c: error sweeps against ref/ (used by pfsweep, pfmathgen, tests).
REF_SRCS += ref/sweep.c
PROGS += $(BUILD)/pfsweep
$(BUILD)/obj/ref/sweep.o: ALL_CFLAGS += -fopenmp

$(BUILD)/pfsweep: $(BUILD)/obj/tests/pfsweep.o $(BUILD)/libpfgen.a $(BUILD)/libpfref.a
	$(CC) $(LDFLAGS) -fopenmp -o $@ $^ $(LIBS_NUM)
