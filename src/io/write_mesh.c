/* Public writers: tr_mesh_write (from the mesh store) and tr_plc_write (a surface), both
 * through struct tr_mesh_view so that the format writers never see the store. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "format_name.h"
#include "write.h"
#include "core/plc.h"
#include "core/vtmap.h"
#include "delaunay/delaunay.h"
#include "mesh/mesh.h"
#include "output/round.h"

/* Faces written: those of include/tetrec.h's tr_mesh_boundary_faces with their markers
 * for a tr_mesh_plc mesh (input_faces); for other meshes (tr_delaunay's) the boundary
 * faces of the kept tets: a face is written when the tet across it is missing, a ghost,
 * or outside the domain, or belongs to another region, listed as seen from its tet
 * (right-hand normal pointing out of it), marker 1. */
static int keep(const struct tr_mesh *m, uint32_t t)
{
  return tr_tet_is_real(m, t) && !(m->flags && (m->flags[t] & TR_TF_OUTER));
}

/* Which tets are written: kept[t] (one byte per slot), or, when kept is NULL, the slots
 * [0, nk) -- the layout of every store tetrec returns (tr_mesh_plc's compact store; a
 * Delaunay store in canonical order, real tets first, then the ghosts). */
struct selection {
  const uint8_t *kept;
  uint32_t nk;
};
static inline int selected(const struct selection *s, uint32_t t)
{
  return s->kept ? s->kept[t] != 0 : t < s->nk;
}

/* The scans of the store: which slots are kept, and the faces to write. Each is cut into
 * one range of slots per thread (tr_dt_run_jobs), every range collecting into its own list,
 * and the lists are joined in slot order: the serial scan's result for any thread count.
 * On 2.7x10^7 tets the two scans were half the time of writing a binary .msh. */
typedef struct scan {
  const struct tr_mesh *m;
  const struct selection *sel;
  const tr_vtmap *input; /* the input faces (a tr_mesh_plc mesh), or NULL */
  uint32_t t0, t1;
  uint32_t nk, first_out, last_in; /* kept slots; the first slot not kept, the last kept */
  tr_u32buf faces;                 /* 3 vertices a face */
  tr_status st;
} scan;

static void *keep_job(void *arg)
{
  scan *j = arg;
  j->first_out = TR_NONE;
  j->last_in = 0;
  for (uint32_t t = j->t0; t < j->t1; t++)
    if (keep(j->m, t)) {
      j->nk++;
      j->last_in = t;
    } else if (j->first_out == TR_NONE)
      j->first_out = t;
  return NULL;
}

/* A face of a kept tet is written when the tet across it is missing or not kept, or --
 * for a mesh without input faces -- belongs to another region (seen once, from the lower
 * tet); with input faces, those on input triangles are written from the input's list, not
 * here. Listed as seen from its tet (tr_face_vtx order reversed: the normal points out). */
static void *faces_job(void *arg)
{
  scan *j = arg;
  const struct tr_mesh *m = j->m;
  for (uint32_t t = j->t0; t < j->t1 && j->st == TR_OK; t++) {
    if (!selected(j->sel, t))
      continue;
    for (int k = 0; k < 4 && j->st == TR_OK; k++) {
      uint32_t o = TR_NEIG(m, t, k);
      if (o != TR_NONE && selected(j->sel, o) &&
          (j->input || !(m->region && m->region[o] != m->region[t] && o > t)))
        continue;
      uint32_t w[3] = {m->tv[4 * (size_t)t + tr_face_vtx[k][0]],
                       m->tv[4 * (size_t)t + tr_face_vtx[k][2]],
                       m->tv[4 * (size_t)t + tr_face_vtx[k][1]]};
      if (j->input) {
        uint32_t q[3];
        tr_vtkey_face(w[0], w[1], w[2], q);
        if (tr_vtmap_get(j->input, 3, q) != TR_VTMAP_NONE)
          continue;
      }
      for (int i = 0; i < 3 && j->st == TR_OK; i++)
        j->st = tr_u32buf_push(&j->faces, w[i]);
    }
  }
  return NULL;
}

