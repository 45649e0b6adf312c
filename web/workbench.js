// The workbench page of `ncurve serve` (docs/serve.md): the editor (wb-editor.js) runs the program
// through POST /api/run on each edit (quick edits together); the answer's moves go to the backplot
// (backplot.js), its diagnostics to the editor, its summary to the panel, its trace to the debugger
// (wb-debug.js), and what differs from another run to the Compare tab (wb-compare.js). Every text
// of the program or the server goes in as textContent.
// window.ncurveWorkbench tells a test what is shown.
(function () {
  'use strict';
  const $ = (id) => document.getElementById(id);
  const {el, fmt} = NcurveDom;
  const DIM = [214, 219, 226];

  const W = window.ncurveWorkbench = {ready: false, runs: 0, refusals: 0, moveCount: 0, diagnostics: [], timing: {}, pos: 0, error: null,
    // what is shown is the run of the text in the editor, and no run is waiting
    settled: () => W.shownText === editor.text && !timer};
  let profiles = [], answer = null, conv = null, plot = null, trace = null, mainFile = 0, viewName = '', measuring = false;
  const breakpoints = new Set();
  let tab = 'summary', name = 'program.nc', dirtyAnalysis = true;

  const editor = W.editor = NcurveEditor.create($('editor'), {
    onChange() { schedule(); dirtyAnalysis = true; files.noteEdit(); files.storeSoon(); },
    onCursorLine(line) { showLineMoves(line); },
    onGutterClick(line) {
      if (breakpoints.has(line)) breakpoints.delete(line); else breakpoints.add(line);
      editor.setBreakpoints(breakpoints);
    },
  });

  // ---- running ----
  // an edit after a quiet spell runs at once; the edits that follow it within 300 ms of each other
  // run together 300 ms after the last
  let timer = 0, seq = 0, inFlight = null, lastEdit = -Infinity;
  function schedule() {
    clearTimeout(timer);
    timer = 0;
    const now = W.timing.edit = performance.now(), quiet = now - lastEdit > 300;
    lastEdit = now;
    if (quiet) run(); else timer = setTimeout(run, 300);
  }
  const profile = () => profiles.find((p) => p.name === $('machine').value) || {};
  // what each run of the editor's program sends: its text and name, the machine, the Settings
  // (wb-settings.js), and while a generated cycle is in the editor the parameters gen says to set for it
  const programRequest = () => Object.assign({program: editor.text, name, machine: $('machine').value || undefined},
    settings.request(name === GENERATED && genRef ? Object.entries(genRef.param).map(([k, v]) => `${k}=${v}`) : []));
  // the Settings' key of the machine chosen: a shipped profile's name, '' (the server's), a file's name
  const machineKey = () => (profile().file ? 'file:' + profile().file : $('machine').value);
  // what the server runs a request naming no machine on, when that is not a shipped profile
  // (serve --machine FILE, or no --machine: the factory-parameter mill of `ncurve run`): the first
  // choice, sent as no "machine" at all
  function serverProfile(p) {
    profiles.push(Object.assign({}, p, {name: ''}));
    const text = p.factory ? `${p.title} (ncurve run's default)`
      : `${p.path} — ${p.title || p.error} (serve --machine)`;
    $('machine').add(new Option(text, '', true, true), 0);
  }
  async function run() {
    clearTimeout(timer);
    timer = 0;
    const my = ++seq, t0 = performance.now();
    if (inFlight) inFlight.abort();
    inFlight = null;
    if (!hasProgram()) { showNoProgram(t0); return; }
    const own = settings.refused('');  // a Setting the page refuses itself, in the command line's words: no request
    if (own) { status(own, 'alarm'); W.refusals++; return; }
    inFlight = new AbortController();
    status('running…', '');
    let r, j;
    // the moves first, drawn as soon as they come; the trace (Debugger) by a second request after
    let extras;
    try {
      extras = await part.extras(name);
    } catch (e) {  // the design field
      if (my === seq) status(`design: ${e.message}`, 'alarm');
      return;
    }
    const request = Object.assign(programRequest(), {format: 'binary'}, extras);
    if (my !== seq) return;
    try {
      r = await fetch('/api/run', {method: 'POST', headers: {'Content-Type': 'application/json'}, signal: inFlight.signal,
        body: JSON.stringify(request)});
      const t1 = performance.now();
      j = await NcurveAnswer.read(r);
      W.timing.request_ms = t1 - t0, W.timing.parse_ms = performance.now() - t1;
    } catch (e) {
      if (my === seq) status(`the server did not answer: ${e.message}`, 'alarm');
      return;
    }
    if (my !== seq) return;
    if (!j.summary) { settings.refused(j.error); status(`${r.status}: ${j.error}`, 'alarm'); W.refusals++; return; }
    answer = j;
    answer.program = request.program;
    if (profile().file && j.profile) Object.assign(profile(), j.profile);  // a file's kind, as the server read it
    settings.showProfile(profile(), machineKey());
    const wantTrace = $('trace').checked;
    show(t0, wantTrace);
    if (!wantTrace) return;
    inFlight = new AbortController();
    let t;
    try {
      r = await fetch('/api/run', {method: 'POST', headers: {'Content-Type': 'application/json'}, signal: inFlight.signal,
        body: JSON.stringify(Object.assign(request, {moves: false, trace: true}))});
      t = await NcurveAnswer.read(r);
    } catch (e) {
      if (my === seq) status(`the server did not answer for the trace: ${e.message}`, 'alarm');
      return;
    }
    if (my !== seq) return;
    if (t.trace) answer.trace = NcurveAnswer.traceInFiles(t.trace, t.files, answer.files);
    setupTrace();
    W.timing.trace_ms = performance.now() - t0;
    W.shownText = answer.program;
    W.runs++;
  }
  // an editor of blanks and % holds no program (the server would answer 400): an empty plot and a
  // calm note, and nothing asked of the server
  const hasProgram = () => /[^\s%]/.test(editor.text);
  const NO_MOVES = {count: 0, complete: true, kinds: ['rapid', 'line', 'arc', 'dwell'], kind: [], file: [], line: [],
    x: [], y: [], z: [], f: [], starts: {index: [], x: [], y: [], z: []},
    arcs: {index: [], cx: [], cy: [], cz: [], plane: [], cw: [], sweep_deg: []}, codes: {index: [], code: []}};
  function showNoProgram(t0) {
    answer = {program: editor.text, none: true, files: [name], diagnostics: [], moves: NO_MOVES,
      summary: {ok: false, alarm: null, motions: 0, none: true}};
    show(t0, false);
  }
  function status(text, cls) {
    $('status').textContent = text;
    $('status').className = 'wb-status ' + (cls || '');
  }

  // the part (wb-part.js): its setup is NAME.setup.toml among the server's files, or the example's
  const part = NcurvePart.create({
    checkbox: $('part'),
    design: $('design'),
    setupUrl: (n) => (n === 'spiral.nc' && example.name === n && !fileNames.includes(n) ? '/assets/example.setup.toml'
      : fileNames.includes(NcurvePart.setupName(n)) ? '/api/files/' + encodeURIComponent(NcurvePart.setupName(n))
      : null),
    request: programRequest,
    onPart: showPart,
  });
  function showPart(p, summary, moves) {
    if (!plot) return;
    plot.setPart(p ? NcurveBackplot.decodePart(p) : null);
    const v = summary && summary.verify;
    W.part = {triangles: plot.state().part, moves, volume: v && v.verified ? v.volume_removed_mm3 : null,
      findings: v && v.verified ? v.findings.length : null, refused: v && !v.verified ? v.refused : null,
      curve: v && v.curve ? v.curve : null, deviated: plot.state().partDeviation};
  }
  $('part').onchange = run;
  $('design').onchange = () => { if ($('part').checked) run(); };

  // ---- showing an answer ----
  function show(t0, traceToCome) {
    const t1 = performance.now();
    const p = profile();
    mainFile = Math.max(0, answer.files.indexOf(name));
    conv = NcurveAnswer.movesForPlot(answer.moves, p);
    const s = answer.summary;
    if (s.alarm) conv.alarmAt = conv.last;
    const t2 = performance.now();
    drawPlot();
    const t3 = performance.now();  // drawn at the next frame
    editor.setDiagnostics(answer.diagnostics.map((d) => Object.assign({}, d, {message: d.message + NcurveDiagnostics.pointer(d)})));
    showDiagnostics();
    // the machine and Settings the program's comments ask for, when others (wb-runline.js)
    W.runLine = NcurveRunLine.show($('runline'), {text: answer.program, machine: $('machine').value, settings,
      shipped: profiles.filter((x) => x.name && !x.file).map((x) => x.name), onUse(n) { $('machine').value = machineShown = n; machineChanged(); }});
    showSummary();
    if (!traceToCome) setupTrace();
    else $('dbg-pos').textContent = 'the trace is coming…';
    showLineMoves(editor.cursorLine());
    colour.showReference();
    colour.apply();
    compare.update(answer, name, conv);
    const t4 = performance.now();
    Object.assign(W.timing, {convert_ms: t2 - t1, draw_ms: t3 - t2, panels_ms: t4 - t3, run_to_drawn_ms: t4 - t0,
      edit_to_drawn_ms: W.timing.edit ? t4 - W.timing.edit : null, drawn_at: t4});
    W.timing.edit = 0;
    if (!traceToCome) W.shownText = answer.program, W.runs++;
    W.moveCount = conv.count, W.diagnostics = answer.diagnostics;
    W.summary = s;
    W.ready = true;
    const result = s.ok ? 'completed' : s.alarm ? `ALARM ${s.alarm.code} line ${s.alarm.line}` : 'stopped';
    W.name = name;
    if (s.none) status('no program', '');
    else status(`${result} · ${s.motions} motions · ${fmt(W.timing.run_to_drawn_ms, 0)} ms`, s.ok ? 'ok' : 'alarm');
    if (tab === 'analyze') analyze();
  }

  // the plot of the answer's moves, with the compared run under them (wb-compare.js)
  function drawPlot() {
    let renderer;
    if (plot) {  // the view kept, but a change to or from a lathe takes the machine's default view
      viewName = plot.moves.lathe === conv.lathe ? plot.state().view || viewName : '';
      measuring = plot.measure.on;  // the Measure tool stays on, its points go with the old path
      $('hover').hidden = true;  // the old path's
      renderer = plot.dispose({keepRenderer: true});
    }
    const s = answer.summary;
    plot = W.plot = NcurveBackplot.create($('plot'), conv, {
      renderer,
      onHover, onClick, measure: measuring, measureWhere: whereOf,
      view: viewName || undefined,
      alarmLabel: s.alarm ? `${s.alarm.code} line ${s.alarm.line}` : '',
      frame: compare.frame(conv),
    });
    compare.drawIn(plot);
    showPart(answer.part || null, s, Infinity);
    buildViews();
  }
  // the compared run drawn again (shown or hidden, another run): the plot made anew to fit it
  const compare = NcurveCompare.create({request: programRequest, profile, editor,
    plot: () => plot,
    highlight(list) { W.highlighted = list; plot.highlight(list); },
    onDraw() {
      if (!answer) return;
      drawPlot();
      showLineMoves(editor.cursorLine());
      colour.showReference();
      colour.apply();
      if (tab === 'debug') goTo(W.pos);
    }});
  W.compare = compare.state;

  function buildViews() {
    const box = $('views');
    box.textContent = '';
    const labels = {top: 'Top', front: 'Front', side: 'Side', iso: 'Iso', zx: 'ZX', end: 'End'};
    const mark = () => { for (const b of box.children) b.classList.toggle('active', b.dataset.view === plot.state().view); };
    for (const v of plot.views) {
      const b = el('button', '', labels[v] || v);
      b.dataset.view = v;
      b.onclick = () => { plot.setView(v); viewName = v; mark(); };
      box.append(b);
    }
    const fit = el('button', '', 'Fit');
    fit.title = 'the cuts in the current view';
    fit.onclick = () => { plot.fit(); mark(); };
    const all = el('button', '', 'Fit all');
    all.title = 'every move in the current view, the rapids to and from home too';
    all.onclick = () => { plot.fitAll(); mark(); };
    box.append(fit, all, plot.measure.button());
    plot.controls.addEventListener('change', mark);
    mark();
  }
  const kindName = (i) => ['rapid', 'feed', 'arc'][conv.kind[i]];
  function onHover(i) {
    const tip = $('hover');
    if (i < 0) { tip.hidden = true; return; }
    tip.textContent = '';
    const f = conv.file[i], line = conv.line[i];
    const where = `${answer.files[f] || '?'} line ${line}`;
    tip.append(el('div', 'where', where));
    if (f === mainFile) tip.append(el('code', 'block', editor.lineText(line)));
    tip.append(el('div', 'what', `move ${conv.moveOf[i] + 1} · ${kindName(i)}${conv.kind[i] ? ' F' + fmt(conv.feed[i]) : ''} · to ${endText(i)}`));
    tip.hidden = false;
    placeTip();
  }
  // the hover tip beside the pointer (below right, else where there is room), kept inside the plot
  let pointer = [0, 0];
  $('plot').addEventListener('pointermove', (e) => {
    const r = $('plot').getBoundingClientRect();
    pointer = [e.clientX - r.left, e.clientY - r.top];
    if (!$('hover').hidden) placeTip();
  });
  function placeTip() {
    const tip = $('hover'), box = $('plot'), W = box.clientWidth, H = box.clientHeight;
    const w = tip.offsetWidth, h = tip.offsetHeight, gap = 16, [px, py] = pointer;
    let x = px + gap, y = py + gap;
    if (x + w > W - 4) x = px - gap - w;
    if (y + h > H - 4) y = py - gap - h;
    tip.style.left = Math.max(4, Math.min(x, W - w - 4)) + 'px';
    tip.style.top = Math.max(4, Math.min(y, H - h - 4)) + 'px';
  }
  // a move's end as the program writes it: a lathe's X and Z (X a diameter where programmed so),
  // then the A, B, C axes the run moved (not drawn), as `run --html` gives them
  function endText(i) {
    const e = [conv.end[3 * i], conv.end[3 * i + 1], conv.end[3 * i + 2]];
    let text = conv.lathe ? `X${fmt(conv.diameter ? 2 * e[0] : e[0])} Z${fmt(e[2])}` : `X${fmt(e[0])} Y${fmt(e[1])} Z${fmt(e[2])}`;
    conv.rotary.forEach((r, k) => { text += ` ${r.axis}${fmt(conv.rotaryEnd[k * conv.count + i])}`; });
    return text;
  }
  // a move's block as the Measure readout names it: its N number, file (if not the program's) and line
  function whereOf(i) {
    const f = conv.file[i], line = conv.line[i], nr = f === mainFile ? /^\s*(?:\/\d?\s*)?N(\d+)/i.exec(editor.lineText(line)) : null;
    return `${nr ? `block N${nr[1]} ` : ''}${f === mainFile ? '' : `${answer.files[f] || '?'} `}line ${line}`;
  }
  function onClick(i) {
    W.clicked = i;
    if (i < 0) { plot.highlight([]); return; }
    if (conv.file[i] === mainFile) editor.selectLine(conv.line[i]);
    showLineMoves(conv.line[i], conv.file[i]);
  }
  // the moves of a line, highlighted
  function showLineMoves(line, file) {
    if (!plot) return;
    if (file === undefined) file = mainFile;
    const list = [];
    for (let i = 0; i < conv.count; i++) if (conv.line[i] === line && conv.file[i] === file) list.push(i);
    W.highlighted = list;
    plot.highlight(list);
  }

  // the diagnostics under the editor (wb-diags.js)
  const showDiagnostics = () => NcurveDiagnostics.show($('diags'), {answer, name, onLine: (line) => editor.selectLine(line),
    onFinding(at) { plot.setTool(at); W.findingShown = at; }, onSettings: () => setTab('settings')});
  const showSummary = () => NcurveSummary.show($('summary'), answer, conv);

  // ---- the debugger ----
  function setupTrace() {
    trace = W.trace = answer.trace ? NcurveTrace.create(answer.trace) : null;
    const slider = $('dbg-slider');
    slider.max = trace ? trace.count : 0;
    if (!trace) { $('dbg-pos').textContent = answer.none ? 'no program' : 'no trace: tick Debugger above'; return; }
    if (!trace.complete) $('dbg-pos').title = trace.message || '';
    goTo(Math.min(W.pos, trace.count), true);
  }
  function goTo(k, quiet) {
    if (!trace) return;
    k = Math.max(0, Math.min(trace.count, k));
    W.pos = k;
    $('dbg-slider').value = k;
    const st = W.state = trace.at(k);
    $('dbg-pos').textContent = k < trace.count ? `block ${k + 1} of ${trace.count} · line ${st.line}` : `after the last block (${trace.count})`;
    if (tab !== 'debug' && quiet) return;
    editor.setCurrentLine(st.file === mainFile ? st.line : 0);
    // the path up to this instant, the rest dimmed; the tool where it is
    const cut = conv.before[Math.min(st.move, conv.before.length - 1)];
    W.drawnUpTo = cut;
    plot.highlight([]);
    plot.setColors((i) => (i >= cut ? DIM : null));
    const at = cut > 0 ? conv.end.subarray(3 * cut - 3, 3 * cut) : conv.count ? conv.start.subarray(0, 3) : null;
    plot.setTool(at ? Array.from(at) : null);
    // the tool in use there (wb-tool.js), drawn in the view
    const tool = W.tool = NcurveToolAtStep.show($('dbg-tool'), st, !!(answer.profile && answer.profile.lathe), at ? Array.from(at) : null);
    plot.setCutter(tool.cutter);
    part.step(cut);
    // the call stack, the modal state and the variables (wb-step.js)
    const shown = NcurveStepView.show({stack: $('dbg-stack'), modal: $('dbg-modal'), vars: $('dbg-vars')}, st,
      {trace, files: answer.files, profile: answer.profile, machine: profile()});
    W.vars = shown.vars;
    W.reads = shown.reads;
    W.readChanged = shown.readChanged;
  }
  const step = (d) => goTo(W.pos + d);
  const seek = (dir) => {
    const b = trace ? trace.seek(W.pos, dir, mainFile, breakpoints, watches) : -1;
    goTo(b >= 0 ? b : dir > 0 ? trace.count : 0);
    W.stoppedOnBreak = b >= 0;
  };
  $('dbg-back').onclick = () => step(-1);
  $('dbg-fwd').onclick = () => step(1);
  $('dbg-first').onclick = () => goTo(0);
  $('dbg-last').onclick = () => goTo(Infinity);
  $('dbg-next-break').onclick = () => seek(1);
  $('dbg-prev-break').onclick = () => seek(-1);
  $('dbg-slider').oninput = () => goTo(+$('dbg-slider').value);
  // the watches (wb-watch.js), checked on the machine with the Settings the program runs with
  const watches = NcurveWatch.create({request: programRequest}).list;
  W.goTo = goTo;
  // keys, with the Debugger tab open: F10 / Shift+F10 one block on / back and F5 / Shift+F5 on to the
  // next / back to the previous breakpoint anywhere (the editor too); ← → Home End elsewhere than in
  // the editor and the text fields (the slider moves itself on them)
  document.addEventListener('keydown', (e) => {
    if (tab !== 'debug' || !trace || e.ctrlKey || e.altKey || e.metaKey) return;
    const t = e.target instanceof Element ? e.target : null;
    const typing = t && t.closest('textarea, select, input:not([type=range]), [contenteditable]');
    let act = null;
    if (e.key === 'F10') act = () => step(e.shiftKey ? -1 : 1);
    else if (e.key === 'F5') act = () => seek(e.shiftKey ? -1 : 1);
    else if (!typing && !e.shiftKey && !(t && t.id === 'dbg-slider')) {
      act = {ArrowRight: () => step(1), ArrowLeft: () => step(-1), Home: () => goTo(0), End: () => goTo(Infinity)}[e.key] || null;
    }
    if (!act) return;
    e.preventDefault();
    act();
  });

  // ---- tabs, analyze, generate ----
  function setTab(t) {
    if (!$('tab-' + t)) return;
    tab = t;
    try { localStorage.setItem(TAB_KEY, t); } catch (e) { /* not kept */ }
    for (const b of document.querySelectorAll('.wb-tabs button')) b.classList.toggle('on', b.dataset.tab === t);
    for (const p of ['summary', 'debug', 'analyze', 'gen', 'settings', 'compare']) $('tab-' + p).hidden = p !== t;
    if (!plot) return;
    if (t === 'debug') goTo(W.pos);
    else { colour.apply(); plot.setTool(null); plot.setCutter(null); editor.setCurrentLine(0); }
    if (t === 'analyze' && dirtyAnalysis) analyze();
    if (t === 'compare') compare.shown();
  }
  for (const b of document.querySelectorAll('.wb-tabs button')) b.onclick = () => setTab(b.dataset.tab);
  W.setTab = setTab;
  // the tab open is kept in this browser across a reload
  const TAB_KEY = 'ncurve-workbench-tab';
  try { setTab(localStorage.getItem(TAB_KEY) || tab); } catch (e) { /* the first tab */ }
  async function analyze() {
    dirtyAnalysis = false;
    const box = $('analysis');
    if (!hasProgram()) { box.textContent = 'no program'; return; }
    box.textContent = 'computing…';
    const r = await fetch('/api/analyze', {method: 'POST', headers: {'Content-Type': 'application/json'},
      body: JSON.stringify(programRequest())});
    const a = W.analysis = await r.json();
    box.textContent = '';
    const fact = (k, v) => box.append(el('dt', '', k), el('dd', '', v));
    if (a.error) { fact('error', settings.refused(a.error) || a.error); return; }
    const s = (v) => (v === undefined ? '—' : `${fmt(v, 2)} s`);
    fact('cycle time', `${s(a.cycle_time_s)}${a.ok ? '' : ' (up to the alarm)'}`);
    fact('motion', s(a.motion_s));
    fact('waits', `${s(a.wait_s)} (${a.waits} waits, ${a.stops} exact stops)`);
    fact('settle', s(a.settle_s));
    fact('dwell', s(a.dwell_s));
    fact('at programmed feed', s(a.programmed_time_s));
    fact('feed', `mean ${fmt(a.mean_feed_mm_min, 0)} mm/min over ${fmt(a.feed_length_mm)} mm`);
    fact('blocks', `${a.nc_blocks} NC blocks, ${a.macro_statements} macro statements, ${a.starved_blocks} starved`);
  }
  $('analyze').onclick = analyze;
  // the curves of `ncurve gen --list` (GET /api/curves) and their fields (wb-gen.js), then an expression
  const genFields = NcurveGen.create();
  $('gen').onclick = async () => {
    const fail = (text) => { $('gen-error').textContent = text; $('gen-out').textContent = ''; };
    $('gen-error').textContent = '';
    $('gen-warnings').textContent = '';
    const machine = $('machine').value;
    let request;
    try { request = genFields.request(machine); } catch (e) { fail(e.message); return; }
    // generated for, and measured on, the control the page runs on: its parameters and tool offsets
    const control = settings.request();
    Object.assign(request, {param: control.param, tool_offsets: control.tool_offsets});
    let r, g;
    try {
      r = await fetch('/api/gen', {method: 'POST', headers: {'Content-Type': 'application/json'}, body: JSON.stringify(request)});
      g = await r.json();
    } catch (e) { fail(`the server did not answer: ${e.message}`); return; }
    for (const w of g.warnings || []) $('gen-warnings').append(el('li', '', `warning: ${w}`));
    if (g.error || !g.program) { settings.refused(g.error); fail(`${r.status}: ${g.error || 'no program'}`); return; }
    const param = g.parameters || {}, set = Object.keys(param).map((k) => `No.${k} = ${param[k]}`).join(', ');
    $('gen-out').textContent = `max deviation ${fmt(g.max_deviation, 6)} mm (tolerance ${g.tolerance} mm), ` +
      `${g.move_deviation.index.length} moves on the curve; the curve in grey, ${g.reference.count} points: generated into the editor` +
      (set ? `, run here with ${set} (set it on the control)` : '');
    genRef = {text: g.program, machine, tol: g.tolerance, max: g.max_deviation, ref: g.reference, param,
      dev: new Map(g.move_deviation.index.map((i, k) => [i, g.move_deviation.mm[k]]))};
    openGenerated();
    colour.setMode('deviation');
    run();
  };
  // the generated program as the current one: its own entry in the Program menu, its name in the
  // diagnostics
  const GEN_FILE = '\u0000generated';
  function openGenerated() {
    const box = $('file');
    if (![...box.options].some((o) => o.value === GEN_FILE)) box.add(new Option(`${GENERATED} (generated)`, GEN_FILE), 0);
    box.value = GEN_FILE;
    loads++;
    name = GENERATED;
    editor.setText(genRef.text);
    genRef.text = editor.text;
    files.mark();
  }

  // ---- colour: by kind, by the feed reached or by the deviation from the generated curve (wb-colour.js) ----
  const GENERATED = 'generated.nc';
  let genRef = null;  // the last generated program: its text, machine, tolerance, curve and deviations
  const colour = NcurveColour.create({
    select: $('colour'), legend: $('legend'),
    now: () => ({plot, conv, answer, text: editor.text, request: programRequest(), profile: profile(), debugging: tab === 'debug',
      generated: genRef && name === GENERATED && genRef.machine === $('machine').value ? genRef : null,
      compared: W.compare.drawn ? W.compare.label : ''}),
    onColour(info) { W.colour = info; },
  });
  W.setColourMode = colour.setMode;

  // ---- start: the profiles, the files, the first program ----
  $('run').onclick = run;
  // a profile from a file: its TOML text is the option's value, sent as "machine" as a shipped name is
  const FROM_FILE = '\u0000file';
  let machineShown = '';
  $('machine').onchange = () => {
    if ($('machine').value !== FROM_FILE) { machineShown = $('machine').value; machineChanged(); return; }
    $('machine').value = machineShown;  // until a file is read
    $('machine-file').value = '';
    $('machine-file').click();
  };
  $('machine-file').onchange = async () => {
    const f = $('machine-file').files[0];
    if (!f) return;
    const text = await f.text();
    if (!text.trim()) { status(`${f.name}: the file is empty`, 'alarm'); return; }
    useMachineFile(f.name, text);
    machineChanged();
  };
  function machineChanged() {
    settings.showProfile(profile(), machineKey());
    files.store();
    run();
  }
  // a profile's TOML text from a file: its own entry in the selector, chosen
  function useMachineFile(fileName, text) {
    const box = $('machine');
    let o = [...box.options].find((x) => x.dataset.file);
    if (!o) {
      o = new Option('', '');
      o.dataset.file = '1';
      box.add(o, box.options.length - 1);
    }
    o.text = `${fileName} (file)`;
    o.value = text;
    profiles = profiles.filter((p) => !p.file).concat([{name: text, title: fileName, file: fileName}]);
    box.value = machineShown = text;
    W.machineFile = fileName;
  }
  $('trace').onchange = run;
  // the shipped example of a server given no FILE: a lathe's when its default machine is a lathe
  let example = {name: 'spiral.nc', url: '/assets/example.nc'};
  let fileNames = [];  // GET /api/files: the programs and their setups
  // (a file that comes after another program was loaded, new or pasted is not shown)
  let loads = 0;
  async function open(fileName) {
    const my = ++loads;
    const r = await fetch(fileName ? '/api/files/' + encodeURIComponent(fileName) : example.url);
    const text = await r.text();
    if (my !== loads) return;
    // a server file's edits kept in this browser come back (wb-files.js)
    const done = load(fileName ? files.opened(fileName, text) : text, fileName || example.name);
    files.mark();
    await done;
    files.store();
  }
  // a program into the editor, named so (in the diagnostics), and run
  function load(text, programName) {
    loads++;
    name = programName;
    for (const id of ['gen-error', 'gen-warnings', 'gen-out']) $(id).textContent = '';  // of the generated program
    editor.setText(text);
    breakpoints.clear();
    editor.setBreakpoints(breakpoints);
    W.pos = 0;
    return run();
  }
  // the files (wb-files.js): save, open, new, pasted, kept across a reload
  const files = W.files = NcurveFiles.create({editor, menu: $('file'), name: () => name, load,
    rename(n) { loads++; name = n; },
    machine: () => ({value: $('machine').value, file: profile().file ? {name: profile().file, text: $('machine').value} : null})});
  // the Settings tab (wb-settings.js): the command line's run options, with every run
  const settings = W.settings = NcurveSettings.create({note: $('settings-note'), onChange() { dirtyAnalysis = true; run(); }});
  $('settings-note').onclick = () => setTab('settings');
  $('file').onchange = () => {
    if ($('file').value === files.LOCAL) { files.choose(); return; }
    if ($('file').value !== GEN_FILE) { open($('file').value); return; }
    openGenerated();
    run();
  };
  W.open = open;
  (async () => {
    try {
      const [pj, fj, cj, lj] = await Promise.all(['/api/profiles', '/api/files', '/api/curves', '/api/libs'].map((u) => fetch(u).then((r) => r.json())));
      profiles = pj.profiles;
      for (const p of profiles) $('machine').add(new Option(`${p.name} — ${p.title}`, p.name, false, p.name === pj.default));
      if (!profiles.some((p) => p.name === pj.default)) serverProfile(pj.server);
      $('machine').add(new Option('from a file…', FROM_FILE));
      // the program and machine this browser had (wb-files.js), else the server's first file
      const saved = files.restored();
      if (saved && saved.machineFile) useMachineFile(saved.machineFile.name, saved.machineFile.text);
      else if (saved && [...$('machine').options].some((o) => o.value === saved.machine && o.value !== FROM_FILE)) $('machine').value = saved.machine;
      machineShown = $('machine').value;
      genFields.setCurves(cj);
      settings.setLibs(lj.libs);
      settings.showProfile(profile(), machineKey());
      fileNames = fj.files.map((f) => f.name);
      for (const f of fj.files) if (!f.name.endsWith('.setup.toml')) $('file').add(new Option(f.name, f.name));
      if (profile().lathe) example = {name: 'lathe-hyperbola.nc', url: '/assets/example-lathe.nc'};
      const programs = fileNames.filter((n) => !n.endsWith('.setup.toml'));
      compare.setPrograms(programs);
      if (!programs.length) $('file').add(new Option(`${example.name} (example)`, ''));
      if (saved && typeof saved.text === 'string') await files.restore(saved, programs.length ? programs : [''], open);
      else {  // the first program given, or one for this machine (wb-files.js), chosen in the menu
        const f = await files.first(programs, example.name, $('machine').value);
        if (f) $('file').value = f;
        await open(f);
      }
    } catch (e) {
      W.error = String(e);
      status(`cannot start: ${e.message}`, 'alarm');
    }
  })();
})();
