/* pfmathgen --scene FILE -o DIR (scene.h): read and check every line first,
 * generate every entry in this process into memory, and only then write
 * DIR's files, each through gen/front/output.c; nothing in DIR is touched unless
 * every entry succeeded, and nothing there is deleted. */
#include "scene.h"

#include "cli.h"
#include "fixed_internal.h"
#include "fixedgen.h"
#include "fixedtype.h"
#include "generate.h"
#include "output.h"

#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAXENT 64

typedef struct {
    char func[32], variant[16], tin[64], tout[64], name[256];
    pf_type in, out;
    int line;
} scene_entry;

typedef struct {
    const char *scene;  /* the file, for messages */
    const char *dir;    /* DIR without trailing slashes */
    char prefix[PF_NAME_MAX + 1];
    scene_entry e[MAXENT];
    int ne;
    /* what will be written: DIR/<file> */
    int nout;
    char *file[MAXENT + 2], *data[MAXENT + 2];
    size_t len[MAXENT + 2];
} scene;

__attribute__((format(printf, 3, 4))) static int fail(const scene *S, int line, const char *fmt, ...)
{
    char msg[1200], full[1500];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (line)
        snprintf(full, sizeof full, "%.200s:%d: %s", S->scene, line, msg);
    else
        snprintf(full, sizeof full, "%.200s: %s", S->scene, msg);
    pf_say(full);
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

static int word_is(const char *p, const char *w)
{
    size_t n = strlen(w);
    return !strncmp(p, w, n) && (!p[n] || isspace((unsigned char)p[n]));
}

/* one non-blank line, comment removed: fills x or reports */
static int parse_line(scene *S, char *p, int ln, scene_entry *x)
{
    memset(x, 0, sizeof *x);
    x->line = ln;
    size_t k = strcspn(p, " \t\r\v\f\n");
    if (k >= sizeof x->func)
        return fail(S, ln, "unknown function '%.40s...'", p);
    memcpy(x->func, p, k);
    const char *q = p + k;
    while (isspace((unsigned char)*q))
        q++;
    int noise = is_noise(x->func);
    if (!strcmp(x->func, "noise"))
        return fail(S, ln, "list noise by dimension: noise1, noise2, noise3 or noise4");
    if (word_is(q, "exact") || word_is(q, "fast")) {
        int l = q[0] == 'e' ? 5 : 4;
        memcpy(x->variant, q, (size_t)l);
        q += l;
        if (noise && l == 4)
            return fail(S, ln, "noise has only the exact variant (within 1 LSB)");
    } else if (noise) {
        strcpy(x->variant, "exact"); /* the variant is optional for noise */
    } else {
        return fail(S, ln, "expected 'function exact|fast input-type output-type'");
    }
    char err[300];
    q = take_type(q, x->tin, sizeof x->tin);
    if (q)
        q = take_type(q, x->tout, sizeof x->tout);
    while (q && isspace((unsigned char)*q))
        q++;
    if (!q || *q)
        return fail(S, ln, "expected an input type and an output type, e.g. fixed<15,12> fixed<15,14>");
    if (pf_parse_type("input type", x->tin, &x->in, err, sizeof err) ||
        pf_parse_type("output type", x->tout, &x->out, err, sizeof err))
        return fail(S, ln, "%s", err);
    if (x->in.is_float != x->out.is_float)
        return fail(S, ln, "float and fixed-point types cannot be mixed in one entry");
    if (noise && x->in.is_float)
        return fail(S, ln, "noise is generated for fixed-point types; float noise is pf_noiseNf in libpfmath");
    int fast = !strcmp(x->variant, "fast");
    /* built in a local first: GCC's -Wrestrict (at -O1, the ASan tree)
       cannot tell x->name from the other fields of the one static scene */
    char nm[sizeof x->name];
    if (x->in.is_float) {
        if (!pf_spec_find(x->func, x->variant, NULL))
            return fail(S, ln, "unknown function %s", x->func);
        snprintf(nm, sizeof nm, "%s%sf%s", S->prefix, x->func, fast ? "_fast" : "");
    } else {
        if (noise && x->in.exp <= 0)
            return fail(S, ln, "noise input %s has no fraction bits (exp <= 0)", x->tin);
        if (noise && x->in.exp > 62)
            return fail(S, ln, "noise input %s: exp > 62 is not supported", x->tin);
        if (!noise && !fx_func_find(x->func))
            return fail(S, ln, "no fixed-point %s (available: %s)", x->func, fx_func_list());
        char a[32], b[32];
        type_tag(&x->in, a, sizeof a);
        type_tag(&x->out, b, sizeof b);
        snprintf(nm, sizeof nm, "%s%s%s_%s_%s", S->prefix, x->func, fast ? "_fast" : "", a, b);
    }
    memcpy(x->name, nm, sizeof nm);
    if (pf_check_name("function name", x->name, err, sizeof err))
        return fail(S, ln, "%s (choose another --prefix)", err);
    for (int j = 0; j < S->ne; j++)
        if (!strcmp(S->e[j].name, x->name))
            return fail(S, ln, "duplicate entry %s (line %d)", x->name, S->e[j].line);
    return 0;
}

/* One line of any length into *line (grown as needed), without its '\n'.
 * Returns 1 for a line, 0 at the end, -1 for a NUL byte (found as it is
 * read: /dev/zero fails at once), -2 past MAX_SCENE bytes, -3 read error. */
#define MAX_SCENE (16u << 20)
static int read_line(FILE *f, char **line, size_t *cap, size_t *total)
{
    size_t n = 0;
    int c;
    while ((c = getc(f)) != EOF && c != '\n') {
        if (c == 0)
            return -1;
        if (++*total > MAX_SCENE)
            return -2;
        if (n + 2 > *cap) {
            size_t nc = *cap ? 2 * *cap : 256;
            char *p = realloc(*line, nc);
            if (!p)
                return -2;
            *line = p;
            *cap = nc;
        }
        (*line)[n++] = (char)c;
    }
    if (ferror(f))
        return -3;
    if (c == EOF && n == 0)
        return 0;
    if (!*line && !(*line = malloc(*cap = 16)))
        return -2;
    (*line)[n] = 0;
    return 1;
}

/* Every line checked before anything is generated. */
static int parse(scene *S)
{
    FILE *f = fopen(S->scene, "r");
    if (!f)
        return fail(S, 0, "cannot read the scene file (%s)", strerror(errno));
    char *line = NULL;
    size_t cap = 0, total = 0;
    int ln = 0, rc = 0, got;
    S->ne = 0;
    while (!rc && (got = read_line(f, &line, &cap, &total)) != 0) {
        ln++;
        if (got == -1) {
            rc = fail(S, ln, "a NUL byte: a scene file is text");
            break;
        }
        if (got == -2) {
            rc = fail(S, ln, "the scene file is over %u MiB", MAX_SCENE >> 20);
            break;
        }
        if (got == -3) {
            rc = fail(S, 0, "cannot read the scene file (%s)", strerror(errno));
            break;
        }
        char *h = strchr(line, '#');
        if (h)
            *h = 0;
        char *p = line;
        /* a UTF-8 byte order mark (some editors write one): not part of the
           first entry, whose function it made unknown ("no fixed-point
           <BOM>sqrt", the mark invisible) */
        if (ln == 1 && !strncmp(p, "\xef\xbb\xbf", 3))
            p += 3;
        while (isspace((unsigned char)*p))
            p++;
        if (!*p)
            continue;
        if (S->ne == MAXENT) {
            rc = fail(S, ln, "too many entries (max %d)", MAXENT);
            break;
        }
        rc = parse_line(S, p, ln, &S->e[S->ne]);
        if (!rc)
            S->ne++;
    }
    free(line);
    fclose(f);
    if (!rc && S->ne == 0)
        rc = fail(S, 0, "no entries");
    return rc;
}

static int add_output(scene *S, const char *file, char *data, size_t len)
{
    S->file[S->nout] = strdup(file);
    S->data[S->nout] = data;
    S->len[S->nout] = len;
    S->nout++;
    return S->file[S->nout - 1] ? 0 : -1;
}

/* float entry: exact = the smallest order whose polynomial is within 2^-25
 * relative (so 0.5 ULP of final rounding + at most 0.5 ULP of
 * approximation), raised further if the sampled sweep still exceeds 1 ULP;
 * fast = the library's fast rule (smallest order reaching 2^-10). */
static int gen_float(scene *S, const scene_entry *x, const char *command, FILE *rep)
{
    pf_gen_req rq = {0};
    rq.func = x->func;
    rq.variant = x->variant;
    rq.name = x->name;
    rq.sweep = 1;
    rq.command = command;
    char err[600];
    pf_gen_result r;
    if (!strcmp(x->variant, "exact")) {
        rq.target = 0x1p-25;
        rq.target_text = "float, within 1 ULP";
        if (pf_generate(&rq, &r, err, sizeof err) != 0)
            return fail(S, x->line, "%s", err);
        while (r.sweep.max_ulp > 1.0 && r.order < FIT_MAX_ORDER) {
            int o = r.order + 1;
            pf_gen_free(&r);
            rq.order = o;
            rq.target = 0;
            if (pf_generate(&rq, &r, err, sizeof err) != 0)
                return fail(S, x->line, "%s", err);
        }
    } else if (pf_generate(&rq, &r, err, sizeof err) != 0) {
        return fail(S, x->line, "%s", err);
    }
    fprintf(rep, "%-28s %-6s %-5s float -> float  order %2d  max rel err %.3e  sweep max %.3f ULP (%llu inputs)\n",
            x->name, x->func, x->variant, r.order, r.poly.max_err, r.sweep.max_ulp,
            (unsigned long long)r.sweep.count);
    char file[sizeof x->name + 4];
    snprintf(file, sizeof file, "%s.c", x->name);
    if (add_output(S, file, r.csrc, r.clen) != 0)
        return fail(S, 0, "out of memory");
    r.csrc = NULL; /* now S's */
    return 0;
}

/* fixed and noise entries: the fixed-point generators, in this process; the
 * file records the single-function command that regenerates it */
static int gen_fixed(scene *S, const scene_entry *x, FILE *rep)
{
    char file[sizeof x->name + 4], *path;
    snprintf(file, sizeof file, "%s.c", x->name);
    size_t pl = strlen(S->dir) + strlen(file) + 2;
    path = malloc(pl);
    if (!path)
        return fail(S, 0, "out of memory");
    snprintf(path, pl, "%s/%s", S->dir, file);
    char *argv[] = {"pfmathgen", "--func", (char *)x->func, "--variant", (char *)x->variant, "--type",
                    (char *)x->tin, "--out-type", (char *)x->tout, "--name", (char *)x->name, "-o", path, NULL};
    pf_request rq = {0};
    rq.mode = is_noise(x->func) ? PF_MODE_NOISE : PF_MODE_FIXED;
    rq.func = x->func;
    rq.variant = x->variant;
    rq.in = x->in;
    rq.out = x->out;
    rq.type_s = x->tin;
    rq.out_type_s = x->tout;
    rq.name = x->name;
    rq.sweep = 1;
    rq.command = pf_cli_command_line(sizeof argv / sizeof argv[0] - 1, argv);
    free(path);
    if (!rq.command)
        return fail(S, 0, "out of memory");
    fprintf(rep, "%-28s %-6s %-5s %s -> %s\n", x->name, x->func, x->variant, x->tin, x->tout);
    char err[800], *src = NULL;
    size_t len = 0;
    int rc = rq.mode == PF_MODE_NOISE ? pf_run_noise(&rq, rep, &src, &len, err, sizeof err)
                                      : pf_run_fixed(&rq, rep, &src, &len, err, sizeof err);
    free(rq.command);
    if (rc) {
        fail(S, x->line, "%s", err);
        return rc;
    }
    if (add_output(S, file, src, len) != 0)
        return fail(S, 0, "out of memory");
    return 0;
}

/* text for a C comment: "*" "/" would end it, and so would "*", a
 * backslash (or the trigraph ??/), a newline and "/", lines being spliced
 * before comments end (pf_cli_command_line); "/" "*" is -Wcomment's
 * warning, a trigraph -Wtrigraphs'.  A blank goes between "*" or "/" and
 * another of "/", "*", a backslash, and between "?" and "?". */
static void comment_text(FILE *h, const char *s)
{
    for (; *s; s++) {
        fputc(*s, h);
        if (((s[0] == '*' || s[0] == '/') && s[1] && s[1] != s[0] && strchr("/*\\", s[1])) ||
            (s[0] == '?' && s[1] == '?'))
            fputc(' ', h);
    }
}

static char *scene_header(const scene *S, const char *command, size_t *len)
{
    char *buf = NULL;
    FILE *h = open_memstream(&buf, len);
    if (!h)
        return NULL;
    char guard[PF_NAME_MAX + 16];
    size_t g = 0;
    for (const char *p = S->prefix; *p && g < sizeof guard - 10; p++)
        guard[g++] = (char)toupper((unsigned char)*p);
    if (g && guard[g - 1] != '_')
        guard[g++] = '_';
    strcpy(guard + g, "SCENE_H");
    fputs("/* Functions generated for the scene ", h);
    comment_text(h, S->scene);
    fputs(" by: ", h);
    comment_text(h, command);
    fprintf(h, " */\n#ifndef %s\n#define %s\n#include <stddef.h>\n#include <stdint.h>\n\n", guard, guard);
    fprintf(h, "#ifdef __cplusplus\nextern \"C\" {\n#endif\n\n");
    for (int i = 0; i < S->ne; i++) {
        const scene_entry *x = &S->e[i];
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
        } else if (!strcmp(x->func, "atan2")) {
            fprintf(h, "%s %s(%s y, %s x);\nvoid %s_array(const %s *y, const %s *x, %s *out, size_t n);\n", co,
                    x->name, ci, ci, x->name, ci, ci, co);
        } else {
            fprintf(h, "%s %s(%s x);\nvoid %s_array(const %s *x, %s *y, size_t n);\n", co, x->name, ci, x->name,
                    ci, co);
        }
    }
    fprintf(h, "\n#ifdef __cplusplus\n}\n#endif\n\n#endif\n");
    if (fclose(h) != 0) {
        free(buf);
        return NULL;
    }
    return buf;
}

