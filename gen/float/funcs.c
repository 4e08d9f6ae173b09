#include "funcs.h"

#include <string.h>

/* Each family's rows live in gen/funcs_<family>.c, ended by a {0} row. */
extern const pf_spec pf_specs_log[], pf_specs_exp[], pf_specs_trig[], pf_specs_atrig[];
static const pf_spec *const families[] = {pf_specs_log, pf_specs_exp, pf_specs_trig, pf_specs_atrig};
#define NFAM ((int)(sizeof families / sizeof families[0]))

int pf_spec_count(void)
{
    int n = 0;
    for (int f = 0; f < NFAM; f++)
        for (const pf_spec *s = families[f]; s->func; s++)
            n++;
    return n;
}

const pf_spec *pf_spec_at(int i)
{
    for (int f = 0; f < NFAM; f++)
        for (const pf_spec *s = families[f]; s->func; s++)
            if (i-- == 0)
                return s;
    return NULL;
}

#define NSPECS pf_spec_count()
#define specs_at(i) (*pf_spec_at(i))

const pf_spec *pf_spec_find(const char *func, const char *variant, const char *reduction)
{
    for (int i = 0; i < NSPECS; i++)
        if (!strcmp(specs_at(i).func, func) && !strcmp(specs_at(i).variant, variant) &&
            (!reduction || !strcmp(specs_at(i).reduction, reduction)))
            return &specs_at(i);
    return NULL;
}

int pf_spec_func_known(const char *func)
{
    for (int i = 0; i < NSPECS; i++)
        if (!strcmp(specs_at(i).func, func))
            return 1;
    return 0;
}

const char *pf_spec_func_list(void)
{
    static char buf[512];
    buf[0] = 0;
    for (int i = 0; i < NSPECS; i++) {
        int seen = 0;
        for (int j = 0; j < i; j++)
            if (!strcmp(specs_at(j).func, specs_at(i).func))
                seen = 1;
        if (seen)
            continue;
        if (buf[0])
            strcat(buf, ", ");
        strcat(buf, specs_at(i).func);
    }
    return buf;
}

void pf_spec_problem(const pf_spec *s, int order, fit_problem *pb)
{
    memset(pb, 0, sizeof *pb);
    pb->g = s->g;
    pb->a = s->a;
    pb->b = s->b;
    pb->order = order;
    pb->parity = s->parity;
    pb->errkind = s->errkind;
    pb->ncon = s->ncon;
    for (int i = 0; i < s->ncon; i++) {
        pb->con[i].kind = s->con[i].kind;
        pb->con[i].t = s->con[i].t;
    }
}
