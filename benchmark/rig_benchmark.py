#!/usr/bin/python3
"""Rig benchmark: our rigs against artists' rigs.

    rig_benchmark.py SKELETONIZE DATA SPLIT [--out DIR] [--threads N] [--rows] [--also-at RESOLUTION]
                     [-- skeletonize options]

DATA is a folder as ../shared/rigs/convert.sh writes it: DATA/SPLIT_final.txt lists the
characters, DATA/SPLIT/ID.obj is a mesh and DATA/SPLIT/ID_rig.txt its artist's rig in the
RigNet format (lines `joints NAME x y z`, `root NAME`, `hier PARENT CHILD`; `skin` lines are
not read here). SKELETONIZE is the package's program; it rigs every mesh of the split in one
batch (--out DIR keeps its JSON files, a temporary folder otherwise).

Prints, over the characters (and per character with --rows), in units of the mesh's largest
axis-aligned extent:
  CD-J2J  half the sum of the mean distance from each of our joints to the nearest artist
          joint and the reverse;
  CD-J2B  the same from joints to the nearest bone (segment) of the other rig;
  CD-B2B  the same between points spaced 0.005 along the bones of both rigs;
the joint counts (ours, the artist's), the characters with fewer than 4 joints, and the limb
measures (is every limb reached?): the share of the artists' chain ends (leaf joints) within
0.1 of one of our bones (recall), the share of our chain ends within 0.1 of one of the
artists' bones (precision), the characters with an artist chain end farther than 0.15 from
all our bones (a limb without a bone), and the recall by the family of the artist's joint
name (foot/toe, hand, arm, leg, ear, tail, head, face: mouth, eyes, jaw, hair; other). A
rig without bones counts its joints as bones of length 0.

With --skinning, the skin weights are measured instead, with the artist's skeleton given
(`skeletonize MESH --skeleton SKELETON.json --weights`) and the artist's weights as the
reference (skinning_measures.py defines the measures): medians over the characters of the
precision and recall of the influencing joints, L1, the share of vertices whose top joint is
the artist's and of those whose top joint is 3 or more bones away, the average and largest
deformation over 10 random poses, bones per vertex, the largest weight, the time; for ours
and, in the same run, for the nearest-bone rule (the floor) and for Blender's bone heat when
--bone-heat DIR holds its outputs (ID.json, from ../shared/rigs/bone_heat_weights.py).
--scale S rigs the meshes scaled by S (the weights should not change). Each character is
skinned by its own process there, so its time includes the first touch of the memory it
needs; `-- --weights` without --skinning times the weights of our skeletons against the chain
in the same process (the time line printed last).

With --also-at RESOLUTION, the split is rigged again at that resolution, and the share of the
characters whose joint count there is within 25 % of the first run's is printed: which joints
a rig has should not depend on the grid.
"""
import concurrent.futures
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile

import numpy as np

import skinning_measures

LIMB_DISTANCE = 0.05  # an end joint this far from every bone of the other rig: a limb one rig lacks
LIMB_REACH = 0.1      # a chain end within this of the other rig's bones is reached (the limb measures)
LIMB_MISSED = 0.15    # an artist chain end farther than this from all our bones: a limb without a bone
# The families of the artists' leaf joint names, the first that matches (lower case, letters only).
LIMB_FAMILIES = [('face', 'mouth|eye|jaw|hair|kuchi|tongue|teeth|lip|brow|nose'),
                 ('foot/toe', 'toe|foot|feet|ankle'),
                 ('hand', 'hand|finger|thumb|index|middle|ring|pinky|wrist|yubi'),
                 ('ear', 'ear'), ('tail', 'tail'), ('head', 'head|neck'),
                 ('arm', 'arm|elbow|shoulder|clavicle'), ('leg', 'leg|knee|thigh|calf')]
SAMPLE_STEP = 0.005   # spacing of the points of CD-B2B


