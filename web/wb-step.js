// The debugger's panel at a step (docs/serve.md): the call stack (innermost first), the modal state
// (#4001.. as G codes, of the groups the machine's G-code system has, and its F M S T, D H on a mill),
// the variables (the locals of each level, the commons, the system variables written, those the last
// block changed marked) and the system variables read so far with the value each read last.
//   const shown = NcurveStepView.show({stack, modal, vars}, state, {trace, files, profile, machine});
//   shown.vars, shown.reads, shown.readChanged: what is shown, for a test
(function (global) {
  'use strict';
  const {el, fmt} = global.NcurveDom;
  // a G code as the control's screen shows it: two digits before the point (G00, G01, G05.1, G13.1)
  const gCode = (v) => `G${v < 10 ? '0' : ''}${fmt(v, 1)}`;
  const num = (v) => (v === null || v === undefined || v !== v ? '<vacant>' : fmt(v, 6));

  // boxes: the list, the modal block and the table; st: NcurveTrace's at(k); trace: the NcurveTrace;
  // files: the answer's; profile: the answer's (modal_groups, lathe); machine: the profile chosen (names)
  function show(boxes, st, {trace, files, profile, machine}) {
    const stack = boxes.stack;
    stack.textContent = '';
    for (const f of st.stack.slice().reverse()) {
      const o = f.program >= 0 ? `O${String(f.program).padStart(4, '0')}` : '(no O number)';
      const call = f.call_line ? ` ← ${files[f.call_file] || ''} line ${f.call_line}` : '';
      stack.append(el('li', '', `${f.kind} ${o}${f.custom ? ' custom' : ''}${f.modal ? ' G66' : ''} · level ${f.level}${call}`));
    }
    // modal state
    const G = [], other = [];
    const letters = {4107: 'D', 4109: 'F', 4111: 'H', 4113: 'M', 4119: 'S', 4120: 'T'};
    // the groups this machine's G codes have (a system-A lathe has no G90/G91 group, its G98/G99 are feeds)
    const groups = new Set((profile && profile.modal_groups) || []);
    const lathe = !!(profile && profile.lathe);
    for (const [v, val] of st.modal) {
      // (0 is G00 in group 1 only: a group the control gives no code reads 0)
      if (v > 4022) {  // a lathe has no D, H; its T is the tool and offset numbers, two digits each (T0101)
        if (lathe && (v === 4107 || v === 4111)) continue;
        const lathe_t = lathe && v === 4120 && Number.isInteger(val) && val >= 0;
        other.push(`${letters[v]}${lathe_t ? String(val).padStart(4, '0') : num(val)}`);
      }
      else if (val !== null && (val !== 0 || v === 4001) && (!groups.size || groups.has(v - 4000))) G.push(gCode(val));
    }
    boxes.modal.textContent = G.join(' ') + '\n' + other.join(' ');
    boxes.modal.style.whiteSpace = 'pre-wrap';
    // variables: locals of each level, commons, the rest
    const table = boxes.vars;
    table.textContent = '';
    const rows = (title, entries) => {
      if (!entries.length) return;
      const h = el('tr');
      const th = el('th', '', title);
      th.colSpan = 2;
      h.append(th);
      table.append(h);
      for (const [label, key] of entries) {
        const tr = el('tr', st.changed.has(key) ? 'changed' : '');
        tr.dataset.key = key;
        tr.append(el('td', '', label), el('td', '', num(st.vars.get(key))));
        table.append(tr);
      }
    };
    const levels = [...new Set(st.stack.map((f) => f.level))].reverse();
    for (const level of levels) {
      const e = [];
      for (let v = 1; v <= 33; v++) {
        const key = trace.key(v, level);
        if (st.vars.has(key) || st.changed.has(key)) e.push([`#${v}`, key]);
      }
      rows(`locals, level ${level}${level === levels[0] ? ' (current)' : ''}`, e);
    }
    const common = [], system = [];
    const keys = new Set([...st.vars.keys(), ...st.changed]);
    for (const key of [...keys].filter((x) => x < 0).sort((a, b) => b - a)) {
      const v = -key;
      if ((v >= 100 && v <= 199) || (v >= 500 && v <= 999)) common.push([`#${v}`, key]);
      else system.push([`#${v} ${global.NcurveTrace.systemName(v, machine)}`.trim(), key]);
    }
    rows('common variables', common);
    rows('system variables written', system);
    showReads(st, table, machine);
    return {
      vars: Object.fromEntries([...st.vars].map(([key, v]) => [key < 0 ? `#${-key}` : `L${Math.floor(key / 100000)}#${key % 100000}`, v])),
      reads: Object.fromEntries([...st.reads].map(([v, x]) => [`#${v}`, x])),
      readChanged: [...st.readChanged].map((v) => `#${v}`),
    };
  }
  // the system variables the program has read so far, each with the value it read last; those the
  // block just run read in yellow when the value differs from the step before
  function showReads(st, table, machine) {
    if (!st.reads.size) return;
    const h = el('tr'), th = el('th', '', 'system variables read (value at the last read)');
    th.colSpan = 2;
    h.append(th);
    table.append(h);
    for (const v of [...st.reads.keys()].sort((a, b) => a - b)) {
      const tr = el('tr', st.readChanged.has(v) ? 'changed' : st.readNow.has(v) ? 'read' : '');
      tr.dataset.sys = v;
      const label = el('td', '', `#${v}`), what = global.NcurveTrace.systemName(v, machine);
      if (what) label.append(el('span', 'what', ` ${what}`));
      tr.append(label, el('td', '', num(st.reads.get(v))));
      table.append(tr);
    }
  }

  global.NcurveStepView = {show};
})(window);
