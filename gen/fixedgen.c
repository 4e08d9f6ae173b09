#include "fixedgen.h"

#include "fixedtype.h"

#include <stdio.h>
#include <string.h>

int pfmathgen_wants_fixed(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        const char *v = NULL;
        if ((!strcmp(argv[i], "--type") || !strcmp(argv[i], "--out-type")) && i + 1 < argc)
            v = argv[i + 1];
        else if (!strncmp(argv[i], "--type=", 7))
            v = argv[i] + 7;
        else if (!strncmp(argv[i], "--out-type=", 11))
            v = argv[i] + 11;
        if (v && strcmp(v, "float"))
            return 1;
    }
    return 0;
}

int pfmathgen_fixed_main(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    fprintf(stderr, "pfmathgen: fixed-point generation is not available in this build\n");
    return 2;
}
