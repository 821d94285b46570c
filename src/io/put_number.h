/* Number formatting for the writers, text and binary, in one module that depends on
 * nothing else in src/io (the parallel writer of issue 48 formats blocks of numbers into
 * memory buffers with these too).
 *
 * Text: integers in decimal and doubles as printf("%.17g") writes them, byte for byte, but
 * without printf's format parsing and glibc's exact conversion, which were most of the
 * time of writing a mesh. Binary: fixed-width little-endian (and, for legacy VTK,
 * big-endian) encodings, built byte by byte so that the files are the same on any host. */
#ifndef TR_IO_PUT_NUMBER_H
#define TR_IO_PUT_NUMBER_H

#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* One line of n (at most 8) integers in decimal, separated by single spaces, then '\n'. */
void tr_io_put_ints(FILE *f, const int64_t *x, int n);
/* x as printf("%.17g") writes it, byte for byte (so it reads back to the same double),
 * into out (at least 32 bytes), NUL-terminated; returns the length. */
int tr_io_fmt_double(char *out, double x);
/* "lead x y z" then tail (at most 16 bytes; lead < 0: none): the doubles as %.17g. */
void tr_io_put_xyz(FILE *f, int64_t lead, const double x[3], const char *tail);

/* The same lines into memory, for the block writers (blocks.h): each writes at p, without
 * a NUL, and returns the end. At most TR_IO_INT_MAX bytes per integer (its separator
 * included) and TR_IO_XYZ_MAX bytes per xyz line. Any n. */
#define TR_IO_INT_MAX 21
#define TR_IO_XYZ_MAX (TR_IO_INT_MAX + 3 * 25 + 16)
char *tr_io_fmt_ints(char *p, const int64_t *x, int n);
char *tr_io_fmt_xyz(char *p, int64_t lead, const double x[3], const char *tail);

/* Little-endian encodings into p; each returns p advanced past what it wrote. */
static inline unsigned char *tr_le16(unsigned char *p, uint16_t x)
{
  p[0] = (unsigned char)x;
  p[1] = (unsigned char)(x >> 8);
  return p + 2;
}
static inline unsigned char *tr_le32(unsigned char *p, uint32_t x)
{
  for (int i = 0; i < 4; i++)
    p[i] = (unsigned char)(x >> (8 * i));
  return p + 4;
}
static inline unsigned char *tr_le64(unsigned char *p, uint64_t x)
{
  for (int i = 0; i < 8; i++)
    p[i] = (unsigned char)(x >> (8 * i));
  return p + 8;
}
static inline unsigned char *tr_le_f64(unsigned char *p, double x)
{
  uint64_t u;
  memcpy(&u, &x, 8);
  return tr_le64(p, u);
}
static inline unsigned char *tr_le_f32(unsigned char *p, float x)
{
  uint32_t u;
  memcpy(&u, &x, 4);
  return tr_le32(p, u);
}

/* Big-endian, for legacy VTK, whose binary form is big-endian by definition. */
static inline unsigned char *tr_be32(unsigned char *p, uint32_t x)
{
  for (int i = 0; i < 4; i++)
    p[i] = (unsigned char)(x >> (24 - 8 * i));
  return p + 4;
}
static inline unsigned char *tr_be_f64(unsigned char *p, double x)
{
  uint64_t u;
  memcpy(&u, &x, 8);
  for (int i = 0; i < 8; i++)
    p[i] = (unsigned char)(u >> (56 - 8 * i));
  return p + 8;
}

/* The little-endian decodings, for the binary readers. */
static inline uint32_t tr_get_le32(const unsigned char *p)
{
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}
static inline uint64_t tr_get_le64(const unsigned char *p)
{
  return (uint64_t)tr_get_le32(p) | (uint64_t)tr_get_le32(p + 4) << 32;
}
static inline double tr_get_le_f64(const unsigned char *p)
{
  uint64_t u = tr_get_le64(p);
  double x;
  memcpy(&x, &u, 8);
  return x;
}
static inline float tr_get_le_f32(const unsigned char *p)
{
  uint32_t u = tr_get_le32(p);
  float x;
  memcpy(&x, &u, 4);
  return x;
}

#endif
