"""The Python module against the C++ path:
  python3 test_tessera.py <teapot.bpt> <tessera CLI> cad|no-cad [<assembly.step>]

Run by CTest with PYTHONPATH=<build>/python. Exits non-zero on the first failed check."""
import re
import subprocess
import sys
import tempfile

import numpy as np

import tessera

teapot, cli, cad = sys.argv[1], sys.argv[2], sys.argv[3]
assembly = sys.argv[4] if len(sys.argv) > 4 else None  # one part at four places (CTest's)


def occt_libraries(maps):
    """The Open CASCADE (libTK*) and TBB libraries in a /proc/<pid>/maps text."""
    return sorted(set(re.findall(r"/(lib(?:TK\w*|tbb\w*)\.so[.\d]*)$", maps, re.M)))


# `import tessera` and a .bpt file load no Open CASCADE: tessera._cad, which links it, waits for
# the first CAD call. In a fresh interpreter, as a user's script starts.
fresh = subprocess.run(
    [sys.executable, "-c", "import sys, tessera; tessera.Tessellator()"
     ".tessellate(sys.argv[1]); print(sorted(sys.modules)); print(open('/proc/self/maps').read())",
     teapot], check=True, capture_output=True, text=True).stdout
assert "tessera._core" in fresh and "tessera._cad" not in fresh, fresh[:2000]
assert not occt_libraries(fresh), occt_libraries(fresh)

# The file path on the CPU: the triangle and vertex counts the CLI reports for the same work.
t = tessera.Tessellator(device="cpu")
assert t.device_name == "cpu" and not t.uses_vulkan
mesh = t.tessellate(teapot, rule="D", flatness=0.05, linearity=0.05)
n, m = mesh.positions.shape[0], mesh.indices.shape[0]
assert mesh.positions.shape == (n, 3) and mesh.positions.dtype == np.float32
assert mesh.normals.shape == (n, 3) and mesh.normals.dtype == np.float32
assert mesh.uvs.shape == (n, 2) and mesh.uvs.dtype == np.float32
assert mesh.patch_ids.shape == (n,) and mesh.patch_ids.dtype == np.uint32
assert mesh.indices.shape == (m, 3) and mesh.indices.dtype == np.uint32
assert mesh.indices.max() < n and mesh.patch_ids.max() < 32
with tempfile.TemporaryDirectory() as out:
    printed = subprocess.run(
        [cli, "tessellate", teapot, "--backend", "cpu", "-m", "D", "--flatness", "0.05",
         "--linearity", "0.05", "-o", out + "/teapot.ply"],
        check=True, capture_output=True, text=True).stdout
found = re.search(r"triangles (\d+)", printed)
assert found, printed
assert int(found.group(1)) == m, (found.group(1), m)

# The same patches as a numpy array (32, 4, 4, 3): the same mesh, bit for bit.
patches = tessera.load_patches(teapot)
assert len(patches) == 32 and all(w is None for _, w in patches)
points = np.stack([p for p, _ in patches])
assert points.shape == (32, 4, 4, 3)
again = t.tessellate(points, rule="D", flatness=0.05, linearity=0.05)
assert np.array_equal(again.indices, mesh.indices)
assert np.array_equal(again.positions, mesh.positions)

# threads=1 (TessellatorOptions::threads): everything on the calling thread, the same mesh.
one = tessera.Tessellator(device="cpu", threads=1).tessellate(points, rule="D", flatness=0.05,
                                                               linearity=0.05)
assert np.array_equal(one.indices, mesh.indices)
assert np.array_equal(one.positions, mesh.positions)

# Rational control points and a tolerance: more triangles for a tighter one.
weights = np.ones((32, 4, 4))
weights[:, 1, 1] = 2.0
coarse = t.tessellate_to_tolerance(points, 0.05, weights=weights)
fine = t.tessellate_to_tolerance(points, 0.005, weights=weights)
assert 0 < coarse.indices.shape[0] < fine.indices.shape[0]
# Each says what it proved; the split rules prove no distance.
assert fine.proof["proven"] and fine.proof["tolerance"] == 0.005
assert 0.0025 < fine.proof["largest_bound"] <= 0.005
assert mesh.proof is None
# The uniform grids by name: sized by the whole patch's rational bound, they spend more than the
# tree at the same tolerance (31,125 against 4,447 triangles). A relative tolerance is of the
# diagonal of the control points' bounding box (the teapot's box, from the points themselves).
uniform = t.tessellate_to_tolerance(points, 0.05, weights=weights, method="uniform")
assert 0 < coarse.indices.shape[0] < uniform.indices.shape[0]
diagonal = float(np.linalg.norm(points.reshape(-1, 3).max(0) - points.reshape(-1, 3).min(0)))
assert abs(tessera.relative_tolerance(points, 0.001) - 0.001 * diagonal) <= 1e-12 * diagonal

