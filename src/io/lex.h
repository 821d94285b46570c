/* A small tokenizer shared by the text readers. It works on a memory buffer (the file
 * readers load the whole file; the fuzzers pass their input directly), tracks line
 * numbers for messages, and parses numbers exactly: strtod is correctly rounded, and
 * nothing goes through float. NaN and infinities are rejected with file:line. */
#ifndef TR_IO_LEX_H
#define TR_IO_LEX_H

#include <stddef.h>
#include <stdint.h>

#include "../core/status.h"

typedef struct tr_lex {
  const char *p, *end;   /* unread part of the buffer */
  const char *name;      /* file name for messages */
  unsigned long line;    /* line of p (1-based) */
  char comment;          /* comment character ('#') or 0 */
  const char *tok;       /* last token read */
  size_t toklen;
  unsigned long tokline;
} tr_lex;

void tr_lex_init(tr_lex *lx, const char *buf, size_t len, const char *name, char comment);
/* Reads the next token; 0 at end of input. */
int tr_lex_next(tr_lex *lx);
/* Skips blanks and a comment on the current line; 1 iff the line (or input) ends. */
int tr_lex_at_eol(tr_lex *lx);
/* Discards the rest of the current line. */
void tr_lex_skip_line(tr_lex *lx);
/* 1 iff the last token equals word, ignoring ASCII case. */
int tr_lex_is(const tr_lex *lx, const char *word);
/* Bytes not yet read: used to bound untrusted counts before allocating. */
static inline size_t tr_lex_left(const tr_lex *lx) { return (size_t)(lx->end - lx->p); }

/* Each reads the next token and converts it; `what` names the item for messages. */
tr_status tr_lex_double(tr_lex *lx, const char *what, double *out);
tr_status tr_lex_u64(tr_lex *lx, const char *what, uint64_t *out);
tr_status tr_lex_i64(tr_lex *lx, const char *what, int64_t *out);
/* Converts the current token (already read). */
tr_status tr_lex_tok_double(tr_lex *lx, const char *what, double *out);
tr_status tr_lex_tok_i64(tr_lex *lx, const char *what, int64_t *out);
/* Error "name:line: unexpected end of file while reading <what>". */
tr_status tr_lex_eof(const tr_lex *lx, const char *what);

/* Checks an untrusted element count against the bytes left, assuming each element takes
 * at least min_bytes; the error names both figures. */
tr_status tr_check_room(const char *name, unsigned long line, uint64_t count, const char *what,
                        size_t bytes_left, size_t min_bytes, uint32_t limit);

/* Exact text-to-double: the whole string must be a finite number. 0 on success, -1 if it
 * is not a number, -2 if it is NaN/Inf or overflows. */
int tr_parse_double(const char *s, size_t len, double *out);

#endif
