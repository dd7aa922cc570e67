"""The scene scripts' one OBJ reader and edge table (NumPy): vertices and triangles of an OBJ written by
hinge simulate or by these scripts, and the interior edges with their two faces."""
import numpy as np


def read_obj(path):
    """(V, F): vertices (n x 3) and 0-based triangles (m x 3); `v` and `f` lines, `a/b/c` forms allowed."""
    v, f = [], []
    with open(path) as src:
        for line in src:
            t = line.split()
            if t and t[0] == "v":
                v.append([float(x) for x in t[1:4]])
            elif t and t[0] == "f":
                f.append([int(x.split("/")[0]) - 1 for x in t[1:4]])
    return np.array(v), np.array(f)


def interior_edges(F):
    """{(i, j): [t1, t2]} for each edge (i < j) shared by two triangles of F."""
    faces = {}
    for t, tri in enumerate(F):
        for s in range(3):
            faces.setdefault(tuple(sorted((int(tri[s]), int(tri[(s + 1) % 3])))), []).append(t)
    return {e: ts for e, ts in faces.items() if len(ts) == 2}
