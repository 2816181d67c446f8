#!/usr/bin/python3
# Makes the user manual's figures from the current code's outputs:
#
#   doc/make_figures.py BUILD_DIR
#
# BUILD_DIR is a Release build of the project (tools, examples and benchmarks built), with
# CGAL's demo meshes in BUILD_DIR/cgal_demo_data (benchmark/get_demo_meshes.sh) for the creases'
# figure, which is skipped without them. The
# script runs them on the bundled meshes, in a scratch folder, and renders the PNGs of
# doc/figures with Debian's python3-matplotlib and python3-numpy (orthographic view, flat
# shading, painter's algorithm; no display needed). It prints what the programs said, which
# the captions quote.

import os
import struct
import subprocess
import sys
import tempfile

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import LineCollection, PolyCollection
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "doc", "figures")


def run(*command, cwd=None):
    print("$", " ".join(command))
    text = subprocess.run(command, cwd=cwd, check=True, capture_output=True, text=True).stdout
    print(text, end="")
    return text


def read_off(path):
    with open(path) as f:
        words = f.read().split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    values = np.array(words[4:4 + 3 * nv], dtype=float).reshape(nv, 3)
    faces, k = [], 4 + 3 * nv
    for _ in range(nf):
        n = int(words[k])
        faces.append([int(w) for w in words[k + 1:k + 1 + n]])
        k += 1 + n
    return values, np.array(faces, dtype=int)


def read_ply_with_deviation(path):
    """The tool's binary PLY output: vertices (x, y, z as double, deviation, at_bound), faces."""
    with open(path, "rb") as f:
        header = []
        while True:
            line = f.readline().decode("ascii").strip()
            header.append(line)
            if line == "end_header":
                break
        body = f.read()
    assert any("binary_little_endian" in h for h in header)
    nv = int(next(h for h in header if h.startswith("element vertex")).split()[2])
    nf = int(next(h for h in header if h.startswith("element face")).split()[2])
    props = []
    in_vertex = False
    for h in header:
        if h.startswith("element"):
            in_vertex = h.startswith("element vertex")
        elif h.startswith("property") and in_vertex:
            props.append((h.split()[1], h.split()[2]))
    formats = {"double": "d", "float": "f", "uchar": "B", "int": "i", "uint": "I"}
    vertex_format = "<" + "".join(formats[t] for t, _ in props)
    size = struct.calcsize(vertex_format)
    names = [n for _, n in props]
    rows = [struct.unpack_from(vertex_format, body, i * size) for i in range(nv)]
    data = np.array(rows, dtype=float)
    points = data[:, [names.index("x"), names.index("y"), names.index("z")]]
    deviation = data[:, names.index("deviation")]
    faces, offset = [], nv * size
    for _ in range(nf):
        n = body[offset]
        faces.append(struct.unpack_from("<%di" % n, body, offset + 1))
        offset += 1 + 4 * n
    return points, np.array(faces, dtype=int), deviation


def mean_curvature(points, faces):
    """|H| per vertex: half the length of the cotangent Laplacian over the mixed area."""
    laplacian = np.zeros_like(points)
    area = np.zeros(len(points))
    for k in range(3):
        i, j, l = faces[:, k], faces[:, (k + 1) % 3], faces[:, (k + 2) % 3]
        u, v = points[j] - points[i], points[l] - points[i]
        cross = np.linalg.norm(np.cross(u, v), axis=1)
        cot = np.einsum("ij,ij->i", u, v) / np.maximum(cross, 1e-300)  # at corner i, opposite edge j-l
        np.add.at(laplacian, j, (cot[:, None] * (points[l] - points[j])))
        np.add.at(laplacian, l, (cot[:, None] * (points[j] - points[l])))
        np.add.at(area, i, cross / 6)
    return 0.5 * np.linalg.norm(laplacian, axis=1) / np.maximum(2 * area, 1e-300)


def view(yaw, pitch):
    """The rotation that turns a model with y up by `yaw` degrees about y, then tilts it by
    `pitch` degrees towards the viewer, who looks along -z."""
    a, e = np.radians(yaw), np.radians(pitch)
    ry = np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])
    rx = np.array([[1, 0, 0], [0, np.cos(e), -np.sin(e)], [0, np.sin(e), np.cos(e)]])
    return rx @ ry


