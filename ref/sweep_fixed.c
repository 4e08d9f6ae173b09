/* Fixed-point error sweeps (see sweep_fixed.h). */
#include "sweep_fixed.h"

#include "pfref_impl.h"

#include <stdlib.h>
#ifdef _OPENMP
#include <omp.h>
#endif

/* ---- typed calls: one wrapper per (input, output) storage pair ---- */

typedef void (*arr_call)(void *fn, const int64_t *x, int64_t *y, size_t n, int inplace);
typedef int64_t (*sc_call)(void *fn, int64_t x);

/* in place: the output buffer is the input's, read as IT and written as OT
   (called so only when the two have one size; int16_t and uint16_t, int32_t
   and uint32_t may alias each other) */
#define BLK 256
#define PAIR(in, IT, out, OT)                                                                 \
    static void arr_##in##_##out(void *fn, const int64_t *x, int64_t *y, size_t n, int inplace) \
    {                                                                                         \
        void (*f)(const IT *, OT *, size_t);                                                  \
        *(void **)&f = fn;                                                                    \
        union {                                                                               \
            IT i[BLK];                                                                        \
            OT o[BLK];                                                                        \
        } b;                                                                                  \
        OT by[BLK], *o = inplace ? b.o : by;                                                  \
        for (size_t i = 0; i < n; i += BLK) {                                                 \
            size_t m = n - i < BLK ? n - i : BLK;                                             \
            for (size_t j = 0; j < m; j++)                                                    \
                b.i[j] = (IT)x[i + j];                                                        \
            f(b.i, o, m);                                                                     \
            for (size_t j = 0; j < m; j++)                                                    \
                y[i + j] = (int64_t)o[j];                                                     \
        }                                                                                     \
    }                                                                                         \
    static int64_t sc_##in##_##out(void *fn, int64_t x)                                       \
    {                                                                                         \
        OT (*f)(IT);                                                                          \
        *(void **)&f = fn;                                                                    \
        return (int64_t)f((IT)x);                                                             \
    }
#define OUTS(in, IT)                                                                          \
    PAIR(in, IT, i8, int8_t) PAIR(in, IT, u8, uint8_t) PAIR(in, IT, i16, int16_t)             \
    PAIR(in, IT, u16, uint16_t) PAIR(in, IT, i32, int32_t) PAIR(in, IT, u32, uint32_t)
OUTS(i8, int8_t)
OUTS(u8, uint8_t)
OUTS(i16, int16_t)
OUTS(u16, uint16_t)
OUTS(i32, int32_t)
OUTS(u32, uint32_t)

#define ROW(in) {arr_##in##_i8, arr_##in##_u8, arr_##in##_i16, arr_##in##_u16, arr_##in##_i32, arr_##in##_u32}
static const arr_call arr_tab[6][6] = {ROW(i8), ROW(u8), ROW(i16), ROW(u16), ROW(i32), ROW(u32)};
#undef ROW
#define ROW(in) {sc_##in##_i8, sc_##in##_u8, sc_##in##_i16, sc_##in##_u16, sc_##in##_i32, sc_##in##_u32}
static const sc_call sc_tab[6][6] = {ROW(i8), ROW(u8), ROW(i16), ROW(u16), ROW(i32), ROW(u32)};
#undef ROW

static int st_index(pf_fmt f)
{
    int b = pf_fmt_storage_bits(f);
    return (b == 8 ? 0 : b == 16 ? 2 : 4) + !f.is_signed;
}

int pf_fx_fn_supported(pf_fmt in, pf_fmt out)
{
    return pf_fmt_storage_bits(in) <= 32 && pf_fmt_storage_bits(out) <= 32;
}

void pf_fx_call_array(const pf_fx_fn *fn, const int64_t *x, int64_t *y, size_t n)
{
    if (fn->array) {
        arr_tab[st_index(fn->in)][st_index(fn->out)](fn->array, x, y, n, 0);
        return;
    }
    for (size_t i = 0; i < n; i++)
        y[i] = pf_fx_call_scalar(fn, x[i]);
}

int pf_fx_call_array_inplace(const pf_fx_fn *fn, const int64_t *x, int64_t *y, size_t n)
{
    if (!fn->array || pf_fmt_storage_bits(fn->in) != pf_fmt_storage_bits(fn->out))
        return 0;
    arr_tab[st_index(fn->in)][st_index(fn->out)](fn->array, x, y, n, 1);
    return 1;
}

