# gen/: pfmathgen, its templates (embedded at build time) and emitters.
GEN_SRCS := gen/funcs.c $(sort $(wildcard gen/funcs_*.c)) gen/generate.c gen/float_model.c gen/compile.c gen/fixedgen.c gen/scene.c gen/plot.c gen/cli.c gen/output.c gen/subproc.c gen/request.c gen/ladder.c
GEN_TEMPLATES := $(sort $(wildcard gen/templates/*.in))
PROGS += $(BUILD)/pfmathgen

$(BUILD)/include/pf_templates.h: gen/embed-templates.sh $(GEN_TEMPLATES)
	@mkdir -p $(dir $@)
	bash gen/embed-templates.sh $@ $(GEN_TEMPLATES)

$(BUILD)/obj/gen/generate.o: $(BUILD)/include/pf_templates.h

GEN_OBJS := $(GEN_SRCS:%.c=$(BUILD)/obj/%.o)
$(BUILD)/libpfgen.a: $(GEN_OBJS)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/pfmathgen: $(BUILD)/obj/gen/pfmathgen.o $(BUILD)/libpfgen.a $(BUILD)/libpffit.a $(BUILD)/libpfref.a
	$(CC) $(LDFLAGS) -fopenmp -o $@ $^ $(LIBS_NUM)

TESTS += $(BUILD)/tests/test_fit $(BUILD)/tests/test_cli
$(BUILD)/tests/test_cli: $(BUILD)/pfmathgen
TESTS += $(BUILD)/tests/test_log
$(BUILD)/tests/test_log: $(BUILD)/pfmathgen
TESTS += $(BUILD)/tests/test_sollya
$(BUILD)/tests/test_sollya: $(BUILD)/pfmathgen
TESTS += $(BUILD)/tests/test_scene
$(BUILD)/tests/test_scene: $(BUILD)/pfmathgen
# Issue 11: hostile inputs, safe outputs (one test per item), and a fuzz of
# the front end and the scene parser.
TESTS += $(BUILD)/tests/test_hostile
$(BUILD)/tests/test_hostile: $(BUILD)/pfmathgen
TESTS += $(BUILD)/tests/test_gen_fuzz
$(BUILD)/tests/test_gen_fuzz: $(BUILD)/pfmathgen
# Every pfmathgen/pfsweep example in README.md runs as written.
TESTS += $(BUILD)/tests/check-readme-examples
$(BUILD)/tests/check-readme-examples: tests/check-readme-examples.sh $(BUILD)/pfmathgen $(BUILD)/pfsweep
	@mkdir -p $(dir $@)
	sed -e 's|@BIN@|$(abspath $(BUILD))|' $< > $@ && chmod +x $@
