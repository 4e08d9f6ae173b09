# gen/: pfmathgen, its templates (embedded at build time) and emitters, a
# folder per stage: front/ (options, request, output, compile, plot, scene),
# emit/ (the emit kit shared by the generators), float/ (the float generator,
# its function table and the --max-ulp ladder search); fixed/ and noise/ come from fixedgen.mk and
# noisegen.mk.  Every folder is on the include path.
GEN_DIRS := gen/front gen/emit gen/float gen/fixed gen/noise
CPPFLAGS += $(GEN_DIRS:%=-I%)
GEN_SRCS := $(filter-out gen/front/pfmathgen.c,$(sort $(wildcard gen/front/*.c))) \
            $(sort $(wildcard gen/emit/*.c)) $(sort $(wildcard gen/float/*.c))
GEN_TEMPLATES := $(sort $(wildcard gen/templates/*.in))
PROGS += $(BUILD)/pfmathgen

$(BUILD)/include/pf_templates.h: gen/emit/embed-templates.sh $(GEN_TEMPLATES)
	@mkdir -p $(dir $@)
	bash gen/emit/embed-templates.sh $@ $(GEN_TEMPLATES)

$(BUILD)/obj/gen/emit/emit.o: $(BUILD)/include/pf_templates.h

GEN_OBJS := $(GEN_SRCS:%.c=$(BUILD)/obj/%.o)
$(BUILD)/libpfgen.a: $(GEN_OBJS)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/pfmathgen: $(BUILD)/obj/gen/front/pfmathgen.o $(BUILD)/libpfgen.a $(BUILD)/libpffit.a $(BUILD)/libpfref.a
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
# Every link of README.md and docs/*.md points to a file and heading that exist.
TESTS += $(BUILD)/tests/check-doc-links
$(BUILD)/tests/check-doc-links: tests/check-doc-links.sh
	@mkdir -p $(dir $@)
	sed -e 's|@BIN@|$(abspath $(BUILD))|' $< > $@ && chmod +x $@
