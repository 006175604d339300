# SPDX-License-Identifier: LGPL-3.0-or-later
"""The rig's layout from skeletonize's control skeleton, without Blender (numpy only): the
chains between junctions, the mesh's mirror plane, left/right pairs of chains, and
names a rigger can read (spine, leg, arm, head, tail where the geometry says so, chain_N
elsewhere), and the parent of every bone."""

import numpy as np

# A chain matches its mirror image when they are closer than this fraction of the
# character's longest extent all along (the joints sit on voxels: a few voxels of 64 apart).
MIRROR_TOLERANCE = 0.05
# A direction is "up" or "down" when its cosine with the up axis is beyond this.
STEEP = 0.5


class Chain:
    """Joints from a root or a junction to the next junction or end; `bones` index the
    skeleton's bones along it."""

    def __init__(self, joints, bones):
        self.joints, self.bones = joints, bones
        self.label, self.side, self.partner = None, "", None


def children_of(parents):
    children = [[] for _ in parents]
    for j, p in enumerate(parents):
        if p >= 0:
            children[p].append(j)
    return children


def split_into_chains(parents, bones):
    """Chains in the order of a walk from the roots (a parent's chains before its children's)."""
    bone_of_child = {c: b for b, (p, c) in enumerate(bones)}
    children = children_of(parents)
    chains, starts = [], [j for j, p in enumerate(parents) if p < 0]
    while starts:
        start = starts.pop(0)
        for child in children[start]:
            joints = [start, child]
            while len(children[joints[-1]]) == 1:
                joints.append(children[joints[-1]][0])
            if joints[-1] != start and children[joints[-1]]:
                starts.append(joints[-1])
            chains.append(Chain(joints, [bone_of_child[j] for j in joints[1:]]))
    return chains


def mirror(points, normal, offset):
    return points - 2.0 * np.outer(points @ normal - offset, normal)


# The mesh is mirror-symmetric across a plane when this share of its surface cells (of a
# grid of MIRROR_GRID cells along its longest extent) have their mirror image within a cell.
MIRROR_GRID = 32
MIRROR_SHARE = 0.8


