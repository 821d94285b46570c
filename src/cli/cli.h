/* Internal pieces of the tetrec command. */
#ifndef TR_CLI_H
#define TR_CLI_H

#include <stdio.h>

#include "core/plc.h"
#include "core/status.h"

/* `check`: validator result on the tets of vol, volume compared with surface. */
tr_status tr_cli_check(const struct tr_plc *surface, const struct tr_plc *vol, int verbose);

#endif
