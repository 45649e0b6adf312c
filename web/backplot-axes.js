// The axes of the 3D backplot (web/backplot.js): a light grid on the floor (mill: the XY plane
// under the path; lathe: the ZX plane), three axes along the box's edges with round ticks, and the
// HTML labels over the canvas: tick numbers at a step that follows the zoom, kept on the canvas and
// clear of the page's boxes as the view turns, axis names, and the markers (the start, the alarm,
// the tool). Needs three.js.
//
//   const axes = NcurveBackplotAxes.create({scene, overlay, container, moves, geometry, alarmLabel});
//   axes.lo, axes.hi, axes.pad;      // the cuts' box in world units; the axes lie pad outside it
//   axes.place(project, W, H, along); // each frame: labels and tick marks for the camera (project:
//                                    // world Vector3 -> [x, y] on a W x H canvas; along: the
//                                    // camera looks along a world axis)
//   axes.marker('tool');             // a marker {world, hidden} to move, placed with the labels
//   axes.shown();                    // what place showed: tick marks, numbers (their values, the
//                                    // step per axis), the axes' lines' ends, names
(function (global) {
  'use strict';
  const THREE = global.THREE;

  // 1, 2 or 5 times a power of ten, near span / count
  function niceStep(span, count) {
    const raw = Math.max(span, 1e-9) / count;
    const p = Math.pow(10, Math.floor(Math.log10(raw)));
    const m = raw / p;
    return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * p;
  }

  // the least of 1, 2 and 5 times a power of ten that is at least x
  function stepAtLeast(x) {
    const p = Math.pow(10, Math.floor(Math.log10(Math.max(x, 1e-12))));
    return [1, 2, 5, 10].find((m) => m * p >= x * (1 - 1e-9)) * p;
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
    const floorK = 2;  // the grid lies across world x and y at the lowest world z
    const tickLen = diag * 0.012;
    // per world axis: the values shown at its ends, whether the path has no extent along it
    const range = [0, 1, 2].map((k) => ({v0: (wlo[k] + origin[perm[k]]) * scale[k], v1: (whi[k] + origin[perm[k]]) * scale[k],
      flat: span[k] <= diag * 1e-6}));
    const toWorldValue = (k, v) => v / scale[k] - origin[perm[k]];
    // the axes' corner: the lowest corner of the box
    const corner = [wlo[0], wlo[1], wlo[2]];
    const pad = diag * 0.04;
    const axisEnds = [];  // per world axis: its two ends (or null where the path has no extent)
    for (let k = 0; k < 3; k++) {
      if (range[k].flat && k === floorK) continue;
      const a = corner.slice(), b = corner.slice();
      a[k] = wlo[k], b[k] = whi[k];
      for (const j of [0, 1, 2]) if (j !== k) a[j] -= pad, b[j] -= pad;
      axisEnds[k] = [a, b];
    }
    const lineSet = (pts, color, opacity) => {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(pts), 3));
      return new THREE.LineSegments(g, new THREE.LineBasicMaterial({color, transparent: opacity < 1, opacity}));
    };
    const grid = lineSet([], 0x90a4ae, 0.35);
    grid.userData.key = '';
    guide.add(grid);
    // per axis: its line and tick marks, and what they hold (a key: rebuilt only when that changes)
    const markLines = axisEnds.map((ends) => {
      if (!ends) return null;
      const line = lineSet([], 0x37474f, 1);
      guide.add(line);
      return {line, key: ''};
    });
    // the values from lo to hi (shown units) at multiples of step, at most 1000
    const multiples = (lo, hi, step) => {
      const out = [];
      for (let m = Math.ceil(lo / step - 1e-9), last = Math.floor(hi / step + 1e-9); m <= last && out.length < 1000; m++) out.push(m * step);
      return out;
    };
    // axis k's line from value lo to hi (none for a flat axis), with marks at the values given
    const tickMarks = (k, values, lo, hi) => {
      const pts = [], a = axisEnds[k][0];
      if (!range[k].flat) {
        const p = a.slice(), q = a.slice();
        p[k] = toWorldValue(k, lo), q[k] = toWorldValue(k, hi);
        pts.push(...p, ...q);
      }
      for (const v of values) {
        const p = a.slice();
        p[k] = toWorldValue(k, v);
        for (const j of [0, 1, 2]) {  // a tick across each of the two other axes
          if (j === k) continue;
          const q = p.slice();
          q[j] -= tickLen;
          pts.push(...p, ...q);
        }
      }
      return new THREE.BufferAttribute(new Float32Array(pts), 3);
    };
    // the grid on the floor at the steps of world x and y, over the values given (shown units)
    const fz = wlo[floorK] - pad;
    const setGrid = (xs, ys) => {
      const key = `${xs[0]} ${xs[xs.length - 1]} ${xs.length} ${ys[0]} ${ys[ys.length - 1]} ${ys.length}`;
      if (grid.userData.key === key) return;
      grid.userData.key = key;
      const pts = [];
      for (const v of xs) { const x = toWorldValue(0, v); pts.push(x, wlo[1] - pad, fz, x, whi[1] + pad, fz); }
      for (const v of ys) { const y = toWorldValue(1, v); pts.push(wlo[0] - pad, y, fz, whi[0] + pad, y, fz); }
      grid.geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(pts), 3));
    };

    // labels: tick numbers (made as needed, a pool per axis) and axis names beside their axis (on the
    // side away from the path), the start point and the alarm; placed on the screen every frame
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
    const numberPool = [[], [], []];
    const numberLabel = (k, i) => {
      const pool = numberPool[k];
      while (pool.length <= i) {
        const el = document.createElement('div');
        el.className = 'ncurve-label tick tick-' + 'xyz'[k];
        overlay.appendChild(el);
        pool.push(el);
      }
      return pool[i];
    };
    const names = [];
    for (let k = 0; k < 3; k++) if (axisEnds[k]) names[k] = addLabel('axis-name axis-' + 'xyz'[k], axisName[k], axisEnds[k][1], k);
    if (n > 0) addLabel('marker start', '', toWorld(moves.start.subarray(0, 3), [0, 0, 0]), -1);
    if (moves.alarmAt) addLabel('marker alarm', alarmLabel || 'alarm', toWorld(moves.alarmAt, [0, 0, 0]), -1).alarm = true;

    // the boxes over the canvas (the views' buttons, the legend, any element of the container
    // marked data-keep-clear), in canvas px
    const boxes = () => {
      const c = container.getBoundingClientRect(), out = [];
      for (const box of container.querySelectorAll('.ncurve-views, .ncurve-legend, [data-keep-clear]')) {
        if (box.hidden || !box.offsetWidth) continue;
        const r = box.getBoundingClientRect();
        out.push({l: r.left - c.left, t: r.top - c.top, r: r.right - c.left, b: r.bottom - c.top});
      }
      return out;
    };
    // a label of w x h centred at x, y moved onto the canvas and off the boxes: down from a box in
    // the upper half, up from one in the lower
    const keepClear = (x, y, w, h, W, H, over) => {
      x = Math.min(Math.max(x, w / 2 + 4), W - w / 2 - 4);
      y = Math.min(Math.max(y, h / 2 + 4), H - h / 2 - 4);
      for (const r of over) {
        if (x + w / 2 <= r.l || x - w / 2 >= r.r || y + h / 2 <= r.t || y - h / 2 >= r.b) continue;
        if ((r.t + r.b) / 2 < H / 2) y = Math.max(y, r.b + h / 2 + 3);
        else y = Math.min(y, r.t - h / 2 - 3);
      }
      return [x, y];
    };
    const covered = (x, y, w, h, over) => over.some((r) => x + w / 2 > r.l && x - w / 2 < r.r && y + h / 2 > r.t && y - h / 2 < r.b);
    const NUMBER_H = 14, charW = 6.6;  // a number's height and the width of a character, px (11 px tabular figures)
    // a number's width as the page's font draws it (measured once a text), the estimate before the
    // fonts are known
    let measurer = null;
    const widths = new Map();
    const textWidth = (text) => {
      let w = widths.get(text);
      if (w !== undefined) return w;
      if (!measurer) {
        const cs = global.getComputedStyle(numberLabel(0, 0));
        if (!cs.fontSize) return text.length * charW;
        measurer = document.createElement('canvas').getContext('2d');
        measurer.font = `${cs.fontStyle} ${cs.fontWeight} ${cs.fontSize} ${cs.fontFamily}`;
      }
      w = Math.ceil(measurer.measureText(text).width);
      widths.set(text, w);
      return w;
    };

    // each frame (along: the camera looks along a world axis): per axis, its line across the canvas
    // (in a view along an axis, beyond the box where that is smaller than the canvas),
    // numbered at a 1, 2 or 5 x 10^n step that leaves the numbers at least 48 px apart (about 5 to 10
    // of them across the canvas); an axis whose line is off the canvas (zoomed in) has its numbers
    // along the canvas' edge
    let shown = null;  // what place showed last
    const place = (project, W, H, along) => {
      const over = boxes();
      const centre = project(new THREE.Vector3((wlo[0] + whi[0]) / 2, (wlo[1] + whi[1]) / 2, (wlo[2] + whi[2]) / 2));
      shown = {marks: [[], [], []], numbers: [[], [], []], values: [[], [], []], steps: [0, 0, 0], lines: [null, null, null], names: []};
      const gridValues = [null, null], pending = [];
      // how much of a world unit along each axis the screen shows: an orthographic view keeps
      // sqrt(sum of squares / 2) of the three, its scale; an axis seen end-on keeps almost none
      const unitPx = [0, 1, 2].map((k) => {
        const q = project(new THREE.Vector3(k === 0 ? 1 : 0, k === 1 ? 1 : 0, k === 2 ? 1 : 0)), o = project(new THREE.Vector3(0, 0, 0));
        return Math.hypot(q[0] - o[0], q[1] - o[1]);
      });
      const viewScale = Math.sqrt(unitPx.reduce((s, p) => s + p * p, 0) / 2) || 1;
      for (let k = 0; k < 3; k++) {
        if (!axisEnds[k]) continue;
        const R = range[k];
        const A = project(new THREE.Vector3(...axisEnds[k][0])), B = project(new THREE.Vector3(...axisEnds[k][1]));
        const len = Math.hypot(B[0] - A[0], B[1] - A[1]);
        const d = len > 1e-6 ? [(B[0] - A[0]) / len, (B[1] - A[1]) / len] : [1, 0];
        let nrm = [-d[1], d[0]];
        const mid = [(A[0] + B[0]) / 2 - centre[0], (A[1] + B[1]) / 2 - centre[1]];
        if (nrm[0] * mid[0] + nrm[1] * mid[1] < 0) nrm = [-nrm[0], -nrm[1]];
        // under 30 px: no numbers, no marks; but in a view along an axis only the one seen end-on (short
        // for its length), not one in the view's plane that is short (a thin part, zoomed out): that
        // one is a ruler across the canvas
        const endOn = len < 30 && !R.flat && (!along || unitPx[k] < 0.5 * viewScale);
        let values = [], marks = [], step = 0, s = 0, visLo = -Infinity, visHi = Infinity;
        const ppv = R.flat ? 0 : len / (R.v1 - R.v0);  // px per unit shown
        const at = (v, off) => [A[0] + (v - R.v0) * ppv * d[0] + off * nrm[0], A[1] + (v - R.v0) * ppv * d[1] + off * nrm[1]];
        if (R.flat) {
          step = niceStep(diag * scale[k], 6);
          values = [Math.round(R.v0 / step) * step];
          marks = values;
        } else if (!endOn) {
          // the numbers' line: 16 px off the axis, moved in to the canvas' edge (less the boxes along
          // it) where the axis is off the canvas
          const flatish = Math.abs(d[0]) >= Math.abs(d[1]);
          let top = NUMBER_H / 2 + 4, bottom = H - NUMBER_H / 2 - 4;
          if (flatish) for (const r of over) {
            if ((r.t + r.b) / 2 < H / 2) top = Math.max(top, r.b + NUMBER_H / 2 + 3);
            else bottom = Math.min(bottom, r.t - NUMBER_H / 2 - 3);
          }
          const left = 24, right = W - 24, corners = [[left, top], [right, top], [left, bottom], [right, bottom]];
          const off = (p) => (p[0] - A[0]) * nrm[0] + (p[1] - A[1]) * nrm[1];
          const cs = corners.map(off), cmin = Math.min(...cs), cmax = Math.max(...cs);
          const inset = (cmax - cmin) * 0.3 * Math.min(Math.abs(d[0]), Math.abs(d[1])) / Math.SQRT1_2;
          s = Math.min(Math.max(16, cmin + inset), Math.max(cmax - inset, cmin + inset));
          // the values whose place on that line is inside [left, right] x [top, bottom]
          const P0 = at(R.v0, s);
          for (const [c, lo, hi] of [[0, left, right], [1, top, bottom]]) {
            const rate = ppv * d[c];
            if (Math.abs(rate) < 1e-12) { if (P0[c] < lo || P0[c] > hi) visLo = Infinity; continue; }
            const u0 = R.v0 + (lo - P0[c]) / rate, u1 = R.v0 + (hi - P0[c]) / rate;
            visLo = Math.max(visLo, Math.min(u0, u1)), visHi = Math.min(visHi, Math.max(u0, u1));
          }
          // a view at a slant numbers the box only; one along an axis, the whole line across the canvas
          if (!along) visLo = Math.max(visLo, R.v0), visHi = Math.min(visHi, R.v1);
          if (visLo <= visHi) {
            // the step: the numbers 48 px apart at least, and as far apart as their text needs
            const room = (st) => {
              const chars = Math.max(...[visLo, visHi].map((v) => formatNumber(Math.round(v / st) * st, st).length));
              return Math.max(48, Math.abs(d[0]) * chars * charW + Math.abs(d[1]) * NUMBER_H + 12);
            };
            step = stepAtLeast(48 / ppv);
            for (let g = 0; g < 8 && step * ppv < room(step); g++) step = stepAtLeast(step * 1.5);
            values = multiples(visLo, visHi, step);
            // fewer than two: the two multiples of a finer step nearest the ends, if far enough apart
            if (values.length < 2) {
              for (let st = stepAtLeast(step / 2.5), g = 0; g < 4; st = stepAtLeast(st / 2.5), g++) {
                const m = multiples(visLo, visHi, st);
                if (m.length >= 2 && (m[m.length - 1] - m[0]) * ppv >= room(st)) {
                  values = [m[0], ...values.filter((v) => v - m[0] > 0.5 * st && m[m.length - 1] - v > 0.5 * st &&
                    Math.min(v - m[0], m[m.length - 1] - v) * ppv >= room(st)), m[m.length - 1]];
                  step = st;
                  break;
                }
              }
            }
            // marks at a fifth or a half of the step where they are 14 px apart (not a comb)
            const minor = [step / 5, step / 2, step].find((m) => m * ppv >= 14);
            marks = multiples(visLo, visHi, minor);
          }
        }
        // the line over the box and the numbers beyond it
        // (and the marks beyond the last number: none off the line)
        const lineLo = Math.min(R.v0, values.length ? values[0] : R.v0, marks.length ? marks[0] : R.v0);
        const lineHi = Math.max(R.v1, values.length ? values[values.length - 1] : R.v1, marks.length ? marks[marks.length - 1] : R.v1);
        const key = `${marks.length} ${marks[0]} ${marks[marks.length - 1]} ${lineLo} ${lineHi}`;
        if (markLines[k].key !== key) {
          markLines[k].key = key;
          markLines[k].line.geometry.setAttribute('position', tickMarks(k, marks, lineLo, lineHi));
        }
        const onScreen = (v) => {
          const p = axisEnds[k][0].slice();
          p[k] = toWorldValue(k, v);
          return project(new THREE.Vector3(...p));
        };
        for (const v of marks) shown.marks[k].push(onScreen(v));
        if (!R.flat) shown.lines[k] = [onScreen(lineLo), onScreen(lineHi)];
        shown.steps[k] = step;
        if (k < 2) gridValues[k] = !R.flat && !endOn && values.length ? {step, visLo, visHi} : null;
        // the name beyond the end of the axis' part on the canvas
        const L = names[k];
        const visible = R.flat || (!endOn && visLo <= visHi) || (endOn && len >= 8);
        L.el.style.display = visible ? '' : 'none';
        const number = (v) => (R.flat ? [A[0] + 16 * nrm[0], A[1] + 16 * nrm[1]] : at(v, s));
        pending.push({k, values, step, number});
        if (!visible) continue;
        const w = L.el.offsetWidth, h = L.el.offsetHeight;
        const end = R.flat || endOn ? B : at(Math.max(R.v1, Math.min(visHi, lineHi)), s - 16);
        const far = Math.abs(d[0]) * w / 2 + Math.abs(d[1]) * h / 2 + 10;
        const placed = shown.names.map((o) => ({l: o.x - o.w / 2 - 3, r: o.x + o.w / 2 + 3, t: o.y - o.h / 2 - 2, b: o.y + o.h / 2 + 2}));
        const [x, y] = keepClear(end[0] + d[0] * far, end[1] + d[1] * far, w, h, W, H, over.concat(placed));
        shown.names.push({text: L.el.textContent, x, y, w, h});
        L.el.style.transform = `translate(${x.toFixed(1)}px, ${y.toFixed(1)}px) translate(-50%, -50%)`;
      }
      // the numbers, where on the canvas and off the boxes, the names and the numbers placed before
      // (their widths measured): one that would overlap is left out
      const clear = over.concat(shown.names.map((n) => ({l: n.x - n.w / 2 - 3, r: n.x + n.w / 2 + 3, t: n.y - n.h / 2, b: n.y + n.h / 2})));
      for (const {k, values, step, number} of pending) {
        const pool = numberPool[k];
        let used = 0;
        for (const v of values) {
          const [x, y] = number(v);
          const text = formatNumber(v, step), w = textWidth(text) + 2;
          if (x < w / 2 || x > W - w / 2 || y < NUMBER_H / 2 || y > H - NUMBER_H / 2 || covered(x, y, w, NUMBER_H, clear)) continue;
          const el = numberLabel(k, used++);
          if (el.textContent !== text) el.textContent = text;
          el.style.display = '';
          el.style.transform = `translate(${x.toFixed(1)}px, ${y.toFixed(1)}px) translate(-50%, -50%)`;
          shown.numbers[k].push([x, y]);
          shown.values[k].push(v);
          clear.push({l: x - w / 2 - 2, r: x + w / 2 + 2, t: y - NUMBER_H / 2, b: y + NUMBER_H / 2});  // no other axis' number over it
        }
        for (let i = used; i < pool.length; i++) pool[i].style.display = 'none';
      }
      // the grid at the numbers' steps of world x and y, over the part of the box in view (and as
      // much again round it, for the views at a slant), 400 lines at most a way
      const gridOf = (k) => {
        const R = range[k], g = gridValues[k];
        let step = g ? g.step : niceStep((R.v1 - R.v0) || diag * scale[k], 6);
        let lo = R.v0, hi = R.v1;
        if (g) {
          const more = g.visHi - g.visLo;
          lo = Math.max(R.v0, g.visLo - more), hi = Math.min(R.v1, g.visHi + more);
        }
        while ((hi - lo) / step > 400) step *= 10;
        return multiples(lo, hi, step);
      };
      setGrid(gridOf(0), gridOf(1));
      // the markers: the start, the alarm, the tool
      for (const L of labels) {
        if (L.axis >= 0) continue;
        const [x, y] = project(L.world);
        const inside = x >= -40 && x <= W + 40 && y >= -20 && y <= H + 20;
        L.el.style.display = inside && !L.hidden ? '' : 'none';
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

  global.NcurveBackplotAxes = {create, niceStep, stepAtLeast, formatNumber};
})(window);
