/* The bulk of a mesh file, formatted in blocks on several threads and written in order
 * (issue 48: writing a mesh of 10^7 tets was mostly number formatting on one core).
 *
 * A writer describes one section of its file (the vertices, the tets, one data array) as
 * n records and a function that formats records [i0, i1) into memory. The records are cut
 * into blocks of TR_IO_BLOCK; each thread takes the next block not taken, formats it into
 * a buffer of its own, waits until every earlier block is written, and writes it. The
 * file is the concatenation of the blocks' bytes in record order, and a block's bytes
 * depend only on its records, so the file is the same byte for byte for any number of
 * threads, and the same as one thread formatting record after record. */
#ifndef TR_IO_BLOCKS_H
#define TR_IO_BLOCKS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "../core/status.h"

/* Records per block: small enough that a mesh of some 20k tets already splits into
 * several blocks (the tests check that the bytes do not depend on the split), large
 * enough that one block is one write of some 100 KiB. */
#define TR_IO_BLOCK 4096u

/* The threads that encode the blocks of the binary writers: one. Encoding binary numbers
 * is so much cheaper than the kernel's copy of the bytes into the page cache that more
 * threads only add the hand-over between them: on a mesh of 2.7x10^7 tets (4x10^6 points,
 * an idle 2-core machine) the 1.2 GB binary .msh took 0.54 s with its blocks on one thread
 * and 0.63 s on two, the 1.4 GB binary .vtu 0.73 and 1.21 s, where every text format took
 * 1.9-2.1 times less time on two threads than on one. (The scans of the store before
 * writing still use every thread: 0.46 s and 0.68 s with two.) */
#define TR_IO_BINARY_THREADS 1

/* Formats records [i0, i1) at out (room for (i1 - i0) * max_bytes bytes, plus 32 bytes
 * of slack a NUL-terminating formatter may use) and returns the end of what it wrote.
 * Called concurrently on distinct ranges: it may only read ctx. */
typedef char *(*tr_io_block_fn)(const void *ctx, uint64_t i0, uint64_t i1, char *out);

/* Writes the n records to f, in order, formatted on up to `threads` threads (0 or 1: the
 * calling thread only; at most 64, and one per block). max_bytes bounds one record's
 * bytes. TR_ERR_NOMEM if the buffers cannot be had (nothing written then); a failed
 * write stays in ferror(f) for the writer's close. */
tr_status tr_io_write_blocks(FILE *f, uint64_t n, size_t max_bytes, tr_io_block_fn fn,
                             const void *ctx, int threads);

#endif
