/* Emitted source compiled and loaded again with one #define line in front
 * (PF_FX_TEST_AVX2, PF_LOGTF_TEST_V3: the macros that make an array form
 * take its AVX2 loop on a CPU that would dispatch to the AVX-512 one).
 * Shared by test_fixedgen_funcs.c and test_ladder_log.c; include after
 * "compile.h".  tu_macro_picks_same: when that second build is needless. */
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

/* 1 in the sanitized build of a test (make test's build/asan tree) */
static int tu_sanitized(void)
{
#if defined(__SANITIZE_ADDRESS__)
    return 1;
#else
    return 0;
#endif
}

/* 1 when building src again with macro defined would run the array loop
 * its plain build already runs on this CPU, so that a second build tests
 * nothing new: this CPU lacks x86-64-v4, and macro occurs once in src, in
 * the dispatch whose lines after the macro's are exactly `after` (the v3
 * test ahead of the v4 one, then v4, then v3 again: without x86-64-v4 both
 * builds take the v3 branch).  0 whenever the text differs in any way (an
 * emitter that changes its dispatch gets the second build again). */
static int tu_macro_picks_same(const char *src, const char *macro, const char *after)
{
    const char *m = strstr(src, macro);
    if (__builtin_cpu_supports("x86-64-v4") || !m || strstr(m + 1, macro))
        return 0;
    const char *nl = strchr(m, '\n');
    return nl && strncmp(nl + 1, after, strlen(after)) == 0;
}

#endif
