# The example of docs/python.md, run by CTest: tessellate the teapot from its file and from
# numpy control points, and print what a user would look at.
#   PYTHONPATH=build/python python3 examples/python/teapot.py data/teapot.bpt
import sys
import numpy as np
import tessera

path = sys.argv[1] if len(sys.argv) > 1 else "data/teapot.bpt"
t = tessera.Tessellator()                                    # "auto": Vulkan if usable, else CPU
mesh = t.tessellate(path, rule="D", flatness=0.05, linearity=0.05)
print(mesh, "on", t.device_name)
print("bounding box", mesh.positions.min(axis=0), mesh.positions.max(axis=0))
points = np.stack([p for p, w in tessera.load_patches(path)])  # (32, 4, 4, 3)
close = t.tessellate_to_tolerance(points, 0.001)
print("within 0.001:", close)
assert mesh.indices.shape[1] == 3 and close.indices.max() < len(close.positions)
