// The cut part under a backplot's moves (web/backplot.js setPart): a mill's Z-map as its top
// surface and walls, a lathe's half-section revolved about the Z axis. Needs three.js.
//
//   const part = NcurveBackplotPart.decode(data.part);   // the JSON of `run --verify --html` (docs/html.md)
//   const mesh = NcurveBackplotPart.mesh(part, toWorld); // toWorld: machine X Y Z -> the scene's
(function (global) {
  'use strict';
  const THREE = global.THREE;
  const SEGMENTS = 96;  // steps of a lathe part's revolution

  function bytes(b64) {
    const bin = atob(b64 || '');
    const out = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
    return out.buffer;
  }

  // Light grey at t = 0 (the stock's surface), darker to t = 1 (the deepest cut).
  const shade = (t, col) => col.push(0.84 - 0.34 * t, 0.85 - 0.33 * t, 0.87 - 0.29 * t);

  // A mesh of the triangles, shaded, pushed back a little in depth so that the moves on its surface
  // are drawn over it.
  function shaded(pos, col, index) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(pos), 3));
    g.setAttribute('color', new THREE.BufferAttribute(new Float32Array(col), 3));
    g.setIndex(index);
    g.computeVertexNormals();
    const m = new THREE.MeshLambertMaterial({vertexColors: THREE.VertexColors, side: THREE.DoubleSide,
                                            polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1});
    const mesh = new THREE.Mesh(g, m);
    mesh.name = 'part';
    return mesh;
  }

  // The cut part of `run --verify --html`: a mill's grid of heights (base64 float32, row by row),
  // with `deviation` ({tol, points: X Y error per wall point measured against the design}) coloured
  // near its walls; or a lathe's half-section contours (base64 float32 Z, X pairs, X a radius).
  function decode(d) {
    if (d.lathe)
      return {lathe: true, radius: d.radius, bore: d.bore, contours: (d.contours || []).map((c) => new Float32Array(bytes(c)))};
    return {nx: d.nx, ny: d.ny, x0: d.x0, y0: d.y0, dx: d.dx, dy: d.dy, bottom: d.bottom, top: d.top,
            heights: new Float32Array(bytes(d.heights)),
            deviation: d.deviation ? {tol: d.deviation.tol, points: new Float32Array(bytes(d.deviation.points))} : null};
  }

  // Per grid point, the largest error of a wall point within two cells of it (NaN where none).
  function deviationOnGrid(part) {
    const {nx, ny, x0, y0, dx, dy} = part, pts = part.deviation.points;
    const dev = new Float32Array(nx * ny).fill(NaN);
    for (let k = 0; k + 2 < pts.length; k += 3) {
      const ci = Math.round((pts[k] - x0) / dx), cj = Math.round((pts[k + 1] - y0) / dy), e = pts[k + 2];
      for (let j = Math.max(cj - 2, 0); j <= Math.min(cj + 2, ny - 1); j++)
        for (let i = Math.max(ci - 2, 0); i <= Math.min(ci + 2, nx - 1); i++) {
          const q = j * nx + i;
          if (!(Math.abs(dev[q]) >= Math.abs(e))) dev[q] = e;
        }
    }
    return dev;
  }
  // within the tolerance green, beyond the design (a gouge) red, short of it (stock left) blue; the
  // colour deepens up to twice the tolerance
  const DEVIATION_COLOURS = {within: [0.26, 0.63, 0.28], gouge: [0.90, 0.22, 0.21], left: [0.12, 0.47, 0.90]};
  function deviationColour(e, tol) {
    const a = Math.abs(e);
    if (a <= tol) return DEVIATION_COLOURS.within;
    const c = e > 0 ? DEVIATION_COLOURS.gouge : DEVIATION_COLOURS.left, t = Math.min((a - tol) / tol, 1);
    return [0.75 + (c[0] - 0.75) * (0.5 + t / 2), 0.75 + (c[1] - 0.75) * (0.5 + t / 2), 0.75 + (c[2] - 0.75) * (0.5 + t / 2)];
  }

  // A mill's part: its top surface on the grid and four walls down to the bottom, coloured by depth
  // below the stock's top (light grey at the top, darker down to the deepest cut), or by the walls'
  // deviation where measured.
  function gridMesh(part, toWorld) {
    const {nx, ny, x0, y0, dx, dy, bottom, top, heights} = part;
    let deepest = top;
    for (let k = 0; k < heights.length; k++) deepest = Math.min(deepest, heights[k]);
    const depth = Math.max(top - deepest, 1e-9);
    const pos = [], col = [], index = [];
    const w = [0, 0, 0];
    const dev = part.deviation ? deviationOnGrid(part) : null;
    const vertex = (x, y, z, e) => {
      toWorld([x, y, z], w);
      pos.push(w[0], w[1], w[2]);
      if (e === e && e !== undefined) col.push(...deviationColour(e, part.deviation.tol));
      else shade(Math.min(Math.max((top - z) / depth, 0), 1), col);
      return pos.length / 3 - 1;
    };
    for (let j = 0; j < ny; j++)
      for (let i = 0; i < nx; i++) vertex(x0 + i * dx, y0 + j * dy, heights[j * nx + i], dev ? dev[j * nx + i] : undefined);
    for (let j = 0; j + 1 < ny; j++)
      for (let i = 0; i + 1 < nx; i++) {
        const a = j * nx + i, b = a + 1, c = a + nx + 1, d = a + nx;
        index.push(a, b, c, a, c, d);
      }
    // the walls: the boundary counter-clockwise from above, each point down to the bottom
    const ring = [];
    for (let i = 0; i < nx - 1; i++) ring.push([i, 0]);
    for (let j = 0; j < ny - 1; j++) ring.push([nx - 1, j]);
    for (let i = nx - 1; i > 0; i--) ring.push([i, ny - 1]);
    for (let j = ny - 1; j > 0; j--) ring.push([0, j]);
    const low = ring.map(([i, j]) => vertex(x0 + i * dx, y0 + j * dy, bottom));
    ring.forEach(([i, j], k) => {
      const [i2, j2] = ring[(k + 1) % ring.length];
      const p = j * nx + i, q = j2 * nx + i2, lp = low[k], lq = low[(k + 1) % ring.length];
      index.push(lp, lq, q, lp, q, p);
    });
    const mesh = shaded(pos, col, index);
    if (dev) {
      const tol = part.deviation.tol, deviated = {within: 0, gouge: 0, left: 0};
      for (const e of dev) if (e === e) deviated[Math.abs(e) <= tol ? 'within' : e > 0 ? 'gouge' : 'left']++;
      mesh.userData.deviated = deviated;
    }
    return mesh;
  }

  // A lathe's part: each edge of each contour swept about the Z axis in SEGMENTS steps, a band of
  // its own (sharp where the section has a corner, smooth round the axis), machine X Y Z = (r cos,
  // r sin, z); shaded by how far below the stock's radius it lies.
  function latheMesh(part, toWorld) {
    const {radius, contours} = part;
    let least = radius;
    for (const c of contours) for (let k = 1; k < c.length; k += 2) least = Math.min(least, c[k]);
    const depth = Math.max(radius - least, 1e-9);
    const pos = [], col = [], index = [];
    const w = [0, 0, 0];
    const cos = [], sin = [];
    for (let s = 0; s <= SEGMENTS; s++) cos.push(Math.cos(2 * Math.PI * s / SEGMENTS)), sin.push(Math.sin(2 * Math.PI * s / SEGMENTS));
    const vertex = (z, r, s) => {
      toWorld([r * cos[s], r * sin[s], z], w);
      pos.push(w[0], w[1], w[2]);
      shade(Math.min(Math.max((radius - r) / depth, 0), 1), col);
      return pos.length / 3 - 1;
    };
    for (const c of contours) {
      const n = c.length / 2;
      for (let i = 0; i < n; i++) {
        const j = (i + 1) % n;
        const az = c[2 * i], ar = c[2 * i + 1], bz = c[2 * j], br = c[2 * j + 1];
        if (ar <= 0 && br <= 0) continue;  // along the axis: no surface
        const first = pos.length / 3;
        for (let s = 0; s <= SEGMENTS; s++) vertex(az, ar, s), vertex(bz, br, s);
        for (let s = 0; s < SEGMENTS; s++) {
          const a = first + 2 * s, b = a + 1, a1 = a + 2, b1 = a + 3;
          index.push(a, b, b1, a, b1, a1);
        }
      }
    }
    return shaded(pos, col, index);
  }

  const mesh = (part, toWorld) => (part.lathe ? latheMesh(part, toWorld) : gridMesh(part, toWorld));

  global.NcurveBackplotPart = {decode, mesh, DEVIATION_COLOURS};
})(window);