def mesh_extent(obj_path):
    lo = np.full(3, np.inf)
    hi = np.full(3, -np.inf)
    with open(obj_path) as f:
        for line in f:
            if line.startswith('v '):
                p = np.array([float(x) for x in line.split()[1:4]])
                lo = np.minimum(lo, p)
                hi = np.maximum(hi, p)
    return float((hi - lo).max())


def artist_rig(rig_path):
    """Joint positions (n x 3) and bones (pairs of joint indices) of a RigNet rig file."""
    positions, bones, _ = artist_rig_with_names(rig_path)
    return positions, bones


def artist_rig_with_names(rig_path):
    """artist_rig(), and the joints' names."""
    index, positions, bones = {}, [], []
    with open(rig_path) as f:
        for line in f:
            words = line.split()
            if words and words[0] == 'joints':
                index[words[1]] = len(positions)
                positions.append([float(x) for x in words[2:5]])
            elif words and words[0] == 'hier':
                bones.append((words[1], words[2]))
    return (np.array(positions, float).reshape(-1, 3), [(index[a], index[b]) for a, b in bones],
            sorted(index, key=index.get))


def limb_family(joint_name):
    letters = re.sub('[^a-z]', '', joint_name.lower())
    return next((family for family, pattern in LIMB_FAMILIES if re.search(pattern, letters)), 'other')


def our_rig(json_path):
    return rig_of_control(json.load(open(json_path))['control'])


def rig_of_control(control):
    """Joint positions (n x 3) and bones of skeletonize's "control" object."""
    positions = np.array([j['position'] for j in control['joints']], float).reshape(-1, 3)
    return positions, [tuple(b) for b in control['bones']]


def segments(joints, bones):
    if not bones:
        return joints, joints
    b = np.array(bones)
    return joints[b[:, 0]], joints[b[:, 1]]


def distances_to_points(p, q):
    return np.sqrt(((p[:, None, :] - q[None, :, :]) ** 2).sum(-1)).min(1)


def distances_to_segments(p, a, b):
    d = b - a
    dd = (d * d).sum(-1)
    t = ((p[:, None, :] - a[None]) * d[None]).sum(-1) / np.where(dd > 0, dd, 1.0)[None]
    t = np.clip(np.where(dd[None] > 0, t, 0.0), 0.0, 1.0)
    nearest = a[None] + t[..., None] * d[None]
    return np.sqrt(((p[:, None, :] - nearest) ** 2).sum(-1)).min(1)


def points_along(a, b, step):
    parts = []
    for p, q in zip(a, b):
        n = max(1, int(np.ceil(np.linalg.norm(q - p) / step)))
        parts.append(p + np.linspace(0.0, 1.0, n + 1)[:, None] * (q - p))
    return np.concatenate(parts)


def leaf_joint_mask(joints, bones):
    """The joints that are no bone's parent (bones go from parent to child)."""
    leaf = np.ones(len(joints), bool)
    for parent, _ in bones:
        leaf[parent] = False
    return leaf


def limb_measures(ours, our_ends, artists, artist_names):
    """Distances from the artist's leaf joints to our bones (with the leaves' name families) and
    from our end joints (a mask over our joints) to the artist's bones."""
    (oj, ob), (aj, ab) = ours, artists
    leaves = leaf_joint_mask(aj, ab)
    return {'artist_ends': distances_to_segments(aj[leaves], *segments(oj, ob)).tolist(),
            'artist_end_families': [limb_family(n) for n, leaf in zip(artist_names, leaves) if leaf],
            'our_ends': distances_to_segments(oj[our_ends], *segments(aj, ab)).tolist()}


def measures(ours, artists):
    (oj, ob), (aj, ab) = ours, artists
    o0, o1 = segments(oj, ob)
    a0, a1 = segments(aj, ab)
    op, ap = points_along(o0, o1, SAMPLE_STEP), points_along(a0, a1, SAMPLE_STEP)
    return {
        'cd_j2j': 0.5 * (distances_to_points(oj, aj).mean() + distances_to_points(aj, oj).mean()),
        'cd_j2b': 0.5 * (distances_to_segments(oj, a0, a1).mean() + distances_to_segments(aj, o0, o1).mean()),
        'cd_b2b': 0.5 * (distances_to_points(op, ap).mean() + distances_to_points(ap, op).mean()),
        'joints': len(oj), 'artist_joints': len(aj),
    }


