#include "scene.h"

#include "fixedtype.h"
#include "generate.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#define MAXENT 64

typedef struct {
    char func[32], variant[16], tin[64], tout[64], name[128];
    pf_type in, out;
    int line;
} scene_entry;

static int fail(const char *scene, int line, const char *msg, const char *arg)
{
    if (line)
        fprintf(stderr, "pfmathgen: %s:%d: %s%s\n", scene, line, msg, arg ? arg : "");
    else
        fprintf(stderr, "pfmathgen: %s: %s%s\n", scene, msg, arg ? arg : "");
    return 2;
}

/* next type token: "float" or "[unsigned|signed] fixed<...>" or "ufixed<...>" */
static const char *take_type(const char *p, char *out, size_t n)
{
    while (isspace((unsigned char)*p))
        p++;
    if (!*p)
        return NULL;
    if (!strncmp(p, "float", 5) && (!p[5] || isspace((unsigned char)p[5]))) {
        snprintf(out, n, "float");
        return p + 5;
    }
    const char *gt = strchr(p, '>');
    if (!gt)
        return NULL;
    size_t len = (size_t)(gt - p + 1);
    if (len >= n)
        return NULL;
    memcpy(out, p, len);
    out[len] = 0;
    return gt + 1;
}

static void type_tag(const pf_type *t, char *buf, size_t n)
{
    snprintf(buf, n, "%c%d_%s%d", t->is_signed ? 's' : 'u', t->size, t->exp < 0 ? "m" : "",
             t->exp < 0 ? -t->exp : t->exp);
}

/* noise1 .. noise4: gradient noise of that dimension (fixed point only) */
static int is_noise(const char *f)
{
    return !strncmp(f, "noise", 5) && f[5] >= '1' && f[5] <= '4' && !f[6];
}

static int parse(const char *scene, scene_entry *e, int *ne)
{
    FILE *f = fopen(scene, "r");
    if (!f)
        return fail(scene, 0, "cannot read the scene file", NULL);
    char line[512];
    int ln = 0;
    *ne = 0;
    while (fgets(line, sizeof line, f)) {
        ln++;
        char *h = strchr(line, '#');
        if (h)
            *h = 0;
        char *p = line;
        while (isspace((unsigned char)*p))
            p++;
        if (!*p)
            continue;
        if (*ne == MAXENT) {
            fclose(f);
            return fail(scene, ln, "too many entries (max 64)", NULL);
        }
        scene_entry *x = &e[*ne];
        memset(x, 0, sizeof *x);
        x->line = ln;
        int k = 0;
        while (*p && !isspace((unsigned char)*p) && k < 31)
            x->func[k++] = *p++;
        const char *q = p;
        while (isspace((unsigned char)*q))
            q++;
        int noise = is_noise(x->func);
        if (!strcmp(x->func, "noise")) {
            fclose(f);
            return fail(scene, ln, "list noise by dimension: noise1, noise2, noise3 or noise4", NULL);
        }
        if (!strncmp(q, "exact", 5) || !strncmp(q, "fast", 4)) {
            int l = q[0] == 'e' ? 5 : 4;
            memcpy(x->variant, q, (size_t)l);
            q += l;
            if (noise && l == 4) {
                fclose(f);
                return fail(scene, ln, "noise has only the exact variant (within 1 LSB)", NULL);
            }
        } else if (noise) {
            strcpy(x->variant, "exact"); /* the variant is optional for noise */
        } else {
            fclose(f);
            return fail(scene, ln, "expected 'function exact|fast input-type output-type'", NULL);
        }
        char err[200];
        q = take_type(q, x->tin, sizeof x->tin);
        if (q)
            q = take_type(q, x->tout, sizeof x->tout);
        while (q && isspace((unsigned char)*q))
            q++;
        if (!q || *q) {
            fclose(f);
            return fail(scene, ln, "expected an input type and an output type, e.g. fixed<15,12> fixed<15,14>", NULL);
        }
        if (pf_type_parse(x->tin, &x->in, err, sizeof err) || pf_type_parse(x->tout, &x->out, err, sizeof err)) {
            fclose(f);
            return fail(scene, ln, err, NULL);
        }
        if (x->in.is_float != x->out.is_float) {
            fclose(f);
            return fail(scene, ln, "float and fixed-point types cannot be mixed in one entry", NULL);
        }
        if (noise && x->in.is_float) {
            fclose(f);
            return fail(scene, ln, "noise is generated for fixed-point types; float noise is pf_noiseNf in libpfmath",
                        NULL);
        }
        if (x->in.is_float) {
            if (!pf_spec_find(x->func, x->variant, NULL)) {
                fclose(f);
                return fail(scene, ln, "unknown function ", x->func);
            }
            snprintf(x->name, sizeof x->name, "pf_%sf%s", x->func, strcmp(x->variant, "fast") ? "" : "_fast");
        } else {
            char a[32], b[32];
            type_tag(&x->in, a, sizeof a);
            type_tag(&x->out, b, sizeof b);
            snprintf(x->name, sizeof x->name, "pf_%s%s_%s_%s", x->func,
                     strcmp(x->variant, "fast") ? "" : "_fast", a, b);
        }
        for (int j = 0; j < *ne; j++)
            if (!strcmp(e[j].name, x->name)) {
                fclose(f);
                return fail(scene, ln, "duplicate entry ", x->name);
            }
        (*ne)++;
    }
    fclose(f);
    if (*ne == 0)
        return fail(scene, 0, "no entries", NULL);
    return 0;
}

