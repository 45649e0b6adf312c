// The page of `ncurve run --html`: the summary header, the backplot (backplot.js), the view
// buttons, the legend, and the block under the pointer. Every text of the program goes in
// through textContent, never as HTML. window.ncurveBackplot tells a test what is drawn.
(function () {
  'use strict';
  const t0 = performance.now();
  const summary = JSON.parse(document.getElementById('ncurve-summary').textContent);
  const data = JSON.parse(document.getElementById('ncurve-data').textContent);
  const moves = NcurveBackplot.decode(data);
  const tDecoded = performance.now();
  const files = data.files || [];
  const unit = data.inch ? 25.4 : 1, unitName = data.inch ? 'in' : 'mm';

  const el = (tag, cls, text) => {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined) e.textContent = text;
    return e;
  };
  const fmt = (v, digits) => (Math.abs(v) < 1e-12 ? 0 : v).toFixed(digits === undefined ? 3 : digits).replace(/\.?0+$/, '') || '0';

  // the source lines, split on first use
  const lines = [];
  const fileName = (f) => (f < files.length ? files[f].name : '?');
  const blockText = (f, line) => {
    if (!(f < files.length) || files[f].text == null) return '';
    if (!lines[f]) lines[f] = files[f].text.split('\n');
    const s = lines[f][line - 1];
    return s === undefined ? '' : s.replace(/\r$/, '');
  };
  const blockOf = (i) => {
    const b = moves.block[i];
    return {file: moves.blockFile[b], line: moves.blockLine[b]};
  };

  // the header
  const head = document.getElementById('summary');
  const title = el('div', 'title');
  title.append(el('h1', '', summary.source || 'program'), el('span', 'machine', summary.machine || ''));
  const result = el('div', summary.ok ? 'result ok' : 'result alarm');
  if (summary.ok) {
    result.textContent = 'completed';
  } else if (data.alarm) {
    const a = data.alarm;
    result.append(el('strong', '', `ALARM ${a.code}`),
      document.createTextNode(` ${a.file ? a.file + ' ' : ''}line ${a.line}: ${a.message}`));
    if (a.block) result.append(el('code', 'block', a.block.trim()));
  }
  title.append(result);
  head.append(title);
  const facts = el('dl', 'facts');
  // a name and its value in a box of their own: a row of the header wraps between facts, not inside one
  const fact = (name, value) => {
    const pair = el('div', 'fact');
    pair.append(el('dt', '', name), el('dd', '', value));
    facts.append(pair);
  };
  const kinds = {rapid: 0, feed: 0, arc: 0};
  for (let i = 0; i < moves.count; i++) kinds[NcurveBackplot.KIND_NAMES[moves.kind[i]]]++;
  fact('motions', `${summary.motions} — ${kinds.rapid} rapid, ${kinds.feed} feed, ${kinds.arc} arc`);
  fact('blocks', `${summary.blocks_executed} executed`);
  fact('path', `${fmt(summary.feed_length_mm / unit)} ${unitName} at feed, ${fmt(summary.rapid_length_mm / unit)} ${unitName} rapid`);
  fact('time', `${fmt(summary.time_at_programmed_feed_s, 1)} s at programmed feed`);
  if (summary.extent) {
    const order = axis => 'XYZABC'.indexOf(axis);  // JSON objects come with their keys sorted
    const axes = Object.entries(summary.extent).sort((a, b) => order(a[0]) - order(b[0]));
    const parts = axes.map(([axis, r]) => {
      const rotary = 'ABC'.includes(axis), u = rotary ? 1 : unit;
      const name = data.lathe && axis === 'X' ? (data.diameter ? 'X⌀' : 'X') : axis;
      return `${name} ${fmt(r[0] / u)} … ${fmt(r[1] / u)}${rotary ? '°' : ''}`;
    });
    fact(`extent, ${unitName}`, parts.join('   '));
  }
  if (summary.verify && summary.verify.verified) {
    const v = summary.verify;
    fact('part', `${fmt(v.volume_removed_mm3 / (unit * unit * unit))} ${unitName}³ removed · ${v.findings.length + v.findings_left_out} finding${v.findings.length + v.findings_left_out === 1 ? '' : 's'}`);
  } else if (summary.verify) {
    fact('part', `not verified: ${summary.verify.refused}`);
  }
  if (summary.warnings && summary.warnings.length) fact('warnings', summary.warnings.map((w) => `${w.code} line ${w.line}: ${w.message}`).join('; '));
  // the rotary (or other A, B, C) axes: the drawing is of X, Y and Z
  if (moves.rotary.length) {
    const range = (r) => `${r.axis} ${fmt(r.min / (r.unit === 'mm' ? unit : 1))} … ${fmt(r.max / (r.unit === 'mm' ? unit : 1))}${r.unit === 'deg' ? '°' : ' ' + unitName}`;
    fact('axes not drawn', `${moves.rotary.map(range).join('   ')} (the view shows X, Y and Z; hover a move for its end)`);
  }
  if (data.left_out) fact('not drawn', `${data.left_out} motions past the first ${moves.count} (the page's limit)`);
  head.append(facts);

  // the backplot
  const container = document.getElementById('plot');
  const tip = document.getElementById('tip');
  const selection = document.getElementById('selection');
  let pointer = [0, 0];
  container.addEventListener('pointermove', (e) => { pointer = [e.clientX, e.clientY]; placeTip(); });
  const placeTip = () => {
    const r = container.getBoundingClientRect();
    let x = pointer[0] - r.left + 16, y = pointer[1] - r.top + 16;
    if (x + tip.offsetWidth > r.width - 8) x = pointer[0] - r.left - tip.offsetWidth - 16;
    if (y + tip.offsetHeight > r.height - 8) y = pointer[1] - r.top - tip.offsetHeight - 16;
    tip.style.left = Math.max(4, x) + 'px';
    tip.style.top = Math.max(4, y) + 'px';
  };
  const KIND_TEXT = ['rapid (G00)', 'feed (G01)', 'arc (G02/G03)'];
  const describe = (box, i) => {
    box.replaceChildren();
    const b = blockOf(i);
    box.append(el('div', 'where', `${fileName(b.file)}:${b.line}`));
    const text = blockText(b.file, b.line);
    if (text) box.append(el('code', 'block', text.trim()));
    const e = moves.end.subarray(3 * i, 3 * i + 3);
    const xs = data.lathe && data.diameter ? 2 : 1;
    let end = data.lathe
      ? `X${fmt(e[0] * xs / unit)} Z${fmt(e[2] / unit)}`
      : `X${fmt(e[0] / unit)} Y${fmt(e[1] / unit)} Z${fmt(e[2] / unit)}`;
    moves.rotary.forEach((r, k) => {  // degrees, or a linear A, B, C in the page's unit
      end += ` ${r.axis}${fmt(moves.rotaryEnd[k * moves.count + i] / (r.unit === 'mm' ? unit : 1))}`;
    });
    const k = moves.kind[i];
    const feed = k === 0 ? '' : ` · F${fmt(moves.feed[i] / (data.inch ? unit : 1))}`;
    box.append(el('div', 'what', `move ${i + 1} of ${moves.count} · ${KIND_TEXT[k]}${feed} · to ${end}`));
  };
  const alarmLabel = data.alarm ? `${data.alarm.code} line ${data.alarm.line}` : '';
  // a move's block as the Measure readout names it: its N number, file and line
  const whereOf = (i) => {
    const b = blockOf(i), nr = /^\s*(?:\/\d?\s*)?N(\d+)/i.exec(blockText(b.file, b.line));
    return `${nr ? `block N${nr[1]} ` : ''}${files.length > 1 ? `${fileName(b.file)} ` : ''}line ${b.line}`;
  };
  let plot;
  try {
    plot = NcurveBackplot.create(container, moves, {
      alarmLabel, measureWhere: whereOf,
      onHover(i) {
        if (i < 0) { tip.hidden = true; return; }
        describe(tip, i);
        tip.hidden = false;
        placeTip();
      },
      onClick(i) {
        if (i < 0) { selection.hidden = true; plot.highlight([]); return; }
        const b = moves.block[i], same = [];
        for (let j = 0; j < moves.count; j++) if (moves.block[j] === b) same.push(j);
        plot.highlight(same);
        describe(selection, i);
        selection.prepend(el('div', 'label', `selected: ${same.length} move${same.length === 1 ? '' : 's'} of this block`));
        selection.hidden = false;
      },
    });
  } catch (err) {
    container.append(el('p', 'ncurve-noscript', `The backplot needs WebGL, which this browser did not give: ${err.message}`));
    window.ncurveBackplot = {ready: false, error: String(err), moveCount: moves.count};
    return;
  }

  if (data.part) plot.setPart(NcurveBackplot.decodePart(data.part));
  const tBuilt = performance.now();

  // view buttons
  const views = document.getElementById('views');
  const NAMES = data.lathe
    ? {zx: 'ZX', top: 'Top', end: 'End', iso: 'Iso'}
    : {top: 'Top', front: 'Front', side: 'Side', iso: 'Iso'};
  const buttons = {};
  for (const [name, label] of Object.entries(NAMES)) {
    const b = el('button', '', label);
    b.type = 'button';
    b.dataset.view = name;
    b.addEventListener('click', () => plot.setView(name));
    views.append(b);
    buttons[name] = b;
  }
  const fit = el('button', 'fit', 'Fit');
  fit.type = 'button';
  fit.title = 'the cuts in the current view';
  fit.addEventListener('click', () => plot.fit());
  const all = el('button', 'fit', 'Fit all');
  all.type = 'button';
  all.title = 'every move in the current view, the rapids to and from home too';
  all.addEventListener('click', () => plot.fitAll());
  views.append(fit, all, plot.measure.button());
  plot.onRender = () => {
    const v = plot.state().view;
    for (const [name, b] of Object.entries(buttons)) b.classList.toggle('active', name === v);
  };

  // legend
  const legend = document.getElementById('legend');
  const swatch = (svg, text) => {
    const item = el('span', 'item');
    item.innerHTML = `<svg width="28" height="12" viewBox="0 0 28 12" aria-hidden="true">${svg}</svg>`;  // fixed markup, no program text
    item.append(el('span', '', text));
    legend.append(item);
  };
  const hex = (c) => '#' + c.map((v) => v.toString(16).padStart(2, '0')).join('');
  const C = NcurveBackplot.KIND_COLORS;
  swatch(`<line x1="1" y1="6" x2="27" y2="6" stroke="${hex(C[0])}" stroke-width="2" stroke-dasharray="5 3"/>`, `rapid ${kinds.rapid}`);
  swatch(`<line x1="1" y1="6" x2="27" y2="6" stroke="${hex(C[1])}" stroke-width="2"/>`, `feed ${kinds.feed}`);
  swatch(`<line x1="1" y1="6" x2="27" y2="6" stroke="${hex(C[2])}" stroke-width="2"/>`, `arc ${kinds.arc}`);
  swatch('<circle cx="14" cy="6" r="4" fill="#111"/>', 'start');
  const holes = plot.state().holes.length;
  if (holes) swatch('<circle cx="14" cy="6" r="4.5" fill="none" stroke="#212121" stroke-width="1.5"/><path d="M14 0v12M8 6h12" stroke="#212121" stroke-width="1.5"/>', `holes ${holes}`);
  if (data.part) swatch('<rect x="2" y="1" width="24" height="10" fill="#d6d9de" stroke="#80858f"/>', 'part (cut stock)');
  if (data.part && data.part.deviation) {  // its walls against the design's curve
    const D = NcurveBackplot.DEVIATION_COLOURS, rgb = (c) => hex(c.map((v) => Math.round(255 * v)));
    const tol = data.part.deviation.tol;
    swatch(`<rect x="2" y="1" width="24" height="10" fill="${rgb(D.within)}"/>`, `wall within ±${tol} mm`);
    swatch(`<rect x="2" y="1" width="24" height="10" fill="${rgb(D.gouge)}"/>`, 'beyond the design (gouge)');
    swatch(`<rect x="2" y="1" width="24" height="10" fill="${rgb(D.left)}"/>`, 'short of it (stock left)');
  }
  if (data.alarm) swatch('<path d="M9 1l10 10M19 1L9 11" stroke="#d50000" stroke-width="2.5"/>', 'alarm');
  // under cutter compensation: the programmed contour beside the tool centre's path, a box to hide it
  const programmed = plot.state().programmed;
  if (programmed) {
    swatch(`<line x1="1" y1="6" x2="27" y2="6" stroke="${hex(NcurveBackplotProgrammed.COLOUR)}" stroke-width="2" stroke-dasharray="4 3"/>`,
      `programmed ${programmed.moves}`);
    const box = el('input');
    box.type = 'checkbox';
    box.checked = true;
    box.title = 'the contour as programmed; the path drawn is the tool centre\'s (cutter radius compensation)';
    box.addEventListener('change', () => plot.showProgrammed(box.checked));
    legend.lastChild.prepend(box);
  }
  swatch('<line x1="1" y1="6" x2="27" y2="6" stroke="#d81b60" stroke-width="2"/>', 'selected block');
  legend.append(el('span', 'hint', 'drag: rotate · right- or shift-drag: pan · wheel: zoom · click: a block · M: measure'));

  plot.render();
  const tDrawn = performance.now();

  // for tests and scripts: what is drawn
  window.ncurveBackplot = {
    ready: true,
    plot,
    summary,
    get moveCount() { return plot.state().moveCount; },
    get kinds() { return plot.state().kinds; },
    get segments() { return plot.state().segments; },
    get view() { return plot.state().view; },
    get camera() { return plot.state().camera; },
    get hovered() { return plot.state().hovered; },
    views: Object.keys(NAMES),
    screenOf: (i) => plot.screenOf(i),
    screenOfPoint: (p) => plot.screenOfPoint(p),
    lineOf: (i) => blockOf(i).line,
    timing: {scriptStartMs: t0, decodeMs: tDecoded - t0, buildMs: tBuilt - tDecoded, firstDrawMs: tDrawn - t0},
  };
})();
