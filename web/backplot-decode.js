// The moves of a run from the data of `ncurve run --html` (docs/html.md): base64 little-endian
// arrays turned into the typed arrays backplot.js draws (its header names the fields).
//   const moves = NcurveBackplotDecode.decode(data);
(function (global) {
  'use strict';

  function bytes(b64) {
    const bin = atob(b64 || '');
    const out = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
    return out.buffer;
  }

  // The moves from the data of `ncurve run --html` (base64 little-endian arrays).
  function decode(d) {
    const kind = new Uint8Array(bytes(d.kind));
    const n = kind.length;
    const end = new Float32Array(bytes(d.end));
    const start = new Float32Array(3 * n);
    const jumps = d.jumps || [];
    let j = 0;
    for (let i = 0; i < n; i++) {
      if (j < jumps.length && jumps[j][0] === i) {
        start[3 * i] = jumps[j][1], start[3 * i + 1] = jumps[j][2], start[3 * i + 2] = jumps[j][3];
        j++;
      } else if (i > 0) {
        start[3 * i] = end[3 * i - 3], start[3 * i + 1] = end[3 * i - 2], start[3 * i + 2] = end[3 * i - 1];
      }
    }
    const arcIndex = new Int32Array(n);
    let a = 0;
    for (let i = 0; i < n; i++) arcIndex[i] = kind[i] === 2 ? a++ : -1;
    // a dog-leg rapid's corners (non-linear positioning): rapidCorners[i] = [x, y, z, ...] in order
    const rapidCorners = new Map();
    for (const c of d.rapid_corners || []) {
      if (!(c[0] >= 0 && c[0] < n) || kind[c[0]] !== 0) continue;
      if (!rapidCorners.has(c[0])) rapidCorners.set(c[0], []);
      rapidCorners.get(c[0]).push(c[1], c[2], c[3]);
    }
    return {
      count: n, kind, start, end, arcIndex, rapidCorners,
      arcs: new Float32Array(bytes(d.arcs)),
      feed: new Float32Array(bytes(d.feed)),
      block: new Uint32Array(bytes(d.block)),
      blockFile: new Uint16Array(bytes(d.block_file)),
      blockLine: new Uint32Array(bytes(d.block_line)),
      lathe: !!d.lathe, diameter: !!d.diameter, inch: !!d.inch, plane: d.plane || 17,
      alarmAt: d.alarm ? d.alarm.at : null,
      rotary: d.rotary || [],
      rotaryEnd: new Float64Array(bytes(d.rotary_end)),
      programmed: global.NcurveBackplotProgrammed ? global.NcurveBackplotProgrammed.decode(d) : null,
    };
  }

  global.NcurveBackplotDecode = {decode};
})(window);
