/* The caller's tr_options as this build knows them (ABI growth, include/tetrec.h). */
#ifndef TR_INPUT_OPTIONS_H
#define TR_INPUT_OPTIONS_H

#include "tetrec.h"

/* *opt = the defaults overwritten by the first in->size bytes of *in (all of them when
 * in->size is 0 or larger than this build's struct); in NULL: the defaults. */
void tr_options_read(const tr_options *in, tr_options *opt);

#endif
