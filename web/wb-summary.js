// The workbench's Summary tab: the run's facts (result, machine, motions, blocks, path, time,
// extents, the axes not drawn, the part when Part is ticked, the warnings).
(function (global) {
  'use strict';
  const {el, fmt} = global.NcurveDom;

  // box: the <dl>; answer: POST /api/run's; conv: its moves as the plot has them
  function show(box, answer, conv) {
    const s = answer.summary;
    box.textContent = '';
    const fact = (k, v, cls) => box.append(el('dt', '', k), el('dd', cls || '', v));
    if (s.none) { fact('program', 'none: the editor holds no program'); return; }
    if (s.ok) fact('result', 'completed', 'ok');
    else if (s.alarm) fact('result', `ALARM ${s.alarm.code} ${s.alarm.file || ''} line ${s.alarm.line}: ${s.alarm.message}${global.NcurveDiagnostics.pointer(s.alarm)}`, 'alarm');
    else fact('result', 'stopped', 'alarm');
    // (a run stopped by its bounds, 422: its alarm above says so with the page's way to Max steps; the
    // answer's note on a request's "max_steps" is for other clients)
    if (answer.error && !s.alarm) fact('stopped', answer.error, 'alarm');
    fact('machine', s.machine);
    const mv = s.moves;
    fact('motions', `${s.motions} — ${mv.rapid} rapid, ${mv.line} feed, ${mv.arc} arc`);
    const events = Object.keys(mv).filter((k) => !['rapid', 'line', 'arc'].includes(k) && mv[k]).map((k) => `${mv[k]} ${k.replace('_', ' ')}`);
    if (events.length) fact('events', events.join(', '));
    fact('blocks', `${s.blocks_executed} executed of ${s.source_blocks} in the source`);
    fact('path', `${fmt(s.feed_length_mm)} mm at feed, ${fmt(s.rapid_length_mm)} mm rapid`);
    fact('time', `${fmt(s.time_at_programmed_feed_s, 1)} s at programmed feed (the Cycle time tab: with acceleration)`);
    if (s.extent) {
      const ax = Object.keys(s.extent).sort((a, b) => 'XYZABC'.indexOf(a) - 'XYZABC'.indexOf(b));
      // X a diameter where the profile the program ran on programs it so, marked as `ncurve run` marks it;
      // a rotary axis in degrees
      const dia = answer.profile && answer.profile.diameter, deg = (answer.profile && answer.profile.rotary) || '';
      fact('extents', ax.map((a) => `${a}${a === 'X' && dia ? '(dia)' : ''} ${fmt(s.extent[a][0])} … ${fmt(s.extent[a][1])}${deg.includes(a) ? '°' : ''}`).join('   '));
    }
    // the A, B, C axes the run moved: the drawing is of X, Y and Z
    if (conv.rotary.length) {
      const range = (r) => `${r.axis} ${fmt(r.min)} … ${fmt(r.max)}${r.unit === 'deg' ? '°' : ' mm'}`;
      fact('axes not drawn', `${conv.rotary.map(range).join('   ')} (the view shows X, Y and Z; hover a move for its end)`);
    }
    if (s.verify) {  // Part ticked: what was cut, or why nothing was
      const v = s.verify, n = v.verified ? v.findings.length + v.findings_left_out : 0;
      fact('part', v.verified ? `${fmt(v.volume_removed_mm3, 1)} mm³ removed from the ${v.stock_default ? 'box round the cuts' : 'setup\'s stock'}` +
        ` · ${n} finding${n === 1 ? '' : 's'} (listed under the editor)` + (v.setup ? ` · ${v.setup}` : '') : `not cut: ${v.refused}`);
    }
    fact('warnings', s.warnings.length ? s.warnings.map((w) => `${w.code} line ${w.line}: ${w.message}${global.NcurveDiagnostics.pointer(w)}`).join('\n') : 'none');
    if (!answer.moves.complete) fact('moves', answer.moves.message, 'alarm');
  }

  global.NcurveSummary = {show};
})(window);
