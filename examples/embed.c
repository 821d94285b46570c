/* Embedding tetrec through its public header only: read a surface, tetrahedralize its
 * points with tr_delaunay, print the counts. Usage: embed FILE.off */
#include <stdio.h>

#include "tetrec.h"

int main(int argc, char **argv)
{
  if (argc != 2) {
    fprintf(stderr, "usage: %s SURFACE (.off .stl .obj .ply .mesh .poly ...)\n", argv[0]);
    return TR_ERR_USAGE;
  }
  tr_plc *plc = NULL;
  tr_status s = tr_plc_read(argv[1], &plc);
  if (s != TR_OK) {
    fprintf(stderr, "%s: %s\n", tr_status_name(s), tr_last_error());
    return (int)s;
  }
  tr_mesh *mesh = NULL;
  s = tr_delaunay(tr_plc_points(plc), tr_plc_num_points(plc), &mesh);
  if (s != TR_OK) {
    fprintf(stderr, "%s: %s\n", tr_status_name(s), tr_last_error());
    tr_plc_destroy(plc);
    return (int)s;
  }
  printf("%u points, %u triangles -> %u vertices, %u tetrahedra\n", tr_plc_num_points(plc),
         tr_plc_num_triangles(plc), tr_mesh_num_vertices(mesh), tr_mesh_num_tets(mesh));
  tr_mesh_destroy(mesh);
  tr_plc_destroy(plc);
  return 0;
}
