/* Embedding tetrec through its public header only: read a surface, mesh it, walk the
 * result through the accessors (points, tets, regions, faces on input triangles with
 * their markers, vertex origins, exact points).
 *
 * Usage: embed SURFACE [MESH]
 * With MESH (the .mesh file `tetrec mesh SURFACE -o MESH` wrote), also checks that the
 * arrays are exactly what the file says: same doubles, tets, regions, triangles and
 * triangle references. tests/api/install_embed.sh builds this file against the installed
 * library with `pkg-config --cflags --libs tetrec` and runs it that way. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tetrec.h"

static int fail(tr_status s)
{
  fprintf(stderr, "%s: %s\n", tr_status_name(s), tr_last_error());
  return (int)s;
}

/* Reads the next whitespace-separated token of a Medit file into buf[64]. */
static int token(FILE *f, char buf[64])
{
  return fscanf(f, " %63s", buf) == 1;
}

/* Compares the mesh with a Medit file section by section; the number of differences. */
static int compare_medit(const tr_mesh *m, const char *path)
{
  FILE *f = fopen(path, "r");
  if (!f) {
    fprintf(stderr, "%s: cannot open\n", path);
    return 1;
  }
  int bad = 0;
  char tok[64];
  const double *x = tr_mesh_points(m);
  const uint32_t *tv = tr_mesh_tets(m), *bf = tr_mesh_boundary_faces(m);
  const int32_t *reg = tr_mesh_tet_regions(m), *mk = tr_mesh_boundary_markers(m);
  int sections = 0;
  while (token(f, tok) && strcmp(tok, "End") != 0) {
    unsigned long n = 0;
    if (!strcmp(tok, "MeshVersionFormatted") || !strcmp(tok, "Dimension")) {
      if (!token(f, tok))
        bad++;
      continue;
    }
    if (fscanf(f, "%lu", &n) != 1) {
      fprintf(stderr, "%s: no count after %s\n", path, tok);
      bad++;
      break;
    }
    if (!strcmp(tok, "Vertices")) {
      sections++;
      if (n != tr_mesh_num_vertices(m)) {
        fprintf(stderr, "%lu vertices in the file, %u in the mesh\n", n, tr_mesh_num_vertices(m));
        bad++;
        break;
      }
      for (unsigned long i = 0; i < n; i++) {
        char c[3][64];
        long ref;
        if (fscanf(f, " %63s %63s %63s %ld", c[0], c[1], c[2], &ref) != 4) {
          bad++;
          break;
        }
        for (int k = 0; k < 3; k++)
          if (strtod(c[k], NULL) != x[3 * i + k]) { /* %.17g reads back exactly */
            fprintf(stderr, "vertex %lu coordinate %d: %s in the file, %.17g here\n", i, k,
                    c[k], x[3 * i + k]);
            bad++;
          }
      }
    } else if (!strcmp(tok, "Tetrahedra") || !strcmp(tok, "Triangles")) {
      int tets = tok[1] == 'e';
      sections++;
      uint32_t want = tets ? tr_mesh_num_tets(m) : tr_mesh_num_boundary_faces(m);
      if (n != want) {
        fprintf(stderr, "%lu %s in the file, %u in the mesh\n", n, tok, want);
        bad++;
        break;
      }
      int per = tets ? 4 : 3;
      for (unsigned long i = 0; i < n; i++) {
        long v[5];
        for (int k = 0; k <= per; k++)
          if (fscanf(f, "%ld", &v[k]) != 1)
            v[k] = -1;
        const uint32_t *e = tets ? tv + 4 * i : bf + 3 * i;
        long ref = tets ? reg[i] : mk[i];
        for (int k = 0; k < per; k++)
          bad += v[k] != (long)e[k] + 1;
        bad += v[per] != ref;
        if (bad && i < 3)
          fprintf(stderr, "%s %lu differs\n", tok, i);
      }
    } else {
      fprintf(stderr, "%s: unexpected section %s\n", path, tok);
      bad++;
      break;
    }
  }
  fclose(f);
  if (sections != 3) {
    fprintf(stderr, "%s: %d of the 3 sections found\n", path, sections);
    bad++;
  }
  return bad;
}

int main(int argc, char **argv)
{
  if (argc != 2 && argc != 3) {
    fprintf(stderr, "usage: %s SURFACE [MESH]\n", argv[0]);
    return TR_ERR_USAGE;
  }
  int major, minor, patch;
  tr_version(&major, &minor, &patch);
  printf("tetrec %d.%d.%d (header %s)\n", major, minor, patch, TETREC_VERSION_STRING);
  tr_plc *plc = NULL;
  tr_status s = tr_plc_read(argv[1], &plc);
  if (s != TR_OK)
    return fail(s);
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  tr_stats stats = {.size = sizeof stats};
  tr_mesh *mesh = NULL;
  s = tr_mesh_plc(plc, &opt, &mesh, &stats);
  tr_plc_destroy(plc);
  if (s != TR_OK)
    return fail(s);
  uint32_t nv = tr_mesh_num_vertices(mesh), nsteiner = 0;
  for (uint32_t v = 0; v < nv; v++) {
    int kind;
    uint32_t index;
    if (tr_mesh_vertex_origin(mesh, v, &kind, &index) == TR_OK && kind != TR_VERTEX_INPUT) {
      char *xyz = NULL;
      if (tr_mesh_point_exact(mesh, v, &xyz) == TR_OK)
        printf("Steiner point %u (%s %u): %s\n", v,
               kind == TR_VERTEX_ON_EDGE       ? "on input edge"
               : kind == TR_VERTEX_ON_TRIANGLE ? "on input triangle"
                                               : "interior",
               index, xyz);
      tr_free(xyz);
      nsteiner++;
    }
  }
  printf("%u vertices (%u Steiner points), %u tetrahedra, %u faces on input triangles\n", nv,
         nsteiner, tr_mesh_num_tets(mesh), tr_mesh_num_boundary_faces(mesh));
  for (int k = 0; k < TR_STAGE_COUNT; k++)
    if (stats.stage_seconds[k] > 0)
      printf("  %-18s %.6f s\n", tr_stage_name(k), stats.stage_seconds[k]);
  int bad = argc == 3 ? compare_medit(mesh, argv[2]) : 0;
  if (argc == 3)
    printf("%s: %s\n", argv[2], bad ? "DIFFERS from the accessors" : "same as the accessors");
  tr_mesh_destroy(mesh);
  return bad ? 1 : 0;
}