def score(data, split, out, ids):
    rows = []
    for i in ids:
        mesh = os.path.join(data, split, i + '.obj')
        result = os.path.join(out, i + '.json')
        if not os.path.exists(result):
            rows.append({'id': i, 'failed': True})
            continue
        scale = 1.0 / mesh_extent(mesh)
        control = json.load(open(result))['control']
        oj, ob = rig_of_control(control)
        our_ends = np.array([j['kind'] == 'end' for j in control['joints']], bool)
        aj, ab, names = artist_rig_with_names(os.path.join(data, split, i + '_rig.txt'))
        if len(oj) == 0:
            rows.append({'id': i, 'failed': True})
            continue
        row = measures((oj * scale, ob), (aj * scale, ab))
        row.update(limb_measures((oj * scale, ob), our_ends, (aj * scale, ab), names))
        row['id'] = i
        rows.append(row)
    return rows


def summary(rows):
    good = [r for r in rows if not r.get('failed')]
    if not good:
        return '%d characters, none rigged' % len(rows)
    lines = ['%d characters, %d rigged, %d failed' % (len(rows), len(good), len(rows) - len(good))]
    for key in ['cd_j2j', 'cd_j2b', 'cd_b2b', 'joints', 'artist_joints']:
        values = [r[key] for r in good]
        lines.append('%-14s mean %.4f  median %.4f' % (key, statistics.mean(values), statistics.median(values)))
    lines.append('fewer than 4 joints: %d' % sum(r['joints'] < 4 for r in good))
    lines += limb_summary(good)
    return '\n'.join(lines)


def limb_summary(rows):
    artist_ends = np.concatenate([r['artist_ends'] for r in rows])
    families = np.concatenate([r['artist_end_families'] for r in rows])
    our_ends = np.concatenate([r['our_ends'] for r in rows])
    missed = sum(max(r['artist_ends'], default=0) > LIMB_MISSED for r in rows)
    lines = ['limbs: artists\' chain ends within %g of our bones %.1f %% (%d of %d); our chain ends within %g of '
             'the artists\' bones %.1f %% (%d of %d); characters with an artist chain end farther than %g: %d '
             '(%.1f %%)' % (LIMB_REACH, 100 * (artist_ends <= LIMB_REACH).mean(), (artist_ends <= LIMB_REACH).sum(),
                            len(artist_ends), LIMB_REACH, 100 * (our_ends <= LIMB_REACH).mean(),
                            (our_ends <= LIMB_REACH).sum(), len(our_ends), LIMB_MISSED, missed,
                            100.0 * missed / len(rows))]
    by_family = []
    for family in [f for f, _ in LIMB_FAMILIES] + ['other']:
        reached = artist_ends[families == family] <= LIMB_REACH
        if len(reached):
            by_family.append('%s %.1f %% (%d of %d)' % (family, 100 * reached.mean(), reached.sum(), len(reached)))
    lines.append('limbs reached by family: ' + ', '.join(by_family))
    return lines


