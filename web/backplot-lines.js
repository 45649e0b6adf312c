// The backplot's moves as GPU line segments: one set of lines per kind of move in the kind's colour
// (a big path's every step-th segment besides, drawn while turning it), each move's own colour
// (setColors), and picking: a scene with each move's number as its colour, rendered for a few
// pixels round the pointer.
//   const lines = NcurveBackplotLines.create({scene, moves, geometry});
//   lines.setColors(fn); lines.useCoarse(on); lines.dash(wpp); lines.pick(renderer, camera, x, y)
(function (global) {
  'use strict';
  const THREE = global.THREE;
  const KIND_NAMES = ['rapid', 'feed', 'arc'];
  const KIND_COLORS = [[0xef, 0x6c, 0x00], [0x15, 0x65, 0xc0], [0x2e, 0x7d, 0x32]];
  const PICK = 9;  // pixels a side picked round the pointer

  function create({scene, moves, geometry: G}) {
    const n = moves.count;
    const {first, segOf, counts, total, layers} = G;
    const kinds = [];  // per kind: {geometries, material, colors} or null
    const coarseLines = [];  // [full, coarse] per kind, for big paths
    layers.forEach((L, k) => {
      if (!L.count) { kinds.push(null); return; }
      const position = new THREE.BufferAttribute(L.pos, 3);
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', position);
      const color = new THREE.Color(`rgb(${KIND_COLORS[k].join(',')})`);
      let m;
      if (k === 0) {
        g.setAttribute('lineDistance', new THREE.BufferAttribute(L.dist, 1));
        m = new THREE.LineDashedMaterial({color, dashSize: 1, gapSize: 1});
      } else {
        m = new THREE.LineBasicMaterial({color});
      }
      const lines = new THREE.LineSegments(g, m);
      lines.frustumCulled = false;
      lines.name = KIND_NAMES[k];
      scene.add(lines);
      const kind = {geometries: [g], material: m, position, colors: null};
      kinds.push(kind);
      // while turning a big path on a slow GPU, and for its first frame: every step-th segment (in
      // buffers of their own, uploaded at once); setColors copies their colours from the full ones
      const step = Math.ceil(total / 150000);
      if (step > 1) {
        const kept = Math.ceil(L.count / step), cpos = new Float32Array(6 * kept), cdist = k === 0 ? new Float32Array(2 * kept) : null;
        for (let seg = 0, o = 0; seg < L.count; seg += step, o++) {
          cpos.set(L.pos.subarray(6 * seg, 6 * seg + 6), 6 * o);
          if (cdist) cdist[2 * o] = L.dist[2 * seg], cdist[2 * o + 1] = L.dist[2 * seg + 1];
        }
        const cg = new THREE.BufferGeometry();
        cg.setAttribute('position', new THREE.BufferAttribute(cpos, 3));
        if (cdist) cg.setAttribute('lineDistance', new THREE.BufferAttribute(cdist, 1));
        cg.userData = {step};
        const coarse = new THREE.LineSegments(cg, m);
        coarse.frustumCulled = false;
        coarse.visible = false;
        scene.add(coarse);
        coarseLines.push([lines, coarse]);
        kind.geometries.push(cg);
      }
    });
    // the colour of each vertex, from the first setColors on
    const vertexColors = (k) => {
      const kind = kinds[k];
      if (!kind.colors) {
        kind.colors = new THREE.BufferAttribute(new Uint8Array(6 * counts[k]), 3, true);
        kind.geometries[0].setAttribute('color', kind.colors);
        const cg = kind.geometries[1];
        if (cg) cg.setAttribute('color', kind.coarseColors = new THREE.BufferAttribute(
          new Uint8Array(3 * cg.attributes.position.count), 3, true));
        kind.material.vertexColors = THREE.VertexColors;
        kind.material.color.set(0xffffff);
        kind.material.needsUpdate = true;
      }
      return kind.colors;
    };
    // colours: fn(i) -> [r, g, b] (0..255) or null for the kind's colour; no fn: by kind
    function setColors(fn) {
      const cols = kinds.map((kind, k) => (kind ? vertexColors(k) : null));
      for (let i = 0; i < n; i++) {
        const k = moves.kind[i], c = (fn && fn(i)) || KIND_COLORS[k], col = cols[k].array;
        for (let v = 6 * first[i], e = 6 * (first[i] + segOf[i]); v < e; v += 3) col[v] = c[0], col[v + 1] = c[1], col[v + 2] = c[2];
      }
      kinds.forEach((kind) => {
        if (!kind) return;
        kind.colors.needsUpdate = true;
        if (!kind.coarseColors) return;
        const step = kind.geometries[1].userData.step, from = kind.colors.array, to = kind.coarseColors.array;
        for (let seg = 0, o = 0; o < to.length; seg += step, o += 6) to.set(from.subarray(6 * seg, 6 * seg + 6), o);
        kind.coarseColors.needsUpdate = true;
      });
    }
    // the coarse lines in place of the full ones, or back
    const useCoarse = (on) => { for (const [full, c] of coarseLines) full.visible = !on, c.visible = on; };
    // the rapids' dashes a fixed size on the screen (wpp: world units a pixel)
    const dash = (wpp) => { if (kinds[0]) kinds[0].material.dashSize = 6 * wpp, kinds[0].material.gapSize = 4 * wpp; };

    // the pick scene (each move's number as its colour), made at the first pick
    let pickScene = null;
    const pickSceneNow = () => {
      if (pickScene) return pickScene;
      pickScene = new THREE.Scene();
      kinds.forEach((kind, k) => {
        if (!kind) return;
        const pg = new THREE.BufferGeometry();
        pg.setAttribute('position', kind.position);  // shared: uploaded once
        pg.setAttribute('color', new THREE.BufferAttribute(G.pickColors(k), 3, true));
        const pl = new THREE.LineSegments(pg, new THREE.LineBasicMaterial({vertexColors: THREE.VertexColors}));
        pl.frustumCulled = false;
        pickScene.add(pl);
      });
      return pickScene;
    };
    const pickTarget = new THREE.WebGLRenderTarget(PICK, PICK);
    const pickPixels = new Uint8Array(4 * PICK * PICK);
    // the move drawn nearest the pointer within the picked square, or -1
    const pick = (renderer, camera, clientX, clientY) => {
      const rect = renderer.domElement.getBoundingClientRect();
      const x = clientX - rect.left, y = clientY - rect.top;
      if (x < 0 || y < 0 || x >= rect.width || y >= rect.height) return -1;
      const dpr = renderer.getPixelRatio();
      const W = Math.round(rect.width * dpr), H = Math.round(rect.height * dpr);
      camera.setViewOffset(W, H, Math.round(x * dpr) - (PICK >> 1), Math.round(y * dpr) - (PICK >> 1), PICK, PICK);
      renderer.setRenderTarget(pickTarget);
      renderer.setClearColor(0x000000, 1);
      renderer.render(pickSceneNow(), camera);
      renderer.setRenderTarget(null);
      camera.clearViewOffset();
      renderer.readRenderTargetPixels(pickTarget, 0, 0, PICK, PICK, pickPixels);
      let best = -1, bestD = Infinity;
      for (let py = 0; py < PICK; py++) for (let px = 0; px < PICK; px++) {
        const o = 4 * (py * PICK + px);
        const id = pickPixels[o] | (pickPixels[o + 1] << 8) | (pickPixels[o + 2] << 16);
        if (!id) continue;
        const d = (px - (PICK >> 1)) ** 2 + (py - (PICK >> 1)) ** 2;
        if (d < bestD) bestD = d, best = id - 1;
      }
      return best < n ? best : -1;
    };
    // the pick scene's buffers and the pick target freed (the scene's own go with the scene)
    function dispose() {
      if (pickScene) pickScene.traverse((o) => {
        if (o.geometry) o.geometry.dispose();
        if (o.material) o.material.dispose();
      });
      pickTarget.dispose();
    }
    return {setColors, useCoarse, dash, pick, dispose, hasCoarse: coarseLines.length > 0};
  }

  global.NcurveBackplotLines = {create, KIND_NAMES, KIND_COLORS};
})(window);
