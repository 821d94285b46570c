// Interop: a surface held in an OpenMesh TriMesh goes into tetrec through tr_plc_set,
// is validated, and its points are tetrahedralized. Usage: openmesh_in FILE (any format
// OpenMesh reads: .off .obj .stl .ply ...).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cstdio>
#include <vector>

#include "tetrec.h"

typedef OpenMesh::TriMesh_ArrayKernelT<> Mesh;

int main(int argc, char **argv)
{
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s SURFACE\n", argv[0]);
    return TR_ERR_USAGE;
  }
  Mesh om;
  if (!OpenMesh::IO::read_mesh(om, argv[1])) {
    std::fprintf(stderr, "OpenMesh cannot read %s\n", argv[1]);
    return TR_ERR_IO;
  }
  std::vector<double> xyz(3 * om.n_vertices());
  std::vector<uint32_t> tris(3 * om.n_faces());
  size_t i = 0;
  for (Mesh::VertexIter v = om.vertices_begin(); v != om.vertices_end(); ++v) {
    Mesh::Point p = om.point(*v);  // OpenMesh's default point is float: widening is exact
    for (int k = 0; k < 3; k++)
      xyz[i++] = (double)p[k];
  }
  i = 0;
  for (Mesh::FaceIter f = om.faces_begin(); f != om.faces_end(); ++f)
    for (Mesh::FaceVertexIter fv = om.fv_iter(*f); fv.is_valid() && i < tris.size(); ++fv)
      tris[i++] = (uint32_t)fv->idx();
  tr_plc *plc = NULL;
  tr_status s = tr_plc_create(&plc);
  if (s == TR_OK)
    s = tr_plc_set(plc, xyz.data(), (uint32_t)om.n_vertices(), tris.data(),
                   (uint32_t)om.n_faces(), NULL);
  if (s == TR_OK)
    s = tr_plc_validate(plc, NULL);
  tr_mesh *mesh = NULL;
  if (s == TR_OK)
    s = tr_delaunay(tr_plc_points(plc), tr_plc_num_points(plc), &mesh);
  if (s != TR_OK) {
    std::fprintf(stderr, "%s: %s\n", tr_status_name(s), tr_last_error());
    tr_plc_destroy(plc);
    return (int)s;
  }
  std::printf("OpenMesh: %zu vertices, %zu faces -> %u tetrahedra\n", (size_t)om.n_vertices(),
              (size_t)om.n_faces(), tr_mesh_num_tets(mesh));
  tr_mesh_destroy(mesh);
  tr_plc_destroy(plc);
  return 0;
}
