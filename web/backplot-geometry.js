// The moves of a backplot (web/backplot.js) as line segments for the GPU: the extents (arcs
// included, exactly), the segments per arc, and one position buffer per kind of move, written
// relative to the extents' centre so that Float32 keeps its precision. Pick colours are made when
// first asked for. No three.js here: typed arrays only.
//
//   const g = NcurveBackplotGeometry.build(moves);   // moves as NcurveBackplot.create takes them
//   g.layers[k].pos (X Y Z of both ends per segment), g.first[i], g.segOf[i], g.lo, g.hi, g.toWorld(p, out)
//   g.frameLo, g.frameHi: the box a view fits, machine X Y Z: the cuts and the rapids near them (not
//   those to and from a home position far off); the whole box where there are no cuts
//   NcurveBackplotGeometry.build(moves, also): the boxes widened to hold also's {lo, hi, frameLo,
//   frameHi} (another run's, drawn with these moves: backplot-compare.js)
(function (global) {
  'use strict';
  const PLANE_AXES = {17: [0, 1], 18: [2, 0], 19: [1, 2]};
  const HALF_PI = Math.PI / 2;

  function build(moves, also) {
    const n = moves.count, K = moves.kind, S = moves.start, E = moves.end, A = moves.arcs, AI = moves.arcIndex;
    const RC = moves.rapidCorners || new Map();  // a dog-leg rapid's corners
    // machine X Y Z -> world: a lathe's Z across and X up (a rotation, so arcs keep their sense)
    const perm = moves.lathe ? [2, 0, 1] : [0, 1, 2];  // world axis k takes machine axis perm[k]

    // per arc (by its index): plane axes p q, centre, start and end radius, start angle, sweep
    const arcCount = Math.floor(A.length / 5);
    const arc = new Float64Array(8 * arcCount);
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    let lo0 = Infinity, lo1 = Infinity, lo2 = Infinity, hi0 = -Infinity, hi1 = -Infinity, hi2 = -Infinity;
    // an axis counts from its first move on: where it stood before (on the shipped mill the
    // reference position, far above the part) is not the program's, and the view frames the
    // program; a cut (a feed or an arc) counts from where it starts, wherever that is
    let m0 = false, m1 = false, m2 = false;
    // the frame: the cuts' box (lines and arcs), which a view fits, and the rapids near it (below)
    const flo = [Infinity, Infinity, Infinity], fhi = [-Infinity, -Infinity, -Infinity];
    const frame = (x, y, z) => {
      if (x < flo[0]) flo[0] = x; if (x > fhi[0]) fhi[0] = x;
      if (y < flo[1]) flo[1] = y; if (y > fhi[1]) fhi[1] = y;
      if (z < flo[2]) flo[2] = z; if (z > fhi[2]) fhi[2] = z;
    };
    for (let i = 0, s = 0; i < n; i++, s += 3) {
      const sx = S[s], sy = S[s + 1], sz = S[s + 2], ex = E[s], ey = E[s + 1], ez = E[s + 2], cut = K[i] !== 0;
      if (cut) frame(sx, sy, sz), frame(ex, ey, ez);
      if (m0 || cut) { if (sx < lo0) lo0 = sx; if (sx > hi0) hi0 = sx; }
      if (m1 || cut) { if (sy < lo1) lo1 = sy; if (sy > hi1) hi1 = sy; }
      if (m2 || cut) { if (sz < lo2) lo2 = sz; if (sz > hi2) hi2 = sz; }
      m0 = m0 || sx !== ex || K[i] === 2, m1 = m1 || sy !== ey || K[i] === 2, m2 = m2 || sz !== ez || K[i] === 2;
      if (m0) { if (ex < lo0) lo0 = ex; if (ex > hi0) hi0 = ex; }
      if (m1) { if (ey < lo1) lo1 = ey; if (ey > hi1) hi1 = ey; }
      if (m2) { if (ez < lo2) lo2 = ez; if (ez > hi2) hi2 = ez; }
      if (K[i] !== 2) continue;  // (a dog-leg's corners lie in the box of its ends)
      const a = 5 * AI[i], c = 8 * AI[i], plane = PLANE_AXES[A[a + 4]] || PLANE_AXES[17], p = plane[0], q = plane[1];
      const cp = A[a + p], cq = A[a + q];
      const sp = S[s + p] - cp, sq = S[s + q] - cq, ep = E[s + p] - cp, eq = E[s + q] - cq;
      const rs = Math.sqrt(sp * sp + sq * sq), re = Math.sqrt(ep * ep + eq * eq), a0 = Math.atan2(sq, sp), sweep = A[a + 3];
      arc[c] = p, arc[c + 1] = q, arc[c + 2] = cp, arc[c + 3] = cq, arc[c + 4] = rs, arc[c + 5] = re, arc[c + 6] = a0, arc[c + 7] = sweep;
      // the quarter points the arc passes (its radius linear in the angle: a spiral's too)
      const from = Math.min(a0, a0 + sweep), to = Math.max(a0, a0 + sweep);
      for (let m = Math.ceil(from / HALF_PI), last = Math.min(Math.floor(to / HALF_PI), m + 8); m <= last; m++) {
        const t = sweep ? (m * HALF_PI - a0) / sweep : 0, r = rs + (re - rs) * t;
        const u = cp + r * Math.cos(m * HALF_PI), v = cq + r * Math.sin(m * HALF_PI);
        const at = [S[s], S[s + 1], S[s + 2]];
        at[p] = u, at[q] = v;
        frame(at[0], at[1], at[2]);
        if (p === 0 || q === 0) { const x = p === 0 ? u : v; if (x < lo0) lo0 = x; if (x > hi0) hi0 = x; }
        if (p === 1 || q === 1) { const y = p === 1 ? u : v; if (y < lo1) lo1 = y; if (y > hi1) hi1 = y; }
        if (p === 2 || q === 2) { const z = p === 2 ? u : v; if (z < lo2) lo2 = z; if (z > hi2) hi2 = z; }
      }
    }
    if (n) {  // an axis nothing counted (it never moves, no cut): where it stands
      if (!(lo0 <= hi0)) lo0 = hi0 = S[0];
      if (!(lo1 <= hi1)) lo1 = hi1 = S[1];
      if (!(lo2 <= hi2)) lo2 = hi2 = S[2];
    }
    lo[0] = lo0, lo[1] = lo1, lo[2] = lo2, hi[0] = hi0, hi[1] = hi1, hi[2] = hi2;
    if (moves.alarmAt) for (let k = 0; k < 3; k++) lo[k] = Math.min(lo[k], moves.alarmAt[k]), hi[k] = Math.max(hi[k], moves.alarmAt[k]);
    if (!(lo[0] <= hi[0])) { lo.fill(0); hi.fill(0); }
    if (Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) < 1e-6)  // no path (an alarm at once): a 10 mm box
      for (let k = 0; k < 3; k++) lo[k] -= 5, hi[k] += 5;
    if (also) for (let k = 0; k < 3; k++) lo[k] = Math.min(lo[k], also.lo[k]), hi[k] = Math.max(hi[k], also.hi[k]);
    const diag = Math.max(Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]), 1e-3);
    // no cuts, or cuts along a line or a point only: the frame is the whole box; else the rapids'
    // ends near the cuts (within a quarter of their diagonal: clearance planes, approaches) join it
    const cutDiag = Math.hypot(fhi[0] - flo[0], fhi[1] - flo[1], fhi[2] - flo[2]);
    if (!(flo[0] <= fhi[0]) || cutDiag < diag * 1e-3) {
      for (let k = 0; k < 3; k++) flo[k] = lo[k], fhi[k] = hi[k];
    } else {
      const m = cutDiag / 4, nlo = flo.map((v) => v - m), nhi = fhi.map((v) => v + m);
      const near = (P, s) => P[s] >= nlo[0] && P[s] <= nhi[0] && P[s + 1] >= nlo[1] && P[s + 1] <= nhi[1] &&
                             P[s + 2] >= nlo[2] && P[s + 2] <= nhi[2];
      for (let i = 0, s = 0; i < n; i++, s += 3) {
        if (K[i] !== 0) continue;
        if (near(S, s)) frame(S[s], S[s + 1], S[s + 2]);
        if (near(E, s)) frame(E[s], E[s + 1], E[s + 2]);
      }
    }
    if (moves.alarmAt) for (let k = 0; k < 3; k++) flo[k] = Math.min(flo[k], moves.alarmAt[k]), fhi[k] = Math.max(fhi[k], moves.alarmAt[k]);
    if (also) for (let k = 0; k < 3; k++) flo[k] = Math.min(flo[k], also.frameLo[k]), fhi[k] = Math.max(fhi[k], also.frameHi[k]);
    const origin = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2];
    const P0 = perm[0], P1 = perm[1], P2 = perm[2], O0 = origin[P0], O1 = origin[P1], O2 = origin[P2];
    const toWorld = (m, out) => {  // machine point -> world, relative to the origin
      out[0] = m[P0] - O0, out[1] = m[P1] - O1, out[2] = m[P2] - O2;
      return out;
    };

    // segments per arc: chord error within a 5000th of the extent, fewer if there would be too many
    const segOf = new Uint16Array(n);
    let tol = diag / 5000, total = 0;
    for (let pass = 0; pass < 6; pass++) {
      total = 0;
      for (let i = 0; i < n; i++) {
        let segs = 1;
        if (K[i] === 0 && RC.has(i)) segs = 1 + RC.get(i).length / 3;
        else if (K[i] === 2) {
          const c = 8 * AI[i], r = Math.max(arc[c + 4], 1e-9);
          const step = 2 * Math.acos(Math.max(-1, 1 - tol / r));
          segs = Math.max(1, Math.min(720, Math.ceil(Math.abs(arc[c + 7]) / Math.max(step, 1e-4)) || 1));
        }
        total += segOf[i] = segs;
      }
      if (total <= Math.max(6e6, 2 * n)) break;
      tol *= 4;
    }
    const counts = [0, 0, 0], moveCounts = [0, 0, 0];
    const first = new Uint32Array(n);  // a move's first segment in its kind's layer
    for (let i = 0; i < n; i++) {
      const k = K[i];
      first[i] = counts[k];
      counts[k] += segOf[i];
      moveCounts[k]++;
    }

    // the layers: both ends of each segment; the rapids' dash distances along each move
    const layers = counts.map((c, k) => ({count: c, pos: new Float32Array(6 * c), dist: k === 0 ? new Float32Array(2 * c) : null}));
    const pt = [0, 0, 0];
    for (let i = 0, s = 0; i < n; i++, s += 3) {
      const k = K[i], pos = layers[k].pos;
      let v = 6 * first[i];
      let x0 = S[s + P0] - O0, y0 = S[s + P1] - O1, z0 = S[s + P2] - O2;
      const ex = E[s + P0] - O0, ey = E[s + P1] - O1, ez = E[s + P2] - O2;
      if (k === 0) {  // a rapid: straight, or through its corners; dash distances along it
        const corners = RC.get(i), d = layers[0].dist;
        let along = 0;
        for (let j = 0; j < segOf[i]; j++, v += 6) {
          let x1 = ex, y1 = ey, z1 = ez;
          if (j + 1 < segOf[i]) {
            pt[0] = corners[3 * j], pt[1] = corners[3 * j + 1], pt[2] = corners[3 * j + 2];
            x1 = pt[P0] - O0, y1 = pt[P1] - O1, z1 = pt[P2] - O2;
          }
          pos[v] = x0, pos[v + 1] = y0, pos[v + 2] = z0, pos[v + 3] = x1, pos[v + 4] = y1, pos[v + 5] = z1;
          const at = 2 * (first[i] + j);
          d[at] = along;
          along += Math.sqrt((x1 - x0) ** 2 + (y1 - y0) ** 2 + (z1 - z0) ** 2);
          d[at + 1] = along;
          x0 = x1, y0 = y1, z0 = z1;
        }
        continue;
      }
      if (k === 1) {
        pos[v] = x0, pos[v + 1] = y0, pos[v + 2] = z0, pos[v + 3] = ex, pos[v + 4] = ey, pos[v + 5] = ez;
        continue;
      }
      const c = 8 * AI[i], p = arc[c], q = arc[c + 1], cp = arc[c + 2], cq = arc[c + 3], rs = arc[c + 4], re = arc[c + 5];
      const segs = segOf[i], turn = arc[c + 7] / segs, cd = Math.cos(turn), sd = Math.sin(turn);
      let ca = Math.cos(arc[c + 6]), sa = Math.sin(arc[c + 6]);
      for (let j = 1; j <= segs; j++, v += 6) {
        let x1 = ex, y1 = ey, z1 = ez;
        if (j < segs) {  // the point j/segs of the way: the rotation stepped on, the rest linear
          const nc = ca * cd - sa * sd;
          sa = sa * cd + ca * sd, ca = nc;
          const t = j / segs, r = rs + (re - rs) * t;
          pt[0] = S[s] + (E[s] - S[s]) * t, pt[1] = S[s + 1] + (E[s + 1] - S[s + 1]) * t, pt[2] = S[s + 2] + (E[s + 2] - S[s + 2]) * t;
          pt[p] = cp + r * ca, pt[q] = cq + r * sa;
          x1 = pt[P0] - O0, y1 = pt[P1] - O1, z1 = pt[P2] - O2;
        }
        pos[v] = x0, pos[v + 1] = y0, pos[v + 2] = z0, pos[v + 3] = x1, pos[v + 4] = y1, pos[v + 5] = z1;
        x0 = x1, y0 = y1, z0 = z1;
      }
    }

    // each segment's move number + 1 as an RGB colour, for picking by rendering (made when asked)
    const pickColors = (k) => {
      const col = new Uint8Array(6 * counts[k]);
      for (let i = 0; i < n; i++) {
        if (K[i] !== k) continue;
        const id = i + 1, r = id & 255, g = (id >> 8) & 255, b = (id >> 16) & 255;
        for (let v = 6 * first[i], e = 6 * (first[i] + segOf[i]); v < e; v += 3) col[v] = r, col[v + 1] = g, col[v + 2] = b;
      }
      return col;
    };

    return {lo, hi, frameLo: flo, frameHi: fhi, diag, origin, perm, toWorld, segOf, first, counts, moveCounts, total, layers, pickColors};
  }

  global.NcurveBackplotGeometry = {build, PLANE_AXES};
})(window);
