/* The static symbol table (.symtab) of a dlopen'ed library.  GCC's
 * target_clones clones (pf_logf_array.arch_x86_64_v3 and so on) are local
 * symbols that dlsym does not see; pfbench (its pfmath and ladder rows) and
 * test_clones look them up here and call each clone directly.  A stripped
 * library has no .symtab: then nothing is found. */
#ifndef PF_ELFSYMS_H
#define PF_ELFSYMS_H

#include <dlfcn.h>
#include <elf.h>
#include <fcntl.h>
#include <link.h>
#include <stdint.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

typedef struct {
    uintptr_t base;        /* load address of the library's first segment */
    const Elf64_Sym *syms; /* the mapped file's .symtab, or NULL */
    size_t n;
    const char *strs;
} pf_elfsyms;

/* s for the library dlopen'ed as handle from path.  The file stays mapped
   for the life of the process: the names point into it. */
static inline void pf_elfsyms_load(pf_elfsyms *s, void *handle, const char *path)
{
    memset(s, 0, sizeof *s);
    struct link_map *lm = NULL;
    if (dlinfo(handle, RTLD_DI_LINKMAP, &lm) == 0 && lm)
        s->base = (uintptr_t)lm->l_addr;
    int fd = open(path, O_RDONLY);
    if (fd < 0)
        return;
    struct stat st;
    void *m = MAP_FAILED;
    if (fstat(fd, &st) == 0 && (size_t)st.st_size >= sizeof(Elf64_Ehdr))
        m = mmap(NULL, (size_t)st.st_size, PROT_READ, MAP_PRIVATE, fd, 0);
    close(fd);
    if (m == MAP_FAILED)
        return;
    const unsigned char *b = m;
    size_t size = (size_t)st.st_size;
    const Elf64_Ehdr *eh = m;
    if (memcmp(eh->e_ident, ELFMAG, SELFMAG) || eh->e_ident[EI_CLASS] != ELFCLASS64 || eh->e_shoff == 0 ||
        eh->e_shentsize != sizeof(Elf64_Shdr) || eh->e_shoff + (size_t)eh->e_shnum * sizeof(Elf64_Shdr) > size)
        return;
    const Elf64_Shdr *sh = (const Elf64_Shdr *)(b + eh->e_shoff);
    for (int i = 0; i < eh->e_shnum; i++) {
        if (sh[i].sh_type != SHT_SYMTAB || sh[i].sh_link >= eh->e_shnum)
            continue;
        const Elf64_Shdr *ss = &sh[sh[i].sh_link];
        if (sh[i].sh_offset + sh[i].sh_size > size || ss->sh_offset + ss->sh_size > size || ss->sh_size == 0 ||
            b[ss->sh_offset + ss->sh_size - 1] != 0)
            return;
        s->syms = (const Elf64_Sym *)(b + sh[i].sh_offset);
        s->n = sh[i].sh_size / sizeof(Elf64_Sym);
        s->strs = (const char *)(b + ss->sh_offset);
        return;
    }
}

/* st_value of the defined function called name, or 0 */
static inline uintptr_t pf_elfsyms_value(const pf_elfsyms *s, const char *name)
{
    for (size_t i = 0; s->syms && i < s->n; i++)
        if (ELF64_ST_TYPE(s->syms[i].st_info) == STT_FUNC && s->syms[i].st_shndx != SHN_UNDEF &&
            strcmp(s->strs + s->syms[i].st_name, name) == 0)
            return (uintptr_t)s->syms[i].st_value;
    return 0;
}

/* its address in this process, or NULL */
static inline void *pf_elfsyms_func(const pf_elfsyms *s, const char *name)
{
    uintptr_t v = pf_elfsyms_value(s, name);
    return v ? (void *)(s->base + v) : NULL;
}

#endif
