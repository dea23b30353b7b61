"""The OBJ reader of the project's Python tools (standard library only): scripts/render_mesh.py, scripts/pictures.py
and tests/data/bs_make_meshes.py read the meshes bin/confsurf writes (v and triangular f lines) with it."""
import sys


def read_obj(path, triangles_only=False):
    """Vertices [[x, y, z], ...] and 0-based faces [[i, j, k], ...]; with triangles_only a face of more than three
    corners ends the program with a message naming the file (the renderers draw triangles only)."""
    verts, faces = [], []
    with open(path) as fh:
        for line in fh:
            s = line.split()
            if not s:
                continue
            if s[0] == "v":
                verts.append([float(x) for x in s[1:4]])
            elif s[0] == "f":
                if triangles_only and len(s) != 4:
                    sys.exit("%s: only triangles are drawn" % path)
                faces.append([int(x.split("/")[0]) - 1 for x in s[1:4]])
    return verts, faces