/* the default prefix: the scene file's base name up to its first '.',
 * other characters than letters and digits as '_', then '_' */
static void default_prefix(const char *scene, char *out, size_t n)
{
    const char *b = strrchr(scene, '/') ? strrchr(scene, '/') + 1 : scene;
    size_t k = 0;
    if (!(isascii((unsigned char)*b) && isalpha((unsigned char)*b)))
        out[k++] = 's'; /* a letter first: never a digit, nor a reserved _X or __ name */
    for (; *b && *b != '.' && k + 2 < n && k < 40; b++)
        out[k++] = isascii((unsigned char)*b) && isalnum((unsigned char)*b) ? *b : '_';
    out[k++] = '_';
    out[k] = 0;
}

/* DIR: an existing directory we may write in, or a name we may create */
static int check_dir(const scene *S, int *exists)
{
    struct stat sb;
    char msg[300];
    *exists = stat(S->dir, &sb) == 0;
    if (*exists) {
        if (!S_ISDIR(sb.st_mode))
            return fail(S, 0, "-o %s exists and is not a directory", S->dir);
        if (access(S->dir, W_OK | X_OK) != 0)
            return fail(S, 0, "-o %s: cannot write in it (%s)", S->dir, strerror(errno));
        return 0;
    }
    if (errno != ENOENT)
        return fail(S, 0, "-o %s: %s", S->dir, strerror(errno));
    if (lstat(S->dir, &sb) == 0)
        return fail(S, 0, "-o %s is a symbolic link to nothing", S->dir);
    char *parent = pf_out_dirname(S->dir);
    int ok = parent && stat(parent, &sb) == 0 && S_ISDIR(sb.st_mode) && access(parent, W_OK | X_OK) == 0;
    snprintf(msg, sizeof msg, "%s", parent ? parent : "?");
    free(parent);
    if (!ok)
        return fail(S, 0, "-o %s: cannot create it (the directory %s does not exist or is not writable)", S->dir,
                    msg);
    return 0;
}