class SurfaceCells:
    """The cells of a grid (MIRROR_GRID cells along the longest extent) that hold vertices,
    and those cells with their 26 neighbours, as sorted integer keys."""

    def __init__(self, vertices, grid=MIRROR_GRID):
        self.origin = vertices.min(axis=0)
        self.cell = max(float((vertices.max(axis=0) - self.origin).max()), 1e-12) / grid
        self.span = grid + 5  # keys for cells -2 .. grid + 2 along each axis
        cells = np.unique(self.key(np.floor((vertices - self.origin) / self.cell).astype(np.int64)))
        steps = np.array([(i * self.span + j) * self.span + k for i in (-1, 0, 1) for j in (-1, 0, 1)
                          for k in (-1, 0, 1)])
        self.near = np.unique((cells[:, None] + steps[None, :]).ravel())
        s = self.span
        self.centres = self.origin + (np.stack([cells // (s * s), cells // s % s, cells % s], axis=1) - 2 + 0.5) \
            * self.cell

    def key(self, cells):
        c = np.clip(cells + 2, 0, self.span - 1)
        return (c[:, 0] * self.span + c[:, 1]) * self.span + c[:, 2]

    def mirror_share(self, normal, offset):
        """The share of the occupied cells whose mirror image is in or beside an occupied cell."""
        images = np.floor((mirror(self.centres, normal, offset) - self.origin) / self.cell).astype(np.int64)
        keys = self.key(images)
        where = np.minimum(np.searchsorted(self.near, keys), len(self.near) - 1)
        return float(np.mean(self.near[where] == keys)) if len(keys) else 0.0


def find_mirror_plane(joints, vertices):
    """The character's mirror plane (unit normal, offset): among the planes x, y, z = const
    and the vertices' principal planes, through the middle of their box or the joints'
    median, the one across which the mesh is most symmetric (its surface cells' mirror
    images on its surface), if at least MIRROR_SHARE of them are; x = const (Blender's
    X-mirror) wins when it is as good within 0.02. None for a mesh that is not symmetric."""
    sample = vertices[:: max(1, len(vertices) // 8000)]
    centre = 0.5 * (vertices.min(axis=0) + vertices.max(axis=0))
    _, _, axes = np.linalg.svd(sample - sample.mean(axis=0), full_matrices=False)
    candidates = [np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), np.array([0, 0, 1.0])] + list(axes)
    cells = SurfaceCells(sample)
    normals = []
    for normal in candidates:
        normal = normal / np.linalg.norm(normal)
        if normal[np.argmax(np.abs(normal))] < 0:
            normal = -normal  # the positive side is the left (+X, as Blender names it)
        if all(abs(normal @ other) < 0.9999 for other in normals):  # a principal axis along x, y or z
            normals.append(normal)
    scored = [(cells.mirror_share(n, centre @ n), n, centre @ n) for n in normals]
    # Through the joints' median too, for the two best normals (a raised arm moves the box).
    for _, normal, _ in sorted(scored, key=lambda s: -s[0])[:2]:
        offset = float(np.median(joints @ normal))
        scored.append((cells.mirror_share(normal, offset), normal, offset))
    best = max(scored, key=lambda s: s[0])
    x_planes = [s for s in scored if abs(s[1][0]) > 0.9999 and s[0] >= best[0] - 0.02]
    share, normal, offset = max(x_planes, key=lambda s: s[0]) if x_planes else best
    return (normal, offset) if share >= MIRROR_SHARE else None


def resample(polyline, count=16):
    """`count` points at equal steps of arc length along the polyline (a few joints: plain
    Python, which is faster than numpy's calls on such small arrays)."""
    points = [tuple(p) for p in polyline.tolist()]
    along = [0.0]
    for p, q in zip(points, points[1:]):
        along.append(along[-1] + ((q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2 + (q[2] - p[2]) ** 2) ** 0.5)
    total, out, segment = along[-1], [], 0
    for step in range(count):
        target = total * step / (count - 1)
        while segment < len(points) - 2 and along[segment + 1] < target:
            segment += 1
        length = along[segment + 1] - along[segment] if len(points) > 1 else 0.0
        t = (target - along[segment]) / length if length > 0 else 0.0
        p, q = points[segment], points[min(segment + 1, len(points) - 1)]
        out.append((p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2])))
    return np.array(out)


def pair_chains(chains, joints, plane, tolerance):
    """Sets side ".L"/".R" and partner on chains that are each other's mirror images: the
    mirrored polyline of one within the tolerance of the other at every step of arc length
    (the voxel grid may give the two sides a different number of joints), +normal being the
    left. Chains on the plane are central."""
    if plane is None:
        return
    normal, offset = plane
    images = mirror(joints, normal, offset)
    mirrored = np.array([resample(images[c.joints]) for c in chains])
    own = np.array([resample(joints[c.joints]) for c in chains])
    # errors[a, b]: the largest gap between chain a's mirror image and chain b; pairs with
    # equal numbers of joints first (then every bone has its mirror).
    errors = np.sqrt(np.sum((mirrored[:, None] - own[None, :]) ** 2, axis=3)).max(axis=2)
    counts = np.array([len(c.joints) for c in chains])
    errors = (errors * np.where(counts[:, None] == counts[None, :], 1.0, 1.5)).tolist()
    for a, chain in enumerate(chains):
        if chain.partner is not None:
            continue
        signed = joints[chain.joints[1:]] @ normal - offset
        if np.all(np.abs(signed) <= tolerance):
            continue  # on the plane: a central chain
        best, best_error = None, tolerance
        for b, other in enumerate(chains):
            if b != a and other.partner is None and errors[a][b] <= best_error:
                best, best_error = b, errors[a][b]
        if best is not None:
            left = np.mean(signed) > 0
            chain.partner, chains[best].partner = best, a
            chain.side, chains[best].side = (".L", ".R") if left else (".R", ".L")


def label_chains(chains, joints, radii, vertices, up, plane, children):
    """A label per chain from where it goes relative to the up axis and the mirror plane:
    leg (down to the lowest quarter), arm (a side chain going sideways), spine (up or along
    the body, with more chains after it), head (a central end chain going up, or a thick one
    not going down), tail (a thin central end chain); chain_N otherwise."""
    heights = vertices @ up
    bottom, height = heights.min(), max(heights.max() - heights.min(), 1e-12)
    thickest = max(radii.max(), 1e-12)
    for i, chain in enumerate(chains):
        start, end = joints[chain.joints[0]], joints[chain.joints[-1]]
        direction = end - start
        length = np.linalg.norm(direction)
        rise = (direction @ up) / length if length > 0 else 0.0
        reaches_ground = (end @ up - bottom) < 0.25 * height
        is_end = not children[chain.joints[-1]]
        thickness = np.mean(radii[chain.joints[1:]]) / thickest
        sideways = plane is not None and length > 0 and abs(direction @ plane[0]) / length > STEEP
        label = None
        if rise < -STEEP and reaches_ground:
            label = "leg"
        elif chain.side:
            label = "arm" if sideways else None
        elif not is_end and rise > -STEEP:
            label = "spine"
        elif is_end and rise > STEEP:
            label = "head"
        elif is_end and thickness < 0.35:
            label = "tail"
        elif is_end and rise >= -STEEP:
            label = "head"
        chain.label = label
    # Labels taken once per side: the others are numbered (leg, leg_2, ...), neutral ones too.
    used, counters = set(), {}
    for i, chain in enumerate(chains):
        if chain.partner is not None and chain.partner < i:
            chain.label = chains[chain.partner].label
            continue
        base = chain.label or "chain"
        counters[base] = counters.get(base, 0) + 1
        label = base if chain.label and counters[base] == 1 else "%s_%d" % (base, counters[base])
        while label in used:
            counters[base] += 1
            label = "%s_%d" % (base, counters[base])
        used.add(label)
        chain.label = label


def bone_names(chains, bone_count):
    names = [None] * bone_count
    for chain in chains:
        for k, bone in enumerate(chain.bones):
            number = "" if len(chain.bones) == 1 else "_%02d" % (k + 1)
            names[bone] = chain.label + number + chain.side
    return names


def distance_to_segment(point, a, b):
    ab = b - a
    t = 0.0 if not ab @ ab else np.clip((point - a) @ ab / (ab @ ab), 0.0, 1.0)
    return np.linalg.norm(point - (a + t * ab))


def bone_parents(chains, joints, parents, bones, radii):
    """For each bone, (parent bone or -1, connected): along a chain and across a junction the
    bone ending at its head joint, connected; the bones leaving a root hang from the first
    bone of the root's thickest chain (the spine or hips), unconnected; the root bone of each
    further piece hangs from the nearest bone of the largest piece, unconnected."""
    bone_ending_at = {c: b for b, (p, c) in enumerate(bones)}
    result = [(-1, False)] * len(bones)
    for b, (p, c) in enumerate(bones):
        if p in bone_ending_at:
            result[b] = (bone_ending_at[p], True)
    roots = [j for j, p in enumerate(parents) if p < 0]
    piece_roots = {}
    for chain in chains:
        if chain.joints[0] in roots:
            piece_roots.setdefault(chain.joints[0], []).append(chain)
    top_bones = {}
    for root, root_chains in piece_roots.items():
        main = max(root_chains, key=lambda ch: (ch.label.startswith("spine"), np.mean(radii[ch.joints[1:]])))
        top_bones[root] = main.bones[0]
        for chain in root_chains:
            if chain is not main:
                result[chain.bones[0]] = (main.bones[0], False)
    if len(top_bones) > 1:
        piece = {}
        for j in range(len(parents)):
            r = j
            while parents[r] >= 0:
                r = parents[r]
            piece[j] = r
        sizes = {r: sum(1 for j in piece if piece[j] == r) for r in top_bones}
        largest = max(top_bones, key=lambda r: sizes[r])
        main_bones = [b for b, (p, c) in enumerate(bones) if piece[c] == largest]
        for root, top in top_bones.items():
            if root == largest:
                continue
            nearest = min(main_bones, key=lambda b: distance_to_segment(joints[root], joints[bones[b][0]],
                                                                           joints[bones[b][1]]))
            result[top] = (nearest, False)
    return result


class Layout:
    """Names, parents and the mirror plane of a control skeleton in world space."""

    def __init__(self, control, vertices, up=(0.0, 0.0, 1.0)):
        joints = control["joints"]
        self.positions = np.array([j["position"] for j in joints], dtype=np.float64)
        self.radii = np.array([j["radius"] for j in joints], dtype=np.float64)
        self.parents = [int(j["parent"]) for j in joints]
        self.bones = [tuple(b) for b in control["bones"]]
        self.up = np.asarray(up, dtype=np.float64)
        extent = vertices.max(axis=0) - vertices.min(axis=0)
        self.tolerance = MIRROR_TOLERANCE * max(float(extent.max()), 1e-12)
        self.plane = find_mirror_plane(self.positions, vertices)
        self.chains = split_into_chains(self.parents, self.bones)
        pair_chains(self.chains, self.positions, self.plane, self.tolerance)
        label_chains(self.chains, self.positions, self.radii, vertices, self.up, self.plane,
                     children_of(self.parents))
        self.names = bone_names(self.chains, len(self.bones))
        self.parent_of_bone = bone_parents(self.chains, self.positions, self.parents, self.bones, self.radii)


def symmetric_control(layout):
    """The control skeleton made mirror-symmetric across the layout's plane, for `skeletonize
    --skeleton`: each left/right pair of chains becomes the mirror images of one chain (the
    average of the two sides when they have as many joints, else the side with more), the
    joints near the plane are moved onto it; None when the layout has no pair. Chains keep
    their order, so a chain's start joint exists when it is reached."""
    if layout.plane is None or not any(c.side for c in layout.chains):
        return None
    normal, offset = layout.plane
    positions, radii = layout.positions, layout.radii
    images = mirror(positions, normal, offset)

    def on_plane(points):
        distance = points @ normal - offset
        near = np.abs(distance) <= layout.tolerance
        return np.where(near[:, None], points - np.outer(distance, normal), points)

    new_positions, new_radii, new_parents = [], [], []
    new_of = {}  # original joint -> new joint, for the joints that chains start from
    for root in [j for j, p in enumerate(layout.parents) if p < 0]:
        new_of[root] = len(new_positions)
        new_positions.append(on_plane(positions[[root]])[0])
        new_radii.append(radii[root])
        new_parents.append(-1)
    for chain in layout.chains:
        tail = chain.joints[1:]
        if chain.partner is None:
            points, chain_radii = on_plane(positions[tail]), radii[tail]
        else:
            other = layout.chains[chain.partner]
            other_tail = other.joints[1:]
            if len(other_tail) == len(tail):
                points = 0.5 * (positions[tail] + images[other_tail])
                chain_radii = 0.5 * (radii[tail] + radii[other_tail])
            elif len(tail) > len(other_tail):
                points, chain_radii = positions[tail], radii[tail]
            else:
                points, chain_radii = images[other_tail], radii[other_tail]
        parent = new_of[chain.joints[0]]
        for point, radius in zip(points, chain_radii):
            new_positions.append(point)
            new_radii.append(radius)
            new_parents.append(parent)
            parent = len(new_positions) - 1
        new_of[chain.joints[-1]] = parent
    joints = [{"position": [float(c) for c in p], "radius": float(r), "parent": int(q)}
              for p, r, q in zip(new_positions, new_radii, new_parents)]
    bones = [[q, j] for j, q in enumerate(new_parents) if q >= 0]
    return {"joints": joints, "bones": bones}
