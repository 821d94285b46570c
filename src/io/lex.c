#include "lex.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void tr_lex_init(tr_lex *lx, const char *buf, size_t len, const char *name, char comment)
{
  lx->p = buf;
  lx->end = buf + len;
  lx->name = name ? name : "<buffer>";
  lx->line = 1;
  lx->comment = comment;
  lx->tok = buf;
  lx->toklen = 0;
  lx->tokline = 1;
}

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
static int is_space(char c) { return is_blank(c) || c == '\n'; }

static void skip_comment(tr_lex *lx)
{
  while (lx->p < lx->end && *lx->p != '\n')
    lx->p++;
}

int tr_lex_next(tr_lex *lx)
{
  for (;;) {
    while (lx->p < lx->end && is_space(*lx->p)) {
      if (*lx->p == '\n')
        lx->line++;
      lx->p++;
    }
    if (lx->p >= lx->end)
      return 0;
    if (lx->comment && *lx->p == lx->comment) {
      skip_comment(lx);
      continue;
    }
    break;
  }
  lx->tok = lx->p;
  lx->tokline = lx->line;
  /* A NUL byte ends a token too, so binary garbage cannot make strtod read past it. */
  while (lx->p < lx->end && !is_space(*lx->p) && *lx->p != '\0' &&
         !(lx->comment && *lx->p == lx->comment))
    lx->p++;
  if (lx->p == lx->tok) /* a lone NUL: make it a one-byte token so progress is made */
    lx->p++;
  lx->toklen = (size_t)(lx->p - lx->tok);
  return 1;
}

int tr_lex_at_eol(tr_lex *lx)
{
  while (lx->p < lx->end && is_blank(*lx->p))
    lx->p++;
  if (lx->p < lx->end && lx->comment && *lx->p == lx->comment)
    skip_comment(lx);
  return lx->p >= lx->end || *lx->p == '\n';
}

void tr_lex_skip_line(tr_lex *lx)
{
  skip_comment(lx);
  if (lx->p < lx->end) {
    lx->p++;
    lx->line++;
  }
}

int tr_lex_is(const tr_lex *lx, const char *word)
{
  size_t n = strlen(word);
  if (n != lx->toklen)
    return 0;
  for (size_t i = 0; i < n; i++) {
    char a = lx->tok[i], b = word[i];
    if (a >= 'A' && a <= 'Z')
      a = (char)(a - 'A' + 'a');
    if (b >= 'A' && b <= 'Z')
      b = (char)(b - 'A' + 'a');
    if (a != b)
      return 0;
  }
  return 1;
}

tr_status tr_lex_eof(const tr_lex *lx, const char *what)
{
  return tr_error(TR_ERR_PARSE, "%s:%lu: unexpected end of file while reading %s", lx->name,
                  lx->line, what);
}

/* Two fast paths before strtod, each giving the double strtod gives (the correctly
 * rounded value of the decimal), for tokens [+-]digits[.digits][(e|E)[+-]digits] of at
 * most 19 digits, whose integer m is exact in 64 bits. strtod was most of reading. */
enum { LEX_FAST_DIGITS = 19 };

/* Clinger's: m <= 2^53 and |e| <= 22 make m and 10^e exact doubles, and m * 10^e or
 * m / 10^-e one IEEE operation: rounded once, to nearest. Needs operations rounded to
 * double itself (not x87's extended precision, which would round twice). */
static int fast_double(uint64_t m, int e, double *v)
{
#if defined(FLT_EVAL_METHOD) && FLT_EVAL_METHOD == 0
  static const double p10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                 1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  if (m > (UINT64_C(1) << 53) || e < -22 || e > 22)
    return 0;
  *v = e >= 0 ? (double)m * p10[e] : (double)m / p10[-e];
  return 1;
#else
  (void)m, (void)e, (void)v;
  return 0;
#endif
}

/* The 17 significant digits that %.17g writes (m > 2^53) on x87's 64-bit significand:
 * m < 2^64 and 10^e for |e| <= 27 (5^27 < 2^63) are exact, so q = m * 10^e or m / 10^-e
 * is the decimal rounded once to 64 bits. Rounding q to double gives the decimal's
 * double unless q is a midpoint between two doubles (its 11 bits below the double's 53
 * are 10000000000): the midpoints are 64-bit numbers, so the decimal lies strictly
 * between the same two midpoints as q. Only where long double ops round to 64 bits (the
 * precision control can be lowered, and valgrind emulates 53 bits: checked each call). */
static int wide_double(uint64_t m, int e, double *v)
{
#if (defined(__x86_64__) || defined(__i386__)) && LDBL_MANT_DIG == 64
  static const long double p10[28] = {
      1e0L,  1e1L,  1e2L,  1e3L,  1e4L,  1e5L,  1e6L,  1e7L,  1e8L,  1e9L,
      1e10L, 1e11L, 1e12L, 1e13L, 1e14L, 1e15L, 1e16L, 1e17L, 1e18L, 1e19L,
      1e20L, 1e21L, 1e22L, 1e23L, 1e24L, 1e25L, 1e26L, 1e27L};
  volatile long double one = 1, tiny = 0x1p-63L;
  if (one + tiny == one || e < -27 || e > 27) /* rounding to fewer than 64 bits */
    return 0;
  long double q = e >= 0 ? (long double)m * p10[e] : (long double)m / p10[-e];
  uint64_t sig;
  memcpy(&sig, &q, sizeof sig); /* x87 extended: the 64-bit significand comes first */
  if ((sig & 0x7ff) == 0x400)
    return 0;
  *v = (double)q;
  return 1;
#else
  (void)m, (void)e, (void)v;
  return 0;
#endif
}

