// The debugger's tool at the step (docs/serve.md): the T in use; on a mill the D offset in force with
// its cutter radius and, under G43/G44, the H offset with its length; on a lathe the offset set, its
// nose radius and tip (the trace's "tool" and modal words). And the tool as the backplot draws it
// there (backplot-cutter.js): the cutter's circle about the tool centre, or the nose circle about
// the nose centre, the imaginary tip less the tip's offset.
//   const t = NcurveToolAtStep.show(box, state, lathe, at);  plot.setCutter(t.cutter);  t.words
(function (global) {
  'use strict';
  const {el, fmt} = global.NcurveDom;
  // the imaginary tip from the nose centre, per tip 0..9, in X and Z (machine::tip_direction)
  const TIP_X = [0, 1, 1, -1, -1, 0, 1, 0, -1, 0], TIP_Z = [0, 1, -1, -1, 1, 1, 0, -1, 0, 0];

  // state: NcurveTrace's at(k); at: where the tool is (X Y Z, X as a radius on a lathe) or null
  function show(box, state, lathe, at) {
    box.textContent = '';
    const modal = state.modal, tool = state.tool, word = (v) => modal.get(v);
    const T = word(4120), D = word(4107), H = word(4111), lengthComp = word(4008), side = word(4007);
    const words = [];
    const line = (label, text, title) => {
      const row = el('div', 'wb-tool-row');
      row.append(el('strong', '', label), document.createTextNode(' ' + text));
      if (title) row.title = title;
      box.append(row);
      words.push(`${label} ${text}`);
    };
    const t = T === null || T === undefined ? '—' : lathe ? String(T).padStart(4, '0') : fmt(T);
    line(`T${t}`, T ? 'in use' : '(no T yet)');
    let cutter = null;
    if (!tool) {
      box.append(el('div', 'wb-hint', 'the trace says nothing of the offsets'));
      return {words, cutter};
    }
    const compensating = side === 41 || side === 42;
    if (lathe) {
      const tip = tool.tip | 0;
      const how = `the offset set of the T code; ${compensating ? `G${side}` : 'G40'}: tool-nose radius compensation ${compensating ? 'on' : 'off'}`;
      line(`offset ${tool.offset}`, tool.offset ? `nose R ${fmt(tool.radius)} mm` : '(none in force)', how);
      if (tool.offset) line('tip', `${tip}${compensating ? ` (G${side})` : ''}`, 'the imaginary tool tip 0..9 (0 and 9: the nose centre)');
      if (at && tool.radius > 0) {
        const r = tool.radius, x = at[0] - (TIP_X[tip] || 0) * r, z = at[2] - (TIP_Z[tip] || 0) * r;
        cutter = {centre: [x, at[1], z], radius: r, plane: 18};
      }
    } else {
      line(`D${fmt(D || 0)}`, D ? `radius ${fmt(tool.radius)} mm${compensating ? ` (G${side})` : ' (G40: not offsetting)'}` : '(no radius offset)');
      if (lengthComp === 43 || lengthComp === 44) line(`H${fmt(H || 0)}`, `length ${fmt(tool.length)} mm (G${lengthComp})`);
      if (at && D && tool.radius > 0) {
        const plane = [17, 18, 19].includes(word(4002)) ? word(4002) : 17;
        cutter = {centre: [at[0], at[1], at[2]], radius: tool.radius, plane, height: 2.5 * tool.radius};
      }
    }
    return {words, cutter};
  }

  global.NcurveToolAtStep = {show};
})(window);
