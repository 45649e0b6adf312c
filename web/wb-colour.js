// The workbench's colour modes (docs/serve.md): the moves by kind, by the feed reached (POST
// /api/analyze "moves") or by the deviation from a generated curve (POST /api/gen), with the legend
// and its scale, and the generated curve drawn in grey under the path.
//   const colour = NcurveColour.create({select, legend, now() {...}, onColour(info) {}});
//   colour.apply();          // after a run, a change of tab or of the feeds: colour as the selector says
//   colour.setMode('deviation');
// now() tells what is shown: {plot, conv, answer, text, request, profile, debugging, generated,
// compared}, where generated is {text, tol, ref, dev} while the generated program (or an edit of it)
// is in the editor on the machine it was generated for, else null, and compared names the run drawn
// grey under the path (wb-compare.js), else ''.
(function (global) {
  'use strict';
  const GREY = [178, 184, 192];
  const RAMP = [[59, 76, 192], [40, 160, 220], [40, 175, 90], [235, 165, 20], [200, 30, 30]];
  const ramp = (u) => {
    u = Math.max(0, Math.min(1, u || 0)) * (RAMP.length - 1);
    const k = Math.min(RAMP.length - 2, Math.floor(u)), f = u - k, a = RAMP[k], b = RAMP[k + 1];
    return [0, 1, 2].map((c) => Math.round(a[c] + (b[c] - a[c]) * f));
  };
  const {el, fmt} = NcurveDom;

  function create(options) {
    const {select, legend, now} = options;
    let mode = select.value || 'kind', feeds = null, feedsWanted = null;

    function setMode(m) {
      mode = select.value = m;
      apply();
    }
    select.addEventListener('change', () => setMode(select.value));

    // the kinds' legend: a dashed or solid swatch and the count of each
    function kindLegend(plot) {
      const k = plot.state().kinds;
      legend.textContent = '';
      ['rapid', 'feed', 'arc'].forEach((nm, i) => {
        const c = NcurveBackplot.KIND_COLORS[i], item = el('span', 'item'), sw = el('span', '');
        sw.style.cssText = `display:inline-block;width:18px;height:0;border-top:2px ${i ? 'solid' : 'dashed'} rgb(${c.join(',')})`;
        item.append(sw, document.createTextNode(`${nm} ${k[nm]}`));
        legend.append(item);
      });
      const holes = plot.state().holes.length;
      if (holes) {  // the markers' ring and cross
        const item = el('span', 'item holes'), sw = el('span', '', '⊕');
        sw.style.cssText = 'font-size:15px;line-height:1;margin-right:4px';
        item.append(sw, document.createTextNode(`holes ${holes}`));
        legend.append(item);
      }
      programmedLegend(plot);
      legend.append(el('span', 'hint', 'click a move: its line · put the cursor on a line: its moves · M: measure'));
    }
    // the run compared with (wb-compare.js), drawn grey under the path
    function comparedLegend(name) {
      const item = el('span', 'item'), sw = el('span', '');
      sw.style.cssText = `display:inline-block;width:18px;height:0;border-top:2px solid rgb(${GREY.join(',')})`;
      item.append(sw, document.createTextNode(`compared: ${name}`));
      legend.insertBefore(item, legend.querySelector('.hint'));
    }
    // under cutter compensation: the programmed contour (dashed) beside the tool centre's path, a box
    // to hide it
    let programmedShown = true;
    function programmedLegend(plot) {
      const p = plot.state().programmed;
      if (!p) return;
      plot.showProgrammed(programmedShown);
      const item = el('label', 'item wb-programmed'), box = el('input'), sw = el('span', '');
      box.type = 'checkbox';
      box.checked = programmedShown;
      box.onchange = () => { programmedShown = box.checked; plot.showProgrammed(programmedShown); };
      sw.style.cssText = `display:inline-block;width:18px;height:0;border-top:2px dashed rgb(${NcurveBackplotProgrammed.COLOUR.join(',')})`;
      item.title = 'the contour as programmed; the path drawn is the tool centre\'s (cutter radius compensation)';
      item.append(box, sw, document.createTextNode(` programmed ${p.moves}`));
      legend.append(item);
    }
    // the generated curve in grey under the path while the generated program is in the editor
    function showReference() {
      const {plot, profile, generated} = now();
      if (!plot) return;
      let pts = null;
      if (generated) {
        const R = generated.ref, xs = profile.diameter ? 0.5 : 1;
        pts = new Float32Array(3 * R.count);
        for (let i = 0; i < R.count; i++) pts[3 * i] = R.x[i] * xs, pts[3 * i + 1] = R.y[i], pts[3 * i + 2] = R.z[i];
      }
      plot.setReference(pts);
    }
    function feedData(request) {  // the feeds of the program in the editor; null while they are asked for
      const key = JSON.stringify(request);
      if (feeds && feeds.key === key) return feeds;
      if (feedsWanted !== key) {
        feedsWanted = key;
        fetch('/api/analyze', {method: 'POST', headers: {'Content-Type': 'application/json'},
          body: JSON.stringify(Object.assign({}, request, {moves: true}))})
          .then((r) => r.json()).then((a) => ({key, error: a.error || (a.moves ? '' : 'no moves'), moves: a.moves}),
            (e) => ({key, error: e.message}))
          .then((f) => { if (feedsWanted === key) { feeds = f, feedsWanted = null; apply(); } });
      }
      return null;
    }
    // colours the moves as the selector says (not while the debugger draws the path up to the tool)
    function apply() {
      const s = now();
      if (!s.plot) return;
      kindLegend(s.plot);
      if (s.debugging) { if (s.compared) comparedLegend(s.compared); return; }
      let info = {mode, coloured: 0, note: ''};
      if (mode === 'feed') info = byFeed(info, s);
      else if (mode === 'deviation') info = byDeviation(info, s);
      if (!info.scale) s.plot.setColors();
      if (info.scale || info.note) scaleLegend(info);
      if (s.compared) comparedLegend(s.compared);
      if (options.onColour) options.onColour(info);
    }
    function byFeed(info, {plot, conv, answer, request}) {
      if (answer.none) return Object.assign(info, {note: 'feed reached: no program'});
      const f = feedData(request);
      if (!f) return Object.assign(info, {note: 'feed reached: computing…'});
      const M = f.moves;
      if (f.error || M.count !== answer.moves.count)
        return Object.assign(info, {note: `feed reached: ${f.error || 'the cycle time run made other moves'}; coloured by kind`});
      let top = 0;
      for (let j = 0; j < conv.count; j++) if (conv.kind[j]) top = Math.max(top, M.feed_programmed[conv.moveOf[j]]);
      if (!(top > 0)) return Object.assign(info, {note: 'feed reached: no moves at feed; coloured by kind'});
      const seen = new Set();
      let most = 0;
      plot.setColors((j) => {
        if (!conv.kind[j]) return GREY;
        const v = M.feed_peak[conv.moveOf[j]], c = ramp(v / top);
        info.coloured++, most = Math.max(most, v), seen.add(c.join());
        return c;
      });
      return Object.assign(info, {scale: {title: 'feed reached (the peak of each move)', max: top, unit: 'mm/min'},
        distinct: seen.size, most, grey: 'rapids grey'});
    }
    function byDeviation(info, {plot, conv, answer, text, generated: g}) {
      if (!g) return Object.assign(info, {note: 'deviation: for a program generated in the Generate tab; coloured by kind'});
      if (text !== g.text)
        return Object.assign(info, {note: 'deviation: the program was edited since it was generated; coloured by kind'});
      const K = answer.moves.kinds, LN = K.indexOf('line'), A = K.indexOf('arc');
      for (const i of g.dev.keys())
        if (i >= answer.moves.count || (answer.moves.kind[i] !== LN && answer.moves.kind[i] !== A))
          return Object.assign(info, {note: 'deviation: the run made other moves than gen measured; coloured by kind'});
      const seen = new Set();
      let most = 0;
      plot.setColors((j) => {
        const d = g.dev.get(conv.moveOf[j]);
        if (d === undefined) return GREY;
        const c = ramp(d / g.tol);
        info.coloured++, most = Math.max(most, d), seen.add(c.join());
        return c;
      });
      return Object.assign(info, {scale: {title: 'deviation from the curve', max: g.tol, unit: 'mm'},
        distinct: seen.size, most, grey: 'approach, retract and rapids grey; the curve in grey under the path'});
    }
    // the scale (five numbers from 0) in place of the kinds, or a note beside them
    function scaleLegend(info) {
      if (!info.scale) { legend.prepend(el('span', 'item', info.note)); return; }
      legend.textContent = '';
      const S = info.scale, ticks = [0, 0.25, 0.5, 0.75, 1].map((u) => u * S.max);
      const digits = Math.max(0, 2 - Math.floor(Math.log10(S.max)));
      info.ticks = ticks.map((v) => fmt(v, digits));
      const scale = el('span', 'wb-scale');
      const bar = el('span', 'bar');
      bar.style.background = `linear-gradient(to right, ${RAMP.map((c) => `rgb(${c.join(',')})`).join(', ')})`;
      const labels = el('span', 'ticks');
      for (const t of info.ticks) labels.append(el('span', '', t));
      scale.append(bar, labels);
      const most = mode === 'deviation' ? `max ${fmt(info.most, 6)} mm` : `highest ${fmt(info.most, 0)} mm/min`;
      legend.append(el('span', 'item', `${S.title}, ${S.unit}`), scale, el('span', 'item', most), el('span', 'hint', info.grey));
      programmedLegend(now().plot);
    }
    return {apply, setMode, showReference, get mode() { return mode; }};
  }

  global.NcurveColour = {create, ramp, RAMP};
})(window);
