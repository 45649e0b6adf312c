// The workbench's Generate fields: a curve of `ncurve gen --list` (GET /api/curves) with one field
// for each of its parameters (its name, default and unit, as gen --list gives them), the range of
// t, or an expression x(t), y(t), z(t) with parameters as NAME=VALUE; the tolerance and form with
// gen's own defaults. request() is the body of POST /api/gen, or an Error saying what is wrong.
//   const g = NcurveGen.create(); g.setCurves(answer of /api/curves); g.request(machine)
(function (global) {
  'use strict';
  const {el, fmt} = global.NcurveDom;
  const $ = (id) => document.getElementById(id);

  // the unit at the end of a parameter's doc ("semi-axis along X, mm", "mm"), '' if none
  const unitOf = (doc) => {
    const m = /(?:^|,\s*)(mm|degrees|deg|rev\/min|mm\/min|mm\/rev)(?:\s*\(.*\))?$/.exec(doc || '');
    return m ? (m[1] === 'degrees' ? '°' : m[1]) : '';
  };
  // "a=50, b=10" or "a=50 b=10": the expression's parameters; an Error naming a bad word
  function namedValues(text) {
    const out = {};
    for (const w of text.split(/[\s,;]+/).filter(Boolean)) {
      const m = /^([A-Za-z_]\w*)=(.*)$/.exec(w);
      if (!m || m[2] === '' || !Number.isFinite(Number(m[2]))) throw new Error(`parameters: "${w}" is not NAME=VALUE with a number (a=50, b=10)`);
      out[m[1]] = Number(m[2]);
    }
    return out;
  }

  function create() {
    let curves = [];
    const curve = () => curves.find((k) => k.name === $('gen-curve').value);
    function choose() {
      const c = curve(), box = $('gen-fields');
      $('gen-expr').hidden = !!c;
      box.textContent = '';
      for (const p of c ? c.params : []) {
        const label = el('label', 'wb-gen-param'), input = el('input'), unit = unitOf(p.doc);
        input.dataset.param = p.name;
        input.value = fmt(p.value, 10);
        input.placeholder = fmt(p.value, 10);
        input.size = 8;
        label.title = `${p.name}: ${p.doc}; default ${fmt(p.value, 10)}`;
        label.append(el('span', 'name', p.name), input, el('span', 'unit', unit));
        box.append(label);
      }
      // the range of t: the curve's own, or 0 to 360 for an expression
      const tUnit = c ? unitOf(c.t_doc) : '°';
      $('gen-from').value = c ? fmt(c.from, 10) : '0';
      $('gen-to').value = c ? fmt(c.to, 10) : '360';
      $('gen-t-unit').textContent = tUnit;
      $('gen-doc').textContent = !c ? 'x(t), y(t), z(t) (z 0 if empty) over t from .. to, in the macro language: SIN COS TAN ATAN ' +
        '... in degrees, [ ] or ( ); names other than t are parameters: give them as NAME=VALUE (a=50, b=10)'
        : `${c.doc}; ${c.t_doc}${c.lathe ? '; a lathe curve: choose a lathe profile' : ''}` +
          c.params.map((p) => `; ${p.name}: ${p.doc} (default ${fmt(p.value, 10)})`).join('');
      $('gen-error').textContent = '';
    }
    $('gen-curve').onchange = choose;
    function setCurves(answer) {
      curves = answer.curves;
      for (const c of curves) $('gen-curve').add(new Option(c.name, c.name, false, c.name === 'ellipse'));
      $('gen-curve').add(new Option('expression x(t), y(t), z(t)', 'expr'));
      // gen's own defaults: its --form and --tol
      if (answer.default_form) $('gen-form').value = answer.default_form;
      if (answer.default_tol) $('gen-tol').value = String(answer.default_tol);
      choose();
    }
    const number = (field, what) => {
      const t = (typeof field === 'string' ? $(field) : field).value.trim(), v = Number(t);
      if (t === '' || !Number.isFinite(v)) throw new Error(`${what}: "${t}" is not a number`);
      return v;
    };
    function request(machine) {
      const c = curve(), params = {};
      if (c) {
        for (const input of $('gen-fields').querySelectorAll('input')) params[input.dataset.param] = number(input, input.dataset.param);
      } else Object.assign(params, namedValues($('gen-params').value));
      const r = {curve: $('gen-curve').value, params, tol: number('gen-tol', 'tolerance'), form: $('gen-form').value,
        machine: machine || undefined};
      const from = number('gen-from', 't from'), to = number('gen-to', 't to');
      if (!c) Object.assign(r, {x: $('gen-x').value, y: $('gen-y').value, z: $('gen-z').value || undefined, t: `${from}:${to}`});
      else if (from !== c.from || to !== c.to) Object.assign(r, {from, to});
      return r;
    }
    return {setCurves, request, choose, get curves() { return curves; }};
  }

  global.NcurveGen = {create, unitOf, namedValues};
})(window);
