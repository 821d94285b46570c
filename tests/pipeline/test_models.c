/* CGAL's sample surfaces end to end: every data/meshes/NAME.off that tr_plc_validate accepts
 * (closed, manifold, not self-intersecting) and has at most MAXTRIS triangles is meshed
 * and checked with tr_check_mesh and tr_check_conformity. Prints one table row per model.
 * usage: test_models DIR MAXTRIS(0 = all) [BUDGET_SECONDS(0 = none) [STATS_DIR]]
 * With STATS_DIR, each model's Table 14 statistics go to STATS_DIR/NAME.json.
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
  printf("%-34s %8s %8s %8s %9s %8s %s\n", "model", "points", "tris", "steiner", "tets",
         "time_s", "valid");
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
    }
    if (argc > 4 && m) {
      char jp[4096];
      snprintf(jp, sizeof jp, "%s/%s.json", argv[4], names[i]);
      if (tr_stats_write_json(&st, jp) != TR_OK)
        fprintf(stderr, "%s\n", tr_last_error());
    }
    meshed++;
    if (s != TR_OK)
      bad++;
    printf("%-34s %8u %8u %8llu %9llu %8.3f %s %s\n", names[i], p->npoints, p->ntris,
           (unsigned long long)(st.points_added_for_edges + st.points_added_for_facets),
           (unsigned long long)st.volume_elements, st.total_seconds, verdict, why);
    fflush(stdout);
    tr_mesh_destroy(m);
    tr_plc_destroy(used);
    tr_plc_destroy(p);
  }
  printf("%d meshed, %d failed, %d rejected by validation, %d over %lu triangles\n", meshed,
         bad, rejected, skipped, maxtris);
  for (size_t i = 0; i < n; i++)
    free(names[i]);
  free(names);
  return bad ? 1 : 0;
}
