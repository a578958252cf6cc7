#!/usr/bin/env python3
"""bench/scan.py - random body-loaded walls, and how their samples end.

Usage: python3 bench/scan.py SLIPWALL DIR SEED [K] [--lintels]

Writes K (default 14) random running- and stack-bond walls of 80-300
blocks under a body load into DIR (friction 0.35-0.95 on bed joints, head
friction the same or lower, depth 0.1-0.45, a load along +x, -x or
inclined; half of the walls of 8 courses or more with a rectangular
opening left out of the layout, without a lintel), runs 12 samples of
each on one thread, two walls at a time, and prints one line a wall: its
blocks and interfaces, which of its blocks hang (the
`check` warning, docs/method.md, "What the method cannot answer: blocks
that hang on friction"), which overhang (its other warning, "Blocks that
overhang an opening"), the accepted count and the rejections by reason.
The walls depend only on SEED: docs/method.md reports seeds 1-20.

--lintels: each opening gets a lintel, one block in place of the blocks
of the course just above it that reach over the opening's blocks (a
quarter block or more of bearing each side), as walls/facade.yaml has,
so that no block hangs on friction; the walls are otherwise the same.
"""
import json
import random
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor


def wall(rng, name):
    bw, bh = rng.choice([(0.2, 0.1), (0.4, 0.2), (0.3, 0.15), (0.25, 0.065),
                         (0.6, 0.3)])
    n = rng.randint(80, 300)
    courses = rng.randint(5, 22)
    length = round(max(bw, bw * n / courses), 3)
    bond = rng.choice(['running'] * 4 + ['stack'])
    first = rng.choice(['half', 'half', 'full'])
    bed = round(rng.uniform(0.35, 0.95), 2)
    head = round(rng.uniform(0.2, bed), 2) if rng.random() < 0.5 else bed
    depth = rng.choice([0.1, 0.2, 0.25, 0.3, 0.45])
    dx, dy = rng.choice([(1, 0)] * 4 + [(1, -0.3), (1, 0.2), (-1, 0)])
    layout = (f"block: [{bw}, {bh}], courses: {courses}, length: {length}, "
              f"bond: {bond}, first_course: {first}")
    text = (f"name: {name}\n"
            f"material: {{friction: {{bed: {bed}, head: {head}}}, "
            f"unit_weight: 20000, thickness: 0.2}}\n"
            f"layout: {{{layout}}}\n"
            f"supports:\n  - ground: {{y: 0}}\n"
            f"loads:\n  - body: {{direction: [{dx}, {dy}]}}\n"
            f"contacts: {{depth: {depth}}}\n"
            f"analysis: {{samples: 12, seed: 1}}\n")
    opening = None
    if rng.random() < 0.5 and courses >= 8:
        h, w = courses * bh, length
        opening = (w * rng.uniform(0.25, 0.45), w * rng.uniform(0.55, 0.75),
                   h * rng.uniform(0.15, 0.35), h * rng.uniform(0.5, 0.7))
    return text, layout, opening


def check(slipwall, path):
    out = subprocess.run([slipwall, 'check', path, '--json'],
                         capture_output=True, text=True).stdout
    return json.loads(out)


def omitting(text, layout, ids):
    """The wall text with ids left out of its layout."""
    return text.replace(layout, layout + ', omit: [' + ', '.join(ids) + ']')


def course_of(block_id):
    """The course of a layout block cCbB, or None."""
    m = re.fullmatch(r'c(\d+)b\d+', block_id)
    return int(m.group(1)) if m else None


def xspan(b):
    xs = [x for x, _ in b['vertices']]
    return min(xs), max(xs)


def lintel(blocks, text, layout, omit):
    """A lintel over the opening whose blocks omit are (above); blocks:
    the wall's blocks before the opening was left out."""
    over_opening = [b for b in blocks if b['id'] in omit]
    lo = min(xspan(b)[0] for b in over_opening)
    hi = max(xspan(b)[1] for b in over_opening)
    top = max(course_of(b['id']) for b in over_opening)
    course = [b for b in blocks if course_of(b['id']) == top + 1]
    if not course:  # a notch in the top: nothing over it to carry
        return omitting(text, layout, omit)
    bw = max(xspan(b)[1] - xspan(b)[0] for b in course)
    over = [b for b in course
            if xspan(b)[0] < hi + bw / 4 and xspan(b)[1] > lo - bw / 4]
    x0 = round(min(xspan(b)[0] for b in over), 9)
    x1 = round(max(xspan(b)[1] for b in over), 9)
    y0 = round(min(y for b in over for _, y in b['vertices']), 9)
    y1 = round(max(y for b in over for _, y in b['vertices']), 9)
    text = omitting(text, layout, omit + [b['id'] for b in over])
    return text.replace('supports:\n', f"blocks:\n  - {{id: lintel, vertices: "
                        f"[[{x0}, {y0}], [{x1}, {y0}], [{x1}, {y1}], [{x0}, {y1}]]}}\n"
                        "supports:\n", 1)


def main():
    args = [a for a in sys.argv[1:] if a != '--lintels']
    lintels = '--lintels' in sys.argv[1:]
    slipwall, out, seed = args[0], args[1], int(args[2])
    k = int(args[3]) if len(args) > 3 else 14
    rng = random.Random(seed)
    paths = []
    for i in range(k):
        name = f's{seed}w{i}'
        path = f'{out}/{name}.yaml'
        text, layout, opening = wall(rng, name)
        with open(path, 'w') as f:
            f.write(text)
        if opening:
            x0, x1, y0, y1 = opening
            d = check(slipwall, path)
            omit = [b['id'] for b in d['blocks']
                    if x0 < b['centroid'][0] < x1 and y0 < b['centroid'][1] < y1]
            if omit:
                text = (lintel(d['blocks'], text, layout, omit) if lintels
                        else omitting(text, layout, omit))
                with open(path, 'w') as f:
                    f.write(text)
        paths.append(path)

    def run(path):
        d = check(slipwall, path)
        hanging = sum('on no joint below' in x for x in d['warnings'])
        text = next((x for x in d['warnings'] if 'on no joint below' in x), '')
        warning = next((x for x in d['warnings'] if 'overhangs' in x), '')
        # "block B overhangs what it rests on (...), and N other blocks
        # likewise: ..." (docs/method.md, "Blocks that overhang an opening")
        m = re.match(r'block (\S+) overhangs[^:]*', warning)
        n = m and re.search(r', and (\d+) other', m.group(0))
        over = (f"overhang: block {m.group(1)}"
                f"{' and ' + n.group(1) + ' others' if n else ''}"
                if m else 'none overhangs')
        r = subprocess.run([slipwall, 'run', path, '-n', '12', '--threads', '1',
                            '--json'], capture_output=True, text=True)
        s = json.loads(r.stdout)
        rej = {k: v for k, v in s['rejected'].items() if v}
        return (f"{path}: {len(d['blocks'])} blocks, "
                f"{len(d['interfaces'])} interfaces; "
                f"{'hanging: ' + text.split(':')[0] if hanging else 'none hangs'}; "
                f"{over}; "
                f"accepted {s['accepted']}, rejected {rej}")

    with ThreadPoolExecutor(2) as pool:
        for line in pool.map(run, paths):
            print(line, flush=True)


if __name__ == '__main__':
    main()
