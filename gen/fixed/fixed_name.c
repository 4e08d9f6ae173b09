/* Names of the generated fixed-point functions (see fixedgen.h). */
#include "fixedgen.h"

#include <stdio.h>
#include <string.h>

/* q<exp> / uq<exp> for a type that fills its storage (the common Q
 * notation), else q<size>_<exp>; a negative exp is spelled m<|exp|>. */
void pf_fixed_type_tag(const pf_type *t, char *buf, size_t n)
{
    char e[16];
    if (t->exp < 0)
        snprintf(e, sizeof e, "m%d", -t->exp);
    else
        snprintf(e, sizeof e, "%d", t->exp);
    int full = t->size + (t->is_signed != 0) == t->storage_bits;
    if (full)
        snprintf(buf, n, "%sq%s", t->is_signed ? "" : "u", e);
    else
        snprintf(buf, n, "%sq%d_%s", t->is_signed ? "" : "u", t->size, e);
}

void pf_fixed_default_name(const char *func, const pf_type *in, const pf_type *out, int fast, char *buf,
                           size_t n)
{
    char a[40], b[40];
    pf_fixed_type_tag(in, a, sizeof a);
    pf_fixed_type_tag(out, b, sizeof b);
    if (!strcmp(a, b))
        snprintf(buf, n, "pf_%s_%s%s", func, a, fast ? "_fast" : "");
    else
        snprintf(buf, n, "pf_%s_%s_%s%s", func, a, b, fast ? "_fast" : "");
}
