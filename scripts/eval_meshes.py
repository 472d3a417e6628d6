#!/usr/bin/env python3
"""Evaluation script (not a test): visfeat's per-point crease labels on public CAD
meshes, scored against a truth computed from the mesh itself, beside PCL's
surface variation (the `curvature` of pcl_normal_estimation) at its best (oracle)
threshold.

It reads the meshes in ../shared/data/models (see PROVENANCE.md there), so it
needs that checkout; it is not part of ctest.

Per mesh:
  1. a seeded uniformly random rotation (normalised Gaussian quaternion);
  2. cell = largest side of the rotated bounding box / R; points sampled uniformly
     by area, points_per_cell2 * area / cell^2 of them, written as ASCII PCD;
  3. truth: mesh edges shared by exactly two triangles (after merging duplicate
     vertices, 1e-9 relative tolerance) whose face normals turn by more than
     --angle (30) degrees are sharp; boundary edges are ignored. A point's truth
     distance is its distance to the nearest sharp edge segment (exact up to 3
     cells, infinite beyond). Truth vertices: mesh vertices with 1 or >= 3 sharp
     edges; truth curves: chains of sharp edges between them (closed loops count);
  4. visfeat in.pcd out.pcd -resolution R -graph g.json; the distances below are
     in its grid's cell_size (g.json). With --resolution auto, R is what visfeat
     chooses for the rotated mesh itself (written as OFF, no option), and the cloud
     of step 2 is sampled for that R;
  5. visfeat: predicted sharp = feature_class 1 or 2. P = predicted points with
     truth distance <= 2 cells; R = points within 1 cell that are predicted;
  6. PCL: pcl_normal_estimation -k 30; for ~200 quantiles t of the curvature,
     predicted = curvature >= t; best F1 (oracle threshold) reported.

Run (from the repository root, with a Release build):
  /usr/bin/python3 scripts/eval_meshes.py --out /tmp/eval_meshes \
      [--meshes fandisk.off cgal_part.off ...] [--resolution 512|auto] \
      [--visfeat build/tools/visfeat] [--threads 2] \
      [--visfeat-option '-min_crease_angle 30'] [--analyse] \
      [--points-per-cell2 1.5]   (sparser clouds: 1.5 = 0.82 cells apart)
      [--no-pcl]   (visfeat alone: PCL's columns NaN, e.g. an A/B of visfeat's changes)
Needs numpy (apt-get install python3-numpy); scripts/install_deps.sh does not
install it, as neither the tests nor the demo use this script.
"""
import argparse, json, os, re, subprocess, sys, time
try:
    import numpy as np
except ImportError:
    sys.exit("eval_meshes.py: needs numpy (Debian: apt-get install python3-numpy)")

HERE = os.path.dirname(os.path.abspath(__file__))
MODELS = os.path.normpath(os.path.join(HERE, "..", "..", "shared", "data", "models"))
DEFAULT_MESHES = ["fandisk.off", "cgal_joint_refined.off", "cgal_part.off",
                  "cgal_pinion.off", "vhacd_block.off", "abc_00000050.stl"]


def read_off(path):
    toks = []
    with open(path) as f:
        for line in f:
            toks += line.split("#", 1)[0].split()
    if not toks[0].endswith("OFF"):
        raise ValueError(path + ": not an OFF file")
    nv, nf = int(toks[1]), int(toks[2])
    pos = 4
    V = np.array(toks[pos:pos + 3 * nv], dtype=float).reshape(nv, 3)
    pos += 3 * nv
    tris = []
    for _ in range(nf):
        n = int(toks[pos]); idx = [int(t) for t in toks[pos + 1:pos + 1 + n]]
        pos += 1 + n
        tris += [(idx[0], idx[i], idx[i + 1]) for i in range(1, n - 1)]  # fan
    return V, np.array(tris, dtype=np.int64)


def read_stl(path):
    data = open(path, "rb").read()
    n = int(np.frombuffer(data[80:84], "<u4")[0]) if len(data) >= 84 else -1
    if len(data) == 84 + 50 * n:  # binary
        rec = np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")])
        P = np.frombuffer(data, rec, n, 84)["v"].astype(float).reshape(-1, 3)
    else:  # ASCII
        nums = re.findall(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data)
        P = np.array(nums, dtype=float).reshape(-1, 3)
    return P, np.arange(len(P), dtype=np.int64).reshape(-1, 3)


