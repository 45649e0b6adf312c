// The axes of the 3D backplot (web/backplot.js): a light grid on the floor (mill: the XY plane
// under the path; lathe: the ZX plane), three axes along the box's edges with round ticks, and the
// HTML labels over the canvas: tick numbers and axis names, thinned and kept clear of the page's
// boxes as the view turns, and the markers (the start, the alarm, the tool). Needs three.js.
//
//   const axes = NcurveBackplotAxes.create({scene, overlay, container, moves, geometry, alarmLabel});
//   axes.lo, axes.hi, axes.pad;      // the cuts' box in world units; the axes lie pad outside it
//   axes.place(project, W, H);       // each frame: labels and tick marks for the camera (project:
//                                    // world Vector3 -> [x, y] on a W x H canvas)
//   axes.marker('tool');             // a marker {world, hidden} to move, placed with the labels
//   axes.shown();                    // what place showed: tick marks, numbers, names
(function (global) {
  'use strict';
  const THREE = global.THREE;
  const MARK_GAP = 8;  // the least distance between tick marks on the screen, px

  // 1, 2 or 5 times a power of ten, near span / count
  function niceStep(span, count) {
    const raw = Math.max(span, 1e-9) / count;
    const p = Math.pow(10, Math.floor(Math.log10(raw)));
    const m = raw / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
  }

  function formatNumber(v, step) {
    const digits = Math.max(0, Math.min(6, -Math.floor(Math.log10(step) + 1e-9)));
    const s = v.toFixed(digits);
    return s === '-0' || /^-0\.0*$/.test(s) ? s.slice(1) : s;
  }

  // scene: where the grid and axes go; overlay: the element over the canvas for the labels;
  // container: the plot's element (its boxes the names keep clear of); geometry: the moves' build
  function create({scene, overlay, container, moves, geometry, alarmLabel}) {
    // the axes frame the cuts (geometry.frameLo/Hi): rapids to and from home reach beyond them
    const {origin, perm, toWorld, frameLo: lo, frameHi: hi} = geometry;
    const diag = Math.max(Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]), 1e-3);
    const n = moves.count;
    const wlo = [0, 0, 0], whi = [0, 0, 0];
    toWorld(lo, wlo), toWorld(hi, whi);
    const span = [whi[0] - wlo[0], whi[1] - wlo[1], whi[2] - wlo[2]];
    const unit = moves.inch ? 25.4 : 1, unitName = moves.inch ? 'in' : 'mm';
    // the value shown along world axis k per world unit, and the axis name
    const scale = [0, 1, 2].map((k) => (moves.lathe && perm[k] === 0 && moves.diameter ? 2 : 1) / unit);
    const axisName = [0, 1, 2].map((k) => {
      const letter = 'XYZ'[perm[k]];
      const what = moves.lathe && letter === 'X' ? (moves.diameter ? ' (diameter)' : ' (radius)') : '';
      return `${letter}${what}, ${unitName}`;
    });
    const guide = new THREE.Group();
    scene.add(guide);
    const gridPts = [], axisPts = [], ticks = [];
    const floorK = 2;  // the grid lies across world x and y at the lowest world z
    const tickLen = diag * 0.012;
    for (let k = 0; k < 3; k++) {
      const shown = span[k] * scale[k];
      const flat = span[k] <= diag * 1e-6;  // the path does not move along this axis: one tick, at its value
      const step = niceStep(flat ? diag * scale[k] : shown, 6);
      const v0 = (wlo[k] + origin[perm[k]]) * scale[k], v1 = (whi[k] + origin[perm[k]]) * scale[k];
      const firstTick = Math.ceil((v0 - 1e-9 * step) / step) * step;
      const list = [];
      for (let v = firstTick, c = 0; v <= v1 + 1e-9 * step && c < 200; v += step, c++) list.push(v);
      if (flat) list.splice(0, list.length, Math.round(v0 / step) * step);
      ticks.push({step, list, toWorld: (v) => v / scale[k] - origin[perm[k]]});
    }
    // the axes' corner: the lowest corner of the box
    const corner = [wlo[0], wlo[1], wlo[2]];
    const pad = diag * 0.04;
    const axisEnds = [];  // per world axis: its two ends (or null where the path has no extent)
    for (let k = 0; k < 3; k++) {
      if (span[k] <= diag * 1e-6 && k === floorK) continue;
      const a = corner.slice(), b = corner.slice();
      a[k] = wlo[k], b[k] = whi[k];
      for (const j of [0, 1, 2]) if (j !== k) a[j] -= pad, b[j] -= pad;
      if (span[k] > diag * 1e-6) axisPts.push(...a, ...b);
      axisEnds[k] = [a, b];
    }
    // the tick marks of axis k, those of the ticks shown(i) says (place thins them on the screen)
    const tickMarks = (k, shown) => {
      const pts = [], a = axisEnds[k][0];
      ticks[k].list.forEach((v, i) => {
        if (!shown(i)) return;
        const p = a.slice();
        p[k] = ticks[k].toWorld(v);
        for (const j of [0, 1, 2]) {  // a tick across each of the two other axes
          if (j === k) continue;
          const q = p.slice();
          q[j] -= tickLen;
          pts.push(...p, ...q);
        }
      });
      return new THREE.BufferAttribute(new Float32Array(pts), 3);
    };
    // grid lines at the ticks of world x and y, on the floor
    const fz = wlo[floorK] - pad;
    for (const v of ticks[0].list) {
      const x = ticks[0].toWorld(v);
      gridPts.push(x, wlo[1] - pad, fz, x, whi[1] + pad, fz);
    }
    for (const v of ticks[1].list) {
      const y = ticks[1].toWorld(v);
      gridPts.push(wlo[0] - pad, y, fz, whi[0] + pad, y, fz);
    }
    const lineSet = (pts, color, opacity) => {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(pts), 3));
      return new THREE.LineSegments(g, new THREE.LineBasicMaterial({color, transparent: opacity < 1, opacity}));
    };
    guide.add(lineSet(gridPts, 0x90a4ae, 0.35));
    guide.add(lineSet(axisPts, 0x37474f, 1));
    // per axis: its tick marks' lines and which ticks they hold (a key, so that they are rebuilt
    // only when that changes)
    const markLines = axisEnds.map((ends) => {
      if (!ends) return null;
      const line = lineSet([], 0x37474f, 1);
      guide.add(line);
      return {line, key: ''};
    });

    // labels: tick numbers and axis names beside their axis (on the side away from the path),
    // the start point and the alarm; placed on the screen every frame
    const labels = [];
    const addLabel = (cls, text, world, axis) => {
      const el = document.createElement('div');
      el.className = 'ncurve-label ' + cls;
      el.textContent = text;
      overlay.appendChild(el);
      const label = {el, world: new THREE.Vector3(world[0], world[1], world[2]), axis};
      labels.push(label);
      return label;
    };
    for (let k = 0; k < 3; k++) {
      if (!axisEnds[k]) continue;
      const a = axisEnds[k][0];
      ticks[k].list.forEach((v) => {
        const p = a.slice();
        p[k] = ticks[k].toWorld(v);
        addLabel('tick tick-' + 'xyz'[k], formatNumber(v, ticks[k].step), p, k);
      });
      const e = axisEnds[k][1].slice();
      if (span[k] <= diag * 1e-6) e[k] += diag * 0.05;
      addLabel('axis-name axis-' + 'xyz'[k], axisName[k], e, k);
    }
    if (n > 0) addLabel('marker start', '', toWorld(moves.start.subarray(0, 3), [0, 0, 0]), -1);
    if (moves.alarmAt) addLabel('marker alarm', alarmLabel || 'alarm', toWorld(moves.alarmAt, [0, 0, 0]), -1).alarm = true;

    // a label of w x h centred at x, y moved onto the canvas and off the boxes over it (the views'
    // buttons, the legend, any element of the container marked data-keep-clear): down from a box
    // in the upper half, up from one in the lower
    let shown = null;  // what place showed last
    const keepClear = (x, y, w, h, W, H) => {
      const c = container.getBoundingClientRect();
      x = Math.min(Math.max(x, w / 2 + 4), W - w / 2 - 4);
      y = Math.min(Math.max(y, h / 2 + 4), H - h / 2 - 4);
      for (const box of container.querySelectorAll('.ncurve-views, .ncurve-legend, [data-keep-clear]')) {
        if (box.hidden || !box.offsetWidth) continue;
        const r = box.getBoundingClientRect(), l = r.left - c.left, t = r.top - c.top;
        if (x + w / 2 <= l || x - w / 2 >= l + r.width || y + h / 2 <= t || y - h / 2 >= t + r.height) continue;
        if (t + r.height / 2 < H / 2) y = Math.max(y, t + r.height + h / 2 + 3);
        else y = Math.min(y, t - h / 2 - 3);
      }
      return [x, y];
    };
    const place = (project, W, H) => {
      const centre = project(new THREE.Vector3((wlo[0] + whi[0]) / 2, (wlo[1] + whi[1]) / 2, (wlo[2] + whi[2]) / 2));
      // per axis: its direction on the screen, the side away from the path, how many ticks to skip
      const screen = axisEnds.map((ends, k) => {
        if (!ends) return null;
        const a = project(new THREE.Vector3(...ends[0])), b = project(new THREE.Vector3(...ends[1]));
        const len = Math.hypot(b[0] - a[0], b[1] - a[1]);
        const d = len > 1e-6 ? [(b[0] - a[0]) / len, (b[1] - a[1]) / len] : [1, 0];
        let nrm = [-d[1], d[0]];
        const mid = [(a[0] + b[0]) / 2 - centre[0], (a[1] + b[1]) / 2 - centre[1]];
        if (nrm[0] * mid[0] + nrm[1] * mid[1] < 0) nrm = [-nrm[0], -nrm[1]];
        const count = ticks[k].list.length;
        const gap = count > 1 ? len * ticks[k].step / (span[k] * scale[k]) : Infinity;  // one step on the screen
        // numbers at least 48 px apart, on round values (1, 2, 2.5, 5 x 10^n: a 2.5 step numbered at
        // 10s, not at its 5th ticks, 12.5s); marks at least MARK_GAP px
        const need = 48 / Math.max(gap, 1e-9), step = ticks[k].step;
        let every = 1;
        if (need > 1) {
          every = 10 * Math.ceil(need / 10);
          const base = Math.pow(10, Math.floor(Math.log10(need * step)));
          for (const f of [1, 2, 2.5, 5, 10, 20, 25, 50]) {
            const v = f * base / step, r = Math.round(v);
            if (r >= need && Math.abs(v - r) < 1e-6) { every = r; break; }
          }
        }
        const endOn = len < 30 && span[k] > diag * 1e-6;
        let markEvery = 1;
        for (let f = 1; markEvery * gap < MARK_GAP && markEvery < 1e6; f *= 10)
          for (const m of [1, 2, 5]) if (markEvery * gap < MARK_GAP) markEvery = m * f;
        // fewer than two round values on the axis: its first and last ticks numbered instead (with
        // any round value between them as far from both as two numbers need)
        const ms = ticks[k].list.map((v) => Math.round(v / step));
        const round = (m) => m % every === 0;
        const byEnds = count >= 2 && ms.filter(round).length < 2 && (ms[count - 1] - ms[0]) >= need;
        const numbered = (i) => (byEnds ? i === 0 || i === count - 1 ||
          (round(ms[i]) && ms[i] - ms[0] >= need && ms[count - 1] - ms[i] >= need) : round(ms[i]));
        const mark = (i) => !endOn && (ms[i] % markEvery === 0 || numbered(i));
        const key = endOn ? 'none' : `${markEvery} ${every} ${byEnds}`;
        if (markLines[k].key !== key) {
          markLines[k].key = key;
          markLines[k].line.geometry.setAttribute('position', tickMarks(k, mark));
        }
        return {d, nrm, len, every, endOn, mark, numbered};
      });
      const tickIndex = [0, 0, 0];
      shown = {marks: [[], [], []], numbers: [[], [], []], names: []};
      screen.forEach((s, k) => {
        if (!s) return;
        ticks[k].list.forEach((v, i) => {
          if (!s.mark(i)) return;
          const p = axisEnds[k][0].slice();
          p[k] = ticks[k].toWorld(v);
          shown.marks[k].push(project(new THREE.Vector3(...p)));
        });
      });
      for (const L of labels) {
        let [x, y] = project(L.world);
        let hide = false;
        if (L.axis >= 0) {
          const s = screen[L.axis];
          const name = L.el.classList.contains('axis-name');
          if (s.endOn && (!name || s.len < 8)) hide = true;  // a name stays unless its axis is seen end-on
          if (!name) {
            const i = tickIndex[L.axis]++;
            if (!s.numbered(i)) hide = true;
            x += s.nrm[0] * 16, y += s.nrm[1] * 16;
          } else if (!hide) {  // beyond the axis' end, clear of its last tick, kept on the canvas
            L.el.style.display = '';  // measured as shown
            const w = L.el.offsetWidth, h = L.el.offsetHeight;
            const along = Math.abs(s.d[0]) * w / 2 + Math.abs(s.d[1]) * h / 2 + 10;
            x += s.d[0] * along, y += s.d[1] * along;
            [x, y] = keepClear(x, y, w, h, W, H);
            shown.names.push({text: L.el.textContent, x, y, w, h});
          }
        }

        const inside = x >= -40 && x <= W + 40 && y >= -20 && y <= H + 20;
        L.el.style.display = inside && !hide && !L.hidden ? '' : 'none';
        if (L.axis >= 0 && inside && !hide && !L.el.classList.contains('axis-name')) shown.numbers[L.axis].push([x, y]);
        // a label centred on its point, but the alarm's ✕ (its left 12 px) on the point and its text after it
        const shift = L.alarm ? 'translate(-6px, -50%)' : 'translate(-50%, -50%)';
        L.el.style.transform = `translate(${x.toFixed(1)}px, ${y.toFixed(1)}px) ${shift}`;
      }
    };

    return {
      lo: wlo, hi: whi, pad, place,
      // a marker of class `marker cls` at the origin, hidden until given a place (its world and hidden)
      marker: (cls) => Object.assign(addLabel('marker ' + cls, '', [0, 0, 0], -1), {hidden: true}),
      // on the canvas: each axis's tick marks and numbers shown, and the axis names (centre, size)
      shown: () => shown,
    };
  }

  global.NcurveBackplotAxes = {create, niceStep, formatNumber};
})(window);
