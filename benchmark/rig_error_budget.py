#!/usr/bin/python3
"""Where our rigs' distance to the artists' rigs comes from, and how much a rule could win.

    rig_error_budget.py DATA SPLIT OUT [--first N]

OUT is the folder of skeletonize's JSON files that `rig_benchmark.py ... --out OUT` wrote for
the split (DATA and SPLIT as there). Everything is in units of the mesh's largest extent, as
in rig_benchmark.py. Prints means over the characters:

- the two halves of CD-J2J: from our joints to the artists' and back;
- the first half by the kind of our joint (the root, the ends, the joints along chains,
  the junctions) and by its distance to the artists' bones (under 0.02: on an artist's
  chain; 0.02 to 0.08; over 0.08: off every chain): the joints per character and their
  part of the half;
- the end chains of our rig (from an end joint to the first junction, the junction left out)
  that are *extra*: every joint farther than 0.05 from every artist bone. Their share of our
  joints and of the first half;
- the artists' joints that are *missing*: from an end of the artist's rig inwards, while
  farther than 0.05 from every bone of ours. Their share and their part of the second half;
- two bounds, what a rule that knew the artists' rig would reach: every extra chain dropped,
  and every end chain trimmed from its tip while its joints are farther than 0.05 from the
  artist's bones (CD-J2J, CD-B2B, joints);
- how well a chain's own measures tell an extra chain from the others (the area under the ROC
  curve: 0.5 is chance, 1 or 0 a perfect split): its length, its mean MAT radius over the
  largest of the rig, its joints, the junctions between it and the root, the end chains of
  the rig;
- what simple rules built on those measures give: dropping the end chains thinner than a
  fraction of the largest radius, or shorter than a fraction of the extent, or that leave a
  junction 3 or more junctions deep; trimming the joints of a tip thinner than a fraction of
  the largest radius;
- the tail: how much of the mean CD-J2J the 10, 20 and 30 worst characters carry, the mean
  without them, and the 20 worst with their CD-J2J.
"""
import collections
import json
import os
import sys

import numpy as np

import rig_benchmark as rb


def our_tree(json_path):
    """Joint positions, bones, MAT radii and parents of skeletonize's control skeleton."""
    control = json.load(open(json_path))['control']
    positions, bones = rb.rig_of_control(control)
    joints = control['joints']
    return positions, bones, np.array([j['radius'] for j in joints], float), [j['parent'] for j in joints]


def neighbours(count, bones):
    adjacent = collections.defaultdict(list)
    for a, b in bones:
        adjacent[a].append(b)
        adjacent[b].append(a)
    return [adjacent[k] for k in range(count)]


def end_chains(count, bones):
    """(joints from the end inwards, the junction it leaves or None) for each end joint."""
    adjacent = neighbours(count, bones)
    chains = []
    for end in range(count):
        if len(adjacent[end]) != 1:
            continue
        path, previous, current, junction = [end], -1, end, None
        while True:
            following = [x for x in adjacent[current] if x != previous]
            if not following:
                break
            previous, current = current, following[0]
            if len(adjacent[current]) > 2:
                junction = current
                break
            path.append(current)
        chains.append((path, junction))
    return chains


JOINT_KINDS = ('root', 'end', 'chain', 'junction')
BAND_EDGES = (0.02, 0.08)  # distance to the artists' bones: on their chain, near, off every chain
BANDS = ('<0.02', '0.02-0.08', '>0.08')


def joint_kind(parent, degree):
    """The root, an end (one bone), a joint along a chain (two) or a junction (three or more)."""
    if parent < 0:
        return 'root'
    return 'end' if degree == 1 else 'chain' if degree == 2 else 'junction'


def junction_depth(parents, adjacent, joint):
    """The junctions (and the root) on the way from `joint` to the root, `joint` included."""
    depth = 0
    while joint >= 0:
        if len(adjacent[joint]) > 2 or parents[joint] < 0:
            depth += 1
        joint = parents[joint]
    return depth


def leading_count(flags):
    """How many of `flags` are true before the first false one."""
    return int(np.argmin(np.append(np.asarray(flags, bool), False)))


