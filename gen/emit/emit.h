/* The emit kit: what the float, fixed-point and noise generators share to
 * write C.  A growable buffer, the templates embedded at build time and
 * their @KEY@ substitution, number literals, and the provenance comment
 * block every emitted file opens with (title, the command that regenerates
 * it, "Label: text" lines, the fit method). */
#ifndef PF_EMIT_H
#define PF_EMIT_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

/* ---- a growable string: {0} is empty; s is NUL-terminated once anything
 * was put (NULL before); malloc failure aborts ---- */
typedef struct {
    char *s;
    size_t n, cap;
} pf_buf;

void pf_putn(pf_buf *b, const char *s, size_t n);
void pf_put(pf_buf *b, const char *s); /* s NULL: nothing */
__attribute__((format(printf, 2, 3))) void pf_printf(pf_buf *b, const char *fmt, ...);
__attribute__((format(printf, 2, 0))) void pf_vprintf(pf_buf *b, const char *fmt, va_list ap);
/* drop one final newline: for a block that goes into a template line
 * which supplies its own */
void pf_chomp(pf_buf *b);

/* ---- templates ---- */

/* the embedded template gen/templates/<name>.in ("sin_pio2_ff.c"), or NULL */
const char *pf_template(const char *name);
/* text with every @KEY@ replaced from kv (key, value pairs, NULL after the
 * last key); an @ that starts no known key is copied as it is */
void pf_subst(pf_buf *b, const char *text, const char *const *kv);

/* ---- literals ---- */

/* C99 hex-float of v ("%a": exact, so a coefficient reads back bit for bit) */
void pf_hexf(char *buf, size_t n, double v);
/* v as a C integer literal: "INT64_C(v)" when int64 is PF_LIT_INT64, or is
 * PF_LIT_INT64_WIDE and |v| > INT32_MAX (int is 32 bits on every target
 * the emitted code is for), else plain */
enum { PF_LIT_PLAIN, PF_LIT_INT64, PF_LIT_INT64_WIDE };
void pf_int_lit(char *buf, size_t n, int64_t v, int int64);

/* ---- the provenance comment block ----
 * Every emitted file opens with one: what it computes and for which types,
 * the exact pfmathgen command that regenerates it, then "Label: text"
 * lines (the reduction, domain, order, method, error bound, sweep...),
 * labels padded to one column. */

/* "/" "* TITLE." and the do-not-edit notice, on the title's line (float
 * files) or on a line of its own (fixed-point and noise files), then a
 * blank comment line and " * Regenerate:  COMMAND" */
enum { PF_NOTICE_SAME_LINE, PF_NOTICE_OWN_LINE };
void pf_prov_begin(pf_buf *b, const char *title, int notice, const char *command);
/* " * Label:      text" on one line; label "" continues the line above */
__attribute__((format(printf, 3, 4))) void pf_prov_line(pf_buf *b, const char *label, const char *fmt, ...);
/* " * Label:      text" wrapped at blanks before column 96, continuation
 * lines indented to the text.  blank_at_break: the blank before a break is
 * kept (trailing blank, the fixed-point files' layout) or dropped (noise) */
void pf_prov_wrap(pf_buf *b, const char *label, const char *text, int blank_at_break);
/* the end of the block, then what integer-only code includes */
void pf_prov_end_int(pf_buf *b);

/* the fit method, for the provenance and the reports:
 * "minimax relative error (nlopt SLSQP, epigraph form, from the
 * least-squares fit), coefficients rounded to ROUNDED_TO by pin-and-refit"
 * or the least-squares (Gauss-Legendre quadrature) equivalent */
const char *pf_method_text(char *buf, size_t n, int minimax, int relative, const char *rounded_to);

#endif