def merge_vertices(V, F, rel_tol=1e-9):
    tol = rel_tol * max(np.linalg.norm(V.max(0) - V.min(0)), 1e-300)
    _, first, inv = np.unique(np.round(V / tol).astype(np.int64), axis=0,
                              return_index=True, return_inverse=True)
    return V[first], inv.reshape(-1)[F]


def random_rotation(rng):
    w, x, y, z = (q := rng.standard_normal(4)) / np.linalg.norm(q)
    return np.array([[1 - 2 * (y*y + z*z), 2 * (x*y - w*z), 2 * (x*z + w*y)],
                     [2 * (x*y + w*z), 1 - 2 * (x*x + z*z), 2 * (y*z - w*x)],
                     [2 * (x*z - w*y), 2 * (y*z + w*x), 1 - 2 * (x*x + y*y)]])


def sample(V, F, n, rng):
    A, B, C = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(B - A, C - A), axis=1)
    t = rng.choice(len(F), size=n, p=area / area.sum())
    r1, r2 = np.sqrt(rng.random(n))[:, None], rng.random(n)[:, None]
    P = (1 - r1) * A[t] + r1 * (1 - r2) * B[t] + r1 * r2 * C[t]
    return P.astype(np.float32).astype(float)  # what visfeat reads


def sharp_edges(V, F, angle_deg):
    """Returns (sharp edges (k,2), #boundary, #non-manifold, #mis-oriented pairs)."""
    N = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    nn = np.linalg.norm(N, axis=1)
    N = N / np.maximum(nn, 1e-300)[:, None]
    he = np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]])  # half-edges
    face = np.tile(np.arange(len(F)), 3)
    key = np.sort(he, axis=1)
    _, inv, cnt = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    inv = inv.reshape(-1)
    order = np.argsort(inv, kind="stable")
    two = np.flatnonzero(cnt == 2)
    start = np.concatenate([[0], np.cumsum(cnt)])[two]
    h0, h1 = order[start], order[start + 1]
    f0, f1 = face[h0], face[h1]
    cosang = np.einsum("ij,ij->i", N[f0], N[f1])
    same_dir = he[h0, 0] == he[h1, 0]  # inconsistent orientation across the edge
    cosang[same_dir] *= -1
    ok = (nn[f0] > 0) & (nn[f1] > 0)
    sharp = ok & (cosang < np.cos(np.radians(angle_deg)))
    return key[h0[sharp]], int((cnt == 1).sum()), int((cnt > 2).sum()), int(same_dir.sum())


def truth_topology(E):
    """Truth vertices (sharp degree 1 or >= 3) and curves (chains between them)."""
    if len(E) == 0:
        return 0, 0
    deg = np.bincount(E.ravel())
    parent = list(range(len(E)))
    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]; a = parent[a]
        return a
    inc = {}
    for i, (a, b) in enumerate(E.tolist()):
        for v in (a, b):
            if deg[v] == 2:
                if v in inc:
                    parent[find(i)] = find(inc[v])
                else:
                    inc[v] = i
    nv = int(((deg == 1) | (deg >= 3)).sum())
    return nv, len({find(i) for i in range(len(E))})