static int write_file(const char *path, const char *data, size_t n)
{
    FILE *f = fopen(path, "w");
    int ok = f && fwrite(data, 1, n, f) == n;
    if (f && fclose(f) != 0)
        ok = 0;
    return ok ? 0 : -1;
}

/* float entry in-process: exact = the smallest order whose polynomial is
 * within 2^-25 relative (so 0.5 ULP of final rounding + at most 0.5 ULP of
 * approximation), raised further if the sampled sweep still exceeds 1 ULP;
 * fast = the library's fast rule (smallest order reaching 2^-10). */
static int gen_float(const scene_entry *x, const char *dir, const char *command, FILE *rep)
{
    pf_gen_req rq = {0};
    rq.func = x->func;
    rq.variant = x->variant;
    rq.name = x->name;
    rq.sweep = 1;
    rq.command = command;
    char err[512];
    pf_gen_result r;
    if (!strcmp(x->variant, "exact")) {
        /* 2^-25 relative: with the final rounding's 0.5 ULP, at most 1 ULP */
        rq.target = 0x1p-25;
        rq.target_text = "float, within 1 ULP";
        if (pf_generate(&rq, &r, err, sizeof err) != 0)
            return fail(x->func, 0, err, NULL);
        while (r.sweep.max_ulp > 1.0 && r.order < FIT_MAX_ORDER) {
            int o = r.order + 1;
            pf_gen_free(&r);
            rq.order = o;
            rq.target = 0;
            if (pf_generate(&rq, &r, err, sizeof err) != 0)
                return fail(x->func, 0, err, NULL);
        }
    } else if (pf_generate(&rq, &r, err, sizeof err) != 0) {
        return fail(x->func, 0, err, NULL);
    }
    char path[PATH_MAX + 256];
    snprintf(path, sizeof path, "%s/%s.c", dir, x->name);
    int rc = write_file(path, r.csrc, r.clen);
    fprintf(rep, "%-28s %-6s %-5s float -> float  order %2d  max rel err %.3e  sweep max %.3f ULP (%llu inputs)\n",
            x->name, x->func, x->variant, r.order, r.poly.max_err, r.sweep.max_ulp,
            (unsigned long long)r.sweep.count);
    pf_gen_free(&r);
    return rc ? fail(path, 0, "cannot write", NULL) : 0;
}

/* fixed and noise entries: the fixed-point pipeline of this same program */
static int gen_fixed(const scene_entry *x, const char *dir, FILE *rep)
{
    char self[PATH_MAX], path[PATH_MAX + 256], log[PATH_MAX + 256];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n < 0)
        return fail("pfmathgen", 0, "cannot locate itself", NULL);
    self[n] = 0;
    snprintf(path, sizeof path, "%s/%s.c", dir, x->name);
    snprintf(log, sizeof log, "%s/%s.log", dir, x->name);
    pid_t pid = fork();
    if (pid == 0) {
        FILE *l = freopen(log, "w", stderr);
        (void)l;
        execl(self, "pfmathgen", "--func", x->func, "--variant", x->variant, "--type", x->tin,
              "--out-type", x->tout, "--name", x->name, "-o", path, (char *)NULL);
        _exit(127);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    FILE *l = fopen(log, "r");
    char buf[1024];
    fprintf(rep, "%-28s %-6s %-5s %s -> %s\n", x->name, x->func, x->variant, x->tin, x->tout);
    char first[1024] = "";
    while (l && fgets(buf, sizeof buf, l)) {
        if (!first[0])
            snprintf(first, sizeof first, "%s", buf);
        fprintf(rep, "    %s", buf);
    }
    if (l)
        fclose(l);
    unlink(log);
    if (!WIFEXITED(st) || WEXITSTATUS(st) != 0) {
        first[strcspn(first, "\n")] = 0;
        fprintf(stderr, "%s\n", first[0] ? first : "pfmathgen: fixed-point generation failed");
        return 2;
    }
    return 0;
}