def draw(ax, points, faces, values, cmap, vmin, vmax, rotation, title, lines=None):
    """Orthographic view along -z after `rotation`, back faces culled, flat shading
    by the light from the viewer, each face coloured by the mean of its vertices' values, or by
    its own value if `values` has one per face; `lines`, pairs of vertex indices, drawn on top
    where a face beside them faces the viewer."""
    p = (points - points.mean(axis=0)) @ rotation.T
    tri = p[faces]
    normal = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    length = np.linalg.norm(normal, axis=1)
    facing = normal[:, 2] > 0
    order = np.argsort(tri[facing][:, :, 2].mean(axis=1))
    shade = 0.35 + 0.65 * (normal[facing][:, 2] / np.maximum(length[facing], 1e-300))[order]
    face_values = values[facing] if len(values) == len(faces) else values[faces[facing]].mean(axis=1)
    colour = plt.get_cmap(cmap)(np.clip((face_values[order] - vmin) / (vmax - vmin), 0, 1))
    colour[:, :3] *= shade[:, None]
    # Edges in the faces' colours, so that no seam shows between neighbours.
    ax.add_collection(PolyCollection(tri[facing][order][:, :, :2], facecolors=colour, edgecolors=colour,
                                     linewidths=0.3))
    if lines is not None:
        seen = set()
        for f in np.flatnonzero(facing):
            for k in range(3):
                seen.add((min(faces[f][k], faces[f][(k + 1) % 3]), max(faces[f][k], faces[f][(k + 1) % 3])))
        shown = [p[list(e), :2] for e in lines if (min(e), max(e)) in seen]
        ax.add_collection(LineCollection(shown, colors="#00e5ff", linewidths=0.8))
    ax.set_xlim(p[:, 0].min(), p[:, 0].max())
    ax.set_ylim(p[:, 1].min(), p[:, 1].max())
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(title, fontsize=10)
    return plt.cm.ScalarMappable(norm=matplotlib.colors.Normalize(vmin, vmax), cmap=cmap)


def save(fig, name):
    path = os.path.join(OUT, name)
    fig.savefig(path, dpi=110, bbox_inches="tight")
    plt.close(fig)
    print("wrote", path)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: doc/make_figures.py BUILD_DIR")
    build = os.path.abspath(sys.argv[1])
    tool = os.path.join(build, "tools", "constrained_fairing")
    data = os.path.join(ROOT, "data")
    os.makedirs(OUT, exist_ok=True)
    work = tempfile.mkdtemp()

    # The bunny (a real scan, 75 k triangles) with noise of a quarter of its mean edge length,
    # faired with epsilon the noise radius; the tool's PLY carries the deviation.
    noisy = os.path.join(work, "bunny_noisy.off")
    said = run(os.path.join(build, "benchmark", "add_noise"), os.path.join(data, "bunny00.off"), "0.25", noisy, "1")
    eps = float(said.split("noise radius ")[1])
    faired = os.path.join(work, "bunny_faired.ply")
    run(tool, "--eps", repr(eps), noisy, faired)
    points0, faces = read_off(noisy)
    points1, faces1, deviation = read_ply_with_deviation(faired)
    assert (faces1 == faces).all()
    front = view(0, 0)

    h0, h1 = mean_curvature(points0, faces), mean_curvature(points1, faces)
    top = np.percentile(h1, 98)
    fig, axes = plt.subplots(1, 2, figsize=(10, 5))
    draw(axes[0], points0, faces, h0, "viridis", 0, top, front, "noisy input (noise radius 0.25 h)")
    mappable = draw(axes[1], points1, faces, h1, "viridis", 0, top, front, "constrained fairing, eps = 0.25 h")
    fig.colorbar(mappable, ax=axes, shrink=0.6, label="mean curvature |H|")
    save(fig, "bunny_curvature.png")

    fig, ax = plt.subplots(figsize=(6, 5))
    mappable = draw(ax, points1, faces, deviation, "magma", 0, eps, front, "distance to the input position")
    fig.colorbar(mappable, ax=ax, shrink=0.7, label="deviation (the scale ends at eps = %.5f)" % eps)
    save(fig, "bunny_deviation.png")

    # Constrained fairing against mean curvature flow at equal bending energy, on the bundled
    # noisy elephant (noise radius 0.25 h, eps the same).
    elephant = os.path.join(data, "elephant_noisy.off")
    eps_elephant = 0.25 * 0.0219972  # data/README.md: h of the clean elephant
    faired_off, flow_off = os.path.join(work, "faired.off"), os.path.join(work, "flow.off")
    run(os.path.join(build, "benchmark", "flow_comparison"), elephant, repr(eps_elephant), faired_off, flow_off)
    pe, fe = read_off(elephant)
    pf, _ = read_off(faired_off)
    pm, _ = read_off(flow_off)
    move_f = np.linalg.norm(pf - pe, axis=1)
    move_m = np.linalg.norm(pm - pe, axis=1)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
    top = 4 * eps_elephant
    side = view(-30, 10)
    draw(axes[0], pf, fe, move_f, "magma", 0, top, side, "constrained fairing")
    mappable = draw(axes[1], pm, fe, move_m, "magma", 0, top, side, "smooth_shape at its lowest bending energy")
    fig.colorbar(mappable, ax=axes, shrink=0.6, label="distance to the input (the scale ends at 4 eps)")
    save(fig, "fairing_vs_flow.png")

    # A terraced isosurface: surface nets of the elephant on slices 3 times thicker than the
    # pixels, before and after fairing within each vertex's voxel.
    run(os.path.join(build, "examples", "Constrained_fairing", "voxel_fairing_example"),
        os.path.join(work, "staircase.off"), os.path.join(work, "voxels_faired.off"))
    ps, fs = read_off(os.path.join(work, "staircase.off"))
    pv, _ = read_off(os.path.join(work, "voxels_faired.off"))
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5))
    draw(axes[0], ps, fs, np.zeros(len(ps)), "Greys", -1, 1, side, "surface nets, 1 x 1 x 3 voxels")
    draw(axes[1], pv, fs, np.zeros(len(pv)), "Greys", -1, 1, side, "faired within each voxel")
    save(fig, "voxels.png")

    label_map_figure(build)
    creases_figure(build)
    point_set_figure(build)