/* Runs fn over the slots of m in up to `threads` ranges (at least 2^16 slots each). */
static int scan_ranges(scan *J, const struct tr_mesh *m, const struct selection *sel,
                       const tr_vtmap *input, int threads, void *(*fn)(void *))
{
  int nth = threads < 1 ? 1 : threads > 64 ? 64 : threads;
  if ((uint32_t)nth > m->nt / 65536 + 1)
    nth = (int)(m->nt / 65536 + 1);
  for (int j = 0; j < nth; j++)
    J[j] = (scan){m, sel, input, (uint32_t)((uint64_t)m->nt * (uint64_t)j / (uint64_t)nth),
                  (uint32_t)((uint64_t)m->nt * (uint64_t)(j + 1) / (uint64_t)nth), 0, 0, 0,
                  {0}, TR_OK};
  tr_dt_run_jobs(fn, J, sizeof *J, nth);
  return nth;
}

/* The faces to write: for a tr_mesh_plc mesh its faces on input triangles with their
 * markers (m->attrs, include/tetrec.h's boundary faces), then any other face on the
 * boundary of the kept tets (the convex hull of an open input meshed with allow_open),
 * marker 0; for any other mesh (tr_delaunay's) the boundary faces, marker 1. */
static tr_status faces(const struct tr_mesh *m, const struct selection *sel, int threads,
                       uint32_t **tris, int32_t **mark, uint32_t *nf)
{
  const struct tr_mesh_attrs *a = m->attrs && m->attrs->faces ? m->attrs : NULL;
  uint32_t n = a ? a->nfaces : 0;
  tr_vtmap key = {0}; /* the input faces, unoriented: a set */
  tr_status st = TR_OK;
  if (a) {
    st = tr_vtmap_reserve(&key, 3, n);
    if (st == TR_OK)
      st = tr_vtmap_filter(&key); /* most boundary faces are input faces, but not all */
    for (uint32_t f = 0; f < n && st == TR_OK; f++) {
      uint32_t q[3];
      tr_vtkey_face(a->faces[3 * (size_t)f], a->faces[3 * (size_t)f + 1],
                    a->faces[3 * (size_t)f + 2], q);
      st = tr_vtmap_put(&key, 3, q, 0, NULL);
    }
  }
  scan J[64];
  int nth = 0;
  if (st == TR_OK)
    nth = scan_ranges(J, m, sel, a ? &key : NULL, threads, faces_job);
  size_t ne = 0;
  for (int j = 0; j < nth; j++) {
    ne += J[j].faces.n / 3;
    if (st == TR_OK)
      st = J[j].st;
  }
  *tris = NULL;
  *mark = NULL;
  if (st == TR_OK && (uint64_t)n + ne > UINT32_MAX / 4)
    st = tr_error(TR_ERR_NOMEM, "%llu faces: too many to write",
                  (unsigned long long)(n + ne));
  if (st == TR_OK) {
    *tris = malloc(sizeof **tris * 3 * (n + ne ? n + ne : 1));
    *mark = malloc(sizeof **mark * (n + ne ? n + ne : 1));
    if (!*tris || !*mark)
      st = tr_error(TR_ERR_NOMEM, "out of memory for %llu faces",
                    (unsigned long long)(n + ne));
  }
  if (st == TR_OK) {
    if (n) {
      memcpy(*tris, a->faces, sizeof **tris * 3 * (size_t)n);
      memcpy(*mark, a->face_marker, sizeof **mark * n);
    }
    size_t at = 3 * (size_t)n;
    for (int j = 0; j < nth; j++) {
      if (J[j].faces.n)
        memcpy(*tris + at, J[j].faces.a, sizeof **tris * J[j].faces.n);
      at += J[j].faces.n;
    }
    for (size_t f = n; f < n + ne; f++)
      (*mark)[f] = a ? 0 : 1;
    *nf = (uint32_t)(n + ne);
  } else {
    free(*tris);
    free(*mark);
    *tris = NULL;
    *mark = NULL;
  }
  for (int j = 0; j < nth; j++)
    tr_u32buf_free(&J[j].faces);
  tr_vtmap_free(&key);
  return st;
}

/* Any vertex with an exact point other than its double. */
static int has_steiner(const struct tr_mesh *m)
{
  for (uint32_t v = 0; m->vq && v < m->nv; v++)
    if (m->vq[v])
      return 1;
  return 0;
}

tr_status tr_mesh_write(const tr_mesh *mesh, const char *path, int exact)
{
  return tr_mesh_write_ex(mesh, path, exact, 41);
}

tr_status tr_mesh_write_ex(const tr_mesh *mesh, const char *path, int exact, int msh_version)
{
  return tr_mesh_write_threads(mesh, path, exact, msh_version, 1);
}

