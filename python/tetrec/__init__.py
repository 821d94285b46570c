"""tetrec: exact conformal boundary recovery for 3D Delaunay tetrahedralization.

    import tetrec
    surface = tetrec.read("model.off")
    mesh = tetrec.tetrahedralize(surface.points, surface.triangles, markers=surface.markers)
    mesh.write("model.vtu")

Every tet is positively oriented (det[v1-v0, v2-v0, v3-v0] > 0); every input vertex,
edge and triangle is in the mesh. Failures raise tetrec.Error with .status (the C
library's tr_status name, e.g. "TR_ERR_OPEN") and .message.
"""
from ._tetrec import C_VERSION, SUPPORTED_OPTIONS, Error, status_name
from ._mesh import Mesh, Surface, read, tetrahedralize, validate

__version__ = C_VERSION
__all__ = ["Error", "Mesh", "Surface", "read", "tetrahedralize", "validate", "status_name",
           "SUPPORTED_OPTIONS", "__version__"]
