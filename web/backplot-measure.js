// The backplot's Measure tool (web/backplot.js): two clicks on the path give the distance between
// them, ΔX ΔY ΔZ and, for a click on an arc, its radius and centre. A click snaps to the nearest move
// end within SNAP px, else to the nearest point of a move; in a view along an axis (top, front,
// ZX...) a click off the path takes the point of the view's plane under the pointer. The points and
// the line between them are drawn in the scene; the readout is a panel over the view, in the place
// of the legend (.ncurve-legend of the container), which it hides while it is on. A click looks
// only at the segments and ends near its line of sight (backplot-snap.js). Needs three.js.
//
//   const m = NcurveBackplotMeasure.create({scene, container, canvas, camera, moves, geometry, where, requestRender});
//   m.set(true); m.click(clientX, clientY); m.key(event); m.state(); m.button(); m.dispose();
// where(i): how the readout names move i ("block N10 line 12"); a lathe's X is shown as the axes
// show it (a diameter where the machine programs diameters), lengths in the page's unit.
(function (global) {
  'use strict';
  const THREE = global.THREE;
  const SNAP = 8;  // px
  const COLOUR = 0x6a1b9a;
  const PLANE_AXES = {17: [0, 1], 18: [2, 0], 19: [1, 2]};

  // a round point sprite, drawn once
  let dotTexture = null;
  const dot = () => {
    if (dotTexture) return dotTexture;
    const c = document.createElement('canvas');
    c.width = c.height = 32;
    const g = c.getContext('2d');
    g.fillStyle = '#fff';
    g.beginPath();
    g.arc(16, 16, 14, 0, 2 * Math.PI);
    g.fill();
    return (dotTexture = new THREE.CanvasTexture(c));
  };

  function create({scene, container, canvas, camera, moves, geometry, where, requestRender}) {
    const G = geometry, n = moves.count, {origin, perm} = G;
    const unit = moves.inch ? 25.4 : 1, unitName = moves.inch ? 'in' : 'mm', places = moves.inch ? 4 : 3;
    const xShown = moves.lathe && moves.diameter ? 2 : 1;  // a lathe's X as a diameter
    const letters = moves.lathe ? [0, 2] : [0, 1, 2];  // the machine axes the readout gives
    const name = (a) => (a === 0 && xShown === 2 ? 'X⌀' : 'XYZ'[a]);
    const shown = (a, v) => v * (a === 0 ? xShown : 1) / unit;
    const num = (v) => (Math.abs(v) < 1e-9 ? 0 : v).toFixed(places).replace(/\.?0+$/, '') || '0';
    const len = (v) => (v / unit).toFixed(places);
    const toMachine = (w) => { const m = [0, 0, 0]; for (let k = 0; k < 3; k++) m[perm[k]] = w[k] + origin[perm[k]]; return m; };
    const toWorld = (m) => G.toWorld(m, [0, 0, 0]);

    let on = false, points = [];  // points: {at (machine X Y Z), snap: 'end' | 'on' | 'plane', move, arc}
    const positions = new THREE.BufferAttribute(new Float32Array(6), 3);
    const pg = new THREE.BufferGeometry();
    pg.setAttribute('position', positions);
    const dots = new THREE.Points(pg, new THREE.PointsMaterial({color: COLOUR, size: 11, sizeAttenuation: false, map: dot(),
      transparent: true, alphaTest: 0.5, depthTest: false}));
    const line = new THREE.Line(pg, new THREE.LineBasicMaterial({color: COLOUR, depthTest: false, transparent: true}));
    for (const o of [dots, line]) o.renderOrder = 12, o.frustumCulled = false, o.visible = false, scene.add(o);

    const panel = document.createElement('div');
    panel.className = 'ncurve-measure';
    panel.hidden = true;
    panel.setAttribute('data-keep-clear', '');
    container.appendChild(panel);
    let toolButton = null;

    // the screen (canvas px) of world points: the camera's matrices once per click
    const screenOf = () => {
      camera.updateMatrixWorld();
      const M = new THREE.Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse).elements;
      const W = canvas.clientWidth, H = canvas.clientHeight;
      return (x, y, z, out) => {
        out[0] = (M[0] * x + M[4] * y + M[8] * z + M[12] + 1) / 2 * W;
        out[1] = (1 - (M[1] * x + M[5] * y + M[9] * z + M[13])) / 2 * H;
        return out;
      };
    };
    // the move each segment of a kind's layer belongs to, made at the first click
    let segMove = null;
    const segMoves = () => {
      if (segMove) return segMove;
      segMove = G.counts.map((c) => new Uint32Array(c));
      for (let i = 0; i < n; i++) segMove[moves.kind[i]].fill(i, G.first[i], G.first[i] + G.segOf[i]);
      return segMove;
    };
    // move i's arc: its centre (machine), plane axes, start angle, sweep, radii at the ends
    const arcOf = (i) => {
      const a = moves.arcIndex[i];
      if (moves.kind[i] !== 2 || a < 0) return null;
      const A = moves.arcs, o = 5 * a, [p, q] = PLANE_AXES[A[o + 4]] || PLANE_AXES[17], c = [A[o], A[o + 1], A[o + 2]];
      const s = moves.start.subarray(3 * i, 3 * i + 3), e = moves.end.subarray(3 * i, 3 * i + 3);
      return {c, p, q, a0: Math.atan2(s[q] - c[q], s[p] - c[p]), sweep: A[o + 3],
        rs: Math.hypot(s[p] - c[p], s[q] - c[q]), re: Math.hypot(e[p] - c[p], e[q] - c[q]), s, e};
    };
    // the point of arc r the fraction u of the way along it (as backplot-geometry.js draws it)
    const onArc = (r, u) => {
      const at = [0, 1, 2].map((k) => r.s[k] + (r.e[k] - r.s[k]) * u), ang = r.a0 + r.sweep * u, rad = r.rs + (r.re - r.rs) * u;
      at[r.p] = r.c[r.p] + rad * Math.cos(ang), at[r.q] = r.c[r.q] + rad * Math.sin(ang);
      return at;
    };

    // the segments and move ends near a click's line of sight (backplot-snap.js), indexed at the first click
    let index = null, looked = 0;
    const nearClick = (x, y, onSegment, onEnd) => {
      if (!index) index = global.NcurveBackplotSnap.build(moves, G);
      const from = new THREE.Vector3(x / canvas.clientWidth * 2 - 1, 1 - y / canvas.clientHeight * 2, -1).unproject(camera);
      const dir = new THREE.Vector3();
      camera.getWorldDirection(dir);
      const wpp = (camera.top - camera.bottom) / camera.zoom / Math.max(canvas.clientHeight, 1);
      looked = 0;
      index.near(from.toArray(), dir.toArray(), SNAP * wpp * 1.01, (id) => { looked++; onSegment(id); }, (i) => { looked++; onEnd(i); });
    };

    // what a click at canvas x, y lands on, or null
    const locate = (x, y) => {
      const proj = screenOf(), s = [0, 0], w = [0, 0, 0];
      // a move's end within SNAP px: the nearest; of ends on one spot (within 1 px), a cut's before a
      // rapid's, then the one nearest the viewer
      let best = -1, bestD = Infinity, bestCut = false, bestDepth = Infinity;
      const view = new THREE.Vector3();
      camera.getWorldDirection(view);
      const E = moves.end, [P0, P1, P2] = perm, O0 = origin[P0], O1 = origin[P1], O2 = origin[P2];
      const endCandidates = [], segCandidates = [];
      nearClick(x, y, (id) => segCandidates.push(id), (i) => endCandidates.push(i));
      endCandidates.sort((p, q) => p - q);  // in the path's order, as a look at every one takes them
      for (const i of endCandidates) {
        const o = 3 * i;
        w[0] = E[o + P0] - O0, w[1] = E[o + P1] - O1, w[2] = E[o + P2] - O2;
        proj(w[0], w[1], w[2], s);
        const d = Math.hypot(s[0] - x, s[1] - y);
        if (d > SNAP || d > bestD + 1) continue;
        const cut = moves.kind[i] !== 0, depth = view.x * w[0] + view.y * w[1] + view.z * w[2];
        if (best < 0 || d < bestD - 1 || (cut && !bestCut) || (cut === bestCut && depth < bestDepth - 1e-9))
          best = i, bestD = d, bestCut = cut, bestDepth = depth;
      }
      if (best >= 0) return {at: Array.from(moves.end.subarray(3 * best, 3 * best + 3)), snap: 'end', move: best, arc: arcOf(best)};
      // else the nearest point of a drawn segment within SNAP px
      const sm = segMoves(), a = [0, 0], b = [0, 0];
      let hit = null, hitD = SNAP * SNAP;
      segCandidates.sort((p, q) => p - q);  // in the path's order, as a look at every one takes them
      for (const id of segCandidates) {
        const [k, seg] = index.layerOf(id), P = G.layers[k].pos, v = 6 * seg;
        proj(P[v], P[v + 1], P[v + 2], a);
        proj(P[v + 3], P[v + 4], P[v + 5], b);
        const dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
        const t = l2 > 0 ? Math.max(0, Math.min(1, ((x - a[0]) * dx + (y - a[1]) * dy) / l2)) : 0;
        const d = (a[0] + t * dx - x) ** 2 + (a[1] + t * dy - y) ** 2;
        if (d < hitD) hitD = d, hit = {k, seg, v, t};
      }
      if (hit) {
        const i = sm[hit.k][hit.seg], arc = arcOf(i), P = G.layers[hit.k].pos, v = hit.v, t = hit.t;
        const at = arc ? onArc(arc, (hit.seg - G.first[i] + t) / G.segOf[i])
          : toMachine([0, 1, 2].map((c) => P[v + c] + (P[v + 3 + c] - P[v + c]) * t));
        return {at, snap: 'on', move: i, arc};
      }
      // off the path: in a view along a world axis, the point of its plane (at the first point's
      // depth, else at 0); in any other view, nothing
      const axis = [view.x, view.y, view.z].findIndex((c) => Math.abs(c) > 0.999);
      if (axis < 0) return null;
      const p = new THREE.Vector3(x / canvas.clientWidth * 2 - 1, 1 - y / canvas.clientHeight * 2, 0).unproject(camera).toArray();
      const m = perm[axis];
      const depth = points.length === 1 ? points[0].at[m] : 0;
      p[axis] = depth - origin[m];
      // the point of the plane to within a pixel: rounded (as shown) to the power of ten under a pixel's size
      const at = toMachine(p), px = (camera.right - camera.left) / camera.zoom / canvas.clientWidth;
      for (let a = 0; a < 3; a++) {
        if (a === m) continue;
        const f = shown(a, 1), g = Math.pow(10, Math.floor(Math.log10(px * f)));
        at[a] = Math.round(at[a] * f / g) * g / f;
      }
      return {at, snap: 'plane', move: -1, arc: null, plane: m, depthFrom: points.length === 1 ? 'as point 1' : 'at 0'};
    };

    // the readout, three lines at most: the distance and its components (else what to do), then
    // each point with what it snapped to and, on an arc, the arc's radius and centre
    const row = (cls, text) => {
      const d = document.createElement('div');
      d.className = cls;
      d.textContent = text;
      panel.appendChild(d);
      return d;
    };
    const coords = (at) => letters.map((a) => `${name(a)}${num(shown(a, at[a]))}`).join(' ');
    const show = () => {
      panel.textContent = '';
      const [p, q] = points, d = q ? [0, 1, 2].map((a) => q.at[a] - p.at[a]) : null;
      const head = row('head', 'Measure');
      const what = head.appendChild(document.createElement('span'));
      if (missed) what.className = 'miss', what.textContent = 'no move under the pointer: click on the path';
      else if (d) what.textContent = `distance ${len(Math.hypot(d[0], d[1], d[2]))} ${unitName}   ` +
        letters.map((a) => `Δ${name(a)} ${len(d[a] * (a === 0 ? xShown : 1))}`).join('  ');
      else what.className = 'hint', what.textContent = `click ${p ? 'the second point' : 'a point of the path'} · Esc leaves`;
      const close = document.createElement('button');
      close.type = 'button';
      close.textContent = '×';
      close.title = 'leave Measure (Esc)';
      close.onclick = () => set(false);
      head.appendChild(close);
      points.forEach((p, k) => {
        const how = p.snap === 'end' ? `end of ${where(p.move)}` : p.snap === 'on' ? `on ${where(p.move)}`
          : `off the path, in the view's plane (${name(p.plane)} ${p.depthFrom})`;
        const r = p.arc, arc = r ? ` · arc radius ${len(Math.hypot(p.at[r.p] - r.c[r.p], p.at[r.q] - r.c[r.q]))}, centre ${coords(r.c)}` : '';
        row('point', `${k + 1}: ${coords(p.at)} · ${how}${arc}`);
      });
    };
    let missed = false;
    const draw = () => {
      points.forEach((p, k) => positions.array.set(toWorld(p.at), 3 * k));
      positions.needsUpdate = true;
      pg.setDrawRange(0, points.length);
      pg.computeBoundingSphere();
      dots.visible = on && points.length > 0;
      line.visible = on && points.length === 2;
      requestRender();
    };
    // the readout in the legend's place (the band a view leaves free under the drawing)
    const legend = container.querySelector('.ncurve-legend');
    function set(v) {
      on = !!v;
      points = [];
      missed = false;
      panel.hidden = !on;
      if (legend) legend.style.visibility = on ? 'hidden' : '';
      if (toolButton) toolButton.classList.toggle('active', on);
      if (on) show();
      draw();
    }
    return {
      get on() { return on; },
      set,
      toggle: () => set(!on),
      // a click at client x, y: the next point (a third click starts again)
      click(clientX, clientY) {
        const r = canvas.getBoundingClientRect();
        const p = locate(clientX - r.left, clientY - r.top);
        missed = !p;
        if (p) {
          if (points.length === 2) points = [];
          points.push(p);
        }
        show();
        draw();
      },
      // M toggles, Esc leaves; not while typing in a field
      key(e) {
        if (e.ctrlKey || e.altKey || e.metaKey) return;
        const t = e.target instanceof Element ? e.target : null;
        if (t && t.closest('textarea, select, input, [contenteditable]')) return;
        if (e.key === 'm' || e.key === 'M') set(!on);
        else if (e.key === 'Escape' && on) set(false);
        else return;
        e.preventDefault();
      },
      // the toolbar's button
      button() {
        toolButton = document.createElement('button');
        toolButton.type = 'button';
        toolButton.textContent = 'Measure';
        toolButton.title = 'the distance between two points of the path, an arc\'s radius and centre (M; Esc leaves)';
        toolButton.classList.toggle('active', on);
        toolButton.onclick = () => set(!on);
        return toolButton;
      },
      state() {
        const d = points.length === 2 ? [0, 1, 2].map((a) => points[1].at[a] - points[0].at[a]) : null;
        return {on, points: points.map((p) => ({at: p.at.slice(), snap: p.snap, move: p.move,
          arc: p.arc ? {centre: p.arc.c.slice(), radius: Math.hypot(p.at[p.arc.p] - p.arc.c[p.arc.p], p.at[p.arc.q] - p.arc.c[p.arc.q])} : null})),
        distance: d ? Math.hypot(d[0], d[1], d[2]) : null, delta: d, text: panel.hidden ? '' : panel.innerText,
        looked, segments: index ? G.layers.reduce((t, L) => t + L.count, 0) : null};  // the last click's candidates, of all
      },
      dispose() { panel.remove(); },
    };
  }

  global.NcurveBackplotMeasure = {create};
})(window);
