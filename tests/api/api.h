/* Shared by the tests of the public API (test_api.c, api_cases.c, api_doubles.c): the
 * counting check (tests/pipeline/texpect.h, one counter for the three files),
 * the inputs and the validated meshing every case starts from. */
#ifndef TR_TESTS_API_H
#define TR_TESTS_API_H

#include <gmp.h>
#include <stdio.h>

#include "core/plc.h"
#include "mesh/mesh.h"
#include "tetrec.h"

#define TEXPECT_SHARED_COUNTER /* test_api.c defines it */
#include "../pipeline/texpect.h"

/* SOURCE_ROOT-relative file -> path (one static buffer). */
const char *api_src(const char *rel);
tr_plc *read_plc(const char *rel);
/* A 2x1x1 box cut by the internal square x = 1 into two regions, markers 100 + index. */
tr_plc *two_region_box(void);
/* A case of tests/hard/hard_cases.c as a PLC (NULL if it does not exist). */
tr_plc *hard_plc(const char *name);
tr_options quiet(void);
/* tr_mesh_plc_ex plus both validators; *used = the PLC as meshed. */
tr_mesh *mesh_checked(const tr_plc *p, const char *name, tr_plc **used);
int cmp_key(const void *a, const void *b);

/* api_cases.c */
void t_writers(const char *tmp);
void t_writers_open(const char *tmp);
void t_progress(void);
void t_progress_refinement(void);
void t_abi_size(void);
void t_stage_times(void);
void t_version(const char *want);
/* api_doubles.c */
void t_strict_doubles(void);

#endif