def without(positions, bones, dropped):
    kept = [k for k in range(len(positions)) if k not in dropped]
    index = {k: i for i, k in enumerate(kept)}
    return positions[kept], [(index[a], index[b]) for a, b in bones if a in index and b in index]


def character(data, split, out, i):
    scale = 1.0 / rb.mesh_extent(os.path.join(data, split, i + '.obj'))
    positions, bones, radii, parents = our_tree(os.path.join(out, i + '.json'))
    artist_joints, artist_bones = rb.artist_rig(os.path.join(data, split, i + '_rig.txt'))
    return positions * scale, bones, radii * scale, parents, artist_joints * scale, artist_bones


def missing_artist_joints(artist_joints, artist_bones, near_ours):
    """Artist joints from each artist end inwards while farther than LIMB_DISTANCE from our bones."""
    missing = np.zeros(len(artist_joints), bool)
    for path, _ in end_chains(len(artist_joints), artist_bones):
        for k in path:
            if near_ours[k] <= rb.LIMB_DISTANCE:
                break
            missing[k] = True
    return missing


def auc(scores, labels):
    """Area under the ROC curve of `scores` for `labels` (ties count a half)."""
    scores, labels = np.asarray(scores, float), np.asarray(labels, bool)
    order = np.argsort(scores, kind='mergesort')
    ranks = np.empty(len(scores))
    sorted_scores = scores[order]
    start = 0
    while start < len(scores):
        stop = start
        while stop + 1 < len(scores) and sorted_scores[stop + 1] == sorted_scores[start]:
            stop += 1
        ranks[order[start:stop + 1]] = 0.5 * (start + stop) + 1
        start = stop + 1
    positives, negatives = labels.sum(), (~labels).sum()
    return (ranks[labels].sum() - positives * (positives + 1) / 2) / (positives * negatives)


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    data, split, out = argv[:3]
    ids = [line.strip() for line in open(os.path.join(data, split + '_final.txt')) if line.strip()]
    if '--first' in argv:
        ids = ids[:int(argv[argv.index('--first') + 1])]

    rules = {'as rigged': lambda chain: []}
    for t in (0.15, 0.2, 0.25):
        rules['drop end chains of mean radius < %.2f R' % t] = (
            lambda chain, t=t: chain['path'] if chain['mean_radius'] < t * chain['largest_radius'] else [])
    for t in (0.05, 0.1):
        rules['drop end chains shorter than %.2f' % t] = lambda chain, t=t: chain['path'] if chain['length'] < t else []
    rules['drop end chains 3+ junctions deep'] = lambda chain: chain['path'] if chain['depth'] >= 3 else []
    for t in (0.1, 0.12, 0.15, 0.2):
        rules['trim tip joints of radius < %.2f R' % t] = (
            lambda chain, t=t: chain['path'][:leading_count(chain['radii'] < t * chain['largest_radius'])])
    rules['bound: extra chains dropped'] = lambda chain: chain['path'] if chain['extra'] else []
    rules['bound: end chains trimmed'] = lambda chain: chain['path'][:chain['far_tip_joints']]

    halves, extra_share, extra_part, missing_share, missing_part = [], [], [], [], []
    by_kind = collections.defaultdict(lambda: np.zeros(2))  # (joints, part of the first half) summed
    features, labels = collections.defaultdict(list), []
    results = collections.defaultdict(list)
    rigged = []
    for i in ids:
        positions, bones, radii, parents, artist_joints, artist_bones = character(data, split, out, i)
        if len(positions) == 0:
            continue
        rigged.append(i)
        a0, a1 = rb.segments(artist_joints, artist_bones)
        o0, o1 = rb.segments(positions, bones)
        ours_to_artists = rb.distances_to_points(positions, artist_joints)
        artists_to_ours = rb.distances_to_points(artist_joints, positions)
        halves.append((ours_to_artists.mean(), artists_to_ours.mean()))
        near_artists = rb.distances_to_segments(positions, a0, a1)
        missing = missing_artist_joints(artist_joints, artist_bones, rb.distances_to_segments(artist_joints, o0, o1))
        missing_share.append(missing.mean())
        missing_part.append(0.5 * artists_to_ours[missing].sum() / len(artist_joints))

        adjacent = neighbours(len(positions), bones)
        for k in range(len(positions)):
            kind = joint_kind(parents[k], len(adjacent[k]))
            band = BANDS[np.searchsorted(BAND_EDGES, near_artists[k], side='right')]
            by_kind[(kind, band)] += (1.0, ours_to_artists[k] / len(positions))
        chains = []
        for path, junction in end_chains(len(positions), bones):
            if junction is None:
                continue
            far = near_artists[path] > rb.LIMB_DISTANCE
            points = positions[path + [junction]]
            chains.append({
                'path': path, 'radii': radii[path], 'mean_radius': radii[path].mean(),
                'largest_radius': radii.max(), 'depth': junction_depth(parents, adjacent, junction),
                'extra': bool(far.all()), 'far_tip_joints': leading_count(far),
                'length': np.linalg.norm(np.diff(points, axis=0), axis=1).sum()})
        on_extra = np.zeros(len(positions), bool)
        for chain in chains:
            on_extra[chain['path']] |= chain['extra']
            labels.append(chain['extra'])
            features['length'].append(chain['length'])
            features['mean radius / largest'].append(chain['mean_radius'] / chain['largest_radius'])
            features['joints'].append(len(chain['path']))
            features['junction depth'].append(chain['depth'])
            features['end chains of the rig'].append(len(chains))
        extra_share.append(on_extra.mean())
        extra_part.append(0.5 * ours_to_artists[on_extra].sum() / len(positions))

        for name, rule in rules.items():
            dropped = set()
            for chain in chains:
                dropped.update(rule(chain))
            kept = without(positions, bones, dropped)
            if len(kept[0]) == 0:
                kept = (positions, bones)
            m = rb.measures(kept, (artist_joints, artist_bones))
            results[name].append((m['cd_j2j'], m['cd_b2b'], m['joints']))

    halves = np.array(halves)
    print('%d characters of %s' % (len(halves), split))
    print('CD-J2J %.4f = (ours to the artists\' %.4f + the artists\' to ours %.4f) / 2'
          % (halves.mean(0).sum() / 2, halves[:, 0].mean(), halves[:, 1].mean()))
    print('ours to the artists\' by our joint\'s kind and its distance to the artists\' bones'
          ' (joints per character, part of the half):')
    for kind in JOINT_KINDS:
        print('  %-9s' % kind + ''.join('  %s %4.1f %.4f' % (band, *(by_kind[(kind, band)] / len(halves)))
                                     for band in BANDS))
    print('our joints on extra end chains: %.3f of them, %.4f of CD-J2J'
          % (np.mean(extra_share), np.mean(extra_part)))
    print('artists\' joints missing from their ends inwards: %.3f of them, %.4f of CD-J2J'
          % (np.mean(missing_share), np.mean(missing_part)))
    print('end chains: %d, extra: %.3f' % (len(labels), np.mean(labels)))
    for name, values in features.items():
        print('  AUC of %-24s %.3f' % (name, auc(values, labels)))
    print('%-42s %8s %8s %8s %7s' % ('rig', 'J2J mean', 'median', 'B2B mean', 'joints'))
    for name, values in results.items():
        values = np.array(values)
        print('%-42s %8.4f %8.4f %8.4f %7d' % (name, values[:, 0].mean(), np.median(values[:, 0]),
                                                values[:, 1].mean(), np.median(values[:, 2])))
    print_tail(rigged, np.array(results['as rigged'])[:, 0])


def print_tail(ids, cd_j2j):
    """How much of the mean CD-J2J the worst characters carry, and which they are."""
    worst = np.argsort(-cd_j2j, kind='stable')
    for count in (10, 20, 30):
        print('the %d worst characters: CD-J2J %.4f on average, %.3f of the sum; the mean without them %.4f'
              % (count, cd_j2j[worst[:count]].mean(), cd_j2j[worst[:count]].sum() / cd_j2j.sum(),
                 cd_j2j[worst[count:]].mean()))
    print('the 20 worst: ' + ' '.join('%s %.3f' % (ids[k], cd_j2j[k]) for k in worst[:20]))


if __name__ == '__main__':
    main(sys.argv[1:])