int64_t pf_fx_call_scalar(const pf_fx_fn *fn, int64_t x)
{
    return sc_tab[st_index(fn->in)][st_index(fn->out)](fn->scalar, x);
}

/* ---- reference ---- */

/* Margin, in output LSBs, past which an exact result is taken to be outside
   the output range.  The glibc estimate is within 2^-43 relative, i.e. below
   2^-11 LSB for results under 2^32 LSB; results nearer the range's end are
   measured against the unclamped value, which can only overstate the error
   (by less than the margin). */
#define SAT_MARGIN 1e-3

typedef struct {
    int defined;      /* reference is a defined value (log x <= 0, sqrt x <= 0) or saturated */
    int64_t ref;      /* that value, stored */
    double scaled;    /* else: estimate of f(x) * 2^out.exp */
} fx_ref;

static fx_ref reference(pf_func f, pf_fmt in, pf_fmt out, int64_t x)
{
    fx_ref r = {0, 0, 0};
    int64_t mx = pf_fmt_max_stored(out), mn = pf_fmt_min_stored(out);
    if ((f == PF_LOG || f == PF_LOG2) && x <= 0) {
        r.defined = 1;
        r.ref = mn;
        return r;
    }
    if (f == PF_SQRT && x <= 0) {
        r.defined = 1;
        r.ref = 0;
        return r;
    }
    double xv = ldexp((double)x, -in.exp); /* exact: |x| < 2^32 */
    double d = pfref__glibc(f, xv, 0);
    double sc = ldexp(d, out.exp);
    if (sc > (double)mx + SAT_MARGIN) {
        r.defined = 1;
        r.ref = mx;
    } else if (sc < (double)mn - SAT_MARGIN) {
        r.defined = 1;
        r.ref = mn;
    }
    r.scaled = sc;
    return r;
}

/* Errors this close to 0.5 or 1 LSB, or to the fast allowance, are decided
   by pfref_lsb_err (MPFR when needed); elsewhere the glibc estimate already
   in hand is within 2^-11 LSB (|f| 2^out.exp < 2^32, see pfref_lsb_err),
   which saves a second evaluation per input. */
#define NEAR 0x1p-10

static double allow_of(pf_fmt out, const fx_ref *r);

static double err_of(pf_func f, pf_fmt in, pf_fmt out, int64_t x, int64_t y, const fx_ref *r)
{
    if (r->defined)
        return fabs((double)(y - r->ref));
    if (fabs(r->scaled) < 0x1p32) {
        double e = fabs((double)y - r->scaled);
        double a = allow_of(out, r);
        if (fabs(e - 0.5) > NEAR && fabs(e - 1.0) > NEAR && fabs(e - a) > NEAR * a)
            return e;
    }
    double e = pfref_lsb_err(f, y, out.exp, ldexp((double)x, -in.exp), 0);
    return isnan(e) ? INFINITY : e;
}

static double allow_of(pf_fmt out, const fx_ref *r)
{
    double v = r->defined ? (double)r->ref : r->scaled;
    double mx = (double)pf_fmt_max_stored(out), mn = (double)pf_fmt_min_stored(out);
    v = v > mx ? mx : v < mn ? mn : v;
    double a = 0x1p-10 * fabs(v);
    return a > 4 ? a : 4;
}

int pf_fx_saturates(pf_func f, pf_fmt in, pf_fmt out, int64_t x)
{
    return reference(f, in, out, x).defined;
}

double pf_fx_err(pf_func f, pf_fmt in, pf_fmt out, int64_t x, int64_t y)
{
    fx_ref r = reference(f, in, out, x);
    return err_of(f, in, out, x, y, &r);
}

double pf_fx_fast_allow(pf_func f, pf_fmt in, pf_fmt out, int64_t x)
{
    fx_ref r = reference(f, in, out, x);
    return allow_of(out, &r);
}

/* ---- statistics ---- */

static const char *const bin_label[PF_FX_HIST_BINS] = {"[0, 0.5]", "(0.5, 0.75]", "(0.75, 1)", "[1, 2)",
                                                      "[2, 4]",   "(4, 16]",     "> 16"};

