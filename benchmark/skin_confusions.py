#!/usr/bin/python3
"""Which joints our skin weights confuse with the artists', by the artists' joint names.

    skin_confusions.py DATA SPLIT OUT [--top N]

OUT is the folder that `rig_benchmark.py ... SPLIT --skinning --out OUT` filled (each
character's ID_weights.json, skinned to the artist's skeleton); DATA and SPLIT as there. Over
all the vertices of the split, where the top joint of our weights is not the artist's, prints:

- the share of vertices one bone away, split into the two directions (the artist's joint
  is the parent of ours, or its child), by the kinds of the two joints: where a joint's
  boundary falls on the wrong side, and on which;
- the vertices three or more bones away (skinning_measures.FAR_IN_JOINTS), by the pair of
  joint names, with the character: the parts bound across the air or across a limb;
- the share of the vertices in detached pieces of the mesh (all but the largest set of
  faces connected by shared vertices), and the top joint right and three or more bones away
  there and in the largest piece.

A joint's kind is read from its name (finger, hand, forearm, ...; 'other' when the name says
nothing, as "joint12"): the artists name their joints in several conventions, so the kinds
are a guide, not a measure.
"""
import collections
import os
import re
import sys

import numpy as np

import rig_benchmark as rb
import skinning_measures as sm

# The first pattern that a lower-cased name matches gives its kind.
KINDS = [('finger|thumb|index|middle|ring|pinky|yubi', 'finger'), ('hand|palm|wrist|_te_', 'hand'),
         ('toe|tuma', 'toe'), ('foot|ankle|heel|asi', 'foot'), ('knee|calf|shin|lowerleg|hiza', 'shin'),
         ('thigh|upleg|leg|momo', 'thigh'), ('forearm|elbow|lowerarm|hiji', 'forearm'),
         ('upperarm|shoulder|arm|ude', 'upper arm'), ('clav|collar', 'clavicle'), ('neck', 'neck'),
         ('head', 'head'), ('jaw|eye|ear|hair|nose|mouth|tongue|teeth|brow|lip|beard', 'face or hair'),
         ('spine|chest|torso|waist|body|mune', 'spine'), ('pelvis|hip|root|center', 'pelvis'),
         ('tail', 'tail'), ('wing', 'wing')]


def kind_of(name):
    name = name.lower()
    for pattern, kind in KINDS:
        if re.search(pattern, name):
            return kind
    return 'other'


def read_obj_faces(path):
    """The faces of an OBJ file, as lists of 0-based vertex indices."""
    with open(path) as f:
        return [[int(corner.split('/')[0]) - 1 for corner in line.split()[1:]] for line in f if line.startswith('f ')]


def in_largest_piece(vertices, faces):
    """Per vertex, whether it is in the largest set of faces connected by shared vertices."""
    parent = list(range(vertices))

    def root(v):
        while parent[v] != v:
            parent[v] = parent[parent[v]]
            v = parent[v]
        return v

    for face in faces:
        for a, b in zip(face, face[1:]):
            ra, rb_ = root(a), root(b)
            if ra != rb_:
                parent[max(ra, rb_)] = min(ra, rb_)
    roots = np.array([root(v) for v in range(vertices)])
    largest = collections.Counter(roots.tolist()).most_common(1)[0][0]
    return roots == largest


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    data, split, out = argv[:3]
    top = int(argv[argv.index('--top') + 1]) if '--top' in argv else 20
    ids = [line.strip() for line in open(os.path.join(data, split + '_final.txt')) if line.strip()]
    one_away, far = collections.Counter(), collections.Counter()
    by_piece = collections.Counter()  # (in the largest piece, 'vertices' / 'right' / 'far')
    vertices = 0
    for i in ids:
        report = os.path.join(out, i + '_weights.json')
        if not os.path.exists(report):
            continue
        mesh = rb.read_obj_vertices(os.path.join(data, split, i + '.obj'))
        rig = sm.ArtistRig(os.path.join(data, split, i + '_rig.txt'), len(mesh))
        ours = sm.weights_from_bones(report, rig)[0]
        vertices += len(mesh)
        main_piece = in_largest_piece(len(mesh), read_obj_faces(os.path.join(data, split, i + '.obj')))
        for v, (artist, mine) in enumerate(zip(rig.weights.argmax(1), ours.argmax(1))):
            hops = rig.hops[artist][mine]
            piece = bool(main_piece[v])
            by_piece[(piece, 'vertices')] += 1
            by_piece[(piece, 'right')] += artist == mine
            by_piece[(piece, 'far')] += hops >= sm.FAR_IN_JOINTS
            if hops == 1:
                parent_is_artists = rig.parent[mine] == artist
                parent, child = (artist, mine) if parent_is_artists else (mine, artist)
                direction = 'the artist\'s is the parent' if parent_is_artists else 'the artist\'s is the child'
                one_away[(kind_of(rig.names[parent]), kind_of(rig.names[child]), direction)] += 1
            elif hops >= sm.FAR_IN_JOINTS:
                far[(i, rig.names[artist], rig.names[mine], int(hops))] += 1
    print('%d vertices; one bone away: %.4f (the artist\'s joint the parent of ours %.4f, the child %.4f)'
          % (vertices, sum(one_away.values()) / vertices,
             sum(v for k, v in one_away.items() if k[2].endswith('parent')) / vertices,
             sum(v for k, v in one_away.items() if k[2].endswith('child')) / vertices))
    print('%8s  %-14s %-14s %s' % ('share', 'parent', 'child', 'the two top joints'))
    for (parent, child, direction), count in one_away.most_common(top):
        print('%8.4f  %-14s %-14s %s' % (count / vertices, parent, child, direction))
    print('%d or more bones away: %.4f' % (sm.FAR_IN_JOINTS, sum(far.values()) / vertices))
    print('%8s  %-8s %-20s %-20s %s' % ('vertices', 'id', 'artist\'s joint', 'ours', 'bones apart'))
    for (i, artist, mine, hops), count in far.most_common(top):
        print('%8d  %-8s %-20s %-20s %d' % (count, i, artist, mine, hops))
    print('detached pieces: %.4f of the vertices, %.4f of those %d or more bones away'
          % (by_piece[(False, 'vertices')] / vertices,
             by_piece[(False, 'far')] / max(1, by_piece[(False, 'far')] + by_piece[(True, 'far')]), sm.FAR_IN_JOINTS))
    for piece, label in ((True, 'the largest piece'), (False, 'detached pieces')):
        count = max(1, by_piece[(piece, 'vertices')])
        print('  %-18s top joint right %.4f, %d or more bones away %.4f'
              % (label, by_piece[(piece, 'right')] / count, sm.FAR_IN_JOINTS, by_piece[(piece, 'far')] / count))


if __name__ == '__main__':
    main(sys.argv[1:])
