// The tool at a point of the path (web/backplot.js; the debugger's step): on a mill a cylinder of
// the cutter radius standing on the plane of cut (its bottom circle at the tool centre, which the
// moves' ends are under compensation), on a lathe the nose circle about the nose centre in the ZX
// plane. Drawn over everything, in world units: the circle is the radius as the control has it.
//
//   const cutter = NcurveBackplotCutter.create(scene, toWorld);
//   cutter.set({centre: [x, y, z], radius, plane: 17, height}); cutter.set(null);
//   cutter.points() -> the bottom circle's points, machine X Y Z
(function (global) {
  'use strict';
  const THREE = global.THREE;
  const COLOUR = 0x00838f;
  const STEPS = 96;
  const PLANES = {17: [0, 1, 2], 18: [2, 0, 1], 19: [1, 2, 0]};  // in-plane axes p, q and the normal

  function create(scene, toWorld) {
    const group = new THREE.Group();
    group.name = 'cutter';
    group.renderOrder = 12;
    scene.add(group);
    let circle = null, shown = null;
    const clear = () => {
      for (const o of [...group.children]) { group.remove(o); o.geometry.dispose(); o.material.dispose(); }
      circle = null;
    };
    // machine points -> a line of the group (segments: pairs, else a closed loop)
    const add = (points, segments) => {
      const pos = new Float32Array(points.length), w = [0, 0, 0];
      for (let v = 0; v < points.length; v += 3) {
        toWorld([points[v], points[v + 1], points[v + 2]], w);
        pos[v] = w[0], pos[v + 1] = w[1], pos[v + 2] = w[2];
      }
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
      const m = new THREE.LineBasicMaterial({color: COLOUR, depthTest: false, transparent: true});
      const line = segments ? new THREE.LineSegments(g, m) : new THREE.LineLoop(g, m);
      line.renderOrder = 12;
      line.frustumCulled = false;
      group.add(line);
    };
    // a circle of radius r about c in the plane (normal lifted by h)
    const ring = (c, r, plane, h) => {
      const [p, q, n] = PLANES[plane] || PLANES[17], out = new Float64Array(3 * STEPS);
      for (let s = 0; s < STEPS; s++) {
        const a = 2 * Math.PI * s / STEPS;
        out[3 * s + p] = c[p] + r * Math.cos(a), out[3 * s + q] = c[q] + r * Math.sin(a), out[3 * s + n] = c[n] + h;
      }
      return out;
    };
    return {
      set(spec) {
        clear();
        shown = spec && spec.radius > 0 ? spec : null;
        if (!shown) return;
        const {centre: c, radius: r, plane} = shown, h = shown.height || 0;
        circle = ring(c, r, plane, 0);
        add(circle);
        if (!h) return;
        // the cylinder's top and four of its sides
        add(ring(c, r, plane, h));
        const [p, q, n] = PLANES[plane] || PLANES[17], sides = [];
        for (const [u, v] of [[1, 0], [0, 1], [-1, 0], [0, -1]]) {
          const a = [c[0], c[1], c[2]];
          a[p] += r * u, a[q] += r * v;
          const b = a.slice();
          b[n] += h;
          sides.push(...a, ...b);
        }
        add(Float64Array.from(sides), true);
      },
      points: () => (circle ? Array.from(circle) : []),
      state: () => (shown ? {radius: shown.radius, centre: shown.centre.slice(), plane: shown.plane || 17} : null),
    };
  }

  global.NcurveBackplotCutter = {create, COLOUR};
})(window);