def main(argv):
    if '--' in argv:
        options = argv[argv.index('--') + 1:]
        argv = argv[:argv.index('--')]
    else:
        options = []
    if len(argv) < 3:
        sys.exit(__doc__)
    skeletonize, data, split = argv[:3]
    rest = argv[3:]
    out = rest[rest.index('--out') + 1] if '--out' in rest else tempfile.mkdtemp(prefix='rig_benchmark_')
    threads = rest[rest.index('--threads') + 1] if '--threads' in rest else str(os.cpu_count() or 1)
    ids = [line.strip() for line in open(os.path.join(data, split + '_final.txt')) if line.strip()]
    if '--first' in rest:
        ids = ids[:int(rest[rest.index('--first') + 1])]
    if '--skinning' in rest:
        scale = float(rest[rest.index('--scale') + 1]) if '--scale' in rest else 1.0
        bone_heat = rest[rest.index('--bone-heat') + 1] if '--bone-heat' in rest else None
        skin_split(skeletonize, data, split, ids, out, int(threads), options, scale, bone_heat, '--rows' in rest)
        return
    rig_split(skeletonize, data, split, ids, out, threads, options)
    rows = score(data, split, out, ids)
    if '--rows' in rest:
        for r in rows:
            print(json.dumps(r))
    print(summary(rows))
    timing = weights_timing(out, ids)
    if timing:
        print(timing)
    if '--also-at' in rest:
        resolution = rest[rest.index('--also-at') + 1]
        other = os.path.join(out, 'at_' + resolution)
        rig_split(skeletonize, data, split, ids, other, threads, options + ['--resolution', resolution])
        print(resolution_stability(rows, other, resolution))


def rig_split(skeletonize, data, split, ids, out, threads, options):
    """Rigs the split's meshes into OUT/ID.json with one skeletonize batch."""
    os.makedirs(out, exist_ok=True)
    listing = os.path.join(out, 'meshes.txt')
    with open(listing, 'w') as f:
        f.write('\n'.join(os.path.abspath(os.path.join(data, split, i + '.obj')) for i in ids) + '\n')
    # The batch exits with 1 when a mesh failed (it counts as failed here), 2 on bad usage.
    run = subprocess.run([skeletonize, '--batch', listing, '-o', out, '--threads', threads] + options,
                         stdout=subprocess.DEVNULL, check=False)
    if run.returncode not in (0, 1):
        sys.exit('rig_benchmark: %s exited with %d' % (skeletonize, run.returncode))


def read_obj_vertices(path):
    with open(path) as f:
        return np.array([[float(x) for x in line.split()[1:4]] for line in f if line.startswith('v ')], float)


def skin_character(skeletonize, data, split, i, out, options, scale):
    """Skins one character to its artist's skeleton; the report's path, or None on failure."""
    mesh = os.path.join(data, split, i + '.obj')
    rig = skinning_measures.ArtistRig(os.path.join(data, split, i + '_rig.txt'), 0)
    skeleton = rig.skeleton_json()
    if scale != 1.0:
        scaled = os.path.join(out, i + '.obj')
        with open(mesh) as f, open(scaled, 'w') as g:
            for line in f:
                if line.startswith('v '):
                    g.write('v %.17g %.17g %.17g\n' % tuple(scale * float(x) for x in line.split()[1:4]))
                else:
                    g.write(line)
        mesh = scaled
        for joint in skeleton['joints']:
            joint['position'] = [scale * x for x in joint['position']]
    skeleton_path = os.path.join(out, i + '_skeleton.json')
    json.dump(skeleton, open(skeleton_path, 'w'))
    report = os.path.join(out, i + '_weights.json')
    run = subprocess.run([skeletonize, mesh, '--skeleton', skeleton_path, '--weights', '-o', report] + options,
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, check=False)
    return report if run.returncode == 0 else None


def bone_heat_weights(path, rig, vertices):
    """Per vertex and joint, the weights of a bone_heat_weights.py output (pairs [joint name, w])."""
    column = {name: rig.owner[j] for j, name in enumerate(rig.names)}
    weights = np.zeros((vertices, len(rig.names)))
    for v, pairs in enumerate(json.load(open(path))['weights']):
        for name, w in pairs:
            weights[v, column[name]] += w
    return weights


