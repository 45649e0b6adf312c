// The workbench's diagnostics under the editor: the run's alarm, warnings and text problems in the
// order of the text (the program's file first), the alarm marked; a click goes to the line and, for
// a finding of the part, marks its place on the part. A message whose remedy the page itself offers
// gets the page's pointer (pointer(d)) and a button opening the Settings tab at its field: the tool
// offsets of NC2071, the Max steps of NC9000 stopped after its steps ("raise --max-steps"; the page
// has no setting of --max-seconds, so that stop has none).
//   NcurveDiagnostics.show(box, {answer, name, onLine(line), onFinding(at), onSettings()});
//   d.message + NcurveDiagnostics.pointer(d)
(function (global) {
  'use strict';
  const {el} = global.NcurveDom;

  // the Settings' field that does what the message asks: its name, the button's title, the field
  function remedy(d) {
    if (d.code === 'NC2071') return {name: 'Tool offsets', title: 'the tool offsets this page runs with, edited over the profile\'s', field: ''};
    if (d.code === 'NC9000' && /raise --max-steps/.test(d.message || ''))
      return {name: 'Max steps', title: 'the most steps a run of this page may take (up to the server\'s --max-steps)', field: 'set-steps'};
    return null;
  }
  // the page's own way to what the message asks, as a sentence after it; '' if none
  function pointer(d) {
    const r = remedy(d);
    return r ? ` (here: the Settings tab, ${r.name})` : '';
  }

  function show(box, {answer, name, onLine, onFinding, onSettings}) {
    box.textContent = '';
    const alarm = answer.summary && answer.summary.alarm ? answer.diagnostics[answer.diagnostics.length - 1] : null;
    const order = (d) => [d.file && d.file !== name ? 1 : 0, d.file || '', d.line || 0, d.column || 0];
    const before = (a, b) => {
      const x = order(a), y = order(b);
      for (let k = 0; k < x.length; k++) if (x[k] !== y[k]) return x[k] < y[k] ? -1 : 1;
      return 0;
    };
    for (const d of [...answer.diagnostics].sort(before)) {
      const li = el('li', d.severity + (d === alarm ? ' alarm' : ''));
      li.append(el('span', 'where', `${d.file || ''}:${d.line}:${d.column || 1}`), el('strong', '', d.code),
        document.createTextNode(' ' + d.message + pointer(d)));
      const r = remedy(d);
      if (r) {  // the Settings tab opened by a click on the pointer, at the field
        const go = el('button', 'wb-diag-go', `Settings: ${r.name}`);
        go.title = r.title;
        go.onclick = (e) => {
          e.stopPropagation();
          onSettings();
          const f = r.field && document.getElementById(r.field);
          if (f) f.focus();
        };
        li.append(document.createTextNode(' '), go);
      }
      // a finding of the part: its place marked on the part too
      const v = answer.summary && answer.summary.verify;
      const found = v && v.findings && v.findings.find((f) => f.code === d.code && f.line === d.line && f.file === d.file);
      li.onclick = () => {
        if (!d.file || d.file === name) onLine(d.line);
        if (found) onFinding(found.at);
      };
      box.append(li);
    }
    box.hidden = !answer.diagnostics.length;
  }

  global.NcurveDiagnostics = {show, pointer};
})(window);
