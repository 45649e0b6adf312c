#!/usr/bin/env python3
"""Hand derivation of FANUC cutter compensation C / tool nose radius compensation
tool paths for the cc_*.nc and nt_*.nc test programs.

This is NOT ncurve's compensation: it is an independent, deliberately plain
restatement of the rules written down in docs/compensation-spec.md, applied to
small programs whose geometry is simple enough to check on paper.  Every corner
rule used below carries the spec rule id (R-xx) it implements; each case
function states the rules it exercises and the numbers a reader can check by
hand.

Run:  python3 tests/programs/derive/derive.py      (rewrites the programs and
      their NAME.expected.moves / NAME.expected.txt / NAME.toml beside them, in
      tests/programs/compensation/ for cc_* and tests/programs/nose/ for nt_*)

Conventions of the expected files (repeated in each file's '#' header):
  * one line per move the control makes, in order:
      LINE rapid|line X Y Z
      LINE arc X Y Z CX CY CZ G02|G03
    tool-centre (mill) or imaginary-tool-tip (lathe) end point, 4 decimals;
  * lathe files give X (and CX) as a DIAMETER, Y = 0;
  * moves inserted at a corner (extra vectors of an outer acute corner, the
    second vector of a type B start-up/cancel) carry the LINE of the EARLIER
    block: FANUC creates those vectors "at the end point" of that block and
    the single-block stop comes after them (spec R-CORNER-OWNER);
  * a block with no movement in the offset plane that moves Z is listed where
    the control executes it (at the end point of the preceding block);
    dwell / M codes produce no line.
"""
import math
import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))
PROGRAMS = os.path.dirname(HERE)                 # tests/programs
FOLDERS = {'cc_': 'compensation', 'nt_': 'nose'}  # cutter compensation (mill), tool nose radius (lathe)

def out(name, ext):
    """tests/programs/FOLDER/NAME.EXT: the folder of the case's feature, by its name's prefix"""
    return os.path.join(PROGRAMS, FOLDERS[name[:3]], name + ext)
LATHE_PROFILE = os.path.join(HERE, '..', '..', '..', 'profiles', 'fanuc-lathe.toml')
EPS = 1e-9

# ----------------------------------------------------------------- 2D helpers
def add(p, q): return (p[0] + q[0], p[1] + q[1])
def sub(p, q): return (p[0] - q[0], p[1] - q[1])
def mul(p, k): return (p[0] * k, p[1] * k)
def dot(p, q): return p[0] * q[0] + p[1] * q[1]
def cross(p, q): return p[0] * q[1] - p[1] * q[0]
def norm(p): return math.hypot(p[0], p[1])
def unit(p):
    n = norm(p)
    return (p[0] / n, p[1] / n)
def left(t): return (-t[1], t[0])               # 90 deg counter-clockwise


class Line:
    def __init__(self, a, b):
        self.a, self.b = a, b
        self.t = unit(sub(b, a))
    def t_start(self): return self.t
    def t_end(self): return self.t


class Arc:
    """ccw=True for G03.  Plane coordinates (a, b) are oriented so that G03 is
    counter-clockwise: (X, Y) for G17, (Z, X) for G18 seen from +Y."""
    def __init__(self, a, b, c, ccw):
        self.a, self.b, self.c, self.ccw = a, b, c, ccw
        self.R = norm(sub(a, c))
    def tangent(self, p):
        u = unit(sub(p, self.c))
        return left(u) if self.ccw else mul(left(u), -1)
    def t_start(self): return self.tangent(self.a)
    def t_end(self): return self.tangent(self.b)
    def sweep(self):
        """programmed sweep, positive, in (0, 2pi]"""
        a0 = math.atan2(self.a[1] - self.c[1], self.a[0] - self.c[0])
        a1 = math.atan2(self.b[1] - self.c[1], self.b[0] - self.c[0])
        d = (a1 - a0) if self.ccw else (a0 - a1)
        d %= 2 * math.pi
        return d if d > 1e-12 else 2 * math.pi


def normal(elem, p, side):
    """R-VEC: the offset vector direction at p: left of the direction of motion
    for G41 (side=+1), right for G42 (side=-1)."""
    return mul(left(elem.tangent(p) if isinstance(elem, Arc) else elem.t), side)


def offset_radius(arc, side, r):
    """R-ARC: an arc keeps its centre; G41 on G03 (or G42 on G02) moves the
    tool towards the centre."""
    return arc.R - side * r if arc.ccw else arc.R + side * r


class Alarm(Exception):
    def __init__(self, code, blk):
        super().__init__(code)
        self.code, self.blk = code, blk


# ---------------------------------------------- intersections of offset paths
def off_line(line, side, r):
    n = mul(left(line.t), side)
    return (add(line.a, mul(n, r)), line.t)       # point, direction

def inter_ll(p1, d1, p2, d2):
    den = cross(d1, d2)
    if abs(den) < 1e-12:
        return []
    t = cross(sub(p2, p1), d2) / den
    return [add(p1, mul(d1, t))]

def inter_lc(p, d, c, R):
    f = sub(p, c)
    b = dot(f, d)
    disc = b * b - (dot(f, f) - R * R)
    if disc < -1e-12:
        return []
    disc = math.sqrt(max(disc, 0.0))
    return [add(p, mul(d, -b - disc)), add(p, mul(d, -b + disc))]

def inter_cc(c1, R1, c2, R2):
    d = norm(sub(c2, c1))
    if d < 1e-12 or d > R1 + R2 + 1e-12 or d < abs(R1 - R2) - 1e-12:
        return []
    a = (R1 * R1 - R2 * R2 + d * d) / (2 * d)
    h = math.sqrt(max(R1 * R1 - a * a, 0.0))
    e = unit(sub(c2, c1))
    m = add(c1, mul(e, a))
    return [add(m, mul(left(e), h)), add(m, mul(left(e), -h))]

def intersect(e1, s1, r1, e2, s2, r2, ref):
    """R-INTERSECT: intersection of the two offset paths (lines extended, arcs
    as whole circles); of two candidates the one nearest the corner."""
    if isinstance(e1, Line) and isinstance(e2, Line):
        p1, d1 = off_line(e1, s1, r1)
        p2, d2 = off_line(e2, s2, r2)
        pts = inter_ll(p1, d1, p2, d2)
    elif isinstance(e1, Line):
        p1, d1 = off_line(e1, s1, r1)
        pts = inter_lc(p1, d1, e2.c, offset_radius(e2, s2, r2))
    elif isinstance(e2, Line):
        p2, d2 = off_line(e2, s2, r2)
        pts = inter_lc(p2, d2, e1.c, offset_radius(e1, s1, r1))
    else:
        pts = inter_cc(e1.c, offset_radius(e1, s1, r1), e2.c, offset_radius(e2, s2, r2))
    if not pts:
        return None
    return min(pts, key=lambda q: norm(sub(q, ref)))