def seg_distance(P, S0, S1, margin, chunk=2_000_000):
    """Distance from each point to the nearest segment; inf beyond ~margin."""
    d = np.full(len(P), np.inf)
    if len(S0) == 0:
        return d
    g = 2 * margin  # grid cell; a segment is registered around samples g/2 apart,
    L = np.linalg.norm(S1 - S0, axis=1)  # so a point within margin is within 0.75 g
    ns = np.ceil(L / (0.5 * g)).astype(np.int64) + 1  # of a sample: +-1 cell suffices
    seg = np.repeat(np.arange(len(S0)), ns)
    u = (np.arange(len(seg)) - np.repeat(np.cumsum(ns) - ns, ns)) / np.repeat(np.maximum(ns - 1, 1), ns)
    X = S0[seg] + u[:, None] * (S1 - S0)[seg]
    origin = X.min(0) - 2 * g
    cs = np.floor((X - origin) / g).astype(np.int64)
    dims = cs.max(0) + 3
    nb = np.stack(np.meshgrid(*[np.arange(-1, 2)] * 3, indexing="ij"), -1).reshape(-1, 3)
    c = (cs[:, None, :] + nb[None]).reshape(-1, 3)
    keys = (c[:, 0] * dims[1] + c[:, 1]) * dims[2] + c[:, 2]
    pair = np.unique(np.c_[keys, np.repeat(seg, 27)], axis=0)
    keys, segs = pair[:, 0], pair[:, 1]
    c = np.floor((P - origin) / g).astype(np.int64)
    inside = np.all((c >= 0) & (c < dims), axis=1)
    pk = np.where(inside, (c[:, 0] * dims[1] + c[:, 1]) * dims[2] + c[:, 2], -1)
    a, b = np.searchsorted(keys, pk, "left"), np.searchsorted(keys, pk, "right")
    cnt = b - a
    pts = np.flatnonzero(cnt > 0)
    csum = np.cumsum(cnt[pts])
    i0 = 0
    while i0 < len(pts):  # chunks of about `chunk` point-segment pairs
        i1 = max(i0 + 1, int(np.searchsorted(csum, (csum[i0 - 1] if i0 else 0) + chunk)))
        p = pts[i0:i1]
        rep = np.repeat(p, cnt[p])
        off = np.arange(len(rep)) - np.repeat(np.cumsum(cnt[p]) - cnt[p], cnt[p])
        s = segs[np.repeat(a[p], cnt[p]) + off]
        A, D = S0[s], S1[s] - S0[s]
        t = np.clip(np.einsum("ij,ij->i", P[rep] - A, D) / np.maximum(np.einsum("ij,ij->i", D, D), 1e-300), 0, 1)
        dist = np.linalg.norm(P[rep] - (A + t[:, None] * D), axis=1)
        d[p] = np.minimum.reduceat(dist, np.cumsum(cnt[p]) - cnt[p])  # rep is sorted
        i0 = i1
    return d


def write_pcd(path, P):
    with open(path, "w") as f:
        f.write("# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS x y z\n"
                "SIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH %d\nHEIGHT 1\n"
                "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA ascii\n" % (len(P), len(P)))
        np.savetxt(f, P.astype(np.float32), fmt="%.9g")


def read_pcd(path, tmpdir):
    """Returns {field: array}; binary_compressed is converted with pcl_convert first."""
    with open(path, "rb") as f:
        hdr = {}
        while True:
            line = f.readline().decode().strip()
            if not line or line.startswith("#"):
                continue
            k, *v = line.split()
            hdr[k] = v
            if k == "DATA":
                break
        body = f.read()
    fmt = hdr["DATA"][0]
    if fmt == "binary_compressed":
        conv = os.path.join(tmpdir, os.path.basename(path)[:-4] + "_ascii.pcd")
        subprocess.run(["pcl_convert_pcd_ascii_binary", path, conv, "0"], check=True, capture_output=True)
        return read_pcd(conv, tmpdir)
    names, counts = hdr["FIELDS"], [int(c) for c in hdr.get("COUNT", ["1"] * len(hdr["FIELDS"]))]
    n = int(hdr["POINTS"][0])
    if fmt == "ascii":
        arr = np.loadtxt(body.decode().splitlines(), dtype=float, ndmin=2) if n else np.zeros((0, sum(counts)))
        cols = np.cumsum([0] + counts)
        return {nm: arr[:, cols[i]] for i, nm in enumerate(names) if nm != "_"}
    dt = np.dtype([(nm if nm != "_" else "_%d" % i, "<%s%s" % ({"F": "f", "U": "u", "I": "i"}[t], s), c)
                   for i, (nm, s, t, c) in enumerate(zip(names, hdr["SIZE"], hdr["TYPE"], counts))])
    rec = np.frombuffer(body, dt, n)
    return {nm: rec[nm].astype(float) for nm in names if nm != "_"}


def read_same_points(path, P, tmpdir):
    c = read_pcd(path, tmpdir)  # the tools must keep the input's points and order
    if len(c["x"]) != len(P) or np.abs(np.c_[c["x"], c["y"], c["z"]] - P).max() > 1e-6 * np.ptp(P):
        raise RuntimeError(path + ": points differ from the input's (order or count)")
    return c


