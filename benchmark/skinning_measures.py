"""Skin weights against the artists': the measures of rig_benchmark.py --skinning.

With the artist's skeleton given, the weights of a method are compared per vertex with the
artist's (RigNet rig files: `skin V NAME w ...`). A weight on joint J means the vertex follows
J's transform, the bones that start at J; so a weight on bone P -> C is a weight on joint P,
and the artist's weights on leaf joints (which start no bone) are folded into their parents,
for every method alike. Distances are in units of the mesh's largest extent.
"""
import json

import numpy as np

INFLUENCE = 1e-4     # a joint influences a vertex when its weight is above this
POSES = 10           # random poses of the deformation measure
POSE_ANGLE = 15.0    # each joint turns about a random axis by up to this many degrees
POSE_SEED = 2026
FAR_IN_JOINTS = 3    # a vertex whose top joint is this many bones or more from the artist's


class ArtistRig:
    """The joints, parents and skin weights of a RigNet rig file."""

    def __init__(self, rig_path, vertices):
        names, positions, parent_name, skin = [], [], {}, []
        with open(rig_path) as f:
            for line in f:
                words = line.split()
                if not words:
                    continue
                if words[0] == 'joints':
                    names.append(words[1])
                    positions.append([float(x) for x in words[2:5]])
                elif words[0] == 'hier':
                    parent_name[words[2]] = words[1]
                elif words[0] == 'skin':
                    skin.append(words[1:])
        index = {name: i for i, name in enumerate(names)}
        self.names = names
        self.positions = np.array(positions, float).reshape(-1, 3)
        self.parent = np.array([index[parent_name[n]] if n in parent_name else -1 for n in names], int)
        has_child = np.zeros(len(names), bool)
        has_child[self.parent[self.parent >= 0]] = True
        # The joint whose transform a weight on joint j applies: j, or its parent for a leaf.
        self.owner = np.array([j if has_child[j] or self.parent[j] < 0 else self.parent[j]
                               for j in range(len(names))], int)
        self.weights = np.zeros((vertices, len(names)))
        for words in skin if vertices else []:
            v = int(words[0])
            for name, w in zip(words[1::2], words[2::2]):
                self.weights[v, self.owner[index[name]]] += float(w)
        self.hops = self._hops()

    def bones(self):
        """[parent, child] per joint with a parent, in joint order."""
        return [[int(p), c] for c, p in enumerate(self.parent) if p >= 0]

    def skeleton_json(self):
        return {'joints': [{'position': list(map(float, p)), 'parent': int(q)}
                           for p, q in zip(self.positions, self.parent)],
                'bones': self.bones()}

    def _hops(self):
        """Bones between every two joints (the tree distance)."""
        n = len(self.parent)
        neighbours = [[] for _ in range(n)]
        for p, c in self.bones():
            neighbours[p].append(c)
            neighbours[c].append(p)
        hops = np.full((n, n), n, int)
        for s in range(n):
            hops[s, s] = 0
            frontier = [s]
            while frontier:
                nxt = []
                for u in frontier:
                    for w in neighbours[u]:
                        if hops[s, w] > hops[s, u] + 1:
                            hops[s, w] = hops[s, u] + 1
                            nxt.append(w)
                frontier = nxt
        return hops


def weights_from_bones(report_path, rig):
    """Per vertex and joint, the weights of a skeletonize --skeleton --weights report."""
    report = json.load(open(report_path))
    w = report['weights']
    bones = report['control']['bones']
    weights = np.zeros((w['vertices'], len(rig.names)))
    joint_of_bone = np.array([b[0] for b in bones], int)
    np.add.at(weights, (np.array(w['vertex'], int), rig.owner[joint_of_bone[np.array(w['bone'], int)]]),
              np.array(w['weight'], float))
    return weights, report['skinning']['milliseconds']