def classify(t1, t2, side):
    """R-CORNER: 'inner' (workpiece-side angle alpha >= 180), 'obtuse'
    (90 <= alpha < 180) or 'acute' (alpha < 90)."""
    c, d = cross(t1, t2), dot(t1, t2)
    if abs(c) < 1e-9 and d > 0:
        return 'straight'
    if side * c > 1e-9:
        return 'inner'
    return 'obtuse' if d >= -1e-12 else 'acute'


# -------------------------------------------------------- the compensation
def corner_points(rec1, rec2, ctx):
    """Tool-centre points passed at the junction G of rec1 and rec2."""
    e1, e2 = rec1['elem'], rec2['elem']
    G = e1.b
    for rec in (rec1, rec2):                          # R-INTERF-ARC: radius < offset
        e = rec['elem']
        if isinstance(e, Arc) and rec['state'] == 'offset' and offset_radius(e, rec['side'], rec['r']) < -1e-9:
            raise Alarm('PS0041', rec['blk'])
    s1, s2 = rec1['side'], rec2['side']
    r = rec1['r']                      # R-DCHANGE: value in force at rec1's end
    t1, t2 = e1.t_end(), e2.t_start()
    n1 = normal(e1, G, s1)
    # start-up (R-SU-*)
    if rec1['state'] == 'startup':
        n2 = normal(e2, G, s1)
        kind = classify(t1, t2, s1)
        if kind in ('straight', 'inner') or not ctx['typeB']:
            return [add(G, mul(n2, r))]                       # R-SU-A, R-SU-INNER
        if kind == 'obtuse':
            q = intersect(e1, s1, r, e2, s1, r, add(G, mul(n2, r)))
            return [q]                                        # R-SU-B-OBTUSE
        return [add(G, mul(n1, r)), add(G, mul(n2, r))]      # R-SU-B-ACUTE
    # cancel (R-CN-*)
    if rec2['state'] == 'cancelblk':
        if rec2.get('ij') is not None:                        # R-CN-IJ
            virt = Line(G, add(G, rec2['ij']))
            q = intersect(e1, s1, r, virt, s1, r, add(G, mul(n1, r)))
            return [q if q is not None else add(G, mul(n1, r))]
        kind = classify(t1, t2, s1)
        if kind in ('straight', 'inner') or not ctx['typeB']:
            return [add(G, mul(n1, r))]                       # R-CN-A, R-CN-INNER
        n2 = normal(e2, G, s1)
        if kind == 'obtuse':
            return [intersect(e1, s1, r, e2, s1, r, add(G, mul(n1, r)))]   # R-CN-B-OBTUSE
        return [add(G, mul(n1, r)), add(G, mul(n2, r))]      # R-CN-B-ACUTE
    # offset mode
    if rec1['nomove_after'] >= 2:                             # R-NOMOVE-EXCEED (N=3)
        return [add(G, mul(n1, r))]
    n2 = normal(e2, G, s2)
    if s1 != s2:                                              # R-SIDE-CHANGE
        q = intersect(e1, s1, r, e2, s2, r, mul(add(add(G, mul(n1, r)), add(G, mul(n2, r))), 0.5))
        if q is None:
            if isinstance(e1, Line) and isinstance(e2, Line):
                return [add(G, mul(n1, r)), add(G, mul(n2, r))]
            raise Alarm('PS0033', rec1['blk'])
        return [q]
    kind = classify(t1, t2, s1)
    if kind == 'straight':
        return [add(G, mul(n1, r))]                           # R-TANGENT
    if kind in ('inner', 'obtuse'):
        q = intersect(e1, s1, r, e2, s2, r, mul(add(add(G, mul(n1, r)), add(G, mul(n2, r))), 0.5))
        if q is None:
            raise Alarm('PS0033', rec1['blk'])               # R-PS0033
        return [q]                                            # R-INNER, R-OBTUSE
    pts = []                                                  # R-ACUTE
    if isinstance(e1, Arc):
        pts.append(add(G, mul(n1, r)))
    pts.append(add(add(G, mul(n1, r)), mul(t1, r)))
    pts.append(sub(add(G, mul(n2, r)), mul(t2, r)))
    if isinstance(e2, Arc):
        pts.append(add(G, mul(n2, r)))
    return pts


def comp_sweep(arc, p0, p1):
    """sweep of the compensated arc from p0 to p1 around arc.c in the
    programmed direction, kept close to the programmed sweep (R-ARC)."""
    def ang(p): return math.atan2(p[1] - arc.c[1], p[0] - arc.c[0])
    sg = 1 if arc.ccw else -1
    def delta(prog_pt, pt):
        d = sg * (ang(pt) - ang(prog_pt))
        return (d + math.pi) % (2 * math.pi) - math.pi
    return arc.sweep() + delta(arc.b, p1) - delta(arc.a, p0)


def interference(rec, p0, p1):
    """R-INTERF: direction check (line reversed) and arc checks."""
    e = rec['elem']
    if isinstance(e, Line):
        if dot(sub(p1, p0), e.t) < 0:
            raise Alarm('PS0041', rec['blk'])
    else:
        Ro = offset_radius(e, rec['side'], rec['r'])
        if Ro < -1e-9:
            raise Alarm('PS0041', rec['blk'])
        if abs(Ro) <= 1e-9:
            raise Alarm('PS0038', rec['blk'])
        sw = comp_sweep(e, p0, p1)
        if sw <= 0 or abs(sw - e.sweep()) > math.pi:
            raise Alarm('PS0041', rec['blk'])


# ---------------------------------------------------------- tiny NC reader
WORD = re.compile(r'([A-Z])\s*(-?\d*\.?\d*)')

class Block:
    def __init__(self, line, text):
        self.line, self.text = line, text
        self.words = []
        body = re.sub(r'\(.*?\)', '', text)
        for letter, num in WORD.findall(body):
            self.words.append((letter, float(num) if num not in ('', '-', '.') else None))
    def gs(self): return [v for l, v in self.words if l == 'G']
    def get(self, letter):
        vals = [v for l, v in self.words if l == letter]
        return vals[0] if vals else None