def face_normals(points, faces):
    normal = np.cross(points[faces[:, 1]] - points[faces[:, 0]], points[faces[:, 2]] - points[faces[:, 0]])
    return normal / np.maximum(np.linalg.norm(normal, axis=1), 1e-300)[:, None]


def creases_figure(build):
    """fandisk of CGAL's demo data, remeshed to about 20,000 triangles with its sharp edges kept,
    with noise of 0.25 h (benchmark/fairing_features): the noisy input, the default call and
    feature_angle(30) with the creases it found, each face coloured by its normal's angle to the
    clean mesh's."""
    demo = os.path.join(build, "cgal_demo_data", "meshes")
    if not os.path.exists(os.path.join(demo, "fandisk.off")):
        print("creases figure skipped: no fandisk.off in %s (benchmark/get_demo_meshes.sh %s)"
              % (demo, os.path.join(build, "cgal_demo_data")))
        return
    work = tempfile.mkdtemp()
    run(os.path.join(build, "benchmark", "fairing_features"), "--runs", "1", "--parts", "fandisk", "--demo", demo,
        "--write", work)
    clean, faces = read_off(os.path.join(work, "fandisk_clean.off"))
    normal = face_normals(clean, faces)
    creases = np.loadtxt(os.path.join(work, "fandisk_0.25_features_creases.txt"), dtype=int)
    angle = view(-40, -30)
    fig, axes = plt.subplots(1, 3, figsize=(15, 5))
    for ax, name, title in ((axes[0], "noisy", "noisy input (noise radius 0.25 h)"),
                            (axes[1], "default", "default call, eps = 0.25 h"),
                            (axes[2], "features", "feature_angle(30), the creases found")):
        points, _ = read_off(os.path.join(work, "fandisk_0.25_%s.off" % name))
        error = np.degrees(np.arccos(np.clip(np.einsum("ij,ij->i", face_normals(points, faces), normal), -1, 1)))
        print("%s: mean normal error %.2f degrees" % (name, error.mean()))
        mappable = draw(ax, points, faces, error, "magma", 0, 20, angle, title,
                        lines=creases if name == "features" else None)
    fig.colorbar(mappable, ax=axes, shrink=0.6, label="normal error (degrees)")
    save(fig, "fandisk_creases.png")


def label_map_figure(build):
    """A ball of 1 x 1 x 2 voxels cut by a tilted plane into labels 1 and 2, with a cap of
    label 3: the surfaces of labels 1 and 3 (label 2 left out, to show the interfaces), coloured
    by label, from the surface nets and after fairing them together."""
    sys.path.insert(0, os.path.join(build, "python"))
    import cgal_constrained_fairing as cf
    spacing = np.array([1.0, 1.0, 2.0])
    shape = (40, 40, 20)
    i, j, k = np.indices(shape)
    x, y, z = i * spacing[0] - 19.5, j * spacing[1] - 19.5, k * spacing[2] - 19.5
    labels = np.zeros(shape, np.uint8)
    inside = x * x + y * y + z * z < 16.5 ** 2
    labels[inside] = np.where(x[inside] < 0.3 * z[inside], 1, 2)
    labels[inside & (z > 9)] = 3
    raw = cf.label_surfaces(labels, spacing, fair=False)
    faired = cf.label_surfaces(labels, spacing)
    print("label map figure:", faired.report)
    fig, axes = plt.subplots(1, 2, figsize=(10, 5))
    angle = view(-35, 20) @ np.array([[1, 0, 0], [0, 0, 1], [0, -1, 0]])  # z up
    for ax, result, title in ((axes[0], raw, "surface nets, 1 x 1 x 2 voxels"),
                              (axes[1], faired, "faired together, each point in its voxel")):
        points, faces, values = [], [], []
        for label in (1, 3):
            V, F = result.surface(label)
            faces.append(F + sum(len(p) for p in points))
            points.append(V)
            values.append(np.full(len(V), label))
        draw(ax, np.concatenate(points), np.concatenate(faces), np.concatenate(values), "tab10",
             0, 10, angle, title)
    save(fig, "label_map.png")