def prf(pred, near2, near1):
    p = near2[pred].mean() if pred.any() else 0.0
    r = pred[near1].mean() if near1.any() else 0.0
    return p, r, (2 * p * r / (p + r) if p + r > 0 else 0.0)


def best_threshold(curv, near2, near1, nq=200):
    curv = np.where(np.isfinite(curv), curv, -np.inf)  # NaN: never sharp
    o = np.argsort(-curv, kind="stable")
    cs, c2, c1 = curv[o], np.concatenate([[0], np.cumsum(near2[o])]), np.concatenate([[0], np.cumsum(near1[o])])
    best = (0.0, 0.0, 0.0, np.nan)
    for t in np.unique(np.quantile(curv[np.isfinite(curv)], np.linspace(0, 1, nq + 1)[:-1])):
        k = int(np.searchsorted(-cs, -t, "right"))  # points with curv >= t
        p, r = c2[k] / max(k, 1), c1[k] / max(near1.sum(), 1)
        f = 2 * p * r / (p + r) if p + r > 0 else 0.0
        if f > best[2]:
            best = (p, r, f, t)
    return best


def mesh_parts(V, F):
    """Part (connected component by shared vertices) of each triangle, and their count."""
    parent = np.arange(len(V))

    def find(v):
        while parent[v] != v:
            parent[v] = parent[parent[v]]
            v = parent[v]
        return v
    for f in F:
        r0 = find(f[0])
        for v in f[1:]:
            parent[find(v)] = r0
    roots = np.array([find(v) for v in range(len(V))])
    part = np.unique(roots[F[:, 0]], return_inverse=True)[1].reshape(-1)
    return part, int(part.max()) + 1


def near_two_parts(V, F, part, nparts, X, cell, rng, reach=2):
    """Whether each point of X lies within `reach` cells (a box of voxels) of the
    surfaces of two different parts (part, nparts: mesh_parts): each part sampled at 3
    points a cell squared, the voxels it touches marked with its bit."""
    lo = np.minimum(V.min(0), X.min(0)) - (reach + 2) * cell
    side = int(np.ceil((np.maximum(V.max(0), X.max(0)) - lo).max() / cell)) + reach + 3

    def voxels(Y):
        return np.floor((Y - lo) / cell).astype(np.int64)

    def key(k):
        return (k[:, 0] * side + k[:, 1]) * side + k[:, 2]
    keys, bits = [], []
    for i in range(nparts):
        Fi = F[part == i]
        A, B, C = V[Fi[:, 0]], V[Fi[:, 1]], V[Fi[:, 2]]
        area = 0.5 * np.linalg.norm(np.cross(B - A, C - A), axis=1).sum()
        k = np.unique(key(voxels(sample(V, Fi, max(int(3 * area / cell ** 2), 1), rng))))
        keys.append(k)
        bits.append(np.full(len(k), 1 << i, np.int64))
    k, b = np.concatenate(keys), np.concatenate(bits)
    o = np.argsort(k, kind="stable")
    k, b = k[o], b[o]
    uk, first = np.unique(k, return_index=True)
    ub = np.bitwise_or.reduceat(b, first)
    kx = voxels(X)
    seen = np.zeros(len(X), np.int64)
    for dx in range(-reach, reach + 1):
        for dy in range(-reach, reach + 1):
            for dz in range(-reach, reach + 1):
                q = key(kx + np.array([dx, dy, dz]))
                i = np.minimum(np.searchsorted(uk, q), len(uk) - 1)
                hit = uk[i] == q
                seen[hit] |= ub[i[hit]]
    return np.array([bin(int(x)).count("1") >= 2 for x in seen])


def _plane_interval(T, n, dist, direction, tol):
    """Where triangle T (3x3) meets the plane n.x = dist, as an interval of the
    parameter x.direction (None when it does not)."""
    s = T @ n - dist
    s = np.where(np.abs(s) < tol, 0.0, s)
    if (s > 0).all() or (s < 0).all():
        return None
    u = [T[a] @ direction for a in range(3) if s[a] == 0]
    for a, b in ((0, 1), (1, 2), (2, 0)):
        if s[a] * s[b] < 0:
            u.append((T[a] + s[a] / (s[a] - s[b]) * (T[b] - T[a])) @ direction)
    return (min(u), max(u)) if u else None


