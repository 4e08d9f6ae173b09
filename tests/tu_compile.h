/* Emitted source compiled and loaded again with one #define line in front
 * (PF_FX_TEST_AVX2, PF_LOGTF_TEST_V3: the macros that make an array form
 * take its AVX2 loop on a CPU that would dispatch to the AVX-512 one).
 * Shared by test_fixedgen_funcs.c and test_ladder_log.c; include after
 * "compile.h". */
#ifndef PF_TU_COMPILE_H
#define PF_TU_COMPILE_H

#include <stdlib.h>
#include <string.h>

/* def: the whole line, newline included; NULL if out of memory, else as
   pf_compile_load */
static void *tu_compile_load_def(const char *def, const char *src, size_t len, char *err, size_t errlen)
{
    size_t dn = strlen(def);
    char *s = malloc(dn + len);
    if (!s)
        return NULL;
    memcpy(s, def, dn);
    memcpy(s + dn, src, len);
    void *h = pf_compile_load(s, dn + len, err, errlen);
    free(s);
    return h;
}

#endif
