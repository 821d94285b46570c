/* Defaults of tr_options (include/tetrec.h): the CLI and tr_plc_validate start here. */
#include <string.h>

#include "options.h"

void tr_options_default(tr_options *opt)
{
  memset(opt, 0, sizeof *opt);
  opt->size = sizeof *opt;
  opt->smooth = 1;
  opt->allow_open = 0;
  opt->verbose = 1;
  opt->optimize = 3;
  opt->refine_spacing_radii = 1;
}

void tr_options_read(const tr_options *in, tr_options *opt)
{
  tr_options_default(opt);
  if (!in)
    return;
  size_t n = in->size == 0 || in->size > sizeof *opt ? sizeof *opt : in->size;
  memcpy(opt, in, n);
  opt->size = sizeof *opt;
}