def skin_split(skeletonize, data, split, ids, out, threads, options, scale, bone_heat, print_rows):
    os.makedirs(out, exist_ok=True)
    with concurrent.futures.ThreadPoolExecutor(threads) as pool:
        reports = dict(zip(ids, pool.map(lambda i: skin_character(skeletonize, data, split, i, out, options, scale),
                                         ids)))
    methods = ['ours', 'nearest_bone', 'artist'] + (['bone_heat'] if bone_heat else [])
    rows = {m: [] for m in methods}
    failed = {m: 0 for m in methods}
    for i in ids:
        vertices = read_obj_vertices(os.path.join(data, split, i + '.obj'))
        rig = skinning_measures.ArtistRig(os.path.join(data, split, i + '_rig.txt'), len(vertices))
        extent = float((vertices.max(0) - vertices.min(0)).max())
        candidates = {'nearest_bone': (skinning_measures.nearest_bone_weights(vertices, rig), 0.0),
                      'artist': (rig.weights, 0.0)}
        if reports[i]:
            candidates['ours'] = skinning_measures.weights_from_bones(reports[i], rig)
        if bone_heat and os.path.exists(os.path.join(bone_heat, i + '.json')):
            heat = json.load(open(os.path.join(bone_heat, i + '.json')))
            candidates['bone_heat'] = (bone_heat_weights(os.path.join(bone_heat, i + '.json'), rig, len(vertices)),
                                       1000.0 * heat.get('seconds', 0.0))
        for m in methods:
            if m not in candidates or candidates[m][0].shape[0] != len(vertices) or not candidates[m][0].any():
                failed[m] += 1
                continue
            row = skinning_measures.measures(vertices, 1.0 / extent, rig, candidates[m][0])
            row['milliseconds'] = candidates[m][1]
            row['id'] = i
            failed[m] += row['unweighted'] == len(vertices)
            rows[m].append(row)
            if print_rows:
                print(m, json.dumps(row))
    print('%d characters, skinned to the artist\'s skeleton; medians over the characters' % len(ids))
    print('%-13s' % 'method' + ''.join('%11s' % k[:10] for k in skinning_measures.KEYS) + '  failed  unweighted')
    for m in methods:
        line = '%-13s' % m
        for k in skinning_measures.KEYS:
            values = [r[k] for r in rows[m] if not np.isnan(r[k])]
            line += '%11.4f' % statistics.median(values) if values else '%11s' % '-'
        line += '%8d %11d' % (failed[m], sum(r['unweighted'] for r in rows[m]))
        print(line)
    # The share of vertices bound 3 or more bones away is 0 on most characters: its median
    # hides the few where it is not.
    for m in methods:
        far = [r['far_top_joint'] for r in rows[m] if not np.isnan(r['far_top_joint'])]
        if far:
            print('%-13s mean share of vertices whose top joint is %d or more bones away: %.4f'
                  % (m, skinning_measures.FAR_IN_JOINTS, statistics.mean(far)))


def weights_timing(out, ids):
    """With `-- --weights`: the time of the weights of our skeleton against the chain's, each
    mesh's both in the same process of the batch (so that neither pays alone for memory the
    process has not touched yet); None without weights."""
    chain, weights = [], []
    for i in ids:
        path = os.path.join(out, i + '.json')
        timings = json.load(open(path)).get('timings_ms', {}) if os.path.exists(path) else {}
        if 'skinning_weights' in timings and timings.get('total', 0) > 0:
            chain.append(timings['total'])
            weights.append(timings['skinning_weights'])
    if not weights:
        return None
    ratios = [w / c for w, c in zip(weights, chain)]
    return ('weights of our skeletons: median %.2f ms against the chain\'s %.2f ms (%.2f times); '
            'median of the per-character ratios %.2f, %d of %d at most 1'
            % (statistics.median(weights), statistics.median(chain),
               statistics.median(weights) / statistics.median(chain), statistics.median(ratios),
               sum(r <= 1 for r in ratios), len(ratios)))


def resolution_stability(rows, other, resolution):
    stable, compared = 0, 0
    for r in rows:
        result = os.path.join(other, r['id'] + '.json')
        if r.get('failed') or not os.path.exists(result):
            continue
        joints = len(our_rig(result)[0])
        compared += 1
        stable += 0.75 <= joints / r['joints'] <= 1.25
    return 'joints at resolution %s within 25 %% of the first run\'s: %d of %d (%.1f %%)' % (
        resolution, stable, compared, 100.0 * stable / max(compared, 1))


if __name__ == '__main__':
    main(sys.argv[1:])