/* an output DIR/file that is the scene file itself (by name or through a
 * symlink in DIR): refused, exit 2, before anything is written */
static int clobbers_scene(const scene *S, const char *file)
{
    size_t pl = strlen(S->dir) + strlen(file) + 2;
    char *path = malloc(pl);
    if (!path) {
        fail(S, 0, "out of memory");
        return 1;
    }
    snprintf(path, pl, "%s/%s", S->dir, file);
    int same = pf_out_same(path, S->scene);
    free(path);
    if (same)
        return fail(S, 0, "-o %s: its %s is the scene file itself, which the run would replace", S->dir, file);
    return 0;
}

/* DIR/file as pf_out_check sees it (exit 2 with its reason) */
static int check_file(const scene *S, const char *file)
{
    size_t pl = strlen(S->dir) + strlen(file) + 2;
    char *path = malloc(pl), e[600];
    if (!path) {
        fail(S, 0, "out of memory");
        return 1;
    }
    snprintf(path, pl, "%s/%s", S->dir, file);
    int bad = pf_out_check("-o", path, e, sizeof e) != 0;
    free(path);
    return bad ? fail(S, 0, "%s", e) : 0;
}

/* Every file is staged (written beside its target) before any is renamed
 * into place: a failure before the renames leaves DIR as it was. */
