/* CGAL's sample surfaces end to end: every data/meshes/NAME.off that tr_plc_validate accepts
 * (closed, manifold, not self-intersecting) and has at most MAXTRIS triangles is meshed
 * and checked with tr_check_mesh and tr_check_conformity. Prints one table row per model.
 * usage: test_models DIR MAXTRIS(0 = all) [BUDGET_SECONDS(0 = none) [STATS_DIR|- [keep]]]
 * With STATS_DIR, each model's Table 14 statistics go to STATS_DIR/NAME.json. With
 * `keep`, models are meshed with tr_options.keep_surface and the output's boundary faces
 * must be exactly the input triangles (tests/suppress/keepcheck.h). The Steiner columns:
 * points added by recovery, then the points left on input edges / facets / inside.
 * The selection depends only on the files (sorted names, triangle counts); the budget is
 * a safety stop that fails the test rather than silently testing fewer models. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"
#include "../suppress/keepcheck.h"

static int cmp_str(const void *a, const void *b)
{
  return strcmp(*(char *const *)a, *(char *const *)b);
}

int main(int argc, char **argv)
{
  if (argc < 3) {
    fprintf(stderr, "usage: %s DIR MAXTRIS [BUDGET_SECONDS]\n", argv[0]);
    return 2;
  }
  const char *dir = argv[1];
  unsigned long maxtris = strtoul(argv[2], NULL, 10);
  double budget = argc > 3 ? atof(argv[3]) : 0;
  const char *statsdir = argc > 4 && strcmp(argv[4], "-") ? argv[4] : NULL;
  int keep = argc > 5 && !strcmp(argv[5], "keep");
  if (argc > 5 && !keep) {
    fprintf(stderr, "unknown mode '%s' (only 'keep')\n", argv[5]);
    return 2;
  }
  uint64_t tot_e = 0, tot_f = 0, tot_i = 0, tot_add = 0;
  DIR *d = opendir(dir);
  if (!d) {
    fprintf(stderr, "cannot open %s: skipping\n", dir);
    return 77;
  }
  char **names = NULL;
  size_t n = 0, cap = 0;
  struct dirent *e;
  while ((e = readdir(d))) {
    size_t l = strlen(e->d_name);
    if (l < 5 || strcmp(e->d_name + l - 4, ".off"))
      continue;
    if (n == cap) {
      cap = cap ? 2 * cap : 64;
      names = realloc(names, cap * sizeof *names);
    }
    names[n++] = strdup(e->d_name);
  }
  closedir(d);
  qsort(names, n, sizeof *names, cmp_str);
  int bad = 0, meshed = 0, rejected = 0, skipped = 0;
  double t0 = tr_pipeline_now();
  printf("%-34s %8s %8s %8s %14s %9s %8s %s\n", "model", "points", "tris", "steiner",
         "left_e/f/i", "tets", "time_s", "valid");
  for (size_t i = 0; i < n; i++) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, names[i]);
    tr_plc *p = NULL;
    tr_status s = tr_plc_read(path, &p);
    /* the size filter uses the file's triangle count (before validation), so big models
     * are not even validated */
    if (s == TR_OK && maxtris && p->ntris > maxtris) {
      skipped++;
      tr_plc_destroy(p);
      continue;
    }
    if (s == TR_OK)
      s = tr_plc_validate(p, NULL);
    if (s != TR_OK) {
      rejected++;
      tr_plc_destroy(p);
      continue;
    }
    if (budget > 0 && tr_pipeline_now() - t0 > budget) {
      printf("%-34s budget of %.0f s exhausted before this model\n", names[i], budget);
      bad++;
      tr_plc_destroy(p);
      break;
    }
    tr_options opt;
    tr_options_default(&opt);
    opt.verbose = 0;
    opt.keep_surface = keep;
    tr_mesh *m = NULL;
    tr_plc *used = NULL;
    tr_stats st;
    memset(&st, 0, sizeof st);
    s = tr_mesh_plc_ex(p, &opt, &m, &st, &used);
    const char *verdict = "yes";
    char why[512] = "";
    if (s != TR_OK) {
      verdict = "FAILED";
      snprintf(why, sizeof why, "%s: %s", tr_status_name(s), tr_last_error());
    } else if ((s = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL)) !=
               TR_OK) {
      verdict = "INVALID";
      snprintf(why, sizeof why, "mesh: %s", tr_last_error());
    } else if ((s = tr_check_conformity(m, used, NULL, 0)) != TR_OK) {
      verdict = "NONCONFORM";
      snprintf(why, sizeof why, "%s", tr_last_error());
    } else if (keep && keep_surface_holds(m, used, why, sizeof why) != 0) {
      verdict = "SURFACE";
      s = TR_ERR_INVALID_MESH;
    }
    if (statsdir && m) {
      char jp[4096];
      snprintf(jp, sizeof jp, "%s/%s.json", statsdir, names[i]);
      if (tr_stats_write_json(&st, jp) != TR_OK)
        fprintf(stderr, "%s\n", tr_last_error());
    }
    meshed++;
    if (s != TR_OK)
      bad++;
    char left[64];
    snprintf(left, sizeof left, "%llu/%llu/%llu", (unsigned long long)st.steiner_on_edges,
             (unsigned long long)st.steiner_on_facets, (unsigned long long)st.steiner_interior);
    tot_e += st.steiner_on_edges;
    tot_f += st.steiner_on_facets;
    tot_i += st.steiner_interior;
    tot_add += st.points_added_for_edges + st.points_added_for_facets;
    printf("%-34s %8u %8u %8llu %14s %9llu %8.3f %s %s\n", names[i], p->npoints, p->ntris,
           (unsigned long long)(st.points_added_for_edges + st.points_added_for_facets), left,
           (unsigned long long)st.volume_elements, st.total_seconds, verdict, why);
    fflush(stdout);
    tr_mesh_destroy(m);
    tr_plc_destroy(used);
    tr_plc_destroy(p);
  }
  printf("Steiner points: %llu added by recovery; left %llu on input edges, %llu on input "
         "facets, %llu inside\n",
         (unsigned long long)tot_add, (unsigned long long)tot_e, (unsigned long long)tot_f,
         (unsigned long long)tot_i);
  printf("%d meshed, %d failed, %d rejected by validation, %d over %lu triangles\n", meshed,
         bad, rejected, skipped, maxtris);
  for (size_t i = 0; i < n; i++)
    free(names[i]);
  free(names);
  return bad ? 1 : 0;
}
