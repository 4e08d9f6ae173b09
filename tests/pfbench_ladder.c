/* pfbench: the accuracy ladder's rows (issue 13, item 2).
 *
 * `make ladder` (mk/ladder.mk) generates, for every float function, one
 * pfmathgen --max-ulp U per level into build/libpfladder.so, named
 * pf_<f>f_l<U>.  Here each level found becomes a row "pfmath-L<U>" for the
 * array form's AVX2 and AVX-512 clones (the widths the vector peers come
 * in; the scalar and SSE2 forms would add bench time and no Pareto check).
 * The clones are found in the library's static symbol table (.symtab:
 * NAME.arch_x86_64_v4), as for libpfmath's own rows; without it (a stripped
 * library) the row is the dispatched form. */
#include "pfbench_ladder.h"

#include "elfsyms.h"

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

/* the levels a function's ladder may hold, ULP (mk/ladder.mk: LADDER_LEVELS
   for every function, plus LADDER_EXTRA_<f>); absent ones are skipped.  In a
   symbol name the level's point is a 'p' (pf_logf_l0p6). */
static const char *const levels[] = {"0.55", "0.6", "0.75", "1", "1.25", "1.5", "2", "2.5", "3", "4", "128", "8192"};
#define NLEVELS ((int)(sizeof levels / sizeof levels[0]))

static void *lh;
static pf_elfsyms es; /* the ladder library's .symtab (elfsyms.h) */

static void *clone_of(const char *name, const char *suffix)
{
    char full[160];
    snprintf(full, sizeof full, "%s.%s", name, suffix);
    return pf_elfsyms_func(&es, full);
}

int pfb_ladder_open(const char *lib, char *err, size_t errlen)
{
    lh = dlopen(lib, RTLD_NOW | RTLD_LOCAL);
    if (!lh) {
        snprintf(err, errlen, "%s", dlerror());
        return -1;
    }
    pf_elfsyms_load(&es, lh, lib);
    return 0;
}

static void level_tag(char *tag, size_t n, const char *level)
{
    snprintf(tag, n, "%s", level);
    for (char *p = tag; *p; p++)
        if (*p == '.')
            *p = 'p';
}

static void add(pfb_cand *c, int *n, const char *level, const char *isa, int arity, void *array)
{
    pfb_cand *k = &c[(*n)++];
    memset(k, 0, sizeof *k);
    snprintf(k->name, sizeof k->name, "pfmath-L%s", level);
    snprintf(k->isa, sizeof k->isa, "%s", isa);
    k->ours = PFB_OURS_LADDER;
    if (arity == 2)
        *(void **)&k->a2 = array;
    else
        *(void **)&k->a1 = array;
}

void pfb_ladder(pf_func f, pfb_cand *c, int *n)
{
    if (!lh)
        return;
    __builtin_cpu_init();
    int arity = pfref_arity(f);
    for (int i = 0; i < NLEVELS && *n + 2 <= PFB_MAX_CANDS; i++) {
        char arr[96], tag[16];
        level_tag(tag, sizeof tag, levels[i]);
        snprintf(arr, sizeof arr, "pf_%sf_l%s_array", pfref_name(f), tag);
        void *a = dlsym(lh, arr);
        if (!a)
            continue;
        void *v3 = clone_of(arr, "arch_x86_64_v3"), *v4 = clone_of(arr, "arch_x86_64_v4");
        if (!v3 && !v4)
            add(c, n, levels[i], "dispatch", arity, a);
        if (v3 && __builtin_cpu_supports("x86-64-v3"))
            add(c, n, levels[i], "avx2", arity, v3);
        if (v4 && __builtin_cpu_supports("x86-64-v4"))
            add(c, n, levels[i], "avx512", arity, v4);
    }
}

void *pfb_ladder_scalar(pf_func f, const pfb_cand *c)
{
    if (!lh || strncmp(c->name, "pfmath-L", 8))
        return NULL;
    char sym[96], tag[16];
    level_tag(tag, sizeof tag, c->name + 8);
    snprintf(sym, sizeof sym, "pf_%sf_l%s", pfref_name(f), tag);
    return dlsym(lh, sym);
}