static void rmrf(const char *dir)
{
    char cmd[PATH_MAX + 32];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) {
    }
}

int pfmathgen_scene_main(const char *scene, const char *outdir, const char *command)
{
    static scene_entry e[MAXENT];
    int ne;
    int rc = parse(scene, e, &ne);
    if (rc)
        return rc;
    /* everything goes to a scratch directory first: no partial output */
    char tmp[PATH_MAX - 64];
    snprintf(tmp, sizeof tmp, "%s.tmp.%ld", outdir, (long)getpid());
    if (mkdir(tmp, 0777) != 0)
        return fail(outdir, 0, "cannot create the output directory", NULL);
    char rp[PATH_MAX + 32];
    snprintf(rp, sizeof rp, "%s/report.txt", tmp);
    FILE *rep = fopen(rp, "w");
    if (!rep) {
        rmrf(tmp);
        return fail(outdir, 0, "cannot write the report", NULL);
    }
    fprintf(rep, "pfmathgen scene report: %s\ncommand: %s\n\n", scene, command);
    for (int i = 0; i < ne && !rc; i++)
        rc = e[i].in.is_float ? gen_float(&e[i], tmp, command, rep) : gen_fixed(&e[i], tmp, rep);
    fclose(rep);
    if (!rc) {
        char hp[PATH_MAX + 32];
        snprintf(hp, sizeof hp, "%s/scene.h", tmp);
        FILE *h = fopen(hp, "w");
        if (!h) {
            rc = fail(outdir, 0, "cannot write scene.h", NULL);
        } else {
            fprintf(h, "/* Functions generated for the scene %s by: %s */\n", scene, command);
            fprintf(h, "#ifndef PF_SCENE_H\n#define PF_SCENE_H\n#include <stddef.h>\n#include <stdint.h>\n\n");
            for (int i = 0; i < ne; i++) {
                const scene_entry *x = &e[i];
                const char *ci = pf_type_ctype(&x->in), *co = pf_type_ctype(&x->out);
                if (is_noise(x->func)) {
                    /* noiseN takes N coordinates: name(x, y, …), name_array(x, y, …, out, n) */
                    static const char *cn[4] = {"x", "y", "z", "w"};
                    int nd = x->func[5] - '0';
                    fprintf(h, "%s %s(", co, x->name);
                    for (int k = 0; k < nd; k++)
                        fprintf(h, "%s%s %s", k ? ", " : "", ci, cn[k]);
                    fprintf(h, ");\nvoid %s_array(", x->name);
                    for (int k = 0; k < nd; k++)
                        fprintf(h, "const %s *%s, ", ci, cn[k]);
                    fprintf(h, "%s *out, size_t n);\n", co);
                } else if (!strcmp(x->func, "atan2"))
                    fprintf(h, "%s %s(%s y, %s x);\nvoid %s_array(const %s *y, const %s *x, %s *out, size_t n);\n",
                            co, x->name, ci, ci, x->name, ci, ci, co);
                else
                    fprintf(h, "%s %s(%s x);\nvoid %s_array(const %s *x, %s *y, size_t n);\n", co, x->name, ci,
                            x->name, ci, co);
            }
            fprintf(h, "\n#endif\n");
            fclose(h);
        }
    }
    if (rc) {
        rmrf(tmp);
        return rc;
    }
    struct stat sb;
    if (stat(outdir, &sb) == 0)
        rmrf(outdir);
    if (rename(tmp, outdir) != 0) {
        rmrf(tmp);
        return fail(outdir, 0, "cannot move the output into place", NULL);
    }
    return 0;
}
