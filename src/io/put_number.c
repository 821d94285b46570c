/* Text numbers for the writers (put_number.h).
 *
 * tr_io_fmt_double: printf("%.17g") without printf. The 17 significant digits are the
 * double's exact value m 2^e times 10^k, rounded to an integer half to even, computed in
 * 128-bit integers whenever m 10^k fits (0 <= k <= 22, i.e. magnitudes from about 1e-6
 * to 1e16, which covers the coordinates of real models); any other double goes through
 * snprintf. The text is the same byte for byte as snprintf's, so it reads back to the
 * same double (17 digits always do). glibc's exact conversion was most of the time of
 * writing the vertices. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "put_number.h"

/* u in decimal at p; returns the end. Two digits a step: integers are most of a mesh
 * file's text. The length first, then the digits straight into place from the end (a
 * buffer and a memcpy of variable length were a third of the function). */
static char *put_u64(char *p, uint64_t u)
{
  static const char pairs[201] = "00010203040506070809101112131415161718192021222324252627282930"
                                 "31323334353637383940414243444546474849505152535455565758596061"
                                 "62636465666768697071727374757677787980818283848586878889909192"
                                 "93949596979899";
  int n; /* the number of digits: under 10^8 (every id of a mesh) by comparisons */
  if (u < 10000)
    n = u < 100 ? 1 + (u >= 10) : 3 + (u >= 1000);
  else if (u < 100000000)
    n = u < 1000000 ? 5 + (u >= 100000) : 7 + (u >= 10000000);
  else {
    n = 9;
    for (uint64_t x = u / 100000000; x >= 10; x /= 10)
      n++;
  }
  char *e = p + n, *q = e;
  while (u >= 100) {
    unsigned r = (unsigned)(u % 100);
    u /= 100;
    q -= 2;
    memcpy(q, pairs + 2 * r, 2);
  }
  if (u >= 10) {
    q -= 2;
    memcpy(q, pairs + 2 * u, 2);
  } else {
    *--q = (char)('0' + u);
  }
  return e;
}

char *tr_io_fmt_ints(char *p, const int64_t *x, int n)
{
  for (int i = 0; i < n; i++) {
    if (i)
      *p++ = ' ';
    if (x[i] < 0)
      *p++ = '-';
    p = put_u64(p, x[i] < 0 ? 0 - (uint64_t)x[i] : (uint64_t)x[i]);
  }
  *p++ = '\n';
  return p;
}

void tr_io_put_ints(FILE *f, const int64_t *x, int n)
{
  char line[TR_IO_INT_MAX * 8];
  char *e = tr_io_fmt_ints(line, x, n < 8 ? n : 8);
  fwrite(line, 1, (size_t)(e - line), f);
}

#ifdef __SIZEOF_INT128__
typedef unsigned __int128 u128;

/* floor(x 10^k) and round(x 10^k) (half to even) for x = m 2^-s (m < 2^53); 0 if they
 * do not fit. */
static int scaled(uint64_t m, int s, int k, uint64_t *fl, uint64_t *q)
{
  static const uint64_t p10[20] = {1ull, 10ull, 100ull, 1000ull, 10000ull, 100000ull,
                                   1000000ull, 10000000ull, 100000000ull, 1000000000ull,
                                   10000000000ull, 100000000000ull, 1000000000000ull,
                                   10000000000000ull, 100000000000000ull,
                                   1000000000000000ull, 10000000000000000ull,
                                   100000000000000000ull, 1000000000000000000ull,
                                   10000000000000000000ull};
  if (k < 0 || k > 22 || s < 1 || s > 127)
    return 0;
  /* 10^k = 10^min(k,19) * 10^(k-19): m 10^k < 2^53 2^73.1 < 2^127 */
  u128 p = (u128)m * p10[k < 19 ? k : 19];
  if (k > 19)
    p *= p10[k - 19];
  u128 qq = p >> s, r = p & (((u128)1 << s) - 1), half = (u128)1 << (s - 1);
  if (qq >> 63)
    return 0;
  *fl = (uint64_t)qq;
  *q = (uint64_t)qq + (r > half || (r == half && (qq & 1)));
  return 1;
}

