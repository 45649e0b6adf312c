// The workbench's time-travel debugger over the execution trace of POST /api/run (docs/serve.md):
// the variables, call stack and modal state at any executed block rebuilt from what each block
// changed, and the search for the next or previous breakpoint (a line, or a write that changes a
// watched variable), forwards or backwards. No re-run: everything comes from the trace.
// The system variables the program read are shown with the value each read last.
//   const t = NcurveTrace.create(trace);  t.at(k) -> {block, line, file, stack, vars, changed, modal, move,
//                                                     reads, readNow, readChanged, tool}
//   (tool: the offsets in force, {offset, radius, length, tip} of the trace's "tool", or null)
//   NcurveTrace.systemName(5021, profile) -> 'machine X' (docs/run.md's table; '' where it has none)
(function (global) {
  'use strict';
  const LOCALS = 33;
  const vacant = (v) => v === null || v !== v;  // null in a JSON answer, NaN in a binary one
  const value = (v) => (vacant(v) ? null : v);
  const key = (v, level) => (v >= 1 && v <= LOCALS ? level * 100000 + v : -v);  // locals per level; others by number

  function create(trace) {
    const B = trace.blocks, W = trace.writes, L = trace.levels, M = trace.modal;
    const n = B.line.length;  // positions 0..n: before block k (n: after the last)
    // writes of block b: wFrom[b + 1] .. wFrom[b + 2] - 1 (b = -1: the presets)
    const wFrom = new Int32Array(n + 2);
    {
      let w = 0;
      for (let b = -1; b <= n; b++) {
        wFrom[b + 1] = w;
        while (w < W.block.length && W.block[w] === b) w++;
      }
      wFrom[n + 1] = W.block.length;
    }
    const lFrom = new Int32Array(n + 1);
    {
      let l = 0;
      for (let b = 0; b <= n; b++) {
        lFrom[b] = l;
        while (l < L.block.length && L.block[l] === b) l++;
      }
    }
    // the state after the presets and blocks 0..k-1, applied onto vars (a Map key -> value)
    const apply = (vars, b) => {  // block b (-1: presets)
      if (b >= 0) for (let l = lFrom[b], e = b + 1 <= n ? lFrom[b + 1] : L.block.length; l < e; l++) {
        const level = L.level[l];
        for (let v = 1; v <= LOCALS; v++) vars.delete(key(v, level));
      }
      for (let w = wFrom[b + 1]; w < wFrom[b + 2]; w++) {
        const k = key(W.var[w], W.level[w]);
        if (vacant(W.new[w])) vars.delete(k);
        else vars.set(k, W.new[w]);
      }
    };
    // system variables read: those of block b are rFrom[b] .. rFrom[b + 1] - 1; rNew[r]: read r got a
    // value other than the read of its variable before it (or is its first)
    const R = trace.reads || {block: [], var: [], value: []};
    const rFrom = new Int32Array(n + 1), rNew = new Uint8Array(R.block.length);
    {
      let r = 0;
      for (let b = 0; b < n; b++) {
        rFrom[b] = r;
        while (r < R.block.length && R.block[r] === b) r++;
      }
      rFrom[n] = r;
      const last = new Map();
      for (let i = 0; i < R.block.length; i++) {
        rNew[i] = !last.has(R.var[i]) || last.get(R.var[i]) !== value(R.value[i]) ? 1 : 0;
        last.set(R.var[i], value(R.value[i]));
      }
    }
    const applyReads = (reads, b) => { for (let r = rFrom[b]; r < rFrom[b + 1]; r++) reads.set(R.var[r], value(R.value[r])); };
    // snapshots every `every` positions so that any position is at most `every` blocks of work away
    const every = Math.max(64, Math.ceil(n / 200));
    const snaps = [], readSnaps = [];
    {
      const vars = new Map(), reads = new Map();
      apply(vars, -1);
      for (let k = 0; k <= n; k++) {
        if (k % every === 0) snaps.push(new Map(vars)), readSnaps.push(new Map(reads));
        if (k < n) apply(vars, k), applyReads(reads, k);
      }
    }
    // the value each system variable read before position k got at its last read (a Map var -> value)
    let readCache = {k: -1, reads: null};
    const readsAt = (k) => {
      let reads, from;
      if (readCache.k >= 0 && readCache.k <= k && k - readCache.k <= every) reads = new Map(readCache.reads), from = readCache.k;
      else reads = new Map(readSnaps[Math.floor(k / every)]), from = Math.floor(k / every) * every;
      for (let b = from; b < k; b++) applyReads(reads, b);
      readCache = {k, reads};
      return reads;
    };
    let cache = {k: -1, vars: null};
    const varsAt = (k) => {
      let vars, from;
      if (cache.k >= 0 && cache.k <= k && k - cache.k <= every) vars = cache.vars, from = cache.k;
      else vars = new Map(snaps[Math.floor(k / every)]), from = Math.floor(k / every) * every;
      for (let b = from; b < k; b++) apply(vars, b);
      cache = {k, vars};
      return vars;
    };
    // modal variable values at position k
    const modalAt = (k) => {
      const out = new Map();
      M.variables.forEach((v, i) => out.set(v, value(M.initial[i])));
      for (let c = 0; c < M.block.length && M.block[c] <= k; c++) out.set(M.var[c], value(M.value[c]));
      return out;
    };
    // the tool offsets in force at position k: the last change at or before it
    const T = trace.tool || {block: []};
    const toolAt = (k) => {
      let lo = 0, hi = T.block.length - 1, at = -1;
      while (lo <= hi) {
        const mid = (lo + hi) >> 1;
        if (T.block[mid] <= k) at = mid, lo = mid + 1; else hi = mid - 1;
      }
      return at < 0 ? null : {offset: T.offset[at], radius: T.radius[at], length: T.length[at], tip: T.tip[at]};
    };
    // variables written by block b (its keys), and whether one of them is v with a change
    const writesOf = (b) => {
      const out = [];
      if (b < -1 || b >= n) return out;
      for (let w = wFrom[b + 1]; w < wFrom[b + 2]; w++) out.push(w);
      return out;
    };
    const changes = (b, v) => {
      for (let w = wFrom[b + 1]; w < wFrom[b + 2]; w++)
        if (W.var[w] === v && value(W.old[w]) !== value(W.new[w])) return true;
      if (b >= 0) for (let r = rFrom[b]; r < rFrom[b + 1]; r++) if (R.var[r] === v && rNew[r]) return true;
      return false;
    };

    return {
      count: n, complete: trace.complete, message: trace.message,
      stacks: trace.stacks, key,
      at(k) {
        k = Math.max(0, Math.min(n, k));
        const vars = varsAt(k);
        const changed = new Set();
        for (const w of writesOf(k - 1)) changed.add(key(W.var[w], W.level[w]));
        // the system variables read by the block just run; changed: the value differs from before it
        const before = k > 0 ? readsAt(k - 1) : new Map(), reads = readsAt(k), readNow = new Set(), readChanged = new Set();
        if (k > 0) for (let r = rFrom[k - 1]; r < rFrom[k]; r++) readNow.add(R.var[r]);
        for (const v of readNow) if (!before.has(v) || before.get(v) !== reads.get(v)) readChanged.add(v);
        return {
          reads, readNow, readChanged,
          k, block: k < n ? k : -1, line: k < n ? B.line[k] : 0, file: k < n ? B.file[k] : -1,
          stack: trace.stacks[B.stack[Math.min(k, n - 1)]] || [], vars, changed, modal: modalAt(k),
          move: k < n ? B.move[k] : trace.moves, tool: toolAt(k),
        };
      },
      // the next position after k (dir +1) or before it (-1) where a breakpoint holds: block b on a
      // line of `lines` (file `file`), or block b-1 changed a variable of `vars`; -1 for none
      seek(k, dir, file, lines, vars) {
        for (let b = k + dir; b >= 0 && b <= n; b += dir) {
          if (b < n && B.file[b] === file && lines.has(B.line[b])) return b;
          for (const v of vars) if (b > 0 && changes(b - 1, v)) return b;
        }
        return -1;
      },
    };
  }

  // The name of system variable v on profile p ({lathe, axes, offset_memory} of GET /api/profiles), as
  // docs/run.md's table of the system variables has it; '' where it gives none.
  function systemName(v, p) {
    p = p || {};
    const axes = p.axes || 'XYZ', axis = (k) => axes[k] || '';
    const inRange = (a, b) => v >= a && v <= b;
    if (inRange(1000, 1035)) return 'interface input';
    if (inRange(1100, 1135)) return 'interface output';
    if (p.lathe && inRange(2001, 2964) && (v - 2000) % 100 >= 1 && (v - 2000) % 100 <= 64) {
      const set = (v - 2000) % 100, what = ['X wear', 'Z wear', 'nose R wear', 'tip', '', '', '', 'X geometry', 'Z geometry', 'nose R geometry'];
      const w = what[Math.floor((v - 2001) / 100)];
      return w ? `${w}, offset ${set}` : '';
    }
    if (!p.lathe) {
      const mem = p.offset_memory || 'A';
      const ranges = [[2001, 2200, 0], [10001, 10999, 0], [2201, 2400, 1], [11001, 11999, 1], [12001, 12999, 2], [13001, 13999, 3]];
      for (const [a, b, kind] of ranges) {
        if (!inRange(a, b)) continue;
        const k = v - a + 1;
        if (mem === 'A') return kind === 0 ? `tool offset ${k}` : '';
        if (mem === 'B') return kind === 0 ? `wear, offset ${k}` : kind === 1 ? `geometry, offset ${k}` : '';
        return [`H wear ${k}`, `H geometry ${k}`, `D wear ${k}`, `D geometry ${k}`][kind];
      }
    }
    const fixed = {3000: 'alarm', 3001: 'timer (ms)', 3002: 'timer (h)', 3003: 'single block, wait', 3004: 'feed hold, override, exact stop',
      3005: 'settings', 3006: 'stop with message', 3011: 'date', 3012: 'time', 3901: 'parts machined', 3902: 'parts required',
      4107: 'D', 4109: 'F', 4111: 'H', 4113: 'M', 4114: 'sequence number', 4115: 'program number', 4119: 'S', 4120: 'T',
      4130: 'G54.1 P'};
    if (fixed[v]) return fixed[v];
    if (inRange(4001, 4022)) return `G group ${v - 4000}`;
    if (inRange(5001, 5120)) {
      const a = axis((v - 5001) % 20), kind = ['end point', 'machine', 'current', 'skip', 'tool length offset', 'servo deviation'];
      return a ? `${kind[Math.floor((v - 5001) / 20)]} ${a}` : '';
    }
    if (inRange(5201, 5340)) {
      const a = axis((v - 5201) % 20), set = Math.floor((v - 5201) / 20);
      return a ? `${set ? `G${53 + set}` : 'external'} offset ${a}` : '';
    }
    if (inRange(7001, 7960)) {
      const a = axis((v - 7001) % 20);
      return a ? `G54.1 P${Math.floor((v - 7001) / 20) + 1} offset ${a}` : '';
    }
    return '';
  }

  global.NcurveTrace = {create, systemName};
})(window);