def crossing_curves(V, F, part, nparts, angle):
    """Segments (S0, S1) where triangles of two different parts cross at more than
    `angle` degrees (and less than 180 - angle): the intersection curves of an
    assembly whose parts interpenetrate. There the sampled surfaces meet along a line,
    a crease of the cloud the per-part truth does not count. Coplanar contacts (flush
    faces) and shallow crossings give none. Triangle pairs are found by bounding-box
    overlap, then intersected exactly (the two triangles' intervals on the line where
    their planes meet)."""
    A, B, C = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    N = np.cross(B - A, C - A)
    N /= np.maximum(np.linalg.norm(N, axis=1), 1e-300)[:, None]
    lo, hi = np.minimum(np.minimum(A, B), C), np.maximum(np.maximum(A, B), C)
    tol = 1e-9 * np.ptp(V, axis=0).max()
    steep = np.cos(np.radians(angle))
    S0, S1 = [], []
    for p in range(nparts):
        for q in range(p + 1, nparts):
            I, J = np.flatnonzero(part == p), np.flatnonzero(part == q)
            for i0 in range(0, len(I), 256):
                ii = I[i0:i0 + 256]
                overlap = np.all((lo[ii, None, :] <= hi[None, J, :] + tol) &
                                 (hi[ii, None, :] >= lo[None, J, :] - tol), axis=2)
                for i, j in zip(*np.nonzero(overlap)):
                    i, j = ii[i], J[j]
                    if abs(N[i] @ N[j]) > steep:
                        continue
                    d = np.cross(N[i], N[j])
                    d /= np.linalg.norm(d)
                    Ti, Tj = V[F[i]], V[F[j]]
                    a = _plane_interval(Ti, N[j], N[j] @ Tj[0], d, tol)
                    b = _plane_interval(Tj, N[i], N[i] @ Ti[0], d, tol) if a else None
                    if b is None or min(a[1], b[1]) - max(a[0], b[0]) <= tol:
                        continue
                    x0 = np.linalg.solve(np.array([N[i], N[j], d]),
                                         np.array([N[i] @ Ti[0], N[j] @ Tj[0], 0.0]))
                    S0.append(x0 + max(a[0], b[0]) * d)
                    S1.append(x0 + min(a[1], b[1]) * d)
    return np.array(S0).reshape(-1, 3), np.array(S1).reshape(-1, 3)


def analyse(V, F, P, pred, d, curvature, cell, angle, rng, sample_size=1_000_000):
    """--analyse: where visfeat's false positives lie (d: distance to the truth in
    cells). Near mesh edges whose dihedral angle is within 10 degrees below the truth's
    (a crease definition, not a detection), and, for meshes of several parts, within 2
    cells of two parts (creases of the union the per-part truth does not count), with
    both methods scored again away from those contacts on a random sample, and with the
    parts' crossing curves (crossing_curves) added to the truth."""
    lines = []
    fp = pred & (d > 2)
    E = sharp_edges(V, F, angle - 10)[0]
    shallow = seg_distance(P[fp], V[E[:, 0]], V[E[:, 1]], 3 * cell) / cell <= 2
    lines.append("false positives: %d, of them %d within 2 cells of an edge of %g-%g degrees"
                 % (fp.sum(), shallow.sum(), angle - 10, angle))
    part, nparts = mesh_parts(V, F)
    if nparts < 2:
        return lines
    take = np.sort(rng.choice(len(P), min(sample_size, len(P)), replace=False))
    contact = near_two_parts(V, F, part, nparts, P[take], cell, rng)
    lines.append("%.3f of the sampled false positives and %.3f of the sampled points lie "
                 "within 2 cells of two parts" % (contact[fp[take]].mean(), contact.mean()))
    away = ~contact
    n2, n1 = d[take][away] <= 2, d[take][away] <= 1
    vp, vr, vf = prf(pred[take][away], n2, n1)
    pp, pr, pf, _ = best_threshold(curvature[take][away], n2, n1)
    lines.append("away from the contacts (%d sampled points): visfeat P %.3f R %.3f F1 %.3f, "
                 "PCL oracle P %.3f R %.3f F1 %.3f" % (away.sum(), vp, vr, vf, pp, pr, pf))
    S0, S1 = crossing_curves(V, F, part, nparts, angle)
    d_all = np.minimum(d[take], seg_distance(P[take], S0, S1, 3 * cell) / cell)
    n2, n1 = d_all <= 2, d_all <= 1
    vp, vr, vf = prf(pred[take], n2, n1)
    pp, pr, pf, _ = best_threshold(curvature[take], n2, n1)
    lines.append("with the parts' crossing curves (%.0f cells long) in the truth (same sample): "
                 "visfeat P %.3f R %.3f F1 %.3f, PCL oracle P %.3f R %.3f F1 %.3f"
                 % (np.linalg.norm(S1 - S0, axis=1).sum() / cell, vp, vr, vf, pp, pr, pf))
    return lines


