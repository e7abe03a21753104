"""Writes the truck's other formats from CesiumMilkTruck.glb, as trimesh writes them.

    pip install trimesh==5.* pillow && python derive.py

truck.obj, truck.mtl and truck.png (OBJ with MTL and its texture: the textured parts,
body and wheels; with the untextured glass and trim as well, trimesh 5 numbers texture
coordinates as if every part had them, past the last one defined), truck.stl (binary
STL, every part) and truck-colours.ply (binary PLY, every part, each vertex's colour
taken from the texture). The files are committed; this script says how they were made.
"""

import trimesh

scene = trimesh.load("CesiumMilkTruck.glb")
textured = trimesh.Scene(
    [g for g in scene.dump() if getattr(g.visual, "uv", None) is not None]
)
text, files = trimesh.exchange.obj.export_obj(
    textured, include_texture=True, return_texture=True, mtl_name="truck.mtl"
)
with open("truck.obj", "w") as f:
    f.write(text)
for name, data in files.items():
    with open(name, "wb") as f:
        f.write(data)
mesh = scene.to_geometry()
mesh.export("truck.stl")
coloured = mesh.copy()
coloured.visual = mesh.visual.to_color()
coloured.export("truck-colours.ply")
