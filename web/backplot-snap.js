// A grid of cubes over the backplot's drawn segments and move ends (world coordinates, as
// backplot-geometry.js lays them out), built once for a run's plot, so that a click asks only the
// segments and ends near its line of sight instead of every one of a big path.
//   const index = NcurveBackplotSnap.build(moves, geometry);
//   index.near(from, dir, reach, (id) => {...}, (i) => {...});  // segment ids and moves whose end may lie within reach
//   index.layerOf(id) -> [k, seg]
(function (global) {
  'use strict';
  const MOST_CELLS = 1 << 21;  // cells at most (a count and a start each)

  function build(moves, G) {
    const layers = G.layers, n = moves.count;
    const base = [];  // a segment's id: base[k] + its number in layer k
    let total = 0;
    for (const L of layers) base.push(total), total += L.count;
    // the grid spans the cuts (the rapids to and from home would stretch it over empty space); a
    // point beyond them is in the grid's nearest cell, and a look beyond them looks there
    const boxOf = (list) => {
      const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
      for (const L of list) {
        const P = L.pos;
        for (let v = 0; v < 6 * L.count; v += 3) {
          for (let a = 0; a < 3; a++) {
            if (P[v + a] < lo[a]) lo[a] = P[v + a];
            if (P[v + a] > hi[a]) hi[a] = P[v + a];
          }
        }
      }
      if (!(lo[0] <= hi[0])) for (let a = 0; a < 3; a++) lo[a] = hi[a] = 0;
      return [lo, hi];
    };
    const cuts = layers.slice(1).some((L) => L.count > 0);
    const [lo, hi] = boxOf(cuts ? layers.slice(1) : layers), [allLo, allHi] = boxOf(layers);
    // cubes of side c: about the square root of the segments along the cuts' longest side, fewer if the
    // grid would pass MOST_CELLS
    const span = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-9);
    let c = span / Math.max(1, Math.min(256, Math.ceil(Math.sqrt(total))));
    const dims = () => [0, 1, 2].map((a) => Math.max(1, Math.ceil((hi[a] - lo[a]) / c) + 1));
    let [nx, ny, nz] = dims();
    while (nx * ny * nz > MOST_CELLS) { c *= 1.25; [nx, ny, nz] = dims(); }
    const cellAt = (x, y, z) => {
      const i = Math.min(nx - 1, Math.max(0, Math.floor((x - lo[0]) / c)));
      const j = Math.min(ny - 1, Math.max(0, Math.floor((y - lo[1]) / c)));
      const k = Math.min(nz - 1, Math.max(0, Math.floor((z - lo[2]) / c)));
      return (k * ny + j) * nx + i;
    };
    // each segment in the cells of points along it half a cube apart (its ends included): a point of
    // it is within a quarter cube of one of them, so a look at the neighbouring cells finds it
    const eachCell = (fn) => {
      layers.forEach((L, k) => {
        const P = L.pos;
        for (let seg = 0, v = 0; seg < L.count; seg++, v += 6) {
          const dx = P[v + 3] - P[v], dy = P[v + 4] - P[v + 1], dz = P[v + 5] - P[v + 2];
          const steps = Math.ceil(Math.hypot(dx, dy, dz) / (c / 2));
          let last = -1;
          for (let s = 0; s <= steps; s++) {
            const t = steps ? s / steps : 0, cell = cellAt(P[v] + dx * t, P[v + 1] + dy * t, P[v + 2] + dz * t);
            if (cell !== last) fn(cell, base[k] + seg), last = cell;
          }
        }
      });
    };
    const cells = nx * ny * nz;
    const csr = (fill) => {  // cell -> its entries, as starts into one array
      const start = new Uint32Array(cells + 1);
      fill((cell) => { start[cell + 1]++; });
      for (let i = 0; i < cells; i++) start[i + 1] += start[i];
      const at = start.slice(0, cells), list = new Uint32Array(start[cells]);
      fill((cell, id) => { list[at[cell]++] = id; });
      return {start, list};
    };
    const segs = csr((put) => eachCell(put));
    const E = moves.end, perm = G.perm, origin = G.origin;
    const ends = csr((put) => {
      for (let i = 0, o = 0; i < n; i++, o += 3)
        put(cellAt(E[o + perm[0]] - origin[perm[0]], E[o + perm[1]] - origin[perm[1]], E[o + perm[2]] - origin[perm[2]]), i);
    });
    const seen = new Uint32Array(cells);
    let stamp = 0;

    // the cells within reach (world units) of the line through `from` along unit `dir`, each once:
    // the line walked a cube at a time across the grid, the cubes round each step looked at
    function near(from, dir, reach, onSegment, onEnd) {
      if (++stamp === 0xffffffff) seen.fill(0), stamp = 1;
      // the part of the line inside the box of every point widened by reach (slabs)
      let t0 = -Infinity, t1 = Infinity;
      for (let a = 0; a < 3; a++) {
        const l = allLo[a] - reach - c, h = allHi[a] + reach + c;
        if (Math.abs(dir[a]) < 1e-12) {
          if (from[a] < l || from[a] > h) return;
          continue;
        }
        let ta = (l - from[a]) / dir[a], tb = (h - from[a]) / dir[a];
        if (ta > tb) [ta, tb] = [tb, ta];
        t0 = Math.max(t0, ta), t1 = Math.min(t1, tb);
      }
      if (!(t0 <= t1)) return;
      const r = Math.ceil(reach / c) + 1;
      const cell = (v, a, most) => Math.min(most - 1, Math.max(0, Math.floor((v - lo[a]) / c)));  // the nearest cell's
      const visit = (cell) => {
        if (seen[cell] === stamp) return;
        seen[cell] = stamp;
        for (let e = segs.start[cell]; e < segs.start[cell + 1]; e++) onSegment(segs.list[e]);
        for (let e = ends.start[cell]; e < ends.start[cell + 1]; e++) onEnd(ends.list[e]);
      };
      for (let t = t0; t <= t1 + c; t += c) {
        const x = from[0] + dir[0] * t, y = from[1] + dir[1] * t, z = from[2] + dir[2] * t;
        const i = cell(x, 0, nx), j = cell(y, 1, ny), k = cell(z, 2, nz);
        for (let kk = Math.max(0, k - r); kk <= Math.min(nz - 1, k + r); kk++)
          for (let jj = Math.max(0, j - r); jj <= Math.min(ny - 1, j + r); jj++)
            for (let ii = Math.max(0, i - r); ii <= Math.min(nx - 1, i + r); ii++) visit((kk * ny + jj) * nx + ii);
      }
    }
    const layerOf = (id) => {
      let k = base.length - 1;
      while (k > 0 && id < base[k]) k--;
      return [k, id - base[k]];
    };
    return {near, layerOf, cube: c, cells};
  }

  global.NcurveBackplotSnap = {build};
})(window);
