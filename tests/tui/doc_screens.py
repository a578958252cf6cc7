#!/usr/bin/env python3
# doc_screens.py - the screen excerpts of docs/workbench.md against the
# screens the workbench draws (tests/tui/tui_doc_screens.sh captures
# them).  An excerpt is a fenced block right after a line
#
#     <!-- screen NAME -->            the whole capture NAME
#     <!-- screen NAME lines A-B -->  its lines A to B (1 first)
#
# and the capture is the file CAPDIR/NAME (tmux capture-pane -p).
#
#   doc_screens.py check DOC CAPDIR [NAME...]  compare (the named ones,
#       or every marked one); prints "ok NAME" or "differ NAME" and the
#       masked lines that differ; exit 1 when any differs or a capture is
#       missing
#   doc_screens.py update DOC CAPDIR           write the captures into
#       DOC's excerpts (the way they were made: run the test with
#       SLIPWALL_DOC_SCREENS=update)
#   doc_screens.py unmarked DOC                the fenced blocks that look
#       like a whole screen (a first line " slipwall | " or " run
#       history: ") and have no marker: one line each, exit 1 if any
#
# What legitimately varies is masked on both sides before comparing:
# rates and thread counts (speed lines, the samples in progress), times (ages, estimates, the
# solve's clock), absolute paths (their directories) and the time
# stamps of samples file names; a line with a masked path also has its
# runs of spaces made one (a path's length moves what follows it).
# Trailing spaces are dropped on both sides (capture-pane drops them).
import re
import sys

MARK = re.compile(r'^<!-- screen (\S+)(?: lines (\d+)-(\d+))? -->$')


def blocks(lines):
    """(name, a, b, start, end) of each marked excerpt: start..end-1 are
    its lines inside the fence."""
    out = []
    for i, l in enumerate(lines):
        m = MARK.match(l.rstrip('\n'))
        if not m:
            continue
        if i + 1 >= len(lines) or not lines[i + 1].startswith('```'):
            sys.exit('%d: a screen marker not followed by a fence' % (i + 1))
        j = i + 2
        while j < len(lines) and not lines[j].startswith('```'):
            j += 1
        a = int(m.group(2)) if m.group(2) else None
        b = int(m.group(3)) if m.group(3) else None
        out.append((m.group(1), a, b, i + 2, j))
    return out


def mask(line):
    s = line.rstrip()
    s = re.sub(r'[0-9.]+(e[+-]?[0-9]+)? /s', '# /s', s)
    s = re.sub(r'[0-9.]+ s/sample', '# s/sample', s)
    s = re.sub(r'on [0-9]+ threads?', 'on # threads', s)
    s = re.sub(r'working +[0-9]+ samples?', 'working # samples', s)
    s = re.sub(r'oldest [0-9:]+( s)?', 'oldest #', s)
    s = re.sub(r'(left +)(about |~)?[0-9:]+( s)? of (about |~)?[0-9:]+( s)?',
               r'\1# of #', s)
    s = re.sub(r'(computing(…|\.\.\.) )[0-9:]+( s)?', r'\1#', s)
    s = re.sub(r'-[0-9]{8}-[0-9]{6}-', '-STAMP-', s)
    t = re.sub(r'(/[^/ ]+)+/', '.../', s)
    if t != s:
        t = re.sub(r'  +', ' ', t)
    return t


def capture(capdir, name, a, b):
    try:
        with open('%s/%s' % (capdir, name), encoding='utf-8') as f:
            cap = f.read().split('\n')
    except OSError:
        return None
    if cap and cap[-1] == '':
        cap.pop()
    if a is not None:
        cap = cap[a - 1:b]
    # a whole screen: its blank last rows are kept, as the doc shows them
    return [l.rstrip() for l in cap]


def main():
    cmd, doc = sys.argv[1], sys.argv[2]
    with open(doc, encoding='utf-8') as f:
        lines = f.readlines()
    if cmd == 'unmarked':
        bad = 0
        marked = {s for (_, _, _, s, _) in blocks(lines)}
        fence = None
        for i, l in enumerate(lines):
            if l.startswith('```'):
                if fence is None:
                    fence = i
                else:
                    first = lines[fence + 1] if fence + 1 < i else ''
                    if (first.startswith(' slipwall | ') or
                            first.startswith(' run history: ')) and \
                            fence + 1 not in marked:
                        print('%s:%d: a screen without a marker' %
                              (doc, fence + 1))
                        bad = 1
                    fence = None
        sys.exit(bad)
    capdir = sys.argv[3]
    names = sys.argv[4:]
    bad = 0
    out = list(lines)
    # from the last, so that an update keeps the earlier line numbers
    for name, a, b, start, end in reversed(blocks(lines)):
        if names and name not in names:
            continue
        cap = capture(capdir, name, a, b)
        if cap is None:
            print('missing %s (no capture)' % name)
            bad = 1
            continue
        if cmd == 'update':
            out[start:end] = [l + '\n' for l in cap]
            continue
        want = [mask(l) for l in lines[start:end]]
        got = [mask(l) for l in cap]
        if want == got:
            print('ok %s' % name)
            continue
        bad = 1
        print('differ %s (docs line %d)' % (name, start + 1))
        for k in range(max(len(want), len(got))):
            w = want[k] if k < len(want) else '(none)'
            g = got[k] if k < len(got) else '(none)'
            if w != g:
                print('  line %d doc:    %s' % (k + 1, w))
                print('  line %d screen: %s' % (k + 1, g))
    if cmd == 'update':
        with open(doc, 'w', encoding='utf-8') as f:
            f.writelines(out)
    sys.exit(bad)


main()
