// The workbench's Compare tab (docs/serve.md): the run in the editor against another, the run kept
// by "Keep this run" or a program (the server's, or a file of this computer) run on the same machine
// and Settings through /api/run. The two texts are aligned by a line diff (Myers), the moves of each
// pair of lines compared (kind, end, arc centre and direction, feed, to the 0.001 the output prints;
// events by kind and code) and the blocks whose moves differ listed, those after an edit that all
// moved by one offset grouped under the first; the other run is drawn grey under the path
// (backplot-compare.js).
//   const cmp = NcurveCompare.create({request(), profile(), editor, onDraw(), highlight(list)});
//   cmp.frame(conv), cmp.drawIn(plot)   while the plot is made (the views fit both runs)
//   cmp.update(answer, name, conv)      after each run; cmp.setPrograms(names); cmp.state (tests)
(function (global) {
  'use strict';
  const {el, fmt} = NcurveDom;
  const MAX_EDITS = 2000;  // the line diff gives up past so many inserted and deleted lines
  const MAX_ROWS = 200;    // rows listed, the rest counted
  const NONE = [];

  // ---- the line diff ----
  // Myers' O((N+M)D) diff of two arrays of line ids: for each line of a its line in b (-1: none) and
  // back; null past maxD inserted and deleted lines
  function myers(a, b, maxD) {
    const n = a.length, m = b.length, off = n + m + 1, v = new Int32Array(2 * off + 1), trace = [];
    for (let d = 0; d <= Math.min(n + m, maxD); d++) {
      trace.push(v.slice(off - d - 1, off + d + 2));  // the furthest x of each diagonal after d - 1 edits
      for (let k = -d; k <= d; k += 2) {
        let x = k === -d || (k !== d && v[off + k - 1] < v[off + k + 1]) ? v[off + k + 1] : v[off + k - 1] + 1, y = x - k;
        while (x < n && y < m && a[x] === b[y]) x++, y++;
        v[off + k] = x;
        if (x >= n && y >= m) return backtrack(trace, n, m);
      }
    }
    return null;
  }
  function backtrack(trace, n, m) {
    const aToB = new Int32Array(n).fill(-1), bToA = new Int32Array(m).fill(-1);
    let x = n, y = m;
    for (let d = trace.length - 1; d >= 0; d--) {
      const V = trace[d], at = (k) => V[k + d + 1], k = x - y;
      const pk = k === -d || (k !== d && at(k - 1) < at(k + 1)) ? k + 1 : k - 1, px = at(pk), py = px - pk;
      while (x > px && y > py) x--, y--, aToB[x] = y, bToA[y] = x;
      x = px, y = py;
    }
    return {aToB, bToA};
  }
  // the lines of two texts in order as pairs {was, now} (1-based; 0: not in that text): the same
  // line in both, or an edit (edited: the lines between two alike, paired by pairHunk, the rest
  // deleted or inserted); capped: the texts differ in too many lines for the diff, their middles
  // paired in order
  function align(A, B) {
    const ids = new Map(), id = (s) => { let v = ids.get(s); if (v === undefined) ids.set(s, v = ids.size); return v; };
    const a = Int32Array.from(A, id), b = Int32Array.from(B, id);
    let p = 0, s = 0;
    while (p < a.length && p < b.length && a[p] === b[p]) p++;
    while (s < a.length - p && s < b.length - p && a[a.length - 1 - s] === b[b.length - 1 - s]) s++;
    const na = a.length - p - s, nb = b.length - p - s;
    const mid = myers(a.subarray(p, p + na), b.subarray(p, p + nb), MAX_EDITS);
    const aToB = mid ? mid.aToB : new Int32Array(na).fill(-1), bToA = mid ? mid.bToA : new Int32Array(nb).fill(-1);
    const pairs = [];
    for (let i = 0; i < p; i++) pairs.push({was: i + 1, now: i + 1});
    for (let i = 0, j = 0; i < na || j < nb;) {
      if (i < na && aToB[i] === j) { pairs.push({was: p + i + 1, now: p + j + 1}); i++, j++; continue; }
      let i2 = i, j2 = j;
      while (i2 < na && aToB[i2] < 0) i2++;
      while (j2 < nb && bToA[j2] < 0) j2++;
      for (const [x, y] of pairHunk(A, p + i, p + i2, B, p + j, p + j2)) pairs.push({was: x + 1, now: y + 1, edited: true});
      i = i2, j = j2;
    }
    for (let t = 0; t < s; t++) pairs.push({was: a.length - s + t + 1, now: b.length - s + t + 1});
    return {pairs, capped: !mid};
  }
  // how alike two lines are: Dice's coefficient of their pairs of characters, 0 to 1
  function likeness(a, b) {
    if (a.length < 2 || b.length < 2) return a === b ? 1 : 0;
    const seen = new Map();
    for (let i = 0; i + 1 < a.length; i++) { const k = a.substr(i, 2); seen.set(k, (seen.get(k) || 0) + 1); }
    let common = 0;
    for (let i = 0; i + 1 < b.length; i++) {
      const k = b.substr(i, 2), c = seen.get(k);
      if (c) common++, seen.set(k, c - 1);
    }
    return 2 * common / (a.length + b.length - 2);
  }
  // the lines A[i..i2) and B[j..j2) between two alike, as [a, b] (0-based; -1: none) in order: as
  // many of each in order as edits of each other, the rest deleted or inserted; of unequal
  // numbers (lines inserted or deleted beside an edit) the pairs most alike, at least a third
  function pairHunk(A, i, i2, B, j, j2) {
    const n = i2 - i, m = j2 - j, out = [];
    if (n === m || !n || !m || n * m > 40000) {
      for (let t = 0; t < Math.max(n, m); t++) out.push([t < n ? i + t : -1, t < m ? j + t : -1]);
      return out;
    }
    const S = new Float64Array((n + 1) * (m + 1)), at = (x, y) => x * (m + 1) + y, gain = (x, y) => likeness(A[i + x - 1], B[j + y - 1]) - 1 / 3;
    for (let x = 1; x <= n; x++) for (let y = 1; y <= m; y++)
      S[at(x, y)] = Math.max(S[at(x - 1, y)], S[at(x, y - 1)], S[at(x - 1, y - 1)] + Math.max(gain(x, y), -1));
    for (let x = n, y = m; x > 0 || y > 0;) {
      if (x && y && S[at(x, y)] === S[at(x - 1, y - 1)] + gain(x, y) && gain(x, y) >= 0) out.push([i + --x, j + --y]);
      else if (y && (!x || S[at(x, y)] === S[at(x, y - 1)])) out.push([-1, j + --y]);
      else out.push([i + --x, -1]);
    }
    return out.reverse();
  }
  // a text's lines as the server numbers them, trailing blanks (a CR) left out of the comparison
  const linesOf = (text) => text.split('\n');
  const bare = (lines) => lines.map((l) => l.replace(/\s+$/, ''));

  // ---- the moves of a run, by source block ----
  // the main file's moves by line (block(L): its move indexes), the other files' (macros called) by
  // "name:line"
  function facts(run) {
    const M = run.moves, K = M.kinds, main = Math.max(0, run.files.indexOf(run.name)), n = run.lines.length;
    const motion = new Set(['rapid', 'line', 'arc'].map((k) => K.indexOf(k)));
    const inText = (i) => M.file[i] === main && M.line[i] >= 1 && M.line[i] <= n;
    const start = new Uint32Array(n + 2), others = new Map();
    for (let i = 0; i < M.count; i++) {
      if (inText(i)) { start[M.line[i] + 1]++; continue; }
      const key = `${run.files[M.file[i]]}:${M.line[i]}`;
      if (!others.has(key)) others.set(key, []);
      others.get(key).push(i);
    }
    for (let L = 1; L <= n + 1; L++) start[L] += start[L - 1];
    const order = new Uint32Array(start[n + 1]), at = start.slice();
    for (let i = 0; i < M.count; i++) if (inText(i)) order[at[M.line[i]]++] = i;
    const block = (L) => (L >= 1 && L <= n ? order.subarray(start[L], start[L + 1]) : NONE);
    const arcOf = new Map(), codeOf = new Map();
    M.arcs.index.forEach((i, k) => arcOf.set(i, k));
    M.codes.index.forEach((i, k) => codeOf.set(i, M.codes.code[k]));
    const axes = [['X', M.x], ['Y', M.y], ['Z', M.z]].concat(['a', 'b', 'c'].filter((k) => M[k]).map((k) => [k.toUpperCase(), M[k]]));
    const A = M.arcs, centre = [['X', A.cx], ['Y', A.cy], ['Z', A.cz]];
    return {M, K, motion, block, others, arcOf, codeOf, axes, centre};
  }
  const r3 = (v) => Math.round(v * 1000);  // to the output's 0.001
  const mm = (r) => (r / 1000).toFixed(3);
  // the axes of a and b whose values differ at 0.001: "X30.000 → X32.000"; '' when alike
  function axesDiff(a, i, b, j) {
    const was = [], now = [];
    for (const [name, col] of a) {
      const other = b.find((x) => x[0] === name);
      if (!other || r3(col[i]) === r3(other[1][j])) continue;
      was.push(name + mm(r3(col[i]))), now.push(name + mm(r3(other[1][j])));
    }
    return was.length ? `${was.join(' ')} → ${now.join(' ')}` : '';
  }
  // what differs between move i of run A and move j of run B, in words ([] when alike)
  function moveDiff(A, i, B, j) {
    const ka = A.K[A.M.kind[i]], kb = B.K[B.M.kind[j]], out = [];
    if (ka !== kb) out.push(`${ka} → ${kb}`);
    if (!A.motion.has(A.M.kind[i]) || !B.motion.has(B.M.kind[j])) {
      const ca = A.codeOf.get(i), cb = B.codeOf.get(j);
      if (ka === kb && ca !== cb) out.push(`${ka} ${ca} → ${cb}`);
      return out;
    }
    const end = axesDiff(A.axes, i, B.axes, j);
    if (end) out.push(`end ${end}`);
    const a = A.arcOf.get(i), b = B.arcOf.get(j);
    if (a !== undefined && b !== undefined) {
      const c = axesDiff(A.centre, a, B.centre, b);
      if (c) out.push(`centre ${c}`);
      const cw = (R, k) => (R.M.arcs.cw[k] ? 'G02' : 'G03');
      if (cw(A, a) !== cw(B, b)) out.push(`${cw(A, a)} → ${cw(B, b)}`);
    }
    if (r3(A.M.f[i]) !== r3(B.M.f[j])) out.push(`F${fmt(A.M.f[i])} → F${fmt(B.M.f[j])}`);
    return out;
  }
  // the offset of move j of B from move i of A when it is move i moved (its end and centre by one
  // vector, all else alike): "dx,dy,dz..." in 0.001; '' for an event alike; null otherwise
  function offsetOf(A, i, B, j) {
    const ka = A.M.kind[i], kb = B.M.kind[j];
    if (A.K[ka] !== B.K[kb]) return null;
    if (!A.motion.has(ka)) return A.codeOf.get(i) === B.codeOf.get(j) ? '' : null;
    if (r3(A.M.f[i]) !== r3(B.M.f[j])) return null;
    const d = A.axes.map(([name, col]) => {
      const other = B.axes.find((x) => x[0] === name);
      return other ? r3(other[1][j]) - r3(col[i]) : 0;
    });
    const a = A.arcOf.get(i), b = B.arcOf.get(j);
    if (a !== undefined && b !== undefined) {
      if (A.M.arcs.cw[a] !== B.M.arcs.cw[b]) return null;
      for (let k = 0; k < 3; k++) if (r3(B.centre[k][1][b]) - r3(A.centre[k][1][a]) !== d[k]) return null;
    }
    return d.join();
  }
  const movesWord = (n) => `${n} move${n === 1 ? '' : 's'}`;
  // move i of A and move j of B alike (kind, end, centre, direction, feed; an event's code), at 0.001
  function alike(A, i, B, j, common) {
    const ka = A.M.kind[i], kb = B.M.kind[j];
    if (A.K[ka] !== B.K[kb]) return false;
    if (!A.motion.has(ka)) return A.codeOf.get(i) === B.codeOf.get(j);
    if (r3(A.M.f[i]) !== r3(B.M.f[j])) return false;
    for (const [a, b] of common) if (r3(a[i]) !== r3(b[j])) return false;
    const a = A.arcOf.get(i), b = B.arcOf.get(j);
    if (a === undefined || b === undefined) return true;
    const P = A.M.arcs, Q = B.M.arcs;
    return P.cw[a] === Q.cw[b] && r3(P.cx[a]) === r3(Q.cx[b]) && r3(P.cy[a]) === r3(Q.cy[b]) && r3(P.cz[a]) === r3(Q.cz[b]);
  }
  // whether block ma of A and block mb of B differ: null when alike, else {what() in words, shift
  // (the offset when the block only moved, else null)}
  function diffBlock(A, ma, B, mb, common) {
    if (ma.length !== mb.length) return {what: () => `${movesWord(ma.length)} → ${movesWord(mb.length)}`, shift: null};
    let first = -1, count = 0, shift = null;
    for (let k = 0; k < ma.length; k++) if (!alike(A, ma[k], B, mb[k], common) && !count++) first = k;
    if (!count) return null;
    const what = () => {
      const w = moveDiff(A, ma[first], B, mb[first]).join(', ');
      return ma.length === 1 ? w : `move ${first + 1} of ${ma.length}: ${w}${count > 1 ? `; ${count} of its ${ma.length} moves differ` : ''}`;
    };
    for (let k = 0; k < ma.length; k++) {
      const s = offsetOf(A, ma[k], B, mb[k]);
      if (s === null || (s && shift !== null && s !== shift)) return {what, shift: null};
      if (s) shift = s;
    }
    return {what, shift: shift && /[^0,]/.test(shift) ? shift : null};
  }
  // an offset of offsetOf in words: "X-1.000"
  const shiftText = (A, shift) => shift.split(',').map((v, k) => (+v ? `${A.axes[k][0]}${+v > 0 ? '+' : ''}${mm(+v)}` : '')).filter(Boolean).join(' ');
  // the moves of a block in a line or two: "line to X10.000 Y0.000 Z-1.000"
  function describe(R, list) {
    const i = list[0], k = R.M.kind[i];
    const what = R.motion.has(k) ? `${R.K[k]} to ${R.axes.map(([n, c]) => n + mm(r3(c[i]))).join(' ')}`
      : `${R.K[k]}${R.codeOf.has(i) ? ' ' + R.codeOf.get(i) : ''}`;
    return list.length === 1 ? what : `${movesWord(list.length)}; the first: ${what}`;
  }

  // The blocks whose moves differ between run ref (was) and run cur (now), each {text, lines,
  // name, moves, files}: entries {kind: changed | inserted | deleted, was, now (lines, or
  // "file:line" of another file), text, old (the reference's text where it differs), what, movesWas,
  // movesNow (the runs' move indexes), after: [the blocks after it moved by the same offset], shift},
  // differ (blocks), quiet (edited lines that make no move either way), capped
  function compareRuns(ref, cur) {
    const A = facts(ref), B = facts(cur);
    const common = A.axes.map(([n, a]) => [a, (B.axes.find((x) => x[0] === n) || [])[1]]).filter((x) => x[1]);
    const {pairs, capped} = align(bare(ref.lines), bare(cur.lines));
    const entries = [];
    let differ = 0, quiet = 0, group = null, lastNow = 0;
    const block = (was, now, ma, mb, tWas, tNow, edited) => {
      if (!ma.length && !mb.length) { if (edited) quiet++; return; }
      differ++;
      if (!was || !now) {
        group = null;
        entries.push({kind: was ? 'deleted' : 'inserted', was, now, text: was ? tWas : tNow, what: describe(was ? A : B, was ? ma : mb),
          movesWas: ma, movesNow: mb, at: now || lastNow + 1, after: []});
        return;
      }
      const d = diffBlock(A, ma, B, mb, common);
      if (!d) { differ--, group = null; return; }
      const e = {kind: 'changed', was, now, text: tNow, movesWas: ma, movesNow: mb, at: now, after: []};
      if (tWas !== tNow) e.old = tWas;
      if (d.shift && group && group.shift === d.shift) { group.entry.after.push(e); return; }
      e.what = d.what();
      if (d.shift) e.shift = shiftText(A, d.shift);
      entries.push(e);
      group = d.shift ? {shift: d.shift, entry: e} : null;
    };
    for (const p of pairs) {
      block(p.was, p.now, A.block(p.was), B.block(p.now),
        p.was ? ref.lines[p.was - 1] : '', p.now ? cur.lines[p.now - 1] : '', p.edited);
      if (p.now) lastNow = p.now;
    }
    group = null;
    for (const [key, mb] of B.others) block(A.others.has(key) ? key : '', key, A.others.get(key) || NONE, mb, '', '');
    for (const [key, ma] of A.others) if (!B.others.has(key)) block(key, '', ma, NONE, '', '');
    return {entries, differ, quiet, capped};
  }

  // ---- the tab ----
  function create(o) {
    const $ = (id) => document.getElementById(id);
    const select = $('cmp-with'), draw = $('cmp-draw');
    const state = {source: '', label: '', running: false, count: 0, same: false, entries: [], note: '', text: null, drawn: 0,
      highlighted: {now: [], was: []}, error: ''};
    let ref = null, kept = null, picked = null, cur = null, seq = 0, chosen = '';
    const requestKey = () => JSON.stringify(Object.assign({}, o.request(), {program: null, name: null}));
    const status = (text, cls) => { $('cmp-status').textContent = text; $('cmp-status').className = 'wb-hint ' + (cls || ''); };

    // the other run as the plot takes it, and its grey layer
    function setRef(r) {
      ref = r;
      if (r) {
        r.lines = r.lines || linesOf(r.text);
        r.conv = r.moves ? NcurveAnswer.movesForPlot(r.moves, r.profile) : null;
        r.other = r.conv ? NcurveBackplotCompare.create(r.conv) : null;
      }
      Object.assign(state, {source: r ? r.source : '', label: r ? r.label : ''});
      o.onDraw();
      compute();
    }
    // a program's text run as the editor's is (its machine, Settings), moves only
    async function runRef(r) {
      const my = ++seq;
      r.key = requestKey();
      state.running = true;
      status(`running ${r.name}…`);
      let res, j;
      try {
        res = await fetch('/api/run', {method: 'POST', headers: {'Content-Type': 'application/json'},
          body: JSON.stringify(Object.assign(o.request(), {program: r.text, name: r.name, format: 'binary'}))});
        j = await NcurveAnswer.read(res);
      } catch (e) { j = {error: `the server did not answer: ${e.message}`}; }
      if (my !== seq) return;
      status('');
      state.running = false;
      r.error = j.summary ? '' : `${res ? res.status + ': ' : ''}${j.error}`;
      Object.assign(r, j.summary ? {moves: j.moves, files: j.files, summary: j.summary, profile: j.profile || o.profile()} : {moves: null});
      setRef(r);
    }
    function choose(value) {
      chosen = select.value = value;
      seq++;
      state.running = false;
      status('');
      if (!value) setRef(null);
      else if (value === 'kept') setRef(kept);
      else if (value === 'picked') runRef(picked);
      else fromServer(value.slice(5));
    }
    async function fromServer(fileName) {
      const my = seq;
      state.running = true;
      let text;
      try {
        const r = await fetch('/api/files/' + encodeURIComponent(fileName));
        text = await r.text();
        if (!r.ok) throw new Error(JSON.parse(text).error);
      } catch (e) {
        if (my === seq) status(`${fileName}: ${e.message}`, 'alarm'), state.running = false;
        return;
      }
      if (my === seq) runRef({source: 'file', name: fileName, label: fileName, text});
    }
    select.onchange = () => {
      if (select.value !== 'local') { choose(select.value); return; }
      select.value = chosen;  // until a file is read
      $('cmp-file').value = '';
      $('cmp-file').click();
    };
    $('cmp-file').onchange = async () => {
      const f = $('cmp-file').files[0];
      if (!f) return;
      const text = await f.text();
      if (!/[^\s%]/.test(text)) { status(`${f.name}: the file holds no program`, 'alarm'); return; }
      picked = {source: 'local', name: f.name, label: `${f.name} (this computer)`, text};
      option('picked', picked.label);
      choose('picked');
    };
    // an entry of the menu, before "a file of this computer…"
    function option(value, text) {
      let opt = [...select.options].find((x) => x.value === value);
      if (!opt) select.add(opt = new Option('', value), value === 'kept' ? 1 : select.options.length - 1);
      opt.text = text;
    }
    $('cmp-keep').onclick = () => {
      if (!cur || cur.none) { status('no run to keep', 'alarm'); return; }
      const p = o.profile(), t = new Date().toTimeString().slice(0, 8);
      kept = Object.assign({}, cur, {source: 'kept', label: `the run kept at ${t} (${cur.name})`,
        profile: {lathe: p.lathe, diameter: p.diameter, rotary: p.rotary}});
      option('kept', kept.label);
      choose('kept');
    };
    draw.onchange = () => o.onDraw();

    // the list made while the tab is shown, else when it is opened (a big run takes a while to compare)
    let stale = false;
    function compute() {
      stale = $('tab-compare').hidden;
      if (!stale) list();
    }
    function list() {
      const box = $('cmp-list'), count = $('cmp-count');
      box.textContent = '';
      Object.assign(state, {count: 0, same: false, entries: [], note: '', text: cur ? cur.text : null, error: ''});
      state.highlighted = {now: [], was: []};
      if (!ref) { count.textContent = 'Keep this run, then edit the program: the blocks whose moves change are listed here. Or compare with another program.'; return; }
      if (ref.error || !ref.moves) { count.textContent = ''; state.error = ref.error || 'running…'; status(state.error, ref.error ? 'alarm' : ''); return; }
      if (!cur || cur.none) { count.textContent = 'no program in the editor'; return; }
      const res = compareRuns(ref, cur);
      const notes = [];
      if (res.quiet) notes.push(`${res.quiet} edited line${res.quiet === 1 ? ' makes' : 's make'} no move`);
      if (res.capped) notes.push(`the texts differ in over ${MAX_EDITS} lines: their middles are paired line by line`);
      for (const [r, who] of [[ref, ref.label], [cur, 'this run']]) {
        const a = r.summary && r.summary.alarm;
        if (a) notes.push(`${who} stopped at ALARM ${a.code} line ${a.line}`);
        if (!r.moves.complete) notes.push(`${who}: ${r.moves.message}`);
      }
      Object.assign(state, {count: res.differ, same: !res.differ, note: notes.join('; '),
        entries: res.entries.map((e) => ({kind: e.kind, was: e.was, now: e.now, text: e.text, old: e.old, what: e.what, shift: e.shift,
          after: e.after.map((x) => ({was: x.was, now: x.now, text: x.text}))}))});
      count.textContent = (res.differ ? `${res.differ} block${res.differ === 1 ? ' differs' : 's differ'} from ${ref.label}`
        : `the same moves as ${ref.label}`) + (notes.length ? ` (${state.note})` : '');
      if (res.differ) rows(box, res.entries);
    }
    // the table: a row per entry, the blocks moved with it folded under a row of their own
    function rows(box, entries) {
      const head = el('tr');
      [['was', `its line in ${ref.label}`], ['now', 'its line in the editor'], ['block', ''], ['what differs', '']].forEach(([h, title]) => {
        const th = el('th', '', h);
        th.title = title;
        head.append(th);
      });
      box.append(head);
      const note = (text) => {
        const tr = el('tr', 'fold'), td = el('td', '', text);
        td.colSpan = 4;
        tr.append(td);
        box.append(tr);
        return tr;
      };
      const row = (e, cls) => {
        const tr = el('tr', cls);
        tr.append(el('td', 'num', String(e.was || '—')), el('td', 'num', String(e.now || '—')));
        const code = el('td', 'code', e.text);
        if (e.old !== undefined) code.title = `was: ${e.old}`;
        const what = el('td', 'what');
        if (e.kind !== 'changed') what.append(el('span', 'badge', e.kind));
        what.append(document.createTextNode(e.what));
        tr.append(code, what);
        tr.onclick = () => pick(e, tr);
        box.append(tr);
        return tr;
      };
      // at most MAX_ROWS entries, and as many blocks of each group
      entries.slice(0, MAX_ROWS).forEach((e) => {
        row(e, e.kind);
        if (!e.after.length) return;
        const n = e.after.length, fold = note(`and ${n} block${n === 1 ? '' : 's'} after it, each moved by the same offset ${e.shift} (show)`);
        const members = e.after.slice(0, MAX_ROWS).map((x) => row(Object.assign({}, x, {what: `moved by ${e.shift}`}), 'changed moved'));
        if (n > MAX_ROWS) members.push(note(`… and ${n - MAX_ROWS} more moved so`));
        for (const tr of members) tr.hidden = true;
        fold.onclick = () => {
          const open = members[0].hidden;
          for (const tr of members) tr.hidden = !open;
          fold.firstChild.textContent = fold.textContent.replace(/\((show|hide)\)$/, open ? '(hide)' : '(show)');
        };
      });
      const left = entries.slice(MAX_ROWS).reduce((n, e) => n + 1 + e.after.length, 0);
      if (left) note(`… and ${left} more block${left === 1 ? '' : 's'} that differ, not listed`);
    }
    // an entry clicked: its line selected in the editor, its moves highlighted (magenta now, dark
    // grey as they were)
    function pick(e, tr) {
      for (const x of tr.parentNode.querySelectorAll('tr.on')) x.classList.remove('on');
      tr.classList.add('on');
      if (typeof e.at === 'number' && e.at) o.editor.selectLine(Math.min(e.at, o.editor.lineCount()));
      const inPlot = (conv, list) => Array.from(list, (i) => conv.before[i]).filter((j, k) => j < conv.count && conv.moveOf[j] === list[k]);
      const now = inPlot(cur.conv, e.movesNow), was = ref.conv ? inPlot(ref.conv, e.movesWas) : [];
      o.highlight(now);
      if (ref.other) ref.other.highlight(was, o.plot());
      state.highlighted = {now, was, line: e.at || 0};
    }

    return {
      state,
      shown() { if (stale) compute(); },
      setPrograms(names) { for (const n of names) option('file:' + n, n); },
      // the box the views fit besides the plot's own moves; undefined without a run drawn
      frame: (conv) => (draw.checked && ref && ref.other && ref.conv.lathe === conv.lathe ? ref.other.frame || undefined : undefined),
      drawIn(plot) {
        state.drawn = 0;
        if (!draw.checked || !ref || !ref.other) return;
        ref.other.drawIn(plot);
        ref.other.highlight(state.highlighted.was);
        state.drawn = ref.other.segments();
      },
      // the run shown: compared, a program run again first when the machine or Settings changed
      update(answer, name, conv) {
        cur = {text: answer.program, lines: linesOf(answer.program), name, moves: answer.moves, files: answer.files,
          summary: answer.summary, conv, none: !!answer.none};
        if (ref && ref.source !== 'kept' && ref.text !== undefined && ref.key !== requestKey()) runRef(ref);
        compute();
      },
    };
  }

  global.NcurveCompare = {create, align, compareRuns};
})(window);
