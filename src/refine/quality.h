/* Shape measures of tets, in doubles: the radius-edge ratio (circumradius / shortest
 * edge; sqrt(6)/4 = 0.612 for the regular tet), the volume and the six dihedral angles.
 * They are measurements (statistics, the refinement's "bad tet" policy), not geometric
 * decisions: no topology depends on their rounding, and doubles are deterministic. */
#ifndef TR_REFINE_QUALITY_H
#define TR_REFINE_QUALITY_H

#include <stdint.h>
#include <stdio.h>

#include "core/plc.h"
#include "mesh/mesh.h"

/* ratio = circumradius / shortest edge (inf for a flat tet), volume = signed volume
 * (positive for a positive tet), dih[6] = dihedral angles in degrees at the edges in
 * ECode order. Returns the circumcentre in cc (may be NULL); 0 if it is not finite. */
int tr_tet_shape(const double *a, const double *b, const double *c, const double *d,
                 double *ratio, double *volume, double dih[6], double cc[3]);

/* The smallest of tr_tet_shape's six dihedral angles (the same double), with one arccosine
 * instead of six: the sliver stage ranks every candidate by it. */
double tr_tet_min_dihedral(const double *a, const double *b, const double *c, const double *d,
                           double *ratio, double *volume);

/* The pieces of tr_tet_min_dihedral for callers that rank many tets: the smallest of the
 * six cosines (the angle is tr_dihedral_of_cos of it, a non-decreasing function, so the
 * smallest cosine of a set of tets gives its smallest angle) and the volume, as
 * tr_tet_shape computes it, without the circumsphere. */
double tr_tet_min_cos(const double *a, const double *b, const double *c, const double *d,
                      double *volume);
double tr_dihedral_of_cos(double lo);
/* A cosine under tr_dihedral_cos_below(d) has tr_dihedral_of_cos under d (-inf for d <= 0:
 * no angle is under it): a test that an angle loses without its arccosine. */
double tr_dihedral_cos_below(double degrees);

#define TR_QUALITY_DIH_BINS 18   /* dihedral angles, 10 degrees each */
#define TR_QUALITY_RATIO_BINS 7  /* radius-edge: <1, <1.414, <2, <4, <10, <100, >=100 */
typedef struct tr_quality {
  uint64_t ntets;
  double min_dihedral, max_dihedral, max_radius_edge; /* degrees, ratio */
  uint64_t below5, below10;   /* tets with a dihedral angle under 5 / 10 degrees */
  uint64_t dihedral_hist[TR_QUALITY_DIH_BINS]; /* all six angles of every tet */
  uint64_t ratio_hist[TR_QUALITY_RATIO_BINS];
} tr_quality;

/* Over the live, real, non-outer tets of m, on m->xyz (the doubles written). */
void tr_quality_measure(const struct tr_mesh *m, tr_quality *q);
/* The tets of tr_quality_measure with a dihedral angle under `degrees`. */
uint64_t tr_quality_count_below(const struct tr_mesh *m, double degrees);
/* Tets under `degrees` standing on thin input triangles (thin.c): an input triangle is
 * thin when its smallest corner is under `corner` degrees and it is a facet of its own
 * (keep_edges: as refinement groups them, facets.h); a tet stands on it when one of its
 * edges is an edge of a boundary face lying in it (m: an output mesh, whose attrs give
 * the boundary faces and their input triangles; m->xyz: the doubles written). */
typedef struct tr_quality_thin {
  uint64_t triangles;      /* thin input triangles */
  uint32_t thinnest;       /* the one with the smallest corner (a triangle of the PLC; the
                              input face it came from is tri_source's), TR_NONE if none */
  uint32_t thinnest_vertex; /* that corner's input vertex */
  double thinnest_angle;   /* that corner, degrees */
  uint64_t below_on_thin;  /* tets under `degrees` on a thin triangle */
} tr_quality_thin;
tr_status tr_quality_thin_input(const struct tr_mesh *m, const struct tr_plc *plc,
                                int keep_edges, double corner, double degrees,
                                tr_quality_thin *out);
/* The thin triangles alone (out->below_on_thin 0); thin (NULL, or plc->ntris flags): 1 for
 * each. tr_facets_thin_triangles: the same with plc's facets already built. */
struct tr_facets;
void tr_facets_thin_triangles(const struct tr_plc *plc, const struct tr_facets *fc,
                              double corner, uint8_t *thin, tr_quality_thin *out);
tr_status tr_plc_thin_triangles(const struct tr_plc *plc, int keep_edges, double corner,
                                uint8_t *thin, tr_quality_thin *out);
/* A short human-readable summary: three lines, each starting with prefix. */
void tr_quality_print(FILE *f, const char *prefix, const tr_quality *q);

#endif
