// Reading POST /api/run's answer for the workbench (docs/serve.md): the JSON or binary answer
// (its arrays typed arrays over the bytes), a second answer's trace in the first one's file
// numbers, and the moves as the backplot takes them.
//   const j = await NcurveAnswer.read(response);
//   const moves = NcurveAnswer.movesForPlot(j.moves, profile);
(function (global) {
  'use strict';
  // the trace of a second answer with its file numbers made those of the first
  function traceInFiles(trace, from, to) {
    const map = from.map((f) => {
      if (!to.includes(f)) to.push(f);
      return to.indexOf(f);
    });
    const file = trace.blocks.file;
    for (let b = 0; b < file.length; b++) file[b] = map[file[b]];
    for (const stack of trace.stacks) for (const f of stack) if (f.call_file !== undefined) f.call_file = map[f.call_file];
    return trace;
  }
  // a JSON answer, or a binary one (docs/serve.md): its JSON with each array named by offset made a
  // typed array over the answer's bytes
  const ARRAY_TYPES = {f64: Float64Array, u8: Uint8Array, u32: Uint32Array, i32: Int32Array};
  async function readAnswer(r) {
    if (!(r.headers.get('Content-Type') || '').startsWith('application/octet-stream')) return r.json();
    const buf = await r.arrayBuffer(), dv = new DataView(buf);
    if (buf.byteLength < 8 || dv.getUint32(0, true) !== 0x3142434e) throw new Error('not an ncurve binary answer');
    const base = 8, length = dv.getUint32(4, true);
    const j = JSON.parse(new TextDecoder().decode(new Uint8Array(buf, base + length)));
    const resolve = (o) => {
      for (const k of Object.keys(o)) {
        const v = o[k];
        if (!v || typeof v !== 'object') continue;
        if (ARRAY_TYPES[v.type] && typeof v.offset === 'number') o[k] = new ARRAY_TYPES[v.type](buf, base + v.offset, v.count);
        else resolve(v);
      }
    };
    if (j.moves) resolve(j.moves);
    if (j.trace) resolve(j.trace);
    return j;
  }
  // the answer's moves as the backplot takes them (docs/html.md): motions only; a lathe's X halved
  // to a radius on a profile p programmed in diameter; the A, B, C axes the motions move away from 0
  // (not drawn) as `rotary`, with their range, and each motion's end of them in `rotaryEnd`
  function movesForPlot(m, p) {
    const K = m.kinds, R = K.indexOf('rapid'), LN = K.indexOf('line'), A = K.indexOf('arc'), DW = K.indexOf('dwell');
    const N = m.count, xs = p.diameter ? 0.5 : 1;
    let n = 0;
    for (let i = 0; i < N; i++) { const k = m.kind[i]; if (k === R || k === LN || k === A) n++; }
    const c = {count: n, kind: new Uint8Array(n), start: new Float32Array(3 * n), end: new Float32Array(3 * n),
      arcIndex: new Int32Array(n), arcs: new Float32Array(5 * m.arcs.index.length), line: new Uint32Array(n),
      file: new Uint16Array(n), feed: new Float32Array(n), moveOf: new Uint32Array(n), before: new Uint32Array(N + 1),
      lathe: !!p.lathe, diameter: !!p.diameter, inch: false, plane: p.lathe ? 18 : 17, alarmAt: null, last: [0, 0, 0]};
    let px = 0, py = 0, pz = 0, s = 0, a = 0, j = 0;
    const S = m.starts, AR = m.arcs;
    // per axis of the answer's a, b, c: its column, its start and end per motion, its range
    const other = ['a', 'b', 'c'].filter((k) => m[k]).map((k) => ({axis: k.toUpperCase(), col: m[k], starts: S[k],
      end: new Float64Array(n), at: 0, min: Infinity, max: -Infinity}));
    for (let i = 0; i < N; i++) {
      c.before[i] = j;
      if (s < S.index.length && S.index[s] === i) {
        px = S.x[s] * xs, py = S.y[s], pz = S.z[s];
        for (const o of other) if (o.starts) o.at = o.starts[s];
        s++;
      }
      const k = m.kind[i], ex = m.x[i] * xs, ey = m.y[i], ez = m.z[i];
      if (k === R || k === LN || k === A) {
        for (const o of other) {
          const e = o.end[j] = o.col[i];
          o.min = Math.min(o.min, o.at, e), o.max = Math.max(o.max, o.at, e);
        }
        c.kind[j] = k === R ? 0 : k === LN ? 1 : 2;
        c.start[3 * j] = px, c.start[3 * j + 1] = py, c.start[3 * j + 2] = pz;
        c.end[3 * j] = ex, c.end[3 * j + 1] = ey, c.end[3 * j + 2] = ez;
        c.arcIndex[j] = -1;
        if (k === A) {
          while (a < AR.index.length && AR.index[a] < i) a++;
          const o = 5 * a;
          c.arcs[o] = AR.cx[a] * xs, c.arcs[o + 1] = AR.cy[a], c.arcs[o + 2] = AR.cz[a];
          c.arcs[o + 3] = AR.sweep_deg[a] * Math.PI / 180, c.arcs[o + 4] = AR.plane[a];
          c.arcIndex[j] = a++;
        }
        c.line[j] = m.line[i], c.file[j] = m.file[i], c.feed[j] = m.f[i], c.moveOf[j] = i;
        j++;
      }
      if (k === R || k === LN || k === A || k === DW) {
        px = ex, py = ey, pz = ez;
        for (const o of other) o.at = o.col[i];
      }
    }
    c.before[N] = j;
    c.last = [px, py, pz];
    // a dog-leg rapid's corners, by motion
    c.rapidCorners = new Map();
    const KC = m.corners;
    if (KC) for (let q = 0; q < KC.index.length; q++) {
      const i = KC.index[q];
      if (i >= N || m.kind[i] !== R) continue;
      const mj = c.before[i];
      if (!c.rapidCorners.has(mj)) c.rapidCorners.set(mj, []);
      c.rapidCorners.get(mj).push(KC.x[q] * xs, KC.y[q], KC.z[q]);
    }
    // as `run --html`'s data: degrees for a rotary axis of the profile (No.1006#0), else mm
    const moved = other.filter((o) => o.min <= o.max && !(o.min === 0 && o.max === 0));
    c.rotary = moved.map((o) => ({axis: o.axis, unit: (p.rotary || '').includes(o.axis) ? 'deg' : 'mm', min: o.min, max: o.max}));
    c.rotaryEnd = new Float64Array(moved.length * n);
    moved.forEach((o, r) => c.rotaryEnd.set(o.end, r * n));
    c.programmed = programmedForPlot(m, xs);
    return c;
  }
  // the programmed contour under cutter compensation (the answer's "programmed" and "programmed_arcs")
  // as moves the backplot takes: lines (kind 1) and arcs (kind 2) from each programmed start to end
  function programmedForPlot(m, xs) {
    const P = m.programmed, PA = m.programmed_arcs || {index: []};
    const n = P ? P.index.length : 0;
    const c = {count: n, kind: new Uint8Array(n), start: new Float64Array(3 * n), end: new Float64Array(3 * n),
      arcIndex: new Int32Array(n), arcs: new Float32Array(5 * PA.index.length), move: new Uint32Array(n), lathe: false};
    const AR = m.arcs;
    for (let e = 0, a = 0, b = 0; e < n; e++) {
      const i = P.index[e];
      c.start.set([P.sx[e] * xs, P.sy[e], P.sz[e]], 3 * e);
      c.end.set([P.x[e] * xs, P.y[e], P.z[e]], 3 * e);
      c.move[e] = i;
      c.kind[e] = 1;
      c.arcIndex[e] = -1;
      while (a < PA.index.length && PA.index[a] < i) a++;
      if (a < PA.index.length && PA.index[a] === i) {
        while (b < AR.index.length && AR.index[b] < i) b++;
        c.arcs.set([PA.cx[a] * xs, PA.cy[a], PA.cz[a], PA.sweep_deg[a] * Math.PI / 180, AR.plane[b]], 5 * a);
        c.kind[e] = 2;
        c.arcIndex[e] = a;
      }
    }
    return c;
  }

  global.NcurveAnswer = {read: readAnswer, traceInFiles, movesForPlot};
})(window);