/* Returns 0 when the token is not of the fast form (strtod decides it). */
static int parse_fast(const char *s, size_t len, double *out)
{
  size_t i = 0;
  int neg = 0;
  if (i < len && (s[i] == '-' || s[i] == '+'))
    neg = s[i++] == '-';
  uint64_t m = 0;
  int digits = 0, frac = 0;
  for (; i < len && s[i] >= '0' && s[i] <= '9'; i++, digits++)
    m = m * 10 + (uint64_t)(s[i] - '0');
  if (i < len && s[i] == '.')
    for (i++; i < len && s[i] >= '0' && s[i] <= '9'; i++, digits++, frac++)
      m = m * 10 + (uint64_t)(s[i] - '0');
  if (digits == 0 || digits > LEX_FAST_DIGITS) /* 19 digits cannot overflow m */
    return 0;
  int e = 0;
  if (i < len && (s[i] == 'e' || s[i] == 'E')) {
    int eneg = 0, ed = 0;
    i++;
    if (i < len && (s[i] == '-' || s[i] == '+'))
      eneg = s[i++] == '-';
    for (; i < len && s[i] >= '0' && s[i] <= '9' && ed < 4; i++, ed++)
      e = e * 10 + (s[i] - '0');
    if (ed == 0)
      return 0;
    e = eneg ? -e : e;
  }
  if (i != len)
    return 0;
  e -= frac;
  double v;
  if (!fast_double(m, e, &v) && !wide_double(m, e, &v))
    return 0;
  *out = neg ? -v : v;
  return 1;
}

int tr_parse_double(const char *s, size_t len, double *out)
{
  if (parse_fast(s, len, out))
    return 0;
  char buf[512];
  if (len == 0 || len >= sizeof buf)
    return -1;
  memcpy(buf, s, len);
  buf[len] = '\0';
  /* strtod would accept "nan", "inf" and "infinity": catch them by the result below. */
  char *endp;
  errno = 0;
  double v = strtod(buf, &endp);
  if (endp != buf + len)
    return -1;
  if (!isfinite(v))
    return -2;
  if (errno == ERANGE && (v == HUGE_VAL || v == -HUGE_VAL))
    return -2;
  /* Underflow to a subnormal or zero is a correctly rounded result: keep it. */
  *out = v;
  return 0;
}

tr_status tr_lex_tok_double(tr_lex *lx, const char *what, double *out)
{
  int r = tr_parse_double(lx->tok, lx->toklen, out);
  if (r == -2)
    return tr_error(TR_ERR_INPUT, "%s:%lu: %s '%.*s' is not a finite number (NaN/Inf rejected)",
                    lx->name, lx->tokline, what, (int)(lx->toklen > 40 ? 40 : lx->toklen),
                    lx->tok);
  if (r != 0)
    return tr_error(TR_ERR_PARSE, "%s:%lu: expected a number for %s, found '%.*s'", lx->name,
                    lx->tokline, what, (int)(lx->toklen > 40 ? 40 : lx->toklen), lx->tok);
  return TR_OK;
}

tr_status tr_lex_double(tr_lex *lx, const char *what, double *out)
{
  if (!tr_lex_next(lx))
    return tr_lex_eof(lx, what);
  return tr_lex_tok_double(lx, what, out);
}

tr_status tr_lex_tok_i64(tr_lex *lx, const char *what, int64_t *out)
{
  const char *s = lx->tok;
  size_t n = lx->toklen, i = 0;
  int neg = 0;
  if (n > 0 && (s[0] == '-' || s[0] == '+')) {
    neg = s[0] == '-';
    i = 1;
  }
  if (i == n)
    goto bad;
  uint64_t v = 0;
  for (; i < n; i++) {
    if (s[i] < '0' || s[i] > '9')
      goto bad;
    if (v > (UINT64_C(1) << 62))
      return tr_error(TR_ERR_INPUT, "%s:%lu: %s '%.*s' is out of range", lx->name, lx->tokline,
                      what, (int)(n > 40 ? 40 : n), s);
    v = v * 10 + (uint64_t)(s[i] - '0');
  }
  *out = neg ? -(int64_t)v : (int64_t)v;
  return TR_OK;
bad:
  return tr_error(TR_ERR_PARSE, "%s:%lu: expected an integer for %s, found '%.*s'", lx->name,
                  lx->tokline, what, (int)(n > 40 ? 40 : n), s);
}

tr_status tr_lex_i64(tr_lex *lx, const char *what, int64_t *out)
{
  if (!tr_lex_next(lx))
    return tr_lex_eof(lx, what);
  return tr_lex_tok_i64(lx, what, out);
}

tr_status tr_lex_u64(tr_lex *lx, const char *what, uint64_t *out)
{
  int64_t v;
  TR_CHECK(tr_lex_i64(lx, what, &v));
  if (v < 0)
    return tr_error(TR_ERR_INPUT, "%s:%lu: %s must not be negative (found %lld)", lx->name,
                    lx->tokline, what, (long long)v);
  *out = (uint64_t)v;
  return TR_OK;
}

tr_status tr_check_room(const char *name, unsigned long line, uint64_t count, const char *what,
                        size_t bytes_left, size_t min_bytes, uint32_t limit)
{
  uint64_t room = min_bytes ? (uint64_t)(bytes_left + 1) / min_bytes : UINT64_MAX;
  if (count > room)
    return tr_error(TR_ERR_PARSE,
                    "%s:%lu: header declares %llu %s but the file has room for at most %llu",
                    name, line, (unsigned long long)count, what, (unsigned long long)room);
  if (count > limit)
    return tr_error(TR_ERR_NOMEM, "%s:%lu: %llu %s exceed the limit of %lu", name, line,
                    (unsigned long long)count, what, (unsigned long)limit);
  return TR_OK;
}
