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

#include <dlfcn.h>
#include <elf.h>
#include <fcntl.h>
#include <link.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

/* the ladder's levels, ULP (mk/ladder.mk: LADDER_LEVELS) */
static const int levels[] = {1, 2, 4, 128, 8192};
#define NLEVELS ((int)(sizeof levels / sizeof levels[0]))

static void *lh;
static uintptr_t base;
static const Elf64_Sym *syms;
static size_t nsym;
static const char *strs;

/* the mapped file's .symtab (kept mapped: names point into it) */
static void map_syms(const char *path)
{
    int fd = open(path, O_RDONLY);
    struct stat st;
    if (fd < 0)
        return;
    void *m = fstat(fd, &st) == 0 && (size_t)st.st_size >= sizeof(Elf64_Ehdr)
                  ? mmap(NULL, (size_t)st.st_size, PROT_READ, MAP_PRIVATE, fd, 0)
                  : MAP_FAILED;
    close(fd);
    if (m == MAP_FAILED)
        return;
    const unsigned char *b = m;
    size_t size = (size_t)st.st_size;
    const Elf64_Ehdr *eh = m;
    if (memcmp(eh->e_ident, ELFMAG, SELFMAG) || eh->e_ident[EI_CLASS] != ELFCLASS64 || !eh->e_shoff ||
        eh->e_shentsize != sizeof(Elf64_Shdr) || eh->e_shoff + (size_t)eh->e_shnum * sizeof(Elf64_Shdr) > size)
        return;
    const Elf64_Shdr *sh = (const Elf64_Shdr *)(b + eh->e_shoff);
    for (int i = 0; i < eh->e_shnum; i++) {
        if (sh[i].sh_type != SHT_SYMTAB || sh[i].sh_link >= eh->e_shnum)
            continue;
        const Elf64_Shdr *ss = &sh[sh[i].sh_link];
        if (sh[i].sh_offset + sh[i].sh_size > size || ss->sh_offset + ss->sh_size > size || !ss->sh_size ||
            b[ss->sh_offset + ss->sh_size - 1])
            return;
        syms = (const Elf64_Sym *)(b + sh[i].sh_offset);
        nsym = sh[i].sh_size / sizeof(Elf64_Sym);
        strs = (const char *)(b + ss->sh_offset);
        return;
    }
}

static void *clone_of(const char *name, const char *suffix)
{
    char full[160];
    snprintf(full, sizeof full, "%s.%s", name, suffix);
    for (size_t i = 0; syms && i < nsym; i++)
        if (ELF64_ST_TYPE(syms[i].st_info) == STT_FUNC && syms[i].st_shndx != SHN_UNDEF &&
            !strcmp(strs + syms[i].st_name, full))
            return (void *)(base + syms[i].st_value);
    return NULL;
}

int pfb_ladder_open(const char *lib, char *err, size_t errlen)
{
    lh = dlopen(lib, RTLD_NOW | RTLD_LOCAL);
    if (!lh) {
        snprintf(err, errlen, "%s", dlerror());
        return -1;
    }
    struct link_map *lm = NULL;
    if (dlinfo(lh, RTLD_DI_LINKMAP, &lm) == 0 && lm)
        base = (uintptr_t)lm->l_addr;
    map_syms(lib);
    return 0;
}

static void add(pfb_cand *c, int *n, int level, const char *isa, int arity, void *array)
{
    pfb_cand *k = &c[(*n)++];
    memset(k, 0, sizeof *k);
    snprintf(k->name, sizeof k->name, "pfmath-L%d", level);
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
        char arr[96];
        snprintf(arr, sizeof arr, "pf_%sf_l%d_array", pfref_name(f), levels[i]);
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
    int level;
    if (!lh || sscanf(c->name, "pfmath-L%d", &level) != 1)
        return NULL;
    char sym[96];
    snprintf(sym, sizeof sym, "pf_%sf_l%d", pfref_name(f), level);
    return dlsym(lh, sym);
}
