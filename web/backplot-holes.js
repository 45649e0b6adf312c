// The drilled holes of a backplot (web/backplot.js), each marked with a ring and a cross of a fixed
// size on the screen at its top. A hole is a feed straight down the tool axis (Z on a mill in G17
// and on a lathe, there at X0 only, Y in G18, X in G19) after which the tool leaves that spot upwards or by a rapid,
// as the canned cycles G73..G89 and hand-written drilling do; a plunge followed by a cut across
// (a pocket's entry) is no hole. Holes at one spot (pecks, a spot drill then a drill) count once.
//
//   const holes = NcurveBackplotHoles.create({scene, moves, geometry});
//   holes.list();   // [[X, Y, Z], ...] machine, each hole's top, in the order drilled
(function (global) {
  'use strict';
  const THREE = global.THREE;
  const COLOUR = '#212121';
  const EPS = 1e-4;  // mm: the same spot

  // the holes of moves (as NcurveBackplot.create takes them): [{at: [X, Y, Z] top, bottom}]
  function find(moves) {
    const n = moves.count, K = moves.kind, S = moves.start, E = moves.end;
    const axis = moves.lathe ? 2 : ({17: 2, 18: 1, 19: 0})[moves.plane] ?? 2;
    const across = [0, 1, 2].filter((k) => k !== axis);
    const still = (i) => across.every((k) => Math.abs(E[3 * i + k] - S[3 * i + k]) <= EPS) && K[i] !== 2;
    // on a lathe only the spindle's axis (X0) is drilled: a feed along Z elsewhere is a turning pass
    const onAxis = (i) => !moves.lathe || Math.abs(S[3 * i]) <= EPS;
    const holes = [], seen = new Map();
    for (let i = 0; i < n; i++) {
      if (K[i] !== 1 || !still(i) || !onAxis(i) || !(E[3 * i + axis] < S[3 * i + axis] - EPS)) continue;
      // what the tool does next: up along the axis, or across by a rapid, before cutting across
      let j = i + 1, up = false;
      for (; j < n && still(j); j++) if (E[3 * j + axis] > S[3 * j + axis] + EPS) up = true;
      if (j < n && !up && K[j] !== 0) continue;
      const at = [S[3 * i], S[3 * i + 1], S[3 * i + 2]];
      const key = across.map((k) => Math.round(at[k] / EPS)).join(' ');
      const known = seen.get(key);
      if (known) { known.bottom = Math.min(known.bottom, E[3 * i + axis]); continue; }
      const hole = {at, bottom: E[3 * i + axis]};
      seen.set(key, hole);
      holes.push(hole);
    }
    return holes;
  }

  // a dark ring and cross on a white edge, so that they show over the lines
  const sprite = () => {
    const c = document.createElement('canvas');
    c.width = c.height = 32;
    const g = c.getContext('2d');
    for (const [style, width] of [['#fff', 7], [COLOUR, 3]]) {
      g.strokeStyle = style;
      g.lineWidth = width;
      g.beginPath(); g.arc(16, 16, 10, 0, 2 * Math.PI); g.stroke();
      g.beginPath(); g.moveTo(16, 3); g.lineTo(16, 29); g.moveTo(3, 16); g.lineTo(29, 16); g.stroke();
    }
    return new THREE.CanvasTexture(c);
  };

  function create({scene, moves, geometry}) {
    const holes = find(moves);
    if (holes.length) {
      const pos = new Float32Array(3 * holes.length), w = [0, 0, 0];
      holes.forEach((h, k) => pos.set(geometry.toWorld(h.at, w), 3 * k));
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
      const marks = new THREE.Points(g, new THREE.PointsMaterial({size: 16, sizeAttenuation: false,
        map: sprite(), transparent: true, alphaTest: 0.3, depthTest: false}));
      marks.name = 'holes';
      marks.renderOrder = 9;
      marks.frustumCulled = false;
      scene.add(marks);
    }
    return {list: () => holes.map((h) => h.at.slice())};
  }

  global.NcurveBackplotHoles = {create, find};
})(window);