/* The 17 digits and the decimal exponent X of |x| (x = d0.d1...d16 10^X), 0 if the
 * fast path does not apply. */
static int digits17(double x, char d[17], int *X)
{
  int e2;
  double f = frexp(x, &e2); /* x = f 2^e2, 0.5 <= f < 1 */
  uint64_t m = (uint64_t)ldexp(f, 53);
  int s = 53 - e2;          /* x = m 2^-s */
  /* E = floor(log10 x) estimated, then corrected on the exact value: 10^16 <= x 10^k
   * < 10^17 before rounding; rounding may then carry to 10^17, i.e. 1.000... 10^(E+1) */
  int k = 16 - (int)floor(log10(x));
  uint64_t fl = 0, q = 0;
  const uint64_t lo = 10000000000000000ull, hi = 100000000000000000ull;
  for (int tries = 0; tries < 4; tries++) {
    if (!scaled(m, s, k, &fl, &q))
      return 0;
    if (fl >= hi)
      k--;
    else if (fl < lo)
      k++;
    else {
      if (q == hi) {
        q = lo;
        k--;
      }
      for (int i = 16; i >= 0; i--, q /= 10)
        d[i] = (char)('0' + q % 10);
      *X = 16 - k;
      return 1;
    }
  }
  return 0;
}
#endif

int tr_io_fmt_double(char *out, double x)
{
#ifdef __SIZEOF_INT128__
  char d[17];
  int X;
  if (isfinite(x) && x != 0 && digits17(fabs(x), d, &X)) {
    char *p = out;
    if (x < 0)
      *p++ = '-';
    int nd = 17;
    while (nd > 1 && d[nd - 1] == '0')
      nd--; /* %g drops trailing zeros */
    if (X < -4 || X >= 17) {
      *p++ = d[0];
      if (nd > 1) {
        *p++ = '.';
        memcpy(p, d + 1, (size_t)nd - 1);
        p += nd - 1;
      }
      *p++ = 'e';
      *p++ = X < 0 ? '-' : '+';
      int a = X < 0 ? -X : X;
      if (a >= 100)
        *p++ = (char)('0' + a / 100);
      *p++ = (char)('0' + a / 10 % 10);
      *p++ = (char)('0' + a % 10);
    } else if (X >= 0) {
      for (int i = 0; i <= X; i++)
        *p++ = d[i];
      if (nd > X + 1) {
        *p++ = '.';
        memcpy(p, d + X + 1, (size_t)(nd - X - 1));
        p += nd - X - 1;
      }
    } else {
      *p++ = '0';
      *p++ = '.';
      for (int i = 0; i < -X - 1; i++)
        *p++ = '0';
      memcpy(p, d, (size_t)nd);
      p += nd;
    }
    *p = '\0';
    return (int)(p - out);
  }
#endif
  return snprintf(out, 32, "%.17g", x);
}

char *tr_io_fmt_xyz(char *p, int64_t lead, const double x[3], const char *tail)
{
  if (lead >= 0) {
    p = put_u64(p, (uint64_t)lead);
    *p++ = ' ';
  }
  for (int i = 0; i < 3; i++) {
    if (i)
      *p++ = ' ';
    p += tr_io_fmt_double(p, x[i]);
  }
  size_t n = strlen(tail);
  if (n > 16)
    n = 16;
  memcpy(p, tail, n);
  return p + n;
}

void tr_io_put_xyz(FILE *f, int64_t lead, const double x[3], const char *tail)
{
  char line[TR_IO_XYZ_MAX + 8]; /* + 8: tr_io_fmt_double may NUL-terminate past the end */
  char *e = tr_io_fmt_xyz(line, lead, x, tail);
  fwrite(line, 1, (size_t)(e - line), f);
}