def pca_normals(points, k=16):
    """Each point's normal as the least-variance direction of its k nearest neighbours: what
    shades a point set, and shows its noise as speckle."""
    from scipy.spatial import cKDTree
    _, near = cKDTree(points).query(points, k)
    local = points[near] - points[near].mean(axis=1, keepdims=True)
    _, vectors = np.linalg.eigh(np.einsum("nki,nkj->nij", local, local))
    return vectors[:, :, 0]


def draw_points(ax, points, values, cmap, vmin, vmax, rotation, title):
    """Orthographic view along -z after `rotation`, far points drawn first, each shaded by the
    light from the viewer on its neighbours' plane."""
    p = (points - points.mean(axis=0)) @ rotation.T
    order = np.argsort(p[:, 2])
    shade = 0.3 + 0.7 * np.abs((pca_normals(points) @ rotation.T)[:, 2])
    colour = plt.get_cmap(cmap)(np.clip((values - vmin) / (vmax - vmin), 0, 1))
    colour[:, :3] *= shade[:, None]
    ax.scatter(p[order, 0], p[order, 1], s=1.5, c=colour[order], linewidths=0)
    ax.set_aspect("equal")
    ax.axis("off")
    ax.set_title(title, fontsize=10)
    return plt.cm.ScalarMappable(norm=matplotlib.colors.Normalize(vmin, vmax), cmap=cmap)


def point_set_figure(build):
    """CGAL's demo scan of the hippo (data/points_3, from benchmark/get_demo_meshes.sh), faired
    within its estimated noise with its own normals, as the tool fairs it: the scan, and a slab
    across it seen edge on, as scanned and faired, the faired points coloured by how far they
    moved."""
    scan = os.path.join(build, "cgal_demo_data", "points_3", "hippo1.ply")
    if not os.path.exists(scan):
        print("point set figure skipped: no %s (benchmark/get_demo_meshes.sh %s)"
              % (scan, os.path.join(build, "cgal_demo_data")))
        return
    sys.path.insert(0, os.path.join(build, "python"))
    import cgal_constrained_fairing as cf
    P, N = cf.read_points(scan)
    eps = cf.estimate_noise_level(P)
    Q, report = cf.fair_points(P, eps, N)
    deviation = np.linalg.norm(Q - P, axis=1)
    print("point set figure: %d points, eps %.6g (estimated), largest move %.6g, %d isolated, %s"
          % (len(P), eps, deviation.max(), report.number_of_isolated_points, report.status))
    assert (deviation <= eps).all()
    angle = view(150, 15)
    fig, axes = plt.subplots(1, 3, figsize=(15, 4.5), gridspec_kw={"width_ratios": [1, 1.2, 1.2]})
    draw_points(axes[0], P, np.zeros(len(P)), "Greys", -1, 1, angle, "the scan (%d points)" % len(P))
    # A slab across the body, seen edge on: the scan's noise is the width of its band.
    p, q = (P - P.mean(axis=0)) @ angle.T, (Q - P.mean(axis=0)) @ angle.T
    slab = np.abs(p[:, 0] - np.median(p[:, 0])) < 4 * eps
    axes[0].scatter(p[slab, 0], p[slab, 1], s=2, c="#d62728", linewidths=0)
    axes[1].scatter(p[slab, 2], p[slab, 1], s=6, linewidths=0, c="0.3")
    axes[2].scatter(q[slab, 2], q[slab, 1], s=6, linewidths=0, c=deviation[slab], cmap="magma", vmin=0, vmax=eps)
    for ax, title in ((axes[1], "the slab's points as scanned"), (axes[2], "faired, coloured by the distance moved")):
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        ax.set_title(title, fontsize=10)
    mappable = plt.cm.ScalarMappable(norm=matplotlib.colors.Normalize(0, eps), cmap="magma")
    fig.colorbar(mappable, ax=axes, shrink=0.6, label="distance moved (ends at eps)")
    save(fig, "hippo_points.png")


if __name__ == "__main__":
    main()