# A CAD model where Tessera has its CAD input (tessera/cad.h): the CLI's triangle count.
assert "tessera._cad" not in sys.modules  # no CAD call yet
assert hasattr(t, "tessellate_cad") == (cad == "cad") == hasattr(tessera, "CadMesh")
if cad == "cad":
    model = "/usr/share/freecad/Mod/Idf/Idflibs/SOT23.stp"
    # Loaded at the first CAD call (hasattr above found CadMesh), and here in this process: the
    # maps check above sees Open CASCADE where it is.
    assert "tessera._cad" in sys.modules
    assert "libTKernel.so" in " ".join(occt_libraries(open("/proc/self/maps").read()))
    part = t.tessellate_cad(model)
    assert isinstance(part, tessera.CadMesh) and repr(part).startswith("<tessera.CadMesh ")
    assert isinstance(part.mesh, tessera.Mesh)
    assert part.faces == part.faces_meshed > 0 and not part.skipped_faces and not part.empty_faces
    assert part.parts == [] and part.placements == []  # one part, placed once
    # Zero-area sliver faces mesh as nothing and are named, no error (docs/cad.md).
    sod = t.tessellate_cad("/usr/share/freecad/Mod/Idf/Idflibs/SOD_323.stp")
    assert (sod.faces, sod.faces_meshed, len(sod.empty_faces)) == (75, 73, 2) and not sod.skipped_faces
    assert "face 15 (#1859 ADVANCED_FACE): zero-area face" in sod.empty_faces[0]
    assert part.triangle_faces.shape == (part.mesh.indices.shape[0],)
    assert part.triangle_faces.dtype == np.uint32 and part.triangle_faces.max() < part.faces
    assert 0 < part.max_deviation <= part.tolerance
    cli_out = subprocess.run([cli, "tessellate", model, "--backend", "cpu"], check=True, capture_output=True,
                             text=True).stdout
    assert re.search(r"triangles %d," % part.mesh.indices.shape[0], cli_out), cli_out
    # On the default device, whose Vulkan context tessera._core made: lavapipe (or the CPU where
    # Vulkan is missing) gives the CPU's mesh bit for bit, another device its count within 1%.
    t_auto = tessera.Tessellator()
    on_auto = t_auto.tessellate_cad(model)
    if not t_auto.uses_vulkan or "llvmpipe" in t_auto.device_name:
        assert np.array_equal(on_auto.mesh.indices, part.mesh.indices)
        assert np.array_equal(on_auto.mesh.positions, part.mesh.positions)
        assert np.array_equal(on_auto.triangle_faces, part.triangle_faces)
    else:
        assert abs(on_auto.mesh.indices.shape[0] - part.mesh.indices.shape[0]) <= \
            0.01 * part.mesh.indices.shape[0]
    finer = t.tessellate_cad(model, tolerance=part.tolerance / 4)
    assert finer.tolerance == part.tolerance / 4
    assert finer.mesh.indices.shape[0] > part.mesh.indices.shape[0]
    # An assembly, its repeated part drawn instanced: the mesh holds it once, and moved by
    # each placement's matrix it is the expanded mesh's copy (docs/api.md, "Assemblies").
    if assembly:
        every = t.tessellate_cad(assembly)
        once = t.tessellate_cad(assembly, expand_instances=False)
        assert len(once.parts) == 1 and len(once.placements) == 3 == len(every.placements)
        assert isinstance(once.parts[0], tessera.CadPart)
        assert isinstance(once.placements[0], tessera.CadPlacement)
        assert (once.faces, once.faces_meshed) == (every.faces, every.faces_meshed)
        assert once.max_deviation == every.max_deviation
        p = once.parts[0]
        m, n = once.mesh.indices.shape[0], once.mesh.positions.shape[0]
        assert np.array_equal(every.mesh.indices[:m], once.mesh.indices)
        assert every.mesh.indices.shape[0] == m + 3 * p.triangle_count
        triangles = once.mesh.indices[p.first_triangle:p.first_triangle + p.triangle_count]
        assert triangles.min() >= p.first_vertex and triangles.max() < p.first_vertex + p.vertex_count
        for k, placed in enumerate(once.placements):
            assert placed.matrix.shape == (4, 4) and np.array_equal(placed.matrix[3], [0, 0, 0, 1])
            turn = placed.matrix[:3, :3]
            assert np.allclose(turn.T @ turn, np.eye(3), atol=1e-12) and np.linalg.det(turn) > 0
            corners = once.mesh.positions[triangles].astype(np.float64)
            moved = corners @ turn.T + placed.matrix[:3, 3]
            copy = every.mesh.indices[m + k * p.triangle_count:m + (k + 1) * p.triangle_count]
            assert np.abs(moved - every.mesh.positions[copy]).max() < 1e-4
            faces = once.triangle_faces[p.first_triangle:p.first_triangle + p.triangle_count]
            copy_faces = every.triangle_faces[m + k * p.triangle_count:m + (k + 1) * p.triangle_count]
            assert np.array_equal(copy_faces, faces - p.first_face + placed.first_face)
        assert n + 3 * p.vertex_count == every.mesh.positions.shape[0]
    try:
        t.tessellate_cad("no_such_model.step")
        raise AssertionError("a missing CAD file was read")
    except tessera.InputError:
        pass

# Typed errors.
for call, error in [
        (lambda: tessera.load_patches("no_such_file.bpt"), tessera.InputError),
        (lambda: t.tessellate(points[:, :, :, :2]), tessera.ArgumentError),
        (lambda: t.tessellate(points, rule="E"), tessera.ArgumentError),
        (lambda: t.tessellate_to_tolerance(points, -1.0), tessera.ArgumentError),
        (lambda: t.tessellate_to_tolerance(points, 0.01, method="best"), tessera.ArgumentError),
        (lambda: tessera.relative_tolerance(points, 1.5), tessera.ArgumentError)]:
    try:
        call()
    except error as e:
        assert isinstance(e, tessera.Error) and isinstance(e, RuntimeError)
    else:
        raise AssertionError(f"expected {error.__name__}")
print(f"python: {m} triangles, {n} vertices, as the CLI; numpy input identical; errors typed")
