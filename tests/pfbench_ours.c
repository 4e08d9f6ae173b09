/* pfbench: the pfmath candidates, found by name in libpfmath.so.
 *
 * Nothing here knows which functions the library has: a row appears when
 * dlsym finds pf_<f>f (exact), pf_<f>f_fast, and their _array forms.
 *
 * The array forms are GCC target_clones (x86-64-v4, -v3, default) behind an
 * ifunc, so dlsym gives only the clone the loader picked for this CPU.  To
 * compare like with like (pfmath's AVX2 code against SLEEF's and libmvec's
 * AVX2 code, and the same for AVX-512) the clones are looked up in the
 * object's static symbol table (.symtab: pf_logf_array.arch_x86_64_v3 and so
 * on) and called directly, each only when the CPU has that level.  A
 * stripped library, or one built by another compiler, has no such symbols:
 * then the row is the dispatched array form, labelled "dispatch". */
#include "elfsyms.h"
#include "funcset.h"
#include "pfbench.h"

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

static void *lib_h;
static pf_elfsyms es; /* the library's .symtab (elfsyms.h) */
static int have_clones;

int pfb_ours_open(const char *lib, char *err, size_t errlen)
{
    lib_h = dlopen(lib, RTLD_NOW | RTLD_LOCAL);
    if (!lib_h) {
        snprintf(err, errlen, "%s", dlerror());
        return -1;
    }
    pf_elfsyms_load(&es, lib_h, lib);
    /* trust the table only if it places an exported function where dlsym does */
    const char *probe[] = {
#define PF_FLOAT(n, id, ar, u, lo, hi) "pf_" #n "f",
#include "functions.def"
    };
    for (size_t i = 0; i < sizeof probe / sizeof probe[0] && es.syms; i++) {
        void *p = dlsym(lib_h, probe[i]);
        /* the scalar forms are target_clones too (an IFUNC symbol): dlsym
           then gives the clone the resolver picked, so compare with those */
        const char *sfx[] = {"", ".arch_x86_64_v4", ".arch_x86_64_v3", ".default"};
        int found = 0;
        for (size_t c = 0; c < sizeof sfx / sizeof sfx[0] && p && !have_clones; c++) {
            char name[64];
            snprintf(name, sizeof name, "%s%s", probe[i], sfx[c]);
            uintptr_t v = pf_elfsyms_value(&es, name);
            found |= v != 0;
            have_clones = v && (uintptr_t)p == es.base + v;
        }
        if (found)
            break;
    }
    return 0;
}

int pfb_ours_have_clones(void) { return have_clones; }

static void *clone_addr(const char *base, const char *suffix)
{
    char name[160];
    snprintf(name, sizeof name, "%s.%s", base, suffix);
    return pf_elfsyms_func(&es, name);
}

static void add(pfb_cand *c, int *n, const char *name, const char *isa, int fast, int arity,
                void *scalar, void *array)
{
    pfb_cand *k = &c[(*n)++];
    memset(k, 0, sizeof *k);
    snprintf(k->name, sizeof k->name, "%s", name);
    snprintf(k->isa, sizeof k->isa, "%s", isa);
    k->ours = 1;
    k->fast = fast;
    /* POSIX: a dlsym result converts to a function pointer */
    if (arity == 2) {
        *(void **)&k->s2 = scalar;
        *(void **)&k->a2 = array;
    } else {
        *(void **)&k->s1 = scalar;
        *(void **)&k->a1 = array;
    }
}

void pfb_ours(pf_func f, pfb_cand *c, int *n)
{
    if (!lib_h)
        return;
    __builtin_cpu_init();
    int arity = pfref_arity(f);
    for (int fast = 0; fast <= 1; fast++) {
        char sym[96], arr[112];
        snprintf(sym, sizeof sym, "pf_%sf%s", pfref_name(f), fast ? "_fast" : "");
        snprintf(arr, sizeof arr, "%s_array", sym);
        void *s = dlsym(lib_h, sym), *a = dlsym(lib_h, arr);
        const char *name = fast ? "pfmath-fast" : "pfmath";
        if (!s)
            continue; /* not generated yet: no row */
        add(c, n, name, "scalar", fast, arity, s, NULL);
        if (!a)
            continue;
        void *v4 = have_clones ? clone_addr(arr, "arch_x86_64_v4") : NULL;
        void *v3 = have_clones ? clone_addr(arr, "arch_x86_64_v3") : NULL;
        void *v1 = have_clones ? clone_addr(arr, "default") : NULL;
        if (!v4 && !v3 && !v1) {
            add(c, n, name, "dispatch", fast, arity, NULL, a);
            continue;
        }
        if (v1)
            add(c, n, name, "sse2", fast, arity, NULL, v1);
        if (v3 && __builtin_cpu_supports("x86-64-v3"))
            add(c, n, name, "avx2", fast, arity, NULL, v3);
        if (v4 && __builtin_cpu_supports("x86-64-v4"))
            add(c, n, name, "avx512", fast, arity, NULL, v4);
    }
}

void pfb_loop1(pf_fn1 f, const float *x, float *y, size_t n)
{
    for (size_t i = 0; i < n; i++)
        y[i] = f(x[i]);
}

void pfb_loop2(pf_fn2 f, const float *y, const float *x, float *out, size_t n)
{
    for (size_t i = 0; i < n; i++)
        out[i] = f(y[i], x[i]);
}

/* ---- fixed point ----
 * The library's fixed-point set: the PF_FIXED rows of libpfmath/functions.def
 * (pf_<name>, stored integers in and out, array form <sym>_array(const IN *x,
 * OUT *y, size_t n)).  A row whose symbol the library lacks is absent. */
#define PFB_ST_i16 PFB_I16
#define PFB_ST_u16 PFB_U16
#define PFB_ST_i32 PFB_I32
#define PFB_ST_u32 PFB_U32
static const pfb_fixed_row fixed_rows[] = {
#define PF_FIXED(n, f, id, ist, isg, isz, ie, ost, osg, osz, oe, lsb, lo, hi)                                  \
    {id, "pf_" #n, PF_FS_TYPE(isg, isz, ie), PF_FS_TYPE(osg, osz, oe), PFB_ST_##ist, PFB_ST_##ost, ie, oe, lo, hi},
#include "functions.def"
};

const pfb_fixed_row *pfb_fixed_rows(int *n)
{
    *n = (int)(sizeof fixed_rows / sizeof fixed_rows[0]);
    return fixed_rows;
}

void *pfb_fixed_scalar(const pfb_fixed_row *r) { return lib_h ? dlsym(lib_h, r->sym) : NULL; }

void *pfb_fixed_array(const pfb_fixed_row *r)
{
    char name[128];
    snprintf(name, sizeof name, "%s_array", r->sym);
    return lib_h ? dlsym(lib_h, name) : NULL;
}
