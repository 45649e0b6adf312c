// Another run's moves drawn thin and grey under a backplot's (web/backplot.js): the run the program
// is compared with (wb-compare.js). Its segments are backplot-geometry.js's for its own moves (arcs
// as the backplot draws them), placed in the plot's scene; where both runs move alike the current
// path covers the grey. Needs three.js.
//
//   const other = NcurveBackplotCompare.create(moves);  // moves as NcurveBackplot.create takes them
//   const plot = NcurveBackplot.create(container, current, {frame: other.frame});  // the views fit both
//   other.drawIn(plot); other.highlight([i, ...]); other.segments();
(function (global) {
  'use strict';
  const THREE = global.THREE;
  const GREY = 0xaab1b9, RAPID_GREY = 0xd3d8dd, HIGHLIGHT = 0x37474f;

  function create(moves) {
    const G = global.NcurveBackplotGeometry.build(moves);
    let hl = null, drawn = 0;
    const frame = moves.count ? {lo: G.lo, hi: G.hi, frameLo: G.frameLo, frameHi: G.frameHi} : null;

    // the moves' segments in one buffer, as the geometry has them (relative to its own origin)
    function segments(list) {
      let c = 0;
      for (const i of list) c += G.segOf[i];
      const out = new Float32Array(6 * c);
      let o = 0;
      for (const i of list) {
        const src = G.layers[moves.kind[i]].pos;
        out.set(src.subarray(6 * G.first[i], 6 * (G.first[i] + G.segOf[i])), o);
        o += 6 * G.segOf[i];
      }
      return new THREE.BufferAttribute(out, 3);
    }
    const lines = (position, material, order) => {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', position);
      const l = new THREE.LineSegments(g, material);
      l.renderOrder = order;
      l.frustumCulled = false;
      return l;
    };

    // drawn first and leaving the depth alone (under the plot's moves); rapids paler than cuts; a
    // plot of the other orientation (a lathe's against a mill's) gets nothing
    function drawIn(plot) {
      hl = null, drawn = 0;
      if (!moves.count || plot.moves.lathe !== moves.lathe) return;
      const group = new THREE.Group();
      group.name = 'compared';
      G.layers.forEach((L, k) => {
        if (!L.count) return;
        group.add(lines(new THREE.BufferAttribute(L.pos, 3),
          new THREE.LineBasicMaterial({color: k ? GREY : RAPID_GREY, depthWrite: false}), -1));
        drawn += L.count;
      });
      // its highlighted moves over everything, dark grey beside the plot's magenta
      hl = lines(segments([]), new THREE.LineBasicMaterial({color: HIGHLIGHT, depthTest: false, transparent: true}), 9);
      group.add(hl);
      group.position.fromArray(plot.toWorld(G.origin));
      plot.addLayer(group);
    }
    return {
      frame, drawIn,
      highlight(list, plot) {
        if (!hl) return;
        hl.geometry.setAttribute('position', segments((list || []).filter((i) => i >= 0 && i < moves.count)));
        if (plot) plot.render();
      },
      segments: () => drawn,
    };
  }

  global.NcurveBackplotCompare = {create};
})(window);