def run_options(a):
    """-threads, and the --visfeat-option words, for every visfeat run."""
    return (["-threads", str(a.threads)] if a.threads else []) + \
        [w for o in a.visfeat_option for w in o.split()]


def resolution_option(text):
    """--resolution: 'auto' or a positive number of cells."""
    if text == "auto":
        return text
    if not text.isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError("expected 'auto' or a positive integer, got " + repr(text))
    return int(text)


def automatic_resolution(V, F, stem, a):
    """The resolution visfeat chooses for the (rotated) mesh itself, with no option
    (its automatic choice and search), and the seconds that run took."""
    with open(stem + "_mesh.off", "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(V), len(F)))
        np.savetxt(f, V, fmt="%.17g")
        np.savetxt(f, np.c_[np.full(len(F), 3), F], fmt="%d")
    cmd = [a.visfeat, stem + "_mesh.off", stem + "_mesh_out.pcd", "-mesh_points", "100000"] + \
        run_options(a)
    t0 = time.time()
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode:
        raise RuntimeError("visfeat failed on the mesh %s: %s" % (stem, res.stderr[-2000:]))
    m = re.search(r"Resolution (\d+) chosen", res.stdout)
    if not m:
        raise RuntimeError("no 'Resolution N chosen' in visfeat's output for " + stem)
    return int(m.group(1)), time.time() - t0


def evaluate(name, a):
    rng = np.random.default_rng(a.seed)
    path = os.path.join(MODELS, name)
    V, F = read_stl(path) if name.lower().endswith(".stl") else read_off(path)
    nv_raw = len(V)
    V, F = merge_vertices(V, F)
    notes = []
    if len(V) != nv_raw:
        notes.append("merged %d duplicate vertices" % (nv_raw - len(V)))
    V = V @ random_rotation(rng).T
    stem = os.path.join(a.out, os.path.splitext(name)[0])
    resolution, auto_s = a.resolution, None
    if resolution == "auto":
        resolution, auto_s = automatic_resolution(V, F, stem, a)
    cell = (V.max(0) - V.min(0)).max() / resolution
    A, B, C = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(B - A, C - A), axis=1).sum()
    P = sample(V, F, int(round(a.points_per_cell2 * area / cell ** 2)), rng)
    write_pcd(stem + "_in.pcd", P)
    E, nb, nm, mis = sharp_edges(V, F, a.angle)
    if nb or nm or mis:
        notes.append("%d boundary, %d non-manifold, %d mis-oriented edges" % (nb, nm, mis))
    tv, tc = truth_topology(E)

    cmd = [a.visfeat, stem + "_in.pcd", stem + "_out.pcd", "-resolution", str(resolution),
           "-graph", stem + "_g.json"] + run_options(a)
    t0 = time.time()
    res = subprocess.run(cmd, capture_output=True, text=True)
    vf_s = time.time() - t0
    if res.returncode:
        raise RuntimeError("visfeat failed on %s: %s" % (name, res.stderr[-2000:]))
    m = re.search(r"Regions: (\d+) vertices, (\d+) edges, (\d+) faces", res.stdout)
    vef = "/".join(m.groups()) if m else "?"
    warn = [l for l in (res.stdout + res.stderr).splitlines() if re.search(r"warn|error", l, re.I)]
    notes += ["visfeat: " + l.strip() for l in warn]
    vcell = json.load(open(stem + "_g.json"))["grid"]["cell_size"]
    out = read_same_points(stem + "_out.pcd", P, a.out)

    d = seg_distance(P, V[E[:, 0]], V[E[:, 1]], 3 * max(vcell, cell)) / vcell
    near2, near1 = d <= 2, d <= 1
    vp, vr, vf1 = prf(np.isin(out["feature_class"], (1, 2)), near2, near1)

    if a.no_pcl:  # visfeat alone (an A/B of visfeat's own changes)
        pp = pr = pf1 = pt = pcl_s = float("nan")
        return dict(mesh=name, R=resolution, points=len(P), vef=vef, sharp=len(E), tv=tv,
                    tc=tc, P=vp, Rc=vr, F1=vf1, vs=vf_s, pP=pp, pR=pr, pF1=pf1, pt=pt,
                    ps=pcl_s, cell=vcell, ourcell=cell, notes=notes)
    t0 = time.time()
    res = subprocess.run(["pcl_normal_estimation", stem + "_in.pcd", stem + "_normals.pcd", "-k", str(a.k)],
                         capture_output=True, text=True)
    pcl_s = time.time() - t0
    if res.returncode:
        raise RuntimeError("pcl_normal_estimation failed: " + res.stderr[-2000:])
    nrm = read_same_points(stem + "_normals.pcd", P, a.out)
    pp, pr, pf1, pt = best_threshold(nrm["curvature"], near2, near1)
    if a.analyse:
        notes += analyse(V, F, P, np.isin(out["feature_class"], (1, 2)), d,
                         nrm["curvature"], vcell, a.angle, np.random.default_rng(a.seed))
    if auto_s is not None:
        notes.append("resolution %d chosen by visfeat on the rotated mesh in %.1f s" % (resolution, auto_s))
    return dict(mesh=name, R=resolution, points=len(P), vef=vef, sharp=len(E), tv=tv, tc=tc,
                P=vp, Rc=vr, F1=vf1, vs=vf_s, pP=pp, pR=pr, pF1=pf1, pt=pt, ps=pcl_s,
                cell=vcell, ourcell=cell, notes=notes)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--meshes", nargs="+", default=DEFAULT_MESHES)
    ap.add_argument("--resolution", type=resolution_option, default=512,
                    help="cells along the longest side, or 'auto': the resolution visfeat "
                         "chooses for the rotated mesh (its search included), then the "
                         "cloud is sampled and run at that resolution")
    ap.add_argument("--points-per-cell2", type=float, default=6.0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--angle", type=float, default=30.0, help="dihedral angle of a sharp edge (degrees)")
    ap.add_argument("--k", type=int, default=30, help="pcl_normal_estimation -k")
    ap.add_argument("--out", default="eval_meshes_out")
    ap.add_argument("--visfeat", default="/work/build-main/tools/visfeat")
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--visfeat-option", action="append", default=[],
                    help="an option for visfeat, e.g. '-min_crease_angle 30' (repeatable); "
                         "given to the automatic-resolution run on the mesh too")
    ap.add_argument("--no-pcl", action="store_true",
                    help="skip PCL's normal estimation (visfeat's scores alone)")
    ap.add_argument("--analyse", action="store_true",
                    help="also say where the false positives lie: near edges up to 10 "
                         "degrees below --angle, and near contacts of a mesh's parts")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    hdr = ("%-24s %4s %8s %10s %6s %7s %6s %6s %6s %7s %7s %9s %6s" %
           ("mesh", "R", "points", "vis V/E/F", "sharpE", "truthVC", "P", "R", "F1", "vis_s", "pclF1", "pcl_t", "pcl_s"))
    rows, notes = [], []
    for name in a.meshes:
        r = evaluate(name, a)
        rows.append("%-24s %4d %8d %10s %6d %7s %6.3f %6.3f %6.3f %7.1f %7.3f %9.3g %6.1f" %
                    (r["mesh"], r["R"], r["points"], r["vef"], r["sharp"], "%d/%d" % (r["tv"], r["tc"]),
                     r["P"], r["Rc"], r["F1"], r["vs"], r["pF1"], r["pt"], r["ps"]))
        print(rows[-1], file=sys.stderr, flush=True)
        notes += ["%s: %s (visfeat cell %.6g, ours %.6g; PCL P %.3f R %.3f)" %
                  (name, "; ".join(r["notes"]) or "-", r["cell"], r["ourcell"], r["pP"], r["pR"])]
    print(hdr); print("\n".join(rows)); print("\n".join(notes))


if __name__ == "__main__":
    main()