def run(lines, machine, params):
    """Walk the program; build records; apply the rules; return moves."""
    lathe = machine['type'] == 'lathe'
    typeB = params.get('5003#0', 0) == 1
    offsets = dict(machine.get('offsets', {}))       # mill: number -> radius
    pos = list(machine['home'])                      # mill (X,Y,Z); lathe (Xdia, 0, Z)
    motion, plane, mode_side, dnum = 0, 17, 0, 0
    tip, rnose = 0, 0.0
    recs = []                                        # plane-moving blocks
    moves_pre = []                                   # raw list of events in order
    for i, text in enumerate(lines, start=1):
        b = Block(i, text)
        if not b.words or text.startswith('('):
            continue
        gs = b.gs()
        if 4 in gs:                                  # dwell: no movement
            if recs: recs[-1]['nomove_after'] += 1
            continue
        if 10 in gs:                                 # G10 L11 P R: offset memory A
            offsets[int(b.get('P'))] = b.get('R')
            continue
        if b.get('T') is not None:
            n = int(b.get('T')) % 100
            tip, rnose = machine['tools'][n]
        for g in gs:
            if g in (0, 1, 2, 3): motion = int(g)
            if g in (17, 18, 19):
                if mode_side and g != plane:
                    raise Alarm('PS0037', b)           # R-PS0037
                plane = int(g)
        new_side = None
        if 41 in gs: new_side = 1
        if 42 in gs: new_side = -1
        cancel = 40 in gs
        if b.get('D') is not None: dnum = int(b.get('D'))
        if lathe:
            X = b.get('X'); Z = b.get('Z')
            end = [X if X is not None else pos[0], 0.0, Z if Z is not None else pos[2]]
            moved_plane = X is not None or Z is not None
            to2 = lambda p: (p[2], p[0] / 2)           # plane (Z, X radius)
        else:
            X, Y, Z = b.get('X'), b.get('Y'), b.get('Z')
            end = [X if X is not None else pos[0], Y if Y is not None else pos[1],
                   Z if Z is not None else pos[2]]
            moved_plane = X is not None or Y is not None
            to2 = lambda p: (p[0], p[1])
        full_circle = motion in (2, 3) and any(b.get(w) is not None for w in 'IJK')
        if not full_circle and (not moved_plane or to2(end) == to2(pos)):
            if b.get('Z') is not None and not lathe:   # Z-only: no plane movement
                if mode_side and recs:                  # R-NOMOVE: counts as a block without movement
                    recs[-1]['nomove_after'] += 1
                    recs[-1]['after'].append(('z', b, end[2]))
                else:
                    moves_pre.append((b, 'rapid' if motion == 0 else 'line', tuple(end)))
                pos = end
                continue
            if mode_side and recs: recs[-1]['nomove_after'] += 1
            if new_side: mode_side = new_side
            if cancel: mode_side = 0
            continue
        a2, b2 = to2(pos), to2(end)
        if motion in (2, 3):
            if lathe:
                I = b.get('I') or 0.0; K = b.get('K') or 0.0
                c2 = (a2[0] + K, a2[1] + I)
            else:
                I = b.get('I') or 0.0; J = b.get('J') or 0.0
                c2 = (a2[0] + I, a2[1] + J)
            elem = Arc(a2, b2, c2, motion == 3)
        else:
            elem = Line(a2, b2)
        r = rnose if lathe else offsets.get(dnum, 0.0)
        prev_active = bool(mode_side)
        if cancel:
            state = 'cancelblk' if prev_active else 'cancel'
            mode_side = 0
        elif new_side and not prev_active:
            state = 'startup'; mode_side = new_side
        else:
            if new_side: mode_side = new_side
            state = 'offset' if prev_active else 'cancel'
        if state in ('startup', 'cancelblk') and motion in (2, 3):
            raise Alarm('PS0034', b)                    # R-PS0034
        ij = None
        if state == 'cancelblk' and not lathe and (b.get('I') is not None or b.get('J') is not None):
            ij = (b.get('I') or 0.0, b.get('J') or 0.0)
        recs.append(dict(blk=b, elem=elem, state=state, side=mode_side if state != 'cancelblk' else (recs[-1]['side'] if recs else 0),
                         r=r, kind='rapid' if motion == 0 else ('arc' if motion in (2, 3) else 'line'),
                         start3=tuple(pos), end3=tuple(end), nomove_after=0, after=[], ij=ij,
                         pre=moves_pre))
        moves_pre = []
        pos = end
    # corners
    ctx = dict(typeB=typeB)
    corners = {}
    for k in range(len(recs) - 1):
        r1, r2 = recs[k], recs[k + 1]
        if r1['state'] in ('startup', 'offset') and r2['state'] in ('offset', 'cancelblk'):
            corners[k] = corner_points(r1, r2, ctx)
    # moves
    tipv = {0: (0, 0), 9: (0, 0), 1: (1, 1), 2: (-1, 1), 3: (-1, -1), 4: (1, -1),
            5: (1, 0), 6: (0, 1), 7: (-1, 0), 8: (0, -1)}[tip] if lathe else (0, 0)
    tipv = mul(tipv, rnose)                             # (dZ, dXradius)  R-TIP
    def out3(p2, z):
        if lathe:
            q = add(p2, tipv)
            return (2 * q[1], 0.0, q[0])
        return (p2[0], p2[1], z)
    moves = []
    cur2 = None
    for k, rec in enumerate(recs):
        for (b, kind, e3) in rec['pre']:
            moves.append((b.line, kind, e3, None, None))
        blk, e, z = rec['blk'], rec['elem'], rec['end3'][2]
        if rec['state'] == 'cancel':
            moves.append((blk.line, rec['kind'], rec['end3'], None, None))
            cur2 = None
        elif rec['state'] == 'startup':
            pts = corners.get(k, [])
            moves.append((blk.line, rec['kind'], out3(pts[0], z), None, None))
            for q in pts[1:]:
                moves.append((blk.line, 'line' if rec['kind'] != 'rapid' else 'rapid', out3(q, z), None, None))
            cur2 = pts[-1]
        elif rec['state'] == 'offset':
            pts = corners[k]
            p0, p1 = cur2, pts[0]
            if recs[k - 1]['nomove_after'] < 2:
                interference(rec, p0, p1)
            if rec['kind'] == 'arc':
                c = out3(e.c, z)
                moves.append((blk.line, 'arc', out3(p1, z), c, 'G03' if e.ccw else 'G02'))
            else:
                moves.append((blk.line, rec['kind'], out3(p1, z), None, None))
            for q in pts[1:]:
                moves.append((blk.line, 'line' if rec['kind'] != 'rapid' else 'rapid', out3(q, z), None, None))
            cur2 = pts[-1]
        elif rec['state'] == 'cancelblk':
            moves.append((blk.line, rec['kind'], rec['end3'], None, None))
            cur2 = None
        if rec['state'] in ('startup', 'offset'):
            zc = z
            for (what, b, znew) in rec['after']:        # Z-only blocks at this point
                moves.append((b.line, 'line', out3(cur2 if rec['nomove_after'] < 2 else corners[k][0], znew), None, None))
            # note: for a corner with several points the Z block runs after them
    for (b, kind, e3) in moves_pre:                     # cancel-mode moves after the last plane move
        moves.append((b.line, kind, e3, None, None))
    return moves, recs


# ------------------------------------------------------------------ writers
def fmt(v):
    v = 0.0 if abs(v) < 5e-5 else v
    return f'{v:.4f}'