static int write_all(scene *S, int exists)
{
    char err[600];
    int created = 0;
    if (!exists) {
        if (mkdir(S->dir, 0777) != 0) {
            fail(S, 0, "cannot create %s (%s)", S->dir, strerror(errno));
            return 1;
        }
        created = 1;
    }
    pf_out_staged st[MAXENT + 2];
    memset(st, 0, sizeof st);
    int rc = 0;
    for (int i = 0; i < S->nout && !rc; i++) {
        size_t pl = strlen(S->dir) + strlen(S->file[i]) + 2;
        char *path = malloc(pl);
        if (!path) {
            rc = 1;
            snprintf(err, sizeof err, "out of memory");
            break;
        }
        snprintf(path, pl, "%s/%s", S->dir, S->file[i]);
        if (pf_out_stage(path, S->data[i], S->len[i], &st[i], err, sizeof err) != 0)
            rc = 1;
        free(path);
    }
    /* the special files (a link to a device) first: pf_out_commit_all */
    if (!rc && pf_out_commit_all(st, S->nout, err, sizeof err) != 0)
        rc = 1;
    for (int i = 0; i < S->nout; i++)
        pf_out_abort(&st[i]);
    if (rc) {
        if (created)
            rmdir(S->dir); /* ours, and empty unless a commit went through */
        fail(S, 0, "%s", err);
    }
    return rc;
}

