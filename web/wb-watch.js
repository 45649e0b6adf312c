// The debugger's watches ("Stop when #104 changes"): a variable the control has, asked of the
// interpreter by a run of #1=#N on the machine chosen with the Settings that make the control (its
// parameters, presets, macro folders, tool offsets; not max_steps, a bound on the program), so a
// number it has not (#99999) is refused in its words, as is a Setting the server refuses. #0 never
// changes. The watches are shown as chips (a click removes one).
//   const w = NcurveWatch.create({request() -> the run request's settings and machine});  w.list
(function (global) {
  'use strict';
  const {el} = global.NcurveDom;
  const $ = (id) => document.getElementById(id);

  function create({request}) {
    const list = [];
    const show = () => {
      const box = $('watches');
      box.textContent = '';
      for (const v of list) {
        const w = el('span', 'w', `#${v}`);
        w.title = 'remove';
        w.onclick = () => { list.splice(list.indexOf(v), 1); show(); };
        box.append(w);
      }
    };
    async function add() {
      const box = $('watch-var'), text = box.value.trim();
      const refuse = (why) => { $('watch-why').textContent = why; box.setAttribute('aria-invalid', 'true'); };
      const m = /^#?\s*(\d{1,8})$/.exec(text);
      if (!m) return refuse(`${JSON.stringify(text)} is not a variable: # and its number, e.g. #104`);
      const v = +m[1];
      if (v === 0) return refuse('#0 is always vacant: it never changes');
      let why = '';
      try {
        const body = Object.assign({}, request(), {program: `#1=#${v}\nM30\n`, name: 'watch.nc', moves: false, max_steps: undefined});
        global.ncurveWorkbench.watchRequest = body;
        const r = await fetch('/api/run', {method: 'POST', headers: {'Content-Type': 'application/json'}, body: JSON.stringify(body)});
        const j = await r.json(), a = j.summary && j.summary.alarm;
        why = a ? `${a.code} ${a.message}` : j.error || '';
      } catch (e) { why = `the server did not answer: ${e.message}`; }
      if (why) return refuse(why);
      $('watch-why').textContent = '';
      box.removeAttribute('aria-invalid');
      if (!list.includes(v)) list.push(v);
      box.value = '';
      show();
    }
    $('watch-add').onclick = add;
    $('watch-var').addEventListener('keydown', (e) => { if (e.key === 'Enter') add(); });
    return {list};
  }

  global.NcurveWatch = {create};
})(window);