def write_case(name, nc_lines, header, machine, params=None, note=''):
    params = params or {}
    path = out(name, '.nc')
    with open(path, 'w') as f:
        f.write('\n'.join(nc_lines) + '\n')
    for ext in ('.expected.moves', '.expected.txt'):
        if os.path.exists(out(name, ext)):
            os.remove(out(name, ext))
    try:
        moves, _ = run(nc_lines, machine, params)
    except Alarm as a:
        b = a.blk
        with open(out(name, '.expected.txt'), 'w') as f:
            f.write('exit 1\n%s\n%s.nc:%d:1\n%s\n' % (a.code, name, b.line, b.text))
        return ('alarm', a.code, b.line)
    with open(out(name, '.expected.moves'), 'w') as f:
        for h in header:
            f.write('# ' + h + '\n')
        if machine['type'] == 'lathe':
            f.write('# X and CX are DIAMETERS; the points are the imaginary tool tip the control commands\n')
        f.write('# inserted corner moves carry the LINE of the earlier block (spec R-CORNER-OWNER)\n')
        for (ln, kind, e3, c3, d) in moves:
            s = '%d %s %s %s %s' % (ln, kind, fmt(e3[0]), fmt(e3[1]), fmt(e3[2]))
            if kind == 'arc':
                s += ' %s %s %s %s' % (fmt(c3[0]), fmt(c3[1]), fmt(c3[2]), d)
            f.write(s + '\n')
    return ('moves', len(moves))


def write_lathe_profile(name, r, tip):
    with open(LATHE_PROFILE) as f:
        text = f.read()
    text = re.sub(r'^"1" = \{[^\n]*\}', '"1" = { x = 0.0, z = 0.0, r = %s, tip = %d }' % (r, tip),
                  text, count=1, flags=re.M)
    text = text.replace('# FANUC 0i-TF 2-axis lathe', '# %s: FANUC 0i-TF 2-axis lathe' % name, 1)
    with open(out(name, '.toml'), 'w') as f:
        f.write(text)


MILL = dict(type='mill', home=(250.0, 200.0, 400.0), offsets={})
def LATHE(r, tip): return dict(type='lathe', home=(300.0, 0.0, 250.0), tools={1: (tip, r)})


# =================================================================== cases
# Every mill program: offset memory A, offset 1 = 5 mm (G10 L11 P1 R5.),
# machine starts at reference point 1, machine zero: X250 Y200 Z400 of G54 (X-250 Y-200 Z-400 in
# profiles/fanuc-mill.toml and the default mill),
# absolute coordinates, G17.  Cites: see docs/compensation-spec.md.
CASES = []
def case(fn):
    CASES.append(fn)
    return fn

def comment(text):
    """A comment line: a comment ends at its first ')', so an aside "(X)" in the text is written "- X"."""
    return '(%s)' % text.replace('(', '- ').replace(')', '')

def mill(name, title, rule, body, param=None):
    lines = []
    if param:
        lines.append('(PARAM %s)' % param)
    lines.append(comment('%s: %s' % (name.upper(), title)))
    lines.append(comment('RULE: %s' % rule))
    lines.append('G10 L11 P1 R5.')
    lines += body
    return lines


SQUARE = ['G90 G17 G40 G00 X10. Y-15. Z0.',
          'G41 G01 X0. Y0. D1 F100.',
          'Y40.',
          'X40.',
          'Y0.',
          'X0.',
          'G40 X-15. Y10.',
          'M30']

