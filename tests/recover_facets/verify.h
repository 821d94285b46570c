/* Geometric verification of a decomposition table on one exact configuration (shared by
 * test_tables.c and test_cluster.c). See verify.c for what is checked and why it proves
 * that the new tets tile the old region. */
#ifndef TESTS_RECOVER_FACETS_VERIFY_H
#define TESTS_RECOVER_FACETS_VERIFY_H

#include "core/dectable.h"
#include "qgeom.h"
#include "recover_facets/cluster_tables.h"

typedef struct config {
  qv p[TR_DV_COUNT];
  int npoly;        /* the cut polygon, in cyclic order */
  uint8_t poly[4];
} config;

/* Set while running mutants: failures are expected, verify() prints nothing. */
extern int verify_quiet;

void config_init(config *cf);
void config_clear(config *cf);
/* 0 if the table is valid on cf (and, when dtype != NULL, the faces of old[0] have the
 * S/Z types dtype[] claims); else 1, with a message naming `what` on stderr. */
int verify(const tr_dectable *t, const config *cf, const int8_t *dtype, const char *what);
/* Places H of case c from the other points of cf (the library's rule). 0 on success. */
int place_h(config *cf, const tr_cluster_case *c);

#endif
