# import tessera (docs/python.md). The API is tessera._core's, which links no Open CASCADE.
# CAD models (Tessellator.tessellate_cad, tessera.CadMesh) are tessera._cad's, imported at the
# first CAD call: it loads Open CASCADE's libraries and TBB, which a user of .bpt files and
# control points never pays for.
from . import _core
from ._core import (ArgumentError, DeviceError, Error, InputError, LimitError, Mesh, Tessellator,
                    __version__, load_patches, relative_tolerance, tessellate)

__doc__ = _core.__doc__

if _core._has_cad:

    def _cad_module():
        """tessera._cad, imported (Open CASCADE loaded) on the first call."""
        from . import _cad
        return _cad

    def tessellate_cad(self, path, tolerance=0.0, relative_tolerance=0.001,
                       skip_bad_faces=False, expand_instances=True):
        """A STEP, IGES or .brep model meshed watertight at `tolerance` (model units), or when 0
        at `relative_tolerance` of its diagonal: a CadMesh. expand_instances=False leaves an
        assembly's repeated parts in the mesh once, their other places in CadMesh.placements"""
        return _cad_module().tessellate_cad(self, path, tolerance, relative_tolerance,
                                            skip_bad_faces, expand_instances)

    tessellate_cad.__qualname__ = "Tessellator.tessellate_cad"
    Tessellator.tessellate_cad = tessellate_cad
    del tessellate_cad

    _CAD_TYPES = ("CadMesh", "CadPart", "CadPlacement")

    def __getattr__(name):  # PEP 562: tessera.CadMesh without importing Open CASCADE first
        if name in _CAD_TYPES:
            return getattr(_cad_module(), name)
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

    def __dir__():
        return sorted(list(globals()) + list(_CAD_TYPES))