tr_status tr_mesh_write_threads(const tr_mesh *mesh, const char *path, int exact, int flags,
                                int threads)
{
  tr_error_clear();
  const struct tr_mesh *m = mesh;
  if (!m)
    return tr_error(TR_ERR_USAGE, "tr_mesh_write: no mesh");
  TR_CHECK(tr_io_check_out_name(path, 0));
  if (flags & TR_WRITE_BINARY)
    TR_CHECK(tr_io_check_binary_name(path));
  /* A mesh that tr_mesh_plc returned under TR_PIPE_KEEP_EXACT may have tets that are flat
   * or inverted on the doubles: only its exact TetGen output is a valid mesh. Without a
   * Steiner point the doubles are the exact points, on which every tet of a store is
   * positive: nothing to check (on 10^7 tets the check was a second). */
  uint32_t bad;
  if (!(exact && tr_io_out_format(path) == TR_OUT_TETGEN) && has_steiner(m) &&
      tr_round_count_nonpositive(m, &bad) > 0)
    return tr_error(TR_ERR_INVALID_MESH,
                    "%s: tet %u is flat or inverted once its Steiner points are written as "
                    "doubles; only the exact output (--exact, .node) is valid for this mesh",
                    path, bad);
  /* The writers read the tets where they are when the kept ones are the first slots, as
   * in every store tetrec returns: no second copy of the mesh. Otherwise (a store edited
   * since) they get a compact copy. */
  struct selection sel = {NULL, 0};
  scan J[64];
  uint32_t first_out = TR_NONE, last_in = 0;
  int nth = scan_ranges(J, m, &sel, NULL, threads, keep_job);
  for (int j = 0; j < nth; j++) {
    sel.nk += J[j].nk;
    if (J[j].nk && J[j].last_in > last_in)
      last_in = J[j].last_in;
    if (J[j].first_out < first_out)
      first_out = J[j].first_out;
  }
  int prefix = sel.nk == 0 || first_out == TR_NONE || last_in < first_out;
  uint8_t *kept = NULL;
  uint32_t *tets = NULL;
  uint32_t *tris = NULL;
  int32_t *mark = NULL, *reg = NULL;
  tr_status st = TR_OK;
  if (!prefix) {
    kept = malloc(m->nt ? m->nt : 1);
    tets = malloc(sizeof *tets * 4 * (size_t)(sel.nk ? sel.nk : 1));
    reg = m->region ? malloc(sizeof *reg * (sel.nk ? sel.nk : 1)) : NULL;
    if (!kept || !tets || (m->region && !reg))
      st = tr_error(TR_ERR_NOMEM, "out of memory writing %s", path);
    for (uint32_t t = 0, i = 0; t < m->nt && st == TR_OK; t++) {
      if (!(kept[t] = (uint8_t)keep(m, t)))
        continue;
      memcpy(tets + 4 * (size_t)i, m->tv + 4 * (size_t)t, 4 * sizeof *tets);
      if (reg)
        reg[i] = (int32_t)m->region[t];
      i++;
    }
    sel.kept = kept;
  }
  uint32_t nf = 0;
  if (st == TR_OK)
    st = faces(m, &sel, threads, &tris, &mark, &nf);
  if (st == TR_OK) {
    /* region ids are small non-negative numbers stored as uint32_t: the writers print
     * the signed view of the same array (as tr_mesh_tet_regions gives it) */
    struct tr_mesh_view v = {m->nv, m->xyz, (const tr_qpoint *const *)m->vq, sel.nk,
                             prefix ? m->tv : tets,
                             prefix ? (const int32_t *)m->region : reg, nf, tris, mark,
                             threads};
    st = tr_write_mesh_view_as(&v, path, exact, flags);
  }
  free(kept);
  free(tets);
  free(reg);
  free(tris);
  free(mark);
  return st;
}

tr_status tr_plc_write(const tr_plc *plc, const char *path)
{
  return tr_plc_write_ex(plc, path, 41);
}

tr_status tr_plc_write_ex(const tr_plc *plc, const char *path, int msh_version)
{
  return tr_plc_write_threads(plc, path, msh_version, 1);
}

tr_status tr_plc_write_threads(const tr_plc *plc, const char *path, int flags, int threads)
{
  tr_error_clear();
  TR_CHECK(tr_io_check_out_name(path, 1));
  if (flags & TR_WRITE_BINARY)
    TR_CHECK(tr_io_check_binary_name(path));
  struct tr_mesh_view v = {plc->npoints, plc->xyz, NULL, plc->ntets, plc->tets, NULL,
                           plc->ntris, plc->tris, plc->tri_marker, threads};
  return tr_write_mesh_view_as(&v, path, 0, flags);
}
