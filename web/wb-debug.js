// The workbench's time-travel debugger over the execution trace of POST /api/run (docs/serve.md):
// the variables, call stack and modal state at any executed block rebuilt from what each block
// changed, and the search for the next or previous breakpoint (a line, or a write that changes a
// watched variable), forwards or backwards. No re-run: everything comes from the trace.
//   const t = NcurveTrace.create(trace);  t.at(k) -> {block, line, file, stack, vars, changed, modal, move}
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
    // snapshots every `every` positions so that any position is at most `every` blocks of work away
    const every = Math.max(64, Math.ceil(n / 200));
    const snaps = [];
    {
      const vars = new Map();
      apply(vars, -1);
      for (let k = 0; k <= n; k++) {
        if (k % every === 0) snaps.push(new Map(vars));
        if (k < n) apply(vars, k);
      }
    }
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
        return {
          k, block: k < n ? k : -1, line: k < n ? B.line[k] : 0, file: k < n ? B.file[k] : -1,
          stack: trace.stacks[B.stack[Math.min(k, n - 1)]] || [], vars, changed, modal: modalAt(k),
          move: k < n ? B.move[k] : trace.moves,
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

  global.NcurveTrace = {create};
})(window);
