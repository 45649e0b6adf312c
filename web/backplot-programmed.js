// The programmed contour under cutter / tool-nose radius compensation, drawn thin and dashed in a
// colour of its own beside the tool centre's path (web/backplot.js): its arcs as arcs, segmented as
// the path's are (backplot-geometry.js).
//
//   const layer = NcurveBackplotProgrammed.create(scene, programmed, geometry, lathe);
//   programmed: {count, kind (1 line, 2 arc), start, end (X Y Z each), arcIndex, arcs (centre X Y Z,
//   sweep in radians, plane per arc)}; geometry: the path's (its origin and axes)
//   layer.dash(worldPerPixel); layer.show(on); layer.points() -> machine X Y Z of each segment's ends
//   NcurveBackplotProgrammed.decode(data): the contour from `run --html`'s data (docs/html.md)
(function (global) {
  'use strict';
  const THREE = global.THREE;
  const COLOUR = [0x6a, 0x1b, 0x9a];

  function create(scene, programmed, path, lathe) {
    if (!programmed || !programmed.count) return null;
    const G = global.NcurveBackplotGeometry.build(Object.assign({}, programmed, {lathe}));
    // the layers are about the contour's own centre: moved onto the path's
    const shift = G.perm.map((a) => G.origin[a] - path.origin[a]);
    const lines = G.layers[1], arcs = G.layers[2], segments = lines.count + arcs.count;
    const pos = new Float32Array(6 * segments), dist = new Float32Array(2 * segments);
    pos.set(lines.pos, 0);
    pos.set(arcs.pos, 6 * lines.count);
    let along = 0;
    for (let s = 0, v = 0; s < segments; s++, v += 6) {
      for (let k = 0; k < 3; k++) pos[v + k] += shift[k], pos[v + 3 + k] += shift[k];
      dist[2 * s] = along;
      along += Math.hypot(pos[v + 3] - pos[v], pos[v + 4] - pos[v + 1], pos[v + 5] - pos[v + 2]);
      dist[2 * s + 1] = along;
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    g.setAttribute('lineDistance', new THREE.BufferAttribute(dist, 1));
    const material = new THREE.LineDashedMaterial({color: new THREE.Color(`rgb(${COLOUR.join(',')})`), dashSize: 1, gapSize: 1,
      depthTest: false, transparent: true});
    const layer = new THREE.LineSegments(g, material);
    layer.name = 'programmed';
    layer.renderOrder = 5;  // over the path and the part: it lies beside the path, often on the part's wall
    layer.frustumCulled = false;
    scene.add(layer);
    return {
      moves: programmed.count, segments,
      dash(wpp) { material.dashSize = 5 * wpp, material.gapSize = 3 * wpp; },
      show(on) { layer.visible = !!on; },
      get visible() { return layer.visible; },
      // the drawn segments' ends in machine X Y Z (X as a radius on a lathe)
      points() {
        const out = new Float64Array(pos.length);
        for (let v = 0; v < pos.length; v += 3)
          for (let k = 0; k < 3; k++) out[v + G.perm[k]] = pos[v + k] + path.origin[G.perm[k]];
        return out;
      },
    };
  }

  // `run --html`'s "programmed" ([motion, start X Y Z, end X Y Z] each) and "programmed_arcs"
  // ([motion, centre X Y Z, sweep, plane] each) as create takes them
  function decode(d) {
    const P = d.programmed || [], A = d.programmed_arcs || [], n = P.length;
    const c = {count: n, kind: new Uint8Array(n), start: new Float64Array(3 * n), end: new Float64Array(3 * n),
      arcIndex: new Int32Array(n), arcs: new Float32Array(5 * A.length)};
    for (let e = 0, a = 0; e < n; e++) {
      const p = P[e];
      c.start.set(p.slice(1, 4), 3 * e);
      c.end.set(p.slice(4, 7), 3 * e);
      c.kind[e] = 1;
      c.arcIndex[e] = -1;
      while (a < A.length && A[a][0] < p[0]) a++;
      if (a < A.length && A[a][0] === p[0]) {
        c.arcs.set(A[a].slice(1, 6), 5 * a);
        c.kind[e] = 2;
        c.arcIndex[e] = a;
      }
    }
    return c;
  }

  global.NcurveBackplotProgrammed = {create, decode, COLOUR};
})(window);