const char *pf_fx_bin_label(int i) { return i >= 0 && i < PF_FX_HIST_BINS ? bin_label[i] : "?"; }

static int bin_of(double e)
{
    if (e <= 0.5)
        return 0;
    if (e <= 0.75)
        return 1;
    if (e < 1.0)
        return 2;
    if (e < 2.0)
        return 3;
    if (e <= 4.0)
        return 4;
    if (e <= 16.0)
        return 5;
    return 6;
}

void pf_fx_stats_init(pf_fx_stats *s)
{
    memset(s, 0, sizeof *s);
    s->max_err = -1;
    s->max_ratio = -1;
}

void pf_fx_stats_merge(pf_fx_stats *into, const pf_fx_stats *from)
{
    if (!from->count)
        return;
    if (from->max_err > into->max_err) {
        into->max_err = from->max_err;
        into->worst_x = from->worst_x;
        into->worst_y = from->worst_y;
    }
    if (from->max_ratio > into->max_ratio) {
        into->max_ratio = from->max_ratio;
        into->worst_ratio_x = from->worst_ratio_x;
    }
    into->count += from->count;
    into->sum_err += from->sum_err;
    into->over_fast += from->over_fast;
    into->saturated += from->saturated;
    into->mismatch += from->mismatch;
    for (int i = 0; i < PF_FX_HIST_BINS; i++)
        into->hist[i] += from->hist[i];
}

void pf_fx_stats_add(pf_fx_stats *s, pf_func f, pf_fmt in, pf_fmt out, int64_t x, int64_t y)
{
    fx_ref r = reference(f, in, out, x);
    double e = err_of(f, in, out, x, y, &r);
    double ratio = e / allow_of(out, &r);
    s->count++;
    s->sum_err += e;
    s->saturated += (uint64_t)r.defined;
    s->hist[bin_of(e)]++;
    if (e > s->max_err) {
        s->max_err = e;
        s->worst_x = x;
        s->worst_y = y;
    }
    if (ratio > s->max_ratio) {
        s->max_ratio = ratio;
        s->worst_ratio_x = x;
    }
    s->over_fast += (uint64_t)(ratio > 1);
}

double pf_fx_mean(const pf_fx_stats *s) { return s->count ? s->sum_err / (double)s->count : 0; }

/* ---- sweeps ---- */

#define CHUNK 65536

static void sweep_chunk(pf_fx_stats *s, pf_func f, const pf_fx_fn *fn, const int64_t *x, size_t n,
                        int check_scalar)
{
    int64_t *y = malloc(sizeof(int64_t) * n);
    if (!y)
        abort();
    pf_fx_call_array(fn, x, y, n);
    for (size_t i = 0; i < n; i++) {
        pf_fx_stats_add(s, f, fn->in, fn->out, x[i], y[i]);
        if (check_scalar && pf_fx_call_scalar(fn, x[i]) != y[i])
            s->mismatch++;
    }
    free(y);
}

void pf_fx_sweep_range(pf_fx_stats *s, pf_func f, const pf_fx_fn *fn, int64_t lo, int64_t hi,
                       int check_scalar, int progress)
{
    if (hi < lo)
        return;
    uint64_t total = (uint64_t)(hi - lo) + 1;
    uint64_t nch = (total + CHUNK - 1) / CHUNK;
    pf_fx_stats *cs = malloc(sizeof *cs * nch);
    if (!cs)
        abort();
    uint64_t done = 0;
#pragma omp parallel
    {
        int64_t *x = malloc(sizeof(int64_t) * CHUNK);
        if (!x)
            abort();
#pragma omp for schedule(dynamic, 1)
        for (uint64_t c = 0; c < nch; c++) {
            int64_t a = lo + (int64_t)(c * CHUNK);
            size_t n = (size_t)(total - c * CHUNK < CHUNK ? total - c * CHUNK : CHUNK);
            for (size_t i = 0; i < n; i++)
                x[i] = a + (int64_t)i;
            pf_fx_stats_init(&cs[c]);
            sweep_chunk(&cs[c], f, fn, x, n, check_scalar);
            if (progress) {
#pragma omp critical(pf_fx_progress)
                {
                    done++;
                    if (done % 256 == 0 || done == nch)
                        fprintf(stderr, "\r  %5.1f%%", 100.0 * (double)done / (double)nch);
                }
            }
        }
        free(x);
    }
    if (progress)
        fputc('\n', stderr);
    for (uint64_t c = 0; c < nch; c++)
        pf_fx_stats_merge(s, &cs[c]);
    free(cs);
}