@case
def cc_startup_a():
    # Start-up S=(10,-15) -> G=(0,0), next block +Y: right turn under G41 ->
    # outer corner, angle between the blocks 33.7 deg (alpha = 146.3: obtuse).
    # R-SU-A (type A, No.5003#0=0, the default): vector perpendicular to the
    # next block at its start: (0,0)+5*(-1,0) = (-5,0).
    # Square corners (90 deg, outer under G41 going clockwise): R-OBTUSE,
    # intersections (-5,45) (45,45) (45,-5).  Last block X0 ends at (0,0);
    # cancel block to E=(-15,10) is a right turn (outer, obtuse) -> R-CN-A:
    # perpendicular to the last block: (0,-5), then E uncompensated.
    lines = mill('cc_startup_a', 'START-UP AND CANCEL TYPE A, CLOSED SQUARE, OUTER 90 DEG CORNERS',
                 'START-UP TYPE A NO.5003#0=0; OFFSET MODE OBTUSE OUTER CORNER; CANCEL TYPE A'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN START-UP / IN OFFSET MODE / IN OFFSET MODE CANCEL', SQUARE)
    return 'cc_startup_a', lines, MILL, {}, [
        'start-up type A (No.5003#0=0): vector perpendicular to the next block: (-5,0)',
        'square corners: intersections (-5,45) (45,45) (45,-5); cancel type A: (0,-5) then E (-15,10)']

@case
def cc_startup_b():
    # Same program with type B (No.5003#0=1).  R-SU-B-OBTUSE: intersection of
    # the start-up block's offset line and the next block's offset line x=-5.
    # Start-up direction d=(-10,15)/18.0278, left normal (-0.8321,-0.5547):
    # offset line through (-4.1603,-2.7735); x=-5 at y=-2.7735+0.8321*1.5139
    # ... = -1.5139.  R-CN-B-OBTUSE: intersection of y=-5 (last block) with
    # the cancel block's offset line: (-1.5139,-5).
    lines = mill('cc_startup_b', 'START-UP AND CANCEL TYPE B, CLOSED SQUARE',
                 'START-UP/CANCEL TYPE B NO.5003#0=1: INTERSECTION AT AN OBTUSE OUTER CORNER'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN START-UP / IN OFFSET MODE CANCEL', SQUARE,
                 param='5003#0=1')
    return 'cc_startup_b', lines, MILL, {'5003#0': 1}, [
        'start-up type B (No.5003#0=1), obtuse outer: intersection of both offset lines (-5,-1.5139)',
        'cancel type B, obtuse outer: intersection (-1.5139,-5), then E (-15,10)']

ACUTE_SU = ['G90 G17 G40 G00 X30. Y10. Z0.',
            'G41 G01 X10. Y0. D1 F100.',
            'X10. Y30.',
            'X-20.',
            'G40 X-30. Y40.',
            'M30']

@case
def cc_startup_b_acute():
    # Start-up S=(30,10) -> G=(10,0): d1=(-0.8944,-0.4472); next +Y.
    # cross(d1,t2) = -0.894 < 0: right turn, G41 -> outer; dot = -0.447 < 0:
    # acute (alpha = 63.4 deg).  R-SU-B-ACUTE: G + r*n1 = (10,0)+5*(0.4472,
    # -0.8944) = (12.2361,-4.4721), then an inserted line to G + r*n2 = (5,0).
    # Y30 then X-20: left turn under G41 -> inner, intersection (5,25).
    # Cancel to (-30,40): from -X to (-10,10): right turn, dot>0 -> obtuse:
    # type B intersection of y=25 with the cancel block's offset line.
    lines = mill('cc_startup_b_acute', 'START-UP TYPE B AT AN ACUTE OUTER CORNER (TWO VECTORS)',
                 'START-UP TYPE B NO.5003#0=1, ACUTE: VECTOR PERPENDICULAR TO THE START-UP BLOCK, THEN TO THE NEXT BLOCK'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN START-UP', ACUTE_SU, param='5003#0=1')
    return 'cc_startup_b_acute', lines, MILL, {'5003#0': 1}, [
        'start-up type B acute: (12.2361,-4.4721) = G + 5*perp(start-up block), inserted line to (5,0)',
        'inner corner at (10,30): intersection (5,25); cancel type B obtuse: intersection on y=25']

@case
def cc_startup_a_acute():
    # Same program, type A: a single vector perpendicular to the next block
    # (5,0); the cancel block: perpendicular to the last block (-20,25).
    lines = mill('cc_startup_a_acute', 'START-UP TYPE A AT AN ACUTE OUTER CORNER (ONE VECTOR)',
                 'START-UP TYPE A NO.5003#0=0: VECTOR PERPENDICULAR TO THE NEXT BLOCK ONLY'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN START-UP', ACUTE_SU)
    return 'cc_startup_a_acute', lines, MILL, {}, [
        'start-up type A acute: straight to (5,0); inner corner (5,25); cancel type A: (-20,25) then (-30,40)']

@case
def cc_inner_corner():
    # Pocket wall, G41, counter-clockwise inside the material: every corner
    # is a left turn -> inner -> R-INNER intersection of the offset lines.
    # Corner (40,0)->(40,30): 90 deg: (35,5).  Corner (40,30)->(10,40):
    # direction (-0.9487,0.3162), offset line through (40,30)+5*(-0.3162,
    # -0.9487); with x=35: y = 30-4.7434+(35-38.4189)*(0.3162/-0.9487)
    # = 26.3962.
    body = ['G90 G17 G40 G00 X20. Y-10. Z0.',
            'G41 G01 X20. Y0. D1 F100.',
            'X40.',
            'Y30.',
            'X10. Y40.',
            'G40 X20. Y20.',
            'M30']
    lines = mill('cc_inner_corner', 'INNER CORNERS LINE TO LINE (90 DEG AND 108.4 DEG)',
                 'OFFSET MODE, INNER SIDE (ALPHA>=180): INTERSECTION OF THE OFFSET PATHS'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN OFFSET MODE', body)
    return 'cc_inner_corner', lines, MILL, {}, [
        'start-up (20,-10)->(20,0) then +X: right turn, G41 -> outer, 90 deg: type A -> (20,5)',
        'inner corners: (35,5), (35,26.3962); cancel at (10,40): perpendicular to last block (8.4189,35.2566)']

@case
def cc_outer_obtuse():
    # G41 going clockwise around the outside of a triangle-like path.
    # Corner at (30,0): +X then direction (0.5,0.8660) (60 deg turn left?)
    # -> we go clockwise so the turn is right: +X then (0.5,-0.8660): right
    # turn of 60 deg under G41 -> outer, alpha = 120 -> R-OBTUSE: the offset
    # lines y=5 and the second line shifted by 5*(0.8660,0.5) meet at
    # (30+5*tan(30deg), 5) = (32.8868, 5).
    body = ['G90 G17 G40 G00 X-10. Y-10. Z0.',
            'G41 G01 X0. Y0. D1 F100.',
            'X30.',
            'X40. Y-17.3205',
            'G40 X50. Y-30.',
            'M30']
    lines = mill('cc_outer_obtuse', 'OUTER CORNER 120 DEG (OBTUSE): INTERSECTION',
                 'OFFSET MODE, OUTER OBTUSE (90<=ALPHA<180): INTERSECTION OF THE OFFSET PATHS'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN OFFSET MODE', body)
    return 'cc_outer_obtuse', lines, MILL, {}, [
        'outer corner at (30,0), alpha 120: intersection (32.8868,5) (= 30 + 5*tan 30)']

@case
def cc_outer_acute():
    # +X to (30,0), then back towards (10,-20): direction (-0.7071,-0.7071),
    # a right turn of 135 deg under G41 -> outer, alpha = 45 -> R-ACUTE:
    # block 1 is extended by r along its direction: (30,5)+(5,0) = (35,5);
    # an inserted line goes to G + r*n2 - r*t2 with t2 = (-0.7071,-0.7071),
    # n2 = left(t2) = (0.7071,-0.7071): (30+3.5355+3.5355, -3.5355+3.5355)
    # = (37.0711, 0); block 2 runs from there on its offset line.
    body = ['G90 G17 G40 G00 X-10. Y-10. Z0.',
            'G41 G01 X0. Y0. D1 F100.',
            'X30.',
            'X10. Y-20.',
            'G40 X0. Y-35.',
            'M30']
    lines = mill('cc_outer_acute', 'OUTER CORNER 45 DEG (ACUTE): EXTENSION BY R AND ONE INSERTED LINE',
                 'OFFSET MODE, OUTER ACUTE (ALPHA<90): VECTORS EXTENDED BY R ALONG BOTH BLOCKS'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN OFFSET MODE', body)
    return 'cc_outer_acute', lines, MILL, {}, [
        'acute outer corner at (30,0): block X30. ends at (35,5); inserted line (given line 6) to (37.0711,0)',
        'then block 8 continues on its offset line']

@case
def cc_arc_convex():
    # Slot end, G41 clockwise outside: line up x=0, G02 half circle centre
    # (10,20) R10, line down x=20.  Tangent joins -> R-TANGENT: the vector is
    # perpendicular at the junction: (-5,20), (25,20).  Convex arc -> R-ARC:
    # G41 on G02 moves away from the centre: R+r = 15, centre kept (10,20).
    body = ['G90 G17 G40 G00 X-10. Y-10. Z0.',
            'G41 G01 X0. Y0. D1 F100.',
            'Y20.',
            'G02 X20. Y20. I10. J0.',
            'G01 Y0.',
            'G40 X30. Y-10.',
            'M30']
    lines = mill('cc_arc_convex', 'LINE-ARC-LINE TANGENT, CONVEX ARC R10 BECOMES R15',
                 'ARC OFFSET KEEPS THE CENTRE; TANGENT JUNCTIONS GET THE PERPENDICULAR VECTOR'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN OFFSET MODE (LINEAR-CIRCULAR)', body)
    return 'cc_arc_convex', lines, MILL, {}, [
        'start-up inner (left turn): (-5,0); line to (-5,20); arc G02 centre (10,20) R15 to (25,20); line to (25,0)']

@case
def cc_arc_concave():
    # Fillet into a wall, G41: +X to (20,0), G03 centre (20,10) R10 to
    # (30,10), +Y.  Concave arc: G41 on G03 moves towards the centre: R-r=5.
    body = ['G90 G17 G40 G00 X-10. Y-10. Z0.',
            'G41 G01 X0. Y0. D1 F100.',
            'X20.',
            'G03 X30. Y10. I0. J10.',
            'G01 Y30.',
            'G40 X40. Y40.',
            'M30']
    lines = mill('cc_arc_concave', 'CONCAVE FILLET R10 BECOMES R5, CENTRE KEPT',
                 'ARC OFFSET KEEPS THE CENTRE; G41 ON G03 SHORTENS THE RADIUS'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN OFFSET MODE (LINEAR-CIRCULAR)', body)
    return 'cc_arc_concave', lines, MILL, {}, [
        'line y=5 to (20,5); arc G03 centre (20,10) R5 to (25,10); line x=25 to (25,30)']

@case
def cc_arc_nontangent():
    # Cove: +X to (8,0), G03 centre (20,0) R12 through the bottom to (32,0),
    # +X again.  At (8,0): +X then the arc starts downwards: right turn under
    # G41 -> outer, alpha = 90 -> R-OBTUSE with an arc: intersection of the
    # offset line y=5 and the offset circle R12-5=7: x = 20 -+ sqrt(49-25):
    # (15.1010,5) nearest the corner.  Symmetric at (32,0): (24.8990,5).
    # The compensated arc runs counter-clockwise from 134.4 deg to 45.6 deg
    # (sweep 271.2 deg, longer than the programmed 180).
    body = ['G90 G17 G40 G00 X-10. Y-10. Z0.',
            'G41 G01 X0. Y0. D1 F100.',
            'X8.',
            'G03 X32. Y0. I12. J0.',
            'G01 X45.',
            'G40 X55. Y-10.',
            'M30']
    lines = mill('cc_arc_nontangent', 'LINE-ARC AND ARC-LINE NOT TANGENT (CONCAVE COVE, OUTER 90 DEG JUNCTIONS)',
                 'OUTER OBTUSE CORNER WITH AN ARC: INTERSECTION OF OFFSET LINE AND OFFSET CIRCLE'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN OFFSET MODE (LINEAR-CIRCULAR, CIRCULAR-LINEAR)', body)
    return 'cc_arc_nontangent', lines, MILL, {}, [
        'junctions (8,0) and (32,0): intersections (15.1010,5) and (24.8990,5)',
        'compensated arc: centre (20,0) R7, counter-clockwise 271.2 deg']

@case
def cc_circle_pocket():
    # Full circle pocket: start-up from the centre to (20,0) (left turn onto
    # the G03 circle under G41 -> inner -> perpendicular: (15,0)); G03 full
    # circle centre (0,0) R20 -> R15; cancel back to the centre (left turn,
    # inner) -> perpendicular to the circle at its end: (15,0).
    body = ['G90 G17 G40 G00 X0. Y0. Z0.',
            'G41 G01 X20. Y0. D1 F100.',
            'G03 X20. Y0. I-20. J0.',
            'G40 G01 X0. Y0.',
            'M30']
    lines = mill('cc_circle_pocket', 'CLOSED CIRCLE R20 WITH LEAD-IN AND LEAD-OUT FROM THE CENTRE',
                 'FULL-CIRCLE ARC IN OFFSET MODE KEEPS ITS CENTRE (R-R); START-UP/CANCEL INNER SIDE'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN START-UP / IN OFFSET MODE CANCEL', body)
    return 'cc_circle_pocket', lines, MILL, {}, [
        'lead-in to (15,0); full circle G03 centre (0,0) R15 back to (15,0); lead-out to (0,0)']

@case
def cc_side_change():
    # G41 along +X (offset y=5); the next block carries G42 and goes to
    # (30,20): direction (0.4472,0.8944), right normal (0.8944,-0.4472):
    # offset line through (24.4721,-2.2361).  R-SIDE-CHANGE: the vector at
    # the end of the G41 block is the intersection of the two offset paths
    # regardless of inner/outer: y=5 -> t=(5+2.2361)/0.8944=8.0902 ->
    # x = 24.4721+0.4472*8.0902 = 28.0902.
    body = ['G90 G17 G40 G00 X-10. Y-10. Z0.',
            'G41 G01 X0. Y0. D1 F100.',
            'X20.',
            'G42 X30. Y20.',
            'X50.',
            'G40 X60. Y30.',
            'M30']
    lines = mill('cc_side_change', 'CHANGE OF OFFSET DIRECTION G41 TO G42 IN OFFSET MODE',
                 'G41<->G42 IN OFFSET MODE: INTERSECTION OF THE OLD-SIDE AND NEW-SIDE OFFSET PATHS'
                 ' - 0I-F/30I-B OPERATOR MANUAL, CHANGE IN THE OFFSET DIRECTION IN OFFSET MODE', body)
    return 'cc_side_change', lines, MILL, {}, [
        'end of the G41 block: intersection (28.0902,5); then G42 offset paths']

@case
def cc_d_change():
    # D1=5 then D2=8 given in the block 'X40. Y30. D2'.  R-DCHANGE: the vector
    # at the START of that block is computed with the old value (5), the
    # vector at its END with the new value (8): the block's compensated path
    # is not parallel to the programmed one.
    body = ['G10 L11 P2 R8.',
            'G90 G17 G40 G00 X-10. Y-10. Z0.',
            'G41 G01 X0. Y0. D1 F100.',
            'X40.',
            'Y30. D2',
            'X0.',
            'G40 X-10. Y40.',
            'M30']
    lines = mill('cc_d_change', 'CHANGE OF THE OFFSET VALUE D1=5 TO D2=8 IN OFFSET MODE',
                 'NEW VALUE APPLIES TO THE VECTOR AT THE END OF THE BLOCK THAT SPECIFIES IT'
                 ' - 0I-F/30I-B OPERATOR MANUAL, CHANGE OF THE CUTTER COMPENSATION VALUE', body)
    return 'cc_d_change', lines, MILL, {}, [
        'inner pocket corners (G41 counter-clockwise): (35,5) with r=5; (32,22) with r=8; ...']

@case
def cc_g40_ij():
    # Last compensated block +X to (30,0) (offset y=5).  The G40 block gives
    # I0 J10: the control ends the previous block at the intersection of its
    # offset path with the offset of a line through (30,0) in direction
    # (0,1) on the same side (x=25): (25,5), whatever inner/outer, then
    # moves to the programmed end (20,20).  Without I J it would stop at
    # (30,5) (type A).
    body = ['G90 G17 G40 G00 X-10. Y-10. Z0.',
            'G41 G01 X0. Y0. D1 F100.',
            'X30.',
            'G40 X20. Y20. I0. J10.',
            'M30']
    lines = mill('cc_g40_ij', 'G40 WITH I J: PREVIOUS BLOCK ENDS AT THE INTERSECTION WITH THE I J DIRECTION',
                 'I J K IN THE G40 BLOCK - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN OFFSET MODE CANCEL', body)
    return 'cc_g40_ij', lines, MILL, {}, [
        'previous block ends at (25,5) (intersection with the I J line offset), then (20,20)']

NOMOVE = ['G90 G17 G40 G00 X20. Y-10. Z0.',
          'G41 G01 X20. Y0. D1 F100.',
          'X40.',
          None,                 # filled per case
          'Y30.',
          'X10.',
          'G40 X20. Y15.',
          'M30']

@case
def cc_nomove_one():
    # One block without movement in the offset plane (Z only) between X40.
    # and Y30.: within the read-ahead (N=3 blocks, M=1 <= N-2) -> R-NOMOVE:
    # no effect on the path; the Z block runs at the inner-corner
    # intersection (35,5).
    body = [l if l is not None else 'G01 Z-1.' for l in NOMOVE]
    lines = mill('cc_nomove_one', 'ONE BLOCK WITHOUT PLANE MOVEMENT (Z ONLY) INSIDE THE READ-AHEAD',
                 '(N-2)>=M WITH N=3 (0I FIXED; 30I NO.19625=3): INTERSECTION STILL COMPUTED'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN OFFSET MODE (BLOCKS WITHOUT MOVEMENT)', body)
    return 'cc_nomove_one', lines, MILL, {}, [
        'Z-1. executes at the inner corner intersection (35,5)']

@case
def cc_nomove_two():
    # Two blocks without plane movement (dwell and Z only): M=2 > N-2=1 ->
    # R-NOMOVE-EXCEED: X40. ends with the vector perpendicular to itself:
    # (40,5) - the tool centre sits ON the wall x=40 of the next block, an
    # OVERCUT of 5.0 mm (= r) into that wall; the next block runs from (40,5)
    # straight to its own end vector (35,25).
    body = []
    for l in NOMOVE:
        if l is None:
            body += ['G04 P100', 'G01 Z-1.']
        else:
            body.append(l)
    lines = mill('cc_nomove_two', 'TWO BLOCKS WITHOUT PLANE MOVEMENT: PERPENDICULAR VECTOR, 5 MM OVERCUT',
                 'M>N-2: VECTOR PERPENDICULAR TO THE PREVIOUS BLOCK AT ITS END POINT (OVERCUT)'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN OFFSET MODE (BLOCKS WITHOUT MOVEMENT)', body)
    return 'cc_nomove_two', lines, MILL, {}, [
        'X40. ends at (40,5): perpendicular vector; overcut 5.0000 mm into the wall x=40 of block Y30.',
        'Z-1. at (40,5); Y30. then goes (40,5) -> (35,25)']

@case
def cc_alarm_ps0041():
    # Groove 6 mm wide (x 10..16), cutter 10 mm: compensated groove bottom
    # runs from (15,-5) to (11,-5), opposite to the programmed +X ->
    # direction check -> PS0041 on the groove-bottom block.
    body = ['G90 G17 G40 G00 X-10. Y10. Z0.',
            'G41 G01 X0. Y0. D1 F100.',
            'X10.',
            'Y-10.',
            'X16.',
            'Y0.',
            'X30.',
            'G40 X40. Y10.',
            'M30']
    lines = mill('cc_alarm_ps0041', 'GROOVE 6 MM NARROWER THAN THE 10 MM CUTTER: INTERFERENCE',
                 'INTERFERENCE CHECK, DIRECTION REVERSED (90..270 DEG) -> PS0041'
                 ' - 0I-F/30I-B OPERATOR MANUAL, INTERFERENCE CHECK', body)
    return 'cc_alarm_ps0041', lines, MILL, {}, []

@case
def cc_alarm_ps0041_arc():
    # Concave arc R3 < r=5 (G41 on G03 towards the centre: 3-5 < 0).
    body = ['G90 G17 G40 G00 X-10. Y-10. Z0.',
            'G41 G01 X0. Y0. D1 F100.',
            'X20.',
            'G03 X23. Y3. I0. J3.',
            'G01 Y30.',
            'G40 X30. Y40.',
            'M30']
    lines = mill('cc_alarm_ps0041_arc', 'INNER ARC R3 SMALLER THAN THE OFFSET 5: INTERFERENCE',
                 'ARC RADIUS SMALLER THAN THE OFFSET ON THE INSIDE -> PS0041'
                 ' - 0I-F/30I-B OPERATOR MANUAL, INTERFERENCE CHECK / OVERCUTTING', body)
    return 'cc_alarm_ps0041_arc', lines, MILL, {}, []

@case
def cc_alarm_ps0033():
    # Lens of two circles R10, centres (-6,0) and (6,0), followed inside
    # with G41 counter-clockwise.  At (0,8) the corner is inner; the offset
    # circles R5 around centres 12 apart do not meet -> no intersection ->
    # PS0033, on the block whose end vector cannot be found (the first arc).
    body = ['G90 G17 G40 G00 X0. Y-20. Z0.',
            'G41 G01 X0. Y-8. D1 F100.',
            'G03 X0. Y8. I-6. J8.',
            'G03 X0. Y-8. I6. J-8.',
            'G40 G01 X0. Y-20.',
            'M30']
    lines = mill('cc_alarm_ps0033', 'INNER ARC-ARC CORNER WHOSE OFFSET CIRCLES DO NOT MEET',
                 'NO INTERSECTION OF THE OFFSET PATHS -> PS0033'
                 ' - 0I-F/30I-B OPERATOR MANUAL, TOOL MOVEMENT IN OFFSET MODE (NO INNER INTERSECTION)', body)
    return 'cc_alarm_ps0033', lines, MILL, {}, []

@case
def cc_alarm_ps0034():
    body = ['G90 G17 G40 G00 X-10. Y0. Z0.',
            'G41 G02 X10. Y0. I10. J0. D1 F100.',
            'G40 G01 X20. Y0.',
            'M30']
    lines = mill('cc_alarm_ps0034', 'G02 IN THE START-UP BLOCK',
                 'START-UP MUST BE G00 OR G01 -> PS0034 - 0I-F/30I-B OPERATOR MANUAL, START-UP', body)
    return 'cc_alarm_ps0034', lines, MILL, {}, []

@case
def cc_alarm_ps0037():
    body = ['G90 G17 G40 G00 X-10. Y-10. Z0.',
            'G41 G01 X0. Y0. D1 F100.',
            'X20.',
            'G18',
            'X30.',
            'G40 X40. Y-10.',
            'M30']
    lines = mill('cc_alarm_ps0037', 'PLANE CHANGE G17 TO G18 WHILE G41 IS ACTIVE',
                 'OFFSET PLANE FIXED IN OFFSET MODE -> PS0037 - 0I-F/30I-B OPERATOR MANUAL, OFFSET PLANE', body)
    return 'cc_alarm_ps0037', lines, MILL, {}, []


# ------------------------------------------------------------------- lathe
# Tool nose radius r = 0.8, offset set 1 (T0101), geometry x = z = 0.
# Plane G18 is drawn with Z to the right and X up (seen from +Y): G02 is
# clockwise there and G41 is the left of the direction of motion.  OD work
# towards the chuck: G42; ID (boring): G41.  The control offsets the nose
# CENTRE by r exactly like cutter compensation, then commands the imaginary
# tip = centre + tip vector (R-TIP): tip 3 = (-r in X, -r in Z), tip 2 =
# (+r X, -r Z), tip 8 = (-r X, 0).
def lathe(name, title, rule, body):
    return [comment('%s: %s' % (name.upper(), title)), comment('RULE: %s' % rule), 'T0101'] + body

OD_CHAMFER = ['G99 G40 G00 X16. Z5.', 'G42 G01 Z0. F0.1', 'X20. Z-2.', 'Z-15.', 'X30.', 'G40 G00 X40. Z5.', 'M30']
OD_TAPER = ['G99 G40 G00 X16. Z5.', 'G42 G01 Z0. F0.1', 'X24. Z-12.', 'Z-20.', 'X32.', 'G40 G00 X40. Z5.', 'M30']
OD_ARC = ['G99 G40 G00 X10. Z5.', 'G42 G01 Z0. F0.1', 'G03 X20. Z-5. K-5.', 'G01 Z-15.', 'X30.', 'G40 G00 X40. Z5.', 'M30']
ID_CHAMFER = ['G99 G40 G00 X24. Z5.', 'G41 G01 Z0. F0.1', 'X20. Z-2.', 'Z-15.', 'X14.', 'G40 G00 X10. Z5.', 'M30']
ID_TAPER = ['G99 G40 G00 X30. Z5.', 'G41 G01 Z0. F0.1', 'X22. Z-12.', 'Z-20.', 'X14.', 'G40 G00 X10. Z5.', 'M30']
ID_ARC = ['G99 G40 G00 X30. Z5.', 'G41 G01 Z0. F0.1', 'G02 X20. Z-5. K-5.', 'G01 Z-15.', 'X14.', 'G40 G00 X10. Z5.', 'M30']
OD_PROFILE = ['G99 G40 G00 X10. Z5.', 'G42 G01 Z0. F0.1', 'X14. Z-2.', 'Z-6.', 'X20. Z-12.',
              'G03 X26. Z-15. K-3.', 'G01 Z-25.', 'X34.', 'G40 G00 X40. Z5.', 'M30']

def lathe_case(name, title, rule, body, tip, notes):
    return name, lathe(name, title, rule, body), LATHE(0.8, tip), {}, notes

R_TNRC = 'TOOL NOSE RADIUS COMPENSATION, IMAGINARY TOOL NOSE DIRECTION - 0I-F/30I-B OPERATOR MANUAL (LATHE)'

@case
def nt_chamfer_t3():
    # Start-up (X16,Z5)->(X16,Z0) moving -Z, next block the 45 deg chamfer
    # moving (-Z,+X): right turn under G42 -> inner -> perpendicular to the
    # chamfer at its start: centre (Z0.5657, Xr8.5657); tip 3 adds (-0.8,
    # -0.8): tip (Z-0.2343, X diameter 15.5314).
    return lathe_case('nt_chamfer_t3', 'OD 45 DEG CHAMFER, G42, TIP 3', 'G42 OD CHAMFER WITH TIP 3; ' + R_TNRC,
                      OD_CHAMFER, 3, ['start-up end: nose centre (Z0.5657, X17.1314 dia) -> tip (Z-0.2343, X15.5314)'])

@case
def nt_taper_t3():
    return lathe_case('nt_taper_t3', 'OD TAPER 18.43 DEG, G42, TIP 3', 'G42 OD TAPER WITH TIP 3; ' + R_TNRC,
                      OD_TAPER, 3, ['taper offset by 0.8 normal to it; tip = centre + (-0.8 X radius, -0.8 Z)'])

@case
def nt_arc_t3():
    # Convex corner G03 R5 centre (Z-5, X10 dia): the nose centre runs on
    # R5.8 about it; the tip arc is that arc moved by (-0.8,-0.8): centre
    # (Z-5.8, X8.4 dia).
    return lathe_case('nt_arc_t3', 'OD CONVEX CORNER ARC R5, G42, TIP 3', 'G42 OD ARC WITH TIP 3; ' + R_TNRC,
                      OD_ARC, 3, ['tip arc centre = programmed centre + tip vector: (Z-5.8, X8.4 dia), radius 5.8'])

@case
def nt_chamfer_t2():
    return lathe_case('nt_chamfer_t2', 'ID 45 DEG CHAMFER, G41, TIP 2 (BORING)', 'G41 ID CHAMFER WITH TIP 2; ' + R_TNRC,
                      ID_CHAMFER, 2, ['tip = centre + (+0.8 X radius, -0.8 Z)'])

@case
def nt_taper_t2():
    return lathe_case('nt_taper_t2', 'ID TAPER, G41, TIP 2 (BORING)', 'G41 ID TAPER WITH TIP 2; ' + R_TNRC,
                      ID_TAPER, 2, ['tip = centre + (+0.8 X radius, -0.8 Z)'])

@case
def nt_arc_t2():
    return lathe_case('nt_arc_t2', 'ID CONVEX ENTRY ARC R5 (G02), G41, TIP 2', 'G41 ID ARC WITH TIP 2; ' + R_TNRC,
                      ID_ARC, 2, ['G41 on G02 away from the centre: R5.8; tip arc centre = (Z-5.8, X31.6 dia)'])

@case
def nt_profile_t8():
    return lathe_case('nt_profile_t8', 'OD CHAMFER, TAPER AND ARC WITH TIP 8 (TIP BELOW THE NOSE CENTRE)',
                      'G42 WITH TIP 8: TIP = CENTRE - R IN X ONLY; ' + R_TNRC,
                      OD_PROFILE, 8, ['tip = centre + (-0.8 X radius, 0 Z)', 'taper->arc junction inner: line/circle intersection'])


def main():
    for fn in CASES:
        name, lines, machine, params, notes = fn()
        header = ['%s: derived by tests/programs/derive/derive.py from the rules of docs/compensation-spec.md' % name]
        header += notes
        if machine['type'] == 'lathe':
            write_lathe_profile(name, 0.8, machine['tools'][1][0])
        res = write_case(name, lines, header, machine, params)
        print(name, res)

if __name__ == '__main__':
    main()


def selfcheck():
    """Closed-form values worked out on paper, compared with the files."""
    def move(name, idx):
        with open(out(name, '.expected.moves')) as f:
            return [l.split() for l in f if not l.startswith('#')][idx]
    # start-up type B obtuse: offset line of (10,-15)->(0,0) meets x = -5
    d = unit((-10, 15)); p = mul(left(d), 5)
    y_b = p[1] + (-5 - p[0]) / d[0] * d[1]
    # G41 -> G42: y = 5 meets the right-hand offset of (20,0)->(30,20)
    d2 = unit((10, 20)); p2 = add((20, 0), mul(left(d2), -5))
    x_sc = p2[0] + (5 - p2[1]) / d2[1] * d2[0]
    checks = [  # name, move index, column (2 = X, 3 = Y), value
        ('cc_outer_obtuse', 2, 2, 30 + 5 * math.tan(math.radians(30))),
        ('cc_arc_nontangent', 2, 2, 20 - math.sqrt(7 ** 2 - 5 ** 2)),
        ('cc_arc_nontangent', 3, 2, 20 + math.sqrt(7 ** 2 - 5 ** 2)),
        ('cc_outer_acute', 3, 2, 30 + 5 * math.sqrt(2)),
        ('cc_startup_b', 1, 3, y_b),
        ('cc_side_change', 2, 2, x_sc),
        ('nt_chamfer_t3', 1, 2, 2 * (8 + 0.8 * math.sqrt(0.5) - 0.8)),
        ('nt_chamfer_t3', 2, 2, 20.0),          # tip 3 on a diameter = programmed X
        ('nt_arc_t3', 2, 5, 8.4),               # tip arc centre X (diameter)
    ]
    for name, idx, col, val in checks:
        m = move(name, idx)
        assert abs(float(m[col]) - val) < 1e-4, (name, idx, m, val)
    print('selfcheck ok')


if __name__ == '__main__':
    selfcheck()