int pf_scene_run(const pf_request *rq)
{
    static scene Ss;
    scene *S = &Ss;
    memset(S, 0, sizeof *S);
    S->scene = rq->scene;
    /* "out/" and "out" are the same directory */
    char *dir = strdup(rq->output);
    if (!dir)
        return 1;
    for (size_t l = strlen(dir); l > 1 && dir[l - 1] == '/'; l--)
        dir[l - 1] = 0;
    S->dir = dir;
    int exists = 0, rc = 0;
    if (rq->prefix) {
        /* a name's beginning: identifier characters, not reserved, and not
           libpfmath's own pf_ alone (the collision scenes avoid) */
        const char *p = rq->prefix;
        if (!pf_cli_is_identifier(p) || strlen(p) > 60 || !strcmp(p, "pf_") ||
            (p[0] == '_' && (p[1] == '_' || isupper((unsigned char)p[1]))))
            rc = fail(S, 0, "bad --prefix '%.80s': letters, digits and '_' (at most 60, not starting with a digit, "
                      "__ or _ and a capital), and not pf_ alone",
                      p);
        else
            snprintf(S->prefix, sizeof S->prefix, "%s", p);
    } else {
        default_prefix(rq->scene, S->prefix, sizeof S->prefix);
        if (!strcmp(S->prefix, "pf_"))
            rc = fail(S, 0, "the scene file's name gives the prefix pf_, libpfmath's own (its functions would "
                      "clash at link time): choose one with --prefix");
    }
    if (!rc && !*dir)
        rc = fail(S, 0, "-o: empty directory name");
    if (!rc)
        rc = parse(S);
    if (!rc)
        rc = check_dir(S, &exists);
    /* DIR's own two files, known before any fit: the scene file itself, or
       one that cannot be replaced (read-only, a directory), is exit 2 now */
    const char *fixed_files[] = {"scene.h", "report.txt"};
    for (int i = 0; i < 2 && !rc; i++) {
        rc = clobbers_scene(S, fixed_files[i]);
        if (!rc && exists)
            rc = check_file(S, fixed_files[i]);
    }
    /* and every entry's NAME.c, known from its line: a directory or the
       scene file under that name was found only at the write, after all
       the fits (exit 1) */
    for (int i = 0; i < S->ne && !rc; i++) {
        char file[sizeof S->e[i].name + 4];
        snprintf(file, sizeof file, "%s.c", S->e[i].name);
        rc = clobbers_scene(S, file);
        if (!rc && exists)
            rc = check_file(S, file);
    }
    char *rtext = NULL;
    size_t rlen = 0;
    FILE *rep = rc ? NULL : open_memstream(&rtext, &rlen);
    if (!rc && !rep)
        rc = 1;
    if (!rc) {
        fprintf(rep, "pfmathgen scene report: %s\ncommand: %s\nprefix: %s\n\n", rq->scene, rq->command, S->prefix);
        for (int i = 0; i < S->ne && !rc; i++)
            rc = S->e[i].in.is_float ? gen_float(S, &S->e[i], rq->command, rep) : gen_fixed(S, &S->e[i], rep);
        fclose(rep);
    }
    if (!rc) {
        size_t hl = 0;
        char *h = scene_header(S, rq->command, &hl);
        /* add_output owns the data from here, even when it fails */
        int bad = !h || add_output(S, "scene.h", h, hl) != 0;
        bad |= add_output(S, "report.txt", rtext, rlen) != 0;
        rtext = NULL;
        if (bad)
            rc = fail(S, 0, "out of memory");
    }
    for (int i = 0; i < S->nout && !rc; i++)
        rc = clobbers_scene(S, S->file[i]);
    if (!rc)
        rc = write_all(S, exists);
    free(rtext);
    for (int i = 0; i < S->nout; i++) {
        free(S->file[i]);
        free(S->data[i]);
    }
    free(dir);
    return rc;
}