def nearest_bone_weights(vertices, rig):
    """Weight 1 on the joint of the bone nearest in straight line: the floor every method should beat."""
    bones = np.array(rig.bones(), int)
    a, b = rig.positions[bones[:, 0]], rig.positions[bones[:, 1]]
    d = b - a
    dd = np.maximum((d * d).sum(-1), 1e-30)
    best = np.full(len(vertices), np.inf)
    owner = np.zeros(len(vertices), int)
    for i in range(len(bones)):
        t = np.clip(((vertices - a[i]) * d[i]).sum(-1) / dd[i], 0.0, 1.0)
        dist = np.linalg.norm(vertices - (a[i] + t[:, None] * d[i]), axis=1)
        closer = dist < best
        best[closer] = dist[closer]
        owner[closer] = rig.owner[bones[i, 0]]
    weights = np.zeros((len(vertices), len(rig.names)))
    weights[np.arange(len(vertices)), owner] = 1.0
    return weights


def random_rotations(count, rng):
    axes = rng.normal(size=(count, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    angles = np.radians(rng.uniform(-POSE_ANGLE, POSE_ANGLE, count))
    k = np.zeros((count, 3, 3))
    k[:, 0, 1], k[:, 0, 2], k[:, 1, 2] = -axes[:, 2], axes[:, 1], -axes[:, 0]
    k -= k.transpose(0, 2, 1)
    s, c = np.sin(angles)[:, None, None], np.cos(angles)[:, None, None]
    return np.eye(3)[None] + s * k + (1 - c) * (k @ k)


def pose_transforms(rig, rng):
    """The world transform (rotation, translation) of every joint in a random pose."""
    n = len(rig.names)
    local = random_rotations(n, rng)
    rotation, translation = np.zeros((n, 3, 3)), np.zeros((n, 3))
    done = np.zeros(n, bool)

    def solve(j):
        if done[j]:
            return
        p = rig.parent[j]
        # The joint turns about its own position, after its parent's transform.
        r_local, t_local = local[j], rig.positions[j] - local[j] @ rig.positions[j]
        if p >= 0:
            solve(p)
            rotation[j] = rotation[p] @ r_local
            translation[j] = rotation[p] @ t_local + translation[p]
        else:
            rotation[j], translation[j] = r_local, t_local
        done[j] = True

    for j in range(n):
        solve(j)
    return rotation, translation


def skinned(vertices, weights, rotation, translation):
    total = weights.sum(1, keepdims=True)
    w = weights / np.where(total > 0, total, 1.0)
    moved = np.einsum('jab,vb->vja', rotation, vertices) + translation[None]
    return np.einsum('vj,vja->va', w, moved)


def measures(vertices, scale, rig, weights):
    """The measures of one method's weights on one character (None for weights of a failure)."""
    artist = rig.weights
    bound = weights.sum(1) > 0
    ours_set, artist_set = weights > INFLUENCE, artist > INFLUENCE
    both = (ours_set & artist_set).sum(1)
    norm = weights / np.where(bound, weights.sum(1), 1.0)[:, None]
    top_ours, top_artist = norm.argmax(1), artist.argmax(1)
    rng = np.random.default_rng(POSE_SEED)
    average, largest = [], 0.0
    for _ in range(POSES):
        rotation, translation = pose_transforms(rig, rng)
        gap = np.linalg.norm(skinned(vertices, norm, rotation, translation) -
                             skinned(vertices, artist, rotation, translation), axis=1)[bound] * scale
        if gap.size:
            average.append(gap.mean())
            largest = max(largest, gap.max())
    return {
        'precision': float((both / np.maximum(ours_set.sum(1), 1))[bound].mean()) if bound.any() else 0.0,
        'recall': float((both / np.maximum(artist_set.sum(1), 1))[bound].mean()) if bound.any() else 0.0,
        'l1': float(np.abs(norm - artist).sum(1)[bound].mean()) if bound.any() else 2.0,
        'top_joint': float((top_ours == top_artist)[bound].mean()) if bound.any() else 0.0,
        'far_top_joint': float((rig.hops[top_ours, top_artist] >= FAR_IN_JOINTS)[bound].mean()) if bound.any() else 1.0,
        'deformation_average': float(np.mean(average)) if average else float('nan'),
        'deformation_max': float(largest),
        'bones_per_vertex': float(ours_set.sum(1)[bound].mean()) if bound.any() else 0.0,
        'top_weight': float(norm.max(1)[bound].mean()) if bound.any() else 0.0,
        'unweighted': int((~bound).sum()),
    }


KEYS = ['precision', 'recall', 'l1', 'top_joint', 'far_top_joint', 'deformation_average', 'deformation_max',
        'bones_per_vertex', 'top_weight', 'milliseconds']
