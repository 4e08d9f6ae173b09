/* Parsing and properties of pf_type (see fixedtype.h). */
#include "fixedtype.h"

#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

static void set_err(char *err, size_t errlen, const char *fmt, ...)
{
    if (!err || errlen == 0)
        return;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
}

/* The input as shown in messages: blanks trimmed, control characters
 * (a newline inside the spelling) replaced so the message stays one line,
 * long inputs cut. */
static void quote_input(const char *b, const char *e, char *out, size_t n)
{
    size_t k = 0, len = (size_t)(e - b), max = n - 4;
    for (size_t i = 0; i < len && k < max; i++)
        out[k++] = iscntrl((unsigned char)b[i]) ? ' ' : b[i];
    if (len > max)
        memcpy(out + k, "...", 3), k += 3;
    out[k] = 0;
}

static const char *skip_blank(const char *p)
{
    while (isspace((unsigned char)*p))
        p++;
    return p;
}

/* identifier [A-Za-z_][A-Za-z0-9_]* at p; its length (0 if none) */
static size_t word_len(const char *p)
{
    size_t n = 0;
    if (!(isalpha((unsigned char)p[0]) || p[0] == '_'))
        return 0;
    while (isalnum((unsigned char)p[n]) || p[n] == '_')
        n++;
    return n;
}

static int word_is(const char *p, size_t n, const char *w)
{
    return strlen(w) == n && memcmp(p, w, n) == 0;
}

/* optional '-' then decimal digits; value clamped to +-1e6 (out of any
 * range we accept, and no overflow) */
static const char *parse_int(const char *p, long *v)
{
    int neg = 0;
    long x = 0;
    if (*p == '-')
        neg = 1, p++;
    if (!isdigit((unsigned char)*p))
        return NULL;
    while (isdigit((unsigned char)*p)) {
        if (x < 1000000)
            x = x * 10 + (*p - '0');
        p++;
    }
    *v = neg ? -x : x;
    return p;
}

int pf_type_parse(const char *s, pf_type *t, char *err, size_t errlen)
{
    char shown[96];
    if (!s)
        s = "";
    const char *b = skip_blank(s), *e = b + strlen(b);
    while (e > b && isspace((unsigned char)e[-1]))
        e--;
    quote_input(b, e, shown, sizeof shown);

    const char *p = b;
    size_t n = word_len(p);
    int is_signed = 1, have_sign_word = 0;
    if (word_is(p, n, "float") && p + n == e) {
        *t = pf_type_float();
        return 0;
    }
    if (word_is(p, n, "signed") || word_is(p, n, "unsigned")) {
        is_signed = n == 6;
        have_sign_word = 1;
        p = skip_blank(p + n);
        n = word_len(p);
    }
    if (!word_is(p, n, "fixed") && !(word_is(p, n, "ufixed") && !have_sign_word)) {
        set_err(err, errlen,
                "malformed type '%s': expected float, fixed<size,exp>, signed fixed<size,exp>, "
                "unsigned fixed<size,exp> or ufixed<size,exp>",
                shown);
        return -1;
    }
    if (n == 6)
        is_signed = 0; /* ufixed */
    p = skip_blank(p + n);

    long size = 0, exp = 0;
    if (*p != '<')
        goto malformed;
    p = skip_blank(p + 1);
    if (!(p = parse_int(p, &size)))
        goto malformed;
    p = skip_blank(p);
    if (*p != ',')
        goto malformed;
    p = skip_blank(p + 1);
    if (!(p = parse_int(p, &exp)))
        goto malformed;
    p = skip_blank(p);
    if (*p != '>')
        goto malformed;
    if (p + 1 != e)
        goto malformed; /* trailing junk */

    if (size < 1 || size > PF_TYPE_SIZE_MAX) {
        set_err(err, errlen, "%s: size must be 1..%d", shown, PF_TYPE_SIZE_MAX);
        return -1;
    }
    if (exp < -PF_TYPE_EXP_MAX || exp > PF_TYPE_EXP_MAX) {
        set_err(err, errlen, "%s: exp must be %d..%d", shown, -PF_TYPE_EXP_MAX, PF_TYPE_EXP_MAX);
        return -1;
    }
    *t = pf_type_fixed(is_signed, (int)size, (int)exp);
    return 0;

malformed:
    set_err(err, errlen, "malformed fixed type '%s': expected %sfixed<size,exp>", shown,
            n == 6 ? "u" : have_sign_word ? (is_signed ? "signed " : "unsigned ") : "");
    return -1;
}

void pf_type_format(const pf_type *t, char *buf, size_t n)
{
    if (t->is_float)
        snprintf(buf, n, "float");
    else
        snprintf(buf, n, "%sfixed<%d,%d>", t->is_signed ? "" : "unsigned ", t->size, t->exp);
}

const char *pf_type_ctype(const pf_type *t)
{
    static const char *const name[2][4] = {
        { "uint8_t", "uint16_t", "uint32_t", "uint64_t" },
        { "int8_t", "int16_t", "int32_t", "int64_t" },
    };
    if (t->is_float)
        return "float";
    int i = t->storage_bits <= 8 ? 0 : t->storage_bits <= 16 ? 1 : t->storage_bits <= 32 ? 2 : 3;
    return name[t->is_signed != 0][i];
}

double pf_type_lsb(const pf_type *t)
{
    return t->is_float ? 0.0 : ldexp(1.0, -t->exp);
}

/* (double) of a stored value is one rounding; the power-of-two scaling is
 * exact for the exps we parse */
double pf_type_max(const pf_type *t)
{
    return t->is_float ? FLT_MAX : ldexp((double)pf_type_max_stored(t), -t->exp);
}

double pf_type_min(const pf_type *t)
{
    return t->is_float ? -FLT_MAX : ldexp((double)pf_type_min_stored(t), -t->exp);
}

int64_t pf_type_max_stored(const pf_type *t)
{
    return t->is_float ? 0 : pf_fmt_max_stored(pf_type_to_fmt(t));
}

int64_t pf_type_min_stored(const pf_type *t)
{
    return t->is_float ? 0 : pf_fmt_min_stored(pf_type_to_fmt(t));
}

pf_type pf_type_fixed(int is_signed, int size, int exp)
{
    pf_type t = { 0, is_signed != 0, size, exp, 0 };
    int need = size + t.is_signed;
    t.storage_bits = need <= 8 ? 8 : need <= 16 ? 16 : need <= 32 ? 32 : 64;
    return t;
}

pf_type pf_type_float(void)
{
    pf_type t = { 1, 1, 0, 0, 32 };
    return t;
}

pf_fmt pf_type_to_fmt(const pf_type *t)
{
    return pf_fmt_make(t->is_signed, t->size, t->exp);
}

pf_type pf_type_from_fmt(pf_fmt f)
{
    return pf_type_fixed(f.is_signed, f.size, f.exp);
}