static uint64_t splitmix(uint64_t *st)
{
    uint64_t z = (*st += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

void pf_fx_sweep_random(pf_fx_stats *s, pf_func f, const pf_fx_fn *fn, uint64_t seed, uint64_t n)
{
    int64_t lo = pf_fmt_min_stored(fn->in), hi = pf_fmt_max_stored(fn->in);
    uint64_t span = (uint64_t)(hi - lo) + 1;
    uint64_t nch = (n + CHUNK - 1) / CHUNK;
    pf_fx_stats *cs = malloc(sizeof *cs * (nch + 1));
    if (!cs)
        abort();
#pragma omp parallel
    {
        int64_t *x = malloc(sizeof(int64_t) * CHUNK);
        if (!x)
            abort();
#pragma omp for schedule(dynamic, 1)
        for (uint64_t c = 0; c < nch; c++) {
            uint64_t st = seed ^ (c * 0xd1b54a32d192ed03ull);
            size_t m = (size_t)(n - c * CHUNK < CHUNK ? n - c * CHUNK : CHUNK);
            for (size_t i = 0; i < m; i++)
                x[i] = lo + (int64_t)(splitmix(&st) % span);
            pf_fx_stats_init(&cs[c]);
            sweep_chunk(&cs[c], f, fn, x, m, 1);
        }
        free(x);
    }
    /* the ends of the range and the values around 0 */
    int64_t ends[] = {lo, lo + 1, hi - 1, hi, -1, 0, 1, 2};
    int64_t e2[8];
    size_t ne = 0;
    for (size_t i = 0; i < 8; i++)
        if (ends[i] >= lo && ends[i] <= hi)
            e2[ne++] = ends[i];
    pf_fx_stats_init(&cs[nch]);
    sweep_chunk(&cs[nch], f, fn, e2, ne, 1);
    for (uint64_t c = 0; c <= nch; c++)
        pf_fx_stats_merge(s, &cs[c]);
    free(cs);
}

void pf_fx_stats_print(FILE *o, const char *title, pf_func f, pf_fmt in, pf_fmt out, const pf_fx_stats *s,
                       int fast)
{
    fprintf(o, "%s\n", title);
    fprintf(o, "  inputs      %llu (%llu with a saturated or defined result)\n", (unsigned long long)s->count,
            (unsigned long long)s->saturated);
    fprintf(o, "  max error   %.6f LSB at x = %lld (%.10g) -> %lld (%.10g); exact %s(x) = %.10g\n", s->max_err,
            (long long)s->worst_x, ldexp((double)s->worst_x, -in.exp), (long long)s->worst_y,
            ldexp((double)s->worst_y, -out.exp), pfref_name(f), pfref_exact_dd(f, ldexp((double)s->worst_x, -in.exp), 0));
    fprintf(o, "  mean error  %.6f LSB\n", pf_fx_mean(s));
    fprintf(o, "  histogram  ");
    for (int i = 0; i < PF_FX_HIST_BINS; i++)
        fprintf(o, " %s: %llu%s", bin_label[i], (unsigned long long)s->hist[i], i + 1 < PF_FX_HIST_BINS ? "," : "\n");
    fprintf(o, "  fast bound  max(2^-10 relative, 4 LSB): max %.4f of it at x = %lld, %llu inputs over%s\n",
            s->max_ratio, (long long)s->worst_ratio_x, (unsigned long long)s->over_fast,
            fast ? "" : " (informational: exact variant)");
    if (s->mismatch)
        fprintf(o, "  MISMATCH    scalar and array forms differ on %llu inputs\n", (unsigned long long)s->mismatch);
    fprintf(o, "TOTAL max_lsb=%.6f mean_lsb=%.6f worst=%lld count=%llu over_fast=%llu mismatch=%llu\n", s->max_err,
            pf_fx_mean(s), (long long)s->worst_x, (unsigned long long)s->count, (unsigned long long)s->over_fast,
            (unsigned long long)s->mismatch);
}
